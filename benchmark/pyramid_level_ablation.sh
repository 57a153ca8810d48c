#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Where the sigmoid weights help, per level of the pyramid and per class (benchmark/README.md,
# "Classification across densities"): each cell size alone (`--pyramid-levels 1`), the groups
# `pyramid` and `pyramid-sigmoid`, trained on the four western IGN LiDAR HD tiles and evaluated on the
# two eastern ones, in ORDERS feature orders; with THINNED_DIR (thinned copies of the tiles, as
# classification_transfer.sh writes them in OUT/tiles/random4), trained on those too. Prints the
# table: mean IoU of each group, the sigmoid's gain, and its gain per class.
# usage: benchmark/pyramid_level_ablation.sh TOOL OUT_DIR [ORDERS] [THINNED_DIR]
set -eu
tool=$1
out=$2
orders=${3:-3}
thinned=${4:-}
here=$(dirname "$0")
labeled=${SN_LABELED:-$here/../../shared/data/labeled}
west="77050_627755 77050_627760 77055_627755 77055_627760"
east="77060_627755 77060_627760"
tiles() { folder=$1; shift; for t in "$@"; do printf '%s ' "$folder/ign_lidarhd_$t.las"; done; }

conditions="same"
[ -n "$thinned" ] && conditions="same thinned"
for condition in $conditions; do
  train_folder=$labeled
  [ "$condition" = thinned ] && train_folder=$thinned
  for cell in 0.5 1 2 4 8; do
    for group in pyramid pyramid-sigmoid; do
      for seed in $(seq 1 "$orders"); do
        run="$out/$condition/$group-$cell-$seed"
        [ -s "$run/evaluation.json" ] && continue
        mkdir -p "$run"
        # shellcheck disable=SC2046
        "$tool" classify train $(tiles "$train_folder" $west) -o "$run/model.json" --features "$group" \
          --pyramid-cell "$cell" --pyramid-levels 1 --feature-order-seed "$seed" --orientation up > "$run/train.log" 2>&1
        # shellcheck disable=SC2046
        "$tool" classify evaluate "$run/model.json" $(tiles "$labeled" $east) -o "$run" > "$run/evaluate.log" 2>&1
        rm -f "$run/model.json"
        echo "$condition $group cell $cell order $seed done"
      done
    done
  done
done

/usr/bin/python3 - "$out" $conditions <<'PY'
import json, pathlib, statistics, sys
out = pathlib.Path(sys.argv[1])
for condition in sys.argv[2:]:
    print(f"\n{condition}: mean IoU per level alone (mean over orders), the sigmoid's gain, and per class")
    classes = None
    rows = []
    for cell in ["0.5", "1", "2", "4", "8"]:
        means, per_class = {}, {}
        for group in ["pyramid", "pyramid-sigmoid"]:
            runs = [json.load(open(p)) for p in sorted((out / condition).glob(f"{group}-{cell}-*/evaluation.json"))]
            means[group] = statistics.mean(r["mean_iou"] for r in runs)
            classes = runs[0]["classes"]
            per_class[group] = [statistics.mean(r["per_class"][c]["iou"] for r in runs) for c in classes]
        gains = [s - p for s, p in zip(per_class["pyramid-sigmoid"], per_class["pyramid"])]
        rows.append((cell, means["pyramid"], means["pyramid-sigmoid"], gains))
    print("| cell (m) | pyramid | pyramid-sigmoid | gain | " + " | ".join(f"gain {c}" for c in classes) + " |")
    print("|---:|---:|---:|---:|" + "---:|" * len(classes))
    for cell, p, s, gains in rows:
        print(f"| {cell} | {p:.3f} | {s:.3f} | {s - p:+.3f} | " + " | ".join(f"{g:+.3f}" for g in gains) + " |")
PY
