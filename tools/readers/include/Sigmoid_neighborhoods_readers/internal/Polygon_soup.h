// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_POLYGON_SOUP_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_POLYGON_SOUP_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>

#include <cstddef>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The vertices and faces of a mesh file, as read: what the reader of each format gives.
struct Polygon_soup
{
  std::vector<Oriented_point_set::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_POLYGON_SOUP_H
