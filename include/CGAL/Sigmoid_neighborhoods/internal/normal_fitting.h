// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The normal of one point from its neighbors: PCA (pca_normal.h) and jet fitting, what
// estimate_normals() and the readers' estimation of missing normals compute.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NORMAL_FITTING_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NORMAL_FITTING_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/pca_normal.h>

#include <CGAL/Monge_via_jet_fitting.h>

#include <Eigen/Core>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Jet fitting divides by the square of the neighborhood's extent: below this it underflows to 0.
constexpr double SMALLEST_JET_EXTENT = 1e-150;

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
