// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The commands of sigmoid-neighborhoods, one translation unit each (*_command.cpp), so that main.cpp
// and a change to one command compile in seconds, and the commands compile in parallel.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_COMMANDS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_COMMANDS_H

namespace sigmoid_tool {

int run_optimal_command(int argc, char** argv);            // optimal_command.cpp
int run_evaluate_command(int argc, char** argv);           // evaluate_command.cpp
int run_merge_command(int argc, char** argv);              // merge_command.cpp
int run_report_command(int argc, char** argv);             // report_command.cpp
int run_filter_normals_command(int argc, char** argv);     // filter_command.cpp
int run_denoise_experiment_command(int argc, char** argv); // denoise_experiment_command.cpp
int run_denoise_command(int argc, char** argv);            // denoise_command.cpp
int run_denoise_comparison_command(int argc, char** argv); // denoise_comparison_command.cpp
int run_classify(int argc, char** argv);                   // classify_command.cpp
int run_catalog(int argc, char** argv);                    // catalog_command.cpp
int run_catalog_retile(int argc, char** argv, const char* usage); // retile_command.cpp

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_COMMANDS_H
