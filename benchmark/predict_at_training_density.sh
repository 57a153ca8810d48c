#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# A model trained on a thinned survey, applied to a denser one: predicted on the dense points as they
# are, or on a copy thinned as the training data was and the labels carried to every dense point from
# its nearest predicted point (benchmark/propagate_labels.py). The IGN LiDAR HD tiles: trained on the
# four western tiles thinned (THINNED_DIR, as classification_transfer.sh writes OUT/tiles/random4),
# tested on the two eastern ones at full density, in ORDERS feature orders, for each feature set.
# usage: benchmark/predict_at_training_density.sh TOOL OUT_DIR THINNED_DIR [ORDERS] [SETS]
set -eu
tool=$1
out=$2
thinned=$3
orders=${4:-3}
sets=${5:-"cgal,multiscale-sigmoid pyramid cgal"}
here=$(dirname "$0")
labeled=${SN_LABELED:-$here/../../shared/data/labeled}
west="77050_627755 77050_627760 77055_627755 77055_627760"
east="77060_627755 77060_627760"
tiles() { folder=$1; suffix=$2; shift 2; for t in "$@"; do printf '%s ' "$folder/ign_lidarhd_$t$suffix"; done; }
comma() { echo "$@" | tr ' ' ','; }

for features in $sets; do
  for seed in $(seq 1 "$orders"); do
    run="$out/$(echo "$features" | tr ',' '+')-$seed"
    mkdir -p "$run"
    if [ ! -s "$run/dense.txt" ]; then
      # shellcheck disable=SC2046
      "$tool" classify train $(tiles "$thinned" .las $west) -o "$run/model.json" --features "$features" \
        --feature-order-seed "$seed" > "$run/train.log" 2>&1
      for t in $east; do
        "$tool" classify predict "$run/model.json" "$labeled/ign_lidarhd_$t.las" -o "$run/dense_$t.ply" > /dev/null 2>&1
        "$tool" classify predict "$run/model.json" "$thinned/ign_lidarhd_$t.las" -o "$run/thinned_$t.ply" > /dev/null 2>&1
      done
      for kind in dense thinned; do
        # shellcheck disable=SC2046
        /usr/bin/python3 "$here/propagate_labels.py" --truth "$(comma $(tiles "$labeled" .las $east))" \
          --predicted "$(comma $(for t in $east; do printf '%s ' "$run/${kind}_$t.ply"; done))" > "$run/$kind.txt"
      done
      rm -f "$run"/*.ply "$run/model.json"
    fi
    echo "$features order $seed: dense: $(cat "$run/dense.txt")"
    echo "$features order $seed: thinned, labels carried: $(cat "$run/thinned.txt")"
  done
done
