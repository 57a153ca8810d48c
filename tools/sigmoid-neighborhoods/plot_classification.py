#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A test tile of the classification experiment seen from above: colored by the truth, by two feature
sets' predictions, and the points each of them gets wrong. Drawn with matplotlib.

Run by `sigmoid-neighborhoods classify experiment`; usable alone:
    plot_classification.py figure_tile.csv OUT.png --classes ground,low_vegetation,...
The CSV has the columns x, y, z, truth, then one column per feature set (class indices, -1: none).
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

NAMED_COLORS = {"ground": "#a06e3c", "low_vegetation": "#96dc5a", "high_vegetation": "#148228",
                "vegetation": "#148228", "building": "#d23228", "roof": "#d23228"}
PALETTE = ["#0072b2", "#e69f00", "#56b4e9", "#cc79a7", "#f0e442", "#009e73", "#d55e00", "#808080"]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--classes", required=True)
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    classes = args.classes.split(",")
    with open(args.csv, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = np.array([[float(v) for v in row] for row in reader])
    if rows.size == 0 or header[:4] != ["x", "y", "z", "truth"] or len(header) < 5:
        sys.exit("plot_classification.py: no points or unexpected columns in " + args.csv)
    x, y, z, truth = rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3].astype(int)
    sets = header[4:]
    colors = np.array([NAMED_COLORS.get(c, PALETTE[i % len(PALETTE)]) for i, c in enumerate(classes)] + ["#d0d0d0"])
    order = np.argsort(z)  # higher points drawn last, as seen from above
    labeled = truth >= 0

    panels = [("truth", truth)] + [(name, rows[:, 4 + i].astype(int)) for i, name in enumerate(sets)]
    errors = [(f"errors of {name}", rows[:, 4 + i].astype(int)) for i, name in enumerate(sets)]
    columns = len(panels)
    fig, axes = plt.subplots(2, columns, figsize=(4.2 * columns, 8.4), squeeze=False)
    for ax, (title, values) in zip(axes[0], panels):
        ax.scatter(x[order], y[order], c=colors[np.where(values[order] >= 0, values[order], len(classes))],
                   s=1.5, linewidths=0)
        if title != "truth":
            right = np.mean(values[labeled] == truth[labeled])
            title = f"{title}: {100 * right:.1f} % right"
        ax.set_title(title, fontsize=10)
    axes[1][0].axis("off")
    for c, name in enumerate(classes):
        axes[1][0].scatter([], [], c=colors[c], label=name, s=30)
    axes[1][0].legend(loc="center", frameon=False, fontsize=11)
    for ax, (title, values) in zip(axes[1][1:], errors):
        wrong = labeled & (values != truth)
        ax.scatter(x[~wrong], y[~wrong], c="#e4e4e4", s=1.0, linewidths=0)
        ax.scatter(x[wrong], y[wrong], c=colors[truth[wrong]], s=2.5, linewidths=0)
        ax.set_title(f"{title}: {wrong.sum()} points, in their true class's color", fontsize=9)
    for ax in axes.flat:
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
