// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods: a thin command-line shell over the library.

#include "command_line.h"
#include "commands.h"

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <utility>

namespace {

// The exit code of a command that ran out of memory (std::bad_alloc, the address space limit of
// `ulimit -v` or of a cluster job included): one line on stderr and, as on any failure, no output file.
constexpr int EXIT_OUT_OF_MEMORY = 3;

const char* USAGE =
  "usage: sigmoid-neighborhoods COMMAND [ARGS]\n"
  "commands:\n"
  "  optimal   the optimal sigmoid weights and neighborhood size (a*, b*, k*) of every point\n"
  "  evaluate  the statistics of the paper's Section 5 over a repository of models (shardable)\n"
  "  merge     merges the evaluation folders of shards\n"
  "  report    Tables 2 and 3 (Markdown) and Figures 3-6 (PNG) of evaluation folders\n"
  "  filter-normals      the normal filter of Yadav et al. 2018, optionally with adaptive neighborhood sizes\n"
  "  denoise-experiment  the paper's Table 4: normal MSE of noisy, filtered and adaptively filtered normals\n"
  "  denoise   Yadav et al. 2018's three-stage denoising of a point set or a mesh's vertices\n"
  "  denoise-comparison  the denoiser against CGAL's jet and bilateral smoothing on noisy CAD models\n"
  "  classify  semantic classification (CGAL's random forest on CGAL's and the package's features)\n"
  "  catalog   tiles of a survey: list, merge the outputs of 'optimal --catalog --tile', cut a LAS file\n"
  "run 'sigmoid-neighborhoods COMMAND --help' for the options of a command\n"
  "exit codes: 0 done, 1 internal error, 2 bad usage or unusable input, 3 out of memory\n";

// The one line of a command that fails, and its exit code.
int fail(const std::string& command, const std::string& message, int exit_code)
{
  std::cerr << "sigmoid-neighborhoods " << command << ": " << message << '\n';
  return exit_code;
}

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
    typedef int (*Run)(int, char**);
    const std::pair<const char*, Run> commands[] = {
      {"optimal", run_optimal_command}, {"evaluate", run_evaluate_command}, {"merge", run_merge_command},
      {"report", run_report_command}, {"filter-normals", run_filter_normals_command},
      {"denoise-experiment", run_denoise_experiment_command}, {"denoise", run_denoise_command},
      {"denoise-comparison", run_denoise_comparison_command},
      {"classify", run_classify}, {"catalog", run_catalog}};
    for(const auto& c : commands)
      if(command == c.first)
        return c.second(argc, argv);
    if(command == "-h" || command == "--help" || command == "help")
    {
      std::cout << USAGE;
      return EXIT_OK;
    }
    std::cerr << "sigmoid-neighborhoods: unknown command '" << command << "'\n" << USAGE;
    return EXIT_BAD_INPUT;
  }
  catch(const Usage_error& e) { return fail(command, e.what(), EXIT_BAD_INPUT); }
  catch(const std::invalid_argument& e) { return fail(command, e.what(), EXIT_BAD_INPUT); }
  catch(const std::bad_alloc&) { return fail(command, "out of memory while running " + command, EXIT_OUT_OF_MEMORY); }
  catch(const std::exception& e) { return fail(command, std::string("internal error: ") + e.what(), EXIT_FAILED); }
}
