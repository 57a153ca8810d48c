// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feature groups a classifier can be trained on, computed on one point set: CGAL's own
// generator and the package's features at fixed, optimal and multiple scales, each group a list of
// named columns with one value per point.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H

#include "cgal_features.h"
#include "feature_options.h"
#include "../command_line.h"
#include "../optimal_command.h"

#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_pyramid_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/add_point_features.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sigmoid_tool {

namespace internal_classification {

// The columns of the features `which` of the records `record(i)` of the points i < n, named with
// `suffix`; allocated first, then filled on `threads` threads (a value depends on its point alone).
template <typename Record>
void append_point_features(std::size_t n, const Record& record, const std::vector<SN::Point_feature>& which,
                           const std::string& suffix, unsigned int threads, std::vector<Feature_column>& columns)
{
  const std::size_t first = columns.size();
  for(SN::Point_feature f : which)
    columns.push_back({SN::point_feature_name(f) + suffix, std::vector<double>(n)});
  const std::ptrdiff_t count = std::ptrdiff_t(n);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads == 0 ? omp_get_max_threads() : int(threads))
#endif
  for(std::ptrdiff_t i = 0; i < count; ++i)
  {
    const SN::Point_features& p = record(std::size_t(i));
    for(std::size_t k = 0; k < which.size(); ++k)
      columns[first + k].values[std::size_t(i)] = p.value(which[k]);
  }
  (void)threads;
}

inline void append_point_features(const std::vector<SN::Point_features>& features,
                                  const std::vector<SN::Point_feature>& which, const std::string& suffix,
                                  unsigned int threads, std::vector<Feature_column>& columns)
{
  append_point_features(features.size(), [&](std::size_t i) -> const SN::Point_features& { return features[i]; },
                        which, suffix, threads, columns);
}

inline void append_height_features(const SN::Oriented_point_set& model, double cell, const std::string& suffix,
                                   std::vector<Feature_column>& columns)
{
  std::vector<SN::Height_features> heights;
  heights.reserve(model.points.size());
  SN::compute_height_features(model.points, cell, std::back_inserter(heights));
  Feature_column above{"height_above_lowest" + suffix, {}}, below{"height_below_highest" + suffix, {}},
    range_column{"vertical_range" + suffix, {}};
  for(const SN::Height_features& h : heights)
  {
    above.values.push_back(h.height_above_lowest);
    below.values.push_back(h.height_below_highest);
    range_column.values.push_back(h.vertical_range);
  }
  columns.push_back(std::move(above));
  columns.push_back(std::move(below));
  columns.push_back(std::move(range_column));
}

// The suffix of a pyramid level's columns: its cell size, e.g. "_pyr0.5".
inline std::string pyramid_suffix(double cell) { return "_pyr" + number17(cell); }

} // namespace internal_classification

// The pyramid of the groups pyramid and pyramid-sigmoid on `model`.
inline std::vector<SN::Pyramid_level> build_model_pyramid(const SN::Oriented_point_set& model, const Feature_options& o)
{
  return SN::build_point_pyramid<SN::Parallel_if_available_tag>(
    point_indices(model.points.size()), o.pyramid_cell_sizes(), o.pyramid_k,
    SN::parameters::number_of_threads(o.threads, model_maps(model)));
}

// How wide a tile's halo must be for the pyramid's records of the tile's points `first` ... `last - 1`
// (of extent `extent` in x and y) to be the union's, checked on `model`, the tile and a halo of the
// union's points within `width` of the extent (read_tile_with_halo()): the result is at most `width`
// when they are. A point's records are its nearest representative's and those of that one's k
// neighbors among the representatives (and, where normals are estimated, the normals of these). Every
// point of the union within xy-distance W + inside(x) of x is read, inside(x) the distance of x to the
// extent's nearest side (negative outside). A representative read is the union's when its cell is
// whole, i.e. every union point of its cell is read; a cell meeting the ball of radius d around x lies
// within d + sqrt(2) c of x in xy. So for a point p, its nearest representative r at d and r's k-th
// neighbor at d_k: when every cell meeting the ball of radius d around p and of radius d_k around r
// is whole, the representatives in both balls are the union's (and no union representative in them
// is missing), so r and its row are the union's (ties break on the global order, which the read set
// keeps). A normal estimated on n neighbors is the union's when the ball of its n-th neighbor is read.
inline double pyramid_halo_width(const SN::Oriented_point_set& model, const Feature_options& o,
                                 const CGAL::Bbox_2& extent, std::size_t first, std::size_t last)
{
  using internal_classification::has_group;
  const std::vector<SN::Pyramid_level> levels = build_model_pyramid(model, o);
  const bool sigmoid = has_group(o, "pyramid-sigmoid");
  const unsigned int normal_neighbors = model.normals_estimated ? model.estimation_neighbors : 0;
  auto distance = [&](std::size_t i, std::size_t j) { return std::sqrt(CGAL::squared_distance(model.points[i], model.points[j])); };
  // the halo point i needs to see every union point within `reach` of it
  auto needed = [&](std::size_t i, double reach) {
    return halo_needed(model.points[i].x(), model.points[i].y(), extent, reach);
  };
  auto normal_reach = [&](std::size_t i) {
    if(normal_neighbors == 0)
      return 0.;
    const std::size_t row = model.neighbor_offsets[i + 1] - model.neighbor_offsets[i];
    if(row < normal_neighbors)
      return std::numeric_limits<double>::infinity();
    return distance(i, model.neighbor_indices[model.neighbor_offsets[i] + normal_neighbors - 1]);
  };
  double width = 0.;
  for(const SN::Pyramid_level& level : levels)
  {
    const double cell = std::sqrt(2.) * level.thinning.cell_size;
    const auto& representatives = level.thinning.representatives;
    std::vector<char> seen(representatives.size(), 0);
    for(std::size_t i = first; i < last; ++i)
    {
      const std::uint32_t r = level.thinning.nearest_representative[i];
      width = std::max(width, needed(i, distance(i, representatives[r]) + cell));
      if(seen[r])
        continue;
      seen[r] = 1;
      const std::size_t begin = level.neighbor_offsets[r], end = level.neighbor_offsets[r + 1];
      const double d_k = distance(representatives[r], representatives[level.neighbor_indices[end - 1]]);
      width = std::max(width, needed(representatives[r], std::max(d_k + cell, normal_reach(representatives[r]))));
      if(sigmoid) // the weights read the neighbors' normals
        for(std::size_t e = begin; e < end; ++e)
          width = std::max(width, needed(representatives[level.neighbor_indices[e]],
                                         normal_reach(representatives[level.neighbor_indices[e]])));
    }
  }
  return width;
}

// The columns of every group of `o` on `model` (positions and oriented normals), in the order of
// `o.groups`. The package's groups share one k-nearest-neighbor structure: the model's own rows when
// its normal estimation kept enough of them (read_model() with largest_neighborhood(o)), else one
// computed here.
template <typename Progress>
std::vector<Feature_column> compute_feature_columns(const SN::Oriented_point_set& model, const Feature_options& o,
                                                    const Progress& progress)
{
  namespace SNP = SN::parameters;
  using internal_classification::append_point_features;
  using internal_classification::has_group;
  const std::vector<SN::Point_feature> shape = SN::Classification::default_point_features();
  std::vector<SN::Point_feature> with_size = shape;
  with_size.push_back(SN::Point_feature::NEIGHBORHOOD_SIZE);
  std::vector<SN::Point_feature> with_triple = with_size;
  for(SN::Point_feature f : {SN::Point_feature::SIGMOID_A, SN::Point_feature::SIGMOID_B, SN::Point_feature::RADIUS,
                             SN::Point_feature::DIMENSIONALITY_ERROR})
    with_triple.push_back(f);

  const unsigned int k_needed = largest_neighborhood(o);
  const auto range = point_indices(model.points.size());
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  const auto maps = model_maps(model);
  const bool model_rows = k_needed > 0 && !model.neighbor_offsets.empty() &&
                          model.neighbor_indices.size() >= std::size_t(k_needed) * model.points.size();
  if(k_needed > 0 && !model_rows)
  {
    if(model.points.size() < std::size_t(k_needed) + 1)
      throw SN::Input_error("needs at least " + std::to_string(k_needed + 1) + " distinct points for the features, got " +
                            std::to_string(model.points.size()));
    progress("neighbors");
    SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(range, k_needed, indices, offsets,
                                                                   SNP::number_of_threads(o.threads, maps));
  }
  const auto rows = SNP::number_of_threads(
    o.threads, SNP::neighbor_indices(std::cref(model_rows ? model.neighbor_indices : indices),
                                     SNP::neighbor_offsets(std::cref(model_rows ? model.neighbor_offsets : offsets), maps)));
  const std::vector<double> pi{CGAL_PI};

  std::vector<SN::Pyramid_level> pyramid; // built once for both pyramid groups

  std::vector<Feature_column> columns;
  for(const std::string& group : o.groups)
  {
    progress(group);
    if((group == "cgal-metric" || group == "cgal-grid") && o.cgal_grids_at_origin)
      append_anchored_cgal_features(model, o.cgal_scales, o.cgal_voxel, o.threads, columns, group == "cgal-grid");
    else if(group == "cgal" || group == "cgal-metric" || group == "cgal-grid")
      append_cgal_features(model, o.cgal_scales, group == "cgal" ? 0. : o.cgal_voxel, o.threads, columns,
                           group == "cgal-grid");
    else if(group == "k20" || group == "multiscale" || group == "multiscale-sigmoid")
    {
      const bool sigmoid = group == "multiscale-sigmoid";
      const std::vector<unsigned int> sizes = group == "k20" ? std::vector<unsigned int>{o.fixed_k} : o.scales;
      const SN::Cosine_sigmoid weights = sigmoid ? SN::Cosine_sigmoid(o.sigmoid_a, o.sigmoid_b)
                                                 : SN::Cosine_sigmoid(CGAL_PI, CGAL_PI);
      std::vector<std::vector<SN::Point_features>> per_point;
      per_point.reserve(model.points.size());
      SN::compute_point_features<SN::Parallel_if_available_tag>(range, weights, sizes, std::back_inserter(per_point),
                                                                rows);
      for(std::size_t s = 0; s < sizes.size(); ++s)
        append_point_features(
          per_point.size(), [&](std::size_t i) -> const SN::Point_features& { return per_point[i][s]; }, shape,
          (sigmoid ? "_sigmoid_k" : "_k") + std::to_string(sizes[s]), o.threads, columns);
    }
    else if(group == "eigenentropy" || group == "dimensionality" || group == "optimal")
    {
      const bool equal = group != "optimal";
      const SN::Neighborhood_criterion criterion = group == "eigenentropy" ? SN::Neighborhood_criterion::EIGENENTROPY
                                                                           : SN::Neighborhood_criterion::DIMENSIONALITY;
      const auto grid = equal ? pi : SN::default_angle_grid();
      std::vector<SN::Point_features> features;
      features.reserve(model.points.size());
      SN::compute_optimal_point_features<SN::Parallel_if_available_tag>(
        range, std::back_inserter(features),
        SNP::criterion(criterion, SNP::k_min(o.k_min, SNP::k_max(o.k_max, SNP::a_grid(grid, SNP::b_grid(grid, rows))))));
      append_point_features(features, equal ? with_size : with_triple, "_" + group, o.threads, columns);
    }
    else if(group == "height")
    {
      for(double cell : o.cell_sizes)
        internal_classification::append_height_features(model, cell, "_cell" + number17(cell), columns);
    }
    else if(group == "pyramid" || group == "pyramid-sigmoid")
    {
      const bool sigmoid = group == "pyramid-sigmoid";
      if(pyramid.empty())
        pyramid = build_model_pyramid(model, o);
      const std::vector<double> cells = o.pyramid_cell_sizes();
      // this group's levels: with the sigmoid weights, or equal ones where the group pyramid does not give them
      std::vector<std::size_t> weighted, equal;
      for(std::size_t l = 0; l < cells.size(); ++l)
        if(sigmoid && o.pyramid_sigmoid_level(cells[l]))
          weighted.push_back(l);
        else if(!sigmoid || !has_group(o, "pyramid"))
          equal.push_back(l);
      std::vector<std::vector<SN::Point_features>> per_point(model.points.size());
      for(const bool with_weights : {true, false})
      {
        const std::vector<std::size_t>& which = with_weights ? weighted : equal;
        if(which.empty())
          continue;
        std::vector<SN::Pyramid_level> levels;
        for(std::size_t l : which)
          levels.push_back(pyramid[l]);
        const SN::Cosine_sigmoid weights = with_weights ? SN::Cosine_sigmoid(o.sigmoid_a, o.sigmoid_b)
                                                        : SN::Cosine_sigmoid(CGAL_PI, CGAL_PI);
        std::vector<std::vector<SN::Point_features>> records;
        records.reserve(model.points.size());
        SN::compute_pyramid_features<SN::Parallel_if_available_tag>(range, levels, o.pyramid_k, weights,
                                                                    std::back_inserter(records),
                                                                    SNP::number_of_threads(o.threads, maps));
        const std::ptrdiff_t count = std::ptrdiff_t(records.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(o.threads == 0 ? omp_get_max_threads() : int(o.threads))
#endif
        for(std::ptrdiff_t i = 0; i < count; ++i)
          per_point[std::size_t(i)].insert(per_point[std::size_t(i)].end(), records[std::size_t(i)].begin(),
                                           records[std::size_t(i)].end());
      }
      // per_point holds the weighted levels, then the equal ones: the columns in that order
      std::vector<std::size_t> order = weighted;
      order.insert(order.end(), equal.begin(), equal.end());
      for(std::size_t c = 0; c < order.size(); ++c)
      {
        const std::string weights_name = c < weighted.size() ? "_sigmoid" : "";
        append_point_features(
          per_point.size(), [&](std::size_t i) -> const SN::Point_features& { return per_point[i][c]; }, shape,
          weights_name + internal_classification::pyramid_suffix(cells[order[c]]), o.threads, columns);
      }
      // the heights in the levels' cells, once when both groups are given
      if(!sigmoid || !has_group(o, "pyramid"))
        for(double cell : cells)
          internal_classification::append_height_features(model, cell, internal_classification::pyramid_suffix(cell),
                                                          columns);
    }
  }
  return columns;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H
