# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module's optimal search against the C++ call, on a scan.

Times ``sigmoid_neighborhoods.optimal()`` on numpy arrays and compares it with the C++ benchmark
``optimal_search_benchmark`` on the same points and normals, one thread by default:

- (c) the optimal search, ``optimal(points, normals, all_features=False)``, against the binary's (c);
- (e) the equal-weights search, ``a_grid=[pi], b_grid=[pi]``, against the binary's (e);
- (c) with ``all_features=True`` (the point features in the same pass), against the binary's (f);
- (c) on Fortran-order (column-major) float64 arrays, read in place;
- (c) on float32 arrays, read in place. The scan's coordinates are UTM (about 5e6 m), where float32
  keeps a quarter of a metre: the float32 rows use the points moved to their mean first, and the
  row "float32 values as float64" runs the same values as contiguous float64, so that the cost of
  the float32 layout is told apart from the change of the points.

The scan is read once (``read()``, normals from the file, or estimated as the C++ benchmark does when
the file has none) and saved as .npy files in a temporary folder; every measurement then runs in a
fresh process that loads the arrays, so that each one's peak memory is its own, and the fastest of
``--repeat`` runs counts (other load on a shared machine only ever adds time). The runs are
interleaved, round after round: one run of the C++ benchmark (``--data scan --skip-plain --repeat 1``,
which also times CGAL's PCA and the features of one triple), then one of each module measurement, so
that a spell of other load does not fall on one side alone (``--cpp-once``: the C++ benchmark once,
``--repeat R``, before the module's runs).

Times: the wall time of the call, and its CPU time: on a shared machine, other load makes a process
wait for a core, which the wall time counts and the CPU time does not. The module's CPU time is
``time.process_time()`` around the call; the C++ benchmark's comes from ``perf record`` (cpu-clock
samples every millisecond, counted per measuring process), where perf is present and permitted
(``--no-perf``: wall times only).

Memory: in each process, after the inputs are loaded, freed memory is given back and the kernel's
peak resident size is reset (``/proc/self/clear_refs``, as the C++ benchmark does); the peak increase
of the call is ``ru_maxrss`` after it minus the resident size before it. The module adds no copy of
float64 contiguous inputs, so that increase should be the outputs' bytes plus the library's own
working memory, which the C++ benchmark reports as bytes per point above the input.

Run it (the module built by cmake in build/python, or installed with ``make python``):

    /usr/bin/python3 python/benchmark/benchmark_module.py [--scan FILE] [--repeat R] [--threads T]
        [--cpp-benchmark PATH] [--module-path DIR] [--cpp-once] [--no-perf] [--only c,e,...]

It prints a Markdown table: module time, C++ time, overhead (module / C++ - 1), the same in CPU time,
peak memory increase, outputs' size, the increase beyond the outputs against the C++ call's own, and
points per second.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# name -> (description, search options, input layout, C++ measurement compared with)
MEASUREMENTS = {
    "c": ("(c) optimal search", {"all_features": False}, "float64", "c"),
    "e": ("(e) equal-weights search", {"all_features": False, "equal": True}, "float64", "e"),
    "c_all": ("(c) with all_features=True", {"all_features": True}, "float64", "f"),
    "c_fortran": ("(c), Fortran-order float64", {"all_features": False}, "fortran", "c"),
    "c_float32_values": ("(c), float32 values as float64", {"all_features": False}, "float32_values", "c"),
    "c_float32": ("(c), float32", {"all_features": False}, "float32", "c"),
}


# ---------------------------------------------------------------------------------------------------
# Child processes: they alone import numpy and the module, so that the parent's memory and threads
# never reach a measurement.


def child_prepare(arguments):
    import numpy as np
    import sigmoid_neighborhoods as sn

    # One thread: the C++ benchmark estimates missing normals with one thread too, and the same
    # normals make the same search.
    try:
        data = sn.read(arguments["scan"], normals="file", threads=1)
        source = "file"
    except OSError:
        data = sn.read(arguments["scan"], normals="auto", threads=1)
        source = "estimated (PCA, spanning-forest orientation: the C++ benchmark's reading)"
    points, normals = data["points"], data["normals"]
    np.save(os.path.join(arguments["folder"], "points.npy"), points)
    np.save(os.path.join(arguments["folder"], "normals.npy"), normals)
    return {"points": int(points.shape[0]), "normals": source}


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def reset_peak():
    # Memory freed while loading goes back to the system, then the peak is reset to the current
    # size: the peak measured after the call is the call's own.
    import ctypes
    import gc

    gc.collect()
    try:
        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except OSError:
        pass
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        return True
    except OSError:
        return False


def child_measure(arguments):
    import math
    import resource

    import numpy as np
    import sigmoid_neighborhoods as sn

    _, options, layout, _ = MEASUREMENTS[arguments["name"]]
    points = np.load(os.path.join(arguments["folder"], "points.npy"))
    normals = np.load(os.path.join(arguments["folder"], "normals.npy"))
    if layout == "fortran":
        points, normals = np.asfortranarray(points), np.asfortranarray(normals)
    elif layout in ("float32", "float32_values"):
        # float32 cannot hold UTM coordinates to the centimetre: moved to their mean first, as a
        # float32 user's points would be
        points = (points - points.mean(axis=0)).astype(np.float32)
        normals = normals.astype(np.float32)
        if layout == "float32_values":
            points, normals = points.astype(np.float64), normals.astype(np.float64)
    input_bytes = points.nbytes + normals.nbytes
    keywords = {"threads": arguments["threads"], "all_features": options["all_features"]}
    if options.get("equal"):
        keywords["a_grid"] = [math.pi]
        keywords["b_grid"] = [math.pi]

    reset = reset_peak()
    before = resident_bytes()
    usage_before = resource.getrusage(resource.RUSAGE_SELF)
    start, start_cpu = time.perf_counter(), time.process_time()
    result = sn.optimal(points, normals, **keywords)
    seconds, cpu_seconds = time.perf_counter() - start, time.process_time() - start_cpu
    usage_after = resource.getrusage(resource.RUSAGE_SELF)
    peak_before, peak_after = usage_before.ru_maxrss * 1024, usage_after.ru_maxrss * 1024
    outputs = sum(v.nbytes for v in result.values() if isinstance(v, np.ndarray))
    return {
        "seconds": seconds,
        "cpu_seconds": cpu_seconds,
        # the kernel's share: first touches of new memory (the library's and the outputs' pages)
        "system_seconds": usage_after.ru_stime - usage_before.ru_stime,
        "page_faults": usage_after.ru_minflt - usage_before.ru_minflt,
        "points": int(points.shape[0]),
        "input_bytes": int(input_bytes),
        "resident_before": before,
        "peak_before": peak_before,
        "peak_after": peak_after,
        # without the reset, the peak before the call may be above the resident size (loading)
        "peak_increase": peak_after - (before if reset else peak_before),
        "peak_reset": reset,
        "output_bytes": int(outputs),
        "failures": int((result["k"] == 0).sum()),
    }


def run_child(task, arguments, module_path, threads):
    environment = dict(os.environ)
    environment["PYTHONPATH"] = os.pathsep.join(p for p in (module_path, environment.get("PYTHONPATH")) if p)
    environment["OMP_NUM_THREADS"] = str(threads)
    completed = subprocess.run(
        [sys.executable, os.path.abspath(__file__), "--child", task, json.dumps(arguments)],
        env=environment, capture_output=True, text=True)
    if completed.returncode != 0:
        sys.exit("benchmark_module.py: the %s process failed:\n%s" % (task, completed.stderr.strip()))
    return json.loads(completed.stdout.strip().splitlines()[-1])


# ---------------------------------------------------------------------------------------------------
# The C++ benchmark


# The order in which the C++ benchmark forks its measuring children with --skip-plain, each
# measurement --repeat times in a row (run() in benchmark/optimal_search_benchmark.cpp).
CPP_CHILDREN = ["a", "knn", "c", "e", "f", "d"]


def run_cpp(binary, scan, threads, repeat, perf, folder):
    environment = dict(os.environ)
    environment["OMP_NUM_THREADS"] = str(threads)
    command = [binary, "--data", "scan", "--scan", scan, "--threads", str(threads), "--skip-plain",
               "--repeat", str(repeat)]
    samples = os.path.join(folder, "perf.data")
    if perf:
        # cpu-clock samples every millisecond of CPU time, per process: the CPU time of each
        # measuring child, which waiting for a core under other load does not count
        command = [perf, "record", "-q", "-e", "cpu-clock", "-c", "1000000", "-o", samples, "--"] + command
    completed = subprocess.run(command, env=environment, capture_output=True, text=True)
    if completed.returncode != 0:
        sys.exit("benchmark_module.py: %s failed (%d):\n%s" % (binary, completed.returncode,
                                                                completed.stderr.strip()))
    parsed = parse_cpp(completed.stdout)
    if perf:
        add_cpu_times(parsed, perf, samples, repeat)
    return parsed, completed.stdout


def add_cpu_times(parsed, perf, samples, repeat):
    report = subprocess.run([perf, "report", "-i", samples, "--sort", "pid", "-n", "--stdio"],
                            capture_output=True, text=True).stdout
    # processes by id: the benchmark first, then its children in the order they were forked
    counts = sorted((int(m.group(2)), int(m.group(1)))
                    for m in re.finditer(r"^\s+[\d.]+%\s+(\d+)\s+(\d+):", report, re.M))
    children = [count for _, count in counts[1:]]
    if len(children) != len(CPP_CHILDREN) * repeat:
        print("benchmark_module.py: %d processes in the C++ benchmark's perf samples, %d expected: no C++ CPU "
              "times" % (len(children), len(CPP_CHILDREN) * repeat), file=sys.stderr)
        return
    for index, name in enumerate(CPP_CHILDREN):
        if name in parsed:
            cpu = min(children[index * repeat:(index + 1) * repeat]) / 1000.
            # a child's CPU time above its measured wall time would mean the order above is wrong
            if cpu > parsed[name]["seconds"] * 1.05 + 0.05:
                print("benchmark_module.py: the C++ benchmark's children are not in the expected order: no C++ CPU "
                      "times", file=sys.stderr)
                for other in CPP_CHILDREN:
                    parsed.get(other, {}).pop("cpu_seconds", None)
                return
            parsed[name]["cpu_seconds"] = cpu


def parse_cpp(text):
    # The benchmark prints rates to the point per second (and seconds to the hundredth only): the
    # times are taken from the rates.
    header = re.search(r"^(\S.*), (\d+) points \(.*\), (\d+) threads$", text, re.M)
    if not header:
        sys.exit("benchmark_module.py: cannot read the C++ benchmark's output:\n" + text)
    n = int(header.group(2))
    result = {"points": n, "threads": int(header.group(3))}
    for name in "acdef":
        match = re.search(r"^\s+\(%s\) .*?:\s+(\d+) points/s \(([\d.]+) s" % name, text, re.M)
        if match:
            result[name] = {"seconds": n / float(match.group(1)) if float(match.group(1)) > 0 else float(match.group(2))}
            per_point = re.search(r"^\s+\(%s\) .*, (\d+) bytes/point above the input" % name, text, re.M)
            if per_point:
                result[name]["extra_bytes"] = float(per_point.group(1)) * n
    # (c)'s peak to the tenth of a MB, finer than its bytes per point
    peak = re.search(r"\(c\) peak ([\d.]+) MB above it", text)
    if peak and "c" in result:
        result["c"]["extra_bytes"] = float(peak.group(1)) * 1e6
    if "c" not in result or "e" not in result:
        sys.exit("benchmark_module.py: no (c) or (e) in the C++ benchmark's output:\n" + text)
    return result


# ---------------------------------------------------------------------------------------------------


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scan", default=os.path.join(REPOSITORY, "..", "shared", "data", "scanned",
                                                       "lone-star_tls.ply"))
    parser.add_argument("--repeat", type=int, default=3, help="runs of each measurement; the fastest counts")
    parser.add_argument("--cpp-benchmark", default=os.path.join(REPOSITORY, "build", "benchmark",
                                                                "optimal_search_benchmark"))
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--module-path", default=os.path.join(REPOSITORY, "build", "python"),
                        help="added to the measuring processes' sys.path ('' for the installed module)")
    parser.add_argument("--only", default=",".join(MEASUREMENTS),
                        help="comma-separated measurements among " + ", ".join(MEASUREMENTS))
    parser.add_argument("--cpp-once", action="store_true",
                        help="run the C++ benchmark once with --repeat R first, instead of once per round with "
                             "--repeat 1 between the module's runs")
    parser.add_argument("--no-perf", action="store_true",
                        help="no CPU times of the C++ benchmark's measurements (they come from perf record)")
    parser.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    arguments = parser.parse_args()

    if arguments.child:
        task, child_arguments = arguments.child[0], json.loads(arguments.child[1])
        result = child_prepare(child_arguments) if task == "prepare" else child_measure(child_arguments)
        print(json.dumps(result))
        return

    scan = os.path.abspath(arguments.scan)
    if not os.path.isfile(scan):
        sys.exit("benchmark_module.py: no scan at %s (give one with --scan FILE)" % scan)
    binary = os.path.abspath(arguments.cpp_benchmark)
    if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
        sys.exit("benchmark_module.py: no C++ benchmark at %s (build it: cmake --build build --target "
                 "optimal_search_benchmark, or give one with --cpp-benchmark PATH)" % binary)
    if arguments.repeat < 1 or arguments.threads < 1:
        sys.exit("benchmark_module.py: --repeat and --threads must be at least 1")
    names = [name for name in arguments.only.split(",") if name]
    for name in names:
        if name not in MEASUREMENTS:
            sys.exit("benchmark_module.py: unknown measurement %r (expected %s)" % (name, ", ".join(MEASUREMENTS)))
    module_path = os.path.abspath(arguments.module_path) if arguments.module_path else ""
    perf = None
    if not arguments.no_perf:
        perf = shutil.which("perf")
        if perf and subprocess.run([perf, "stat", "-e", "cpu-clock", "-x", ",", "true"],
                                   capture_output=True).returncode != 0:
            perf = None
        if not perf:
            print("benchmark_module.py: perf is missing or not permitted: wall times only", file=sys.stderr)

    load = [os.getloadavg()[0]]
    folder = tempfile.mkdtemp(prefix="sn_benchmark_")
    try:
        print("reading %s ..." % scan, file=sys.stderr)
        prepared = run_child("prepare", {"scan": scan, "folder": folder}, module_path, 1)
        n = prepared["points"]

        # Round after round: one run of the C++ benchmark, then one of each module measurement, so
        # that a spell of other load falls on both sides alike; the fastest run of each counts.
        runs = {name: [] for name in names}
        cpp_runs = []
        rounds = arguments.repeat
        if arguments.cpp_once:
            print("C++ benchmark, --repeat %d ..." % arguments.repeat, file=sys.stderr)
            cpp_runs.append(run_cpp(binary, scan, arguments.threads, arguments.repeat, perf, folder))
        for round_ in range(rounds):
            if not arguments.cpp_once:
                print("round %d/%d: C++ benchmark ..." % (round_ + 1, rounds), file=sys.stderr)
                cpp_runs.append(run_cpp(binary, scan, arguments.threads, 1, perf, folder))
            for name in names:
                print("round %d/%d: %s ..." % (round_ + 1, rounds, MEASUREMENTS[name][0]), file=sys.stderr)
                runs[name].append(run_child("measure", {"name": name, "folder": folder, "threads": arguments.threads},
                                            module_path, arguments.threads))
            load.append(os.getloadavg()[0])
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    for parsed, _ in cpp_runs:
        if parsed["points"] != n:
            sys.exit("benchmark_module.py: the C++ benchmark read %d points, the module %d" % (parsed["points"], n))
    # the fastest run of each C++ measurement, and the largest memory of its runs
    cpp = {}
    for key in "acdef":
        measured = [parsed[key] for parsed, _ in cpp_runs if key in parsed]
        if measured:
            cpp[key] = {"seconds": min(m["seconds"] for m in measured)}
            if all("extra_bytes" in m for m in measured):
                cpp[key]["extra_bytes"] = max(m["extra_bytes"] for m in measured)
            if all("cpu_seconds" in m for m in measured):
                cpp[key]["cpu_seconds"] = min(m["cpu_seconds"] for m in measured)

    print("scan: %s, %d points, normals %s; %d thread(s), the fastest of %d runs; load average (1 min) "
          "during the runs %.2f-%.2f on %d CPUs" % (os.path.basename(scan), n, prepared["normals"], arguments.threads,
                                                    arguments.repeat, min(load), max(load), os.cpu_count()))
    print()
    print("| measurement | module time (s) | C++ time (s) | overhead | module CPU (s) | C++ CPU (s) | CPU overhead "
          "| peak memory increase (MB) | outputs (MB) | increase beyond outputs (MB) | C++ call's own (MB) | points/s |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    nan = float("nan")
    for name in names:
        description, _, _, cpp_name = MEASUREMENTS[name]
        best = min(runs[name], key=lambda r: r["seconds"])
        best_cpu = min(r["cpu_seconds"] for r in runs[name])
        # the largest increase of the runs: memory does not depend on the load
        increase = max(r["peak_increase"] for r in runs[name])
        outputs = best["output_bytes"]
        reference = cpp.get(cpp_name, {})
        cpp_seconds, cpp_cpu = reference.get("seconds", nan), reference.get("cpu_seconds", nan)
        cpp_extra = reference.get("extra_bytes", nan)
        label = description + (" (C++: (f))" if cpp_name == "f" else "")
        print("| %s | %.3f | %.3f | %+.1f %% | %.3f | %.3f | %+.1f %% | %.1f | %.1f | %.1f | %.1f | %s |" % (
            label, best["seconds"], cpp_seconds, 100. * (best["seconds"] / cpp_seconds - 1.), best_cpu, cpp_cpu,
            100. * (best_cpu / cpp_cpu - 1.), increase / 1e6, outputs / 1e6, (increase - outputs) / 1e6,
            cpp_extra / 1e6, format(int(round(n / best["seconds"])), ",")))
    print()
    # every run, with the CPU time of the call: under other load the wall time grows, the CPU time less
    for name in names:
        print("%s: runs %s s (CPU %s s, of which system %s s; %s page faults)" % (
            MEASUREMENTS[name][0], ", ".join("%.3f" % r["seconds"] for r in runs[name]),
            ", ".join("%.3f" % r["cpu_seconds"] for r in runs[name]),
            ", ".join("%.3f" % r["system_seconds"] for r in runs[name]),
            ", ".join(format(r["page_faults"], ",") for r in runs[name])))
    print()
    if "a" in cpp:
        line = "CGAL's Local_eigen_analysis at k = 20 (the C++ benchmark's (a)): %.3f s" % cpp["a"]["seconds"]
        for name, cpp_name in (("c", "c"), ("e", "e")):
            if name in runs:
                best = min(r["seconds"] for r in runs[name])
                line += "; %s/(a) %.2f (C++ %.2f)" % (MEASUREMENTS[name][0].split()[0], best / cpp["a"]["seconds"],
                                                     cpp[cpp_name]["seconds"] / cpp["a"]["seconds"])
        print(line)
    if any(r["failures"] for rs in runs.values() for r in rs):
        print("failures (k = 0): " + ", ".join("%s %d" % (name, runs[name][0]["failures"]) for name in names))
    print()
    if not arguments.cpp_once:
        print("C++ benchmark: runs " + "; ".join(
            "(%s) %s s" % (key, ", ".join("%.3f" % parsed[key]["seconds"] for parsed, _ in cpp_runs if key in parsed))
            for key in "acef"))
        if all("cpu_seconds" in parsed.get(key, {}) for parsed, _ in cpp_runs for key in "acef"):
            print("C++ benchmark: CPU " + "; ".join(
                "(%s) %s s" % (key, ", ".join("%.3f" % parsed[key]["cpu_seconds"] for parsed, _ in cpp_runs))
                for key in "acef"))
        print()
    print("C++ benchmark output (the last run):")
    print("\n".join("    " + line for line in cpp_runs[-1][1].strip().splitlines()))


if __name__ == "__main__":
    main()
