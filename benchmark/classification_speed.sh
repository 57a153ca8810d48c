#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# What a user pays to classify a survey with a model of each feature set: the whole
# `classify predict` run (reading, normals and neighbor rows where the set needs them, the features,
# the forest's prediction, the PLY written) on the two eastern IGN LiDAR HD tiles, one after the other,
# on one thread and on two, the median of REPEATS runs. Each set is trained once on the four western
# tiles (25 trees, depth 20, as classify train by default). The ratio is against the first set (give
# cgal, CGAL's generator, first). Each figure is the median [min, max] of the runs. Needs a quiet
# machine: the figures are wall times.
# usage: benchmark/classification_speed.sh TOOL OUT_DIR [REPEATS] [SETS]
#   SETS: NAME=GROUPS[ OPTION VALUE...] separated by ';', e.g.
#   "cgal=cgal;default=cgal-metric,multiscale-sigmoid,pyramid;fast=multiscale-sigmoid,pyramid,height --scales 10,25"
set -eu
tool=$1
out=$2
repeats=${3:-3}
sets=${4:-"cgal=cgal;default=cgal-metric,multiscale-sigmoid,pyramid"}
here=$(dirname "$0")
labeled=${SN_LABELED:-$here/../../shared/data/labeled}
west="77050_627755 77050_627760 77055_627755 77055_627760"
east="77060_627755 77060_627760"
mkdir -p "$out"

seconds() { # the wall time of a command, in seconds
  start=$(date +%s.%N)
  "$@" > /dev/null 2>&1 || { echo "failed: $*" >&2; exit 1; }
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }' 
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

printf '| set | groups and options | 1 thread (s) | 2 threads (s) | against cgal, 1 / 2 threads |\n|---|---|---:|---:|---|\n' \
  > "$out/speed.md"
base1=""; base2=""
echo "$sets" | tr ';' '\n' | while IFS= read -r spec; do
  [ -n "$spec" ] || continue
  name=${spec%%=*}
  rest=${spec#*=}
  groups=${rest%% *}
  options=""
  [ "$groups" = "$rest" ] || options=${rest#* }
  model="$out/$name.model"
  if [ ! -s "$model" ]; then
    # shellcheck disable=SC2086,SC2046
    "$tool" classify train $(for t in $west; do printf '%s ' "$labeled/ign_lidarhd_$t.las"; done) -o "$model" \
      --features "$groups" $options > "$out/$name.train.log" 2>&1 || { echo "$name: training failed" >&2; exit 1; }
  fi
  for threads in 1 2; do
    for r in $(seq 1 "$repeats"); do
      total=0
      for t in $east; do
        s=$(seconds "$tool" classify predict "$model" "$labeled/ign_lidarhd_$t.las" -o "$out/$name.$t.ply" --threads $threads)
        total=$(awk -v a="$total" -v b="$s" 'BEGIN { print a + b }')
      done
      echo "$total"
    done > "$out/$name.$threads.runs"
    median < "$out/$name.$threads.runs" > "$out/$name.$threads.txt"
  done
  t1=$(cat "$out/$name.1.txt"); t2=$(cat "$out/$name.2.txt")
  range() { sort -g "$out/$name.$1.runs" | awk 'NR == 1 { lo = $1 } { hi = $1 } END { printf "[%.2f, %.2f]", lo, hi }'; }
  [ -n "$base1" ] || { base1=$t1; base2=$t2; }
  printf '| %s | `%s` | %.2f %s | %.2f %s | %.2fx / %.2fx |\n' "$name" "$rest" "$t1" "$(range 1)" "$t2" "$(range 2)" \
    "$(awk -v a="$t1" -v b="$base1" 'BEGIN { print a / b }')" "$(awk -v a="$t2" -v b="$base2" 'BEGIN { print a / b }')" \
    >> "$out/speed.md"
  echo "$name: $t1 s on one thread, $t2 s on two"
done
cat "$out/speed.md"
