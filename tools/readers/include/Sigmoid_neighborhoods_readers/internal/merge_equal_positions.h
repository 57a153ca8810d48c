// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_MERGE_EQUAL_POSITIONS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_MERGE_EQUAL_POSITIONS_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/internal/merge_equal_positions.h>

#include <cstddef>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The values of the distinct positions of `merged`, each its first point's; nothing when empty.
template <typename T>
void keep_first_of_merged(std::vector<T>& values, const Merged_positions& merged)
{
  if(values.empty())
    return;
  for(std::size_t j = 0; j < merged.first.size(); ++j)
    values[j] = values[merged.first[j]];
  values.resize(merged.first.size());
}

// A point set read with or without normals: duplicates merged into the first, with its normal and
// its per-point values (labels, LAS fields); returns which points were kept.
inline Merged_positions merge_duplicate_points(Oriented_point_set& out, bool has_normals, unsigned int threads = 1)
{
  const Merged_positions merged = merge_equal_positions(out.points, {}, threads);
  keep_first_of_merged(out.points, merged);
  if(has_normals)
    keep_first_of_merged(out.normals, merged);
  keep_first_of_merged(out.labels, merged);
  keep_first_of_merged(out.intensities, merged);
  keep_first_of_merged(out.return_numbers, merged);
  keep_first_of_merged(out.numbers_of_returns, merged);
  keep_first_of_merged(out.gps_times, merged);
  out.merged_duplicates = merged.merged;
  if(merged.merged != 0)
    out.point_of_input = merged.position_of;
  return merged;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_MERGE_EQUAL_POSITIONS_H
