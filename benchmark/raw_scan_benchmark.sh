#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# `optimal` end to end on a scan without normals against the same points with normals given, for
# each normal method and thread count: wall time and peak memory (GNU time), fastest of REPEAT runs.
#
#   benchmark/raw_scan_benchmark.sh TOOL SCAN.ply [THREADS...]     (REPEAT=3 by default)
#
# The points with normals are the scan with its default estimated normals, written once by
# `filter-normals --iterations 0` as a binary PLY of x y z nx ny nz (what a scan with normals is).
set -eu
tool=$1
scan=$2
shift 2
threads=${*:-"1 2"}
repeat=${REPEAT:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tool" filter-normals "$scan" -o "$work/with_normals.ply" --iterations 0 2>/dev/null

# the fastest wall time and its peak resident memory of $repeat runs of `optimal "$@"`
measure() {
  best=""
  i=0
  while [ "$i" -lt "$repeat" ]; do
    /usr/bin/time -f "%e %M" -o "$work/time" "$tool" optimal "$@" -o "$work/out.csv" 2>"$work/err" >/dev/null
    read -r seconds kilobytes <"$work/time"
    if [ -z "$best" ] || awk "BEGIN { exit !($seconds < $best) }"; then best=$seconds; memory=$kilobytes; fi
    i=$((i + 1))
  done
  echo "$best $((memory / 1024))"
}

echo "| threads | input | seconds | peak MB | time / with normals | memory / with normals |"
echo "|---:|---|---:|---:|---:|---:|"
for t in $threads; do
  set -- $(measure "$work/with_normals.ply" --threads "$t")
  base_s=$1 base_m=$2
  echo "| $t | normals given | $base_s | $base_m | 1 | 1 |"
  for method in pca jet; do
    set -- $(measure "$scan" --threads "$t" --normals "$method")
    echo "| $t | raw, $method | $1 | $2 | $(awk "BEGIN { printf \"%.2f\", $1 / $base_s }") | $(awk "BEGIN { printf \"%.2f\", $2 / $base_m }") |"
  done
done
