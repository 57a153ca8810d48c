#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# LAZ input against its uncompressed twin and an independent decoder:
# 1. decoding speed on one and two threads (laz_codec_benchmark: the records alone, then the whole
#    read into points) on the IGN tiles, autzen_trim.laz and a file of 14 chunks, beside the LAS twins;
# 2. npm's laz-perf (installed here, in a scratch folder, never a dependency) on the same files;
# 3. what reading LAZ adds to a command: `optimal` and `classify predict` on an IGN tile and its twin;
# 4. peak memory of reading the largest file, LAZ against LAS.
# usage: benchmark/laz_benchmark.sh BUILD_DIR [SHARED_DATA]   (run from the repository's root)
set -eu
build=${1:-build}
data=${2:-../shared/data}
tool=$build/tools/sigmoid-neighborhoods/sigmoid-neighborhoods
bench=$build/benchmark/laz_codec_benchmark
[ -x "$bench" ] && [ -x "$tool" ] || { echo "build $build first (make build)" >&2; exit 1; }
[ -d "$data/laz" ] || { echo "$data/laz not found" >&2; exit 1; }
data=$(cd "$data" && pwd) # node runs in the scratch folder
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
laz=$data/laz
ign="$laz/test_data_77050_627755_LA93_IGN69.laz $laz/test_data_77055_627755_LA93_IGN69.laz $laz/test_data_77060_627755_LA93_IGN69.laz"
files="$ign $laz/autzen_trim.laz $laz/las_with_several_extra_byte_bloc.laz $laz/test_semis_2023_0292_6833_LA93_IGN69.laz"
twins="$data/labeled/ign_lidarhd_77050_627755.las $data/labeled/ign_lidarhd_77055_627755.las $data/labeled/ign_lidarhd_77060_627755.las"

echo "== 1. decoding (median of 7 runs, warm page cache)"
# shellcheck disable=SC2086
"$bench" --threads 1,2 --runs 7 $files $twins

echo "== 2. npm laz-perf (WebAssembly under node), one thread"
if command -v npm > /dev/null && command -v node > /dev/null &&
   (cd "$scratch" && npm install --silent --no-audit --no-fund laz-perf@0.0.7 > npm.txt 2>&1); then
  cat > "$scratch/laz_perf.js" <<'EOF'
const { createLazPerf } = require('laz-perf');
const fs = require('fs');
(async () => {
  const L = await createLazPerf();
  for (const path of process.argv.slice(2)) {
    const file = fs.readFileSync(path);
    const times = [];
    let n = 0;
    for (let r = 0; r < 8; ++r) {
      const bytes = L._malloc(file.length);
      L.HEAPU8.set(file, bytes);
      const reader = new L.LASZip();
      const start = process.hrtime.bigint();
      reader.open(bytes, file.length);
      n = reader.getCount();
      const point = L._malloc(reader.getPointLength());
      for (let i = 0; i < n; ++i) reader.getPoint(point);
      if (r > 0) times.push(Number(process.hrtime.bigint() - start) / 1e9); // the first run warms up
      reader.delete(); L._free(point); L._free(bytes);
    }
    times.sort((a, b) => a - b);
    const median = times[Math.floor(times.length / 2)];
    console.log(`${path.split('/').pop().padEnd(52)} ${String(n).padStart(9)} ${median.toFixed(4).padStart(12)} ${(n / median / 1e6).toFixed(2).padStart(12)}`);
  }
})();
EOF
  echo "file                                                    points     decode_s    Mpoints/s"
  # shellcheck disable=SC2086
  (cd "$scratch" && node laz_perf.js $files 2>&1 | cut -c1-200)
else
  echo "npm or node missing, or laz-perf not installed: skipped"
fi

echo "== 3. a command on LAZ and on its LAS twin (median of 5 runs, 2 threads)"
median_time() { # seconds of the median run of a command
  for r in 1 2 3 4 5; do
    start=$(date +%s.%N); "$@" > /dev/null 2>&1; end=$(date +%s.%N)
    echo "$end - $start" | bc
  done | sort -n | sed -n 3p
}
"$tool" classify train "$data/labeled/ign_lidarhd_77055_627755.las" -o "$scratch/model.bin" --trees 10 > /dev/null 2>&1
for twin in "las $data/labeled/ign_lidarhd_77050_627755.las" "laz $laz/test_data_77050_627755_LA93_IGN69.laz"; do
  set -- $twin
  optimal=$(OMP_NUM_THREADS=2 median_time "$tool" optimal "$2" -o "$scratch/o.csv")
  predict=$(OMP_NUM_THREADS=2 median_time "$tool" classify predict "$scratch/model.bin" "$2" -o "$scratch/p.ply")
  echo "$1: optimal ${optimal} s, classify predict ${predict} s"
done

echo "== 4. peak memory of reading a tile, LAZ against its LAS twin (GNU time; the LAS twin's records are read 4 MB at a time)"
if [ -x /usr/bin/time ]; then
  for f in "$data/labeled/ign_lidarhd_77060_627755.las" "$laz/test_data_77060_627755_LA93_IGN69.laz" \
           "$laz/test_semis_2023_0292_6833_LA93_IGN69.laz"; do
    for t in 1 2; do
      /usr/bin/time -f "%M kB peak, $t thread(s): $(basename "$f")" "$bench" --threads "$t" --runs 0 "$f" 2>&1 > /dev/null | tail -1
    done
  done
else
  echo "/usr/bin/time missing: skipped"
fi
