// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The groups cgal, cgal-metric and cgal-grid: CGAL's Point_set_feature_generator, compiled once
// (cgal_features.cpp) for every command that computes features.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CGAL_FEATURES_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CGAL_FEATURES_H

#include "feature_options.h"

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>

#include <CGAL/Bbox_2.h>

#include <cstddef>
#include <vector>

namespace sigmoid_tool {

// The point-based features of CGAL's Point_set_feature_generator on `scales` scales of `model`,
// appended as columns in the generator's order and with its names. `voxel`: the first scale in metres,
// doubled per scale; 0: CGAL's choice, the mean range of each point's 12 nearest neighbors. On one
// thread, CGAL's generator itself; on more (`threads`, 0: all), the scales are built side by side, each
// as the generator builds it with CGAL::Sequential_tag, so that the values are the sequential
// generator's bit for bit for any thread count (the generator's own parallel build differs in the last
// bits from run to run).
// `grid_only`: the features of the planimetric grids alone (vertical dispersion, elevation, heights
// below and above, vertical range), without the neighborhoods and eigen analyses; needs `voxel` > 0.
void append_cgal_features(const SN::Oriented_point_set& model, unsigned int scales, double voxel, unsigned int threads,
                          std::vector<Feature_column>& columns, bool grid_only = false);

// The same features of cgal-metric (or cgal-grid: `grid_only`) with the grids anchored at the origin
// (SN::Classification::compute_anchored_cgal_features()), so that a tile with its halo gets the
// union's values: the groups' features in models that say so (Feature_options::cgal_grids_at_origin).
void append_anchored_cgal_features(const SN::Oriented_point_set& model, unsigned int scales, double voxel,
                                   unsigned int threads, std::vector<Feature_column>& columns, bool grid_only);

// The halo that the anchored features of the points `first` ... `last - 1` (a tile of extent
// `extent`) need to be the union's, checked on `model`, the tile and its halo: the widest of their
// neighbors' reach and of the grids' (anchored_cgal_grid_reach()).
double anchored_cgal_halo_width(const SN::Oriented_point_set& model, unsigned int scales, double voxel,
                                bool grid_only, unsigned int threads, const CGAL::Bbox_2& extent, std::size_t first,
                                std::size_t last);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CGAL_FEATURES_H
