// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The optimal search on every point (see config.h): included by optimal_search_all.h, or compiled
// once in CGAL::Sigmoid_neighborhoods_core.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_ALL_IMPL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_ALL_IMPL_H

#include <CGAL/Sigmoid_neighborhoods/internal/optimal_search_all.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Optimal_search.h>
#include <CGAL/Sigmoid_neighborhoods/internal/point_features_of.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void run_optimal_search(const Oriented_points& input, const Neighbor_query& query,
                                                           const Search_settings& settings, const Record_sink& sink)
{
  check_enough_points(input.size(), settings.k_max);
  check_neighborhood_size(query, settings.k_max);
  const Optimal_search search(settings);
  for_each_neighborhood<Parallel_if_available_tag, Optimal_sigmoid_neighborhood>(
    input, query, settings.k_max, settings.threads, [&search] { return search.make_scratch(); },
    [&search](std::size_t, const Local_neighborhood& local, Optimal_search::Scratch& s) { return search(local, s); },
    sink, search.needs_angles(), Scattered_input::IN_SPATIAL_ORDER);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void run_optimal_point_features(const Oriented_points& input,
                                                                   const Neighbor_query& query,
                                                                   const Search_settings& settings,
                                                                   const Record_features_sink& sink)
{
  check_enough_points(input.size(), settings.k_max);
  check_neighborhood_size(query, settings.k_max);
  const Optimal_search search(settings);
  struct Scratch
  {
    Optimal_search::Scratch search;
    std::vector<double> weights;
  };
  typedef std::pair<Optimal_sigmoid_neighborhood, Point_features> Result;
  for_each_neighborhood<Parallel_if_available_tag, Result>(
    input, query, settings.k_max, settings.threads, [&search] { return Scratch{search.make_scratch(), {}}; },
    [&](std::size_t i, const Local_neighborhood& local, Scratch& s) {
      Result result;
      result.first = search(local, s.search);
      const Optimal_sigmoid_neighborhood& record = result.first;
      if(record.is_failure())
      {
        result.second.normal_z = input.normals[i].z();
        return result;
      }
      const Cosine_sigmoid sigmoid(record.a, record.b, settings.angle_tolerance);
      s.weights.resize(local.size());
      local.weights(sigmoid, s.weights.data());
      // the search's own features at its optimum: the same covariance, no second eigenvalue solve
      result.second = point_features_of(local, s.weights.data(), record.k, settings.barycenter, sigmoid,
                                        input.normals[i].z(), &record.features);
      return result;
    },
    [&sink](std::size_t i, const Result& r) { sink(i, r.first, r.second); }, search.needs_angles(),
    Scattered_input::IN_SPATIAL_ORDER);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_ALL_IMPL_H
