// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The kd-tree's construction and queries (see config.h): included by Neighbor_query.h, or compiled
// once in CGAL::Sigmoid_neighborhoods_core.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_IMPL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_IMPL_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Kd_tree_search.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Point_kd_tree_impl.h>

#include <CGAL/assertions.h>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION Neighbor_query::Neighbor_query(const std::vector<Double_point>& points,
                                                                   unsigned int threads, Neighbor_search structure)
  : m_points(points)
{
  if(structure == Neighbor_search::PACKAGE_KD_TREE)
    m_package_tree = std::make_unique<const Point_kd_tree>(points, threads);
  else
  {
    m_search = std::make_unique<const Index_kd_tree_search>(points, threads);
    m_leaf_order = m_search->leaf_order();
  }
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Neighbor_query::query(std::uint32_t i, unsigned int k, std::vector<Neighbor>& result,
                                                                double squared_bound) const
{
  if(m_package_tree)
  {
    m_package_tree->nearest(i, k, result, squared_bound);
    return;
  }
  if(!m_given)
  {
    nearest_by_tie_rule(*m_search, m_points, m_points[i], i, k, result);
    return;
  }
  // the first k entries of the row, in the caller's order
  result.clear();
  const Double_point& p = m_points[i];
  const std::size_t end = (std::min)(m_offsets[i] + k, m_offsets[i + 1]);
  for(std::size_t e = m_offsets[i]; e < end; ++e)
  {
    const std::uint32_t j = m_indices[e];
    const Double_point& q = m_points[j];
    const double dx = q.x() - p.x(), dy = q.y() - p.y(), dz = q.z() - p.z();
    result.push_back(Neighbor{j, dx * dx + dy * dy + dz * dz});
  }
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION bool Neighbor_query::has_scattered_order() const
{
  const std::vector<std::uint32_t>& leaves = spatial_order();
  const std::size_t n = m_points.size();
  if(m_given || n < 2 || leaves.size() != n)
    return false;
  // medians of squared distances between consecutive points, at up to 4096 evenly spaced places
  const std::size_t samples = (std::min)(n - 1, std::size_t(4096)), step = (n - 1) / samples;
  std::vector<double> in_index_order, in_leaf_order;
  in_index_order.reserve(samples);
  in_leaf_order.reserve(samples);
  for(std::size_t s = 0, i = 0; s < samples; ++s, i += step)
  {
    in_index_order.push_back(squared_distance(std::uint32_t(i), std::uint32_t(i + 1)));
    in_leaf_order.push_back(squared_distance(leaves[i], leaves[i + 1]));
  }
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double index_gap = median(in_index_order), leaf_gap = median(in_leaf_order);
  return index_gap > SCATTERED_ORDER_RATIO * SCATTERED_ORDER_RATIO * leaf_gap;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Neighbor_query::query_ball(std::uint32_t i, double radius, std::vector<Neighbor>& result) const
{
  CGAL_precondition(!m_given);
  if(m_package_tree)
  {
    m_package_tree->ball(i, radius * radius, result);
    return;
  }
  const Double_point& p = m_points[i];
  m_search->ball(p, radius, result);
  for(std::size_t e = 0; e < result.size();)
  {
    if(result[e].index == i)
    {
      result[e] = result.back();
      result.pop_back();
      continue;
    }
    result[e].squared_distance = squared_distance_between(m_points[result[e].index], p);
    ++e;
  }
  sort_by_nearness(result);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Neighbor_query::query_position(const Double_point& q, unsigned int k,
                                                                        std::vector<Neighbor>& result) const
{
  CGAL_precondition(!m_given);
  if(m_package_tree)
    m_package_tree->nearest(q, k, result);
  else
    nearest_by_tie_rule(*m_search, m_points, q, NO_POINT, k, result);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_IMPL_H
