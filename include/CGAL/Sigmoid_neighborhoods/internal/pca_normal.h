// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The PCA normal of one point from its neighbors (normal_fitting.h adds jet fitting). Apart, so that
// the readers' estimation of zero normals, which takes PCA only, does not parse CGAL's jet fitting
// (Monge_via_jet_fitting.h and Eigen's SVD: seconds of every such translation unit).

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PCA_NORMAL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PCA_NORMAL_H

#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A neighborhood whose middle eigenvalue is at most this share of the trace is a line (or a point):
// its normal is undefined. The degenerate test of the covariance (SPEC §4) uses the same share.
constexpr double FLAT_NEIGHBORHOOD_THRESHOLD = DEGENERATE_TRACE_THRESHOLD;

struct Normal_estimation_scratch
{
  std::vector<Neighbor> neighbors;
  std::vector<Eigen::Vector3d> offsets;
  std::vector<double> weights;
  std::vector<Double_point> points;
};

// PCA on the point and its neighbors: offsets from the point (as the features take them), scaled
// by a power of 2 (exactly) to a largest length in [1, 2) so that no square underflows or
// overflows, the two-pass covariance about their centroid, Eigen's iterative solver (SPEC §4).
// A template (as jet_normal()), so that only a translation unit that estimates normals compiles
// the solver: as an inline function, every one that included this header did.
template <typename PointVector>
Eigen::Vector3d pca_normal(const PointVector& points, std::uint32_t i, Normal_estimation_scratch& s)
{
  const Double_point& p = points[i];
  s.offsets.assign(1, Eigen::Vector3d::Zero());
  double largest = 0.;
  for(const Neighbor& n : s.neighbors)
  {
    const Double_point& q = points[n.index];
    s.offsets.emplace_back(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
    largest = (std::max)(largest, s.offsets.back().lpNorm<Eigen::Infinity>());
  }
  if(!(largest > 0.))
    throw std::invalid_argument("point " + std::to_string(i) + " and its " + std::to_string(s.neighbors.size()) +
                                " nearest points coincide: no normal (pca)");
  const double scale = std::ldexp(1., -std::ilogb(largest));
  for(Eigen::Vector3d& offset : s.offsets)
    offset *= scale;
  s.weights.assign(s.offsets.size(), 1.);
  Weighted_covariance covariance;
  accumulate_covariance(s.offsets.data(), s.weights.data(), s.offsets.size(), Barycenter::UNWEIGHTED, covariance);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance.matrix, Eigen::ComputeEigenvectors);
  const double trace = covariance.matrix.trace();
  if(!(solver.eigenvalues()[1] > FLAT_NEIGHBORHOOD_THRESHOLD * trace))
    throw std::invalid_argument("point " + std::to_string(i) + " and its " + std::to_string(s.neighbors.size()) +
                                " nearest points lie on a line: no normal (pca)");
  return solver.eigenvectors().col(0);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PCA_NORMAL_H
