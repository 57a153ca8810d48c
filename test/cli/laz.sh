#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Every command reads a LAZ file like its uncompressed twin: two IGN LiDAR HD tiles of ../shared/data,
# compressed (laz/) and not (labeled/), through optimal, evaluate, classify train, predict, evaluate
# and experiment, and a catalog of LAZ tiles with halos; the outputs equal byte for byte. A damaged
# LAZ file exits 2 with one line naming the file and the chunk, and writes nothing.
# usage: laz.sh TOOL SHARED_DATA_FOLDER
set -eu
tool=$1
data=$2
dir=laz-test
rm -rf "$dir" && mkdir -p "$dir/las" "$dir/laz" "$dir/out"
. "$(dirname "$0")/refusals.sh"

for tile in 77050_627755 77050_627760; do
  ln -s "$data/labeled/ign_lidarhd_$tile.las" "$dir/las/t_$tile.las"
  ln -s "$data/laz/test_data_${tile}_LA93_IGN69.laz" "$dir/laz/t_$tile.laz"
done
same() { # a command run on the twin of each format; its output files (given after --) equal
  what=$1; shift
  for format in las laz; do
    # shellcheck disable=SC2046
    eval "\"\$tool\" $(echo "$*" | sed "s/@F/$format/g")" > "$dir/out/$what.$format.txt" 2>&1 \
      || fail "$what on $format: $(cat "$dir/out/$what.$format.txt")"
  done
}
compare() { cmp "$dir/out/$1.las$2" "$dir/out/$1.laz$2" || fail "$1: LAZ and LAS outputs differ ($2)"; }

options="--k-max 10 --a-grid 0,pi --b-grid 0,pi"
same optimal "optimal $dir/@F/t_77050_627760.@F -o $dir/out/optimal.@F.csv $options"
compare optimal .csv
same evaluate "evaluate $dir/@F/t_77050_627760.@F -o $dir/out/evaluate.@F --per-point $options"
cmp "$dir/out/evaluate.las/models/t_77050_627760.las.csv" "$dir/out/evaluate.laz/models/t_77050_627760.laz.csv" \
  || fail "evaluate: per-point rows differ"

same train "classify train $dir/@F/t_77050_627755.@F -o $dir/out/train.@F.bin --features k20,height --trees 3 --depth 8"
compare train .bin
same predict "classify predict $dir/out/train.las.bin $dir/@F/t_77050_627760.@F -o $dir/out/predict.@F.ply"
compare predict .ply
same classify_evaluate "classify evaluate $dir/out/train.las.bin $dir/@F/t_77050_627760.@F -o $dir/out/classify_evaluate.@F"
compare classify_evaluate /evaluation.csv
same experiment "classify experiment --train $dir/@F/t_77050_627755.@F --test $dir/@F/t_77050_627760.@F \
  --sets small=k20 --orders 1 --graphcut 0 --trees 2 --depth 6 -o $dir/out/experiment.@F"
for format in las laz; do cut -d, -f1-10 "$dir/out/experiment.$format/runs.csv" > "$dir/out/runs.$format"; done # no times
cmp "$dir/out/runs.las" "$dir/out/runs.laz" || fail "experiment: results differ"

# a catalog of LAZ tiles: each tile with its halo
same catalog "classify predict $dir/out/train.las.bin --catalog $dir/@F --tile t_77050_627755 -o $dir/out/catalog.@F.ply"
compare catalog .ply

# damaged: the chunk table's first coded bytes set to 0xFF; the file named, nothing written
cp "$data/laz/simple.laz" "$dir/damaged.laz"
table=$(od -A n -t u4 -j "$(od -A n -t u4 -j 96 -N 4 "$dir/damaged.laz" | tr -d ' ')" -N 4 "$dir/damaged.laz" | tr -d ' ')
printf '\377\377\377\377\377\377\377\377' | dd of="$dir/damaged.laz" bs=1 seek=$((table + 8)) conv=notrunc 2> /dev/null
expect_refusal "damaged.laz: cannot decode the file as laz (" "$tool" optimal "$dir/damaged.laz" -o "$dir/damaged.csv"
grep -q "chunk 0 of 1" "$dir/err.txt" || fail "the chunk is not named: $(cat "$dir/err.txt")"
[ ! -e "$dir/damaged.csv" ] || fail "a damaged file wrote its output"
expect_refusal "wave packets" "$tool" optimal "$data/laz/fullwave.laz" -o "$dir/fullwave.csv"
echo "laz-ok"
