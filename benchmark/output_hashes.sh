#!/usr/bin/env bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Runs every command of the tool on `make evaluate`'s corpus and on ../shared/data, and writes the
# SHA-256 of every output to OUTDIR/SHA256SUMS: a change that must keep outputs bit for bit (a
# refactoring) shows it by the same sums before and after. Timings and host facts (run.json,
# progress logs) are left out of the sums. Text tables (.csv, .xyz) are hashed by the values they
# parse to, each number as the exact bits of its double: the text of a number may change (the
# shortest one that reads back the same, since the writers format in parallel), its value may not.
#
#   benchmark/output_hashes.sh TOOL OUTDIR [CGAL_DATA_DIR] [SHARED_DATA_DIR]
#   diff OLD/SHA256SUMS NEW/SHA256SUMS
set -euo pipefail
tool=$(realpath "$1"); out=$2
corpus=${3:-build/cgal-data/data}; shared=${4:-../shared/data}
rm -rf "$out"; mkdir -p "$out/optimal" "$out/filter"
log="$out/log.txt"
run() { echo "+ $*" >> "$log"; "$@" >> "$log" 2>&1 || echo "exit $? : $*" >> "$out/exit_codes.txt"; }

if [ -d "$corpus/meshes" ]; then
  run "$tool" evaluate "$corpus/meshes" -o "$out/clean" --repository "CGAL meshes" --per-point
  run "$tool" evaluate "$corpus/points_3" -o "$out/scanned" --repository "CGAL point sets" --only-with-normals --per-point
  run "$tool" report "$out/clean" "$out/scanned" -o "$out/report" --figure-model "$corpus/meshes/fandisk.off"
  run "$tool" denoise-experiment -o "$out/table4" --seed 1 --fandisk "$corpus/meshes/fandisk.off"
  for barycenter in weighted unweighted; do
    run "$tool" optimal "$corpus/meshes/fandisk.off" -o "$out/optimal/fandisk_$barycenter.csv" \
      --ply "$out/optimal/fandisk_$barycenter.ply" --barycenter $barycenter
  done
fi
if [ -d "$shared" ]; then
  for f in "$shared"/clean/* "$shared"/scanned/* "$shared"/application/*.* "$shared"/application/noisy_reference/*; do
    name=$(basename "$f")
    run "$tool" optimal "$f" -o "$out/optimal/$name.csv" --ply "$out/optimal/$name.ply"
  done
  for f in "$shared"/application/*.* "$shared"/application/noisy_reference/*; do
    name=$(basename "$f")
    run "$tool" filter-normals "$f" -o "$out/filter/$name.xyz" --iterations 5
    run "$tool" filter-normals "$f" -o "$out/filter/$name.adaptive.ply" --iterations 3 --adaptive
  done
fi
# The sum of a text table's values: every field that reads as a number replaced by its double's bits.
values_sum() {
  /usr/bin/python3 - "$@" <<'PYTHON'
import hashlib, re, sys
split = re.compile(r'([,\s]+)')
def canonical(field):
    try:
        return float(field).hex()
    except ValueError:
        return field
for path in sys.argv[1:]:
    h = hashlib.sha256()
    with open(path) as f:
        for line in f:
            h.update(''.join(canonical(x) if i % 2 == 0 else x for i, x in enumerate(split.split(line))).encode())
    print('%s  %s' % (h.hexdigest(), path))
PYTHON
}
cd "$out"
mapfile -d '' tables < <(find . -type f \( -name '*.csv' -o -name '*.xyz' \) ! -name timings.csv -print0 | sort -z)
( find . -type f ! -name run.json ! -name timings.csv ! -name log.txt ! -name 'SHA256SUMS*' ! -name '*.log' \
    ! -name '*.csv' ! -name '*.xyz' -print0 | sort -z | xargs -0 -r sha256sum
  [ ${#tables[@]} -eq 0 ] || values_sum "${tables[@]}"
) | sort -k 2 > SHA256SUMS.tmp
cd - > /dev/null
mv "$out/SHA256SUMS.tmp" "$out/SHA256SUMS"
echo "$(wc -l < "$out/SHA256SUMS") outputs hashed: $out/SHA256SUMS"
