#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The hostile evaluation files of test/data/bad_evaluation/EXPECTED.txt, and generated ones too
# large for the repository: each replaces one file of a valid evaluation folder, and `report` and
# `merge` on that folder must exit with the expected code, one line naming the file and what is
# wrong, no output, within 256 MiB of address space and 5 s of CPU time (limits, not timings).
#
#   bad_evaluation.sh TOOL CORPUS_DIR WORK_DIR
set -eu
tool=$1; corpus=$2; work=$3
tab=$(printf '\t')
rm -rf "$work"; mkdir -p "$work/in/sub"

# a valid evaluation: two spheres with normals, an unreadable file, a model too small for the grid
sphere() {
  awk -v n="$1" -v s="$2" 'BEGIN { for(i = 0; i < n; ++i) { z = 1 - 2 * (i + 0.5) / n; r = sqrt(1 - z * z); p = 2.399963229728653 * i;
    printf "%.17g %.17g %.17g %.17g %.17g %.17g\n", s * r * cos(p), s * r * sin(p), s * z, r * cos(p), r * sin(p), z } }'
}
sphere 60 1 > "$work/in/sphere.xyz"
sphere 40 2 > "$work/in/sub/sphere.xyz"
: > "$work/in/broken.xyz"
sphere 8 1 > "$work/in/tiny.xyz"
"$tool" evaluate "$work/in" -o "$work/base" --repository hostile --threads 1 2> "$work/evaluate.log"
# on 3 threads the next models are read ahead: the same results and failures, reported for the same models
"$tool" evaluate "$work/in" -o "$work/base3" --repository hostile --threads 3 2> "$work/evaluate3.log"
for file in failures.json summary.json models/sphere.xyz.json models/sub/sphere.xyz.json; do
  cmp "$work/base/$file" "$work/base3/$file" || { echo "read ahead: $file differs"; exit 1; }
done
if [ "$(sed 's/ (.*//' "$work/evaluate.log" | head -n 4)" != "$(sed 's/ (.*//' "$work/evaluate3.log" | head -n 4)" ]; then
  echo "read ahead: other progress lines"; cat "$work/evaluate.log" "$work/evaluate3.log"; exit 1
fi
grep -q "^\[1/4\] broken.xyz: FAILED: the file is empty" "$work/evaluate3.log" || { echo "read ahead: no failure"; exit 1; }
"$tool" merge "$work/base" -o "$work/merged_ok" 2> /dev/null

cases=0
commands="report merge"
# check NAME FOLDER... EXPECTED_CODE MESSAGE_PIECE FILE: report and merge on the folders
check() {
  name=$1; folder=$2; code=$3; piece=$4; file=$5; shift 5
  for command in $commands; do
    out="$work/out_${cases}_$command"
    rm -rf "$out"
    status=0
    echo "no /usr/bin/time" > "$work/time.txt"
    # AddressSanitizer reserves terabytes of shadow memory: under it (SN_SANITIZED) no address-space
    # limit; the CPU limit stays
    ( [ -n "${SN_SANITIZED:-}" ] || ulimit -v 262144; ulimit -t 5
      if [ -x /usr/bin/time ]; then
        exec /usr/bin/time -f "%e s, %M KiB" -o "$work/time.txt" "$tool" $command "$folder" "$@" -o "$out"
      fi
      exec "$tool" $command "$folder" "$@" -o "$out" ) 2> "$work/err.txt" || status=$?
    message=$(cat "$work/err.txt")
    if [ "$status" -ne "$code" ]; then echo "$name: $command exits $status, expected $code: $message"; exit 1; fi
    if [ "$(wc -l < "$work/err.txt")" -ne 1 ]; then echo "$name: $command writes more than one line: $message"; exit 1; fi
    case "$message" in
      "sigmoid-neighborhoods $command: "*"$file: "*"$piece"*) ;;
      "sigmoid-neighborhoods $command: "*".json: "*"$piece"*) [ "$file" = "*" ] || { echo "$name: $command names another file: $message"; exit 1; } ;;
      *) echo "$name: $command says '$message', expected '$file: ...$piece'"; exit 1;;
    esac
    if [ -e "$out" ]; then echo "$name: $command wrote $out"; exit 1; fi
    echo "$name: $command exit $status, $(tail -n 1 "$work/time.txt")"
  done
  cases=$((cases + 1))
}

# replace FILE TARGET: a copy of the valid folder with TARGET replaced by FILE
replace() {
  folder="$work/case_$cases"
  rm -rf "$folder"; cp -r "$work/base" "$folder"
  cp "$1" "$folder/$2"
}

while IFS="$tab" read -r file target code piece; do
  case "$file" in ''|'#'*) continue;; esac
  replace "$corpus/$file" "$target"
  # a model named in failures.json is refused in the model's file or in failures.json
  [ "$file" = failures_lists_an_evaluated_model.json ] && target='*'
  check "$file" "$folder" "$code" "$piece" "$target"
done < "$corpus/EXPECTED.txt"

# generated: too large for the repository
replace /dev/null models/sphere.xyz.json
head -c 400000 /dev/zero | tr '\0' '[' > "$folder/models/sphere.xyz.json"
check "400 KB of nested brackets" "$folder" 2 "nested deeper than 16" models/sphere.xyz.json
replace /dev/null failures.json
{ printf '{"failures": '; head -c 400000 /dev/zero | tr '\0' '['; } > "$folder/failures.json"
check "400 KB of nested brackets in failures.json" "$folder" 2 "nested deeper than 16" failures.json
replace /dev/null failures.json
awk 'BEGIN { printf "["; for(i = 0; i < 2097000; ++i) printf "0,"; print "0]" }' > "$folder/failures.json"
check "an array of 2,097,001 numbers within 4 MiB" "$folder" 2 "the file is an array, expected an object" failures.json
replace /dev/null failures.json
head -c 4194305 /dev/zero | tr '\0' ' ' > "$folder/failures.json"
check "a failures.json of 4 MiB + 1 byte" "$folder" 2 "larger than the 4 MiB" failures.json
replace /dev/null models/sphere.xyz.json
{ printf '{"model": "sphere.xyz", "settings": {"a_grid": ['; seq 1 10000000 | tr '\n' ','; printf '0]}}\n'; } \
  > "$folder/models/sphere.xyz.json"
check "an a_grid of 10,000,000 values" "$folder" 2 "larger than the 1 MiB" models/sphere.xyz.json
rm -f "$folder/models/sphere.xyz.json"
replace /dev/null models/sphere.xyz.json
awk 'BEGIN { printf "{\"model\": \"sphere.xyz\", \"settings\": {\"k_min\": ["; for(i = 0; i < 500000; ++i) printf "0,"; print "0]}}" }' \
  > "$folder/models/sphere.xyz.json"
check "an array of 500,000 numbers within 1 MiB" "$folder" 2 "settings.k_min is an array, expected an integer" models/sphere.xyz.json
replace /dev/null models/sphere.xyz.json
awk '{ print } /"pair_k_histogram": \[/ { for(i = 0; i < 400000; ++i) printf "0,"; printf "\n" }' \
  "$work/base/models/sphere.xyz.json" > "$folder/models/sphere.xyz.json"
check "a pair_k_histogram of 400,420 entries" "$folder" 2 "pair_k_histogram has 400420 entries" models/sphere.xyz.json
replace /dev/null models/sphere.xyz.json
awk 'BEGIN { printf "{\"model\": \"sphere.xyz\", \"settings\": {\"k_min\": 6, \"k_max\": 20, \"fixed_k\": 20, \"barycenter\": \"";
  for(i = 0; i < 900000; ++i) printf "a"; print "\"}}" }' > "$folder/models/sphere.xyz.json"
check "a string of 900,000 bytes" "$folder" 2 "settings.barycenter is a string of 900000 bytes" models/sphere.xyz.json
replace /dev/null summary.json
head -c 1048577 /dev/zero | tr '\0' ' ' > "$folder/summary.json"
check "a summary of 1 MiB of spaces" "$folder" 2 "more than twice the" summary.json
replace /dev/null summary.json
head -c 3000 "$work/base/summary.json" > "$folder/summary.json"
head -c 60000 /dev/zero | tr '\0' ' ' >> "$folder/summary.json"
check "a truncated summary padded with 60 KB of spaces" "$folder" 2 "not valid JSON" summary.json

# a model in two shards
cp -r "$work/base" "$work/shard_copy"
commands=merge
check "a model in two shards" "$work/base" 2 "is also in" '*' "$work/shard_copy"
# merge FOLDER -o FOLDER rewrites an edited summary (or one of an earlier version) from the model files
replace "$corpus/summary_points_edited.json" summary.json
"$tool" merge "$folder" -o "$folder" 2> "$work/err.txt" || { echo "merge in place: $(cat "$work/err.txt")"; exit 1; }
cmp "$folder/summary.json" "$work/base/summary.json" || { echo "merge in place: another summary"; exit 1; }
echo "bad-evaluation-ok $cases cases"
