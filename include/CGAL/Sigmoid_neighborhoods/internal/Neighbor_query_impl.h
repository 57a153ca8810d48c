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

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION Neighbor_query::Neighbor_query(const std::vector<Double_point>& points)
  : m_points(points), m_map{&points}, m_traits(m_map),
    m_tree(boost::counting_iterator<std::uint32_t>(0),
           boost::counting_iterator<std::uint32_t>(std::uint32_t(points.size())), Splitter(), m_traits)
{
  // before any parallel query: queries on a built tree are read-only (CGAL's build() needs a point)
  if(!points.empty())
    m_tree.build();
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Neighbor_query::query(std::uint32_t i, unsigned int k, std::vector<Neighbor>& result) const
{
  if(m_given)
  {
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
    return;
  }
  const std::size_t n = m_points.size();
  const std::size_t wanted = (std::min)(std::size_t(k), n - 1);
  // One more than needed (k others + i itself + 1) tells whether a tie crosses the boundary.
  std::size_t asked = (std::min)(wanted + 2, n);
  for(;;)
  {
    result.clear();
    // unsorted: the one sort is ours, with the tie rule
    Search search(m_tree, m_points[i], static_cast<unsigned int>(asked), 0., true, Distance(m_map), false);
    for(const auto& found : search)
      result.push_back(Neighbor{found.first, found.second});
    sort_by_nearness(result);
    const double farthest = result.empty() ? 0. : result.back().squared_distance;
    result.erase(std::remove_if(result.begin(), result.end(),
                                [i](const Neighbor& x) { return x.index == i; }),
                 result.end());
    // Every point closer than the farthest returned one is in `result`. The selection is
    // exact unless points at the k-th distance may remain outside: then ask for more.
    if(wanted == 0 || asked >= n || result.size() < wanted ||
       result[wanted - 1].squared_distance < farthest)
      break;
    asked = (std::min)(2 * asked, n);
  }
  result.resize((std::min)(result.size(), wanted));
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Neighbor_query::query_ball(std::uint32_t i, double radius, std::vector<Neighbor>& result) const
{
  CGAL_precondition(!m_given);
  result.clear();
  const Sphere sphere(i, radius * (1. + BALL_SEARCH_MARGIN), 0., m_traits);
  m_tree.search(boost::make_function_output_iterator(Ball_collector{&m_points, i, radius * radius, &result}), sphere);
  sort_by_nearness(result);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_IMPL_H
