#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# classify predict on a catalog of tiles: a small model trained on one IGN tile predicts each tile with
# its halo and the union in one run; the tiles' PLY vertices, concatenated in the catalog's order, equal
# the union's byte for byte (positions, labels, confidences, truth, colors). Then the refusals with
# --tile (the group cgal, --graphcut): exit 2, one line, nothing written.
# usage: classify_catalog.sh TOOL LABELED_FOLDER PYTHON
set -eu
tool=$1
labeled=$2
python=$3
dir=classify-catalog-test
rm -rf "$dir" && mkdir -p "$dir/tiles"
. "$(dirname "$0")/refusals.sh"
start=$(date +%s)

# the package's fixed and optimal neighborhoods (k 20, normals' sigmoid weights) and the heights in cells
"$tool" classify train "$labeled/ign_lidarhd_77050_627755.las" -o "$dir/model.bin" --features k20,optimal,height \
  --trees 4 --depth 12 2> "$dir/train.txt" || fail "train: $(cat "$dir/train.txt")"

"$tool" catalog list "$labeled" --names > "$dir/names.txt" || fail "catalog list"
[ "$(wc -l < "$dir/names.txt")" -eq 6 ] || fail "not 6 tiles: $(cat "$dir/names.txt")"
set --
while read -r name; do
  "$tool" classify predict "$dir/model.bin" --catalog "$labeled" --tile "$name" -o "$dir/tiles/$name.ply" \
    2> "$dir/tiles/$name.txt" || fail "predict $name: $(cat "$dir/tiles/$name.txt")"
  grep -q '"exact": true' "$dir/tiles/$name.tile.json" || fail "$name: no exact tile description"
  grep -q '"command": "classify predict"' "$dir/tiles/$name.tile.json" || fail "$name: not classify predict"
  set -- "$@" "$dir/tiles/$name.ply"
done < "$dir/names.txt"
tiles_done=$(date +%s)
"$tool" classify predict "$dir/model.bin" --catalog "$labeled" -o "$dir/union.ply" 2> "$dir/union.txt" \
  || fail "predict the union: $(cat "$dir/union.txt")"
[ ! -e "$dir/union.tile.json" ] || fail "a tile description for the union"

"$python" - "$dir/union.ply" "$@" > "$dir/compare.txt" 2>&1 <<'EOF' || fail "$(cat "$dir/compare.txt")"
import sys

def vertices(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    count = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    properties = [l for l in header if l.startswith("property")]
    assert "format binary_little_endian 1.0" in header, path
    assert not [l for l in header if l.startswith("element") and not l.startswith("element vertex")], path
    return count, properties, data[end:]

union_count, union_properties, union_data = vertices(sys.argv[1])
assert "property int scalar_label" in union_properties and \
    any(p.startswith("property float scalar_confidence_") for p in union_properties), union_properties
record = len(union_data) // union_count
assert record * union_count == len(union_data)
joined, count = b"", 0
for path in sys.argv[2:]:
    n, properties, data = vertices(path)
    if properties != union_properties:
        sys.exit(path + ": other properties than the union's")
    joined += data
    count += n
if count != union_count:
    sys.exit("the tiles have %d points, the union %d" % (count, union_count))
differing = sum(joined[i:i + record] != union_data[i:i + record] for i in range(0, len(joined), record))
if differing:
    sys.exit("%d of %d points differ from the union's" % (differing, union_count))
print("%d points of %d tiles, %d properties: identical" % (count, len(sys.argv) - 2, len(union_properties)))
EOF
end=$(date +%s)
cat "$dir/compare.txt"
echo "train + 6 tiles: $((tiles_done - start)) s, union: $((end - tiles_done)) s"

# refusals with --tile: CGAL's generator (a model whose groups name cgal; refused before its forest is
# read) and the graph-cut; nothing written
first=$(head -1 "$dir/names.txt")
{ head -1 "$dir/model.bin"; sed -n 2p "$dir/model.bin" | sed 's/"groups":\["k20"/"groups":["cgal","k20"/'; } \
  > "$dir/cgal_model.bin"
tail -n +3 "$dir/model.bin" >> "$dir/cgal_model.bin"
grep -q '"cgal","k20"' "$dir/cgal_model.bin" || fail "the model with the group cgal was not made"
expect_refusal "feature group cgal depends on the whole point set" \
  "$tool" classify predict "$dir/cgal_model.bin" --catalog "$labeled" --tile "$first" -o "$dir/none.ply"
expect_refusal "--graphcut minimises over the whole point set" \
  "$tool" classify predict "$dir/model.bin" --catalog "$labeled" --tile "$first" -o "$dir/none.ply" --graphcut 0.2
expect_refusal "--tile and --halo go with --catalog" \
  "$tool" classify predict "$dir/model.bin" "$labeled/$first.las" --tile "$first" -o "$dir/none.ply"
expect_refusal "takes --catalog SOURCE or INPUT, not both" \
  "$tool" classify predict "$dir/model.bin" "$labeled/$first.las" --catalog "$labeled" -o "$dir/none.ply"
[ ! -e "$dir/none.ply" ] && [ ! -e "$dir/none.tile.json" ] || fail "a refused command wrote its output"
echo "classify-catalog-ok"
