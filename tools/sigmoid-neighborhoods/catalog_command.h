// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods catalog (catalog_command.cpp): list the tiles of a survey, merge the outputs
// of its tiles, cut a large file into tiles.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_COMMAND_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_COMMAND_H

namespace sigmoid_tool {

int run_catalog(int argc, char** argv);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_COMMAND_H
