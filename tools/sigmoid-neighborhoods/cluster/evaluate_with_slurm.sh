#!/usr/bin/env bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Submits the evaluation of a repository as a Slurm job array of N shards, and a merge job that
# runs when every shard has succeeded. DATA and OUT must be on a file system the nodes share.
#
#   evaluate_with_slurm.sh DATA OUT N [REPOSITORY] [-- sbatch options, e.g. --partition=cpu --time=4:00:00]
#
# Rerunning the same command resumes: finished models of each shard are kept (--resume).
set -euo pipefail
. "$(dirname "$0")/shard_arguments.sh"

mkdir -p "$out/logs"
array_job=$(sbatch --parsable --job-name=sigmoid-evaluate --array="1-$shards" --cpus-per-task="${CPUS:-8}" \
  --output="$out/logs/shard-%a.log" "$@" \
  --wrap="\"$tool\" evaluate \"$data\" -o \"$out/shard-\$SLURM_ARRAY_TASK_ID\" --repository \"$repository\" \
          --shard \$SLURM_ARRAY_TASK_ID/$shards --threads \${SLURM_CPUS_PER_TASK:-1} --resume")
sbatch --parsable --job-name=sigmoid-merge --dependency="afterok:$array_job" --output="$out/logs/merge.log" "$@" \
  --wrap="\"$tool\" merge \"$out\"/shard-* -o \"$out/merged\""
echo "submitted job array $array_job ($shards shards); the merged evaluation will be in $out/merged"
