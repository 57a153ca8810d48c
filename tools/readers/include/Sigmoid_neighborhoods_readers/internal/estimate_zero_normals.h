// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_ZERO_NORMALS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_ZERO_NORMALS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/internal/pca_normal.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The zero normals of a point set whose other normals come from its file (SPEC §1): each estimated
// by PCA on its `o.neighbors` nearest points, exactly as estimate_normals() would, and given the
// sign that agrees with its neighbors' normals (the sum of the dot products is not negative).
// Neighbors with a zero normal of their own do not vote until they have a sign: the points are
// taken in index order, again and again while one of them gains a sign; a point none of whose
// neighbors ever has one keeps the sign of the estimation. Sets `out.zero_normals`.
inline void estimate_zero_normals(Oriented_point_set& out, const Normal_options& o)
{
  const std::size_t n = out.points.size();
  std::vector<std::uint32_t> zero;
  for(std::size_t i = 0; i < n; ++i)
    if(out.normals[i] == CGAL::NULL_VECTOR)
      zero.push_back(std::uint32_t(i));
  out.zero_normals = zero.size();
  if(zero.empty())
    return;
  const unsigned int fewest = fewest_estimation_neighbors(Normal_estimation_method::PCA);
  if(n < std::size_t(fewest) + 1)
    throw Input_error("point " + std::to_string(zero.front()) + " has a zero normal, and too few distinct points (" +
                      std::to_string(n) + ") to estimate it");
  const unsigned int k = unsigned((std::min)(std::size_t(o.neighbors), n - 1));
  const std::vector<Double_point> copy =
    checked_points(out.points, CGAL::Identity_property_map<Oriented_point_set::Point_3>());
  const Neighbor_query query(copy);
  std::vector<std::vector<Neighbor>> neighbors(zero.size());
  std::vector<Eigen::Vector3d> estimated(zero.size());
  Normal_estimation_scratch s;
  try
  {
    for(std::size_t z = 0; z < zero.size(); ++z)
    {
      query.query(zero[z], k, s.neighbors);
      estimated[z] = pca_normal(copy, zero[z], s);
      neighbors[z] = s.neighbors;
    }
  }
  catch(const std::invalid_argument& e)
  {
    // a zero normal among coincident or collinear points: as a file without normals would fail
    throw Input_error(std::string(e.what()) + ", for its zero normal");
  }

  std::vector<bool> has_sign(n, true);
  for(std::uint32_t i : zero)
    has_sign[i] = false;
  std::vector<std::size_t> left(zero.size());
  for(std::size_t z = 0; z < zero.size(); ++z)
    left[z] = z;
  while(!left.empty())
  {
    std::vector<std::size_t> next;
    for(std::size_t z : left)
    {
      const Eigen::Vector3d& e = estimated[z];
      double agreement = 0.;
      bool voted = false;
      for(const Neighbor& nb : neighbors[z])
        if(has_sign[nb.index])
        {
          const Oriented_point_set::Vector_3& m = out.normals[nb.index];
          agreement += e.x() * m.x() + e.y() * m.y() + e.z() * m.z();
          voted = true;
        }
      if(!voted)
      {
        next.push_back(z);
        continue;
      }
      const double sign = agreement < 0. ? -1. : 1.;
      out.normals[zero[z]] = Oriented_point_set::Vector_3(sign * e.x(), sign * e.y(), sign * e.z());
      has_sign[zero[z]] = true;
    }
    if(next.size() == left.size())
    {
      for(std::size_t z : next)
        out.normals[zero[z]] = Oriented_point_set::Vector_3(estimated[z].x(), estimated[z].y(), estimated[z].z());
      break;
    }
    left.swap(next);
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_ZERO_NORMALS_H
