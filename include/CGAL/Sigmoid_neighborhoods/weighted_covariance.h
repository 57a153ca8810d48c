// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_WEIGHTED_COVARIANCE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_WEIGHTED_COVARIANCE_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {
// the relative threshold of the degenerate test of `Weighted_covariance::is_degenerate()` (SPEC §4)
constexpr double DEGENERATE_TRACE_THRESHOLD = 1e-12;
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the weighted covariance `C_i = sum_j w_ij (p_j - c_i)(p_j - c_i)^T` of one neighborhood,
  in coordinates centred at its first point `p_i`, with what the degenerate test needs.
  Returned by `weighted_covariance()`; `dimensionality_features()` gives its features.
*/
struct Weighted_covariance
{
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Zero(); ///< lower triangle and diagonal are set
  double weight_sum = 0.;                           ///< `sum_j w_ij`
  double squared_radius = 0.;                       ///< largest `|p_j - p_i|^2` over the neighborhood

  /// the trace of `matrix`, the sum of its eigenvalues.
  double trace() const { return matrix(0, 0) + matrix(1, 1) + matrix(2, 2); }

  /// `sum w = 0` or `trace(C) <= 1e-12 sum_j w_ij r_i^2` (SPEC §4): the matrix vanishes.
  bool is_degenerate() const
  {
    return !(weight_sum > 0.) ||
           trace() <= internal::DEGENERATE_TRACE_THRESHOLD * weight_sum * squared_radius;
  }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The one place where the covariance is summed: every path of the package goes through it,
// in neighbor order, so equal inputs give equal bits. Zero weights are skipped, which does not
// change a single bit of the sums (x + 0 * y == x for finite y).
inline void accumulate_covariance(const Eigen::Vector3d* offsets, const double* weights, std::size_t size,
                                  Barycenter barycenter, Weighted_covariance& result)
{
  double weight_sum = 0.;
  Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
  for(std::size_t j = 0; j < size; ++j)
  {
    if(weights[j] == 0.)
      continue;
    weight_sum += weights[j];
    weighted_sum += weights[j] * offsets[j];
  }
  result.weight_sum = weight_sum;
  result.matrix.setZero();
  if(!(weight_sum > 0.))
    return;

  Eigen::Vector3d center;
  if(barycenter == Barycenter::WEIGHTED)
    center = weighted_sum / weight_sum;
  else
  {
    center = Eigen::Vector3d::Zero();
    for(std::size_t j = 0; j < size; ++j)
      center += offsets[j];
    center /= double(size);
  }

  double c00 = 0., c10 = 0., c20 = 0., c11 = 0., c21 = 0., c22 = 0.;
  for(std::size_t j = 0; j < size; ++j)
  {
    const double w = weights[j];
    if(w == 0.)
      continue;
    const double dx = offsets[j][0] - center[0];
    const double dy = offsets[j][1] - center[1];
    const double dz = offsets[j][2] - center[2];
    c00 += w * dx * dx;
    c10 += w * dy * dx;
    c20 += w * dz * dx;
    c11 += w * dy * dy;
    c21 += w * dz * dy;
    c22 += w * dz * dz;
  }
  result.matrix(0, 0) = c00;
  result.matrix(1, 0) = c10;
  result.matrix(2, 0) = c20;
  result.matrix(1, 1) = c11;
  result.matrix(2, 1) = c21;
  result.matrix(2, 2) = c22;
  result.matrix(0, 1) = c10;
  result.matrix(0, 2) = c20;
  result.matrix(1, 2) = c21;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the weighted covariance of a neighborhood given as points and weights;
  the first point is the centre `p_i` of the neighborhood.

  \tparam PointRange a range of `Point_3` of a CGAL kernel (coordinates are converted to `double`)
  \tparam WeightRange a range of `double`, as long as `points`
  \param points the neighborhood, its centre `p_i` first
  \param weights the weight `w_ij` of each point, in the order of `points` (1 for `p_i` in the paper)
  \param barycenter the centre `c_i`: `Barycenter::WEIGHTED` or `Barycenter::UNWEIGHTED`
  \pre `points` is not empty and has as many elements as `weights`; otherwise `std::invalid_argument`
  \sa `Cosine_sigmoid`, which gives the weights
*/
template <typename PointRange, typename WeightRange>
Weighted_covariance weighted_covariance(const PointRange& points, const WeightRange& weights,
                                        Barycenter barycenter = Barycenter::WEIGHTED)
{
  std::vector<Eigen::Vector3d> offsets;
  std::vector<double> w(std::begin(weights), std::end(weights));
  for(const auto& p : points)
    offsets.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  if(offsets.empty() || offsets.size() != w.size())
    throw std::invalid_argument("weighted_covariance(): needs as many weights as points, and at least one");
  Weighted_covariance result;
  const Eigen::Vector3d origin = offsets.front();
  for(Eigen::Vector3d& q : offsets)
  {
    q -= origin;
    result.squared_radius = (std::max)(result.squared_radius, q.squaredNorm());
  }
  internal::accumulate_covariance(offsets.data(), w.data(), offsets.size(), barycenter, result);
  return result;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the features of a weighted covariance: a degenerate record when `covariance.is_degenerate()`,
  otherwise `dimensionality_features(covariance.matrix)`.
  \param covariance the result of `weighted_covariance()`
*/
inline Dimensionality_features dimensionality_features(const Weighted_covariance& covariance)
{
  if(covariance.is_degenerate())
    return Dimensionality_features();
  return dimensionality_features(covariance.matrix);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_WEIGHTED_COVARIANCE_H
