#!/usr/bin/env bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Evaluates a repository in N shards with GNU parallel, on this machine or on several
# (--sshlogin, with DATA and OUT on a file system that all machines share), then merges them.
#
#   evaluate_with_parallel.sh DATA OUT N [REPOSITORY] [-- GNU parallel options, e.g. --sshlogin 4/node1,4/node2]
#
# A shard that stops early can be rerun with the same command: --resume keeps its finished models.
set -euo pipefail
. "$(dirname "$0")/shard_arguments.sh"

mkdir -p "$out"
seq 1 "$shards" | parallel --line-buffer --halt soon,fail=1 "$@" \
  "$tool" evaluate "$data" -o "$out/shard-{}" --repository "'$repository'" --shard "{}/$shards" --resume
"$tool" merge "$out"/shard-* -o "$out/merged"
