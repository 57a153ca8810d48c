#!/usr/bin/python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Split a labeled point set in space into two files: the diagonal quadrants about a centre.

    split_labeled.py IN OUT_A OUT_B [--center X Y | --center-class CODE]

OUT_A holds the points with x >= cx and y >= cy or x < cx and y < cy, OUT_B the two other
quadrants. The centre is the median x and y (the middle of a survey), --center (a scan's sensor), or
the median x and y of the points of class CODE (a rare class that one place holds, a drone survey's
few buildings: both files get some of it).
Two opposite quadrants each, rather than two halves: both files see the scene's middle and its
edges, near and far from a sensor, so a class that lives on one side of a half-cut (a beach's
vegetation, a scan's fence) is in both; each file has two borders where its neighborhoods end,
against one for a half.

IN: an uncompressed LAS file (the records copied byte for byte, header counts and bounds rewritten,
benchmark/thin_las.py) or a binary little-endian PLY (the vertex records copied, the count rewritten;
other elements refused). Standard library and numpy only.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from thin_las import read_las, write_las  # noqa: E402

PLY_TYPES = {"char": "i1", "uchar": "u1", "int8": "i1", "uint8": "u1", "short": "<i2", "ushort": "<u2",
             "int16": "<i2", "uint16": "<u2", "int": "<i4", "uint": "<u4", "int32": "<i4", "uint32": "<u4",
             "float": "<f4", "float32": "<f4", "double": "<f8", "float64": "<f8"}


def read_ply(path):
    """The header's lines, the vertex records (a numpy structured array) and their coordinates."""
    data = open(path, "rb").read()
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        sys.exit(path + ": not a PLY file")
    lines = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in lines:
        sys.exit(path + ": only binary little-endian PLY is split")
    fields, count, element = [], 0, None
    for line in lines:
        words = line.split()
        if words[:1] == ["element"]:
            element = words[1]
            if element != "vertex":
                sys.exit(path + ": element " + element + " is not split")
            count = int(words[2])
        elif words[:1] == ["property"] and element == "vertex":
            if words[1] == "list":
                sys.exit(path + ": list properties are not split")
            fields.append((words[2], PLY_TYPES[words[1]]))
    vertices = np.frombuffer(data, dtype=np.dtype(fields), count=count, offset=end + len(b"end_header\n"))
    xyz = np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1).astype(np.float64)
    return lines, vertices, xyz


def write_ply(lines, vertices, keep, path):
    kept = vertices[keep]
    header = [("element vertex %d" % len(kept)) if line.startswith("element vertex") else line for line in lines]
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\nend_header\n").encode("ascii"))
        f.write(kept.tobytes())
    return len(kept)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output_a")
    parser.add_argument("output_b")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--center", type=float, nargs=2, metavar=("X", "Y"))
    where.add_argument("--center-class", type=int, metavar="CODE")
    a = parser.parse_args()
    ply = a.input.lower().endswith(".ply")
    if ply:
        lines, vertices, xyz = read_ply(a.input)
        codes = vertices["label"] if a.center_class is not None else None
    else:
        data, records, xyz, codes = read_las(a.input)
    around = xyz
    if a.center_class is not None:
        around = xyz[codes == a.center_class]
        if len(around) == 0:
            sys.exit(a.input + ": no point of class %d" % a.center_class)
    cx, cy = a.center if a.center else (np.median(around[:, 0]), np.median(around[:, 1]))
    side_a = (xyz[:, 0] >= cx) == (xyz[:, 1] >= cy)
    for path, keep in ((a.output_a, side_a), (a.output_b, ~side_a)):
        n = write_ply(lines, vertices, keep, path) if ply else write_las(data, records, xyz, keep, path)
        print("%s: %d of %d points (quadrants about %.3f, %.3f)" % (path, n, len(xyz), cx, cy))


if __name__ == "__main__":
    main()
