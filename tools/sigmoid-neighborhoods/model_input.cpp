// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// model_input.h, compiled once for the tool.

#include "model_input.h"

#ifdef __GLIBC__
#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <malloc.h>
#endif

namespace sigmoid_tool {

SN::Normal_source read_normal_source(const std::string& text)
{
  try
  {
    return SN::normal_source_from_name(text);
  }
  catch(const std::invalid_argument&)
  {
    throw Usage_error("--normals must be auto, file, pca or jet, got '" + text + "'");
  }
}

SN::Normal_options read_normal_options(const Arguments& args)
{
  SN::Normal_options o;
  o.source = read_normal_source(args.get("--normals", "auto"));
  o.neighbors = args.get_unsigned("--normal-neighbors", SN::DEFAULT_ESTIMATION_NEIGHBORS);
  const SN::Normal_estimation_method method = o.source == SN::Normal_source::JET
                                                ? SN::Normal_estimation_method::JET
                                                : SN::Normal_estimation_method::PCA;
  const unsigned int fewest = method == SN::Normal_estimation_method::PCA ? 2 : 5;
  if(o.neighbors < fewest)
    throw Usage_error("--normal-neighbors must be at least " + std::to_string(fewest) + " for " +
                      (method == SN::Normal_estimation_method::PCA ? "pca" : "jet fitting (degree 2)"));
  const std::string orientation = args.get("--orientation", args.has("--viewpoint") ? "viewpoint" : "mst");
  try
  {
    o.orientation = SN::normal_orientation_from_name(orientation);
  }
  catch(const std::invalid_argument&)
  {
    throw Usage_error("--orientation must be mst, viewpoint, up or none, got '" + orientation + "'");
  }
  if(o.orientation == SN::Normal_orientation::VIEWPOINT)
  {
    if(!args.has("--viewpoint"))
      throw Usage_error("--orientation viewpoint needs --viewpoint X Y Z");
    const std::vector<double> xyz = args.get_doubles("--viewpoint");
    o.viewpoint = SN::Oriented_point_set::Point_3(xyz[0], xyz[1], xyz[2]);
  }
  else if(args.has("--viewpoint"))
    throw Usage_error("--viewpoint goes with --orientation viewpoint, not " + orientation);
  o.threads = read_threads(args);
  return o;
}

SN::Oriented_point_set read_model(const std::string& path, unsigned int k_max,
                                         const SN::Normal_options& o,
                                         bool estimate_normals)
{
  SN::Normal_options normals = o;
  if(!estimate_normals)
    normals.neighbors = 0;
  normals.kept_neighbors = k_max;
  SN::Oriented_point_set model = SN::read_oriented_point_set(path, normals);
#ifdef __GLIBC__
  // The reader's and the normals' neighbor search (CGAL's kd-tree: many small nodes), freed, stay in
  // glibc's heap between blocks still held; the search's columns that follow do not reuse them, so
  // without this they add to its peak (+23 MB, +14 %, on a scan of 519,000 points on one thread).
  if(normals.neighbors > 0)
    malloc_trim(0);
#endif
  if(model.points.size() < std::size_t(k_max) + 1)
    throw Too_small_for_the_grid("needs at least k_max + 1 = " + std::to_string(k_max + 1) +
                                   " distinct points, got " + std::to_string(model.points.size()) +
                                   (model.dropped_vertices == 0
                                      ? std::string()
                                      : " (" + std::to_string(model.dropped_vertices) +
                                          " vertices dropped: no face or no defined normal)"),
                                 std::size_t(k_max) + 1, model.points.size());
  return model;
}

std::string normal_source_name(const SN::Oriented_point_set& model)
{
  if(model.normals_estimated)
    return SN::normal_estimation_method_name(model.estimation_method);
  return model.is_mesh ? "mesh" : "file";
}

std::string model_description(const SN::Oriented_point_set& model)
{
  std::string s = std::to_string(model.points.size()) + " points (";
  if(model.normals_estimated)
  {
    s += "normals estimated by " + normal_source_name(model) + " on " + std::to_string(model.estimation_neighbors) +
         " neighbors for " + std::to_string(model.normals.size()) + " points, ";
    if(model.orientation == SN::Normal_orientation::SPANNING_FOREST)
      s += "oriented by a spanning forest of " + std::to_string(model.orientation_components) + " tree" +
           (model.orientation_components == 1 ? "" : "s") + ", ";
    else if(model.orientation == SN::Normal_orientation::VIEWPOINT)
      s += "oriented towards the viewpoint, ";
    else if(model.orientation == SN::Normal_orientation::UPWARD)
      s += "oriented upwards, ";
    else
      s += "not oriented, ";
  }
  else if(model.is_mesh)
    s += "mesh vertex normals, ";
  else
    s += "normals from the file, ";
  if(model.zero_normals > 0)
    s += model.normals_estimated ? "the file's normals all zero, "
                                 : std::to_string(model.zero_normals) + " zero normal" +
                                     (model.zero_normals == 1 ? "" : "s") +
                                     " estimated and oriented by the neighbors' normals, ";
  if(model.is_mesh)
    s += std::to_string(model.dropped_vertices) + " dropped vertices, ";
  s += std::to_string(model.merged_duplicates) + " merged duplicates)";
  return s;
}
} // namespace sigmoid_tool
