#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Compares two output folders of benchmark/output_hashes.sh: every JSON file value by value, every
other file by its SHA-256 (SHA256SUMS), and prints every difference.

    compare_outputs.py OLD_OUTDIR NEW_OUTDIR

A JSON number is equal to another of the same value whatever its text (`0` and `0.0`, `0.1` and
`0.10000000000000001`); null equals null. run.json's date, host and seconds are left out. The exit
code is 0 when nothing differs, 1 otherwise.
"""
import json
import math
import os
import sys

UNTIMED = {"date", "host", "seconds"}


def compare(old, new, where, out):
    if isinstance(old, dict) and isinstance(new, dict):
        for key in old:
            if key not in new:
                out.append("%s/%s: only in the old file" % (where, key))
        for key in new:
            if key not in old:
                out.append("%s/%s: only in the new file" % (where, key))
        for key in old:
            if key in new and not (where.endswith("run.json") and key in UNTIMED):
                compare(old[key], new[key], "%s/%s" % (where, key), out)
    elif isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            out.append("%s: %d entries, now %d" % (where, len(old), len(new)))
        for i, (a, b) in enumerate(zip(old, new)):
            compare(a, b, "%s/%d" % (where, i), out)
    elif isinstance(old, bool) or isinstance(new, bool):
        if old is not new:
            out.append("%s: %r, now %r" % (where, old, new))
    elif isinstance(old, (int, float)) and isinstance(new, (int, float)):
        if not (old == new or (isinstance(old, float) and isinstance(new, float) and math.isnan(old) and math.isnan(new))):
            out.append("%s: %r, now %r" % (where, old, new))
    elif old != new:
        out.append("%s: %r, now %r" % (where, old, new))


def sums(folder):
    result = {}
    with open(os.path.join(folder, "SHA256SUMS")) as f:
        for line in f:
            digest, name = line.rstrip("\n").split("  ", 1)
            result[name] = digest
    return result


def main():
    old_dir, new_dir = sys.argv[1], sys.argv[2]
    old_sums, new_sums = sums(old_dir), sums(new_dir)
    differences, json_files, other_files = [], 0, 0
    for name in sorted(set(old_sums) | set(new_sums)):
        if name not in new_sums or name not in old_sums:
            differences.append("%s: only in the %s folder" % (name, "old" if name in old_sums else "new"))
        elif name.endswith(".json"):
            json_files += 1
            with open(os.path.join(old_dir, name)) as a, open(os.path.join(new_dir, name)) as b:
                compare(json.load(a), json.load(b), name, differences)
        else:
            other_files += 1
            if old_sums[name] != new_sums[name]:
                differences.append("%s: other bytes (SHA-256)" % name)
    # run.json is not hashed: compared too, its timings left out
    for root, _, files in os.walk(old_dir):
        for f in files:
            if f == "run.json":
                name = os.path.relpath(os.path.join(root, f), old_dir)
                other = os.path.join(new_dir, name)
                if not os.path.exists(other):
                    differences.append("%s: only in the old folder" % name)
                    continue
                json_files += 1
                with open(os.path.join(root, f)) as a, open(other) as b:
                    compare(json.load(a), json.load(b), name, differences)
    for d in differences:
        print(d)
    print("%d JSON files compared value by value, %d other files by SHA-256: %d differences"
          % (json_files, other_files, len(differences)))
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
