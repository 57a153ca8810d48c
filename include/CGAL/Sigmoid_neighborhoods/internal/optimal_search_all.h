// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The optimal search on every point, the kernel (config.h) of compute_optimal_sigmoid_neighborhoods(),
// compute_optimal_point_features() and the denoiser's vote weights.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_ALL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_ALL_H

#include <CGAL/Sigmoid_neighborhoods/config.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <cstddef>
#include <functional>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

typedef std::function<void(std::size_t, const Optimal_sigmoid_neighborhood&)> Record_sink;
typedef std::function<void(std::size_t, const Optimal_sigmoid_neighborhood&, const Point_features&)> Record_features_sink;

// The search on every point of `input`, on the shared `query`, on settings.threads threads;
// `sink(i, record)` is called in index order.
CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void run_optimal_search(const Oriented_points& input, const Neighbor_query& query,
                                                           const Search_settings& settings, const Record_sink& sink);

// The same, and the Point_features of each point's optimum from the same covariance.
CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void run_optimal_point_features(const Oriented_points& input,
                                                                   const Neighbor_query& query,
                                                                   const Search_settings& settings,
                                                                   const Record_features_sink& sink);

template <typename ConcurrencyTag, typename Sink>
void optimal_search_all(const Oriented_points& input, const Neighbor_query& query, Search_settings settings,
                        const Sink& sink)
{
  settings.threads = kernel_threads<ConcurrencyTag>(settings.threads);
  run_optimal_search(input, query, settings, Record_sink(std::cref(sink)));
}

template <typename ConcurrencyTag, typename Sink>
void optimal_point_features_all(const Oriented_points& input, const Neighbor_query& query, Search_settings settings,
                                const Sink& sink)
{
  settings.threads = kernel_threads<ConcurrencyTag>(settings.threads);
  run_optimal_point_features(input, query, settings, Record_features_sink(std::cref(sink)));
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/optimal_search_all_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_ALL_H
