#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# benchmark/generate_survey on a tiny survey: 4 tiles, every one a valid LAS 1.4 format 6 file
# (check_las_tiles.py: counts, bounding boxes, every point in its tile's cell, classes 2, 5, 6),
# read by 'catalog list', 50,000 points within 3 %, the same bytes for the same seed; one tile
# computed with its halo. Then 'catalog retile' of a generated 30 MB tile within --buffer 1 MiB:
# a peak resident size far below the input's size.
# usage: generate_survey.sh TOOL GENERATOR PYTHON CHECKER
set -eu
tool=$1
generator=$2
python=$3
checker=$4
dir=survey-test
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "FAILED: $*"; exit 1; }

"$generator" 50000 "$dir/survey" --tile-size 30 --seed 3 2> "$dir/generate.txt" || fail "$(cat "$dir/generate.txt")"
grep -q "points in 2 x 2 tiles of 30 m" "$dir/generate.txt" || fail "summary: $(cat "$dir/generate.txt")"
"$python" "$checker" survey "$dir/survey" 50000 0.03 30 > "$dir/check.txt" || fail "$(cat "$dir/check.txt")"
"$tool" catalog list "$dir/survey" > "$dir/list.txt" || fail "catalog list"
[ "$(cut -d, -f1 "$dir/list.txt" | tr '\n' ' ')" = "survey_0_0 survey_0_1 survey_1_0 survey_1_1 " ] \
  || fail "catalog list: $(cat "$dir/list.txt")"
points=$(awk -F, '{ s += $2 } END { print s }' "$dir/list.txt")
[ "$points" -ge 48500 ] && [ "$points" -le 51500 ] || fail "$points points, not 50000 within 3 %"

"$generator" 50000 "$dir/again" --tile-size 30 --seed 3 2> /dev/null
for f in "$dir"/survey/*.las; do cmp -s "$f" "$dir/again/$(basename "$f")" || fail "$f: not the same bytes again"; done
"$generator" 50000 "$dir/other" --tile-size 30 --seed 4 2> /dev/null
cmp -s "$dir/survey/survey_0_0.las" "$dir/other/survey_0_0.las" && fail "another seed, the same survey"

mkdir "$dir/tile"
"$tool" optimal --catalog "$dir/survey" --tile survey_1_0 -o "$dir/tile/survey_1_0.csv" --orientation up \
  --threads 2 2> "$dir/tile.txt" || fail "optimal --tile: $(cat "$dir/tile.txt")"
[ -s "$dir/tile/survey_1_0.tile.json" ] || fail "no tile description"

status=0; "$generator" 0 "$dir/none" 2> "$dir/err.txt" || status=$?
[ "$status" -eq 2 ] && grep -q "POINTS must be" "$dir/err.txt" || fail "0 points: exit $status"
status=0; "$generator" 1000 "$dir/none" --tile-size 0.005 2> "$dir/err.txt" || status=$?
[ "$status" -eq 2 ] && grep -q -- "--tile-size" "$dir/err.txt" || fail "bad --tile-size: exit $status"

# retile streams: a 30 MB tile cut into 10 m tiles within --buffer 1
"$generator" 1e6 "$dir/large" --tile-size 260 2> /dev/null
[ "$(find "$dir/large" -name '*.las' | wc -l)" -eq 1 ] || fail "not one large tile"
if [ -x /usr/bin/time ]; then
  /usr/bin/time -v -o "$dir/retile.time" "$tool" catalog retile "$dir/large/survey_0_0.las" --size 10 -o "$dir/cut" \
    --buffer 1 2> "$dir/retile.txt" || fail "retile: $(cat "$dir/retile.txt")"
  peak=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$dir/retile.time")
  [ "$peak" -lt 25000 ] || fail "retile of a 30 MB file with --buffer 1: peak $peak kB"
else
  "$tool" catalog retile "$dir/large/survey_0_0.las" --size 10 -o "$dir/cut" --buffer 1 2> "$dir/retile.txt"
fi
large=$("$tool" catalog list "$dir/large" | cut -d, -f2)
[ "$("$tool" catalog list "$dir/cut" | awk -F, '{ s += $2 } END { print s }')" -eq "$large" ] || fail "retile lost points"
echo survey-ok
