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
#include "../model_input.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sigmoid_tool {

const char* const CLASSIFIER_MODEL_MAGIC = "sigmoid-neighborhoods classifier 1";
// A model's JSON line is a few kilobytes; more is not a model of the tool.
constexpr std::size_t LARGEST_MODEL_HEADER = 1 << 20;

struct Classifier_settings
{
  Label_mapping labels;
  Feature_options features;
  SN::Normal_options normals;
  std::vector<std::string> feature_names; // in the order the forest reads them
  unsigned int trees = 25, depth = 20;
  unsigned int feature_order_seed = 0;
  unsigned int max_per_class = 0; // training points per class at most (0: all), evenly spaced
};

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
  return j;
}

// Throws Usage_error naming `path` and what is wrong: the file is the tool's input too.
inline Classifier_settings settings_from_json(const nlohmann::json& j, const std::string& path)
{
  auto bad = [&](const std::string& what) { return Usage_error(path + ": not a usable classifier model: " + what); };
  try
  {
    Classifier_settings s;
    s.labels = parse_label_mapping(j.at("labels").get<std::string>());
    const nlohmann::json& f = j.at("features");
    std::string groups;
    for(const auto& g : f.at("groups"))
      groups += (groups.empty() ? "" : ",") + g.get<std::string>();
    s.features.groups = parse_feature_groups(groups);
    s.features.fixed_k = f.at("fixed_k").get<unsigned int>();
    s.features.k_min = f.at("k_min").get<unsigned int>();
    s.features.k_max = f.at("k_max").get<unsigned int>();
    s.features.scales = f.at("scales").get<std::vector<unsigned int>>();
    const std::vector<double> sigmoid = f.at("sigmoid").get<std::vector<double>>();
    s.features.cell_sizes = f.at("cell_sizes").get<std::vector<double>>();
    s.features.cgal_scales = f.at("cgal_scales").get<unsigned int>();
    if(f.contains("cgal_voxel")) // models written before it have none (nor the group cgal-metric)
      s.features.cgal_voxel = f.at("cgal_voxel").get<double>();
    // models written before the anchor have CGAL's grids, anchored at the bounding box
    const std::string anchor = f.value("cgal_grid_anchor", std::string("bounding box"));
    if(anchor != "origin" && anchor != "bounding box")
      throw bad("unknown cgal_grid_anchor '" + anchor + "'");
    s.features.cgal_grids_at_origin = anchor == "origin";
    if(sigmoid.size() != 2 || !(sigmoid[0] >= 0. && sigmoid[0] <= sigmoid[1] && sigmoid[1] <= CGAL_PI))
      throw bad("the sigmoid is not 0 <= a <= b <= pi");
    s.features.sigmoid_a = sigmoid[0];
    s.features.sigmoid_b = sigmoid[1];
    const unsigned int largest_k = 10000;
    if(s.features.fixed_k < 1 || s.features.fixed_k > largest_k || s.features.k_min < 1 ||
       s.features.k_min > s.features.k_max || s.features.k_max > largest_k || s.features.scales.empty() ||
       s.features.scales.size() > 64 || s.features.cell_sizes.empty() || s.features.cell_sizes.size() > 64 ||
       s.features.cgal_scales < 1 || s.features.cgal_scales > 32 || !(s.features.cgal_voxel > 0.) ||
       !std::isfinite(s.features.cgal_voxel))
      throw bad("feature settings out of range");
    for(unsigned int k : s.features.scales)
      if(k < 1 || k > largest_k)
        throw bad("a scale out of range");
    for(double c : s.features.cell_sizes)
      if(!(c > 0.) || !std::isfinite(c))
        throw bad("a cell size is not positive");
    if(f.contains("pyramid")) // models written before the pyramid have none: the defaults, unused
    {
      const nlohmann::json& p = f.at("pyramid");
      s.features.pyramid_cell = p.at("cell").get<double>();
      s.features.pyramid_levels = p.at("levels").get<unsigned int>();
      s.features.pyramid_k = p.at("k").get<unsigned int>();
      if(!(s.features.pyramid_cell > 0.) || !std::isfinite(s.features.pyramid_cell) || s.features.pyramid_levels < 1 ||
         s.features.pyramid_levels > 32 || s.features.pyramid_k < 1 || s.features.pyramid_k > largest_k ||
         !std::isfinite(s.features.pyramid_cell_sizes().back()))
        throw bad("pyramid settings out of range");
      if(p.contains("cell_sizes") && p.at("cell_sizes").get<std::vector<double>>() != s.features.pyramid_cell_sizes())
        throw bad("the pyramid's cell sizes are not its cell times 1, 2, 4 ...");
      if(p.contains("sigmoid_cells")) // empty, or absent in older models: every level
      {
        s.features.pyramid_sigmoid_cells = p.at("sigmoid_cells").get<std::vector<double>>();
        const std::vector<double> cells = s.features.pyramid_cell_sizes();
        for(double c : s.features.pyramid_sigmoid_cells)
          if(std::find(cells.begin(), cells.end(), c) == cells.end())
            throw bad("a sigmoid cell is not a cell size of the pyramid");
      }
    }
    const nlohmann::json& n = j.at("normals");
    s.normals.source = n.at("source").get<std::string>() == "jet" ? SN::Normal_source::JET : SN::Normal_source::PCA;
    s.normals.neighbors = n.at("neighbors").get<unsigned int>();
    if(s.normals.neighbors < 5 || s.normals.neighbors > largest_k)
      throw bad("normal neighbors out of range");
    const std::string orientation = n.at("orientation").get<std::string>();
    try
    {
      s.normals.orientation = SN::normal_orientation_from_name(orientation);
    }
    catch(const std::invalid_argument&)
    {
      throw bad("unknown orientation '" + orientation + "'");
    }
    const std::vector<double> v = n.at("viewpoint").get<std::vector<double>>();
    if(v.size() != 3)
      throw bad("the viewpoint is not three numbers");
    s.normals.viewpoint = SN::Oriented_point_set::Point_3(v[0], v[1], v[2]);
    s.feature_names = j.at("feature_names").get<std::vector<std::string>>();
    s.trees = j.at("trees").get<unsigned int>();
    s.depth = j.at("depth").get<unsigned int>();
    s.feature_order_seed = j.at("feature_order_seed").get<unsigned int>();
    s.max_per_class = j.value("max_per_class", 0u); // absent from older models
    if(s.feature_names.empty())
      throw bad("no features");
    return s;
  }
  catch(const nlohmann::json::exception& e)
  {
    throw bad(e.what());
  }
  catch(const Usage_error& e)
  {
    throw bad(e.what());
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
  // a model's settings nest 3 deep: deeper is forged, and would take nlohmann's recursive destructor deep
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for(char ch : header)
  {
    if(in_string)
    {
      if(escaped)
        escaped = false;
      else if(ch == '\\')
        escaped = true;
      else if(ch == '"')
        in_string = false;
      continue;
    }
    in_string = ch == '"';
    depth += (ch == '[' || ch == '{') - (ch == ']' || ch == '}');
    deepest = std::max(deepest, depth);
  }
  if(deepest > 8)
    throw Usage_error(path + ": not a usable classifier model: its settings nest " + std::to_string(deepest) + " deep");
  nlohmann::json j;
  try
  {
    j = nlohmann::json::parse(header);
  }
  catch(const nlohmann::json::exception& e)
  {
    throw Usage_error(path + ": not a usable classifier model: " + e.what());
  }
  Classifier_settings s = settings_from_json(j, path);
  std::ostringstream rest;
  rest << in.rdbuf();
  forest_bytes = rest.str();
  if(forest_bytes.empty())
    throw Usage_error(path + ": not a usable classifier model: the forest is missing");
  return s;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_SETTINGS_H
