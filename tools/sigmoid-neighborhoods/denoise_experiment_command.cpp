// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods denoise-experiment (denoise_command.h).

#include "commands.h"
#include "denoise_command.h"

namespace sigmoid_tool {

int run_denoise_experiment_command(int argc, char** argv) { return run_denoise_experiment(argc, argv); }

} // namespace sigmoid_tool
