// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_LOCAL_NEIGHBORHOOD_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_LOCAL_NEIGHBORHOOD_H

#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/internal/K_neighbor_query.h>

#include <CGAL/number_utils.h>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The input as the computation sees it: double coordinates and unit normals.
struct Oriented_points
{
  std::vector<Double_point> points;
  std::vector<Eigen::Vector3d> normals;
  std::size_t size() const { return points.size(); }
};

// Copies a point range through its maps, rejecting what the paper's features are undefined for.
// Normals that are unit to 1e-12 are used as given (normalising again would move their last bit).
template <typename PointRange, typename PointMap, typename NormalMap>
Oriented_points copy_oriented_points(const PointRange& range, PointMap point_map, NormalMap normal_map)
{
  Oriented_points result;
  // reserved: growing by doubling would hold the old and the new buffer at once
  const auto size = std::distance(std::begin(range), std::end(range));
  result.points.reserve(std::size_t(size));
  result.normals.reserve(std::size_t(size));
  std::size_t i = 0;
  for(const auto& item : range)
  {
    const auto& p = get(point_map, item);
    const auto& n = get(normal_map, item);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    Eigen::Vector3d normal(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
    // Beyond this, squared distances overflow.
    if(std::abs(x) > 1e150 || std::abs(y) > 1e150 || std::abs(z) > 1e150)
      throw std::invalid_argument("point " + std::to_string(i) + " has a coordinate beyond 1e150");
    if(!normal.allFinite())
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite normal");
    const double squared_norm = normal.squaredNorm();
    if(!(squared_norm > 0.))
      throw std::invalid_argument("point " + std::to_string(i) + " has a zero normal");
    if(std::abs(squared_norm - 1.) > 1e-12)
      normal /= std::sqrt(squared_norm);
    result.points.emplace_back(x, y, z);
    result.normals.push_back(normal);
    ++i;
  }
  return result;
}

// The neighborhood N_i(k_max) of one point: offsets p_j - p_i, normal angles, and the running
// largest squared radius, from which every (a, b, k) with k <= k_max is evaluated.
class Local_neighborhood
{
public:
  void assign(const Oriented_points& input, std::uint32_t i, const std::vector<Neighbor>& neighbors)
  {
    const std::size_t m = neighbors.size() + 1;
    m_offsets.resize(m);
    m_angles.resize(m);
    m_squared_radius.resize(m);
    m_offsets[0].setZero();
    m_angles[0] = 0.;
    m_squared_radius[0] = 0.;
    m_largest_angle = 0.;
    const Double_point& p = input.points[i];
    const Eigen::Vector3d& n = input.normals[i];
    for(std::size_t j = 1; j < m; ++j)
    {
      const std::uint32_t index = neighbors[j - 1].index;
      const Double_point& q = input.points[index];
      m_offsets[j] = Eigen::Vector3d(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
      m_angles[j] = normal_angle(n, input.normals[index]);
      m_largest_angle = (std::max)(m_largest_angle, m_angles[j]);
      m_squared_radius[j] = (std::max)(m_squared_radius[j - 1], m_offsets[j].squaredNorm());
    }
    // Scaled by a power of 2 (exactly) to a largest radius in [1, 2): covariances at that scale
    // keep their cubes far from overflow and underflow.
    const double largest = m_squared_radius[m - 1];
    const double scale = largest > 0. ? std::ldexp(1., -std::ilogb(std::sqrt(largest))) : 1.;
    m_unit_scale = scale;
    m_unit_offsets.resize(m);
    m_unit_squared_radius.resize(m);
    for(std::size_t j = 0; j < m; ++j)
    {
      m_unit_offsets[j] = m_offsets[j] * scale;
      m_unit_squared_radius[j] = m_squared_radius[j] * (scale * scale);
    }
  }

  std::size_t size() const { return m_offsets.size(); }
  const Eigen::Vector3d& offset(std::size_t j) const { return m_offsets[j]; }
  double squared_radius(unsigned int k) const { return m_squared_radius[k]; }
  // the offsets and squared radii scaled so that the largest radius lies in [1, 2)
  const Eigen::Vector3d& unit_offset(std::size_t j) const { return m_unit_offsets[j]; }
  double unit_squared_radius(unsigned int k) const { return m_unit_squared_radius[k]; }
  double unit_scale() const { return m_unit_scale; } // unit offset / offset, a power of 2

  // w_ij for all j in N_i(k_max); w_ii = sig(0) = 1. Returns true when all weights are 1 because
  // every angle is below a (or within the tolerance): on smooth surfaces, most pairs of the grid.
  bool weights(const Cosine_sigmoid& sigmoid, double* w) const
  {
    const bool all_ones = transition_arguments(sigmoid, w);
    for(std::size_t j = 0; j < m_angles.size(); ++j)
      w[j] = Cosine_sigmoid::weight_of_argument(w[j]); // in place: sigmoid(angle j)
    return all_ones;
  }

  // Cosine_sigmoid::transition_argument() for all j in N_i(k_max): weights() short of the cosine;
  // returns true when all weights are 1, as weights() does.
  bool transition_arguments(const Cosine_sigmoid& sigmoid, double* t) const
  {
    if(m_largest_angle <= sigmoid.angle_tolerance() || m_largest_angle < sigmoid.a())
    {
      // what transition_argument(x) gives for every x <= m_largest_angle
      std::fill(t, t + m_angles.size(), Cosine_sigmoid::WEIGHT_ONE);
      return true;
    }
    for(std::size_t j = 0; j < m_angles.size(); ++j)
      t[j] = sigmoid.transition_argument(m_angles[j]);
    return false;
  }

  Weighted_covariance covariance(const double* w, unsigned int k, Barycenter barycenter) const
  {
    Weighted_covariance result;
    result.squared_radius = m_squared_radius[k];
    accumulate_covariance(m_offsets.data(), w, std::size_t(k) + 1, barycenter, result);
    return result;
  }

  Dimensionality_features features(const double* w, unsigned int k, Barycenter barycenter) const
  {
    return dimensionality_features(covariance(w, k, barycenter));
  }

private:
  std::vector<Eigen::Vector3d> m_offsets;
  std::vector<double> m_angles;
  std::vector<double> m_squared_radius;
  std::vector<Eigen::Vector3d> m_unit_offsets;
  std::vector<double> m_unit_squared_radius;
  double m_unit_scale = 1.;
  double m_largest_angle = 0.;
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_LOCAL_NEIGHBORHOOD_H
