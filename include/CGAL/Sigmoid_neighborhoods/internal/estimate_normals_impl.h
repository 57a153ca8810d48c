// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The kernel of estimate_normals() (see config.h): included by estimate_normals.h, or compiled once
// in CGAL::Sigmoid_neighborhoods_core.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ESTIMATE_NORMALS_IMPL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ESTIMATE_NORMALS_IMPL_H

#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/internal/normal_fitting.h>

#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::vector<Eigen::Vector3d>
estimate_normals_all(const Neighbor_query& query, unsigned int k, Normal_estimation_method method, unsigned int degree,
                     unsigned int threads)
{
  const std::vector<Double_point>& points = query.points();
  std::vector<Eigen::Vector3d> normals(points.size());
  for_each_index<Parallel_if_available_tag>(
    points.size(), threads, [] { return Normal_estimation_scratch(); },
    [&](std::size_t i, Normal_estimation_scratch& s) {
      query.query(static_cast<std::uint32_t>(i), k, s.neighbors);
      normals[i] = method == Normal_estimation_method::PCA ? pca_normal(points, static_cast<std::uint32_t>(i), s)
                                                           : jet_normal(points, static_cast<std::uint32_t>(i), degree, s);
    });
  return normals;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ESTIMATE_NORMALS_IMPL_H
