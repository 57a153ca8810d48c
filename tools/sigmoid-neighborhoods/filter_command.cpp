// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods filter-normals (filter_command.h).

#include "commands.h"
#include "filter_command.h"

namespace sigmoid_tool {

int run_filter_normals_command(int argc, char** argv) { return run_filter_normals(argc, argv); }

} // namespace sigmoid_tool
