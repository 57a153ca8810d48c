// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MERGE_EQUAL_POSITIONS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MERGE_EQUAL_POSITIONS_H

#include <CGAL/Sigmoid_neighborhoods/internal/sort_on_threads.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The one merge of points at one position, for the readers and for the meshes of the library.
// Points at one position become the first of them (SPEC §1).
struct Merged_positions
{
  static constexpr std::size_t LEFT_OUT = std::size_t(-1);
  std::vector<std::size_t> first;       // per distinct position, in input order: its first point
  std::vector<std::size_t> position_of; // per point: the index of its position in `first`, or LEFT_OUT
  std::size_t merged = 0;               // points merged into an earlier one
};

// The distinct positions of the points `i` with `included[i]` (all points when `included` is empty).
// Positions are equal when their coordinates are (so 0 and -0 are one position). The points sorted
// by position, ties by index, put each position's points together, its first one first: a sort of
// indices, where a search tree of positions took a node per point.
// `threads` sort the points (0: OpenMP's default): the order is total, so the result is the same.
template <typename Point>
Merged_positions merge_equal_positions(const std::vector<Point>& points, const std::vector<bool>& included = {},
                                       unsigned int threads = 1)
{
  Merged_positions result;
  result.position_of.assign(points.size(), Merged_positions::LEFT_OUT);
  std::vector<std::size_t> order;
  order.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    if(included.empty() || included[i])
      order.push_back(i);
  const auto position = [&](std::size_t i) {
    return std::array<double, 3>{{double(points[i].x()), double(points[i].y()), double(points[i].z())}};
  };
  const auto before = [&](std::size_t a, std::size_t b) {
    const auto pa = position(a), pb = position(b);
    return pa < pb || (!(pb < pa) && a < b);
  };
  sort_on_threads(order.begin(), order.end(), before, threads);
  // each point's first point at its position; a first point is its own
  std::vector<std::size_t> first_at(points.size(), Merged_positions::LEFT_OUT);
  for(std::size_t r = 0; r < order.size(); ++r)
    first_at[order[r]] = r > 0 && !(position(order[r - 1]) < position(order[r])) ? first_at[order[r - 1]] : order[r];
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(first_at[i] == Merged_positions::LEFT_OUT)
      continue;
    if(first_at[i] == i)
    {
      result.position_of[i] = result.first.size();
      result.first.push_back(i);
    }
    else
    {
      result.position_of[i] = result.position_of[first_at[i]]; // set: the first comes before
      ++result.merged;
    }
  }
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MERGE_EQUAL_POSITIONS_H
