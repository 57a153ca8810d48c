#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The points of every method of the denoising comparison colored by their distance to the clean
surface (units of l): the model seen from an octant (top row) and a thin slab through its middle seen
edge-on (bottom row), where sharp edges show as corners of the section. Drawn with matplotlib.

Run by `sigmoid-neighborhoods denoise-comparison`; usable alone:
    plot_denoising.py denoising_points.csv OUT.png [--title TEXT]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    methods, points = [], {}
    with open(args.csv, newline="") as f:
        reader = csv.reader(f)
        next(reader)
        for row in reader:
            if row[0] not in points:
                methods.append(row[0])
                points[row[0]] = []
            points[row[0]].append([float(v) for v in row[1:5]])
    if not methods:
        sys.exit("no points in " + args.csv)
    data = {m: np.array(points[m]) for m in methods}
    reference = data[methods[0]]
    low, high = reference[:, :3].min(axis=0), reference[:, :3].max(axis=0)
    ranges = np.maximum(high - low, 1e-12 * max(1.0, float(np.max(high - low))))
    # The slab: a thin slice across the axis of the smallest extent, through the middle.
    axis = int(np.argmin(ranges))
    middle = 0.5 * (low[axis] + high[axis])
    half_width = 0.02 * ranges[axis] + 1e-12
    shown = [a for a in range(3) if a != axis]
    vmax = float(np.percentile(np.concatenate([data[m][:, 3] for m in methods]), 99)) or 1.0

    point_size = float(np.clip(12000.0 / len(reference), 0.5, 6.0))
    fig = plt.figure(figsize=(3.8 * len(methods), 7.6))
    scatter = None
    for c, m in enumerate(methods):
        xyz, d = data[m][:, :3], data[m][:, 3]
        ax = fig.add_subplot(2, len(methods), c + 1, projection="3d")
        order = np.argsort(d)  # far points drawn last, on top
        scatter = ax.scatter(xyz[order, 0], xyz[order, 1], xyz[order, 2], c=d[order], s=point_size, cmap="viridis",
                             vmin=0.0, vmax=vmax, linewidths=0, depthshade=False)
        ax.set_xlim(low[0], high[0])
        ax.set_ylim(low[1], high[1])
        ax.set_zlim(low[2], high[2])
        ax.set_box_aspect(tuple(ranges), zoom=1.0)
        ax.view_init(elev=25, azim=35)
        ax.set_axis_off()
        ax.set_title("%s\nmean %.3f l, RMS %.3f l" % (m, float(d.mean()), float(np.sqrt((d * d).mean()))), fontsize=10)
        slab = np.abs(xyz[:, axis] - middle) < half_width
        ax2 = fig.add_subplot(2, len(methods), len(methods) + c + 1)
        ax2.scatter(xyz[slab, shown[0]], xyz[slab, shown[1]], c=d[slab], s=4 * point_size, cmap="viridis", vmin=0.0,
                    vmax=vmax, linewidths=0)
        ax2.set_aspect("equal")
        ax2.set_xticks([])
        ax2.set_yticks([])
        ax2.set_title("slab %s = %.3g ± %.2g" % ("xyz"[axis], middle, half_width), fontsize=9)
    fig.suptitle("Distance to the clean surface%s" % (": " + args.title if args.title else ""), fontsize=12)
    fig.subplots_adjust(left=0.01, right=0.9, bottom=0.02, top=0.88, wspace=0.05, hspace=0.15)
    bar = fig.add_axes([0.92, 0.15, 0.015, 0.7])
    fig.colorbar(scatter, cax=bar, label="distance / l (saturated at the 99th percentile, %.3g)" % vmax)
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
