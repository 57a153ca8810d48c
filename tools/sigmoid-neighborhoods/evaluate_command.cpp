// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods evaluate and merge (evaluate_command.h).

#include "commands.h"
#include "evaluate_command.h"

namespace sigmoid_tool {

int run_evaluate_command(int argc, char** argv) { return run_evaluate(argc, argv); }

int run_merge_command(int argc, char** argv) { return run_merge(argc, argv); }
} // namespace sigmoid_tool
