#!/usr/bin/env bash
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The optimal (a, b, k) of every point of a catalog of tiles, one tile per job with GNU parallel,
# on this machine or on several (--sshlogin, with SOURCE and OUT on a shared file system), each
# tile with its exact halo; then the rows merged in the catalog's order into OUT/union.csv.
#
#   optimal_tiles_with_parallel.sh SOURCE OUT [optimal options] [-- GNU parallel options, e.g. -j 4]
#
# SOURCE: a folder of tiles or a list file (sigmoid-neighborhoods catalog list). Rerunning the same
# command resumes: a tile whose OUT/tiles/NAME.tile.json exists (written last) is not redone.
set -euo pipefail
. "$(dirname "$0")/tile_arguments.sh"

mkdir -p "$out/tiles"
"$tool" catalog list "$source" --names |
  parallel --line-buffer --halt soon,fail=1 "$@" \
    "[ -e '$out/tiles/{}.tile.json' ] || '$tool' optimal --catalog '$source' --tile {} -o '$out/tiles/{}.csv' $options"
"$tool" catalog merge "$source" "$out/tiles" -o "$out/union.csv"
