#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Cross-validation across densities on the four western IGN tiles (the training tiles of
# benchmark/classification_transfer.sh, nothing of the two test tiles): each tile left out in turn,
# the forest trained on the three others thinned (random, 4x) and tested on the left-out tile at full
# density. With the leave-one-out cross-validation at one density that `classify experiment` computes,
# this is what the default feature set of `classify train` is chosen on (benchmark/README.md).
# usage: benchmark/classification_transfer_cv.sh TOOL OUT_DIR [SETS] [THINNING] [FEATURE OPTIONS...]
#   OUT_DIR as given to classification_transfer.sh (its thinned tiles are reused); THINNING: random4;
#   the feature options of classify experiment (e.g. --cgal-voxel 0.5) apply to every set;
#   CV_ORDERS=N: each fold in N feature orders (default 1), the fold's score their mean
set -eu
tool=$1
out=$2
sets=${3:-"A=cgal;G_multiscale_sigmoid=cgal,multiscale-sigmoid;P=pyramid;P_sigmoid=pyramid-sigmoid;H_pyramid=cgal,pyramid;H_pyramid_sigmoid=cgal,pyramid-sigmoid"}
thinning=${4:-random4}
shift $(( $# < 4 ? $# : 4 ))
here=$(dirname "$0")
labeled=${SN_LABELED:-$here/../../shared/data/labeled}
west="77050_627755 77050_627760 77055_627755 77055_627760"
[ -d "$out/tiles/$thinning" ] || { echo "run classification_transfer.sh first: $out/tiles/$thinning" >&2; exit 1; }
for left in $west; do
  folder="$out/cv_$thinning/without_$left"
  [ -s "$folder/runs.csv" ] && continue
  train=$(for t in $west; do [ "$t" = "$left" ] || printf '%s,' "$out/tiles/$thinning/ign_lidarhd_$t.las"; done)
  mkdir -p "$out/cv_$thinning"
  "$tool" classify experiment -o "$folder" --train "${train%,}" --test "$labeled/ign_lidarhd_$left.las" \
    --sets "$sets" --orders "${CV_ORDERS:-1}" --cv-orders 0 --graphcut 0 "$@" > "$folder.log" 2>&1 ||
    { echo "fold $left failed: $(tail -1 "$folder.log")"; exit 1; }
  echo "fold without $left done"
done
# the mean IoU of each set over the four folds (each fold's held-out tile at full density)
/usr/bin/python3 - "$out/cv_$thinning" <<'EOF'
import json, os, sys
folds = sorted(d for d in os.listdir(sys.argv[1]) if d.startswith("without_") and not d.endswith(".log"))
scores = {}
for d in folds:
    for s in json.load(open(os.path.join(sys.argv[1], d, "experiment.json")))["sets"]:
        if not s["graphcut"]:
            scores.setdefault(s["set"], []).append(s["mean_iou"]["mean"])
print("| set | cross-validated mean IoU, trained thinned, tested at full density (mean of %d folds) |" % len(folds))
print("|---|---:|")
for name, values in scores.items():
    print("| %s | %.3f |" % (name, sum(values) / len(values)))
EOF
