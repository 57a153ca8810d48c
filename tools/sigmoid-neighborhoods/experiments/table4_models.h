// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The models of the paper's Table 4 (Section 5.5, SPEC §7): the filter's settings per model and the
// MSEs the paper publishes, next to which the replication prints its own.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_MODELS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_MODELS_H

#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;

// A model of Table 4 with the paper's (p, cut-off, eigenvalue threshold) and its published MSEs.
struct Denoise_model
{
  std::string name;    // command-line name, file stem
  std::string title;   // as in the paper
  unsigned int iterations;
  double cut_off, eigenvalue_threshold;
  std::size_t paper_vertices;
  // MSE(Noise), MSE(Yadav et al.), MSE(ours) at 0.3 l, then at 0.6 l
  double paper[6];
};

// The noise levels of the paper's Table 4, in units of l; the index of `Denoise_model::paper` / 3.
constexpr double PAPER_NOISE_LEVELS[2] = {0.3, 0.6};
// The columns of one level in `Denoise_model::paper`: MSE(Noise), MSE(Yadav et al.), MSE(ours).
constexpr int PAPER_COLUMNS_PER_LEVEL = 3;

// SPEC §7: the larger number of each pair is the cut-off, the smaller the eigenvalue threshold.
inline const std::vector<Denoise_model>& table4_models()
{
  static const std::vector<Denoise_model> models = {
    {"cube", "Cube", 150, 0.95, 0.3, 1906,
     {0.018171157, 0.004720763, 0.003817538, 0.067785183, 0.041014649, 0.017185731}},
    {"bearing", "Bearing", 100, 0.9, 0.25, 3475,
     {0.019149792, 0.092202990, 0.06311642, 0.087963467, 0.105885719, 0.099716185}},
    {"fandisk", "Fandisk", 150, 0.9, 0.3, 6475,
     {0.015985698, 0.047105692, 0.033043562, 0.059076477, 0.067027229, 0.052858261}},
    {"sharp_sphere", "Sharp Sphere", 100, 0.9, 0.25, 8354,
     {0.033954089, 0.152198571, 0.124993406, 0.091947551, 0.162334741, 0.143099697}},
    {"fertility", "Fertility", 100, 0.9, 0.25, 9239,
     {0.134043694, 0.220368116, 0.197418828, 0.232151395, 0.25364564, 0.25100736}},
    {"octahedron", "Octahedron", 80, 0.9, 0.25, 16395,
     {0.287851891, 0.282346769, 0.275334065, 0.304714745, 0.277547626, 0.271626537}},
    {"rockerarm", "Rockerarm", 80, 0.9, 0.25, 24106,
     {0.017150895, 0.081370198, 0.067150116, 0.063687905, 0.084070141, 0.078171864}}};
  return models;
}

// The model of Table 4 called `name`, or nullptr.
inline const Denoise_model* find_table4_model(const std::string& name)
{
  for(const auto& m : table4_models())
    if(m.name == name)
      return &m;
  return nullptr;
}

// The settings of a model of Table 4, or for a mesh file the filter's defaults and no paper figures.
inline Denoise_model denoise_settings(const std::string& name)
{
  if(const Denoise_model* m = find_table4_model(name))
    return *m;
  const std::filesystem::path file(name);
  return {file.stem().string(),          file.filename().string(),      SN::defaults::FILTER_ITERATIONS,
          SN::defaults::NORMAL_CUT_OFF,    SN::defaults::EIGENVALUE_THRESHOLD, 0,
          {0, 0, 0, 0, 0, 0}};
}

// The level of the paper's table that `level` is (0 for 0.3 l, 1 for 0.6 l), or -1.
inline int paper_level_index(double level)
{
  for(int i = 0; i < 2; ++i)
    if(level == PAPER_NOISE_LEVELS[i])
      return i;
  return -1;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_MODELS_H
