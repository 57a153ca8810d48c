// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_H

#include <CGAL/Sigmoid_neighborhoods/config.h>

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Spatial_search.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Point_kd_tree.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The one neighbor structure of a point set, built once and queried by every step for k nearest
// neighbors and for balls, both ordered by is_nearer() (SPEC §2's tie rule applied to CGAL's
// searches): CGAL's kd-tree over the point indices, the caller's CGAL search tree over the same
// points, or the package's own kd-tree (Neighbor_search::PACKAGE_KD_TREE), all with the same results;
// or the neighborhoods the caller computed, in compressed rows, whose first k entries are N_i(k).
class Neighbor_query
{
public:
  // `points` must outlive the query. The tree is built on `threads` threads (kernel_threads()).
  explicit Neighbor_query(const std::vector<Double_point>& points, unsigned int threads = 1,
                          Neighbor_search structure = Neighbor_search::CGAL_KD_TREE);

  // The caller's search structure over the same points (caller_tree_search()), which must outlive the query.
  Neighbor_query(const std::vector<Double_point>& points, std::unique_ptr<const Spatial_search> search)
    : m_points(points), m_search(std::move(search)), m_leaf_order(m_search->leaf_order())
  {}

  // The caller's rows (checked by check_neighbor_rows()) instead of the tree: no tree is built.
  Neighbor_query(const std::vector<Double_point>& points, std::vector<std::size_t> offsets,
                 std::vector<std::uint32_t> indices)
    : m_points(points), m_own_offsets(std::move(offsets)),
      m_own_indices(std::move(indices)), m_offsets(m_own_offsets.data()), m_indices(m_own_indices.data()), m_given(true)
  {}

  // The same rows read where they are, without a copy: they must outlive the query.
  Neighbor_query(const std::vector<Double_point>& points, const std::size_t* offsets, const std::uint32_t* indices)
    : m_points(points), m_offsets(offsets),
      m_indices(indices), m_given(true)
  {}

  Neighbor_query(const Neighbor_query&) = delete;
  Neighbor_query& operator=(const Neighbor_query&) = delete;

  // true when the neighborhoods are the caller's rows
  bool is_given() const { return m_given; }

  // The first k entries of the caller's row of point `i`, without their distances (is_given() only).
  const std::uint32_t* given_row_begin(std::size_t i) const { return m_indices + m_offsets[i]; }
  const std::uint32_t* given_row_end(std::size_t i, unsigned int k) const
  {
    return m_indices + (std::min)(m_offsets[i] + k, m_offsets[i + 1]);
  }

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
  // ordered by is_nearer(). `squared_bound`: a hint for the package's tree, see
  // Point_kd_tree::nearest(). Thread-safe.
  void query(std::uint32_t i, unsigned int k, std::vector<Neighbor>& result,
             double squared_bound = (std::numeric_limits<double>::infinity)()) const;

  // The `k` nearest points to the position `q` (|result| = min(k, n)), ordered by is_nearer(); not
  // with given rows. Thread-safe.
  void query_position(const Double_point& q, unsigned int k, std::vector<Neighbor>& result) const;

  // The squared distance between points `i` and `j`, as query() computes it.
  double squared_distance(std::uint32_t i, std::uint32_t j) const
  {
    return squared_distance_between(m_points[j], m_points[i]);
  }

  // The points j != i with |p_j - p_i|^2 <= radius^2, ordered by is_nearer(). Thread-safe.
  void query_ball(std::uint32_t i, double radius, std::vector<Neighbor>& result) const;

  // The point indices in an order where consecutive points are near, for queries on every point:
  // the tree's leaf order, or 0, 1, ... with given rows (empty).
  const std::vector<std::uint32_t>& spatial_order() const
  {
    return m_package_tree ? m_package_tree->leaf_order() : m_leaf_order;
  }

  // Whether the points come in an order without locality (shuffled, or sorted along one axis
  // only), where a query per point in index order misses the cache at every neighbor: the median
  // distance between points consecutive in index order, over a sample, is more than
  // SCATTERED_ORDER_RATIO times the one in the tree's leaf order. Scans (acquisition order), LAS
  // files (GPS time) and meshes are local; false with given rows.
  bool has_scattered_order() const;
  static constexpr double SCATTERED_ORDER_RATIO = 16.;

  std::size_t size() const { return m_points.size(); }
  const std::vector<Double_point>& points() const { return m_points; }

private:
  const std::vector<Double_point>& m_points;
  std::unique_ptr<const Spatial_search> m_search;
  std::unique_ptr<const Point_kd_tree> m_package_tree; // instead of m_search
  std::vector<std::uint32_t> m_leaf_order;
  // given rows: owned (converted from the caller's types) or the caller's own
  std::vector<std::size_t> m_own_offsets;
  std::vector<std::uint32_t> m_own_indices;
  const std::size_t* m_offsets = nullptr;
  const std::uint32_t* m_indices = nullptr;
  bool m_given = false;
};

// The search structure of `np` (neighbor_search), CGAL's kd-tree by default.
template <typename NamedParameters>
Neighbor_search neighbor_search(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::neighbor_search),
                                            Neighbor_search::CGAL_KD_TREE);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_QUERY_H
