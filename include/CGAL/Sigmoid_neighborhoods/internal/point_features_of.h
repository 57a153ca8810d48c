// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_FEATURES_OF_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_FEATURES_OF_H

#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>

#include <cmath>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The features of N_i(k) with the weights w (of `sigmoid`) on `local`, the neighborhood of point i;
// `known`, when given, holds its dimensionality features already (the search's record at its optimum).
inline Point_features point_features_of(const Local_neighborhood& local, const double* w, unsigned int k,
                                        Barycenter barycenter, const Cosine_sigmoid& sigmoid, double normal_z,
                                        const Dimensionality_features* known = nullptr)
{
  const Weighted_covariance covariance = local.covariance(w, k, barycenter);
  Point_features f;
  f.dimensionality = known != nullptr ? *known : dimensionality_features(covariance);
  complete_point_features(covariance, f);
  f.normal_z = normal_z;
  f.k = k;
  f.a = sigmoid.a();
  f.b = sigmoid.b();
  f.radius = std::sqrt(local.squared_radius(k));
  return f;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_FEATURES_OF_H
