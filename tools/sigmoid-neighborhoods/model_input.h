// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading a model for the commands that compute on its normals (optimal, evaluate, filter-normals):
// the options that say where the normals come from, how they are estimated and oriented and which
// angle the weights take, and the one line that says what was done.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_MODEL_INPUT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_MODEL_INPUT_H

#include "command_line.h"

#include <CGAL/Sigmoid_neighborhoods/IO/read_oriented_point_set.h>

#include <cstdio>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;

// The options of every command that reads a model through read_model(): valued, taking three
// values, flags.
const std::vector<std::string> NORMAL_OPTIONS = {"--normals", "--normal-neighbors", "--orientation"};
const std::vector<std::string> NORMAL_TRIPLE_OPTIONS = {"--viewpoint"};
const std::vector<std::string> NORMAL_FLAGS = {"--line-angles"};

inline const char* NORMAL_USAGE =
  "  normals: --normals auto|file|pca|jet (auto: the file's, else pca), --normal-neighbors 18,\n"
  "           --orientation mst|viewpoint|up|none (mst: a spanning forest, every component from its\n"
  "           highest point; up: n_z >= 0, for airborne scans), --viewpoint X Y Z (implies viewpoint), --line-angles (weights on the\n"
  "           angle between normal lines: for normals whose signs cannot be trusted)\n";

inline std::vector<std::string> with_normal_options(std::vector<std::string> valued)
{
  valued.insert(valued.end(), NORMAL_OPTIONS.begin(), NORMAL_OPTIONS.end());
  return valued;
}

inline std::vector<std::string> with_normal_flags(std::vector<std::string> flags)
{
  flags.insert(flags.end(), NORMAL_FLAGS.begin(), NORMAL_FLAGS.end());
  return flags;
}

inline SN::Normal_source read_normal_source(const std::string& text)
{
  if(text == "auto")
    return SN::Normal_source::AUTO;
  if(text == "file")
    return SN::Normal_source::FROM_FILE;
  if(text == "pca")
    return SN::Normal_source::PCA;
  if(text == "jet")
    return SN::Normal_source::JET;
  throw Usage_error("--normals must be auto, file, pca or jet, got '" + text + "'");
}

// --normals, --normal-neighbors, --orientation, --viewpoint and --threads (--line-angles is the
// computation's: read_line_angles()).
inline SN::Normal_options read_normal_options(const Arguments& args)
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
  if(orientation == "mst")
    o.orientation = SN::Normal_orientation::SPANNING_FOREST;
  else if(orientation == "viewpoint")
    o.orientation = SN::Normal_orientation::VIEWPOINT;
  else if(orientation == "none")
    o.orientation = SN::Normal_orientation::NONE;
  else if(orientation == "up")
    o.orientation = SN::Normal_orientation::UPWARD;
  else
    throw Usage_error("--orientation must be mst, viewpoint, up or none, got '" + orientation + "'");
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

inline bool read_line_angles(const Arguments& args) { return args.has("--line-angles"); }

// A model with fewer distinct points than the `k_max + 1` of the search: not a failure of the
// model or of the package, a model too small for the grid (counted and listed apart).
struct Too_small_for_the_grid : SN::Input_error
{
  std::size_t needed, points;
  Too_small_for_the_grid(const std::string& message, std::size_t needed_, std::size_t points_)
    : SN::Input_error(message), needed(needed_), points(points_)
  {
  }
};

// Reads INPUT with its normals as `o` says and checks that `k_max` neighbors exist; Input_error
// (Too_small_for_the_grid when there are too few points) carries the reason. Without `estimate_normals`, a point set without normals comes back without
// normals. Estimated normals keep their neighbor rows when they have `k_max`, for the search.
inline SN::Oriented_point_set read_model(const std::string& path, unsigned int k_max,
                                         const SN::Normal_options& o = SN::Normal_options(),
                                         bool estimate_normals = true)
{
  SN::Normal_options normals = o;
  if(!estimate_normals)
    normals.neighbors = 0;
  normals.kept_neighbors = k_max;
  SN::Oriented_point_set model = SN::read_oriented_point_set(path, normals);
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

// "pca", "jet", "file" or "mesh": where the normals of `model` come from.
inline std::string normal_source_name(const SN::Oriented_point_set& model)
{
  if(model.normals_estimated)
    return model.estimation_method == SN::Normal_estimation_method::JET ? "jet" : "pca";
  return model.is_mesh ? "mesh" : "file";
}

inline std::string orientation_name(SN::Normal_orientation orientation)
{
  return orientation == SN::Normal_orientation::SPANNING_FOREST ? "mst"
         : orientation == SN::Normal_orientation::VIEWPOINT   ? "viewpoint"
         : orientation == SN::Normal_orientation::UPWARD      ? "up"
                                                                 : "none";
}

inline std::string model_description(const SN::Oriented_point_set& model)
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

#endif // SIGMOID_NEIGHBORHOODS_TOOL_MODEL_INPUT_H
