// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_DENOISE_POINT_SET_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_DENOISE_POINT_SET_H

#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Point_set_3_maps.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_3.h>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `denoise_point_set()` on a `CGAL::Point_set_3` with normals: its points move in place and its
  normal map receives the filtered normals.
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
Point_set_denoising_summary denoise_point_set(CGAL::Point_set_3<Point, Vector>& points,
                                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "denoise_point_set");
  auto indices = internal::point_set_indices(points);
  return denoise_point_set<ConcurrencyTag>(indices, internal::with_point_set_maps(points, np));
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_DENOISE_POINT_SET_H
