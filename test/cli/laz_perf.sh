#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# LAZ output read by an independent decoder: laz-perf 0.0.7 (npm, LASzip compiled to WebAssembly)
# decodes LAZ files written by the las_copy example (point-wise format 3 with extra bytes, layered
# formats 6 and 8 in several chunks, EVLRs) and by the tool (optimal on a point set: format 6 with
# float dimensions; catalog retile's LAZ tiles of a format 6 survey), and gives the records of
# their uncompressed copies. Skipped (exit 77) when node, npm or the npm registry is not there.
# usage: laz_perf.sh TOOL LAS_COPY SHARED_DATA_FOLDER NODE_SCRIPT
set -eu
tool=$1
las_copy=$2
data=$3
script=$4
dir=laz-perf-test
mkdir -p "$dir"
. "$(dirname "$0")/refusals.sh"
if ! command -v node > /dev/null || ! command -v npm > /dev/null; then
  echo "node or npm not found: laz-perf check skipped"
  exit 77
fi
if [ ! -f "$dir/npm/node_modules/laz-perf/package.json" ]; then
  timeout 300 npm install --prefix "$dir/npm" --no-audit --no-fund laz-perf@0.0.7 > "$dir/npm.log" 2>&1 || {
    echo "npm install laz-perf@0.0.7 failed (no registry?): laz-perf check skipped"
    exit 77
  }
fi

pairs=""
for name in simple test_data_77050_627755_LA93_IGN69 test_semis_2023_0292_6833_LA93_IGN69_extra_dims 1_4_w_evlr; do
  "$las_copy" "$data/laz/$name.laz" "$dir/$name.laz" --numbered --threads 2 > /dev/null || fail "$name: not written"
  "$las_copy" "$dir/$name.laz" "$dir/$name.las" > /dev/null || fail "$name: not read again"
  pairs="$pairs $dir/$name.laz=$dir/$name.las"
done
awk 'BEGIN { for(i = 0; i < 3000; ++i) { t = i * 2.39996; z = 1 - 2 * (i + 0.5) / 3000; r = sqrt(1 - z * z)
  printf "%.9f %.9f %.9f\n", 650000 + 3 * r * cos(t), 6860000 + 3 * r * sin(t), 100 + 3 * z } }' > "$dir/sphere.xyz"
"$tool" optimal "$dir/sphere.xyz" -o "$dir/sphere.laz" --k-max 10 --a-grid 0,pi --b-grid 0,pi 2> /dev/null \
  || fail "optimal to LAZ"
"$las_copy" "$dir/sphere.laz" "$dir/sphere.las" > /dev/null || fail "optimal's LAZ not read again"
pairs="$pairs $dir/sphere.laz=$dir/sphere.las"
rm -rf "$dir/retiled"
"$tool" catalog retile "$data/laz/test_data_77050_627755_LA93_IGN69.laz" --size 20 -o "$dir/retiled" 2> /dev/null \
  || fail "catalog retile to LAZ"
for tile in "$dir"/retiled/*.laz; do
  "$las_copy" "$tile" "${tile%.laz}.las" > /dev/null || fail "$tile: not read again"
  pairs="$pairs $tile=${tile%.laz}.las"
done
node "$script" "$dir/npm/node_modules" $pairs
