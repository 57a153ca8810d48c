#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Semantic classification of airborne lidar with the module's features and scikit-learn.

The six IGN LiDAR HD tiles of ../shared/data/labeled (uncompressed LAS 1.4 with a classification code
per point): a RandomForestClassifier is trained on the four western tiles (ign_lidarhd_77050_* and
ign_lidarhd_77055_*) and tested on the two eastern ones (ign_lidarhd_77060_*), the split of the C++
command `sigmoid-neighborhoods classify experiment` (`make classification`). Per point, as that
command's feature sets F and F_sigmoid compute them:

- normals by PCA on 18 neighbors, turned towards +z (read(..., normals="pca", orientation="up"));
- the ten eigen features (linearity, planarity, scattering, omnivariance, anisotropy, eigenentropy,
  sum of eigenvalues, change of curvature, verticality, normal z) at k = 10, 25, 50, 100, with equal
  weights (set F) or with the sigmoid weights a = 30 deg, b = 60 deg (set F_sigmoid; --a, --b);
- the height features in 2.5, 5 and 10 m cells (--cells).

No absolute coordinate is a feature. The classes are the command's default mapping, ground = 2,
low_vegetation = 3 + 4, high_vegetation = 5, building = 6 (--labels, the same syntax); other codes
take no part in training or evaluation. The scores are the command's: the confusion matrix of both
test tiles pooled, overall accuracy, per-class IoU and F1, and their means over the classes present
in the truth. They are printed as a Markdown table next to the command's published numbers
(benchmark/README.md) and written to --out (classification.md, classification.csv).

The forest is scikit-learn's, not the command's CGAL ETHZ forest, with the command's size by default
(25 trees of depth at most 20): the numbers are expected to be close, not equal. More trees help
little and cost time in proportion (100 trees: about 8 minutes on two cores under load).

Run (two to four minutes on two cores for the full tiles):

    PYTHONPATH=build/python python3 python/examples/classify_tiles.py --out /tmp/classification

--max-points N keeps N random points of each tile (fixed seed) after the normal estimation, before
the features: faster, but on a thinner cloud, where k neighbors span a larger radius.
"""

import argparse
import csv
import os
import pathlib
import sys
import time

import numpy as np

import sigmoid_neighborhoods as sn

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
TRAIN_PREFIXES = ("ign_lidarhd_77050_", "ign_lidarhd_77055_")
TEST_PREFIXES = ("ign_lidarhd_77060_",)
# tools/sigmoid-neighborhoods/classification/label_mapping.h, DEFAULT_LABELS
DEFAULT_LABELS = "ground=2,low_vegetation=3+4,high_vegetation=5,building=6"
# SN::Classification::default_point_features(), in the command's column order
EIGEN_FEATURES = (
    "linearity",
    "planarity",
    "scattering",
    "omnivariance",
    "anisotropy",
    "eigenentropy",
    "sum_of_eigenvalues",
    "change_of_curvature",
    "verticality",
    "normal_z",
)
SCALES = (10, 25, 50, 100)
HEIGHT_FEATURES = ("height_above_lowest", "height_below_highest", "vertical_range")

# The C++ command's results, benchmark/README.md, section "Semantic classification of airborne lidar",
# second table (every set in 10 feature orders, mean over them; CGAL's ETHZ forest, 25 trees, depth 20;
# no graph-cut), rows F (multiscale + height) and F_sigmoid (multiscale-sigmoid + height).
PUBLISHED = {
    "F": {
        "mean_iou": 0.828,
        "overall_accuracy": 0.933,
        "mean_f1": 0.902,
        "iou": {"ground": 0.957, "low_vegetation": 0.666, "high_vegetation": 0.846, "building": 0.841},
    },
    "F_sigmoid": {
        "mean_iou": 0.835,
        "overall_accuracy": 0.937,
        "mean_f1": 0.906,
        "iou": {"ground": 0.958, "low_vegetation": 0.665, "high_vegetation": 0.861, "building": 0.856},
    },
}
PUBLISHED_SOURCE = (
    "benchmark/README.md, section \"Semantic classification of airborne lidar\", second table "
    "(`sigmoid-neighborhoods classify experiment`, CGAL's ETHZ forest of 25 trees of depth 20, "
    "mean over 10 feature orders, no graph-cut)"
)


def parse_labels(text):
    """NAME=CODE[+CODE...],... as the command's --labels: (class names, {file code: class index})."""
    names, class_of_code = [], {}
    for item in text.split(","):
        name, _, codes = item.partition("=")
        if not name or not codes or name in names:
            raise SystemExit(f"--labels: expected NAME=CODE[+CODE...] with distinct names, got '{item}'")
        for code in codes.split("+"):
            if int(code) in class_of_code:
                raise SystemExit(f"--labels: code {code} is in two classes")
            class_of_code[int(code)] = len(names)
        names.append(name)
    if len(names) < 2:
        raise SystemExit("--labels: a classification needs at least two classes")
    return names, class_of_code


def default_data_dir():
    shared = os.environ.get("SN_SHARED_DATA_DIR")
    return pathlib.Path(shared) / "labeled" if shared else REPOSITORY.parent / "shared" / "data" / "labeled"


def finite(values):
    # A degenerate neighborhood has an infinite eigenentropy; the command's CGAL feature set turns
    # non-finite values into -1, below every feature's range, and so does this.
    return np.where(np.isfinite(values), values, -1.0)


def tile_features(path, args, class_of_code, rng):
    """The feature columns ({name: (n,) array}) and the class index per point (-1: no class) of one tile."""
    model = sn.read(path, normals="pca", k=18, orientation="up", threads=args.threads)
    points, normals = model["points"], model["normals"]
    if args.max_points and len(points) > args.max_points:
        keep = np.sort(rng.choice(len(points), args.max_points, replace=False))
        points, normals, codes = points[keep], normals[keep], model["labels"][keep]
    else:
        codes = model["labels"]
    truth = np.full(len(points), -1, dtype=np.int64)
    for code, index in class_of_code.items():
        truth[codes == code] = index

    columns = {}
    for group, (a, b) in (("multiscale", (np.pi, np.pi)), ("multiscale-sigmoid", (args.a, args.b))):
        # One neighbor query of the largest size serves every scale.
        f = sn.features(points, normals, k=list(SCALES), a=a, b=b, threads=args.threads)
        suffix = "_sigmoid_k" if group == "multiscale-sigmoid" else "_k"
        for s, k in enumerate(SCALES):
            for name in EIGEN_FEATURES:
                columns[(group, f"{name}{suffix}{k}")] = finite(f[name][:, s])
    for cell in args.cells:
        h = sn.height_features(points, cell)
        for name in HEIGHT_FEATURES:
            columns[("height", f"{name}_cell{cell:g}")] = h[name]
    return columns, truth


def confusion_matrix(truth, predicted, classes):
    """Rows the truth, columns the prediction; points of no class (-1) are not counted."""
    counted = truth >= 0
    return np.bincount(truth[counted] * classes + predicted[counted], minlength=classes * classes).reshape(
        classes, classes
    )


def scores(confusion):
    with np.errstate(invalid="ignore", divide="ignore"):
        diagonal = np.diag(confusion).astype(float)
        true_count = confusion.sum(axis=1)
        predicted_count = confusion.sum(axis=0)
        iou = diagonal / (true_count + predicted_count - diagonal)
        f1 = 2 * diagonal / (true_count + predicted_count)
        present = true_count > 0  # the means are over the classes present in the truth
        return {
            "overall_accuracy": diagonal.sum() / confusion.sum(),
            "mean_iou": float(np.mean(iou[present])),
            "mean_f1": float(np.mean(f1[present])),
            "iou": iou,
            "f1": f1,
            "points": int(confusion.sum()),
        }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", type=pathlib.Path, default=None,
                        help="the folder of the six tiles (default: $SN_SHARED_DATA_DIR/labeled, else "
                        "../shared/data/labeled next to the repository)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("classification"),
                        help="folder of classification.md and classification.csv (default ./classification)")
    parser.add_argument("--sets", default="F,F_sigmoid",
                        help="comma-separated among F (equal weights), F_sigmoid (sigmoid weights), "
                        "F_both (both, no published counterpart); default F,F_sigmoid")
    parser.add_argument("--trees", type=int, default=25, help="as the command's forest (default 25)")
    parser.add_argument("--max-depth", type=int, default=20, help="as the command's forest (default 20)")
    parser.add_argument("--a", type=float, default=np.pi / 6, help="sigmoid a in radians (default pi/6)")
    parser.add_argument("--b", type=float, default=np.pi / 3, help="sigmoid b in radians (default pi/3)")
    parser.add_argument("--cells", type=float, nargs="+", default=[2.5, 5.0, 10.0],
                        help="cell sizes of the height features in metres (default 2.5 5 10)")
    parser.add_argument("--labels", default=DEFAULT_LABELS, help=f"class mapping (default {DEFAULT_LABELS})")
    parser.add_argument("--max-points", type=int, default=None,
                        help="keep this many random points of each tile (default: all)")
    parser.add_argument("--seed", type=int, default=1, help="of the subsample and the forest (default 1)")
    parser.add_argument("--threads", type=int, default=None, help="module threads and forest jobs (default: all)")
    args = parser.parse_args()

    try:
        from sklearn.ensemble import RandomForestClassifier
    except ImportError:
        print("classify_tiles.py needs scikit-learn (Debian: python3-sklearn)", file=sys.stderr)
        return 77
    set_groups = {
        "F": ("multiscale", "height"),
        "F_sigmoid": ("multiscale-sigmoid", "height"),
        "F_both": ("multiscale", "multiscale-sigmoid", "height"),
    }
    sets = args.sets.split(",")
    for s in sets:
        if s not in set_groups:
            parser.error(f"--sets: unknown set '{s}' (F, F_sigmoid, F_both)")
    if not 0 <= args.a <= args.b <= np.pi:
        parser.error("--a, --b: 0 <= a <= b <= pi")
    names, class_of_code = parse_labels(args.labels)

    data = args.data or default_data_dir()
    files = sorted(data.glob("ign_lidarhd_*.las"))
    train_files = [f for f in files if f.name.startswith(TRAIN_PREFIXES)]
    test_files = [f for f in files if f.name.startswith(TEST_PREFIXES)]
    if len(train_files) != 4 or len(test_files) != 2:
        print(f"expected 4 western and 2 eastern IGN tiles in {data}, found {len(train_files)} and "
              f"{len(test_files)}", file=sys.stderr)
        return 2

    rng = np.random.default_rng(args.seed)
    start = time.perf_counter()
    tiles = {path: tile_features(path, args, class_of_code, rng) for path in train_files + test_files}
    feature_seconds = time.perf_counter() - start

    def stack(paths, groups):
        columns = [name for name in tiles[paths[0]][0] if name[0] in groups]
        x = np.concatenate([np.column_stack([tiles[p][0][c] for c in columns]) for p in paths])
        y = np.concatenate([tiles[p][1] for p in paths])
        return x, y, [c[1] for c in columns]

    results = []
    for set_name in sets:
        x_train, y_train, columns = stack(train_files, set_groups[set_name])
        labeled = y_train >= 0  # points of no class are not trained on
        forest = RandomForestClassifier(n_estimators=args.trees, max_depth=args.max_depth,
                                        n_jobs=args.threads or -1, random_state=args.seed)
        t = time.perf_counter()
        forest.fit(x_train[labeled], y_train[labeled])
        train_seconds = time.perf_counter() - t
        x_test, y_test, _ = stack(test_files, set_groups[set_name])
        t = time.perf_counter()
        predicted = forest.predict(x_test)
        classify_seconds = time.perf_counter() - t
        confusion = confusion_matrix(y_test, predicted, len(names))
        results.append({
            "set": set_name,
            "features": len(columns),
            "train_points": int(labeled.sum()),
            "confusion": confusion,
            "train_seconds": train_seconds,
            "classify_seconds": classify_seconds,
            **scores(confusion),
        })

    args.out.mkdir(parents=True, exist_ok=True)
    markdown = report(results, names, args, feature_seconds, time.perf_counter() - start)
    (args.out / "classification.md").write_text(markdown)
    with open(args.out / "classification.csv", "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["set", "source", "features", "train_points", "test_points", "overall_accuracy",
                         "mean_f1", "mean_iou"] + [f"iou_{n}" for n in names] + [f"f1_{n}" for n in names]
                        + ["train_seconds", "classify_seconds"])
        for r in results:
            writer.writerow([r["set"], "module+sklearn", r["features"], r["train_points"], r["points"],
                             f"{r['overall_accuracy']:.6f}", f"{r['mean_f1']:.6f}", f"{r['mean_iou']:.6f}"]
                            + [f"{v:.6f}" for v in r["iou"]] + [f"{v:.6f}" for v in r["f1"]]
                            + [f"{r['train_seconds']:.2f}", f"{r['classify_seconds']:.2f}"])
            published = PUBLISHED.get(r["set"])
            if published and names == list(published["iou"]):
                writer.writerow([r["set"], "C++ classify (published)", r["features"], "", "",
                                 published["overall_accuracy"], published["mean_f1"], published["mean_iou"]]
                                + [published["iou"][n] for n in names] + [""] * len(names) + ["", ""])
    print(markdown)
    return 0


def report(results, names, args, feature_seconds, total_seconds):
    lines = [
        "# Classification of the IGN LiDAR HD tiles: module features + scikit-learn",
        "",
        f"Train: the four western tiles ({results[0]['train_points']:,} labeled points); test: the two eastern "
        f"ones ({results[0]['points']:,} labeled points). RandomForestClassifier, {args.trees} trees, depth "
        f"at most {args.max_depth}, seed {args.seed}. Sigmoid a = {np.degrees(args.a):g} deg, "
        f"b = {np.degrees(args.b):g} deg; height cells {', '.join(f'{c:g}' for c in args.cells)} m.",
    ]
    if args.max_points:
        lines.append(f"Each tile subsampled to {args.max_points:,} points (seed {args.seed}): the features are on a "
                     "thinner cloud and the numbers are not comparable with the published ones.")
    lines += [
        "",
        "| set | source | features | mean IoU | OA | mean F1 | "
        + " | ".join(f"IoU {n}" for n in names) + " | train + classify |",
        "|---|---|---:|---:|---:|---:|" + "---:|" * len(names) + "---:|",
    ]
    for r in results:
        lines.append(f"| {r['set']} | module + scikit-learn | {r['features']} | {r['mean_iou']:.3f} | "
                     f"{100 * r['overall_accuracy']:.1f} % | {r['mean_f1']:.3f} | "
                     + " | ".join(f"{v:.3f}" for v in r["iou"])
                     + f" | {r['train_seconds']:.1f} + {r['classify_seconds']:.1f} s |")
        published = PUBLISHED.get(r["set"])
        if published and names == list(published["iou"]):
            lines.append(f"| {r['set']} | C++ `classify` (published) | {r['features']} | {published['mean_iou']:.3f} | "
                         f"{100 * published['overall_accuracy']:.1f} % | {published['mean_f1']:.3f} | "
                         + " | ".join(f"{published['iou'][n]:.3f}" for n in names) + " | |")
    lines += [
        "",
        f"Published numbers: {PUBLISHED_SOURCE}.",
        "",
        f"Features of all six tiles: {feature_seconds:.1f} s; whole run: {total_seconds:.1f} s.",
    ]
    for r in results:
        lines += ["", f"Confusion matrix of {r['set']} (rows: truth, columns: prediction):", "",
                  "| truth \\ predicted | " + " | ".join(names) + " |",
                  "|---|" + "---:|" * len(names)]
        for t, row in enumerate(r["confusion"]):
            lines.append(f"| {names[t]} | " + " | ".join(str(int(v)) for v in row) + " |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
