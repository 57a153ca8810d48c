// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  one feature of `Point_features`, in the order of `Point_features::value()`: the eigenvalue
  features of Weinmann et al. (2015, their Table 1) of the weighted covariance, the point's normal,
  and the neighborhood's own descriptors.
*/
enum class Point_feature
{
  LINEARITY,           ///< `(lambda1 - lambda2) / lambda1`
  PLANARITY,           ///< `(lambda2 - lambda3) / lambda1`
  SCATTERING,          ///< `lambda3 / lambda1`
  OMNIVARIANCE,        ///< `(e1 e2 e3)^(1/3)`, `e_i = lambda_i / (lambda1 + lambda2 + lambda3)`
  ANISOTROPY,          ///< `(lambda1 - lambda3) / lambda1`
  EIGENENTROPY,        ///< `-sum e_i ln e_i`
  SUM_OF_EIGENVALUES,  ///< `(lambda1 + lambda2 + lambda3) / sum_j w_ij`: the weighted mean squared distance to the barycenter
  CHANGE_OF_CURVATURE, ///< `e3 = lambda3 / (lambda1 + lambda2 + lambda3)`
  VERTICALITY,         ///< `1 - |v3 . z|`, `v3` the eigenvector of `lambda3`: 0 on a horizontal plane, 1 on a wall
  NORMAL_Z,            ///< the `z` of the point's unit normal (as given: orient towards `+z` for airborne scans)
  DIMENSIONALITY_ERROR,///< `E_dim`, the entropy of linearity, planarity and scattering
  NEIGHBORHOOD_SIZE,   ///< `k`
  SIGMOID_A,           ///< `a` of the weights, radians
  SIGMOID_B,           ///< `b` of the weights, radians
  RADIUS               ///< the distance from the point to its `k`-th nearest neighbor
};

/// \cond SKIP_IN_MANUAL
namespace internal {
constexpr std::size_t NUMBER_OF_POINT_FEATURES = std::size_t(Point_feature::RADIUS) + 1;
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the name of a feature in files and in a `CGAL::Classification::Feature_set`: `linearity`,
  `planarity`, `scattering`, `omnivariance`, `anisotropy`, `eigenentropy`, `sum_of_eigenvalues`,
  `change_of_curvature`, `verticality`, `normal_z`, `error`, `k`, `a`, `b`, `radius`.
*/
inline const char* point_feature_name(Point_feature f)
{
  static const char* const names[internal::NUMBER_OF_POINT_FEATURES] = {
    "linearity",   "planarity", "scattering", "omnivariance", "anisotropy", "eigenentropy", "sum_of_eigenvalues",
    "change_of_curvature", "verticality", "normal_z", "error", "k", "a", "b", "radius"};
  return names[std::size_t(f)];
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the features a classifier takes from one weighted neighborhood `N_i(k)` with the weights
  `sig_{a,b}`: the eigenvalue features of its weighted covariance, the point's normal, and the
  neighborhood itself (`k`, `a`, `b`, its radius). Written by `compute_point_features()` and
  `compute_optimal_point_features()`.

  A degenerate neighborhood (`dimensionality.is_degenerate()`) has every eigenvalue feature 0 and
  both entropies `+inf`, as `Dimensionality_features` has.
*/
struct Point_features
{
  /// eigenvalues, linearity, planarity, scattering, `E_dim`, eigenentropy and label, bit for bit
  /// those of `dimensionality_features()` on the same covariance
  Dimensionality_features dimensionality;
  double omnivariance = 0.;        ///< `(e1 e2 e3)^(1/3)`
  double anisotropy = 0.;          ///< `(lambda1 - lambda3) / lambda1`
  double sum_of_eigenvalues = 0.;  ///< `(lambda1 + lambda2 + lambda3) / sum_j w_ij`
  double change_of_curvature = 0.; ///< `lambda3 / (lambda1 + lambda2 + lambda3)`
  double verticality = 0.;         ///< `1 - |v3 . z|`
  double normal_z = 0.;            ///< the `z` of the point's unit normal
  unsigned int k = 0;              ///< the neighborhood size
  double a = std::numeric_limits<double>::quiet_NaN(); ///< of the weights, radians (NaN: none, a failure)
  double b = std::numeric_limits<double>::quiet_NaN(); ///< of the weights, radians
  double radius = 0.;              ///< distance to the `k`-th nearest neighbor

  /// the value of `f`
  double value(Point_feature f) const
  {
    switch(f)
    {
      case Point_feature::LINEARITY: return dimensionality.linearity;
      case Point_feature::PLANARITY: return dimensionality.planarity;
      case Point_feature::SCATTERING: return dimensionality.scattering;
      case Point_feature::OMNIVARIANCE: return omnivariance;
      case Point_feature::ANISOTROPY: return anisotropy;
      case Point_feature::EIGENENTROPY: return dimensionality.eigenentropy;
      case Point_feature::SUM_OF_EIGENVALUES: return sum_of_eigenvalues;
      case Point_feature::CHANGE_OF_CURVATURE: return change_of_curvature;
      case Point_feature::VERTICALITY: return verticality;
      case Point_feature::NORMAL_Z: return normal_z;
      case Point_feature::DIMENSIONALITY_ERROR: return dimensionality.error;
      case Point_feature::NEIGHBORHOOD_SIZE: return double(k);
      case Point_feature::SIGMOID_A: return a;
      case Point_feature::SIGMOID_B: return b;
      default: return radius;
    }
  }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The features of `covariance` beyond its eigenvalues, from `f.dimensionality`'s eigenvalues (of the
// same matrix). The eigenvector of the least eigenvalue comes from Eigen's closed form
// (computeDirect()): ample for the verticality, and a small part of the cost of the optimal search.
inline void complete_point_features(const Weighted_covariance& covariance, Point_features& f)
{
  if(f.dimensionality.is_degenerate())
    return;
  const auto& ev = f.dimensionality.eigenvalues;
  const double sum = ev[0] + ev[1] + ev[2];
  f.omnivariance = std::cbrt((ev[0] / sum) * (ev[1] / sum) * (ev[2] / sum));
  f.anisotropy = (ev[0] - ev[2]) / ev[0];
  f.sum_of_eigenvalues = sum / covariance.weight_sum;
  f.change_of_curvature = ev[2] / sum;
  // scaled by the trace first: the closed form then neither overflows nor underflows
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance.matrix / covariance.trace(), Eigen::ComputeEigenvectors);
  f.verticality = 1. - (std::min)(std::abs(solver.eigenvectors()(2, 0)), 1.); // column 0: the least eigenvalue
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the features of one weighted covariance (the eigenvalue features and the verticality; `normal_z`,
  `k`, `a`, `b` and `radius` are left to the caller).
  The eigenvalues come from `dimensionality_features()`, so that they are bit for bit those of the
  search and of `compute_sigmoid_features()`; the eigenvector of the least one, for the verticality,
  from Eigen's closed-form solver on the matrix scaled by its trace.
*/
inline Point_features point_features(const Weighted_covariance& covariance)
{
  Point_features f;
  f.dimensionality = dimensionality_features(covariance);
  internal::complete_point_features(covariance, f);
  return f;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_FEATURES_H
