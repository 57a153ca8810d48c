// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods denoise-experiment`: the command line of the paper's Table 4, whose
// replication (models, published numbers, data, experiment, tables) is in experiments/.

#include "command_line.h"
#include "commands.h"
#include "denoise_options.h"
#include "experiments/table4_data.h"
#include "experiments/table4_experiment.h"
#include "experiments/table4_models.h"
#include "experiments/table4_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const DENOISE_EXPERIMENT_USAGE =
  "usage: sigmoid-neighborhoods denoise-experiment [MODELS...] -o DIR [--noise 0.3,0.6] [--seed 1]\n"
  "         [--data DIR] [--fandisk FILE] [--figure-model NAME] [--noisy-normals mesh|pca] [--threads N]\n"
  "  MODELS: cube bearing fandisk sharp_sphere fertility octahedron rockerarm (default: all seven), or mesh\n"
  "          files (filtered with p = 50, cut-off 0.9, eigenvalue threshold 0.25)\n"
  "  cube, octahedron: generated (1,946 and 16,386 vertices); fandisk: --fandisk FILE, else libcgal-demo's\n"
  "          data/meshes/fandisk.off as CMake extracted it;\n"
  "  the others: NAME.off/.obj/.ply/.stl in --data DIR (default: CMake's SIGMOID_NEIGHBORHOODS_APPLICATION_DATA,\n"
  "          ../shared/data/application), skipped if absent\n"
  "  --noise: noise levels, sd in units of l (mean distance to the 6 nearest neighbors)\n"
  "  --noisy-normals: the filter's input normals, vertex normals of the noisy mesh (default) or PCA over\n"
  "                   12 neighbors oriented like the noise-free normals\n"
  "  writes DIR/table4.md, DIR/table4.csv, DIR/normal_error_MODEL.csv and .png, DIR/timings.csv\n";

// The options and the models named on the command line, checked before anything is read.
Denoise_options experiment_options(const Arguments& args, std::vector<std::string>& names)
{
  Denoise_options o;
  o.output = args.output();
  if(o.output.empty())
    throw Usage_error("denoise-experiment needs -o DIR");
  if(args.has("--noise"))
    o.noise = parse_noise_levels(args.get("--noise"));
  if(args.has("--seed"))
    o.seed = parse_seed(args.get("--seed"));
  o.data_dir = args.get("--data", default_application_data());
  o.fandisk = args.get("--fandisk");
  const std::string normals = args.get("--noisy-normals", "mesh");
  if(normals != "mesh" && normals != "pca")
    throw Usage_error("--noisy-normals must be mesh or pca, got '" + normals + "'");
  o.pca_normals = normals == "pca";
  o.threads = read_threads(args);
  names = args.positional();
  if(names.empty())
    for(const auto& m : table4_models())
      names.push_back(m.name);
  std::error_code ec;
  for(const auto& name : names)
    if(find_table4_model(name) == nullptr && !fs::is_regular_file(name, ec))
      throw Usage_error("unknown model '" + name +
                        "': expected cube, bearing, fandisk, sharp_sphere, fertility, octahedron, rockerarm or a mesh file");
  o.figure_model = args.get("--figure-model");
  if(!o.figure_model.empty() && std::find(names.begin(), names.end(), o.figure_model) == names.end())
    throw Usage_error("--figure-model " + o.figure_model + " is not among the models run");
  if(!o.fandisk.empty() && !fs::is_regular_file(o.fandisk, ec))
    throw Usage_error("--fandisk " + o.fandisk + ": no such file");
  return o;
}

// Runs every loaded model at every noise level into `results`, one line of `timings` each, and
// writes the per-point errors of the figure's model; returns that model's name in the files.
std::string run_experiment_models(const Denoise_inputs& inputs, const Denoise_options& o,
                                  std::vector<Denoise_result>& results, std::vector<std::string>& timings)
{
  std::string figure_name;
  for(const auto& l : inputs.loaded)
  {
    const std::size_t first = results.size();
    for(Denoise_result& r : run_denoise_model(l, o))
    {
      char line[256];
      std::snprintf(line, sizeof(line), "%s,%s,%zu,%u,%.3f,%.3f", r.model.c_str(), level_name(r.level).c_str(),
                    r.points, r.iterations, r.seconds_default, r.seconds_adaptive);
      timings.push_back(line);
      std::cerr << "denoise-experiment: " << r.title << " at " << level_name(r.level) << " l: MSE noise "
                << number9(r.mse_noise) << ", default " << number9(r.mse_default) << " (" << r.seconds_default
                << " s), adaptive " << number9(r.mse_adaptive) << " (" << r.seconds_adaptive << " s)\n";
      results.push_back(std::move(r));
    }
    if(l.name == o.figure_model)
    {
      figure_name = l.settings.name;
      std::vector<const Denoise_result*> figure;
      for(std::size_t i = first; i < results.size(); ++i)
        figure.push_back(&results[i]);
      const std::string csv = (fs::path(o.output) / ("normal_error_" + figure_name + ".csv")).string();
      write_file_atomically(csv, [&](std::ofstream& out) { write_error_csv(out, l.mesh, figure); });
    }
    for(std::size_t i = first; i < results.size(); ++i) // per-point errors are no longer needed
    {
      results[i].error_noise.clear();
      results[i].error_default.clear();
      results[i].error_adaptive.clear();
    }
  }
  return figure_name;
}

void write_experiment_tables(const std::vector<Denoise_result>& results, const std::vector<std::string>& timings,
                             const Denoise_inputs& inputs, const Denoise_options& o)
{
  write_file_atomically((fs::path(o.output) / "table4.csv").string(),
                        [&](std::ofstream& out) { write_table4_csv(out, results); });
  write_file_atomically((fs::path(o.output) / "table4.md").string(), [&](std::ofstream& out) {
    write_table4_markdown(out, results, inputs.sources, inputs.skipped, o);
  });
  write_file_atomically((fs::path(o.output) / "timings.csv").string(), [&](std::ofstream& out) {
    out << "model,noise,points,iterations,seconds_default,seconds_adaptive\n";
    for(const auto& t : timings)
      out << t << '\n';
  });
}

} // namespace

int run_denoise_experiment_command(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT,
                       {"-o", "--output", "--noise", "--seed", "--data", "--fandisk", "--figure-model",
                        "--noisy-normals", "--threads"},
                       {"-h", "--help"});
  if(print_help(args, DENOISE_EXPERIMENT_USAGE))
    return EXIT_OK;
  std::vector<std::string> names;
  Denoise_options o = experiment_options(args, names);

  // Models first (a bad file stops the run before anything is written), then the experiment.
  const Denoise_inputs inputs = load_denoise_inputs(names, o);
  if(inputs.loaded.empty())
    throw Usage_error("no model could be loaded");
  if(o.figure_model.empty())
  {
    o.figure_model = inputs.loaded.front().name;
    for(const auto& l : inputs.loaded)
      if(l.name == "fandisk")
        o.figure_model = "fandisk";
  }
  create_output_folder(o.output);

  std::vector<Denoise_result> results;
  std::vector<std::string> timings;
  const std::string figure_name = run_experiment_models(inputs, o, results, timings);
  write_experiment_tables(results, timings, inputs, o);

  const std::string csv = (fs::path(o.output) / ("normal_error_" + figure_name + ".csv")).string();
  const std::string png = (fs::path(o.output) / ("normal_error_" + figure_name + ".png")).string();
  if(!run_python_script("plot_normal_error.py", {csv, png, "--title", figure_name}))
  {
    std::cerr << "sigmoid-neighborhoods denoise-experiment: the figure could not be drawn (needs python3 with "
                 "matplotlib); the tables are written in "
              << o.output << '\n';
    return EXIT_FAILED;
  }
  std::cerr << "denoise-experiment: " << (fs::path(o.output) / "table4.md").string() << ", table4.csv and " << png
            << '\n';
  return EXIT_OK;
}

} // namespace sigmoid_tool
