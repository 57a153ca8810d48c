// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A trained classifier as one file: a first line naming the format, one line of JSON with what the
// features and the labels were (so that a model is never applied to other features or labels), then
// CGAL's ETHZ random forest as its save_configuration() writes it (gzip-compressed Boost archive).
// This header: the settings and the file's checks, without CGAL's classifier (classifier_model.h).

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
inline Classifier_settings settings_from_json(const nlohmann::json& j, const std::string& path)
{
  const std::string file = path + ": not a usable classifier model";
  constexpr std::uint64_t LARGEST_UNSIGNED = std::numeric_limits<unsigned int>::max();
  auto unsigned_value = [](const Json_object& o, const char* key) { return unsigned(o.integer(key, 0, LARGEST_UNSIGNED)); };
  auto unsigned_values = [&](const Json_object& o, const char* key) {
    std::vector<unsigned int> values;
    const Json_value& a = o.array(key, 1024);
    for(const std::uint64_t v : o.integers(key, a.size(), LARGEST_UNSIGNED))
      values.push_back(unsigned(v));
    return values;
  };
  const double not_a_number = std::numeric_limits<double>::quiet_NaN(); // null: refused by check()
  try
  {
    const Json_object model(j, file);
    Classifier_settings s;
    s.labels = parse_label_mapping(model.string("labels", 1 << 16));
    const Json_object f = model.object("features");
    for(const Json_value& g : f.array("groups", 64))
    {
      if(!g.is_string())
        f.fail("features.groups", "holds " + Json_object::type_name(g) + ", expected group names");
      s.features.groups.push_back(g.get<std::string>());
    }
    s.features.fixed_k = unsigned_value(f, "fixed_k");
    s.features.k_min = unsigned_value(f, "k_min");
    s.features.k_max = unsigned_value(f, "k_max");
    s.features.scales = unsigned_values(f, "scales");
    const std::vector<double> sigmoid = f.numbers("sigmoid", 2);
    if(sigmoid.size() != 2)
      f.fail("features.sigmoid", "is not two angles");
    s.features.sigmoid_a = sigmoid[0];
    s.features.sigmoid_b = sigmoid[1];
    s.features.cell_sizes = f.numbers("cell_sizes", 1024);
    s.features.cgal_scales = unsigned_value(f, "cgal_scales");
    if(f.has("cgal_voxel")) // models written before it have none (nor the group cgal-metric)
      s.features.cgal_voxel = f.number("cgal_voxel", not_a_number);
    // models written before the anchor have CGAL's grids, anchored at the bounding box
    s.features.cgal_grids_at_origin =
      f.has("cgal_grid_anchor") && f.choice("cgal_grid_anchor", {"origin", "bounding box"}) == "origin";
    std::vector<double> written_cells; // the pyramid's cell sizes as written, for the reader
    if(f.has("pyramid")) // models written before the pyramid have none: the defaults, unused
    {
      const Json_object p = f.object("pyramid");
      s.features.pyramid_cell = p.number("cell", not_a_number);
      s.features.pyramid_levels = unsigned_value(p, "levels");
      s.features.pyramid_k = unsigned_value(p, "k");
      if(p.has("sigmoid_cells")) // empty, or absent in older models: every level
        s.features.pyramid_sigmoid_cells = p.numbers("sigmoid_cells", 64);
      if(p.has("cell_sizes"))
        written_cells = p.numbers("cell_sizes", 64);
    }
    s.features.check(Feature_options::MODEL_FILE);
    if(!written_cells.empty() && written_cells != s.features.pyramid_cell_sizes())
      f.fail("features.pyramid.cell_sizes", "are not its cell times 1, 2, 4 ...");
    const Json_object n = model.object("normals");
    s.normals.source = n.choice("source", {"jet", "pca"}) == "jet" ? SN::Normal_source::JET : SN::Normal_source::PCA;
    s.normals.neighbors = unsigned_value(n, "neighbors");
    s.normals.neighbor_search = CLASSIFICATION_NEIGHBOR_SEARCH;
    if(s.normals.neighbors < 5 || s.normals.neighbors > 10000)
      n.fail("normals.neighbors", "is " + std::to_string(s.normals.neighbors) + ", expected 5 to 10000");
    const std::string orientation = n.string("orientation", 64);
    try
    {
      s.normals.orientation = SN::normal_orientation_from_name(orientation);
    }
    catch(const std::invalid_argument&)
    {
      n.fail("normals.orientation", "is '" + orientation + "', not an orientation");
    }
    const std::vector<double> v = n.numbers("viewpoint", 3);
    if(v.size() != 3)
      n.fail("normals.viewpoint", "is not three numbers");
    s.normals.viewpoint = SN::Oriented_point_set::Point_3(v[0], v[1], v[2]);
    const Json_value& names = model.array("feature_names", 1 << 16);
    for(const Json_value& name : names)
    {
      if(!name.is_string())
        model.fail("feature_names", "holds " + Json_object::type_name(name) + ", expected names");
      s.feature_names.push_back(name.get<std::string>());
    }
    if(s.feature_names.empty())
      model.fail("feature_names", "is empty: no features");
    s.trees = unsigned_value(model, "trees");
    s.depth = unsigned_value(model, "depth");
    s.feature_order_seed = unsigned_value(model, "feature_order_seed");
    s.max_per_class = unsigned(model.integer_or("max_per_class", 0, 0, LARGEST_UNSIGNED)); // absent from older models
    return s;
  }
  catch(const Usage_error& e)
  {
    // Json_object's messages name the file already; the others (labels, feature settings) not
    const std::string what = e.what();
    if(what.compare(0, file.size(), file) == 0)
      throw;
    throw Usage_error(file + ": " + what);
  }
}

// The settings of a model file and its forest's bytes, checked; a damaged file is a Usage_error.
inline Classifier_settings read_classifier_settings(const std::string& path, std::string& forest_bytes)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Usage_error(path + ": cannot open the classifier model");
  std::string magic;
  std::getline(in, magic);
  if(magic != CLASSIFIER_MODEL_MAGIC)
    throw Usage_error(path + ": not a classifier model of sigmoid-neighborhoods (first line '" + magic.substr(0, 60) + "')");
  std::string header;
  char c;
  while(in.get(c) && c != '\n')
  {
    if(header.size() >= LARGEST_MODEL_HEADER)
      throw Usage_error(path + ": not a usable classifier model: its settings line is longer than 1 MiB");
    header.push_back(c);
  }
  Classifier_settings s = settings_from_json(parse_json_text(header, path + ": not a usable classifier model"), path);
  std::ostringstream rest;
  rest << in.rdbuf();
  forest_bytes = rest.str();
  if(forest_bytes.empty())
    throw Usage_error(path + ": not a usable classifier model: the forest is missing");
  return s;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_SETTINGS_H
