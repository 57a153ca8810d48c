#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# sigmoid-neighborhoods catalog retile on an IGN LiDAR HD tile (LAS 1.4, point format 8): every
# record in exactly one tile, byte for byte and in order (check_las_tiles.py), the same tiles
# whatever the buffer and the open files, negative cell indices, EVLRs copied, the tiles a catalog
# whose union has the input's points; with LAS_COPY (las_copy_example, the package's public reader
# and writers), the same input as LAZ: LAS tiles equal to the LAS input's, LAZ tiles that decode to
# them, the same bytes from either input and for any threads; an older LAS version made LAS 1.4;
# the refusals exit 2 with a message and write no tile.
# usage: retile.sh TOOL INPUT.las PYTHON CHECKER [LAS_COPY]
set -eu
tool=$1
input=$2
python=$3
checker=$4
las_copy=${5:-}
dir=retile-test
rm -rf "$dir" && mkdir -p "$dir"
. "$(dirname "$0")/refusals.sh"
tiles_in() { find "$1" -name '*.las' | wc -l; }
points=$("$python" -c "import struct,sys; d=open(sys.argv[1],'rb').read(375); print(struct.unpack_from('<Q',d,247)[0])" "$input")

# 10 m tiles: the records, the headers, the names and their order
"$tool" catalog retile "$input" --size 10 -o "$dir/t10" 2> "$dir/retile.txt" || fail "retile: $(cat "$dir/retile.txt")"
grep -q "^$dir/t10: $points points of .* in [0-9]* tiles of side 10, [0-9.]* s (reading [0-9.]* s.*, writing [0-9.]* s)$" "$dir/retile.txt" \
  || fail "summary: $(cat "$dir/retile.txt")"
"$python" "$checker" retile "$input" "$dir/t10" 10 0 0 > "$dir/check.txt" || fail "$(cat "$dir/check.txt")"
tiles=$(tiles_in "$dir/t10")
"$tool" catalog list "$dir/t10" > "$dir/list.txt" || fail "catalog list"
[ "$(wc -l < "$dir/list.txt")" -eq "$tiles" ] || fail "catalog list: not $tiles tiles"
[ "$(awk -F, '{ s += $2 } END { print s }' "$dir/list.txt")" -eq "$points" ] || fail "catalog list: not $points points"

# the same bytes with a buffer of a few records per tile and three open files (tiles reopened to append)
"$tool" catalog retile "$input" --size 10 -o "$dir/t10small" --buffer 0.01 --open-files 3 2> "$dir/small.txt" \
  || fail "retile small: $(cat "$dir/small.txt")"
for f in "$dir"/t10/*.las; do cmp -s "$f" "$dir/t10small/$(basename "$f")" || fail "$f differs with a small buffer"; done
[ "$(tiles_in "$dir/t10small")" -eq "$tiles" ] || fail "small buffer: other tiles"

# 1 m tiles: thousands of files, 64 open at once
"$tool" catalog retile "$input" --size 1 -o "$dir/t1" 2> "$dir/t1.txt" || fail "retile 1 m: $(cat "$dir/t1.txt")"
"$python" "$checker" retile "$input" "$dir/t1" 1 0 0 > "$dir/check.txt" || fail "1 m: $(cat "$dir/check.txt")"

# negative cell indices around an origin inside the tile: written plus 10 in the names, in order
"$tool" catalog retile "$input" --size 10 --origin 770520 6277525 -o "$dir/negative" 2> "$dir/negative.txt" \
  || fail "retile --origin: $(cat "$dir/negative.txt")"
grep -q "i + 10 in the names, j + 10 in the names" "$dir/negative.txt" || fail "no bias note: $(cat "$dir/negative.txt")"
"$python" "$checker" retile "$input" "$dir/negative" 10 770520 6277525 > "$dir/check.txt" \
  || fail "negative: $(cat "$dir/check.txt")"
"$tool" catalog list "$dir/negative" --names > "$dir/names.txt"
sort "$dir/names.txt" | cmp -s - "$dir/names.txt" || fail "catalog order is not name order"

# EVLRs: copied after every tile's records, the header's offset to them moved
"$python" - "$input" "$dir/evlr.las" << 'EOF'
import struct, sys
d = bytearray(open(sys.argv[1], "rb").read())
payload = bytes(range(256)) * 3
evlr = struct.pack("<H16sHQ32s", 0, b"retile-test", 7, len(payload), b"an EVLR copied whole") + payload
struct.pack_into("<QI", d, 235, len(d), 1)
open(sys.argv[2], "wb").write(bytes(d) + evlr)
EOF
"$tool" catalog retile "$dir/evlr.las" --size 25 -o "$dir/evlr" 2> "$dir/evlr.txt" || fail "retile EVLR: $(cat "$dir/evlr.txt")"
grep -q "its EVLRs and waveform data (828 bytes) in every tile" "$dir/evlr.txt" || fail "EVLR summary: $(cat "$dir/evlr.txt")"
"$python" "$checker" retile "$dir/evlr.las" "$dir/evlr" 25 0 0 > "$dir/check.txt" || fail "EVLR: $(cat "$dir/check.txt")"
grep -q "828 trailer bytes each" "$dir/check.txt" || fail "EVLR: $(cat "$dir/check.txt")"

# the catalog's union is the input's point set: as many rows
"$tool" optimal --catalog "$dir/t10" -o "$dir/union_tiles.csv" --orientation up --threads 2 2> /dev/null \
  || fail "optimal --catalog"
"$tool" optimal "$input" -o "$dir/union_file.csv" --orientation up --threads 2 2> /dev/null || fail "optimal"
[ "$(wc -l < "$dir/union_tiles.csv")" -eq "$(wc -l < "$dir/union_file.csv")" ] \
  || fail "union of the tiles: $(wc -l < "$dir/union_tiles.csv") lines, the file: $(wc -l < "$dir/union_file.csv")"

# LAZ in and out
if [ -n "$las_copy" ]; then
  laz_input="$dir/$(basename "$input" .las).laz"  # the same stem, so the same tile names
  "$las_copy" "$input" "$laz_input" --threads 2 > /dev/null || fail "las_copy_example to LAZ"
  "$tool" catalog retile "$laz_input" --size 10 -o "$dir/laz10" 2> "$dir/laz10.txt" || fail "retile LAZ: $(cat "$dir/laz10.txt")"
  grep -q "^$dir/laz10: $points points of .* in $tiles tiles of side 10 (LAZ), " "$dir/laz10.txt" \
    || fail "LAZ summary: $(cat "$dir/laz10.txt")"
  [ "$(find "$dir/laz10" -name '*.laz' | wc -l)" -eq "$tiles" ] || fail "LAZ input: not $tiles .laz tiles"
  mkdir -p "$dir/laz10las"
  for f in "$dir"/laz10/*.laz; do
    name=$(basename "$f" .laz)
    "$las_copy" "$f" "$dir/laz10las/$name.las" --threads 1 > /dev/null || fail "las_copy_example cannot decode $f"
    cmp -s "$dir/laz10las/$name.las" "$dir/t10/$name.las" || fail "$f does not decode to the LAS input's tile"
  done
  "$tool" catalog retile "$laz_input" --size 10 --format las -o "$dir/laz10to_las" 2> /dev/null || fail "retile LAZ --format las"
  for f in "$dir"/t10/*.las; do cmp -s "$f" "$dir/laz10to_las/$(basename "$f")" || fail "$f differs from the LAZ input's"; done
  "$tool" catalog retile "$input" --size 10 --format laz --threads 1 -o "$dir/las10to_laz" 2> /dev/null \
    || fail "retile --format laz"
  for f in "$dir"/laz10/*.laz; do cmp -s "$f" "$dir/las10to_laz/$(basename "$f")" || fail "$f differs from the LAS input's on 1 thread"; done
  "$tool" catalog list "$dir/laz10" > "$dir/lazlist.txt" || fail "catalog list of LAZ tiles"
  [ "$(awk -F, '{ s += $2 } END { print s }' "$dir/lazlist.txt")" -eq "$points" ] || fail "LAZ tiles: not $points points"
  # LAS 1.2 (point format 3, the laspy sample) made LAS 1.4, and a format with waveform packets refused in LAZ
  data=$(dirname "$input")/../laz
  if [ -f "$data/simple.las" ] && [ -f "$data/fullwave.laz" ]; then
    "$tool" catalog retile "$data/simple.las" --size 100 -o "$dir/simple" 2> /dev/null || fail "retile LAS 1.2"
    "$python" "$checker" retile "$data/simple.las" "$dir/simple" 100 0 0 > "$dir/check.txt" || fail "LAS 1.2: $(cat "$dir/check.txt")"
    expect_refusal "point format 10 refers to waveform packets" "$tool" catalog retile "$data/fullwave.laz" --size 10 -o "$dir/refused"
  fi
fi

# refusals: exit 2, one line, no tile written
expect_refusal "cannot open" "$tool" catalog retile "$dir/absent.las" --size 10 -o "$dir/refused"
expect_refusal "--format must be las or laz" "$tool" catalog retile "$input" --size 10 --format zip -o "$dir/refused"
expect_refusal "not a .las or .laz file" "$tool" catalog retile "$dir/list.txt" --size 10 -o "$dir/refused"
"$python" -c "import sys; d=bytearray(open(sys.argv[1],'rb').read()); d[104]|=0x80; open(sys.argv[2],'wb').write(d)" \
  "$input" "$dir/compressed.las"
expect_refusal "compressed" "$tool" catalog retile "$dir/compressed.las" --size 10 -o "$dir/refused"
for size in 0 -5 abc inf; do
  expect_refusal "--size" "$tool" catalog retile "$input" --size "$size" -o "$dir/refused"
done
expect_refusal "needs --size" "$tool" catalog retile "$input" -o "$dir/refused"
expect_refusal "needs -o DIR" "$tool" catalog retile "$input" --size 10
expect_refusal "--origin needs two finite numbers" "$tool" catalog retile "$input" --size 10 -o "$dir/refused" --origin 1
expect_refusal "already holds tiles" "$tool" catalog retile "$input" --size 10 -o "$dir/t10"
[ "$(tiles_in "$dir/t10")" -eq "$tiles" ] || fail "a refused retile changed the folder"
if [ -d "$dir/refused" ]; then [ "$(ls -A "$dir/refused" | wc -l)" -eq 0 ] || fail "a refused retile wrote files"; fi
ls -A "$dir"/t10 "$dir"/t1 | grep -q '\.tmp\.' && fail "temporary files left"
echo retile-ok
