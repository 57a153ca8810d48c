// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_PLY_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_PLY_H

#include <Sigmoid_neighborhoods_readers/internal/Polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/cgal_5_5_workarounds.h>
#include <Sigmoid_neighborhoods_readers/internal/check_ply_counts.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>

#include <CGAL/IO/PLY.h>

#include <string>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The polygon soup of a PLY file (no faces: a point set, read by read_points_without_faces()):
// CGAL's reader behind the checks it needs, of the header (check_ply_header()) and of every count
// (check_ply_counts()).
inline bool read_ply_soup(const Input_file& file, Polygon_soup& soup)
{
  check_ply_header(file.name);
  check_ply_counts(file);
  return CGAL::IO::read_PLY(file.name, soup.points, soup.polygons);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_PLY_H
