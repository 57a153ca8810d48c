// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The folders CMake knows (tool_paths.cpp): the only translation unit whose flags name the source
// tree, so that a compiler cache serves the others to a clone in another folder.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_TOOL_PATHS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_TOOL_PATHS_H

namespace sigmoid_tool {
namespace tool_paths {

const char* script_dir();       // the plotting scripts in the source tree
const char* application_data(); // the default --data folder of denoise-experiment ("" when unknown)
const char* default_fandisk();   // libcgal-demo's fandisk as CMake extracted it ("" when absent)
const char* shared_data();       // ../shared/data beside the source tree ("" when unknown)

} // namespace tool_paths
} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_TOOL_PATHS_H
