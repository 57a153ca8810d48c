// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading a model for the commands that compute on its normals (optimal, evaluate, filter-normals):
// the options that say where the normals come from, how they are estimated and oriented and which
// angle the weights take, and the one line that says what was done.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_MODEL_INPUT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_MODEL_INPUT_H

#include "command_line.h"

#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

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

SN::Normal_source read_normal_source(const std::string& text);

// --normals, --normal-neighbors, --orientation, --viewpoint and --threads (--line-angles is the
// computation's: read_line_angles()).
SN::Normal_options read_normal_options(const Arguments& args);

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
SN::Oriented_point_set read_model(const std::string& path, unsigned int k_max,
                                         const SN::Normal_options& o = SN::Normal_options(),
                                         bool estimate_normals = true);

// "pca", "jet", "file" or "mesh": where the normals of `model` come from.
std::string normal_source_name(const SN::Oriented_point_set& model);


std::string model_description(const SN::Oriented_point_set& model);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_MODEL_INPUT_H
