#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# classify predict on a catalog of tiles: small models trained on one IGN tile (the package's k-neighbor
# groups and heights; the pyramid groups; the default set) predict each tile with its halo and the
# union in one run; the tiles' PLY vertices, concatenated in the catalog's order, equal the union's
# byte for byte (positions, labels, confidences, truth, colors). Then the refusals with
# --tile (the group cgal, cgal-metric in an older model, --graphcut): exit 2, one line, nothing written.
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

# the six adjacent IGN tiles, listed: the folder holds other surveys too
for tile in 77050_627755 77050_627760 77055_627755 77055_627760 77060_627755 77060_627760; do
  echo "$(cd "$labeled" && pwd)/ign_lidarhd_$tile.las"
done > "$dir/tiles.txt"
catalog=$dir/tiles.txt
"$tool" catalog list "$catalog" --names > "$dir/names.txt" || fail "catalog list"
[ "$(wc -l < "$dir/names.txt")" -eq 6 ] || fail "not 6 tiles: $(cat "$dir/names.txt")"
first_tile=$(head -1 "$dir/names.txt")

# predict_and_compare MODEL NAME [OPTIONS]: every tile with its halo (and OPTIONS), then the union, into $dir/NAME/
predict_and_compare() {
  model=$1
  label=$2
  options=${3:-}
  out="$dir/$label"
  mkdir -p "$out/tiles"
  set --
  while read -r name; do
    "$tool" classify predict "$dir/$model" --catalog "$catalog" --tile "$name" -o "$out/tiles/$name.ply" \
      $options 2> "$out/tiles/$name.txt" || fail "predict $name ($label): $(cat "$out/tiles/$name.txt")"
    grep -q '"exact": true' "$out/tiles/$name.tile.json" || fail "$name ($label): no exact tile description"
    grep -q '"command": "classify predict"' "$out/tiles/$name.tile.json" || fail "$name ($label): not classify predict"
    set -- "$@" "$out/tiles/$name.ply"
  done < "$dir/names.txt"
  "$tool" classify predict "$dir/$model" --catalog "$catalog" -o "$out/union.ply" 2> "$out/union.txt" \
    || fail "predict the union ($label): $(cat "$out/union.txt")"
  [ ! -e "$out/union.tile.json" ] || fail "a tile description for the union ($label)"
  "$python" - "$out/union.ply" "$@" > "$out/compare.txt" 2>&1 <<'EOF' || fail "$label: $(cat "$out/compare.txt")"
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
  echo "$label: $(cat "$out/compare.txt")"
}

predict_and_compare model.bin k20-optimal-height
tiles_done=$(date +%s)

# the pyramid (scales in metres, both weights, their heights): representatives and rows near each tile
# checked to be the union's, the halo widened until they are
"$tool" classify train "$labeled/ign_lidarhd_77050_627755.las" -o "$dir/pyramid.bin" --features pyramid,pyramid-sigmoid \
  --trees 4 --depth 12 2> "$dir/train_pyramid.txt" || fail "train pyramid: $(cat "$dir/train_pyramid.txt")"
grep -q '"pyramid":{"cell":0.5,"cell_sizes":\[0.5,1.0,2.0,4.0,8.0\],"k":10,"levels":5,"sigmoid_cells":\[\]}' "$dir/pyramid.bin" \
  || fail "the pyramid model does not store its cell sizes"
# the tiles from a 10 m halo (too narrow: read again, wider), then one from the default first halo
predict_and_compare pyramid.bin pyramid "--halo 10"
grep -q ' readings, ' "$dir/pyramid/tiles/$first_tile.txt" || fail "a 10 m halo was enough for the pyramid"
"$tool" classify predict "$dir/pyramid.bin" --catalog "$catalog" --tile "$first_tile" -o "$dir/pyramid_default.ply" \
  2> "$dir/pyramid_default.txt" || fail "predict $first_tile (pyramid): $(cat "$dir/pyramid_default.txt")"
cmp -s "$dir/pyramid_default.ply" "$dir/pyramid/tiles/$first_tile.ply" \
  || fail "the pyramid's tile from the default halo differs from the one from 10 m"
pyramid_done=$(date +%s)

# the default set (cgal-metric's grids anchored at the origin, multiscale-sigmoid, pyramid): every tile
# with its halo classified as in the union
"$tool" classify train "$labeled/ign_lidarhd_77050_627755.las" -o "$dir/default.bin" --trees 4 --depth 12 \
  2> "$dir/train_default.txt" || fail "train default: $(cat "$dir/train_default.txt")"
grep -q '"groups":\["cgal-metric","multiscale-sigmoid","pyramid"\]' "$dir/default.bin" || fail "not the default set"
grep -q '"cgal_grid_anchor":"origin"' "$dir/default.bin" || fail "the default model's grids are not anchored at the origin"
predict_and_compare default.bin default
end=$(date +%s)
echo "train + 6 tiles + union: $((tiles_done - start)) s, the pyramid's: $((pyramid_done - tiles_done)) s," \
  "the default's: $((end - pyramid_done)) s"

# refusals with --tile: CGAL's generator (a model whose groups name cgal; refused before its forest is
# read) and the graph-cut; nothing written
first=$(head -1 "$dir/names.txt")
{ head -1 "$dir/model.bin"; sed -n 2p "$dir/model.bin" | sed 's/"groups":\["k20"/"groups":["cgal","k20"/'; } \
  > "$dir/cgal_model.bin"
tail -n +3 "$dir/model.bin" >> "$dir/cgal_model.bin"
grep -q '"cgal","k20"' "$dir/cgal_model.bin" || fail "the model with the group cgal was not made"
expect_refusal "feature group cgal depends on the whole point set" \
  "$tool" classify predict "$dir/cgal_model.bin" --catalog "$catalog" --tile "$first" -o "$dir/none.ply"
# a model of cgal-metric written before the grids were anchored at the origin (CGAL's, at the bounding box)
sed -n 2p "$dir/default.bin" | grep -q '"cgal_grid_anchor":"origin"' || fail "the anchor is not on the model's second line"
{ head -1 "$dir/default.bin"; sed -n 2p "$dir/default.bin" | sed 's/"cgal_grid_anchor":"origin"/"cgal_grid_anchor":"bounding box"/'; } \
  > "$dir/bbox_model.bin"
tail -n +3 "$dir/default.bin" >> "$dir/bbox_model.bin"
expect_refusal "feature group cgal-metric depends on the whole point set" \
  "$tool" classify predict "$dir/bbox_model.bin" --catalog "$catalog" --tile "$first" -o "$dir/none.ply"
expect_refusal "--graphcut minimises over the whole point set" \
  "$tool" classify predict "$dir/model.bin" --catalog "$catalog" --tile "$first" -o "$dir/none.ply" --graphcut 0.2
expect_refusal "--tile and --halo go with --catalog" \
  "$tool" classify predict "$dir/model.bin" "$labeled/$first.las" --tile "$first" -o "$dir/none.ply"
expect_refusal "takes --catalog SOURCE or INPUT, not both" \
  "$tool" classify predict "$dir/model.bin" "$labeled/$first.las" --catalog "$catalog" -o "$dir/none.ply"
[ ! -e "$dir/none.ply" ] && [ ! -e "$dir/none.tile.json" ] || fail "a refused command wrote its output"
echo "classify-catalog-ok"
