#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks LAS tiles, independently of the tool, from the ASPRS LAS 1.4 R15 layout.

  check_las_tiles.py retile INPUT.las DIR SIZE OX OY
      the tiles of 'catalog retile': one file per cell floor((x - OX) / SIZE), floor((y - OY) / SIZE)
      holding points, named as the tool documents; each is LAS 1.4, the input's header, VLRs and trailer
      (EVLRs), its records those of the cell byte for byte in the input's order, its counts and
      bounding box right; name order is (i, j) order
  check_las_tiles.py survey DIR POINTS TOLERANCE SIZE
      the tiles of generate_survey: LAS 1.4 format 6, counts and bounding boxes right, every point
      inside its tile's cell, classes 2, 5 and 6, POINTS points within TOLERANCE (a fraction)
Prints 'tiles-ok' and a summary, or the first failure (exit 1).
"""
import math
import os
import struct
import sys


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


class Las:
    def __init__(self, path):
        self.path = path
        with open(path, "rb") as f:
            self.data = f.read()
        d = self.data
        if d[:4] != b"LASF":
            fail(path + ": no LASF signature")
        self.minor = d[25]
        self.header_size, self.point_data_start = struct.unpack_from("<HI", d, 94)
        self.format = d[104] & 0x3F
        self.record_length, self.legacy_count = struct.unpack_from("<HI", d, 105)
        self.legacy_by_return = struct.unpack_from("<5I", d, 111)
        self.scale = struct.unpack_from("<3d", d, 131)
        self.offset = struct.unpack_from("<3d", d, 155)
        self.bounds = struct.unpack_from("<6d", d, 179)  # max x, min x, max y, min y, max z, min z
        self.is_1_4 = self.minor == 4 and self.header_size >= 375
        self.count = self.legacy_count
        if self.is_1_4:
            self.waveform_start, self.evlr_start, self.evlrs, self.count64 = struct.unpack_from("<QQIQ", d, 227)
            self.by_return = struct.unpack_from("<15Q", d, 255)
            if self.count64:
                self.count = self.count64
        else:
            self.evlrs = 0
        end = self.point_data_start + self.count * self.record_length
        if end > len(d):
            fail(path + ": %d records of %d bytes do not fit" % (self.count, self.record_length))
        self.records = [d[self.point_data_start + k * self.record_length:self.point_data_start + (k + 1) * self.record_length]
                        for k in range(self.count)]
        self.trailer_start = self.evlr_start if self.evlrs else len(d)
        self.trailer = d[self.trailer_start:]
        if self.trailer_start < end:
            fail(path + ": EVLRs inside the point records")

    def raw(self, record):
        return struct.unpack_from("<3i", record, 0)

    def xyz(self, record):
        return tuple(v * self.scale[c] + self.offset[c] for c, v in enumerate(self.raw(record)))

    def return_number(self, record):
        return record[14] & (0x0F if self.format >= 6 else 0x07)

    def check_summary(self):
        """Counts and bounding box against the records (LAS 1.4: legacy counts 0 in formats 6-10)."""
        n = len(self.records)
        by_return = [0] * 15
        for r in self.records:
            k = self.return_number(r)
            if k >= 1:
                by_return[k - 1] += 1
        if self.is_1_4:
            if self.count64 != n or list(self.by_return) != by_return:
                fail(self.path + ": 64-bit counts %d %s, records %d %s" % (self.count64, self.by_return, n, by_return))
            legacy = self.format < 6 and n < 2 ** 32
        else:
            legacy = True
        expected_legacy = (n, by_return[:5]) if legacy else (0, [0] * 5)
        if (self.legacy_count, list(self.legacy_by_return)) != expected_legacy:
            fail(self.path + ": legacy counts %d %s, expected %s" % (self.legacy_count, self.legacy_by_return,
                                                                     expected_legacy))
        points = [self.xyz(r) for r in self.records]
        for c in range(3):
            values = [p[c] for p in points]
            if (self.bounds[2 * c], self.bounds[2 * c + 1]) != (max(values), min(values)):
                fail(self.path + ": bounds of axis %d are %r, the points' %r" % (c, self.bounds[2 * c:2 * c + 2],
                                                                                  (max(values), min(values))))
        expected_size = self.point_data_start + n * self.record_length + len(self.trailer)
        if len(self.data) != expected_size or (self.evlrs and self.evlr_start != self.point_data_start + n * self.record_length):
            fail(self.path + ": %d bytes, EVLRs at %d" % (len(self.data), self.trailer_start))


def index_format(indices):
    """The tool's rule: zero-padded to the digits w of the largest magnitude; plus 10^w on w + 1
    digits when one is negative."""
    w = len(str(max(abs(i) for i in indices)))
    if min(indices) < 0:
        return lambda i: str(i + 10 ** w).zfill(w + 1)
    return lambda i: str(i).zfill(w)


def las_files(folder):
    names = sorted(os.listdir(folder))
    others = [n for n in names if not n.endswith(".las")]
    if others:
        fail(folder + ": files other than tiles: " + ", ".join(others[:5]))
    return names


def check_retile(input_path, folder, size, ox, oy):
    source = Las(input_path)
    cells = {}
    for r in source.records:
        x, y, _ = source.xyz(r)
        cells.setdefault((math.floor((x - ox) / size), math.floor((y - oy) / size)), []).append(r)
    i_text = index_format([c[0] for c in cells])
    j_text = index_format([c[1] for c in cells])
    stem = os.path.splitext(os.path.basename(input_path))[0]
    expected = {"%s_%s_%s.las" % (stem, i_text(c[0]), j_text(c[1])): c for c in cells}
    names = las_files(folder)
    if set(names) != set(expected):
        fail("tile names %s..., expected %s..." % (names[:3], sorted(expected)[:3]))
    if [expected[n] for n in names] != sorted(cells):
        fail("name order is not (i, j) order")
    # LAS 1.4 tiles: the system identifier and the generating software, the counts, the bounds
    # and the offsets after the points are the writer's; an older input's header is made a 1.4 one
    changed = set(range(26, 90)) | set(range(107, 131)) | set(range(179, 227))
    changed |= set(range(247, 375)) | set(range(227, 243))
    for name in names:
        tile = Las(os.path.join(folder, name))
        if tile.records != cells[expected[name]]:
            fail(name + ": its records are not those of its cell in the input's order")
        if (tile.minor, tile.header_size, tile.format, tile.scale, tile.offset) != \
                (4, 375, source.format, source.scale, source.offset):
            fail(name + ": not LAS 1.4 with the input's point format, scale and offset")
        if tile.data[58:90].rstrip(b"\0") != b"Sigmoid_neighborhoods" or tile.data[26:38] != b"MODIFICATION":
            fail(name + ": generating software %r, system identifier %r" % (tile.data[58:90], tile.data[26:58]))
        vlrs = source.data[source.header_size:source.point_data_start]
        if tile.data[375:tile.point_data_start] != vlrs:
            fail(name + ": its VLRs are not the input's")
        if source.is_1_4:
            if tile.point_data_start != source.point_data_start:
                fail(name + ": another offset to the point data")
            differ = [k for k in range(source.header_size) if tile.data[k] != source.data[k] and k not in changed]
            if differ:
                fail(name + ": header bytes differ from the input's at %s" % differ[:10])
        if tile.trailer != source.trailer:
            fail(name + ": its EVLRs differ from the input's")
        tile.check_summary()
    total = sum(len(v) for v in cells.values())
    if total != len(source.records):
        fail("lost records")
    print("tiles-ok %d records in %d tiles, %d trailer bytes each" % (total, len(names), len(source.trailer)))


def check_survey(folder, points, tolerance, size):
    names = las_files(folder)
    total = 0
    order = []
    for name in names:
        tile = Las(os.path.join(folder, name))
        if (tile.minor, tile.format, tile.record_length, tile.header_size) != (4, 6, 30, 375):
            fail(name + ": not LAS 1.4 point format 6 with 30-byte records")
        tile.check_summary()
        i, j = (int(v) for v in name[:-4].split("_")[-2:])
        order.append((i, j))
        cell = round(size / tile.scale[0])
        for r in tile.records:
            x, y, _ = tile.raw(r)
            if not (i * cell <= x < (i + 1) * cell and j * cell <= y < (j + 1) * cell):
                fail(name + ": a point outside the tile's cell")
            if r[16] not in (2, 5, 6):
                fail(name + ": class %d" % r[16])
        total += len(tile.records)
    if order != sorted(order):
        fail("name order is not (i, j) order")
    if abs(total - points) > tolerance * points:
        fail("%d points, asked %d within %g" % (total, points, tolerance))
    print("tiles-ok %d points in %d tiles" % (total, len(names)))


if __name__ == "__main__":
    if len(sys.argv) == 7 and sys.argv[1] == "retile":
        check_retile(sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6]))
    elif len(sys.argv) == 6 and sys.argv[1] == "survey":
        check_survey(sys.argv[2], int(float(sys.argv[3])), float(sys.argv[4]), float(sys.argv[5]))
    else:
        print(__doc__)
        sys.exit(2)
