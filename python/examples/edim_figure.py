#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A figure of the dimensionality error E_dim at every point's optimal sigmoid neighborhood.

Reads a mesh (one point per vertex, with its vertex normal) or a point set (normals estimated and
oriented when the file has none), searches every point's optimal (a*, b*, k*) with optimal(), and
draws the points coloured by E_dim next to a histogram of E_dim with the optimal weights against
E_dim with equal weights (a = b = pi at the best k), the paper's comparison. Prints one line: the
points, both mean errors and the failures (points whose every neighborhood is degenerate).

Run:

    PYTHONPATH=build/python python3 python/examples/edim_figure.py \\
        build/test-models/data/meshes/fandisk.off -o fandisk_edim.png
    PYTHONPATH=build/python python3 python/examples/edim_figure.py \\
        ../shared/data/scanned/lone-star_tls.ply -o lone-star_edim.png --view top --threads 2
"""

import argparse
import pathlib
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402

import sigmoid_neighborhoods as sn  # noqa: E402


def finite_mean(values):
    finite = values[np.isfinite(values)]
    return float(finite.mean()) if finite.size else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", type=pathlib.Path, help="a mesh or point set: .off .obj .ply .stl .xyz .pwn .las")
    parser.add_argument("-o", "--output", type=pathlib.Path, required=True, help="the figure (.png, .pdf, .svg)")
    parser.add_argument("--k-min", type=int, default=sn.DEFAULT_K_MIN, help=f"default {sn.DEFAULT_K_MIN}")
    parser.add_argument("--k-max", type=int, default=sn.DEFAULT_K_MAX, help=f"default {sn.DEFAULT_K_MAX}")
    parser.add_argument("--threads", type=int, default=None, help="default: OpenMP's")
    parser.add_argument("--view", choices=("3d", "top"), default="3d",
                        help="a 3D scatter (default) or a top view, the highest points on top (airborne scans)")
    parser.add_argument("--plot-points", type=int, default=100_000,
                        help="draw at most this many random points (the search uses all; default 100000)")
    args = parser.parse_args()

    model = sn.read(args.input, threads=args.threads)
    points, normals = model["points"], model["normals"]
    # all_features=False: the figure needs the errors only, which saves the features' pass
    result = sn.optimal(points, normals, k_min=args.k_min, k_max=args.k_max, all_features=False,
                        threads=args.threads)
    error, error_equal = result["error"], result["error_equal"]
    failures = int(np.count_nonzero(result["k"] == 0))
    failures_equal = int(np.count_nonzero(result["k_equal"] == 0))

    figure = plt.figure(figsize=(13, 5.5))
    drawn = np.arange(len(points))
    if len(points) > args.plot_points:
        # a scatter of millions of markers is slow and unreadable; a fixed random subset is drawn
        drawn = np.sort(np.random.default_rng(1).choice(len(points), args.plot_points, replace=False))
    if args.view == "top":
        drawn = drawn[np.argsort(points[drawn, 2], kind="stable")]  # the highest points drawn last, on top
    shown = error[drawn]
    finite = np.isfinite(shown)
    # the colour scale stops at the 99th percentile, so that a few large errors do not wash it out
    top = np.percentile(shown[finite], 99) if finite.any() else 1.0
    p = points[drawn] - points.min(axis=0)  # local coordinates: scans often sit at UTM offsets
    size = float(np.clip(30_000 / len(drawn), 0.2, 6.0))  # markers shrink as the cloud grows
    style = dict(c=shown[finite], cmap="viridis", vmin=0.0, vmax=top, s=size, linewidths=0, rasterized=True)
    if args.view == "top":
        view = figure.add_subplot(1, 2, 1)
        scatter = view.scatter(p[finite, 0], p[finite, 1], **style)
        if (~finite).any():
            view.scatter(p[~finite, 0], p[~finite, 1], c="red", s=4.0, label="failure")
        view.set_aspect("equal")
        view.set_xlabel("x - min x")
        view.set_ylabel("y - min y")
    else:
        view = figure.add_subplot(1, 2, 1, projection="3d")
        scatter = view.scatter(p[finite, 0], p[finite, 1], p[finite, 2], depthshade=False, **style)
        if (~finite).any():
            view.scatter(p[~finite, 0], p[~finite, 1], p[~finite, 2], c="red", s=4.0, label="failure")
        view.set_box_aspect(np.ptp(points, axis=0) + 1e-12)  # true proportions, not a stretched cube
        view.set_axis_off()
    if (~finite).any():
        view.legend(loc="upper left")
    view.set_title(f"{args.input.name}: E_dim at the optimal (a*, b*, k*)")
    figure.colorbar(scatter, ax=view, shrink=0.7, label="E_dim")

    histogram = figure.add_subplot(1, 2, 2)
    ok = np.isfinite(error) & np.isfinite(error_equal)
    bins = np.linspace(0.0, max(float(np.max(error_equal[ok], initial=0.0)), 1e-9), 60)
    histogram.hist(error_equal[ok], bins=bins, alpha=0.6, label=f"equal weights (mean {finite_mean(error_equal):.4f})")
    histogram.hist(error[ok], bins=bins, alpha=0.6, label=f"optimal sigmoid (mean {finite_mean(error):.4f})")
    histogram.set_yscale("log")  # most points sit near 0; the tail is what differs
    histogram.set_xlabel("E_dim")
    histogram.set_ylabel("points")
    histogram.set_title(f"k in [{args.k_min}, {args.k_max}], {len(points):,} points")
    histogram.legend()
    figure.tight_layout()
    figure.savefig(args.output, dpi=120)

    print(f"{args.input.name}: {len(points)} points, mean E_dim {finite_mean(error):.6f} (optimal weights), "
          f"{finite_mean(error_equal):.6f} (equal weights), failures {failures} (equal weights {failures_equal}); "
          f"figure {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
