// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods merge`: the evaluation folders of shards (evaluate_command.cpp) joined into one.

#include "commands.h"

#include "command_line.h"
#include "evaluation_json.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <system_error>

namespace sigmoid_tool {

namespace {

const char* const MERGE_USAGE = "usage: sigmoid-neighborhoods merge OUTDIR... -o OUTDIR [--repository NAME]\n";

int run_merge(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT, {"-o", "--output", "--repository"},
                       {"-h", "--help"});
  if(print_help(args, MERGE_USAGE))
    return EXIT_OK;
  const std::string outdir = args.output();
  if(outdir.empty() || args.positional().empty())
    throw Usage_error("merge needs OUTDIR... -o OUTDIR");
  std::string repository = args.get("--repository");
  for(const auto& folder : args.positional())
  {
    const fs::path summary = fs::path(folder) / "summary.json";
    if(!fs::exists(summary))
      throw Usage_error(folder + " has no summary.json: not an evaluation folder");
    // each folder checked whole (its summary against its models) before anything is written, but
    // for the summary that this merge replaces
    std::error_code ec;
    const std::string name = fs::equivalent(folder, outdir, ec) ? read_summary_repository(folder)
                                                                : read_summary(folder)["repository"].get<std::string>();
    if(repository.empty())
      repository = name;
    else if(!args.has("--repository") && name != repository)
      throw Usage_error("folders of different repositories (" + repository + ", " + name +
                        "): pass --repository to merge them anyway");
  }
  // a model in two of the folders, and the models' settings, refused before anything is written
  const Evaluation_contents contents = read_evaluation_folders(args.positional());
  create_output_folder(outdir, "models");
  std::error_code ec;
  // Copy the model files, so that the merged folder is an evaluation folder like any other.
  for(const auto& folder : args.positional())
  {
    if(fs::equivalent(folder, outdir, ec))
      continue;
    for(const auto& m : model_files(folder))
    {
      const fs::path target = fs::path(outdir) / "models" / (m.first + ".json");
      fs::create_directories(target.parent_path());
      const std::string text = [&] {
        std::ifstream in(m.second);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }();
      write_file_atomically(target.string(), [&](std::ofstream& out) { out << text; });
      const fs::path csv = fs::path(folder) / "models" / (m.first + ".csv");
      if(fs::exists(csv))
        fs::copy_file(csv, fs::path(outdir) / "models" / (m.first + ".csv"), fs::copy_options::overwrite_existing);
    }
  }
  write_file_atomically((fs::path(outdir) / "failures.json").string(),
                        [&](std::ofstream& out) { write_failures_json(out, contents.failures, contents.small); });
  write_summary({outdir}, repository, (fs::path(outdir) / "summary.json").string());
  std::cerr << outdir << ": merged " << args.positional().size() << " folders\n";
  return EXIT_OK;
}

} // namespace

int run_merge_command(int argc, char** argv) { return run_merge(argc, argv); }

} // namespace sigmoid_tool
