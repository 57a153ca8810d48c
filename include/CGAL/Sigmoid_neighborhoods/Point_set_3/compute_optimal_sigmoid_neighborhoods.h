// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H

#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Point_set_3_maps.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_3.h>

#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `compute_optimal_sigmoid_neighborhoods()` on a `CGAL::Point_set_3` with normals, the
  records written to its properties: `scalar_a`, `scalar_b`, `scalar_error`, `scalar_linearity`,
  `scalar_planarity`, `scalar_scattering`, `scalar_error_equal` (`double`), `scalar_k`,
  `scalar_k_equal` (`int`) and `scalar_label` (`std::uint8_t`: 0 linear, 1 planar, 2 scattered,
  3 degenerate), the columns of the tool's CSV. A failure has NaN `a`, `b` and features, `k = 0` and
  an infinite error. Existing properties of these names are overwritten.

  \param points the point set; its point and normal maps are used
  \param np the named parameters of `compute_optimal_sigmoid_neighborhoods()` but the maps
  \return the number of failures (points whose every triple is degenerate)
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`; the preconditions of the range overload
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t compute_optimal_sigmoid_neighborhoods(CGAL::Point_set_3<Point, Vector>& points,
                                                  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "compute_optimal_sigmoid_neighborhoods");
  std::vector<Optimal_sigmoid_neighborhood> records;
  records.reserve(points.size());
  compute_optimal_sigmoid_neighborhoods<ConcurrencyTag>(internal::point_set_indices(points), std::back_inserter(records),
                                                        internal::with_point_set_maps(points, np));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto a = internal::point_set_property<double>(points, "a", nan);
  auto b = internal::point_set_property<double>(points, "b", nan);
  auto k = internal::point_set_property<int>(points, "k", 0);
  auto error_equal = internal::point_set_property<double>(points, "error_equal", nan);
  auto k_equal = internal::point_set_property<int>(points, "k_equal", 0);
  std::vector<Dimensionality_features> features;
  features.reserve(records.size());
  std::size_t i = 0, failures = 0;
  for(const auto index : points)
  {
    const Optimal_sigmoid_neighborhood& r = records[i++];
    failures += r.is_failure();
    a[index] = r.a;
    b[index] = r.b;
    k[index] = int(r.k);
    error_equal[index] = r.error_equal;
    k_equal[index] = int(r.k_equal);
    features.push_back(r.features);
  }
  internal::write_features(points, features);
  return failures;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H
