#!/bin/bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The multi-core figures of benchmark/README.md ("Every core busy") in one run, for a machine with
# many cores where the project is not built: the tool, optimal_search_benchmark and generate_survey
# copied from a build with their shared libraries (see --bundle), then on that machine
#   - `optimal` on the lone-star scan on 1, 4 and all threads, with its phases, and its sequential
#     fraction (benchmark/phase_fractions.py when python3 is there);
#   - the optimal search alone, (c) and (e) of optimal_search_benchmark, on 1 and all threads, beside
#     pgeof's algorithm (g) and nanoflann's k-NN (h) where the benchmark was built with them;
#   - `classify predict` of the two eastern IGN tiles with a model of the default set and one of
#     CGAL's generator (trained beforehand: classify train on the four western tiles);
#   - a synthetic survey of N points (generate_survey) tile by tile on every core
#     (benchmark/tiled_survey_benchmark.sh, jobs x threads chosen for the machine).
#
# usage: benchmark/multicore_run.sh --bundle DIR BUILD SHARED_DATA MODELS_DIR  # on the build machine
#        benchmark/multicore_run.sh DIR [SURVEY_POINTS]                          # on the many-core one
# DIR holds bin/, lib/, data/ and models/; SURVEY_POINTS defaults to 52e6 (0: no survey).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)

if [ "${1:-}" = --bundle ]; then
  dir=$2 build=$3 shared=$4 models=$5
  mkdir -p "$dir/bin" "$dir/lib" "$dir/data" "$dir/models"
  cp "$build/tools/sigmoid-neighborhoods/sigmoid-neighborhoods" "$build/benchmark/optimal_search_benchmark" \
     "$build/benchmark/generate_survey" "$dir/bin/"
  for library in $(ldd "$dir"/bin/* | awk '$3 ~ /^\// { print $3 }' | sort -u); do
    case $(basename "$library") in libc.so*|libm.so*|libgcc_s.so*|ld-linux*) ;; *) cp -L "$library" "$dir/lib/" ;; esac
  done
  cp "$shared/scanned/lone-star_tls.ply" "$shared"/labeled/ign_lidarhd_77060_6277*.las "$dir/data/"
  cp "$models"/*.model "$dir/models/"
  du -sh "$dir"
  exit 0
fi

dir=$(cd "$1" && pwd) survey_points=${2:-52e6}
export LD_LIBRARY_PATH="$dir/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
tool=$dir/bin/sigmoid-neighborhoods
cores=$(nproc)
work=$(mktemp -d)
echo "machine: $cores cores, $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
"$tool" --help > /dev/null || { ldd "$tool"; exit 2; }

echo "## optimal on the scan"
for threads in 1 4 "$cores"; do
  "$tool" optimal "$dir/data/lone-star_tls.ply" -o "$work/scan.csv" --threads "$threads" 2>&1 | tail -1 |
    sed "s|^.*failures, |  $threads threads: |"
done
if command -v python3 > /dev/null; then
  python3 "$here/phase_fractions.py" --threads "1,$cores" --repeat 1 -- "$tool" optimal "$dir/data/lone-star_tls.ply" \
    -o "$work/scan.csv"
fi

echo "## the search alone, (c) and (e), beside pgeof's algorithm (g) and nanoflann's k-NN (h)"
for threads in 1 "$cores"; do
  "$dir/bin/optimal_search_benchmark" --data scan --scan "$dir/data/lone-star_tls.ply" --skip-plain --threads "$threads" \
    2>&1 | grep -E "^  \((a|c|e|g|h)\)|k-NN|summary" || true
done

echo "## classify predict, the two eastern tiles"
for model in "$dir"/models/*.model; do
  for threads in 1 2 "$cores"; do
    start=$(date +%s.%N)
    for tile in "$dir"/data/ign_lidarhd_*.las; do
      "$tool" classify predict "$model" "$tile" -o "$work/predict.ply" --threads "$threads" 2>&1 | tail -1 |
        sed "s|^|  $(basename "$model") $threads threads: |"
    done
    awk -v a="$start" -v b="$(date +%s.%N)" -v m="$(basename "$model")" -v t="$threads" \
      'BEGIN { printf "  %s, %d threads: both tiles %.2f s\n", m, t, b - a }'
  done
done

if [ "$survey_points" != 0 ]; then
  echo "## the survey"
  SIGMOID_NEIGHBORHOODS=$tool GENERATE_SURVEY=$dir/bin/generate_survey \
    "$here/tiled_survey_benchmark.sh" --points "$survey_points" --tile-size 465 --discard-csv --skip-alone \
    --work "$work/survey"
fi
rm -rf "$work"
