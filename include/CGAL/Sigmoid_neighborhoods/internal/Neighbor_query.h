// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_H

#include <CGAL/Sigmoid_neighborhoods/config.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Fuzzy_sphere.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

typedef CGAL::Simple_cartesian<double> Double_kernel;
typedef Double_kernel::Point_3 Double_point;

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

// Sorts by is_nearer(). A k-NN result (a few dozen neighbors, in the tree's heap order) is placed
// by rank, each neighbor's rank the number of neighbors nearer than it: comparisons without
// branches, where std::sort's mispredicted ones took a quarter of the query's time on a scan.
// Indices are distinct, so the ranks are a permutation.
inline void sort_by_nearness(std::vector<Neighbor>& neighbors)
{
  constexpr std::size_t RANKED = 64;
  const std::size_t m = neighbors.size();
  if(m > RANKED)
  {
    std::sort(neighbors.begin(), neighbors.end(), is_nearer);
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

// The point of an index, for CGAL's kd-trees over indices (Search_traits_adapter).
struct Index_to_point_map
{
  typedef std::uint32_t key_type;
  typedef Double_point value_type;
  typedef const Double_point& reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<Double_point>* points = nullptr;
  friend reference get(const Index_to_point_map& map, key_type i) { return (*map.points)[i]; }
};

// The one neighbor structure of a point set: CGAL's kd-tree over the point indices, built once and
// queried by every step for k nearest neighbors and for balls, both ordered by is_nearer(); or the
// neighborhoods the caller computed, in compressed rows, whose first k entries are N_i(k).
class Neighbor_query
{
  typedef CGAL::Search_traits_3<Double_kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<std::uint32_t, Index_to_point_map, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Base_search;
  typedef Base_search::Tree Tree;
  typedef Tree::Splitter Splitter;
  typedef Base_search::Distance Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> Search;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

  // Fuzzy_sphere decides points on its boundary differently on its two code paths (`<=` and `<`),
  // so the tree is asked for a ball larger by this relative margin and the decision taken exactly.
  static constexpr double BALL_SEARCH_MARGIN = 1e-9;

  // Keeps the points found within the exact radius (assignable, as the tree's output iterator must be).
  struct Ball_collector
  {
    const std::vector<Double_point>* points;
    std::uint32_t i;
    double squared_radius;
    std::vector<Neighbor>* result;
    void operator()(std::uint32_t j) const
    {
      if(j == i)
        return;
      const Double_point &p = (*points)[i], &q = (*points)[j];
      const double dx = q.x() - p.x(), dy = q.y() - p.y(), dz = q.z() - p.z();
      const double d2 = dx * dx + dy * dy + dz * dz;
      if(d2 <= squared_radius)
        result->push_back(Neighbor{j, d2});
    }
  };

public:
  // `points` must outlive the query.
  explicit Neighbor_query(const std::vector<Double_point>& points);

  // The caller's rows (checked by check_neighbor_rows()) instead of the tree: no tree is built.
  Neighbor_query(const std::vector<Double_point>& points, std::vector<std::size_t> offsets,
                 std::vector<std::uint32_t> indices)
    : m_points(points), m_map{&points}, m_traits(m_map), m_tree(Splitter(), m_traits), m_own_offsets(std::move(offsets)),
      m_own_indices(std::move(indices)), m_offsets(m_own_offsets.data()), m_indices(m_own_indices.data()), m_given(true)
  {}

  // The same rows read where they are, without a copy: they must outlive the query.
  Neighbor_query(const std::vector<Double_point>& points, const std::size_t* offsets, const std::uint32_t* indices)
    : m_points(points), m_map{&points}, m_traits(m_map), m_tree(Splitter(), m_traits), m_offsets(offsets),
      m_indices(indices), m_given(true)
  {}

  Neighbor_query(const Neighbor_query&) = delete;
  Neighbor_query& operator=(const Neighbor_query&) = delete;

  // true when the neighborhoods are the caller's rows
  bool is_given() const { return m_given; }

  // The fewest neighbors query() gives any point for a large k.
  std::size_t fewest_neighbors() const
  {
    if(!m_given)
      return m_points.empty() ? 0 : m_points.size() - 1;
    std::size_t result = m_points.empty() ? 0 : m_offsets[1] - m_offsets[0];
    for(std::size_t i = 1; i < m_points.size(); ++i)
      result = (std::min)(result, m_offsets[i + 1] - m_offsets[i]);
    return result;
  }

  // The `k` nearest points of point `i` other than `i` itself (|result| = min(k, n - 1)),
  // ordered by is_nearer(). Thread-safe.
  void query(std::uint32_t i, unsigned int k, std::vector<Neighbor>& result) const;

  // The points j != i with |p_j - p_i|^2 <= radius^2, ordered by is_nearer(). Thread-safe.
  void query_ball(std::uint32_t i, double radius, std::vector<Neighbor>& result) const;

  std::size_t size() const { return m_points.size(); }
  const std::vector<Double_point>& points() const { return m_points; }

private:
  const std::vector<Double_point>& m_points;
  Index_to_point_map m_map;
  Traits m_traits;
  Tree m_tree;
  // given rows: owned (converted from the caller's types) or the caller's own
  std::vector<std::size_t> m_own_offsets;
  std::vector<std::uint32_t> m_own_indices;
  const std::size_t* m_offsets = nullptr;
  const std::uint32_t* m_indices = nullptr;
  bool m_given = false;
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_H
