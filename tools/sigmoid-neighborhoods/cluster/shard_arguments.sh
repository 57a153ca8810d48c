# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Sourced by the scale-out recipes (evaluate_with_parallel.sh, evaluate_with_slurm.sh): reads their
# arguments DATA OUT N [REPOSITORY] [-- OPTIONS...] into data, out, shards, repository and tool
# (the executable: $SIGMOID_NEIGHBORHOODS, else sigmoid-neighborhoods on PATH), and leaves the
# scheduler's OPTIONS in "$@". Without enough arguments, prints the recipe's usage (its lines 5-11).
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
