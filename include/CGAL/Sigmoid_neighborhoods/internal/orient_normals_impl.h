// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The spanning forest of orient_normals_by_spanning_forest() (see config.h): included by
// orient_normals.h, or compiled once in CGAL::Sigmoid_neighborhoods_core.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENT_NORMALS_IMPL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENT_NORMALS_IMPL_H

#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>

#include <boost/graph/detail/d_ary_heap.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Hoppe et al.'s graph is undirected (edge i-j when either point is among the k nearest of the
// other): the rows give the edges out of a point, and these reversed rows the edges into it.
inline Neighbor_lists reversed_neighbor_rows(const Neighbor_query& query, unsigned int k)
{
  const std::size_t n = query.size();
  Neighbor_lists reversed;
  reversed.offsets.assign(n + 1, 0);
  std::vector<Neighbor> found;
  for(std::size_t i = 0; i < n; ++i)
  {
    query.query(static_cast<std::uint32_t>(i), k, found);
    for(const Neighbor& x : found)
      ++reversed.offsets[std::size_t(x.index) + 1];
  }
  std::partial_sum(reversed.offsets.begin(), reversed.offsets.end(), reversed.offsets.begin());
  reversed.indices.resize(reversed.offsets[n]);
  std::vector<std::size_t> next(reversed.offsets.begin(), reversed.offsets.end() - 1);
  for(std::size_t i = 0; i < n; ++i)
  {
    query.query(static_cast<std::uint32_t>(i), k, found);
    for(const Neighbor& x : found)
      reversed.indices[next[x.index]++] = static_cast<std::uint32_t>(i);
  }
  return reversed;
}

// The points by decreasing height, ties by index: the seeds of the components in turn, the first
// point of each the highest (the first of the highest, as CGAL's mst_orient_normals() takes it).
inline std::vector<std::uint32_t> points_from_the_top(const std::vector<Double_point>& points)
{
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), std::uint32_t(0));
  std::sort(order.begin(), order.end(), [&points](std::uint32_t i, std::uint32_t j) {
    return points[i].z() > points[j].z() || (points[i].z() == points[j].z() && i < j);
  });
  return order;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::size_t orient_along_spanning_forest(const std::vector<Double_point>& points,
                                                                            const Neighbor_query& query, unsigned int k,
                                                                            std::vector<Eigen::Vector3d>& normals)
{
  const std::size_t n = points.size();
  const Neighbor_lists reversed = reversed_neighbor_rows(query, k);
  constexpr std::uint32_t NO_PARENT = std::uint32_t(-1);
  std::vector<double> key(n, 2.); // above every weight
  std::vector<std::uint32_t> parent(n, NO_PARENT);
  std::vector<std::size_t> index_in_heap(n, std::size_t(-1));
  std::vector<bool> done(n, false);
  typedef boost::d_ary_heap_indirect<std::uint32_t, 4, std::size_t*, double*, std::less<double>> Heap;
  Heap heap(key.data(), index_in_heap.data());
  std::vector<Neighbor> found;

  std::size_t trees = 0;
  for(std::uint32_t seed : points_from_the_top(points))
  {
    if(done[seed])
      continue;
    ++trees;
    key[seed] = 0.;
    heap.push(seed);
    while(!heap.empty())
    {
      const std::uint32_t u = heap.top();
      heap.pop();
      done[u] = true;
      Eigen::Vector3d& nu = normals[u];
      if(parent[u] == NO_PARENT ? nu.z() < 0. : nu.dot(normals[parent[u]]) < 0.)
        nu = -nu;
      auto relax = [&](std::uint32_t v) {
        if(done[v])
          return;
        const double weight = (std::max)(0., 1. - std::abs(nu.dot(normals[v])));
        if(weight < key[v])
        {
          key[v] = weight;
          parent[v] = u;
          heap.push_or_update(v);
        }
      };
      query.query(u, k, found);
      for(const Neighbor& x : found)
        relax(x.index);
      for(const std::uint32_t* v = reversed.begin(u); v != reversed.end(u); ++v)
        relax(*v);
    }
  }
  return trees;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENT_NORMALS_IMPL_H
