// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods denoise (denoise_point_set_command.h).

#include "commands.h"
#include "denoise_point_set_command.h"

namespace sigmoid_tool {

int run_denoise_command(int argc, char** argv) { return run_denoise_point_set(argc, argv); }

} // namespace sigmoid_tool
