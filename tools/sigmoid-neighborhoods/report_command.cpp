// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods report (report_command.h).

#include "commands.h"
#include "report_command.h"

namespace sigmoid_tool {

int run_report_command(int argc, char** argv) { return run_report(argc, argv); }

} // namespace sigmoid_tool
