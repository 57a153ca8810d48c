// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feature groups a classifier can be trained on, computed on one point set: CGAL's own
// generator and the package's features at fixed, optimal and multiple scales, each group a list of
// named columns with one value per point. Compiled once, with the table of groups, in
// feature_groups.cpp.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H

#include "feature_options.h"

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>

#include <CGAL/Bbox_2.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace sigmoid_tool {

// The columns of every group of `o` on `model` (positions and oriented normals), in the order of
// `o.groups`; `progress` hears each step's name. The package's groups share one k-nearest-neighbor
// structure: the model's own rows when its normal estimation kept enough of them (read_model() with
// largest_neighborhood(o)), else one computed here.
std::vector<Feature_column> compute_feature_columns(const SN::Oriented_point_set& model, const Feature_options& o,
                                                    const std::function<void(const std::string&)>& progress);

// The halo a tile needs for the groups of `o` whose reach depends on the points (the pyramid groups;
// cgal-metric's neighbors and cgal-grid's windows) to give its points `first` ... `last - 1` the
// union's records, checked on `model`, the tile of extent `extent` with its halo: at most the halo's
// width when it holds (0 without such a group).
double checked_halo_width_of_tile(const SN::Oriented_point_set& model, const Feature_options& o,
                                  const CGAL::Bbox_2& extent, std::size_t first, std::size_t last);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H
