// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_H

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

typedef CGAL::Simple_cartesian<double> Double_kernel;
typedef Double_kernel::Point_3 Double_point;

// no point: not an index of the set
constexpr std::uint32_t NO_POINT = (std::numeric_limits<std::uint32_t>::max)();

struct Neighbor
{
  std::uint32_t index;
  double squared_distance;
};

// The order of neighborhoods (SPEC §2): by squared distance, ties by index, so that they do not
// depend on the tree's traversal.
inline bool is_nearer(const Neighbor& x, const Neighbor& y)
{
  return x.squared_distance < y.squared_distance || (x.squared_distance == y.squared_distance && x.index < y.index);
}

// Sorts by is_nearer(). Up to 64 neighbors (a k-NN result or a ball, unordered) are placed by
// rank, each neighbor's rank the number of neighbors nearer than it: comparisons without branches,
// where std::sort's mispredicted ones took a quarter of the query's time on a scan. Indices are
// distinct, so the ranks are a permutation.
inline void sort_by_nearness(std::vector<Neighbor>& neighbors)
{
  constexpr std::size_t RANKED = 64;
  const std::size_t m = neighbors.size();
  if(m > RANKED)
  {
    std::sort(neighbors.begin(), neighbors.end(), [](const Neighbor& x, const Neighbor& y) { return is_nearer(x, y); });
    return;
  }
  double distance[RANKED];
  std::uint32_t index[RANKED];
  Neighbor sorted[RANKED];
  for(std::size_t e = 0; e < m; ++e)
  {
    distance[e] = neighbors[e].squared_distance;
    index[e] = neighbors[e].index;
  }
  for(std::size_t e = 0; e < m; ++e)
  {
    std::size_t rank = 0;
    for(std::size_t f = 0; f < m; ++f)
      rank += std::size_t((distance[f] < distance[e]) | ((distance[f] == distance[e]) & (index[f] < index[e])));
    sorted[rank] = neighbors[e];
  }
  std::copy(sorted, sorted + m, neighbors.begin());
}

// The squared distance between two points as every query computes it: (dx^2 + dy^2) + dz^2 of the
// coordinates' differences, as CGAL's Euclidean_distance and Fuzzy_sphere compute it, so that
// results do not depend on the search structure.
inline double squared_distance_between(const Double_point& p, const Double_point& q)
{
  const double dx = p.x() - q.x(), dy = p.y() - q.y(), dz = p.z() - q.z();
  return dx * dx + dy * dy + dz * dz;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_H
