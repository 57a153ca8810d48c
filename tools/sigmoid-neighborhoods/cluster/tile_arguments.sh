# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Sourced by the tile recipes (optimal_tiles_with_parallel.sh, optimal_tiles_with_slurm.sh): reads
# their arguments SOURCE OUT [OPTIMAL OPTIONS...] [-- SCHEDULER OPTIONS...] into source, out, tool
# (the executable: $SIGMOID_NEIGHBORHOODS, else sigmoid-neighborhoods on PATH) and options (the
# optimal options quoted for a shell command line), and leaves the scheduler's options in "$@". Without enough arguments, prints the
# recipe's usage (its lines 5-12).
if [ $# -lt 2 ]; then
  sed -n '5,12p' "$0" >&2
  exit 2
fi
source=$1 out=$2
shift 2
optimal_options=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do optimal_options+=("$1"); shift; done
[ $# -gt 0 ] && shift
options=""
[ ${#optimal_options[@]} -gt 0 ] && options=$(printf ' %q' "${optimal_options[@]}")
tool=${SIGMOID_NEIGHBORHOODS:-sigmoid-neighborhoods}
