#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Figures 3-6 of the paper's Section 5 from evaluation folders (summary.json), drawn with matplotlib.

Run by `sigmoid-neighborhoods report`, which checks the evaluation files first; usable alone:
    plot_evaluation.py --output DIR [--figure3 POINTS.csv --figure3-name NAME] EVALUATION_DIR...
Any failure is one line on stderr and exit code 1.
"""
import argparse
import csv
import json
import math
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt  # noqa: E402
    import numpy as np  # noqa: E402
except ImportError as e:
    sys.stderr.write("plot_evaluation.py: needs matplotlib and numpy (%s)\n" % e)
    sys.exit(1)

LABEL_COLORS = {"linear": "#f28e2b", "planar": "#f2f2f2", "scattered": "#1f3b73", "degenerate": "#d62728"}
ANGLE_NAMES = {0: "0", 1: "π/6", 2: "π/3", 3: "π/2", 4: "2π/3", 5: "5π/6", 6: "π"}


def angle_name(x):
    steps = x / (math.pi / 6)
    return ANGLE_NAMES.get(round(steps), "%.3g" % x) if abs(steps - round(steps)) < 1e-9 else "%.3g" % x


def load(folders):
    result = []
    for folder in folders:
        with open(os.path.join(folder, "summary.json")) as f:
            result.append(json.load(f))
    return [s for s in result if "statistics" in s]


def figure3(csv_path, name, out):
    """Per-point E_dim (top) and label (bottom) for equal, cut-off and optimal weights."""
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    xyz = np.array([[float(r["x"]), float(r["y"]), float(r["z"])] for r in rows])
    columns = [("equal weights: a = b = π", "error_equal", "label_equal"),
               ("cut-off: a = b = arccos(0.9)", "error_cut_off", "label_cut_off"),
               ("optimal (a*, b*, k*)", "error", "label")]
    fig = plt.figure(figsize=(13, 8.5))
    cmap = plt.get_cmap("Blues")
    vmax = math.log(3)
    for c, (title, error_key, label_key) in enumerate(columns):
        error = np.array([float(r[error_key]) if r[error_key] not in ("", "inf") else np.inf for r in rows])
        failed = ~np.isfinite(error)
        ax = fig.add_subplot(2, 3, c + 1, projection="3d")
        ax.scatter(*xyz[~failed].T, c=error[~failed], cmap=cmap, vmin=0, vmax=vmax, s=3, depthshade=False)
        ax.scatter(*xyz[failed].T, c="#d62728", s=4, depthshade=False)
        ax.set_title("%s\nE_dim (white 0 to blue ln 3), %d failures in red" % (title, failed.sum()), fontsize=9)
        ax2 = fig.add_subplot(2, 3, c + 4, projection="3d")
        colors = [LABEL_COLORS[r[label_key]] for r in rows]
        ax2.scatter(*xyz.T, c=colors, s=3, depthshade=False, edgecolors="none")
        ax2.set_title("label: linear orange, planar white, scattered blue", fontsize=9)
        for a in (ax, ax2):
            a.set_box_aspect(np.ptp(xyz, axis=0) + 1e-12)  # true proportions
            a.set_facecolor("#bbbbbb")
            a.view_init(elev=25, azim=-60)
            a.set_axis_off()
    fig.suptitle("Figure 3: %s" % name)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def pairs(settings):
    return [(a, b) for a in settings["a_grid"] for b in settings["b_grid"] if a <= b]


def figure4(summaries, out):
    """(a*, b*) histogram, each bar split by k*."""
    fig, axes = plt.subplots(len(summaries), 1, figsize=(12, 3.6 * len(summaries)), squeeze=False)
    for ax, s in zip(axes[:, 0], summaries):
        st, ks = s["settings"], list(range(s["settings"]["k_min"], s["settings"]["k_max"] + 1))
        counts = np.array(s["statistics"]["pair_k_histogram"], dtype=float).reshape(len(pairs(st)), len(ks))
        bottom = np.zeros(len(counts))
        colors = plt.get_cmap("viridis")(np.linspace(0, 1, len(ks)))
        x = np.arange(len(counts))
        for j, k in enumerate(ks):
            ax.bar(x, counts[:, j], bottom=bottom, color=colors[j], label="k = %d" % k, width=0.85)
            bottom += counts[:, j]
        ax.set_xticks(x)
        ax.set_xticklabels(["%s, %s" % (angle_name(a), angle_name(b)) for a, b in pairs(st)], rotation=90, fontsize=8)
        ax.set_ylabel("points")
        ax.set_title("%s: (a*, b*), bars split by k* (bottom k = %d, top k = %d)" % (s["repository"], ks[0], ks[-1]))
    axes[0, 0].legend(ncol=8, fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def two_decimals(x):
    """x to two decimals; null (no point with an optimum) as a dash."""
    return "–" if x is None else "%.2f" % x


def figure5(summaries, out):
    """k* histogram in percent of points, per repository."""
    fig, ax = plt.subplots(figsize=(10, 4))
    width = 0.8 / max(1, len(summaries))
    for i, s in enumerate(summaries):
        st = s["settings"]
        ks = np.arange(st["k_min"], st["k_max"] + 1)
        h = np.array(s["statistics"]["optimal"]["k_histogram"], dtype=float)
        ax.bar(ks + (i - (len(summaries) - 1) / 2) * width, 100 * h / max(1, h.sum()), width=width,
               label="%s (mean %s, sd %s)" % (s["repository"], two_decimals(s["statistics"]["k_mean"]),
                                             two_decimals(s["statistics"]["k_standard_deviation"])))
    ax.set_xlabel("k*")
    ax.set_ylabel("% of points")
    ax.set_title("Figure 5: optimal neighborhood size k*")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def figure6(summaries, out):
    """Box-whisker of the per-model standard deviation of k*; whiskers at min and max."""
    fig, ax = plt.subplots(figsize=(3 + 2 * len(summaries), 4))
    data = [[m["k_standard_deviation"] for m in s["per_model"] if m["k_standard_deviation"] is not None]
            for s in summaries]
    ax.boxplot(data, whis=(0, 100), labels=["%s\n(%d models)" % (s["repository"], len(d)) for s, d in zip(summaries, data)])
    ax.set_ylabel("sd of k* per model")
    ax.set_title("Figure 6: variation of k* within a model")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def run():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--output", required=True)
    parser.add_argument("--figure3")
    parser.add_argument("--figure3-name", default="")
    args = parser.parse_args()
    summaries = load(args.folders)
    if not summaries:
        sys.exit("no evaluated model in " + ", ".join(args.folders))
    os.makedirs(args.output, exist_ok=True)
    if args.figure3:
        figure3(args.figure3, args.figure3_name, os.path.join(args.output, "figure3_per_point.png"))
    figure4(summaries, os.path.join(args.output, "figure4_ab_histogram.png"))
    figure5(summaries, os.path.join(args.output, "figure5_k_histogram.png"))
    figure6(summaries, os.path.join(args.output, "figure6_k_deviation.png"))


def main():
    try:
        run()
    except Exception as e:  # noqa: BLE001 - one line, never a traceback
        sys.stderr.write("plot_evaluation.py: %s: %s\n" % (type(e).__name__, str(e).splitlines()[0] if str(e) else ""))
        sys.exit(1)


if __name__ == "__main__":
    main()
