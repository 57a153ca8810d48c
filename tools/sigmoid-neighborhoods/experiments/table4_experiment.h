// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The replication of the paper's Table 4 (Section 5.5, SPEC §7): noise along the normals of clean
// meshes, then the normal filter of Yadav et al. (2018) with its default neighborhoods and with
// adaptive sizes; the MSE of the normals against the noise-free ones.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_EXPERIMENT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_EXPERIMENT_H

#include "../command_line.h"
#include "../filter_command.h"
#include "table4_data.h"
#include "table4_models.h"

#include "normal_noise.h"
#include <CGAL/Sigmoid_neighborhoods/compute_mean_neighbor_distance.h>
#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Real_timer.h>
#include <CGAL/pca_estimate_normals.h>

#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

constexpr unsigned int SPACING_NEIGHBORS = 6; // l of SPEC §7
constexpr unsigned int PCA_NEIGHBORS = 12;    // the authors' initial normals

struct Denoise_options
{
  std::vector<double> noise{PAPER_NOISE_LEVELS[0], PAPER_NOISE_LEVELS[1]};
  std::uint64_t seed = 1;
  std::string data_dir, fandisk, figure_model, output;
  bool pca_normals = false;
  unsigned int threads = 0; // 0: OpenMP's default
};

// One (model, noise level) of the table.
struct Denoise_result
{
  std::string model, title;
  std::size_t points = 0;
  double level = 0., spacing = 0., sigma = 0.;
  unsigned int iterations = 0;
  double cut_off = 0., eigenvalue_threshold = 0.;
  double mse_noise = 0., mse_default = 0., mse_adaptive = 0.;
  SN::Normal_filter_summary default_summary, adaptive_summary;
  const Denoise_model* paper = nullptr; // for the paper's figures, when this level is 0.3 or 0.6
  int paper_level = -1;                 // 0 for 0.3 l, 1 for 0.6 l
  double seconds_default = 0., seconds_adaptive = 0.;
  std::vector<double> error_noise, error_default, error_adaptive; // per point
};

// A model of the run, with its mesh.
struct Denoise_input
{
  std::string name;
  Denoise_model settings;
  Denoise_mesh mesh;
};

// The models of a run, loaded before anything runs (a bad file stops the run before anything is
// written), with where each comes from and why some are skipped.
struct Denoise_inputs
{
  std::vector<Denoise_input> loaded;
  std::vector<std::pair<std::string, std::string>> sources, skipped; // (title, text)
};

inline Denoise_inputs load_denoise_inputs(const std::vector<std::string>& names, const Denoise_options& o)
{
  Denoise_inputs inputs;
  for(const auto& name : names)
  {
    Denoise_input l;
    l.name = name;
    l.settings = denoise_settings(name);
    std::string source, absent;
    const bool loaded =
      read_input(name, [&] { return load_denoise_mesh(name, o.data_dir, o.fandisk, l.mesh, source, absent); });
    if(!loaded)
    {
      inputs.skipped.emplace_back(l.settings.title, absent);
      std::cerr << "denoise-experiment: " << l.settings.title << " skipped: " << absent << '\n';
      continue;
    }
    const std::string paper_vertices =
      l.settings.paper_vertices ? std::to_string(l.settings.paper_vertices) : std::string("–");
    inputs.sources.emplace_back(l.settings.title, source + " (" + std::to_string(l.mesh.number_of_vertices()) +
                                                    " vertices; the paper's: " + paper_vertices + ")");
    inputs.loaded.push_back(std::move(l));
  }
  return inputs;
}

// One noise level of one model: noise, noisy normals, both filters, MSEs.
inline Denoise_result run_denoise_level(const Denoise_mesh& clean, const std::vector<Denoise_vector>& truth,
                                        double spacing, double level, const Denoise_model& settings,
                                        const Denoise_options& o)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Denoise_result r;
  r.points = clean.number_of_vertices();
  r.level = level;
  r.spacing = spacing;
  r.sigma = level * spacing;
  r.iterations = settings.iterations;
  r.cut_off = settings.cut_off;
  r.eigenvalue_threshold = settings.eigenvalue_threshold;

  // Noise along the noise-free normals, in vertex order.
  Denoise_mesh noisy = clean;
  auto truth_map = noisy.add_property_map<Denoise_mesh::Vertex_index, Denoise_vector>("v:truth").first;
  std::size_t i = 0;
  for(auto v : noisy.vertices())
    truth_map[v] = truth[i++];
  auto vertices = noisy.vertices();
  SN::add_normal_noise(vertices, r.sigma, o.seed, CGAL::parameters::point_map(noisy.points()).normal_map(truth_map));

  std::vector<Denoise_point> points;
  for(auto v : noisy.vertices())
    points.push_back(noisy.point(v));
  std::vector<Denoise_vector> normals;
  if(!o.pca_normals)
  {
    auto noisy_normals = noisy.add_property_map<Denoise_mesh::Vertex_index, Denoise_vector>("v:noisy").first;
    PMP::compute_vertex_normals(noisy, noisy_normals);
    for(auto v : noisy.vertices())
      normals.push_back(noisy_normals[v]);
  }
  else
  {
    typedef std::pair<Denoise_point, Denoise_vector> Item;
    std::vector<Item> items;
    for(const auto& p : points)
      items.emplace_back(p, CGAL::NULL_VECTOR);
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      items, PCA_NEIGHBORS,
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Item>())
        .normal_map(CGAL::Second_of_pair_property_map<Item>()));
    for(std::size_t j = 0; j < items.size(); ++j)
      normals.push_back(items[j].second * truth[j] < 0 ? -items[j].second : items[j].second);
  }
  for(std::size_t j = 0; j < normals.size(); ++j)
    if(!(normals[j].squared_length() > 0.))
      throw std::invalid_argument("noisy vertex " + std::to_string(j) + " has no defined normal");

  auto errors = [&truth](const std::vector<Denoise_vector>& n) {
    std::vector<double> e(n.size());
    for(std::size_t j = 0; j < n.size(); ++j)
      e[j] = SN::normal_squared_error(truth[j], n[j]);
    return e;
  };
  r.mse_noise = SN::normal_mse(truth, normals);
  r.error_noise = errors(normals);

  Filter_options f;
  f.iterations = settings.iterations;
  f.cut_off = settings.cut_off;
  f.eigenvalue_threshold = settings.eigenvalue_threshold;
  f.threads = o.threads;
  for(bool adaptive : {false, true})
  {
    f.adaptive = adaptive;
    std::vector<Denoise_vector> filtered = normals;
    CGAL::Real_timer timer;
    timer.start();
    const SN::Normal_filter_summary summary = filter_point_normals(points, filtered, f);
    timer.stop();
    (adaptive ? r.adaptive_summary : r.default_summary) = summary;
    (adaptive ? r.seconds_adaptive : r.seconds_default) = timer.time();
    (adaptive ? r.mse_adaptive : r.mse_default) = SN::normal_mse(truth, filtered);
    (adaptive ? r.error_adaptive : r.error_default) = errors(filtered);
  }
  return r;
}

// Every noise level of one model, in the order of `o.noise`. A model the experiment cannot run on
// (too few points, an undefined normal) throws a Usage_error naming it.
inline std::vector<Denoise_result> run_denoise_model(const Denoise_input& l, const Denoise_options& o)
{
  auto truth_map = get(CGAL::dynamic_vertex_property_t<Denoise_vector>(), l.mesh);
  CGAL::Polygon_mesh_processing::compute_vertex_normals(l.mesh, truth_map);
  std::vector<Denoise_vector> truth;
  for(auto v : l.mesh.vertices())
  {
    truth.push_back(get(truth_map, v));
    if(!(truth.back().squared_length() > 0.))
      throw Usage_error(l.name + ": vertex " + std::to_string(std::size_t(v)) + " has no defined normal");
  }
  auto vertices = l.mesh.vertices();
  std::vector<Denoise_result> results;
  try
  {
    const double spacing = SN::compute_mean_neighbor_distance<SN::Parallel_if_available_tag>(
      vertices, SPACING_NEIGHBORS, SN::parameters::number_of_threads(o.threads).point_map(l.mesh.points()));
    for(double level : o.noise)
    {
      Denoise_result r = run_denoise_level(l.mesh, truth, spacing, level, l.settings, o);
      r.model = l.settings.name;
      r.title = l.settings.title;
      r.paper = find_table4_model(l.name);
      if(r.paper != nullptr)
        r.paper_level = paper_level_index(level);
      results.push_back(std::move(r));
    }
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(l.name + ": " + e.what());
  }
  return results;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_EXPERIMENT_H
