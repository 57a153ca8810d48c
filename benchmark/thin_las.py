#!/usr/bin/python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Thin an uncompressed LAS file by a factor, as a sparser survey of the same ground would be.

    thin_las.py IN.las OUT.las --factor 4 --method random|voxel [--seed 1]

random: each record kept with probability 1 / factor (a seeded generator; the kept records in the
file's order). voxel: one record per cubic cell anchored at the origin, the first of the cell in the
file's order, the cell's side found by bisection so that about n / factor records remain (a survey
of regular spacing). The header and the variable-length records are copied, the point counts (legacy,
LAS 1.4, and per return) and the bounding box rewritten; EVLRs are not copied (the labeled tiles have
none). Standard library and numpy only.
"""
import argparse
import struct
import sys

import numpy as np


def read_las(path):
    """The file's bytes, its records (one row of bytes each), their coordinates and their
    classification codes; exits on anything but an uncompressed LAS file."""
    data = open(path, "rb").read()
    if data[:4] != b"LASF" or data[104] & 0xC0:
        sys.exit(path + ": not an uncompressed LAS file")
    offset, = struct.unpack_from("<I", data, 96)
    record, = struct.unpack_from("<H", data, 105)
    count, = struct.unpack_from("<I", data, 107)
    if data[25] == 4:
        count = struct.unpack_from("<Q", data, 247)[0] or count
    scale = np.array(struct.unpack_from("<3d", data, 131))
    origin = np.array(struct.unpack_from("<3d", data, 155))
    records = np.frombuffer(data, dtype=np.uint8, count=count * record, offset=offset).reshape(count, record)
    xyz = records[:, :12].copy().view("<i4").astype(np.float64) * scale + origin
    extended = (data[104] & 0x3F) >= 6
    codes = records[:, 16].copy() if extended else records[:, 15] & 0x1F
    return data, records, xyz, codes


def write_las(data, records, xyz, keep, path):
    """The file of `data` with the records where `keep` holds: the header and the variable-length
    records copied, the point counts (legacy, LAS 1.4, per return) and the bounding box rewritten,
    no EVLR."""
    minor = data[25]
    offset, = struct.unpack_from("<I", data, 96)
    kept = records[keep]
    out = bytearray(data[:offset])
    n = len(kept)
    struct.pack_into("<I", out, 107, n if n < 2**32 else 0)
    points = xyz[keep]
    struct.pack_into("<6d", out, 179, points[:, 0].max(), points[:, 0].min(), points[:, 1].max(),
                     points[:, 1].min(), points[:, 2].max(), points[:, 2].min())
    extended = (data[104] & 0x3F) >= 6
    returns = (kept[:, 14] & 0x0F) if extended else (kept[:, 14] & 0x07)
    legacy = [int(np.sum(returns == r)) for r in range(1, 6)]
    struct.pack_into("<5I", out, 111, *legacy)
    if minor == 4:
        struct.pack_into("<Q", out, 247, n)
        struct.pack_into("<15Q", out, 255, *[int(np.sum(returns == r)) for r in range(1, 16)])
        struct.pack_into("<Q", out, 235, 0)  # no EVLRs copied
        struct.pack_into("<I", out, 243, 0)
    with open(path, "wb") as f:
        f.write(out)
        f.write(kept.tobytes())
    return n


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--factor", type=float, required=True)
    parser.add_argument("--method", choices=["random", "voxel"], required=True)
    parser.add_argument("--seed", type=int, default=1)
    a = parser.parse_args()
    data, records, xyz, _ = read_las(a.input)
    count = len(records)

    if a.method == "random":
        keep = np.random.default_rng(a.seed).random(count) < 1.0 / a.factor
    else:
        def voxel_keep(side):
            cells = np.floor(xyz / side).astype(np.int64)
            _, first = np.unique(cells, axis=0, return_index=True)
            mask = np.zeros(count, dtype=bool)
            mask[first] = True
            return mask
        low, high = 1e-3, 100.0
        for _ in range(40):  # the side whose cells keep n / factor records
            side = np.sqrt(low * high)
            if voxel_keep(side).sum() > count / a.factor:
                low = side
            else:
                high = side
        keep = voxel_keep(high)
    n = write_las(data, records, xyz, keep, a.output)
    print("%s: %d of %d points (%s, factor %g)" % (a.output, n, count, a.method, a.factor))


if __name__ == "__main__":
    main()
