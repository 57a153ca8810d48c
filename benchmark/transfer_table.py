#!/usr/bin/python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The table of benchmark/classification_transfer.sh: per feature set (without graph-cut), the mean IoU
on the test tiles of each condition as mean [min, max] over the feature orders, its drop from the
same-density result, the cross-validated mean IoU where the condition has one, and the time per point
of the features and of the classification.

    transfer_table.py OUT_DIR  > table.md
"""
import json
import os
import sys

CONDITIONS = [
    ("same", "same density"),
    ("train_random2", "train thinned 2x (random)"),
    ("train_voxel2", "train thinned 2x (voxel)"),
    ("train_random4", "train thinned 4x (random)"),
    ("train_voxel4", "train thinned 4x (voxel)"),
    ("test_random4", "test thinned 4x (random)"),
    ("test_voxel4", "test thinned 4x (voxel)"),
]


def load(folder):
    path = os.path.join(folder, "experiment.json")
    if not os.path.exists(path):
        return None
    sets = {}
    for s in json.load(open(path))["sets"]:
        if not s["graphcut"]:
            sets[s["set"]] = s
    return sets


def main():
    out = sys.argv[1]
    results = {c: load(os.path.join(out, c)) for c, _ in CONDITIONS}
    same = results["same"] or {}
    names = list(same) or sorted({n for r in results.values() if r for n in r})
    print("| set | " + " | ".join(title for c, title in CONDITIONS if results[c]) + " |")
    print("|---|" + "---|" * sum(1 for c, _ in CONDITIONS if results[c]))
    for name in names:
        cells = []
        for c, _ in CONDITIONS:
            r = results[c]
            if not r:
                continue
            s = r.get(name)
            if s is None:
                cells.append("")
                continue
            m = s["mean_iou"]
            cell = "%.3f [%.3f, %.3f]" % (m["mean"], m["min"], m["max"])
            if c != "same" and name in same:
                cell += " (%+.3f)" % (m["mean"] - same[name]["mean_iou"]["mean"])
            if "cross_validated_mean_iou" in s:
                cell += ", CV %.3f" % s["cross_validated_mean_iou"]
            cells.append(cell)
        print("| %s | %s |" % (name, " | ".join(cells)))


if __name__ == "__main__":
    main()
