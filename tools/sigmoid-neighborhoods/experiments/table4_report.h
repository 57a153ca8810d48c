// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The files of the Table 4 replication: table4.csv, table4.md (the paper's layout and its figures
// next to ours) and the per-point errors of the figure model.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_REPORT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_REPORT_H

#include "../command_line.h"
#include "table4_experiment.h"
#include "table4_models.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

inline std::string number9(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.9f", v);
  return buffer;
}

inline std::string level_name(double level)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%g", level);
  return buffer;
}

inline void write_table4_csv(std::ostream& out, const std::vector<Denoise_result>& results)
{
  out << "model,points,noise,spacing,sigma,iterations,cut_off,eigenvalue_threshold,mse_noise,mse_default,"
         "mse_adaptive,adaptive_below_default,radius,mean_k_default,mean_k_adaptive,fallbacks,empty_cones_default,"
         "paper_mse_noise,paper_mse_default,paper_mse_adaptive\n";
  for(const auto& r : results)
  {
    out << r.model << ',' << r.points << ',' << level_name(r.level) << ',' << number17(r.spacing) << ','
        << number17(r.sigma) << ',' << r.iterations << ',' << number17(r.cut_off) << ','
        << number17(r.eigenvalue_threshold) << ',' << number17(r.mse_noise) << ',' << number17(r.mse_default) << ','
        << number17(r.mse_adaptive) << ',' << (r.mse_adaptive < r.mse_default ? "yes" : "no") << ','
        << number17(r.default_summary.radius) << ',' << number17(r.default_summary.mean_neighbors) << ','
        << number17(r.adaptive_summary.mean_selected_size) << ',' << r.adaptive_summary.fallbacks << ','
        << r.default_summary.empty_cones << ',';
    if(r.paper_level >= 0)
      for(int c = 0; c < PAPER_COLUMNS_PER_LEVEL; ++c)
        out << (c == 0 ? "" : ",") << number17(r.paper->paper[PAPER_COLUMNS_PER_LEVEL * r.paper_level + c]);
    else
      out << ",,";
    out << '\n';
  }
}

// The paper's layout: one row per model, the noise levels side by side; bold the smallest of three.
inline void write_table4_rows(std::ostream& out, const std::vector<Denoise_result>& results, const Denoise_options& o)
{
  std::vector<std::string> models;
  for(const auto& r : results)
    if(std::find(models.begin(), models.end(), r.model) == models.end())
      models.push_back(r.model);
  out << "| model | points |";
  for(double level : o.noise)
    out << ' ' << level_name(level) << " l: MSE(Noise) | MSE(default) | MSE(adaptive) |";
  out << "\n|---|---:|";
  for(std::size_t l = 0; l < o.noise.size(); ++l)
    out << "---:|---:|---:|";
  out << '\n';
  for(const auto& name : models)
  {
    bool first = true;
    for(const auto& r : results)
      if(r.model == name)
      {
        if(first)
          out << "| " << r.title << " | " << r.points << " |";
        first = false;
        const double best = (std::min)({r.mse_noise, r.mse_default, r.mse_adaptive});
        for(double v : {r.mse_noise, r.mse_default, r.mse_adaptive})
          out << ' ' << (v == best ? "**" + number9(v) + "**" : number9(v)) << " |";
      }
    out << '\n';
  }
  out << "\nBold: the smallest of the three.\n\n";

}

// Whether adaptive < default holds, beside the paper's numbers.
inline void write_table4_comparison(std::ostream& out, const std::vector<Denoise_result>& results)
{
  out << "## Does adaptive < default hold (the paper: on every model)?\n\n";
  out << "| model | noise | MSE(default) | MSE(adaptive) | adaptive - default | adaptive < default | "
         "paper: MSE(Noise) | paper: default | paper: adaptive |\n|---|---:|---:|---:|---:|:---:|---:|---:|---:|\n";
  std::size_t holds = 0;
  for(const auto& r : results)
  {
    holds += r.mse_adaptive < r.mse_default;
    char difference[40];
    std::snprintf(difference, sizeof(difference), "%+.9f", r.mse_adaptive - r.mse_default);
    out << "| " << r.title << " | " << level_name(r.level) << " l | " << number9(r.mse_default) << " | "
        << number9(r.mse_adaptive) << " | " << difference << " | " << (r.mse_adaptive < r.mse_default ? "yes" : "no")
        << " |";
    if(r.paper_level >= 0)
      for(int c = 0; c < PAPER_COLUMNS_PER_LEVEL; ++c)
        out << ' ' << number9(r.paper->paper[PAPER_COLUMNS_PER_LEVEL * r.paper_level + c]) << " |";
    else
      out << " – | – | – |";
    out << '\n';
  }
  out << "\nAdaptive < default holds for " << holds << " of " << results.size() << " model/noise pairs here.\n\n";

}

// The neighborhoods of every run.
inline void write_table4_neighborhoods(std::ostream& out, const std::vector<Denoise_result>& results)
{
  out << "## Neighborhoods\n\n";
  out << "| model | noise | p | cut-off | threshold | l | radius 5 m | mean k_i | mean adaptive k | "
         "fallbacks | empty cones (default) | empty cones (adaptive) |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const auto& r : results)
  {
    char line[512];
    std::snprintf(line, sizeof(line), "| %s | %s l | %u | %g | %g | %.6g | %.6g | %.2f | %.2f | %zu | %zu | %zu |\n",
                  r.title.c_str(), level_name(r.level).c_str(), r.iterations, r.cut_off, r.eigenvalue_threshold,
                  r.spacing, r.default_summary.radius, r.default_summary.mean_neighbors,
                  r.adaptive_summary.mean_selected_size, r.adaptive_summary.fallbacks,
                  r.default_summary.empty_cones, r.adaptive_summary.empty_cones);
    out << line;
  }
  out << "\nFallbacks and empty cones count point-sweeps. A fallback is a point whose every size is degenerate "
         "with the cut-off weights: it votes with its default neighborhood and equal weights.\n\n";

}

inline void write_table4_markdown(std::ostream& out, const std::vector<Denoise_result>& results,
                                  const std::vector<std::pair<std::string, std::string>>& sources,
                                  const std::vector<std::pair<std::string, std::string>>& skipped,
                                  const Denoise_options& o)
{
  out << "# Table 4: normal filtering with default and adaptive neighborhood sizes\n\n";
  out << "Noise: Gaussian offsets along the noise-free vertex normals, sd = level x l, l = mean distance of the "
         "points to their 6 nearest neighbors (noise-free), `std::mt19937_64` seed "
      << o.seed << " for every model and level, drawn in vertex order. ";
  out << "Filter input normals: "
      << (o.pca_normals ? "PCA over the 12 nearest neighbors (CGAL `pca_estimate_normals`), oriented like the "
                          "noise-free normals"
                        : "vertex normals of the noisy mesh (CGAL `compute_vertex_normals`, as the noise-free ones)")
      << ". Filter: Yadav et al. (2018) stage 1, `(p, cut-off, eigenvalue threshold)` per model (SPEC §7), damping "
         "3, balls of radius 5 m (m = mean 12-NN distance of the noisy points); adaptive: every point takes the "
         "`k` of least `E_dim` in `{k_i - 10, ..., k_i + 10}` with `a = b = arccos(cut-off)` before each sweep. "
         "MSE = mean `|n - n~|^2` against the noise-free vertex normals.\n\n";

  write_table4_rows(out, results, o);
  write_table4_comparison(out, results);
  write_table4_neighborhoods(out, results);
  out << "## Models\n\n";
  for(const auto& s : sources)
    out << "- " << s.first << ": " << s.second << '\n';
  for(const auto& s : skipped)
    out << "- " << s.first << ": skipped, " << s.second << '\n';
}

inline void write_error_csv(std::ostream& out, const Denoise_mesh& clean, const std::vector<const Denoise_result*>& levels)
{
  out << "x,y,z";
  for(const auto* r : levels)
  {
    const std::string l = level_name(r->level);
    out << ",noise_" << l << ",default_" << l << ",adaptive_" << l;
  }
  out << '\n';
  std::size_t i = 0;
  for(auto v : clean.vertices())
  {
    const auto& p = clean.point(v);
    out << number17(p.x()) << ',' << number17(p.y()) << ',' << number17(p.z());
    for(const auto* r : levels)
      out << ',' << number17(r->error_noise[i]) << ',' << number17(r->error_default[i]) << ','
          << number17(r->error_adaptive[i]);
    out << '\n';
    ++i;
  }
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_REPORT_H
