#!/bin/bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The tiled pipeline at survey scale: a synthetic airborne survey (generate_survey, written once),
# every tile computed with its halo by 'optimal --catalog SURVEY --tile NAME', J jobs of T threads
# at a time under GNU parallel, each job's wall time and peak resident size recorded; then J tiles
# computed alone in memory, J at once, for the cost of the halo. Resumable: a tile whose
# NAME.tile.json (written last) is in the output folder is not computed again.
#
# usage: benchmark/tiled_survey_benchmark.sh [--points N] [--tile-size S] [--jobs J|auto] [--threads T|auto]
#          [--a-grid ANGLES] [--b-grid ANGLES] [--halo WIDTH] [--seed SEED] [--work DIR] [--discard-csv]
#          [--skip-alone]
#   --points: about N points (default 2e6); --tile-size: S metres (default 180): the survey has m x m
#       tiles, m the nearest to sqrt(N / 15) / S (see generate_survey --help)
#   --jobs, --threads: J jobs at once, T threads each (default auto: as many one-thread jobs as the
#       machine has cores, tiles and memory for, about 400 bytes per point of a tile and its halo, the
#       cores left over shared among them as threads; a job on one thread wastes no time waiting on
#       the others, so jobs come first)
#   --skip-alone: no tiles alone in memory after the survey
# The jobs run under GNU parallel, or under xargs -P where it is missing (the same jobs; a failed tile
# then stops no other, and the script reports it at the end).
#   --a-grid, --b-grid, --halo: passed to optimal (--halo to the tiles' jobs alone: the first halo,
#       instead of the one from the tile's density; one too narrow costs a second reading)
#   --work: the folder of the survey and the outputs (default survey-benchmark); the survey is
#       WORK/survey_N_S_SEED, generated when absent; the outputs WORK/optimal_N_S_SEED_TAG
#   --discard-csv: removes each tile's CSV once its job is done (its .tile.json, .log and .time kept):
#       for surveys whose CSVs would not fit on the disk (about 255 bytes per point)
# The table: wall time of this run and per point; the jobs' wall and CPU (user + system) time per
# point, which other load on the machine does not inflate; the largest peak resident size of a job;
# and the same for J middle tiles of the catalog computed alone, in memory, J at once (the same load).
# Environment: SIGMOID_NEIGHBORHOODS and GENERATE_SURVEY, the programs (default: the build folder
# next to this script).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
tool=${SIGMOID_NEIGHBORHOODS:-$here/../build/tools/sigmoid-neighborhoods/sigmoid-neighborhoods}
generator=${GENERATE_SURVEY:-$here/../build/benchmark/generate_survey}
points=2e6 tile_size=180 jobs=auto threads=auto seed=1 work=survey-benchmark discard_csv=0 skip_alone=0
grid=() halo=()
usage() { sed -n '/^# usage:/,/^# next to this script/p' "$0" | sed 's/^# \{0,1\}//'; exit "$1"; }
while [ $# -gt 0 ]; do
  case $1 in
    --points) points=$2; shift 2 ;;
    --tile-size) tile_size=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --a-grid|--b-grid) grid+=("$1" "$2"); shift 2 ;;
    --halo) halo=("$1" "$2"); shift 2 ;;
    --discard-csv) discard_csv=1; shift ;;
    --skip-alone) skip_alone=1; shift ;;
    -h|--help) usage 0 ;;
    *) echo "tiled_survey_benchmark.sh: unknown argument $1" >&2; usage 2 ;;
  esac
done
for program in "$tool" "$generator"; do
  [ -x "$program" ] || { echo "tiled_survey_benchmark.sh: $program not found (build the project)" >&2; exit 2; }
done

# The survey, written once: generated aside, then renamed, so that a folder there is complete.
mkdir -p "$work"
survey=$work/survey_${points}_${tile_size}_${seed}
if [ ! -d "$survey" ]; then
  rm -rf "$survey.partial"
  "$generator" "$points" "$survey.partial" --tile-size "$tile_size" --seed "$seed"
  mv "$survey.partial" "$survey"
fi
"$tool" catalog list "$survey" > "$work/catalog.csv"
tiles=$(wc -l < "$work/catalog.csv")
survey_points=$(awk -F, '{ s += $2 } END { print s }' "$work/catalog.csv")
survey_bytes=$(du -sb "$survey" | cut -f1)

# Jobs x threads for this machine: one-thread jobs on every core, as many as the tiles and the
# memory allow; the cores left over go to them as threads.
cores=$(nproc)
if [ "$jobs" = auto ]; then
  largest_tile=$(awk -F, '$2 > m { m = $2 } END { print m + 0 }' "$work/catalog.csv")
  available_kb=$(awk '/^MemAvailable/ { print $2 }' /proc/meminfo)
  by_memory=$(awk -v a="$available_kb" -v n="$largest_tile" 'BEGIN { j = int(a * 1024 / (400 * n * 1.1)); print j < 1 ? 1 : j }')
  jobs=$(printf '%s\n' "$cores" "$tiles" "$by_memory" | sort -n | head -1)
fi
[ "$threads" != auto ] || threads=$(( cores / jobs > 0 ? cores / jobs : 1 ))
if command -v parallel > /dev/null; then launcher=parallel; else launcher=xargs; fi

# Outputs per setting: the grids change the rows, the threads and the first halo only the times.
tag=$(printf '%s ' "${grid[@]+"${grid[@]}"}" "${halo[@]+"${halo[@]}"}" | cksum | cut -d' ' -f1)
out=$work/optimal_${points}_${tile_size}_${seed}_T${threads}_$tag
mkdir -p "$out"

# Runs a command with its stderr in LOG; its wall time and peak resident size in REPORT:
# /usr/bin/time -v's report or, where there is none, the same two lines, VmHWM read from /proc.
measure() {
  local report=$1 log=$2
  shift 2
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -v -o "$report" "$@" 2> "$log"
    return
  fi
  local start peak=0 hwm status=0
  start=$(date +%s.%N)
  "$@" 2> "$log" &
  local pid=$!
  while kill -0 "$pid" 2> /dev/null; do
    hwm=$(awk '/^VmHWM/ { print $2 }' "/proc/$pid/status" 2> /dev/null || true)
    [ -n "$hwm" ] && peak=$hwm
    sleep 0.2
  done
  wait "$pid" || status=$?
  awk -v a="$(date +%s.%N)" -v b="$start" -v m="$peak" 'BEGIN {
    printf "\tElapsed (wall clock) time (h:mm:ss or m:ss): 0:%.2f\n\tMaximum resident set size (kbytes): %d\n", a - b, m }' \
    > "$report"
  return "$status"
}
# One job: the tile's rows, NAME.time, NAME.log.
run_tile() {
  local name=$1
  [ -e "$out/$name.tile.json" ] && return 0 # done by an earlier run
  measure "$out/$name.time" "$out/$name.log" "$tool" optimal --catalog "$survey" --tile "$name" -o "$out/$name.csv" \
    --orientation up --threads "$threads" "${grid[@]+"${grid[@]}"}" "${halo[@]+"${halo[@]}"}"
  [ "$discard_csv" -eq 0 ] || rm -f "$out/$name.csv"
}
# The wall seconds, CPU seconds (0: unknown) and peak resident kB of a report.
read_time() {
  awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0; for(i = 1; i <= n; ++i) s = s * 60 + t[i] }
              /(User|System) time \(seconds\)/ { c += $2 }
              /Maximum resident set size/ { m = $2 } END { printf "%.2f %.2f %d\n", s, c, m }' "$1"
}
seconds_since() { awk -v a="$(date +%s.%N)" -v b="$1" 'BEGIN { printf "%.2f", a - b }'; }
export -f measure run_tile
export tool survey out threads discard_csv
export grid_text="${grid[*]+"${grid[*]}"}" halo_text="${halo[*]+"${halo[*]}"}"

done_before=$(cut -d, -f1 "$work/catalog.csv" | while read -r name; do [ ! -e "$out/$name.tile.json" ] || echo; done | wc -l)
echo "survey: $survey_points points in $tiles tiles ($survey_bytes bytes), $done_before tiles already done; $jobs jobs of $threads threads on $cores cores ($launcher)" >&2
start=$(date +%s.%N)
# GNU parallel or xargs runs the function in a new bash: the options travel as text (they have no spaces).
# Without GNU parallel, the same by hand: sigmoid-neighborhoods catalog list SURVEY --names |
#   xargs -P J -I{} sigmoid-neighborhoods optimal --catalog SURVEY --tile {} -o OUT/{}.csv --threads T
if [ "$launcher" = parallel ]; then
  "$tool" catalog list "$survey" --names |
    parallel -j "$jobs" --halt now,fail=1 --joblog "$out/joblog.txt" 'grid=($grid_text) halo=($halo_text); run_tile {}' ||
    { echo "tiled_survey_benchmark.sh: a tile failed: see $out/joblog.txt and its NAME.log" >&2; exit 1; }
else
  "$tool" catalog list "$survey" --names |
    xargs -P "$jobs" -I{} bash -c 'grid=($grid_text) halo=($halo_text); run_tile "$1"' _ {} ||
    { echo "tiled_survey_benchmark.sh: a tile failed: see its NAME.log in $out" >&2; exit 1; }
fi
wall=$(seconds_since "$start")

# The table: every tile's report, this run's wall.
job_seconds=0 cpu_seconds=0 peak_kb=0 peak_tile=
add() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a + b }'; }
while IFS=, read -r name _; do
  read -r seconds cpu kb < <(read_time "$out/$name.time")
  job_seconds=$(add "$job_seconds" "$seconds")
  cpu_seconds=$(add "$cpu_seconds" "$cpu")
  if [ "$kb" -gt "$peak_kb" ]; then peak_kb=$kb; peak_tile=$name; fi
done < "$work/catalog.csv"
csv_bytes=$(find "$out" -name '*.csv' -printf '%s\n' | awk '{ s += $1 } END { print s + 0 }')

# Tiles alone, in memory, J of them at once as the tile jobs ran (the same load on the machine):
# the middle ones of the catalog.
if [ "$skip_alone" -eq 0 ]; then
first=$(( (tiles + 1) / 2 ))
sed -n "${first},$((first + jobs - 1))p" "$work/catalog.csv" > "$work/alone.csv"
run_alone() {
  local name=$1 path=$2
  measure "$work/alone_$name.time" "$work/alone_$name.log" "$tool" optimal "$path" -o "$work/alone_$name.csv" \
    --orientation up --threads "$threads" "${grid[@]+"${grid[@]}"}"
  rm -f "$work/alone_$name.csv"
}
export -f run_alone
export work
awk -F, '{ path = $7; for(i = 8; i <= NF; ++i) path = path "," $i; print $1 "\t" path }' "$work/alone.csv" |
  xargs -P "$jobs" -n 1 -d '\n' bash -c 'grid=($grid_text); IFS=$(printf "\t") read -r n p <<< "$1"; run_alone "$n" "$p"' _ ||
  { echo "tiled_survey_benchmark.sh: a tile alone failed: see $work/alone_NAME.log" >&2; exit 1; }
alone_names= alone_points=0 alone_seconds=0 alone_cpu=0 alone_kb=0
while IFS=, read -r name count _; do
  read -r seconds cpu kb < <(read_time "$work/alone_$name.time")
  alone_names="$alone_names${alone_names:+ }$name"
  alone_points=$((alone_points + count))
  alone_seconds=$(add "$alone_seconds" "$seconds")
  alone_cpu=$(add "$alone_cpu" "$cpu")
  [ "$kb" -le "$alone_kb" ] || alone_kb=$kb
done < "$work/alone.csv"
alone_tiles=$(wc -l < "$work/alone.csv")
fi

per_point() { awk -v s="$1" -v n="$2" 'BEGIN { if(s > 0) printf "%.2f", 1e6 * s / n; else printf "n/a" }'; } # us
{
  echo
  echo "| run | tiles | points | jobs x threads (cores) | wall (s) | points per second | wall per point (us) | job wall per point (us) | job CPU per point (us) | largest peak RSS of a job (MiB) |"
  echo "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|"
  printf '| %s%s | %d | %d | %d x %d (%d) | %.1f | %s | %s | %s | %s | %d (%s) |\n' "$(basename "$survey")" \
    "$([ "$done_before" -eq 0 ] || echo " (resumed: $done_before tiles from earlier runs)")" "$tiles" "$survey_points" \
    "$jobs" "$threads" "$cores" "$wall" "$(awk -v n="$survey_points" -v s="$wall" 'BEGIN { printf "%.0f", n / s }')" \
    "$(per_point "$wall" "$survey_points")" "$(per_point "$job_seconds" "$survey_points")" \
    "$(per_point "$cpu_seconds" "$survey_points")" $((peak_kb / 1024)) "$peak_tile"
  [ "$skip_alone" -eq 1 ] ||
  printf '| tiles alone, in memory: %s | %d | %d | %d x %d (%d) | | | | %s | %s | %d |\n' "$alone_names" "$alone_tiles" \
    "$alone_points" "$jobs" "$threads" "$cores" "$(per_point "$alone_seconds" "$alone_points")" \
    "$(per_point "$alone_cpu" "$alone_points")" $((alone_kb / 1024))
  echo
  echo "survey files: $survey_bytes bytes; CSV outputs kept: ${csv_bytes:-0} bytes in $out"
} | tee -a "$work/results.md"
