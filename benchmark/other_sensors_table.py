#!/usr/bin/python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tables of benchmark/classification_other_sensors.sh: mean IoU of each set per condition, then
the per-class IoU of CGAL's generator against the default set at its chosen scale.

    other_sensors_table.py OUT_DIR
"""
import json
import os
import sys

CONDITIONS = [("drone", "drone photogrammetry, quadrants about the buildings"),
              ("vehicle", "ground-vehicle lidar, quadrants about the sensor"),
              ("region", "IGN tile of another region, quadrants"),
              ("transfer", "six IGN tiles -> the other region"),
              ("ign", "four western IGN tiles -> the two eastern")]


def sets_of(folder):
    path = os.path.join(folder, "experiment.json")
    if not os.path.exists(path):
        return None
    return {s["set"]: s for s in json.load(open(path))["sets"] if not s["graphcut"]}


def iou(s):
    m = s["mean_iou"]
    return "%.3f [%.3f, %.3f]" % (m["mean"], m["min"], m["max"])


def main():
    out = sys.argv[1]
    rows = []
    print("| condition | CGAL's generator (A) | default, chosen scale (D) | default at 0.5 m (D_05) "
          "| default, equal weights (DE) | cgal-metric (M) | + pyramid (MP) | + multiscale-sigmoid (MS) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, text in CONDITIONS:
        chosen, fixed = sets_of(os.path.join(out, name + "-chosen")), sets_of(os.path.join(out, name + "-fixed"))
        equal = sets_of(os.path.join(out, name + "-equal")) or {}
        if chosen is None:
            continue
        cells = [iou(chosen["A"])]
        for key in ["D", "M", "MP", "MS"]:
            s = chosen.get(key)
            cell = iou(s) + " at %g m" % s["scale_choice"]["chosen"] if s else ""
            cells.append(cell)
            if key == "D":
                cells.append(iou(fixed["D_05"]) if fixed and "D_05" in fixed else "")
                s = equal.get("DE")
                cells.append(iou(s) + " at %g m" % s["scale_choice"]["chosen"] if s else "")
        print("| %s | %s |" % (text, " | ".join(cells)))
        rows.append((text, chosen))
    print()
    # the set as the choice of scales would choose it too: the best of the worse of the two densities'
    # cross-validated scores at each set's chosen scale, then that set's score on the test files
    print("| condition | set of the best cross-validated score | its score | its test mean IoU | the default's |")
    print("|---|---|---:|---:|---:|")
    for text, chosen in rows:
        scores = {}
        for key in ["D", "M", "MP", "MS"]:
            c = chosen[key]["scale_choice"]
            scores[key] = max(min(a, b) for a, b in zip(c["same_density"], c["thinned"]))
        best = max(scores, key=lambda k: scores[k])
        print("| %s | %s | %.3f | %.3f | %.3f |" % (text, best, scores[best], chosen[best]["mean_iou"]["mean"],
                                                  chosen["D"]["mean_iou"]["mean"]))
    print()
    print("| condition | set | features + classification of all files, seconds | ratio to CGAL's generator |")
    print("|---|---|---:|---:|")
    for text, chosen in rows:
        base = chosen["A"]["feature_seconds"] + chosen["A"]["classify_seconds_mean"]
        for key in ["A", "D", "M", "MP", "MS"]:
            t = chosen[key]["feature_seconds"] + chosen[key]["classify_seconds_mean"]
            print("| %s | %s | %.1f | %.2f |" % (text, key, t, t / base))
    print()
    print("| condition | class | CGAL's generator | default, chosen scale | difference |")
    print("|---|---|---:|---:|---:|")
    for text, chosen in rows:
        a, d = chosen["A"]["iou_mean"], chosen["D"]["iou_mean"]
        for c in a:
            print("| %s | %s | %.3f | %.3f | %+.3f |" % (text, c, a[c], d[c], d[c] - a[c]))


if __name__ == "__main__":
    main()
