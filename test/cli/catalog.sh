#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# A catalog of four XYZ tiles written here: one tile per job through the Slurm recipe (with a
# stand-in sbatch) and the GNU parallel recipe (when installed), merged, equal byte for byte to the
# union in one run; a resumed run redoes only the missing tile; evaluate --catalog's per-point rows
# equal the union's; merge and optimal refuse what is
# wrong (exit 2, one line, nothing written).
# usage: catalog.sh TOOL STAND_IN_SBATCH_DIR RECIPE_DIR
set -eu
tool=$1
stand_ins=$2
recipes=$3
dir=catalog-test
rm -rf "$dir" && mkdir -p "$dir/tiles"
. "$(dirname "$0")/refusals.sh"

# 2 x 2 tiles of 20 x 20 m, a point every 0.5 m with a wavy ground and a roof; seams in both tiles
for tx in 0 1; do for ty in 0 1; do
  awk -v tx=$tx -v ty=$ty 'BEGIN { for(i = 0; i <= 40; ++i) for(j = 0; j <= 40; ++j) {
      x = 20 * tx + i / 2; y = 20 * ty + j / 2;
      z = 0.3 * sin(x / 3) * cos(y / 4) + ((x > 14 && x < 26 && y > 12 && y < 24) ? 4 + 0.2 * (x - 14) : 0);
      printf "%.2f %.2f %.3f\n", x, y, z } }' > "$dir/tiles/t_${tx}_${ty}.xyz"
done; done
options="--k-max 12 --a-grid 0,pi --b-grid 0,pi"

"$tool" catalog list "$dir/tiles" > "$dir/list.csv"
[ "$(wc -l < "$dir/list.csv")" -eq 4 ] || fail "catalog list: $(cat "$dir/list.csv")"
grep -q "^t_1_0,1681,20,0,40,20," "$dir/list.csv" || fail "catalog list row: $(cat "$dir/list.csv")"
"$tool" optimal --catalog "$dir/tiles" -o "$dir/union.csv" $options 2> "$dir/union.txt" || fail "union: $(cat "$dir/union.txt")"
[ "$(wc -l < "$dir/union.csv")" -eq 6562 ] || fail "union rows: $(wc -l < "$dir/union.csv")" # 81 x 81 + header

SIGMOID_NEIGHBORHOODS="$tool" PATH="$stand_ins:$PATH" "$recipes/optimal_tiles_with_slurm.sh" "$dir/tiles" "$dir/slurm" \
  $options > "$dir/slurm.txt" 2>&1 || fail "slurm recipe: $(cat "$dir/slurm.txt")"
cmp "$dir/union.csv" "$dir/slurm/union.csv" || fail "the Slurm recipe's union differs from one run"
grep -q '"exact": true' "$dir/slurm/tiles/t_0_1.tile.json" || fail "tile description"

if command -v parallel > /dev/null; then
  SIGMOID_NEIGHBORHOODS="$tool" "$recipes/optimal_tiles_with_parallel.sh" "$dir/tiles" "$dir/parallel" $options -- -j 2 \
    > "$dir/parallel.txt" 2>&1 || fail "parallel recipe: $(cat "$dir/parallel.txt")"
  cmp "$dir/union.csv" "$dir/parallel/union.csv" || fail "the GNU parallel recipe's union differs from one run"
  # resumed: the tile without its description is redone, the others are kept
  rm "$dir/parallel/tiles/t_1_0.tile.json" "$dir/parallel/union.csv"
  touch -d "2001-01-01" "$dir/parallel/tiles/t_0_0.csv"
  SIGMOID_NEIGHBORHOODS="$tool" "$recipes/optimal_tiles_with_parallel.sh" "$dir/tiles" "$dir/parallel" $options -- -j 2 \
    > "$dir/resume.txt" 2>&1 || fail "resume: $(cat "$dir/resume.txt")"
  grep -q "tile t_1_0" "$dir/resume.txt" || fail "t_1_0 not redone: $(cat "$dir/resume.txt")"
  grep -q "tile t_0_0" "$dir/resume.txt" && fail "t_0_0 redone"
  cmp "$dir/union.csv" "$dir/parallel/union.csv" || fail "the resumed union differs"
fi

# evaluate --catalog: every tile a model, its per-point rows those of the union as one file
cat "$dir/tiles/t_0_0.xyz" "$dir/tiles/t_0_1.xyz" "$dir/tiles/t_1_0.xyz" "$dir/tiles/t_1_1.xyz" > "$dir/union.xyz"
"$tool" evaluate --catalog "$dir/tiles" -o "$dir/evaluated" --per-point $options 2> "$dir/evaluate.txt" \
  || fail "evaluate --catalog: $(cat "$dir/evaluate.txt")"
"$tool" evaluate "$dir/union.xyz" -o "$dir/evaluated_union" --per-point --orientation up $options 2> "$dir/evaluate.txt" \
  || fail "evaluate union: $(cat "$dir/evaluate.txt")"
for t in t_0_0 t_0_1 t_1_0 t_1_1; do tail -n +2 "$dir/evaluated/models/$t.csv"; done > "$dir/evaluated_tiles.csv"
tail -n +2 "$dir/evaluated_union/models/union.xyz.csv" | cmp - "$dir/evaluated_tiles.csv" \
  || fail "evaluate --catalog: the tiles' per-point rows differ from the union's"
grep -q '"points": 6561' "$dir/evaluated/summary.json" || fail "evaluate --catalog summary: $(head -c 600 "$dir/evaluated/summary.json")"
"$tool" report "$dir/evaluated" -o "$dir/report" > /dev/null 2>&1 || fail "report of evaluate --catalog"

# merge refuses: a missing tile, a tile twice, other settings, rows missing, a foreign tile, bad JSON
t="$dir/slurm/tiles"
mkdir -p "$dir/other" "$dir/copy"
cp "$t/t_0_0.csv" "$t/t_0_0.tile.json" "$dir/copy/"
expect_refusal "tile t_0_0 is in two folders" "$tool" catalog merge "$dir/tiles" "$t" "$dir/copy" -o "$dir/m.csv"
mv "$t/t_1_1.tile.json" "$dir/other/"
expect_refusal "1 of 4 tiles have no output: t_1_1" "$tool" catalog merge "$dir/tiles" "$t" -o "$dir/m.csv"
"$tool" optimal --catalog "$dir/tiles" --tile t_1_1 -o "$t/t_1_1.csv" --k-max 10 2> /dev/null
expect_refusal "computed by 'optimal --k-max 10'" "$tool" catalog merge "$dir/tiles" "$t" -o "$dir/m.csv"
mv "$dir/other/t_1_1.tile.json" "$t/"
"$tool" optimal --catalog "$dir/tiles" --tile t_1_1 -o "$t/t_1_1.csv" $options 2> /dev/null
head -n 100 "$t/t_1_0.csv" > "$dir/short.csv" && cp "$dir/short.csv" "$t/t_1_0.csv"
expect_refusal "t_1_0.csv: 99 rows, its description says" "$tool" catalog merge "$dir/tiles" "$t" -o "$dir/m.csv"
"$tool" optimal --catalog "$dir/tiles" --tile t_1_0 -o "$t/t_1_0.csv" $options 2> /dev/null
mkdir -p "$dir/foreign" && cp "$dir/copy/t_0_0.tile.json" "$dir/foreign/t_9_9.tile.json"
expect_refusal "t_9_9.tile.json is not a tile of" "$tool" catalog merge "$dir/tiles" "$t" "$dir/foreign" -o "$dir/m.csv"
printf '{"tile": [[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]}' > "$t/t_0_0.tile.json"
expect_refusal "nested deeper" "$tool" catalog merge "$dir/tiles" "$t" -o "$dir/m.csv"
printf '{"tile": "t_0_0"' > "$t/t_0_0.tile.json"
expect_refusal "not valid JSON" "$tool" catalog merge "$dir/tiles" "$t" -o "$dir/m.csv"
[ ! -e "$dir/m.csv" ] || fail "a refused merge wrote its output"

# optimal refuses
expect_refusal "--tile and --halo go with --catalog" "$tool" optimal "$dir/tiles/t_0_0.xyz" --tile t_0_0 -o "$dir/x.csv"
expect_refusal "no tile named 'north'" "$tool" optimal --catalog "$dir/tiles" --tile north -o "$dir/x.csv"
expect_refusal "not both" "$tool" optimal "$dir/tiles/t_0_0.xyz" --catalog "$dir/tiles" -o "$dir/x.csv"
expect_refusal "--halo must be a width" "$tool" optimal --catalog "$dir/tiles" --tile t_0_0 --halo -1 -o "$dir/x.csv"
expect_refusal "no such folder or file" "$tool" optimal --catalog "$dir/absent" --tile t_0_0 -o "$dir/x.csv"
mkdir -p "$dir/empty"
expect_refusal "no tiles" "$tool" catalog list "$dir/empty"
[ ! -e "$dir/x.csv" ] || fail "a refused optimal wrote its output"
echo catalog-ok
