// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_H

#include <CGAL/Sigmoid_neighborhoods/config.h>

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A kd-tree over point indices for the package's exact queries: the k nearest other points and the
// balls of a point of the set, ordered by is_nearer(). Each node is split at the middle of its cell
// along the cell's widest side (nanoflann's sliding midpoint: cells stay near cubes, so a query
// compares fewer points than with median splits); deep in the tree the split is moved so that each
// side keeps a quarter of the node's points, which bounds the depth on any input. Leaves of at most
// LEAF_SIZE points. It holds the indices in leaf order and its nodes, 9 to 12 bytes per point on a
// scan, and reads the coordinates where they are (a copy in leaf order, 24 bytes more per point, was
// no faster on scans, whose points come in acquisition order). The k nearest are selected with the
// tie rule itself, so no query is repeated for ties. A node is skipped only when it is farther than
// the current k-th neighbor; its lower bound is the sum of the squared gaps per axis between the
// query and the node's slab (each child's slab ends at its extreme point along the split axis),
// computed as a point's squared distance is, from rounded differences that are monotone: it never
// exceeds the distance of a point inside. The squared distances are (dx^2 + dy^2) + dz^2 of the
// coordinates' differences, as CGAL's Euclidean_distance computes them, so results do not depend on
// the search structure.
class Point_kd_tree
{
public:
  // leaves of 8 to 32 points tried on a scan's 20 and 100 nearest: 24 the fastest (fewer nodes to
  // walk outweigh the more points compared, up to there)
  static constexpr std::uint32_t LEAF_SIZE = 24;
  // up to this many neighbors, a query keeps its candidates sorted; beyond, it selects them in bulk
  // (on a scan and an airborne tile, sorted insertion took 0.63-0.72 of the bulk selection's time
  // for 33 to 64 neighbors, 0.76-0.79 for 100, 0.88 for 150, as much for 200, 1.2 times for 300)
  static constexpr std::size_t SORTED_INSERTION_K = 128;

  Point_kd_tree() = default;
  // `points` must outlive the tree. Built on `threads` threads (kernel_threads()), the same tree.
  explicit Point_kd_tree(const std::vector<Double_point>& points, unsigned int threads = 1);

  // The min(k, n - 1) nearest points of point `i` other than `i` itself, ordered by is_nearer().
  // `squared_bound`, when given, is a squared distance within which the caller knows that many
  // points (e.g. from a nearby point's k-th neighbor): the search starts with it. A wrong bound costs
  // a second search, never a wrong result.
  void nearest(std::uint32_t i, std::size_t k, std::vector<Neighbor>& result,
               double squared_bound = (std::numeric_limits<double>::infinity)()) const;
  // The min(k, n) nearest points to the position `query` (in the set or not), ordered by is_nearer().
  void nearest(const Double_point& query, std::size_t k, std::vector<Neighbor>& result) const;


  // The points j != i with squared distance to point `i` at most `squared_radius`, ordered by
  // is_nearer().
  void ball(std::uint32_t i, double squared_radius, std::vector<Neighbor>& result) const;

  // The point indices in leaf order: neighbors in this order are near in memory and in space.
  const std::vector<std::uint32_t>& leaf_order() const { return m_index; }

private:
  // An inner node splits along `axis`: its left child (the next node) has its points at most at
  // `left_end`, its right child (node `begin`) at least at `right_begin`. A leaf (axis 3) holds the
  // positions [begin, end).
  struct Node
  {
    double left_end, right_begin;
    std::uint32_t begin, end; // for an inner node, begin is the right child
    std::uint32_t axis;
  };
  // The box a node splits (not the tight box of its points): its middle is the split's first choice.
  struct Cell
  {
    double low[3], high[3];
  };
  // A node of the top levels, split before the subtrees below them are built on the threads.
  struct Top
  {
    std::uint32_t begin, end;
    std::size_t depth;
    Cell cell;
    Node node;
    std::size_t children = 0; // the left child's position in the tops (the right one follows); 0: a subtree
  };
  // Splits at the cut down to FREE_DEPTH; below, each side keeps at least a quarter of the more than
  // LEAF_SIZE points split, so that fewer than 2^32 points need at most 69 levels more.
  static constexpr std::size_t FREE_DEPTH = 64;
  // the walk's stack holds at most one farther child per level of the path it follows
  static constexpr std::size_t MAX_DEPTH = FREE_DEPTH + 70;

  // Splits the positions [begin, end) in `cell`: false for a leaf; otherwise the node (its right
  // child to be set), its children's positions [begin, middle), [middle, end) and cells.
  bool split(std::uint32_t begin, std::uint32_t end, const Cell& cell, std::size_t depth, Node& node,
             std::uint32_t& middle, Cell& left, Cell& right);
  // Where build() appends a subtree's nodes: a slice of m_nodes with room for `room` of them, then,
  // past it, a vector of their own (spilled), with room for `spill_room` reserved.
  class Node_sink
  {
  public:
    Node_sink(Node* slice, std::size_t room, std::size_t spill_room = 0) : m_slice(slice), m_room(room)
    {
      m_spill.reserve(spill_room);
    }
    std::size_t size() const { return m_size; }
    Node& operator[](std::size_t id) { return m_spilled ? m_spill[id] : m_slice[id]; }
    std::size_t append()
    {
      if(m_size == m_room && !m_spilled)
      {
        m_spill.assign(m_slice, m_slice + m_size);
        m_spilled = true;
      }
      if(m_spilled)
        m_spill.emplace_back();
      return m_size++;
    }
    bool spilled() const { return m_spilled; }
    // the nodes, wherever they are
    std::vector<Node> take() { return m_spilled ? std::move(m_spill) : std::vector<Node>(m_slice, m_slice + m_size); }

  private:
    Node* m_slice;
    std::size_t m_room, m_size = 0;
    bool m_spilled = false;
    std::vector<Node> m_spill;
  };
  // Appends the subtree of [begin, end) at `depth` to `nodes` in preorder, its ids counted from the
  // first node of `nodes`
  void build(std::uint32_t begin, std::uint32_t end, const Cell& cell, std::size_t depth, Node_sink& nodes);
  // Moves the top `t` and the subtrees below it down to `next` in m_nodes, in the preorder of build(),
  // each node's right child moved with it; returns the position after them
  std::size_t place(const std::vector<Top>& tops, std::size_t t, const std::vector<std::size_t>& slice_of,
                    const std::vector<Node_sink>& sinks, const std::vector<std::size_t>& sink_of, std::size_t next);
  // The same, from the subtrees' own vectors, appended to m_nodes (when one did not fit in its slice)
  void assemble(const std::vector<Top>& tops, std::size_t t, std::vector<std::vector<Node>>& subtrees,
                const std::vector<std::size_t>& subtree_of);
  static constexpr std::uint32_t NO_POINT = (std::numeric_limits<std::uint32_t>::max)();
  // The k nearest points to q other than point `i` (NO_POINT: any), k at most the points there are.
  void nearest_to(const double* q, std::uint32_t i, std::size_t k, std::vector<Neighbor>& result,
                  double squared_bound) const;
  template <typename Visit_leaf, typename Bound>
  void walk(const double* q, const Visit_leaf& visit, const Bound& bound) const;

  std::vector<Node> m_nodes;
  const std::vector<Double_point>* m_points = nullptr;
  std::vector<std::uint32_t> m_index; // the point index of each position
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/Point_kd_tree_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_H
