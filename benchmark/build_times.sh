#!/usr/bin/env bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# What the build costs a newcomer, a developer and a CGAL user (benchmark/README.md, "Build times"):
#  1. a fresh clone's `make evaluate`, phase by phase, with an empty ccache of its own (the Debian
#     packages are those already installed: `make deps` then only checks them);
#  2. every translation unit of the tool, its compile time and peak memory (one job, so that the
#     figures do not depend on what runs beside them), and the rest of `make build` with all cores;
#  3. a CGAL user's translation unit beside CGAL's comparable example, compiled one after the other
#     with the same flags: time, peak memory and their ratios;
#  4. rebuilds: after touching one tool source, after touching one library header (the tool alone),
#     and `pip install ./python` in a fresh virtual environment;
#  5. with --ci, `.ci/run` on the clone, timed (CI's own command: sanitizers, then `make test`).
#
#   benchmark/build_times.sh [--ci] [WORKDIR]     (default WORKDIR: /tmp/sn-build-times)
set -euo pipefail
# The whole script is read before it runs (one block): it goes on even if the file changes meanwhile.
{
run_ci=0
if [ "${1:-}" = "--ci" ]; then run_ci=1; shift; fi
repo=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-/tmp/sn-build-times}
jobs=$(nproc)
rm -rf "$work"; mkdir -p "$work"
clone="$work/clone"
git clone -q "$repo" "$clone"
# ../shared beside the clone, as CI has it
[ -d "$repo/../shared" ] && ln -s "$(cd "$repo/../shared" && pwd)" "$work/shared"
export CCACHE_DIR="$work/ccache"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-$jobs}
table="$work/build_times.md"
row() { echo "| $1 | $2 |" | tee -a "$table"; }
seconds() { local s=$1; shift; local t0; t0=$(date +%s.%N); "$@" > "$work/last.log" 2>&1;
            echo "$(date +%s.%N) $t0" | awk '{printf "%.0f\n", $1 - $2}' > "$work/$s.seconds"; }
# A change that a compiler cache cannot serve (a comment would be: ccache compares the preprocessed
# text): a new declaration at the end of the file, inside a header's include guard (a unit may include
# the header twice).
edit() {
  local declaration="[[maybe_unused]] static const int build_times_$(date +%s%N) = 0;"
  case $1 in
    *.h) /usr/bin/python3 - "$1" "$declaration" <<'PY' ;;
import sys
path, declaration = sys.argv[1], sys.argv[2]
text = open(path).read()
guard = text.rindex("#endif")
open(path, "w").write(text[:guard] + declaration + "\n\n" + text[guard:])
PY
    *) echo "$declaration" >> "$1" ;;
  esac
}

{
  echo "Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)," \
       "$(g++ --version | head -1), ccache $(ccache --version | head -1 | awk '{print $3}') (empty at the start)"
  echo
  echo "| step | seconds |"
  echo "|---|---:|"
} > "$table"

# 1. make evaluate, phase by phase (the same targets as the Makefile's evaluate)
cd "$clone"
seconds deps make deps-evaluate; row "make deps-evaluate (the packages already installed: checked only)" "$(cat "$work/deps.seconds")"
seconds build_tool make build-tool; row "configure and build the tool (empty ccache)" "$(cat "$work/build_tool.seconds")"
seconds corpus make corpus; row "extract the corpus" "$(cat "$work/corpus.seconds")"
seconds main_job make evaluate; row "main job (make evaluate, nothing left to build)" "$(cat "$work/main_job.seconds")"
total=$(cat "$work"/{deps,build_tool,corpus,main_job}.seconds | awk '{s += $1} END {print s}')
row "**make evaluate, all phases**" "**$total**"

# 4. incremental rebuilds of the tool
edit tools/sigmoid-neighborhoods/report_command.cpp
seconds touch_tool make build-tool; row "rebuild after editing tools/sigmoid-neighborhoods/report_command.cpp" "$(cat "$work/touch_tool.seconds")"
edit include/CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h
seconds touch_header make build-tool
git checkout -q -- tools/sigmoid-neighborhoods/report_command.cpp include/CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h
row "rebuild of the tool after editing include/CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h" "$(cat "$work/touch_header.seconds")"

# the rest of make test's build, from the warm cache of the tool
seconds build_all make build; row "make build after make evaluate (tests, examples, module, benchmarks)" "$(cat "$work/build_all.seconds")"

# 2. every translation unit of the tool and the readers' library, one at a time, without ccache
cmake -S . -B "$work/units" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  -DCMAKE_CXX_COMPILER_LAUNCHER= > /dev/null
{
  echo
  echo "The tool's translation units, compiled one at a time without ccache (-O3):"
  echo
  echo "| translation unit | seconds | peak memory (MB) |"
  echo "|---|---:|---:|"
} >> "$table"
/usr/bin/python3 - "$work/units/compile_commands.json" "$clone" >> "$table" <<'EOF'
import json, os, resource, shlex, subprocess, sys, time
commands, root = sys.argv[1], sys.argv[2]
for c in json.load(open(commands)):
    name = os.path.relpath(c["file"], root)
    if not name.startswith(("tools/", "src/")):
        continue
    args = shlex.split(c["command"])
    out = args.index("-o")
    args[out + 1] = "/dev/null"
    t0 = time.time()
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    p = subprocess.run(["/usr/bin/time", "-f", "%M"] + args, cwd=c["directory"], stderr=subprocess.PIPE, text=True)
    peak = int(p.stderr.strip().split("\n")[-1]) // 1024 if p.returncode == 0 else -1
    print(f"| {name} | {time.time() - t0:.0f} | {peak} |", flush=True)
EOF

# 3. a user's translation unit beside CGAL's example
ex="$work/cgal-examples"; mkdir -p "$ex"
tar -xzf /usr/share/doc/libcgal-dev/examples.tar.gz -C "$ex" examples/Point_set_processing_3/normals_example.cpp \
  examples/Classification/example_ethz_random_forest.cpp
flags="-DBOOST_ALL_NO_LIB -DCGAL_EIGEN3_ENABLED -DCGAL_USE_GMPXX=1 -I$clone/include -isystem /usr/include/eigen3 -O3 -DNDEBUG -frounding-math -fopenmp -std=gnu++17"
# $2: the example's own macros (those its CMake target gives it: CGAL::Sigmoid_neighborhoods_core's)
measure() { /usr/bin/time -f "%e %M" -o "$work/tu.txt" g++ $flags ${2:-} -c "$1" -o /dev/null; cat "$work/tu.txt"; }
{
  echo
  echo "A CGAL user's translation unit beside CGAL 5.5's comparable example, one after the other, the same flags (\`$flags\`, \`-c\`):"
  echo
  echo "| translation unit | seconds | peak memory (MB) | CGAL's example | seconds | peak memory (MB) | time ratio | memory ratio |"
  echo "|---|---:|---:|---|---:|---:|---:|---:|"
} >> "$table"
pair() {
  read -r t1 m1 < <(measure "$clone/examples/$1" "${3:-}")
  read -r t2 m2 < <(measure "$ex/examples/$2")
  echo "| examples/$1${3:+ ($3)} | $t1 | $((m1 / 1024)) | $2 | $t2 | $((m2 / 1024)) |" \
       "$(echo "$t1 $t2" | awk '{printf "%.2f", $1 / $2}') | $(echo "$m1 $m2" | awk '{printf "%.2f", $1 / $2}') |" | tee -a "$table"
}
# as CMake builds them (linking the kernels compiled once), then header-only
core=-DCGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
pair optimal_point_set_example.cpp Point_set_processing_3/normals_example.cpp "$core"
pair classification_example.cpp Classification/example_ethz_random_forest.cpp "$core"
pair optimal_point_set_example.cpp Point_set_processing_3/normals_example.cpp
pair classification_example.cpp Classification/example_ethz_random_forest.cpp

# pip install ./python in a fresh virtual environment (no compiler cache)
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
seconds pip env CCACHE_DISABLE=1 "$work/venv/bin/pip" install --no-build-isolation --no-index --no-deps ./python
echo >> "$table"; echo "| step | seconds |" >> "$table"; echo "|---|---:|" >> "$table"
row "pip install ./python in a fresh venv ($jobs cores)" "$(cat "$work/pip.seconds")"

# 5. CI's command on the clone
if [ "$run_ci" = 1 ]; then
  seconds ci .ci/run; row ".ci/run (cold sanitizer build, then make test on the warm release build)" "$(cat "$work/ci.seconds")"
fi
echo "Table: $table"
exit
}
