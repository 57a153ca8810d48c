// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feature groups a classifier can be trained on, computed on one point set: CGAL's own
// generator and the package's features at fixed, optimal and multiple scales, each group a list of
// named columns with one value per point.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H

#include "feature_options.h"
#include "../command_line.h"
#include "../optimal_command.h"

#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/add_point_features.h>

#include <CGAL/Classification/Feature_set.h>
#include <CGAL/Classification/Point_set_feature_generator.h>
#include <CGAL/Point_set_3.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace internal_classification {

inline void append_point_features(const std::vector<SN::Point_features>& features,
                                  const std::vector<SN::Point_feature>& which, const std::string& suffix,
                                  std::vector<Feature_column>& columns)
{
  for(SN::Point_feature f : which)
  {
    Feature_column c{SN::point_feature_name(f) + suffix, {}};
    c.values.reserve(features.size());
    for(const SN::Point_features& p : features)
      c.values.push_back(p.value(f));
    columns.push_back(std::move(c));
  }
}

// CGAL's generator on its own neighbor structures (it builds them), its features read back as columns.
inline void append_cgal_features(const SN::Oriented_point_set& model, unsigned int scales,
                                 std::vector<Feature_column>& columns)
{
  typedef SN::Oriented_point_set::Kernel Kernel;
  typedef CGAL::Point_set_3<Kernel::Point_3> Point_set;
  Point_set points;
  points.reserve(model.points.size());
  for(const auto& p : model.points)
    points.insert(p);
  CGAL::Classification::Point_set_feature_generator<Kernel, Point_set, Point_set::Point_map> generator(
    points, points.point_map(), scales);
  CGAL::Classification::Feature_set features;
  features.begin_parallel_additions();
  generator.generate_point_based_features(features);
  features.end_parallel_additions();
  for(std::size_t f = 0; f < features.size(); ++f)
  {
    Feature_column c{features[f]->name(), {}};
    c.values.reserve(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      c.values.push_back(features[f]->value(i));
    columns.push_back(std::move(c));
  }
}

} // namespace internal_classification

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

  std::vector<Feature_column> columns;
  for(const std::string& group : o.groups)
  {
    progress(group);
    if(group == "cgal")
      internal_classification::append_cgal_features(model, o.cgal_scales, columns);
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
      {
        std::vector<SN::Point_features> at_size;
        at_size.reserve(per_point.size());
        for(const auto& p : per_point)
          at_size.push_back(p[s]);
        append_point_features(at_size, shape, (sigmoid ? "_sigmoid_k" : "_k") + std::to_string(sizes[s]), columns);
      }
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
      append_point_features(features, equal ? with_size : with_triple, "_" + group, columns);
    }
    else if(group == "height")
    {
      for(double cell : o.cell_sizes)
      {
        std::vector<SN::Height_features> heights;
        heights.reserve(model.points.size());
        SN::compute_height_features(model.points, cell, std::back_inserter(heights));
        const std::string suffix = "_cell" + number17(cell);
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
    }
  }
  return columns;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FEATURE_GROUPS_H
