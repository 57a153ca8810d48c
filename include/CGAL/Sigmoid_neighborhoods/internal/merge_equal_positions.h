// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MERGE_EQUAL_POSITIONS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MERGE_EQUAL_POSITIONS_H

#include <array>
#include <cstddef>
#include <map>
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
// Positions are equal when their coordinates are (so 0 and -0 are one position).
template <typename Point>
Merged_positions merge_equal_positions(const std::vector<Point>& points, const std::vector<bool>& included = {})
{
  Merged_positions result;
  result.position_of.assign(points.size(), Merged_positions::LEFT_OUT);
  std::map<std::array<double, 3>, std::size_t> position_at;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(!included.empty() && !included[i])
      continue;
    const auto inserted =
      position_at.emplace(std::array<double, 3>{{points[i].x(), points[i].y(), points[i].z()}}, result.first.size());
    if(inserted.second)
      result.first.push_back(i);
    else
      ++result.merged;
    result.position_of[i] = inserted.first->second;
  }
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MERGE_EQUAL_POSITIONS_H
