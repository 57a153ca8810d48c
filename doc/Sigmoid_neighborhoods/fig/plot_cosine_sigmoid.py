#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Draws cosine_sigmoid.png, the manual's plot of sig_{a,b} on [0, pi] for the three parameter
# pairs of the paper's Figure 1. Run from anywhere with a Python that has matplotlib:
#   /usr/bin/python3 doc/Sigmoid_neighborhoods/fig/plot_cosine_sigmoid.py

import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def sig(x, a, b):
    """sig_{a,b}(x) as CGAL::Sigmoid_neighborhoods::Cosine_sigmoid computes it (no angle tolerance)."""
    if x < a:
        return 1.0
    if a == b:
        return 1.0 if x <= a else 0.0
    if x > b:
        return 0.0
    return 0.5 * math.cos(math.pi * (x - a) / (b - a)) + 0.5


def main():
    n = 601
    xs = [math.pi * i / (n - 1) for i in range(n)]
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)

    a, b = 3 * math.pi / 4, math.pi
    ax.plot(xs, [sig(x, a, b) for x in xs], color="#1f3b73", lw=3, ls=":", zorder=4,
            label=r"$a = 3\pi/4,\ b = \pi$")

    a, b = 0.0, math.pi
    ax.plot(xs, [sig(x, a, b) for x in xs], color="#e07b00", lw=3, ls="--", zorder=3,
            label=r"$a = 0,\ b = \pi$")

    # The sharp cut-off a = b = 2 pi / 3: two pieces, x = a keeps weight 1 (filled dot). Drawn
    # below the other curves, which it overlaps on [0, 2 pi / 3] and [3 pi / 4, pi].
    c = 2 * math.pi / 3
    ax.plot([0, c], [1, 1], color="#8fb8e8", lw=5, zorder=1, label=r"$a = b = 2\pi/3$")
    ax.plot([c, math.pi], [0, 0], color="#8fb8e8", lw=5, zorder=1)
    ax.plot([c], [1], "o", color="#3a7dc9", ms=8, zorder=5)
    ax.plot([c], [0], "o", mfc="white", mec="#3a7dc9", mew=2, ms=8, zorder=5)

    ax.set_xlim(0, math.pi * 1.02)
    ax.set_ylim(-0.05, 1.08)
    ax.set_xticks([0, math.pi / 4, math.pi / 2, 3 * math.pi / 4, math.pi])
    ax.set_xticklabels(["0", r"$\pi/4$", r"$\pi/2$", r"$3\pi/4$", r"$\pi$"])
    ax.set_xlabel(r"angle $x$ between the normals $n_i$ and $n_j$ (radians)")
    ax.set_ylabel(r"$\mathrm{sig}_{a,b}(x)$")
    ax.spines["top"].set_visible(False)
    ax.spines["right"].set_visible(False)
    ax.legend(loc="lower left", frameon=False)
    fig.tight_layout()
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cosine_sigmoid.png")
    fig.savefig(out, metadata={"Software": None})
    print(out)


if __name__ == "__main__":
    main()
