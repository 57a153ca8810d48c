#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Where a command's time goes, and how much of it runs on one core.

Runs one command of the tool with --threads 1 and with each other count given, reads the phases of
its summary line ("... s (reading 1.20 s, search 5.02 s, writing 0.80 s)"), and prints for each phase
its seconds at each count (the median of --repeat runs) and its sequential fraction: Karp and Flatt's
f = (T_p / T_1 - 1 / p) / (1 - 1 / p), the share of the phase that Amdahl's law says did not speed
up, measured at the largest count p. The run's sequential time is the sum of f * T_1 over the phases;
its fraction of T_1 bounds the speed-up on any number of cores: 1 / (f + (1 - f) / n).

    benchmark/phase_fractions.py [--threads 1,2] [--repeat 3] -- TOOL optimal SCAN -o OUT.csv

The command must not contain --threads. Prints a Markdown table, then one line
`sequential: fraction=F of T1=S s, speed-up at 16 threads <= X` for scripts.
"""

import argparse
import re
import statistics
import subprocess
import sys

PHASES = re.compile(r"\(([a-z ]+ [0-9.]+ s(?:, [a-z ]+ [0-9.]+ s)*)\)\s*$")


def phases_of(stderr):
    """The phases of the last summary line of `stderr`, {name: seconds} in their order."""
    for line in reversed(stderr.splitlines()):
        m = PHASES.search(line)
        if m:
            result = {}
            for item in m.group(1).split(", "):
                name, seconds, _ = item.rsplit(" ", 2)
                result[name] = float(seconds)
            return result
    raise SystemExit("no phase timings in the command's output:\n" + stderr[-2000:])


def run(command, threads):
    p = subprocess.run(command + ["--threads", str(threads)], capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("the command failed (%d):\n%s" % (p.returncode, p.stderr[-2000:]))
    return phases_of(p.stderr)


def karp_flatt(t1, tp, p):
    if t1 <= 0 or p <= 1:
        return float("nan")
    return min(1.0, max(0.0, (tp / t1 - 1.0 / p) / (1.0 - 1.0 / p)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", default="1,2", help="thread counts, 1 first (default 1,2)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per count; the median is kept")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command or "--threads" in command:
        parser.error("give the command after --, without --threads")
    counts = [int(t) for t in args.threads.split(",")]
    if counts[0] != 1 or len(counts) < 2:
        parser.error("--threads must start with 1 and give at least one more count")

    medians = {}
    for t in counts:
        runs = [run(command, t) for _ in range(args.repeat)]
        names = list(runs[0])
        medians[t] = {n: statistics.median(r.get(n, 0.0) for r in runs) for n in names}
    names = list(medians[1])
    p = counts[-1]
    header = "| phase | " + " | ".join("%d thread%s (s)" % (t, "" if t == 1 else "s") for t in counts)
    print(header + " | speed-up at %d | sequential fraction |" % p)
    print("|---|" + "---:|" * (len(counts) + 2))
    sequential = 0.0
    for n in names + ["total"]:
        row = [sum(medians[t].values()) if n == "total" else medians[t].get(n, 0.0) for t in counts]
        f = karp_flatt(row[0], row[-1], p)
        if n != "total":
            sequential += f * row[0] if f == f else 0.0
        speedup = row[0] / row[-1] if row[-1] > 0 else float("nan")
        print("| %s | %s | %.2f | %.3f |" % (n, " | ".join("%.2f" % v for v in row), speedup, f))
    t1 = sum(medians[1].values())
    fraction = sequential / t1 if t1 > 0 else float("nan")
    bound = 1.0 / (fraction + (1.0 - fraction) / 16.0)
    print("sequential: fraction=%.3f of T1=%.2f s, speed-up at 16 threads <= %.1f" % (fraction, t1, bound))


if __name__ == "__main__":
    sys.exit(main())
