// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The kd-tree's construction and queries (see config.h): included by Point_kd_tree.h, or compiled
// once in CGAL::Sigmoid_neighborhoods_core.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_IMPL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_IMPL_H

#include <CGAL/Sigmoid_neighborhoods/internal/Point_kd_tree.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION Point_kd_tree::Point_kd_tree(const std::vector<Double_point>& points,
                                                                 unsigned int threads)
{
  const std::uint32_t n = static_cast<std::uint32_t>(points.size());
  if(n == 0)
    return;
  m_points = &points;
  m_index.resize(n);
  for(std::uint32_t i = 0; i < n; ++i)
    m_index[i] = i;
  m_nodes.resize(subtree_nodes(n));
  // The top levels split node by node, each level's nodes in parallel, until there are subtrees
  // enough for every thread; then the subtrees in parallel. Each split reads and writes its own
  // positions and nodes: the tree is the sequential one for any number of threads.
  if(threads == 1)
  {
    build(Pending{0, 0, n});
    return;
  }
  std::vector<Pending> level{Pending{0, 0, n}};
  const std::size_t enough = 8 * std::size_t(threads == 0 ? 16 : threads);
  while(!level.empty() && level.size() < enough)
  {
    std::vector<Pending> children(2 * level.size(), Pending{0, 0, 0});
    std::vector<char> is_split(level.size(), 0);
    for_each_index<Parallel_if_available_tag>(
      level.size(), threads, [] { return 0; },
      [&](std::size_t i, int) { is_split[i] = split(level[i], children[2 * i], children[2 * i + 1]); }, 1);
    std::vector<Pending> next;
    for(std::size_t i = 0; i < level.size(); ++i)
      if(is_split[i])
      {
        next.push_back(children[2 * i]);
        next.push_back(children[2 * i + 1]);
      }
    level.swap(next);
  }
  for_each_index<Parallel_if_available_tag>(
    level.size(), threads, [] { return 0; }, [&](std::size_t i, int) { build(level[i]); }, 1);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::uint32_t Point_kd_tree::subtree_nodes(std::uint32_t count)
{
  // nodes(m) = 1 + nodes(m / 2) + nodes(m - m / 2) above a leaf. The sizes of one depth differ by one
  // at most (lows[d] and highs[d]), so the recursion meets two per depth: counted from the leaves up.
  std::vector<std::uint32_t> lows, highs;
  for(std::uint32_t low = count, high = count;; low /= 2, high -= high / 2)
  {
    lows.push_back(low);
    highs.push_back(high);
    if(high <= LEAF_SIZE)
      break;
  }
  std::uint32_t low_nodes = 1, high_nodes = 1; // the deepest sizes are leaves
  for(std::size_t d = lows.size() - 1; d-- > 0;)
  {
    auto below = [&](std::uint32_t m) { return m == lows[d + 1] ? low_nodes : high_nodes; };
    auto nodes = [&](std::uint32_t m) { return m <= LEAF_SIZE ? 1u : 1u + below(m / 2) + below(m - m / 2); };
    const std::uint32_t new_low = nodes(lows[d]), new_high = nodes(highs[d]);
    low_nodes = new_low;
    high_nodes = new_high;
  }
  return low_nodes;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION bool Point_kd_tree::split(const Pending& node, Pending& left, Pending& right)
{
  const std::uint32_t begin = node.begin, end = node.end;
  if(end - begin <= LEAF_SIZE)
  {
    m_nodes[node.id] = Node{0., 0., begin, end, 3};
    return false;
  }
  double low[3], high[3];
  for(int d = 0; d < 3; ++d)
  {
    low[d] = (std::numeric_limits<double>::max)();
    high[d] = -(std::numeric_limits<double>::max)();
  }
  for(std::uint32_t e = begin; e < end; ++e)
    for(int d = 0; d < 3; ++d)
    {
      const double c = (*m_points)[m_index[e]][d];
      low[d] = (std::min)(low[d], c);
      high[d] = (std::max)(high[d], c);
    }
  int axis = 0;
  for(int d = 1; d < 3; ++d)
    if(high[d] - low[d] > high[axis] - low[axis])
      axis = d;
  const std::uint32_t middle = begin + (end - begin) / 2;
  const std::vector<Double_point>& points = *m_points;
  auto coordinate = [&points, axis](std::uint32_t a) { return points[a][axis]; };
  std::nth_element(m_index.begin() + begin, m_index.begin() + middle, m_index.begin() + end,
                   [&coordinate](std::uint32_t a, std::uint32_t b) {
                     const double ca = coordinate(a), cb = coordinate(b);
                     return ca < cb || (ca == cb && a < b);
                   });
  double left_end = -(std::numeric_limits<double>::max)();
  for(std::uint32_t e = begin; e < middle; ++e)
    left_end = (std::max)(left_end, coordinate(m_index[e]));
  const double right_begin = coordinate(m_index[middle]);
  left = Pending{node.id + 1, begin, middle};
  right = Pending{node.id + 1 + subtree_nodes(middle - begin), middle, end};
  m_nodes[node.id] = Node{left_end, right_begin, right.id, 0, std::uint32_t(axis)};
  return true;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::build(const Pending& node)
{
  Pending left, right;
  if(!split(node, left, right))
    return;
  build(left);
  build(right);
}

// Visits the leaves of node `id` that are not farther than bound(), nearer child first; `gap`
// holds the gaps per axis between q and the node's slab (restored on return).
template <typename Visit_leaf, typename Bound>
void Point_kd_tree::descend(std::uint32_t id, const double* q, double* gap, const Visit_leaf& visit,
                            const Bound& bound) const
{
  const Node& node = m_nodes[id];
  if(node.axis == 3)
  {
    visit(node.begin, node.end);
    return;
  }
  const std::uint32_t axis = node.axis;
  const double c = q[axis], parent_gap = gap[axis];
  // the gap of each child along the axis: wider than the parent's only beyond the child's end
  const double left_gap = c > node.left_end ? c - node.left_end : parent_gap;
  const double right_gap = c < node.right_begin ? node.right_begin - c : parent_gap;
  const bool left_first = left_gap <= right_gap;
  const std::uint32_t children[2] = {id + 1, node.begin};
  const double gaps[2] = {left_gap, right_gap};
  for(int side = 0; side < 2; ++side)
  {
    const int child = left_first ? side : 1 - side;
    gap[axis] = gaps[child];
    // `<=`: a point at the bound may still win its tie by index
    if(gap[0] * gap[0] + gap[1] * gap[1] + gap[2] * gap[2] <= bound())
      descend(children[child], q, gap, visit, bound);
  }
  gap[axis] = parent_gap;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::nearest(std::uint32_t i, std::size_t k,
                                                                    std::vector<Neighbor>& result,
                                                                    double squared_bound) const
{
  const std::size_t n = m_index.size();
  const Double_point& query = (*m_points)[i];
  const double q[3] = {query.x(), query.y(), query.z()};
  nearest_to(q, i, (std::min)(k, n == 0 ? std::size_t(0) : n - 1), result, squared_bound);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::nearest(const Double_point& query, std::size_t k,
                                                                    std::vector<Neighbor>& result) const
{
  const double q[3] = {query.x(), query.y(), query.z()};
  nearest_to(q, NO_POINT, (std::min)(k, m_index.size()), result, (std::numeric_limits<double>::infinity)());
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::nearest_to(const double* q, std::uint32_t i, std::size_t k,
                                                                       std::vector<Neighbor>& result,
                                                                       double squared_bound) const
{
  result.clear();
  if(k == 0)
    return;
  double gap[3] = {0., 0., 0.};
  if(k <= SORTED_INSERTION_K)
  {
    // few neighbors: kept sorted, each candidate inserted in place
    double threshold = squared_bound;
    result.reserve(k + 1);
    auto visit = [&](std::uint32_t begin, std::uint32_t end) {
      for(std::uint32_t e = begin; e < end; ++e)
      {
        const double d2 = squared_distance_at(e, q);
        if(d2 > threshold || m_index[e] == i)
          continue;
        const Neighbor candidate{m_index[e], d2};
        if(result.size() == k)
        {
          if(!is_nearer(candidate, result.back()))
            continue;
          result.pop_back();
        }
        std::size_t hole = result.size();
        result.push_back(candidate);
        for(; hole > 0 && is_nearer(candidate, result[hole - 1]); --hole)
          result[hole] = result[hole - 1];
        result[hole] = candidate;
        if(result.size() == k)
          threshold = result.back().squared_distance;
      }
    };
    descend(0, q, gap, visit, [&] { return threshold; });
    if(result.size() < k) // the caller's bound was too small
      nearest_to(q, i, k, result, (std::numeric_limits<double>::infinity)());
    return;
  }
  // Candidates are gathered unordered below a threshold, the k-th nearest distance among those
  // kept, and cut down to the k nearest (the tie rule decides) as soon as k are found, so that the
  // threshold prunes early, then whenever they reach 2k: far cheaper for large k than a heap, which
  // reorders at each candidate. (A lambda, not is_nearer's address, lets the standard algorithms
  // inline the comparison.)
  const auto nearer = [](const Neighbor& x, const Neighbor& y) { return is_nearer(x, y); };
  double threshold = squared_bound;
  std::size_t cut_at = k;
  auto keep_nearest = [&] {
    std::nth_element(result.begin(), result.begin() + (k - 1), result.end(), nearer);
    result.resize(k);
    threshold = result[k - 1].squared_distance;
    cut_at = k + (std::max)(k, std::size_t(16));
  };
  result.reserve(k + (std::max)(k, std::size_t(16)) + LEAF_SIZE);
  auto visit = [&](std::uint32_t begin, std::uint32_t end) {
    for(std::uint32_t e = begin; e < end; ++e)
    {
      const double d2 = squared_distance_at(e, q);
      if(d2 <= threshold && m_index[e] != i)
        result.push_back(Neighbor{m_index[e], d2});
    }
    if(result.size() >= cut_at)
      keep_nearest();
  };
  // `<=` in descend(): a point at the threshold may still win its tie by index
  descend(0, q, gap, visit, [&] { return threshold; });
  if(result.size() < k) // the caller's bound was too small
  {
    nearest_to(q, i, k, result, (std::numeric_limits<double>::infinity)());
    return;
  }
  if(result.size() > k)
    keep_nearest();
  sort_by_nearness(result);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::ball(std::uint32_t i, double squared_radius,
                                                                 std::vector<Neighbor>& result) const
{
  result.clear();
  if(m_index.empty())
    return;
  const Double_point& query = (*m_points)[i];
  const double q[3] = {query.x(), query.y(), query.z()};
  auto visit = [&](std::uint32_t begin, std::uint32_t end) {
    for(std::uint32_t e = begin; e < end; ++e)
    {
      const double d2 = squared_distance_at(e, q);
      if(d2 <= squared_radius && m_index[e] != i)
        result.push_back(Neighbor{m_index[e], d2});
    }
  };
  double gap[3] = {0., 0., 0.};
  descend(0, q, gap, visit, [squared_radius] { return squared_radius; });
  sort_by_nearness(result);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_IMPL_H
