// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_ORIENTED_NORMALS_IMPL_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_ORIENTED_NORMALS_IMPL_H

#include <Sigmoid_neighborhoods_readers/estimate_oriented_normals.h>
#include <Sigmoid_neighborhoods_readers/internal/estimate_normals.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

SIGMOID_NEIGHBORHOODS_READERS_FUNCTION void estimate_oriented_normals(Oriented_point_set& points,
                                                                     const Normal_options& options)
{
  if(options.source == Normal_source::FROM_FILE)
    throw std::invalid_argument("estimate_oriented_normals: Normal_source::FROM_FILE estimates nothing");
  const unsigned int fewest = internal::fewest_estimation_neighbors(internal::estimation_method(options.source));
  if(options.neighbors < fewest)
    throw std::invalid_argument("estimate_oriented_normals: the estimation needs at least " + std::to_string(fewest) +
                                " neighbors, got " + std::to_string(options.neighbors));
  // rows of other points (the set this one was made from) must not be taken for its own
  std::vector<std::uint32_t>().swap(points.neighbor_indices);
  std::vector<std::size_t>().swap(points.neighbor_offsets);
  points.seconds = Oriented_point_set::Step_seconds();
  internal::estimate_normals(points, options);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_ORIENTED_NORMALS_IMPL_H
