// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_COMPUTE_SIGMOID_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_COMPUTE_SIGMOID_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/compute_sigmoid_features.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Point_set_3_maps.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_3.h>

#include <iterator>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `compute_sigmoid_features()` on a `CGAL::Point_set_3` with normals, the features written
  to its properties `scalar_linearity`, `scalar_planarity`, `scalar_scattering`, `scalar_error`
  (`double`; NaN for a degenerate neighborhood but the error, infinite) and `scalar_label`
  (`std::uint8_t`): the names of the optimal search's, whose values they replace.

  \param points the point set; its point and normal maps are used
  \param sigmoid the weights
  \param k the neighborhood size
  \param np the named parameters of `compute_sigmoid_features()` but the maps
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`; the preconditions of the range overload
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
void compute_sigmoid_features(CGAL::Point_set_3<Point, Vector>& points, const Cosine_sigmoid& sigmoid, unsigned int k,
                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "compute_sigmoid_features");
  std::vector<Dimensionality_features> features;
  features.reserve(points.size());
  compute_sigmoid_features<ConcurrencyTag>(internal::point_set_indices(points), sigmoid, k, std::back_inserter(features),
                                           internal::with_point_set_maps(points, np));
  internal::write_features(points, features);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_COMPUTE_SIGMOID_FEATURES_H
