#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# LAS output (-o OUT.las) of optimal, classify predict, filter-normals and denoise, read by
# check_las_output.py (numpy alone):
# every record of the input as it was but the classification, the header's summary right, the
# results as described extra bytes dimensions equal to the CSV's columns and the PLY's classes, on
# the six IGN tiles and on the LAS and LAZ files of ../shared/data/laz (LAS 1.2 to 1.4, extra bytes,
# EVLRs); a LAZ input gives the LAS twin's output byte for byte; an output read again by the tool
# gives the input's results; a point set of another format gets format 6 records within half a
# scale unit. LAZ output (-o OUT.laz), decompressed by the las_copy example: the LAS output byte for
# byte, in fewer bytes. A catalog's tile (--tile) gets its file's records with the union's results.
# The refusals exit 2 with one line and write nothing; a LAZ output of wave packets before the work.
# usage: las_output.sh TOOL SHARED_DATA_FOLDER PYTHON CHECKER LAS_COPY
set -eu
tool=$1
data=$2
python=$3
checker=$4
las_copy=$5
dir=las-output-test
rm -rf "$dir" && mkdir -p "$dir"
. "$(dirname "$0")/refusals.sh"
search="--k-max 10 --a-grid 0,pi --b-grid 0,pi"
columns="normal_x=nx normal_y=ny normal_z=nz a b k error linearity planarity scattering error_equal k_equal"

# optimal: the CSV's columns, on LAS 1.2, 1.4 with EVLRs and extra bytes described by the input
for name in simple 1_4_w_evlr extrabytes; do
  "$tool" optimal "$data/laz/$name.las" -o "$dir/$name.csv" $search 2> /dev/null || fail "optimal $name (CSV)"
  "$tool" optimal "$data/laz/$name.las" -o "$dir/$name.las" $search 2> /dev/null || fail "optimal $name (LAS)"
  "$python" "$checker" "$dir/$name.las" "$data/laz/$name.las" --csv "$dir/$name.csv" $columns > "$dir/names.txt" \
    || fail "optimal $name: the LAS output"
  grep -q "^normal_x,normal_y,normal_z,a,b,k,error,linearity,planarity,scattering,label,error_equal,k_equal$" \
    "$dir/names.txt" || fail "optimal $name: the added dimensions: $(cat "$dir/names.txt")"
done
# optimal to LAZ (point-wise: LAS 1.2 format 3; layered with EVLRs): the LAS output once decompressed
for name in simple 1_4_w_evlr; do
  "$tool" optimal "$data/laz/$name.laz" -o "$dir/$name.laz" $search 2> /dev/null || fail "optimal $name (LAZ)"
  "$tool" optimal "$data/laz/$name.laz" -o "$dir/$name.from_laz.las" $search 2> /dev/null || fail "optimal $name (LAS)"
  "$las_copy" "$dir/$name.laz" "$dir/$name.unzipped.las" > /dev/null || fail "optimal $name: LAZ unread"
  cmp "$dir/$name.from_laz.las" "$dir/$name.unzipped.las" || fail "optimal $name: the LAZ output is not the LAS output"
done
# every LAZ file under 1 MB (point-wise and layered, extra bytes, EVLRs, COPC): the output read again
# gives the input's results, byte for byte
for laz in $(find "$data/laz" -name "*.laz" -size -1000k | sort); do
  name=$(basename "$laz" .laz).laz
  "$tool" optimal "$laz" -o "$dir/$name.in.csv" $search 2> /dev/null || continue # refused inputs: other tests
  "$tool" optimal "$laz" -o "$dir/$name.las" $search 2> /dev/null || fail "optimal $name: no LAS output"
  "$tool" optimal "$dir/$name.las" -o "$dir/$name.again.csv" $search 2> /dev/null || fail "$name: output unread"
  cmp "$dir/$name.in.csv" "$dir/$name.again.csv" || fail "$name: the LAS output does not read as its input"
done

# classify predict on the six IGN tiles: the PLY's classes as ASPRS codes
tiles="77050_627755 77050_627760 77055_627755 77055_627760 77060_627755 77060_627760"
"$tool" classify train "$data/labeled/ign_lidarhd_77050_627755.las" -o "$dir/model.bin" --features k20,height \
  --trees 3 --depth 8 2> /dev/null || fail "classify train"
codes="--class-codes ground=2,low_vegetation=3,high_vegetation=5,building=6"
for tile in $tiles; do
  input="$data/labeled/ign_lidarhd_$tile.las"
  "$tool" classify predict "$dir/model.bin" "$input" -o "$dir/p_$tile.ply" 2> /dev/null || fail "predict $tile (PLY)"
  "$tool" classify predict "$dir/model.bin" "$input" -o "$dir/p_$tile.las" $codes 2> /dev/null \
    || fail "predict $tile (LAS)"
  "$python" "$checker" "$dir/p_$tile.las" "$input" --changed classification --classes "$dir/p_$tile.ply" 2,3,5,6 \
    > "$dir/names.txt" || fail "predict $tile: the LAS output"
  grep -q "^confidence,original_class$" "$dir/names.txt" || fail "predict $tile: $(cat "$dir/names.txt")"
  "$python" "$checker" "$dir/p_$tile.las" "$input" --changed classification --values original_class \
    > "$dir/original.txt"
  [ "$(sort -u "$dir/original.txt" | tr '\n' ' ')" != "0 " ] || fail "predict $tile: no original class kept"
done
# the same compressed: decompressed, the LAS output byte for byte, in fewer bytes
for tile in $tiles; do
  "$tool" classify predict "$dir/model.bin" "$data/labeled/ign_lidarhd_$tile.las" -o "$dir/p_$tile.laz" $codes \
    2> /dev/null || fail "predict $tile (LAZ)"
  "$las_copy" "$dir/p_$tile.laz" "$dir/p_$tile.unzipped.las" --threads 2 > /dev/null || fail "$tile: LAZ unread"
  cmp "$dir/p_$tile.las" "$dir/p_$tile.unzipped.las" || fail "predict $tile: the LAZ output is not the LAS output"
  [ "$(wc -c < "$dir/p_$tile.laz")" -lt "$(($(wc -c < "$dir/p_$tile.las") / 4))" ] || fail "predict $tile: LAZ not smaller"
done
twin="$data/laz/test_data_77050_627760_LA93_IGN69.laz"
"$tool" classify predict "$dir/model.bin" "$twin" -o "$dir/p_laz.las" $codes 2> /dev/null || fail "predict on LAZ"
cmp "$dir/p_laz.las" "$dir/p_77050_627760.las" || fail "predict: a LAZ input and its LAS twin give different outputs"
"$tool" classify predict "$dir/model.bin" "$twin" -o "$dir/p_laz.laz" $codes --threads 3 2> /dev/null \
  || fail "predict LAZ to LAZ"
cmp "$dir/p_laz.laz" "$dir/p_77060_627760.laz" > /dev/null 2>&1 && fail "two tiles, one LAZ output"
"$las_copy" "$dir/p_laz.laz" "$dir/p_laz.unzipped.las" > /dev/null || fail "LAZ to LAZ: unread"
cmp "$dir/p_laz.unzipped.las" "$dir/p_77050_627760.las" || fail "predict: LAZ to LAZ is not LAS to LAS"
# a legacy point format (classes 0 to 31): the model's codes fit
"$tool" classify predict "$dir/model.bin" "$data/laz/simple.las" -o "$dir/p_simple.las" $codes 2> /dev/null \
  || fail "predict on a LAS 1.2 file"
"$python" "$checker" "$dir/p_simple.las" "$data/laz/simple.las" --changed classification > /dev/null \
  || fail "predict on a LAS 1.2 file: the LAS output"

# denoise: the records with their coordinates moved to the denoised points (within half the file's
# scale of the XYZ output's) and the filtered normals added
"$tool" denoise "$data/laz/simple.las" -o "$dir/d.xyz" --iterations 3 2> /dev/null || fail "denoise (XYZ)"
"$tool" denoise "$data/laz/simple.las" -o "$dir/d.las" --iterations 3 2> /dev/null || fail "denoise (LAS)"
"$python" "$checker" "$dir/d.las" "$data/laz/simple.las" --changed xyz > "$dir/names.txt" || fail "denoise: the LAS output"
grep -q "^normal_x,normal_y,normal_z$" "$dir/names.txt" || fail "denoise: $(cat "$dir/names.txt")"
"$tool" denoise "$data/laz/simple.las" -o "$dir/d.laz" --iterations 3 2> /dev/null || fail "denoise (LAZ)"
"$las_copy" "$dir/d.laz" "$dir/d.unzipped.las" > /dev/null || fail "denoise: LAZ unread"
cmp "$dir/d.las" "$dir/d.unzipped.las" || fail "denoise: the LAZ output is not the LAS output"
"$python" -c "
import numpy as np, struct
data = open('$dir/d.las', 'rb').read()
start, length, count = struct.unpack_from('<I', data, 96)[0], struct.unpack_from('<H', data, 105)[0], struct.unpack_from('<Q', data, 247)[0]
scale, offset = np.array(struct.unpack_from('<3d', data, 131)), np.array(struct.unpack_from('<3d', data, 155))
records = np.frombuffer(data, np.uint8, count * length, start).reshape(count, length)
xyz = records[:, :12].copy().view('<i4').reshape(-1, 3) * scale + offset
expected = np.loadtxt('$dir/d.xyz')
assert len(expected) == count and np.abs(xyz - expected[:, :3]).max() <= scale.max() / 2 * 1.001
normal_x = records[:, length - 12:length - 8].copy().view('<f4').reshape(-1)
assert np.abs(normal_x - expected[:, 3]).max() < 1e-7
" || fail "denoise: the LAS output's positions or normals"

# filter-normals: the records as they were, the filtered normals as extra bytes (the XYZ output's)
"$tool" filter-normals "$data/laz/simple.las" -o "$dir/f.xyz" --iterations 3 2> /dev/null || fail "filter-normals (XYZ)"
"$tool" filter-normals "$data/laz/simple.las" -o "$dir/f.las" --iterations 3 2> /dev/null || fail "filter-normals (LAS)"
"$python" "$checker" "$dir/f.las" "$data/laz/simple.las" > "$dir/names.txt" || fail "filter-normals: the LAS output"
grep -q "^normal_x,normal_y,normal_z$" "$dir/names.txt" || fail "filter-normals: $(cat "$dir/names.txt")"
for c in x y z; do
  "$python" "$checker" "$dir/f.las" "$data/laz/simple.las" --values normal_$c > "$dir/f_$c.txt"
done
"$python" -c "
import numpy as np
expected = np.loadtxt('$dir/f.xyz')
got = np.stack([np.loadtxt('$dir/f_%s.txt' % c) for c in 'xyz'], axis=1)
assert got.shape == expected[:, 3:].shape and np.abs(got - expected[:, 3:]).max() < 1e-7
" || fail "filter-normals: the LAS output's normals are not the XYZ output's"
"$tool" filter-normals "$data/laz/simple.las" -o "$dir/f.laz" --iterations 3 2> /dev/null || fail "filter-normals (LAZ)"
"$las_copy" "$dir/f.laz" "$dir/f.unzipped.las" > /dev/null || fail "filter-normals: LAZ unread"
cmp "$dir/f.las" "$dir/f.unzipped.las" || fail "filter-normals: the LAZ output is not the LAS output"

# a point set of another format: new records, coordinates within half a unit of the scale
"$python" -c "
import numpy as np
points = np.random.default_rng(1).normal(size=(2000, 3))
points = points / np.linalg.norm(points, axis=1)[:, None] * 3.7 + [1000.25, -20., 5.]
np.savetxt('$dir/sphere.xyz', points, fmt='%.17g')"
"$tool" optimal "$dir/sphere.xyz" -o "$dir/sphere.csv" $search 2> /dev/null || fail "optimal sphere (CSV)"
"$tool" optimal "$dir/sphere.xyz" -o "$dir/sphere.las" $search 2> /dev/null || fail "optimal sphere (LAS)"
"$tool" optimal "$dir/sphere.las" -o "$dir/sphere.again.csv" $search 2> /dev/null || fail "sphere: output unread"
"$tool" optimal "$dir/sphere.xyz" -o "$dir/sphere.laz" $search 2> /dev/null || fail "optimal sphere (LAZ)"
"$las_copy" "$dir/sphere.laz" "$dir/sphere.unzipped.las" > /dev/null || fail "sphere: LAZ unread"
# the copy says MODIFICATION where the original says OTHER (bytes 27-58, the system identifier)
tail -c +59 "$dir/sphere.las" > "$dir/sphere.las.tail"
tail -c +59 "$dir/sphere.unzipped.las" > "$dir/sphere.unzipped.las.tail"
cmp "$dir/sphere.las.tail" "$dir/sphere.unzipped.las.tail" || fail "sphere: the LAZ output is not the LAS output"
"$python" -c "
import numpy as np, struct, sys
a = np.genfromtxt('$dir/sphere.csv', delimiter=',', names=True)
b = np.genfromtxt('$dir/sphere.again.csv', delimiter=',', names=True)
header = open('$dir/sphere.las', 'rb').read(375)
scale = struct.unpack_from('<3d', header, 131)
assert header[104] == 6 and header[26:31] == b'OTHER', 'format 6, system OTHER'
assert scale == (1e-8,) * 3, scale  # half extent 3.7: the smallest power of ten for which it takes 2^30 units
assert len(a) == len(b) and all(np.abs(a[c] - b[c]).max() <= 0.5e-8 * 1.0001 for c in 'xyz'), 'coordinates'
" || fail "a point set's LAS output"

# a catalog's tiles (--tile): each tile's file's records with the union's results at their positions
# (a seam duplicate's: those of the earlier tile's point it was merged into); LAZ as the LAS
for t in 77050_627760 77055_627760 77055_627755; do echo "$data/labeled/ign_lidarhd_$t.las"; done > "$dir/tiles.txt"
"$tool" optimal --catalog "$dir/tiles.txt" -o "$dir/union.csv" $search 2> /dev/null || fail "optimal: the union"
seams=0
for name in $("$tool" catalog list "$dir/tiles.txt" --names); do
  "$tool" optimal --catalog "$dir/tiles.txt" --tile "$name" -o "$dir/$name.laz" $search 2> "$dir/tile.txt" ||
    fail "optimal --tile $name: $(cat "$dir/tile.txt")"
  "$las_copy" "$dir/$name.laz" "$dir/$name.las" > /dev/null || fail "tile $name: LAZ unread"
  "$python" "$checker" "$dir/$name.las" "$data/labeled/$name.las" --union-csv "$dir/union.csv" $columns \
    > /dev/null || fail "optimal --tile $name: the LAS output"
  [ -s "$dir/$name.tile.json" ] || fail "tile $name: no tile description"
  seams=$((seams + $(grep -o '"seam_duplicates": [0-9]*' "$dir/$name.tile.json" | grep -o '[0-9]*$')))
done
[ "$seams" -gt 0 ] || fail "no seam duplicate among the tiles: the test does not see their records"
"$tool" classify predict "$dir/model.bin" --catalog "$dir/tiles.txt" --tile ign_lidarhd_77055_627760 \
  -o "$dir/p_tile.las" 2> /dev/null || fail "classify predict --tile to LAS"
"$python" "$checker" "$dir/p_tile.las" "$data/labeled/ign_lidarhd_77055_627760.las" --changed classification \
  > "$dir/names.txt" || fail "classify predict --tile: the LAS output"

# refusals
expect_refusal "LAS output of the catalog's union" "$tool" optimal --catalog "$data/laz" -o "$dir/x.laz" $search
# a LAZ output of records with wave packets: refused before the work (point format 10: 8 and 29 wave bytes)
"$python" - "$data/labeled/ign_lidarhd_77050_627755.las" "$dir/wave.las" << 'EOF'
import struct, sys
d = open(sys.argv[1], "rb").read()
offset, n = struct.unpack_from("<I", d, 96)[0], 200
header = bytearray(d[:offset])
header[104] = 10
struct.pack_into("<H", header, 105, 38 + 29)
struct.pack_into("<Q", header, 247, n)
struct.pack_into("<15Q", header, 255, n, *([0] * 14))
records = b"".join(d[offset + 38 * i:offset + 38 * (i + 1)] + bytes(29) for i in range(n))
open(sys.argv[2], "wb").write(bytes(header) + records)
EOF
# (the message names the input: only the check before the work does; the writer's own refusal does not)
for command in optimal filter-normals denoise; do
  expect_refusal "the wave packets of point format 10 of $dir/wave.las are not compressed" \
    "$tool" $command "$dir/wave.las" -o "$dir/x.laz"
done
expect_refusal "of 31 at most" "$tool" classify predict "$dir/model.bin" "$data/laz/simple.las" -o "$dir/x.las" \
  --class-codes ground=40
expect_refusal "is not NAME=CODE" "$tool" classify predict "$dir/model.bin" "$data/laz/simple.las" -o "$dir/x.las" \
  --class-codes water=9
expect_refusal "goes with -o OUT.las" "$tool" classify predict "$dir/model.bin" "$data/laz/simple.las" -o "$dir/x.ply" \
  --class-codes ground=2
expect_refusal "LAS output of the catalog's union" "$tool" optimal --catalog "$data/laz" -o "$dir/x.las" $search
[ ! -e "$dir/x.las" ] && [ ! -e "$dir/x.laz" ] && [ ! -e "$dir/x.ply" ] || fail "a refused command wrote its output"
ls "$dir" | grep -q "\.tmp\." && fail "a temporary file left behind"
echo "las-output-ok"
