// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify (classify_command.cpp): train, predict, evaluate, experiment.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFY_COMMAND_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFY_COMMAND_H

namespace sigmoid_tool {

int run_classify(int argc, char** argv);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFY_COMMAND_H
