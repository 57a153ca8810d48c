#!/usr/bin/env bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Submits the optimal (a, b, k) of a catalog of tiles as a Slurm job array, one task per tile (each
# with its exact halo), and a merge job, run when every task has succeeded, that writes OUT/union.csv.
#
#   optimal_tiles_with_slurm.sh SOURCE OUT [optimal options] [-- sbatch options, e.g. --partition=cpu]
#
# SOURCE and OUT must be on a file system the nodes share. Rerunning the same command resumes: a
# tile whose OUT/tiles/NAME.tile.json exists (written last) is not redone.
set -euo pipefail
. "$(dirname "$0")/tile_arguments.sh"

mkdir -p "$out/tiles" "$out/logs"
"$tool" catalog list "$source" --names > "$out/tiles.txt"
tiles=$(wc -l < "$out/tiles.txt")
array_job=$(sbatch --parsable --job-name=sigmoid-tiles --array="1-$tiles" --cpus-per-task="${CPUS:-8}" \
  --output="$out/logs/tile-%a.log" "$@" \
  --wrap="tile=\$(sed -n \"\${SLURM_ARRAY_TASK_ID}p\" \"$out/tiles.txt\"); \
          [ -e \"$out/tiles/\$tile.tile.json\" ] || \"$tool\" optimal --catalog \"$source\" --tile \"\$tile\" \
          -o \"$out/tiles/\$tile.csv\" --threads \${SLURM_CPUS_PER_TASK:-1} $options")
sbatch --parsable --job-name=sigmoid-tiles-merge --dependency="afterok:$array_job" --output="$out/logs/merge.log" "$@" \
  --wrap="\"$tool\" catalog merge \"$source\" \"$out/tiles\" -o \"$out/union.csv\""
echo "submitted job array $array_job ($tiles tiles); the union will be in $out/union.csv"
