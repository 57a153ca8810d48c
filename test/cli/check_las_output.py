#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Checks a LAS 1.4 output of the tool against its uncompressed LAS input, with numpy alone (an
# independent reading of the LAS 1.4 R15 layout): the header's counts, bounds and by-return counts
# agree with the records; every record holds the input's bytes but the fields named by --changed;
# the Extra Bytes record describes the input's extra bytes, then the added dimensions, which follow
# the copied bytes. Prints the added dimensions' names; with --values NAME, writes that dimension's
# values, one per line, to stdout instead. With --classes PLY CODES, the classification of each record
# is the code (CODES: one per class index, comma-separated) of the PLY's scalar_label at its position
# (the PLY holds the distinct positions in their first record's order).
# With --csv CSV NAME[=COLUMN]..., each named dimension holds the CSV column of that name at its record's
# position (to float precision; blanks as NaN). With --union-csv, the CSV holds the rows of several
# files (a catalog's union, one row per distinct position): each record's row is the one at its
# coordinates. The input's EVLRs follow the output's points unchanged.
# usage: check_las_output.py OUTPUT.las INPUT.las [--changed classification|xyz] [--values NAME]
#                            [--classes PREDICTION.ply CODES] [--csv|--union-csv CSV NAME[=COLUMN]...]
import struct
import sys

import numpy as np

BASE = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67]
TYPES = {1: "u1", 2: "i1", 3: "<u2", 4: "<i2", 5: "<u4", 6: "<i4", 7: "<u8", 8: "<i8", 9: "<f4", 10: "<f8"}


def fail(message):
    sys.exit("check_las_output: " + message)


def read_las(path):
    data = open(path, "rb").read()
    if data[:4] != b"LASF":
        fail(path + ": no LAS signature")
    h = {"minor": data[25], "header_size": struct.unpack_from("<H", data, 94)[0],
         "point_data": struct.unpack_from("<I", data, 96)[0], "vlrs": struct.unpack_from("<I", data, 100)[0],
         "format": data[104], "record_length": struct.unpack_from("<H", data, 105)[0],
         "legacy_count": struct.unpack_from("<I", data, 107)[0],
         "legacy_by_return": struct.unpack_from("<5I", data, 111),
         "scale": struct.unpack_from("<3d", data, 131), "offset": struct.unpack_from("<3d", data, 155),
         "bounds": struct.unpack_from("<6d", data, 179)}
    h["count"] = h["legacy_count"]
    if h["minor"] == 4 and struct.unpack_from("<Q", data, 247)[0]:
        h["count"] = struct.unpack_from("<Q", data, 247)[0]
        h["by_return"] = struct.unpack_from("<15Q", data, 255)
        h["evlr_start"], h["evlrs"] = struct.unpack_from("<QI", data, 235)
    vlrs, at = [], h["header_size"]
    for _ in range(h["vlrs"]):
        user = data[at + 2:at + 18].split(b"\0")[0].decode()
        record, length = struct.unpack_from("<HH", data, at + 18)
        vlrs.append((user, record, data[at + 54:at + 54 + length]))
        at += 54 + length
    start, n, length = h["point_data"], h["count"], h["record_length"]
    records = np.frombuffer(data, dtype=np.uint8, count=n * length, offset=start).reshape(n, length)
    return h, vlrs, records, data


def descriptors(vlrs):
    out = []
    for user, record, payload in vlrs:
        if user == "LASF_Spec" and record == 4:
            for d in range(0, len(payload) - len(payload) % 192, 192):
                b = payload[d:d + 192]
                out.append((b[2], b[3], b[4:36].split(b"\0")[0].decode(), struct.unpack_from("<d", b, 112)[0],
                            struct.unpack_from("<d", b, 136)[0]))
    return out


def size_of(kind, options):
    if kind == 0:
        return options
    return np.dtype(TYPES[(kind - 1) % 10 + 1]).itemsize * ((kind - 1) // 10 + 1)


def ply_labels(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    fields, count = [], 0
    for line in data[:end].decode().splitlines():
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            kinds = {"float": "<f4", "double": "<f8", "int": "<i4", "uchar": "u1", "char": "i1", "short": "<i2",
                     "ushort": "<u2", "uint": "<u4"}
            fields.append((words[2], kinds[words[1]]))
    return np.frombuffer(data, dtype=np.dtype(fields), count=count, offset=end)["scalar_label"]


def point_of_record(out):
    """per record, the index of its position among the distinct positions in first-record order"""
    xyz = np.ascontiguousarray(out[:, :12]).view("<i4").reshape(-1, 3)
    _, first, position = np.unique(xyz, axis=0, return_index=True, return_inverse=True)
    point_of_position = np.empty(len(first), dtype=np.int64)
    point_of_position[np.argsort(first)] = np.arange(len(first))
    return point_of_position[position.reshape(-1)], len(first)


def dimension(out, layout, name):
    at, kind, scale, offset = layout[name]
    column = out[:, at:at + size_of(kind, 0)].copy().view(TYPES[kind]).reshape(-1).astype(np.float64)
    return column * scale + offset


def row_at_position(out, h, table):
    """per record, the CSV row at its coordinates (the reader's: integer times scale plus offset)"""
    xyz = out[:, :12].copy().view("<i4").reshape(-1, 3).astype(np.float64)
    coords = xyz * np.array(h["scale"]) + np.array(h["offset"])
    rows = {(x, y, z): i for i, (x, y, z) in enumerate(zip(table["x"], table["y"], table["z"]))}
    try:
        return np.array([rows[(x, y, z)] for x, y, z in coords], dtype=np.int64)
    except KeyError as missing:
        fail("no CSV row at the position %s" % (missing,))


def check_csv(out, layout, csv, names, h=None):
    table = np.genfromtxt(csv, delimiter=",", names=True)
    if h is not None:
        point = row_at_position(out, h, table)
    else:
        point, count = point_of_record(out)
        if len(table) != count:
            fail("%d distinct positions, %d CSV rows" % (count, len(table)))
    for name in names:  # NAME, or NAME=COLUMN where the CSV names it otherwise
        name, column = name.split("=") if "=" in name else (name, name)
        got, expected = dimension(out, layout, name), table[column][point]
        same = np.isclose(got, expected, rtol=1e-6, atol=1e-6) | (np.isnan(expected) & np.isnan(got)) | (
            np.isinf(expected) & (got == expected))
        if not same.all():
            fail("%s: %d values differ from the CSV's" % (name, int((~same).sum())))


def check_classes(out, extended, ply, codes):
    point, count = point_of_record(out)
    labels = ply_labels(ply)
    if len(labels) != count:
        fail("%d distinct positions, %d PLY points" % (count, len(labels)))
    expected = np.array([int(c) for c in codes.split(",")])[labels[point]]
    got = out[:, 16] if extended else out[:, 15] & 0x1F
    if (got != expected).any():
        fail("%d classes differ from the PLY's" % int((got != expected).sum()))


def main():
    args = sys.argv[1:]
    changed = args[args.index("--changed") + 1].split(",") if "--changed" in args else []
    values = args[args.index("--values") + 1] if "--values" in args else None
    out_path, in_path = args[0], args[1]
    h, vlrs, out, data = read_las(out_path)
    hi, vlrs_in, inp, data_in = read_las(in_path)
    if h["minor"] != 4 or h["header_size"] != 375:
        fail("not a LAS 1.4 header of 375 bytes")
    if any(user == "laszip encoded" for user, _, _ in vlrs) or h["format"] & 0xC0:
        fail("a LASzip record or compression bit in an uncompressed file")
    if h["format"] != hi["format"] & 0x3F or h["count"] != hi["count"]:
        fail("format %d, %d points; the input's %d, %d" % (h["format"], h["count"], hi["format"] & 0x3F, hi["count"]))
    if h["scale"] != hi["scale"] or h["offset"] != hi["offset"]:
        fail("the scales or offsets changed")
    copied = hi["record_length"]
    mask = np.ones(copied, dtype=bool)
    extended = h["format"] >= 6
    if "classification" in changed:
        mask[16 if extended else 15] = False
    if "xyz" in changed:
        mask[:12] = False
    differ = np.nonzero((out[:, :copied] != inp)[:, mask].any(axis=1))[0]
    if len(differ):
        fail("%d records changed, the first %d" % (len(differ), differ[0]))
    if not extended and "classification" in changed and ((out[:, 15] & 0xE0) != (inp[:, 15] & 0xE0)).any():
        fail("the classification flags changed")
    # the header's summary of the records
    xyz = out[:, :12].copy().view("<i4").reshape(-1, 3).astype(np.float64)
    for c in range(3):
        coords = xyz[:, c] * h["scale"][c] + h["offset"][c]
        if (h["bounds"][2 * c], h["bounds"][2 * c + 1]) != (coords.max(), coords.min()):
            fail("the bounds of axis %d are not the records'" % c)
    returns = out[:, 14] & (0x0F if extended else 0x07)
    counts = [int((returns == r).sum()) for r in range(1, 16)]
    if list(h["by_return"]) != counts:
        fail("the counts by return are not the records'")
    if not extended and (h["legacy_count"] != h["count"] or list(h["legacy_by_return"]) != counts[:5]):
        fail("the legacy counts of a legacy format differ")
    if extended and h["legacy_count"] != 0:
        fail("a legacy count in point format %d" % h["format"])
    # the descriptors: the input's extra bytes first, then the added dimensions
    ds = descriptors(vlrs)
    described = BASE[h["format"]]
    layout = {}
    for kind, options, name, scale, offset in ds:
        size = size_of(kind, options)
        layout[name] = (described, kind, scale if options & 0x08 else 1.0, offset if options & 0x10 else 0.0)
        described += size
    if described != h["record_length"]:
        fail("the Extra Bytes record describes %d bytes of %d" % (described, h["record_length"]))
    if "--classes" in args:
        check_classes(out, extended, args[args.index("--classes") + 1], args[args.index("--classes") + 2])
    added = [name for kind, options, name, _, _ in ds if layout[name][0] >= copied]
    if "--csv" in args:
        check_csv(out, layout, args[args.index("--csv") + 1], args[args.index("--csv") + 2:])
    if "--union-csv" in args:
        check_csv(out, layout, args[args.index("--union-csv") + 1], args[args.index("--union-csv") + 2:], h)
    if hi.get("evlrs"):
        if h.get("evlrs") != hi["evlrs"] or data[h["evlr_start"]:] != data_in[hi["evlr_start"]:]:
            fail("the input's EVLRs are not after the points")
    if values is not None:
        np.savetxt(sys.stdout, dimension(out, layout, values), fmt="%.9g")
    else:
        print(",".join(added))


main()
