// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The normal of one point from its neighbors: PCA and jet fitting, what estimate_normals() and the
// readers' estimation of missing normals compute.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NORMAL_FITTING_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NORMAL_FITTING_H

#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>

#include <CGAL/Monge_via_jet_fitting.h>

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

// Jet fitting divides by the square of the neighborhood's extent: below this it underflows to 0.
constexpr double SMALLEST_JET_EXTENT = 1e-150;
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

// Jet fitting on the point and its neighbors, nearest first, as CGAL's jet_estimate_normals() does.
template <typename PointVector>
Eigen::Vector3d jet_normal(const PointVector& points, std::uint32_t i, unsigned int degree, Normal_estimation_scratch& s)
{
  typedef CGAL::Monge_via_jet_fitting<Double_kernel> Monge_fitting;
  s.points.assign(1, points[i]);
  for(const Neighbor& n : s.neighbors)
    s.points.push_back(points[n.index]);
  if(!(s.neighbors.back().squared_distance >= SMALLEST_JET_EXTENT * SMALLEST_JET_EXTENT))
    throw std::invalid_argument("point " + std::to_string(i) + " and its " + std::to_string(s.neighbors.size()) +
                                " nearest points lie within 1e-150 of each other: no normal (jet)");
  Monge_fitting fitting;
  const Monge_fitting::Monge_form form = fitting(s.points.begin(), s.points.end(), degree, 1);
  const Double_kernel::Vector_3 n = form.normal_direction();
  const Eigen::Vector3d normal(n.x(), n.y(), n.z());
  if(!normal.allFinite() || !(normal.squaredNorm() > 0.))
    throw std::invalid_argument("point " + std::to_string(i) + ": the jet fitted to its " +
                                std::to_string(s.neighbors.size()) + " nearest points has no normal (jet)");
  return normal;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NORMAL_FITTING_H
