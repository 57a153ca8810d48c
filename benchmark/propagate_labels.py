#!/usr/bin/python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Score labels predicted on other points (a thinned copy) at the points of labeled LAS files.

    propagate_labels.py --truth A.las,B.las --predicted A.ply,B.ply [--labels ground=2,...]

Every point of a truth file takes the label of its nearest vertex in the matching prediction
(`classify predict`'s PLY: x, y, z, scalar_label); the score is that of `classify evaluate`: the
points whose code is in --labels, the IoU per class and their mean. With a prediction made on the
same file, it is `classify evaluate`'s (a check). numpy and scikit-learn's KDTree only.
"""
import argparse
import os
import sys

import numpy as np
from sklearn.neighbors import KDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import thin_las  # noqa: E402 (the LAS reader, beside this script)

DEFAULT_LABELS = "ground=2,low_vegetation=3+4,high_vegetation=5,building=6"


def read_las(path):
    _, _, xyz, codes = thin_las.read_las(path)
    return xyz, codes


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        sys.exit(path + ": not a binary little-endian PLY")
    types = {"float": "<f4", "double": "<f8", "int": "<i4", "uint": "<u4", "uchar": "u1", "char": "i1",
             "short": "<i2", "ushort": "<u2", "float32": "<f4", "float64": "<f8", "int32": "<i4",
             "uint8": "u1", "int8": "i1", "uint32": "<u4"}
    fields, count, in_vertex = [], 0, False
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count, in_vertex = int(words[2]), True
        elif words[:1] == ["element"]:
            in_vertex = False
        elif words[:1] == ["property"] and in_vertex:
            fields.append((words[2], types[words[1]]))
    vertices = np.frombuffer(data, dtype=np.dtype(fields), count=count, offset=end)
    xyz = np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1).astype(np.float64)
    return xyz, vertices["scalar_label"].astype(np.int64)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--truth", required=True)
    parser.add_argument("--predicted", required=True)
    parser.add_argument("--labels", default=DEFAULT_LABELS)
    a = parser.parse_args()
    names, code_to_class = [], {}
    for i, item in enumerate(a.labels.split(",")):
        name, codes = item.split("=")
        names.append(name)
        for code in codes.split("+"):
            code_to_class[int(code)] = i
    lookup = np.full(256, -1, dtype=np.int64)
    for code, c in code_to_class.items():
        lookup[code] = c
    confusion = np.zeros((len(names), len(names)), dtype=np.int64)
    for truth_path, predicted_path in zip(a.truth.split(","), a.predicted.split(",")):
        xyz, codes = read_las(truth_path)
        predicted_xyz, predicted = read_ply(predicted_path)
        nearest = KDTree(predicted_xyz).query(xyz, k=1, return_distance=False)[:, 0]
        truth = lookup[codes]
        keep = truth >= 0
        np.add.at(confusion, (truth[keep], predicted[nearest[keep]]), 1)
    tp = np.diag(confusion).astype(float)
    iou = tp / (confusion.sum(axis=0) + confusion.sum(axis=1) - tp)
    print("points %d, overall accuracy %.4f, mean IoU %.4f, IoU %s" % (
        confusion.sum(), tp.sum() / confusion.sum(), iou.mean(),
        " ".join("%s %.4f" % (n, v) for n, v in zip(names, iou))))


if __name__ == "__main__":
    main()
