#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The per-point normal error |n - n~|^2 of one model of Table 4: noisy input, default filter, adaptive filter
(columns), one row per noise level, on the noise-free points. Drawn with matplotlib.

Run by `sigmoid-neighborhoods denoise-experiment`; usable alone:
    plot_normal_error.py normal_error_MODEL.csv OUT.png [--title MODEL]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLUMNS = [("noise", "noisy input"), ("default", "default filter"), ("adaptive", "adaptive filter")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    with open(args.csv, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = np.array([[float(v) for v in row] for row in reader])
    if rows.size == 0:
        sys.exit("no points in " + args.csv)
    xyz = rows[:, 0:3]
    levels = [h[len("noise_"):] for h in header if h.startswith("noise_")]
    column = {name: i for i, name in enumerate(header)}

    # One colour scale for all panels: squared errors up to the 99th percentile, larger ones saturate.
    errors = rows[:, 3:]
    vmax = float(np.percentile(errors, 99)) or 1.0
    # Axes fitted to the model, equal scales, seen from an octant so that three sides of a box show.
    low, high = xyz.min(axis=0), xyz.max(axis=0)
    ranges = np.maximum(high - low, 1e-12 * max(1.0, float(np.max(high - low))))

    point_size = float(np.clip(12000.0 / len(rows), 0.5, 6.0))
    fig = plt.figure(figsize=(4.2 * len(COLUMNS), 4.0 * len(levels) + 0.6))
    scatter = None
    for r, level in enumerate(levels):
        for c, (key, label) in enumerate(COLUMNS):
            e = rows[:, column["%s_%s" % (key, level)]]
            ax = fig.add_subplot(len(levels), len(COLUMNS), r * len(COLUMNS) + c + 1, projection="3d")
            order = np.argsort(e)  # large errors drawn last, on top
            scatter = ax.scatter(xyz[order, 0], xyz[order, 1], xyz[order, 2], c=e[order], s=point_size,
                                 cmap="viridis", vmin=0.0, vmax=vmax, linewidths=0, depthshade=False)
            ax.set_xlim(low[0], high[0])
            ax.set_ylim(low[1], high[1])
            ax.set_zlim(low[2], high[2])
            ax.set_box_aspect(tuple(ranges), zoom=1.0)
            ax.view_init(elev=25, azim=35)
            ax.set_axis_off()
            ax.set_title("%s, %s l\nMSE %.6f" % (label, level, float(e.mean())), fontsize=10)
    fig.suptitle("Normal error |n - ñ|² per point%s" % (": " + args.title if args.title else ""), fontsize=12)
    fig.subplots_adjust(left=0.0, right=0.9, bottom=0.02, top=0.9, wspace=0.0, hspace=0.12)
    bar = fig.add_axes([0.92, 0.15, 0.015, 0.7])
    fig.colorbar(scatter, cax=bar, label="|n - ñ|² (saturated at the 99th percentile, %.3g)" % vmax)
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
