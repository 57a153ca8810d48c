// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feature groups of classify: their options and the table of groups, each with what it needs
// from the input (neighbors, halo) and how it is computed. This header is light: every classify
// subcommand parses the options; the checks are in feature_options.cpp, the table and the
// computations in feature_groups.cpp.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_OPTIONS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_OPTIONS_H

#include "../command_line.h"

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
struct Oriented_point_set;
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;

// Every neighbor search of the classification (the normals' rows, the groups' rows, the pyramids,
// cgal-metric's eigen analyses): the package's own kd-tree, 1.4 times faster than CGAL's in a whole
// prediction of an IGN tile, for the same rows (benchmark/README.md, "The neighbor search").
constexpr SN::Neighbor_search CLASSIFICATION_NEIGHBOR_SEARCH = SN::Neighbor_search::PACKAGE_KD_TREE;

struct Feature_column
{
  std::string name;
  std::vector<double> values; // one per point
};

// What the feature groups are computed with.
struct Feature_options
{
  std::vector<std::string> groups;
  unsigned int fixed_k = 20;                           // group k20 (its name follows fixed_k)
  unsigned int k_min = SN::defaults::K_MIN, k_max = SN::defaults::K_MAX; // the optimal searches
  std::vector<unsigned int> scales{10, 25, 50, 100};   // groups multiscale and multiscale-sigmoid
  double sigmoid_a = CGAL_PI / 6., sigmoid_b = CGAL_PI / 3.; // multiscale-sigmoid's weights
  std::vector<double> cell_sizes{2.5, 5., 10.};        // group height
  unsigned int cgal_scales = 5;                        // groups cgal, cgal-metric and cgal-grid
  // groups cgal-metric and cgal-grid: their planimetric grids anchored at the origin (a tile with its
  // halo gets the union's features); false in models written before, whose grids CGAL anchors at the
  // bounding box of the point set
  bool cgal_grids_at_origin = true;
  // groups cgal-metric and cgal-grid: the voxel of CGAL's first scale in metres, doubled per scale (the group cgal
  // takes CGAL's own choice, the mean range of each file's 12 nearest neighbors, which follows the
  // file's density: a model trained at one density reads other scales at another)
  double cgal_voxel = 0.5;
  // groups pyramid and pyramid-sigmoid: cells of pyramid_cell * 2^l metres, l < pyramid_levels. A base
  // of 0.5 m is coarser than the spacing of airborne surveys of 4 points/m^2 and more (IGN LiDAR HD:
  // 10 or more, about 0.3 m), so that every level thins and its features do not depend on the density;
  // 8 m at the top: k = 10 representatives then span about 30 m, a building and its surroundings.
  double pyramid_cell = 0.5;
  unsigned int pyramid_levels = 5;
  unsigned int pyramid_k = 10; // neighbors per level, among the level's representatives (Hackel et al. 2016)
  // group pyramid-sigmoid: the cells whose levels have the sigmoid weights (empty: every level); the
  // others have equal weights (given once when the group pyramid is there too)
  std::vector<double> pyramid_sigmoid_cells;
  unsigned int threads = 0;

  std::vector<double> pyramid_cell_sizes() const
  {
    std::vector<double> sizes;
    for(unsigned int l = 0; l < pyramid_levels; ++l)
      sizes.push_back(std::ldexp(pyramid_cell, int(l)));
    return sizes;
  }

  bool pyramid_sigmoid_level(double cell) const
  {
    return pyramid_sigmoid_cells.empty() ||
           std::find(pyramid_sigmoid_cells.begin(), pyramid_sigmoid_cells.end(), cell) != pyramid_sigmoid_cells.end();
  }

  // Where the settings come from, for the names in check()'s messages.
  enum Source { COMMAND_LINE, MODEL_FILE };

  // Throws Usage_error naming the first setting out of range (its option, or its key in a model file):
  // the same rules for the command line and the model files. The groups as check_groups(); none is
  // not an error here (the command line reads them apart from the other settings).
  void check(Source source) const;

  // The groups alone: known, each once, at most one of a family (CGAL's).
  void check_groups(Source source) const;
};

// classify train's groups without --features: the set that the cross-validation on the training
// tiles picks, at their density and trained on them thinned 4x (the worse of the two: a set must hold
// at both), among the manual's sets (benchmark/README.md, "Classification across densities").
inline const char* const DEFAULT_FEATURE_GROUPS = "cgal-metric,multiscale-sigmoid,pyramid";

struct Feature_group_input; // feature_groups.cpp: the point set, its neighbor rows, the shared pyramid

// One feature group of classify: everything the tool knows of it, one entry of feature_groups().
// What a group needs depends on the options alone, not on the other groups, so that the needs of a
// set of groups are the largest of its groups' (a function shared by groups is evaluated once).
struct Feature_group
{
  const char* name;
  const char* help; // its lines of --help after the name, '\n' between lines
  // the k nearest neighbors its features read (0: none)
  unsigned int (*neighbors)(const Feature_options&);
  // the halo a tile needs around its extent for its cells and grids (0: none); `first_guess`: with a
  // first guess of the reach of the groups whose reach the points decide (checked_halo)
  double (*halo)(const Feature_options&, bool first_guess);
  // the halo that its points need, for groups whose reach the points decide, checked on a tile (extent,
  // points first ... last - 1) read with a halo: at most that halo's width when it holds; nullptr: halo()
  double (*checked_halo)(const SN::Oriented_point_set& model, const Feature_options&, const CGAL::Bbox_2& extent,
                         std::size_t first, std::size_t last);
  // whether a tile with its halo gets the union's features (false: its features depend on the whole set)
  bool (*on_tiles)(const Feature_options&);
  // appends its columns, named and ordered as the model files name them
  void (*compute)(Feature_group_input&, std::vector<Feature_column>&);
  // groups of one family give the same columns (CGAL's): one of them at most in a set
  const char* family;
  // its scales are in metres, from a first scale that classify train may choose (cgal_voxel and
  // pyramid_cell, set together: scale_choice.h)
  bool metric_scales;
};

// The groups, in the order of --help.
const std::vector<Feature_group>& feature_groups();

// The group named `name`; nullptr when there is none.
const Feature_group* find_feature_group(const std::string& name);

// The entries of the groups of `o`, in its order (checked by Feature_options::check()).
std::vector<const Feature_group*> groups_of(const Feature_options& o);

// --help's lines on --features, from feature_groups().
std::string feature_groups_usage();

// The groups of a --features list, checked (Feature_options::check_groups()).
std::vector<std::string> parse_feature_groups(const std::string& text);

// The largest neighborhood the package's groups of `o` need (0: none, CGAL's and the heights only).
unsigned int largest_neighborhood(const Feature_options& o);

// The halo the groups of `o` need around a tile (0: none); `first_guess` false: what their cells and
// grids need alone, without the first guess of the groups whose reach the points decide (the caller
// gives that halo), see Feature_group::checked_halo.
double cell_halo(const Feature_options& o, bool first_guess = true);

// The groups of `o` whose features depend on the whole point set, so that a tile with any halo gets
// other values than the union's (the group cgal: CGAL's generator takes its scales from the average
// spacing; cgal-metric and cgal-grid in older models, whose grids CGAL anchors at the bounding box):
// "" when there is none, else the first one's name.
std::string whole_set_groups(const Feature_options& o);

// How far the grids of the groups cgal-metric and cgal-grid reach when anchored at the origin
// (SN::Classification::anchored_cgal_grid_reach(), cgal_features.cpp).
double anchored_cgal_grid_reach(const Feature_options& o);

// How much wider than `extent` a tile's halo must be for a point at (x, y) to see every point
// within `reach` of it (0 or less: the extent alone does), with a relative margin for rounding.
inline double halo_needed(double x, double y, const CGAL::Bbox_2& extent, double reach)
{
  const double inside = std::min({x - extent.xmin(), extent.xmax() - x, y - extent.ymin(), extent.ymax() - y});
  return reach * (1. + 1e-9) + 1e-9 * (std::abs(x) + std::abs(y)) - inside;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_OPTIONS_H
