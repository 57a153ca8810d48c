// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The point-set denoising commands, compiled in their own translation unit (denoising_commands.cpp):
// CGAL's smoothing and AABB tree templates are heavy.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_DENOISING_COMMANDS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_DENOISING_COMMANDS_H

namespace sigmoid_tool {

// `sigmoid-neighborhoods denoise`
int run_denoise(int argc, char** argv);
// `sigmoid-neighborhoods denoise-comparison`
int run_denoise_comparison_command(int argc, char** argv);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_DENOISING_COMMANDS_H
