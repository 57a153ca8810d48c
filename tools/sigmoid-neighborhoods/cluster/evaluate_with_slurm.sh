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
if [ $# -lt 3 ]; then
  sed -n '5,11p' "$0" >&2
  exit 2
fi
data=$1 out=$2 shards=$3
shift 3
repository=$(basename "$data")
if [ $# -gt 0 ] && [ "$1" != "--" ]; then repository=$1; shift; fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
tool=${SIGMOID_NEIGHBORHOODS:-sigmoid-neighborhoods}

mkdir -p "$out/logs"
array_job=$(sbatch --parsable --job-name=sigmoid-evaluate --array="1-$shards" --cpus-per-task="${CPUS:-8}" \
  --output="$out/logs/shard-%a.log" "$@" \
  --wrap="\"$tool\" evaluate \"$data\" -o \"$out/shard-\$SLURM_ARRAY_TASK_ID\" --repository \"$repository\" \
          --shard \$SLURM_ARRAY_TASK_ID/$shards --threads \${SLURM_CPUS_PER_TASK:-1} --resume")
sbatch --parsable --job-name=sigmoid-merge --dependency="afterok:$array_job" --output="$out/logs/merge.log" "$@" \
  --wrap="\"$tool\" merge \"$out\"/shard-* -o \"$out/merged\""
echo "submitted job array $array_job ($shards shards); the merged evaluation will be in $out/merged"
