// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_MERGE_EQUAL_POSITIONS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_MERGE_EQUAL_POSITIONS_H

#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/internal/merge_equal_positions.h>

#include <cstddef>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A point set read with or without normals: duplicates merged into the first, with its normal.
inline void merge_duplicate_points(Oriented_point_set& out, bool has_normals)
{
  const Merged_positions merged = merge_equal_positions(out.points);
  for(std::size_t j = 0; j < merged.first.size(); ++j)
  {
    out.points[j] = out.points[merged.first[j]];
    if(has_normals)
      out.normals[j] = out.normals[merged.first[j]];
  }
  out.merged_duplicates = merged.merged;
  out.points.resize(merged.first.size());
  if(has_normals)
    out.normals.resize(merged.first.size());
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_MERGE_EQUAL_POSITIONS_H
