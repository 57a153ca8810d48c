# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Sourced by the command-line tests: fail MESSAGE stops the test; expect_refusal PIECE COMMAND...
# runs COMMAND and requires exit code 2 and one line on stderr that holds PIECE (files in $dir).
fail() { echo "FAILED: $*"; exit 1; }
expect_refusal() {
  piece=$1; shift
  set +e; "$@" > "$dir/out.txt" 2> "$dir/err.txt"; code=$?; set -e
  [ "$code" -eq 2 ] || fail "exit $code, not 2: $* ($(cat "$dir/err.txt"))"
  grep -q -- "$piece" "$dir/err.txt" || fail "no '$piece' in: $(cat "$dir/err.txt")"
  [ "$(wc -l < "$dir/err.txt")" -eq 1 ] || fail "not one line: $(cat "$dir/err.txt")"
}
