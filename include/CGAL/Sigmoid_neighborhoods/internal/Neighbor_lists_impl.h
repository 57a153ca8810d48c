// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The rows of the k nearest neighbors (see config.h): included by Neighbor_lists.h, or compiled once
// in CGAL::Sigmoid_neighborhoods_core.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_IMPL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_IMPL_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION Neighbor_lists nearest_neighbor_rows(const Neighbor_query& query, unsigned int k,
                                                                        unsigned int threads)
{
  const std::size_t n = query.size();
  const std::size_t row = n == 0 ? 0 : (std::min)(std::size_t(k), n - 1);
  Neighbor_lists rows;
  rows.indices.resize(n * row);
  rows.offsets.resize(n + 1);
  for(std::size_t i = 0; i <= n; ++i)
    rows.offsets[i] = i * row;
  const std::vector<std::uint32_t>& order = query.spatial_order();
  // The points in the tree's order: consecutive queries read the same leaves, and each starts from
  // the bound its predecessor gives (triangle inequality: the predecessor's k-th neighbor distance
  // plus their distance, with a relative margin far above the roundings, 1e-15 at most): a hint the
  // package's tree takes, and CGAL's search goes without.
  struct Scratch
  {
    std::vector<Neighbor> found;
    std::uint32_t previous = 0;
    double previous_radius = -1.;
  };
  for_each_index<Parallel_if_available_tag>(
    n, threads, [] { return Scratch(); },
    [&](std::size_t t, Scratch& s) {
      const std::uint32_t i = static_cast<std::uint32_t>(order.empty() ? t : order[t]);
      double bound = (std::numeric_limits<double>::infinity)();
      if(s.previous_radius >= 0.)
      {
        const double reach = s.previous_radius + std::sqrt(query.squared_distance(i, s.previous));
        bound = reach * reach * (1. + 1e-9);
      }
      query.query(i, k, s.found, bound);
      for(std::size_t j = 0; j < row; ++j)
        rows.indices[i * row + j] = s.found[j].index;
      s.previous = i;
      s.previous_radius = row == 0 ? -1. : std::sqrt(s.found[row - 1].squared_distance);
    });
  return rows;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_IMPL_H
