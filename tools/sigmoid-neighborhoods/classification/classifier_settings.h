// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A trained classifier as one file: a first line naming the format, one line of JSON with what the
// features and the labels were (so that a model is never applied to other features or labels), then
// CGAL's ETHZ random forest as its save_configuration() writes it (gzip-compressed Boost archive).
// This header: the settings and the file's checks (classifier_settings.cpp), without CGAL's classifier
// (classifier_model.h).

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_SETTINGS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_SETTINGS_H

#include "feature_options.h"
#include "label_mapping.h"
#include "../json.h"
#include "../model_input.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace sigmoid_tool {

const char* const CLASSIFIER_MODEL_MAGIC = "sigmoid-neighborhoods classifier 1";
// A model's JSON line is a few kilobytes; more is not a model of the tool.
constexpr std::size_t LARGEST_MODEL_HEADER = 1 << 20;

// How classify train chose the first scale of the groups with scales in metres (scale_choice.h):
// each candidate's mean IoU in cross-validation at the training density and trained 4x thinner.
struct Scale_choice_report
{
  std::vector<double> ladder, same_density, thinned; // metres, and the mean IoU of each
  double chosen = 0.;
  std::size_t cap = 0;        // training points per class and fold during the choice
  std::size_t training_points = 0, test_points = 0; // of a fold's forests, summed over the folds
  double seconds = 0.;
};

struct Classifier_settings
{
  Label_mapping labels;
  Feature_options features;
  SN::Normal_options normals;
  std::vector<std::string> feature_names; // in the order the forest reads them
  unsigned int trees = 25, depth = 20;
  unsigned int feature_order_seed = 0;
  unsigned int max_per_class = 0; // training points per class at most (0: all), evenly spaced
  std::optional<Scale_choice_report> scale_choice; // when classify train chose the scales
};

inline nlohmann::json scale_choice_json(const Scale_choice_report& c)
{
  return {{"ladder", c.ladder},
          {"same_density", c.same_density},
          {"thinned", c.thinned},
          {"chosen", c.chosen},
          {"cap_per_class", c.cap},
          {"training_points", c.training_points},
          {"test_points", c.test_points},
          {"seconds", c.seconds}};
}

inline nlohmann::json settings_json(const Classifier_settings& s)
{
  nlohmann::json j;
  j["labels"] = s.labels.text();
  j["features"] = {{"groups", s.features.groups},         {"fixed_k", s.features.fixed_k},
                   {"k_min", s.features.k_min},           {"k_max", s.features.k_max},
                   {"scales", s.features.scales},         {"sigmoid", {s.features.sigmoid_a, s.features.sigmoid_b}},
                   {"cell_sizes", s.features.cell_sizes}, {"cgal_scales", s.features.cgal_scales}};
  j["features"]["cgal_voxel"] = s.features.cgal_voxel;
  j["features"]["cgal_grid_anchor"] = s.features.cgal_grids_at_origin ? "origin" : "bounding box";
  // the pyramid's scales in metres, so that the model applies them at any density; cell_sizes is
  // what cell and levels give, for the reader
  j["features"]["pyramid"] = {{"cell", s.features.pyramid_cell},
                              {"levels", s.features.pyramid_levels},
                              {"k", s.features.pyramid_k},
                              {"cell_sizes", s.features.pyramid_cell_sizes()},
                              {"sigmoid_cells", s.features.pyramid_sigmoid_cells}};
  j["normals"] = {{"source", s.normals.source == SN::Normal_source::JET ? "jet" : "pca"},
                  {"neighbors", s.normals.neighbors},
                  {"orientation", SN::normal_orientation_name(s.normals.orientation)},
                  {"viewpoint", {s.normals.viewpoint.x(), s.normals.viewpoint.y(), s.normals.viewpoint.z()}}};
  j["feature_names"] = s.feature_names;
  j["trees"] = s.trees;
  j["depth"] = s.depth;
  j["feature_order_seed"] = s.feature_order_seed;
  j["max_per_class"] = s.max_per_class;
  if(s.scale_choice) // for the reader; the scales themselves are the features' settings above
    j["scale_choice"] = scale_choice_json(*s.scale_choice);
  return j;
}

// Throws Usage_error naming `path` and what is wrong: the file is the tool's input too. The feature
// settings follow the command line's rules (Feature_options::check()).
Classifier_settings settings_from_json(const nlohmann::json& j, const std::string& path);

// The settings of a model file and its forest's bytes, checked; a damaged file is a Usage_error.
Classifier_settings read_classifier_settings(const std::string& path, std::string& forest_bytes);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_SETTINGS_H
