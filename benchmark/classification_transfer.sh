#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Classification across densities on the six IGN LiDAR HD tiles (../shared/data/labeled): trained on
# the four western tiles, tested on the two eastern ones, as `make classification` does, but with the
# training tiles thinned 2x and 4x (random and voxel thinning: benchmark/thin_las.py), and the
# reverse (trained at full density, tested on thinned copies). Each condition is one
# `classify experiment` (its feature orders, and the leave-one-tile-out cross-validation on the
# training tiles where asked); benchmark/transfer_table.py gathers the mean IoU of each set and its
# drop from the same-density result.
# usage: benchmark/classification_transfer.sh TOOL OUT_DIR [ORDERS] [SETS] [FEATURE OPTIONS...]
#   e.g.  benchmark/classification_transfer.sh build/tools/sigmoid-neighborhoods/sigmoid-neighborhoods results/transfer 10
#   the feature options of classify experiment (e.g. --cgal-voxel 0.5) apply to every set
set -eu
tool=$1
out=$2
orders=${3:-10}
sets=${4:-"A=cgal;G_multiscale_sigmoid=cgal,multiscale-sigmoid;P=pyramid;P_sigmoid=pyramid-sigmoid;H_pyramid_sigmoid=cgal,pyramid-sigmoid"}
shift $(( $# < 4 ? $# : 4 ))
options="$*" # words without spaces: run() has its own arguments
here=$(dirname "$0")
labeled=${SN_LABELED:-$here/../../shared/data/labeled}
python=/usr/bin/python3
west="77050_627755 77050_627760 77055_627755 77055_627760"
east="77060_627755 77060_627760"
mkdir -p "$out/tiles"

list() { # the tiles $2.. of folder $1, comma-separated
  folder=$1; shift
  echo "$@" | tr ' ' '\n' | sed "s|^|$folder/ign_lidarhd_|; s|$|.las|" | paste -sd, -
}
for method in random voxel; do
  for factor in 2 4; do
    mkdir -p "$out/tiles/${method}$factor"
    for t in $west $east; do
      [ -s "$out/tiles/${method}$factor/ign_lidarhd_$t.las" ] ||
        "$python" "$here/thin_las.py" "$labeled/ign_lidarhd_$t.las" "$out/tiles/${method}$factor/ign_lidarhd_$t.las" \
          --factor $factor --method $method > /dev/null
    done
  done
done

run() { # condition, training folder, test folder, cross-validation orders
  [ -s "$out/$1/runs.csv" ] && { echo "$1: done before"; return; }
  start=$(date +%s)
  "$tool" classify experiment -o "$out/$1" --train "$(list "$2" $west)" --test "$(list "$3" $east)" \
    --sets "$sets" --orders "$orders" --cv-orders "$4" --graphcut 0 $options > "$out/$1.log" 2>&1 ||
    { echo "$1 failed: $(tail -1 "$out/$1.log")"; exit 1; }
  echo "$1: $(( $(date +%s) - start )) s"
}
run same "$labeled" "$labeled" 1
run train_random4 "$out/tiles/random4" "$labeled" 1
run train_voxel4 "$out/tiles/voxel4" "$labeled" 1
run train_random2 "$out/tiles/random2" "$labeled" 0
run train_voxel2 "$out/tiles/voxel2" "$labeled" 0
run test_random4 "$labeled" "$out/tiles/random4" 0
run test_voxel4 "$labeled" "$out/tiles/voxel4" 0
"$python" "$here/transfer_table.py" "$out"
