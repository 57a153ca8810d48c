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
  for_each_index<Parallel_if_available_tag>(
    n, threads, [] { return std::vector<Neighbor>(); },
    [&](std::size_t i, std::vector<Neighbor>& found) {
      query.query(static_cast<std::uint32_t>(i), k, found);
      for(std::size_t j = 0; j < row; ++j)
        rows.indices[i * row + j] = found[j].index;
    });
  return rows;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_IMPL_H
