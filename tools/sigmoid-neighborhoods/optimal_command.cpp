// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods optimal (optimal_command.h).

#include "commands.h"
#include "optimal_command.h"

namespace sigmoid_tool {

int run_optimal_command(int argc, char** argv) { return run_optimal(argc, argv); }

} // namespace sigmoid_tool
