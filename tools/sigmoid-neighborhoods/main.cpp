// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods: a thin command-line shell over the library.

#include "command_line.h"
#include "optimal_command.h"
#include "evaluate_command.h"
#include "report_command.h"
#include "filter_command.h"
#include "denoise_command.h"

#include <exception>
#include <iostream>
#include <string>

namespace {

const char* USAGE =
  "usage: sigmoid-neighborhoods COMMAND [ARGS]\n"
  "commands:\n"
  "  optimal   the optimal sigmoid weights and neighborhood size (a*, b*, k*) of every point\n"
  "  evaluate  the statistics of the paper's Section 5 over a repository of models (shardable)\n"
  "  merge     merges the evaluation folders of shards\n"
  "  report    Tables 2 and 3 (Markdown) and Figures 3-6 (PNG) of evaluation folders\n"
  "  filter-normals      the normal filter of Yadav et al. 2018, optionally with adaptive neighborhood sizes\n"
  "  denoise-experiment  the paper's Table 4: normal MSE of noisy, filtered and adaptively filtered normals\n"
  "run 'sigmoid-neighborhoods COMMAND --help' for the options of a command\n";

} // namespace

int main(int argc, char** argv)
{
  using namespace sigmoid_tool;
  if(argc < 2)
  {
    std::cerr << USAGE;
    return EXIT_BAD_INPUT;
  }
  const std::string command = argv[1];
  try
  {
    if(command == "optimal")
      return run_optimal(argc, argv);
    if(command == "evaluate")
      return run_evaluate(argc, argv);
    if(command == "merge")
      return run_merge(argc, argv);
    if(command == "report")
      return run_report(argc, argv);
    if(command == "filter-normals")
      return run_filter_normals(argc, argv);
    if(command == "denoise-experiment")
      return run_denoise_experiment(argc, argv);
    if(command == "-h" || command == "--help" || command == "help")
    {
      std::cout << USAGE;
      return EXIT_OK;
    }
    std::cerr << "sigmoid-neighborhoods: unknown command '" << command << "'\n" << USAGE;
    return EXIT_BAD_INPUT;
  }
  catch(const Usage_error& e)
  {
    std::cerr << "sigmoid-neighborhoods " << command << ": " << e.what() << '\n';
    return EXIT_BAD_INPUT;
  }
  catch(const std::invalid_argument& e)
  {
    std::cerr << "sigmoid-neighborhoods " << command << ": " << e.what() << '\n';
    return EXIT_BAD_INPUT;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "sigmoid-neighborhoods " << command << ": out of memory\n";
    return EXIT_FAILED;
  }
  catch(const std::exception& e)
  {
    std::cerr << "sigmoid-neighborhoods " << command << ": internal error: " << e.what() << '\n';
    return EXIT_FAILED;
  }
}
