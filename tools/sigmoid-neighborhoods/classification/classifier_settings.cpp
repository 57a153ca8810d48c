// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A classifier model's settings read back and checked (classifier_settings.h).

#include "classifier_settings.h"

#include "../command_line.h"
#include "../json.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

constexpr std::uint64_t LARGEST_UNSIGNED = std::numeric_limits<unsigned int>::max();
const double NOT_A_NUMBER = std::numeric_limits<double>::quiet_NaN(); // null: refused by check()

unsigned int unsigned_value(const Json_object& o, const char* key)
{
  return unsigned(o.integer(key, 0, LARGEST_UNSIGNED));
}

std::vector<unsigned int> unsigned_values(const Json_object& o, const char* key)
{
  std::vector<unsigned int> values;
  const Json_value& a = o.array(key, 1024);
  for(const std::uint64_t v : o.integers(key, a.size(), LARGEST_UNSIGNED))
    values.push_back(unsigned(v));
  return values;
}

// The pyramid's settings; models written before the pyramid have none: the defaults, unused.
// Returns its cell sizes as written, for the reader.
std::vector<double> read_pyramid_settings(const Json_object& f, Feature_options& o)
{
  std::vector<double> written_cells;
  if(!f.has("pyramid"))
    return written_cells;
  const Json_object p = f.object("pyramid");
  o.pyramid_cell = p.number("cell", NOT_A_NUMBER);
  o.pyramid_levels = unsigned_value(p, "levels");
  o.pyramid_k = unsigned_value(p, "k");
  if(p.has("sigmoid_cells")) // empty, or absent in older models: every level
    o.pyramid_sigmoid_cells = p.numbers("sigmoid_cells", 64);
  if(p.has("cell_sizes"))
    written_cells = p.numbers("cell_sizes", 64);
  return written_cells;
}

Feature_options read_feature_settings(const Json_object& f)
{
  Feature_options o;
  for(const Json_value& g : f.array("groups", 64))
  {
    if(!g.is_string())
      f.fail("features.groups", "holds " + Json_object::type_name(g) + ", expected group names");
    o.groups.push_back(g.get<std::string>());
  }
  o.fixed_k = unsigned_value(f, "fixed_k");
  o.k_min = unsigned_value(f, "k_min");
  o.k_max = unsigned_value(f, "k_max");
  o.scales = unsigned_values(f, "scales");
  const std::vector<double> sigmoid = f.numbers("sigmoid", 2);
  if(sigmoid.size() != 2)
    f.fail("features.sigmoid", "is not two angles");
  o.sigmoid_a = sigmoid[0];
  o.sigmoid_b = sigmoid[1];
  o.cell_sizes = f.numbers("cell_sizes", 1024);
  o.cgal_scales = unsigned_value(f, "cgal_scales");
  if(f.has("cgal_voxel")) // models written before it have none (nor the group cgal-metric)
    o.cgal_voxel = f.number("cgal_voxel", NOT_A_NUMBER);
  // models written before the anchor have CGAL's grids, anchored at the bounding box
  o.cgal_grids_at_origin = f.has("cgal_grid_anchor") && f.choice("cgal_grid_anchor", {"origin", "bounding box"}) == "origin";
  const std::vector<double> written_cells = read_pyramid_settings(f, o);
  o.check(Feature_options::MODEL_FILE);
  if(!written_cells.empty() && written_cells != o.pyramid_cell_sizes())
    f.fail("features.pyramid.cell_sizes", "are not its cell times 1, 2, 4 ...");
  return o;
}

SN::Normal_options read_normal_settings(const Json_object& n)
{
  SN::Normal_options o;
  o.source = n.choice("source", {"jet", "pca"}) == "jet" ? SN::Normal_source::JET : SN::Normal_source::PCA;
  o.neighbors = unsigned_value(n, "neighbors");
  o.neighbor_search = CLASSIFICATION_NEIGHBOR_SEARCH;
  if(o.neighbors < 5 || o.neighbors > 10000)
    n.fail("normals.neighbors", "is " + std::to_string(o.neighbors) + ", expected 5 to 10000");
  const std::string orientation = n.string("orientation", 64);
  try
  {
    o.orientation = SN::normal_orientation_from_name(orientation);
  }
  catch(const std::invalid_argument&)
  {
    n.fail("normals.orientation", "is '" + orientation + "', not an orientation");
  }
  const std::vector<double> v = n.numbers("viewpoint", 3);
  if(v.size() != 3)
    n.fail("normals.viewpoint", "is not three numbers");
  o.viewpoint = SN::Oriented_point_set::Point_3(v[0], v[1], v[2]);
  return o;
}

std::vector<std::string> read_feature_names(const Json_object& model)
{
  std::vector<std::string> names;
  for(const Json_value& name : model.array("feature_names", 1 << 16))
  {
    if(!name.is_string())
      model.fail("feature_names", "holds " + Json_object::type_name(name) + ", expected names");
    names.push_back(name.get<std::string>());
  }
  if(names.empty())
    model.fail("feature_names", "is empty: no features");
  return names;
}

} // namespace

Classifier_settings settings_from_json(const nlohmann::json& j, const std::string& path)
{
  const std::string file = path + ": not a usable classifier model";
  try
  {
    const Json_object model(j, file);
    Classifier_settings s;
    s.labels = parse_label_mapping(model.string("labels", 1 << 16));
    s.features = read_feature_settings(model.object("features"));
    s.normals = read_normal_settings(model.object("normals"));
    s.feature_names = read_feature_names(model);
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

Classifier_settings read_classifier_settings(const std::string& path, std::string& forest_bytes)
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
