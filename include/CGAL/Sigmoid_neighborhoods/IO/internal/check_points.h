// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_CHECK_POINTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_CHECK_POINTS_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The checks of internal/Oriented_points.h, with the readers' exception.
inline void check_coordinates(const Oriented_point_set::Point_3& p, const char* what, std::size_t i)
{
  checked_point<Input_error>(p, what, i);
}

// Every point finite and within LARGEST_COORDINATE; with normals, every normal finite and non-zero,
// made unit length (unit_normal()).
inline void check_points_and_normals(std::vector<Oriented_point_set::Point_3>& points,
                                     std::vector<Oriented_point_set::Vector_3>& normals, bool has_normals)
{
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    check_coordinates(points[i], "point", i);
    if(!has_normals)
      continue;
    Eigen::Vector3d unit;
    if(!unit_normal(normals[i], unit))
      throw Input_error("point " + std::to_string(i) + " has a " +
                        (std::isfinite(normals[i].squared_length()) ? "zero" : "non-finite") + " normal");
    normals[i] = Oriented_point_set::Vector_3(unit.x(), unit.y(), unit.z());
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_CHECK_POINTS_H
