#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# with_data.sh FILE... -- COMMAND ARGS...: runs the command where every FILE exists, else exits 77,
# which ctest reports as skipped (SKIP_RETURN_CODE): a test whose data is missing never passes.
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
  if [ ! -e "$1" ]; then
    echo "skipped: $1 is missing"
    exit 77
  fi
  shift
done
[ "$1" = "--" ] && shift
exec "$@"
