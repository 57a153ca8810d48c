// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feature groups of classify: their names and options (this header, light: every classify
// subcommand parses them) and what each group needs from the input (neighbors, halo). Their
// computation is in feature_groups.h.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_OPTIONS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_OPTIONS_H

#include "../command_line.h"

#include <CGAL/Sigmoid_neighborhoods/search_parameters.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;


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
  unsigned int k_min = SN::DEFAULT_K_MIN, k_max = SN::DEFAULT_K_MAX; // the optimal searches
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
};

// classify train's groups without --features: the set that the cross-validation on the training
// tiles picks, at their density and trained on them thinned 4x (the worse of the two: a set must hold
// at both), among the manual's sets (benchmark/README.md, "Classification across densities").
inline const char* const DEFAULT_FEATURE_GROUPS = "cgal-metric,multiscale-sigmoid,pyramid";

inline const char* FEATURE_GROUPS_USAGE =
  "  --features GROUPS: comma-separated, in any combination (default cgal-metric,multiscale-sigmoid,pyramid:\n"
  "      the best in cross-validation at the training density and trained 4x thinner, benchmark/README.md):\n"
  "      cgal            CGAL's Point_set_feature_generator on 5 scales (eigenvalues, heights, ...), the\n"
  "                      first from each file's spacing, as CGAL chooses it\n"
  "      cgal-metric     the same on scales in metres: --cgal-voxel 0.5 m times 1, 2, 4 ... (a model\n"
  "                      applies at another density), its grids anchored at the origin (tile by tile)\n"
  "      cgal-grid       the features of cgal-metric's planimetric grids alone (vertical dispersion,\n"
  "                      elevation, heights below and above, vertical range): no eigen analysis\n"
  "      k20             the eigen features (linearity ... normal_z) at k = 20, equal weights\n"
  "      eigenentropy    the same at the eigenentropy-optimal k of Weinmann et al., equal weights, and k\n"
  "      dimensionality  the same at the E_dim-optimal k, equal weights, and k\n"
  "      optimal         the same at the optimal sigmoid triple (a*, b*, k*), and k, a, b, the radius\n"
  "      multiscale      the eigen features at k = 10, 25, 50, 100 (--scales), equal weights\n"
  "      multiscale-sigmoid  the same with the sigmoid weights of --sigmoid A,B (default 30deg,60deg; the\n"
  "                      smaller angle is a, the larger b, one angle a step; pyramid-sigmoid's weights too)\n"
  "      height          z above the lowest point, below the highest and the range in 2.5, 5, 10 m cells\n"
  "      pyramid         the eigen features at k = 10 on voxel grids of --pyramid-cell x 2^l metres, l below\n"
  "                      --pyramid-levels, each point's from its nearest representative, and the heights\n"
  "                      in the same cells (scales in metres: a model applies at another density)\n"
  "      pyramid-sigmoid the same with the sigmoid weights of --sigmoid, on the levels of\n"
  "                      --pyramid-sigmoid-cells C,... (default every level; the others with equal weights)\n";

inline const std::vector<std::string>& known_feature_groups()
{
  static const std::vector<std::string> groups{"cgal",         "cgal-metric",        "cgal-grid", "k20", "eigenentropy",
                                               "dimensionality", "optimal",            "multiscale",
                                               "multiscale-sigmoid", "height", "pyramid", "pyramid-sigmoid"};
  return groups;
}

inline std::vector<std::string> parse_feature_groups(const std::string& text)
{
  std::vector<std::string> groups;
  for(const std::string& group : split(text, ','))
  {
    const auto& known = known_feature_groups();
    if(std::find(known.begin(), known.end(), group) == known.end())
      throw Usage_error("--features: unknown group '" + group +
                        "': expected cgal, cgal-metric, cgal-grid, k20, eigenentropy, dimensionality, optimal, multiscale, "
                        "multiscale-sigmoid, height, pyramid or pyramid-sigmoid");
    if(std::find(groups.begin(), groups.end(), group) != groups.end())
      throw Usage_error("--features: group '" + group + "' given twice");
    groups.push_back(group);
  }
  auto has = [&](const char* g) { return std::find(groups.begin(), groups.end(), g) != groups.end(); };
  if(int(has("cgal")) + int(has("cgal-metric")) + int(has("cgal-grid")) > 1)
    throw Usage_error("--features: cgal, cgal-metric and cgal-grid share CGAL's features (cgal-grid its grids' "
                      "alone): give one of them");
  return groups;
}

namespace internal_classification {

inline bool has_group(const Feature_options& o, const char* group)
{
  return std::find(o.groups.begin(), o.groups.end(), group) != o.groups.end();
}

inline bool has_pyramid(const Feature_options& o) { return has_group(o, "pyramid") || has_group(o, "pyramid-sigmoid"); }

} // namespace internal_classification

// The largest neighborhood the package's groups of `o` need (0: none, CGAL's and the heights only).
inline unsigned int largest_neighborhood(const Feature_options& o)
{
  using internal_classification::has_group;
  unsigned int k = 0;
  if(has_group(o, "k20"))
    k = std::max(k, o.fixed_k);
  if(has_group(o, "eigenentropy") || has_group(o, "dimensionality") || has_group(o, "optimal"))
    k = std::max(k, o.k_max);
  if(has_group(o, "multiscale") || has_group(o, "multiscale-sigmoid"))
    k = std::max(k, *std::max_element(o.scales.begin(), o.scales.end()));
  return k;
}

// How far the grids of the groups cgal-metric and cgal-grid reach when anchored at the origin
// (SN::Classification::anchored_cgal_grid_reach(), cgal_features.cpp).
double anchored_cgal_grid_reach(const Feature_options& o);

// The halo the groups height, pyramid, cgal-metric and cgal-grid need around a tile (0: none). Height: a cell meeting the
// tile lies within its side of the tile, so a halo that wide holds every point of the tile's cells.
// The relative margin covers the rounding of x / side at the cells' borders while |x| / side stays
// below 10^9. Pyramid: a first guess only, 4 coarsest cells (a point's nearest representative within
// a cell's diagonal, 1.7 cells, the k = 10 nearest of that one within about 2 cells on a surface, and
// their cells; the six IGN tiles need 3.4 to 3.9); pyramid_halo_width() (feature_groups.h) checks it
// on what was read, and the tile is read again with a wider halo when it does not hold.
// cgal-metric and cgal-grid anchored at the origin: their grids' windows, with the same margin; their
// neighbors are checked on what was read, as the pyramid's (anchored_cgal_halo_width()).
// `pyramid_guess` false: what the cells need alone (the caller gives the pyramid's first halo).
inline double cell_halo(const Feature_options& o, bool pyramid_guess = true)
{
  using internal_classification::has_group;
  double halo = 0.;
  if(has_group(o, "height"))
    halo = *std::max_element(o.cell_sizes.begin(), o.cell_sizes.end()) * (1. + 1e-6);
  if(internal_classification::has_pyramid(o))
    halo = std::max(halo, o.pyramid_cell_sizes().back() * (1. + 1e-6)); // the heights in its cells
  if(pyramid_guess && internal_classification::has_pyramid(o))
    halo = std::max(halo, 4. * o.pyramid_cell_sizes().back());
  if(o.cgal_grids_at_origin && (has_group(o, "cgal-metric") || has_group(o, "cgal-grid")))
    halo = std::max(halo, anchored_cgal_grid_reach(o) * (1. + 1e-6)); // the grids' windows
  return halo;
}

// The groups of `o` that depend on the whole point set (the cgal group: CGAL's generator takes its
// scales from the average spacing; cgal-metric and cgal-grid in older models, whose grids CGAL anchors
// at the bounding box), so that a tile with any halo gets other values than the union: "" when there
// is none.
inline std::string whole_set_groups(const Feature_options& o)
{
  using internal_classification::has_group;
  if(has_group(o, "cgal"))
    return "cgal";
  if(o.cgal_grids_at_origin)
    return "";
  return has_group(o, "cgal-metric") ? "cgal-metric" : has_group(o, "cgal-grid") ? "cgal-grid" : "";
}

// How much wider than `extent` a tile's halo must be for a point at (x, y) to see every point
// within `reach` of it (0 or less: the extent alone does), with a relative margin for rounding.
inline double halo_needed(double x, double y, const CGAL::Bbox_2& extent, double reach)
{
  const double inside = std::min({x - extent.xmin(), extent.xmax() - x, y - extent.ymin(), extent.ymax() - y});
  return reach * (1. + 1e-9) + 1e-9 * (std::abs(x) + std::abs(y)) - inside;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_OPTIONS_H
