// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods report`: the paper's Tables 2 and 3 as Markdown, Figures 3-6 as PNG.

#include "commands.h"

#include "command_line.h"
#include "evaluate_command.h"
#include "evaluation_files.h"
#include "evaluation_json.h"
#include "json.h"
#include "model_input.h"
#include "optimal_command.h"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const REPORT_USAGE =
  "usage: sigmoid-neighborhoods report OUTDIR... [-o DIR] [--figure-model MODEL]\n"
  "  one column group per evaluation folder (repository); Figure 3 shows MODEL, or the first model\n"
  "  evaluated with --per-point\n";

std::string format(const char* pattern, double v)
{
  if(!std::isfinite(v))
    return "–";
  char text[64];
  std::snprintf(text, sizeof(text), pattern, v);
  return text;
}

std::string percent(std::size_t part, std::size_t whole)
{
  return whole == 0 ? "–" : format("%.2f %%", 100. * double(part) / double(whole));
}

// `text` in a Markdown table cell: one line, no column break.
std::string markdown_cell(const std::string& text)
{
  std::string cell;
  for(char c : text)
  {
    if(c == '|')
      cell += "\\|";
    else if(c == '\n' || c == '\r')
      cell += ' ';
    else
      cell += c;
  }
  return cell;
}

struct Repository_summary
{
  std::string folder, name;
  Json_value tree;              // summary.json, checked by read_summary()
  Evaluation_contents contents; // its model files and failures.json: the failures' messages
  bool evaluated() const { return tree.contains("statistics"); }
  // the value at `path` ("statistics/optimal/mean"), NaN for null
  double number(const std::string& path) const
  {
    const Json_value& v = tree.at(Json_value::json_pointer("/" + path));
    return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
  }
  std::size_t count(const std::string& path) const { return tree.at(Json_value::json_pointer("/" + path)).get<std::size_t>(); }
};

// One row of a Markdown table.
void markdown_row(std::ostream& out, const std::string& head, const std::vector<std::string>& cells)
{
  out << "| " << head;
  for(const auto& c : cells)
    out << " | " << c;
  out << " |\n";
}

// The rule under a header of a text column and `n` number columns.
void markdown_rule(std::ostream& out, std::size_t n)
{
  out << "|---";
  for(std::size_t i = 0; i < n; ++i)
    out << "|---:";
  out << "|\n";
}

// How an evaluation estimated its normals, as its settings record it.
std::string normal_estimation_text(const Repository_summary& r)
{
  std::string how = "–";
  if(r.evaluated())
  {
    const Json_value& s = r.tree["settings"];
    const std::string orientation = s["orientation"].get<std::string>();
    how = "PCA on " + std::to_string(s["normal_neighbors"].get<unsigned int>()) + " neighbors, " +
          (orientation == "mst"         ? "a minimum spanning forest"
           : orientation == "viewpoint" ? "towards the viewpoint"
           : orientation == "up"        ? "upwards"
           : orientation == "none"      ? "not oriented"
                                        : "as recorded") +
          "; zero normals by their neighbors' normals";
    if(s["normals"] == "jet")
      how.replace(0, 3, "jet fitting");
    else if(s["normals"] == "file")
      how = "none: `--normals file`";
  }
  return how;
}

// The introduction and the tables of the models and of their normals.
void write_report_inputs(std::ostream& out, const std::vector<Repository_summary>& repos)
{
  out << "# Evaluation of sigmoid neighborhoods\n\n";
  out << "Per point, the classification error `E_dim` of its neighborhood (Shannon entropy of linearity, "
         "planarity and scattering; 0 is a clear 1D, 2D or 3D shape, ln 3 the least clear) for equal "
         "weights (`a = b = π`), the sharp cut-off `a = b = arccos(0.9)` and the optimal `(a*, b*, k*)`, "
         "each with its best `k`; a failure is a point whose covariance is degenerate at every `k`.\n\n";
  out << "| repository | models | too small for the grid | failed models | points | merged duplicates | "
         "dropped vertices |\n"
         "|---|---:|---:|---:|---:|---:|---:|\n";
  for(const auto& r : repos)
    out << "| " << r.name << " | " << r.count("models") << " | " << r.count("too_small_models") << " | "
        << r.count("failed_models") << " | " << r.count("points") << " | " << r.count("merged_duplicates") << " | "
        << r.count("dropped_vertices") << " |\n";
  out << "\n`models`: the models evaluated. Too small for the grid: fewer distinct points than the `k_max + 1` "
         "the search needs (listed below, not failures). Failed: a model that could not be read or evaluated, "
         "listed below with its message.\n";
  out << "\n| repository | models with estimated normals | points with estimated normals | models with zero normals "
         "in the file | zero normals | estimation, orientation |\n|---|---:|---:|---:|---:|---|\n";
  for(const auto& r : repos)
    out << "| " << r.name << " | " << r.count("models_with_estimated_normals") << " | "
        << r.count("points_with_estimated_normals") << " | " << r.count("models_with_zero_normals") << " | "
        << r.count("zero_normals") << " | " << normal_estimation_text(r) << " |\n";
  out << "\nNormals are the mesh's vertex normals or the file's; a point set without normals, or whose normal "
         "columns are all zero, gets estimated ones; a few zero normals among the file's are estimated and "
         "turned to agree with their neighbors' normals.\n";
}

// Table 2: the statistics of E_dim for every weighting, and the failures.
void write_table2(std::ostream& out, const std::vector<Repository_summary>& repos)
{
  out << "\n## Table 2: `E_dim` over all points\n\n";
  out << "| ";
  std::vector<std::string> columns;
  for(const auto& r : repos)
  {
    const std::string fixed = r.evaluated() ? std::to_string(r.count("settings/fixed_k")) : "?";
    for(const char* w : {"equal", "cut-off", "optimal"})
      columns.push_back(r.name + ": " + w);
    columns.push_back(r.name + ": equal, k = " + fixed);
  }
  for(const auto& c : columns)
    out << " | " << c;
  out << " |\n";
  markdown_rule(out, columns.size());
  const std::vector<std::pair<std::string, std::string>> stats = {
    {"min", "min"}, {"mean", "mean"}, {"max", "max"}, {"sd", "standard_deviation"}};
  for(const auto& st : stats)
  {
    std::vector<std::string> cells;
    for(const auto& r : repos)
      for(const char* w : {"equal", "cut_off", "optimal", "fixed_k"})
        cells.push_back(r.evaluated() ? format("%.4f", r.number(std::string("statistics/") + w + "/" + st.second)) : "–");
    markdown_row(out, st.first, cells);
  }
  std::vector<std::string> cells;
  for(const auto& r : repos)
    for(const char* w : {"equal", "cut_off", "optimal", "fixed_k"})
    {
      if(!r.evaluated())
      {
        cells.push_back("–");
        continue;
      }
      const std::size_t f = r.count(std::string("statistics/") + w + "/failures");
      cells.push_back(std::to_string(f) + " (" + percent(f, r.count("statistics/points")) + ")");
    }
  markdown_row(out, "failures", cells);
}

// Table 3: where the optimal (a*, b*) lie on the grids, and the mean k*; then the paper's figures.
void write_table3(std::ostream& out, const std::vector<Repository_summary>& repos)
{
  out << "\n## Table 3: where the optimal `(a*, b*)` lie\n\n"
         "Group a: `a = 0` when `a* = 0`; else `a-` when lowering `a*` one grid step (same `b*`, `k*`) does not "
         "fail, `¬a-` when it does. Group b: `b = a` when `b* = a*`; else `b-` / `¬b-` for lowering `b*` one "
         "step (staying `≥ a*`). Percent of the points with an optimum.\n\n";
  out << "|";
  for(const auto& r : repos)
    out << " | " << r.name;
  out << " |\n";
  markdown_rule(out, repos.size());
  const std::vector<std::pair<std::string, std::string>> t3 = {
    {"a = 0", "a_zero"}, {"a-", "a_lower_valid"}, {"¬a-", "a_lower_fails"},
    {"b = a", "b_equals_a"}, {"b-", "b_lower_valid"}, {"¬b-", "b_lower_fails"}};
  for(const auto& t : t3)
  {
    std::vector<std::string> cells;
    for(const auto& r : repos)
      cells.push_back(r.evaluated() ? percent(r.count("statistics/table3/" + t.second), r.count("statistics/optimal/count"))
                                    : "–");
    markdown_row(out, t.first, cells);
  }
  std::vector<std::string> mean, sd;
  for(const auto& r : repos)
  {
    mean.push_back(r.evaluated() ? format("%.2f", r.number("statistics/k_mean")) : "–");
    sd.push_back(r.evaluated() ? format("%.2f", r.number("statistics/k_standard_deviation")) : "–");
  }
  markdown_row(out, "mean k*", mean);
  markdown_row(out, "sd k*", sd);

  out << "\n## The paper's figures, for comparison (other data)\n\n"
         "| repository | points | E eq. mean | E opt. mean | E opt. sd | a = 0 | b = a | ¬b- | mean k* (sd) |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
         "| clean (TetWild/Thingi10K) | 7,213,429 | 0.631 | 0.248 | 0.188 | 60.19 % | 36.80 % | 37.72 % | 10.55 (4.77) |\n"
         "| scanned (Choi et al.) | 25,929,256 | 0.335 | 0.253 | 0.157 | 54.30 % | 43.50 % | 42.29 % | 12.09 (4.62) |\n"
         "| scanned (FAUST) | 17,918,016 | 0.250 | 0.211 | 0.096 | 62.44 % | 36.86 % | 42.11 % | 14.23 (4.49) |\n"
         "| scanned (Pan et Oursons) | 1,199,992 | 0.383 | 0.320 | 0.134 | 60.70 % | 37.33 % | 42.21 % | 13.54 (4.40) |\n";
}

// The models too small for the grid and the failed ones, when there are any.
void write_model_lists(std::ostream& out, const std::vector<Repository_summary>& repos)
{
  bool any_small = false, any_failed = false;
  for(const auto& r : repos)
  {
    any_small = any_small || !r.contents.small.empty();
    any_failed = any_failed || !r.contents.failures.empty();
  }
  if(any_small)
  {
    out << "\n## Models too small for the grid\n\n| repository | model | distinct points | needed (`k_max + 1`) |\n"
           "|---|---|---:|---:|\n";
    for(const auto& r : repos)
      for(const auto& m : r.contents.small)
        out << "| " << r.name << " | " << markdown_cell(m.model) << " | " << m.points << " | " << m.needed << " |\n";
  }
  if(any_failed)
  {
    out << "\n## Failed models\n\n| repository | model | message |\n|---|---|---|\n";
    for(const auto& r : repos)
      for(const auto& f : r.contents.failures)
        out << "| " << r.name << " | " << markdown_cell(f.model) << " | " << markdown_cell(f.message) << " |\n";
  }
}

void write_report_markdown(std::ostream& out, const std::vector<Repository_summary>& repos,
                           const std::string& figure3_note, bool figure3)
{
  write_report_inputs(out, repos);
  write_table2(out, repos);
  write_table3(out, repos);
  write_model_lists(out, repos);
  out << "\n## Figures\n\n";
  if(figure3)
    out << "![Figure 3](figure3_per_point.png)\n\n" << figure3_note << "\n\n";
  else
    out << figure3_note << "\n\n";
  out << "![Figure 4](figure4_ab_histogram.png)\n\n"
         "Figure 4: how often each `(a*, b*)` is optimal, each bar split by `k*`.\n\n"
         "![Figure 5](figure5_k_histogram.png)\n\n"
         "Figure 5: `k*` in percent of the points of each repository.\n\n"
         "![Figure 6](figure6_k_deviation.png)\n\n"
         "Figure 6: per model, the standard deviation of `k*` over its points; boxes at the quartiles, "
         "whiskers at the extremes.\n";
}

std::vector<Repository_summary> read_repositories(const Arguments& args)
{
  std::vector<Repository_summary> repos;
  for(const auto& folder : args.positional())
  {
    const fs::path summary = fs::path(folder) / "summary.json";
    if(!fs::exists(summary))
      throw Usage_error(folder + " has no summary.json: run evaluate first");
    Repository_summary r;
    r.folder = folder;
    r.tree = read_summary(folder, r.contents); // with its model files: the plot script reads only checked files
    r.contents.models.clear();
    r.name = r.tree["repository"].get<std::string>();
    repos.push_back(r);
  }
  return repos;
}

// Figure 3's per-point values and what its caption names.
struct Figure3
{
  std::string csv, name;
};

// The per-point values of --figure-model, evaluated as the first folder's evaluation searched.
Figure3 evaluate_figure_model(const Arguments& args, const Repository_summary& first, const std::string& outdir)
{
  const std::string model_path = args.get("--figure-model");
  Search_options options = read_search_options(args);
  Evaluation_settings settings;
  settings.a_grid = settings.b_grid = SN::defaults::angle_grid();
  if(first.evaluated()) // its grids too: the figure is of the evaluation's search
    settings = read_settings(Json_object(first.tree, (fs::path(first.folder) / "summary.json").string()));
  settings.cut_off_angle = std::acos(EVALUATION_CUT_OFF_COSINE);
  options.k_min = settings.k_min;
  options.k_max = settings.k_max;
  options.barycenter = settings.barycenter == "unweighted" ? SN::Barycenter::UNWEIGHTED : SN::Barycenter::WEIGHTED;
  options.angle_tolerance = settings.angle_tolerance;
  options.line_angles = settings.line_angles;
  options.a_grid = settings.a_grid;
  options.b_grid = settings.b_grid;
  const SN::Normal_options normals = normal_options(settings, options.threads);
  const SN::Oriented_point_set model =
    read_input(model_path, [&] { return read_model(model_path, options.k_max, normals); });
  const auto evaluations = evaluate_model(model, options, settings);
  Figure3 figure;
  figure.csv = (fs::path(outdir) / "figure3_points.csv").string();
  write_file_atomically(figure.csv, [&](std::ofstream& out) { write_evaluation_csv(out, model, evaluations, options.threads); });
  figure.name = fs::path(model_path).filename().string();
  return figure;
}

// The first per-point CSV of the evaluations (evaluate --per-point), if any.
Figure3 find_per_point_csv(const std::vector<Repository_summary>& repos)
{
  for(const auto& r : repos)
  {
    const fs::path models = fs::path(r.folder) / "models";
    for(const auto& m : model_files(r.folder))
    {
      const fs::path csv = models / (m.first + ".csv");
      if(fs::exists(csv))
        return {csv.string(), r.name + "/" + m.first};
    }
  }
  return {};
}

int run_report(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT, {"-o", "--output", "--figure-model", "--threads"},
                       {"-h", "--help"});
  if(print_help(args, REPORT_USAGE))
    return EXIT_OK;
  if(args.positional().empty())
    throw Usage_error("report needs at least one evaluation folder");
  const std::string outdir = args.get("-o", args.get("--output", args.positional().front()));
  const std::vector<Repository_summary> repos = read_repositories(args);
  create_output_folder(outdir);

  // Figure 3's per-point values: computed for --figure-model, else a --per-point CSV of the evaluation.
  const Figure3 figure3 =
    args.has("--figure-model") ? evaluate_figure_model(args, repos.front(), outdir) : find_per_point_csv(repos);
  const std::string figure3_note =
    figure3.csv.empty()
      ? "Figure 3 needs per-point values: pass `--figure-model MODEL` or evaluate with `--per-point`."
      : "Figure 3: " + figure3.name + ": per point `E_dim` (top) and label (bottom) for equal weights, "
        "the cut-off `a = b = arccos(0.9)` and the optimal triple; failures in red.";

  const std::string report = (fs::path(outdir) / "report.md").string();
  write_file_atomically(report, [&](std::ofstream& out) {
    write_report_markdown(out, repos, figure3_note, !figure3.csv.empty());
  });

  std::vector<std::string> plot_arguments = {"--output", outdir};
  if(!figure3.csv.empty())
    plot_arguments.insert(plot_arguments.end(), {"--figure3", figure3.csv, "--figure3-name", figure3.name});
  for(const auto& r : repos)
    plot_arguments.push_back(r.folder);
  if(!run_python_script("plot_evaluation.py", plot_arguments))
  {
    std::cerr << "sigmoid-neighborhoods report: the figures could not be drawn (needs python3 with matplotlib); "
              << report << " is written\n";
    return EXIT_FAILED;
  }
  std::cerr << "report: " << report << " and figures in " << outdir << '\n';
  return EXIT_OK;
}

} // namespace

int run_report_command(int argc, char** argv) { return run_report(argc, argv); }

} // namespace sigmoid_tool
