// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CHECK_POINTS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CHECK_POINTS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
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
// made unit length (unit_normal()). With `allow_zero_normals`, a zero normal is left zero and
// counted instead (the index of the first in `first_zero`): the caller estimates it or refuses it.
inline std::size_t check_points_and_normals(std::vector<Oriented_point_set::Point_3>& points,
                                            std::vector<Oriented_point_set::Vector_3>& normals, bool has_normals,
                                            bool allow_zero_normals = false, std::size_t* first_zero = nullptr)
{
  std::size_t zeros = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    check_coordinates(points[i], "point", i);
    if(!has_normals)
      continue;
    Eigen::Vector3d unit;
    if(!unit_normal(normals[i], unit))
    {
      const bool zero = std::isfinite(normals[i].squared_length());
      if(!zero || !allow_zero_normals)
        throw Input_error("point " + std::to_string(i) + " has a " + (zero ? "zero" : "non-finite") + " normal");
      if(zeros++ == 0 && first_zero != nullptr)
        *first_zero = i;
      normals[i] = CGAL::NULL_VECTOR;
      continue;
    }
    normals[i] = Oriented_point_set::Vector_3(unit.x(), unit.y(), unit.z());
  }
  return zeros;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CHECK_POINTS_H
