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

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstring>
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
  Cell root;
  for(int d = 0; d < 3; ++d)
  {
    root.low[d] = (std::numeric_limits<double>::max)();
    root.high[d] = -(std::numeric_limits<double>::max)();
  }
  for(const Double_point& p : points)
    for(int d = 0; d < 3; ++d)
    {
      root.low[d] = (std::min)(root.low[d], p[d]);
      root.high[d] = (std::max)(root.high[d], p[d]);
    }
  // Leaves hold 8 points or more on the scans and meshes measured (13 on average on a scan): room for
  // nodes of that many, so that no node is copied while the tree is built (a copy would be the peak
  // of a search's memory).
  const auto room = [](std::uint32_t count) { return std::size_t(count) / 4 + 1; };
  if(threads == 1)
  {
    // a vector of its own from the start, its room reserved: the pages of the room it does not use
    // are never touched
    Node_sink sink(nullptr, 0, room(n));
    build(0, n, root, 0, sink);
    m_nodes = sink.take();
    return;
  }
  // The top levels split node by node, each level's nodes in parallel, until there are subtrees
  // enough for every thread; then the subtrees in parallel, each in a slice of m_nodes laid out in
  // the preorder of the sequential build, and moved down together at the end. Each split reads and
  // writes its own positions: the tree is the sequential one for any number of threads.
  std::vector<Top> tops{Top{0, n, 0, root, Node{0., 0., 0, n, 3}}};
  std::vector<std::size_t> level{0}, subtree_roots;
  const std::size_t enough = 8 * std::size_t(threads == 0 ? 16 : threads);
  for(std::size_t depth = 0; !level.empty() && subtree_roots.size() + level.size() < enough; ++depth)
  {
    std::vector<Top> children(2 * level.size());
    std::vector<char> is_split(level.size(), 0);
    for_each_index<Parallel_if_available_tag>(
      level.size(), threads, [] { return 0; },
      [&](std::size_t l, int) {
        Top& top = tops[level[l]];
        std::uint32_t middle = 0;
        Top& left = children[2 * l];
        Top& right = children[2 * l + 1];
        is_split[l] = split(top.begin, top.end, top.cell, depth, top.node, middle, left.cell, right.cell);
        left.begin = top.begin;
        left.end = right.begin = middle;
        right.end = top.end;
        left.depth = right.depth = depth + 1;
      }, 1);
    std::vector<std::size_t> next;
    for(std::size_t l = 0; l < level.size(); ++l)
      if(is_split[l])
      {
        tops[level[l]].children = tops.size();
        for(int side = 0; side < 2; ++side)
        {
          next.push_back(tops.size());
          tops.push_back(children[2 * l + std::size_t(side)]);
        }
      }
      else
        subtree_roots.push_back(level[l]);
    level.swap(next);
  }
  subtree_roots.insert(subtree_roots.end(), level.begin(), level.end());
  // each top's place in m_nodes, in preorder: one node for a split, a slice for a subtree
  std::vector<std::size_t> slice_of(tops.size(), 0), sink_of(tops.size(), 0);
  for(std::size_t r = 0; r < subtree_roots.size(); ++r)
    sink_of[subtree_roots[r]] = r;
  std::size_t total = 0;
  std::vector<std::size_t> preorder{0};
  while(!preorder.empty())
  {
    const std::size_t t = preorder.back();
    preorder.pop_back();
    slice_of[t] = total;
    if(tops[t].children == 0)
      total += room(tops[t].end - tops[t].begin);
    else
    {
      ++total;
      preorder.push_back(tops[t].children + 1);
      preorder.push_back(tops[t].children);
    }
  }
  m_nodes.resize(total);
  std::vector<Node_sink> sinks;
  sinks.reserve(subtree_roots.size());
  for(std::size_t t : subtree_roots)
    sinks.emplace_back(m_nodes.data() + slice_of[t], room(tops[t].end - tops[t].begin));
  for_each_index<Parallel_if_available_tag>(
    subtree_roots.size(), threads, [] { return 0; },
    [&](std::size_t r, int) {
      const Top& top = tops[subtree_roots[r]];
      build(top.begin, top.end, top.cell, top.depth, sinks[r]);
    }, 1);
  if(std::none_of(sinks.begin(), sinks.end(), [](const Node_sink& sink) { return sink.spilled(); }))
  {
    m_nodes.resize(place(tops, 0, slice_of, sinks, sink_of, 0));
    return;
  }
  std::vector<std::vector<Node>> subtrees;
  for(Node_sink& sink : sinks)
    subtrees.push_back(sink.take());
  std::vector<Node>().swap(m_nodes);
  std::size_t nodes = tops.size() - subtree_roots.size();
  for(const std::vector<Node>& subtree : subtrees)
    nodes += subtree.size();
  m_nodes.reserve(nodes);
  assemble(tops, 0, subtrees, sink_of);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION bool Point_kd_tree::split(std::uint32_t begin, std::uint32_t end,
                                                                  const Cell& cell, std::size_t depth, Node& node, std::uint32_t& middle,
                                                                  Cell& left, Cell& right)
{
  const std::uint32_t count = end - begin;
  if(count <= LEAF_SIZE)
  {
    node = Node{0., 0., begin, end, 3};
    return false;
  }
  const std::vector<Double_point>& points = *m_points;
  double low[3], high[3];
  for(int d = 0; d < 3; ++d)
  {
    low[d] = (std::numeric_limits<double>::max)();
    high[d] = -(std::numeric_limits<double>::max)();
  }
  for(std::uint32_t e = begin; e < end; ++e)
    for(int d = 0; d < 3; ++d)
    {
      const double c = points[m_index[e]][d];
      low[d] = (std::min)(low[d], c);
      high[d] = (std::max)(high[d], c);
    }
  // among the cell's widest sides (to a relative 1e-5), the one its points spread most along;
  // the points' widest side when they do not spread along those
  double widest = 0.;
  for(int d = 0; d < 3; ++d)
    widest = (std::max)(widest, cell.high[d] - cell.low[d]);
  int axis = -1;
  for(int d = 0; d < 3; ++d)
    if(cell.high[d] - cell.low[d] >= (1. - 1e-5) * widest && high[d] > low[d] &&
       (axis < 0 || high[d] - low[d] > high[axis] - low[axis]))
      axis = d;
  if(axis < 0)
  {
    axis = 0;
    for(int d = 1; d < 3; ++d)
      if(high[d] - low[d] > high[axis] - low[axis])
        axis = d;
  }
  // halves first: the middle of a cell from -DBL_MAX to DBL_MAX is 0, not an overflow
  const double cut = (std::min)((std::max)(0.5 * cell.low[axis] + 0.5 * cell.high[axis], low[axis]), high[axis]);
  auto coordinate = [&points, axis](std::uint32_t a) { return points[a][axis]; };
  const auto first = m_index.begin() + begin, last = m_index.begin() + end;
  const auto below = std::partition(first, last, [&](std::uint32_t a) { return coordinate(a) < cut; });
  const auto at_most = std::partition(below, last, [&](std::uint32_t a) { return coordinate(a) <= cut; });
  const std::uint32_t lim1 = std::uint32_t(below - first), lim2 = std::uint32_t(at_most - first);
  std::uint32_t size = lim1 > count / 2 ? lim1 : lim2 < count / 2 ? lim2 : count / 2;
  if(size == 0 || size == count) // cannot happen with finite coordinates; never an empty side
    size = count / 2;
  // below FREE_DEPTH the split stays where the cut puts it; deeper, each side keeps a quarter of the
  // points (the nearest quarter, ties by index), which bounds the depth on any input
  const std::uint32_t fewest = depth < FREE_DEPTH ? 0 : count / 4;
  if(size < fewest || size > count - fewest)
  {
    size = size < fewest ? fewest : count - fewest;
    std::nth_element(first, first + size, last, [&coordinate](std::uint32_t a, std::uint32_t b) {
      const double ca = coordinate(a), cb = coordinate(b);
      return ca < cb || (ca == cb && a < b);
    });
  }
  middle = begin + size;
  double left_end = -(std::numeric_limits<double>::max)(), right_begin = (std::numeric_limits<double>::max)();
  for(std::uint32_t e = begin; e < middle; ++e)
    left_end = (std::max)(left_end, coordinate(m_index[e]));
  for(std::uint32_t e = middle; e < end; ++e)
    right_begin = (std::min)(right_begin, coordinate(m_index[e]));
  left = cell;
  right = cell;
  // the cells meet at the cut, or between the sides when the split moved off it
  const double border = left_end <= cut && cut <= right_begin ? cut : 0.5 * left_end + 0.5 * right_begin;
  left.high[axis] = border;
  right.low[axis] = border;
  node = Node{left_end, right_begin, 0, 0, std::uint32_t(axis)};
  return true;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::build(std::uint32_t begin, std::uint32_t end,
                                                                  const Cell& cell, std::size_t depth,
                                                                  Node_sink& nodes)
{
  const std::size_t id = nodes.append();
  Node node;
  std::uint32_t middle = 0;
  Cell left, right;
  if(!split(begin, end, cell, depth, node, middle, left, right))
  {
    nodes[id] = node;
    return;
  }
  build(begin, middle, left, depth + 1, nodes);
  node.begin = std::uint32_t(nodes.size());
  build(middle, end, right, depth + 1, nodes);
  nodes[id] = node;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::size_t Point_kd_tree::place(const std::vector<Top>& tops, std::size_t t,
                                                                         const std::vector<std::size_t>& slice_of,
                                                                         const std::vector<Node_sink>& sinks,
                                                                         const std::vector<std::size_t>& sink_of,
                                                                         std::size_t next)
{
  // Every place before this top took at most its room, so `next` is at most the top's slice: the
  // nodes move down, over places already moved.
  const Top& top = tops[t];
  if(top.children == 0)
  {
    const std::size_t size = sinks[sink_of[t]].size();
    if(next != slice_of[t])
      std::memmove(static_cast<void*>(m_nodes.data() + next), m_nodes.data() + slice_of[t], size * sizeof(Node));
    for(std::size_t e = next; e < next + size; ++e)
      if(m_nodes[e].axis != 3)
        m_nodes[e].begin += std::uint32_t(next);
    return next + size;
  }
  const std::size_t id = next;
  m_nodes[id] = top.node;
  const std::size_t right = place(tops, top.children, slice_of, sinks, sink_of, id + 1);
  m_nodes[id].begin = std::uint32_t(right);
  return place(tops, top.children + 1, slice_of, sinks, sink_of, right);
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::assemble(const std::vector<Top>& tops, std::size_t t,
                                                                     std::vector<std::vector<Node>>& subtrees,
                                                                     const std::vector<std::size_t>& subtree_of)
{
  const Top& top = tops[t];
  if(top.children == 0)
  {
    // a subtree's ids count from its first node: moved to where it lands
    const std::uint32_t offset = std::uint32_t(m_nodes.size());
    for(Node node : subtrees[subtree_of[t]])
    {
      if(node.axis != 3)
        node.begin += offset;
      m_nodes.push_back(node);
    }
    std::vector<Node>().swap(subtrees[subtree_of[t]]);
    return;
  }
  const std::size_t id = m_nodes.size();
  m_nodes.push_back(top.node);
  assemble(tops, top.children, subtrees, subtree_of);
  m_nodes[id].begin = std::uint32_t(m_nodes.size());
  assemble(tops, top.children + 1, subtrees, subtree_of);
}

// Visits the leaves that are not farther than bound() from q, the nearer child first (a stack of the
// farther ones, each tested again when its turn comes, as the bound may have shrunk). A node's lower
// bound is the sum of the squared gaps per axis between q and its slab.
template <typename Visit_leaf, typename Bound>
CGAL_SIGMOID_NEIGHBORHOODS_ALWAYS_INLINE void Point_kd_tree::walk(const double* q, const Visit_leaf& visit, const Bound& bound) const
{
  struct Pending
  {
    std::uint32_t node;
    double gap[3];
    double lower;
  };
  Pending stack[MAX_DEPTH + 1];
  std::size_t top = 0;
  stack[top++] = Pending{0, {0., 0., 0.}, 0.};
  const Node* nodes = m_nodes.data();
  while(top > 0)
  {
    Pending p = stack[--top];
    // `<=` everywhere: a point at the bound may still win its tie by index
    if(!(p.lower <= bound()))
      continue;
    bool reached = true;
    while(nodes[p.node].axis != 3)
    {
      const Node& node = nodes[p.node];
      const std::uint32_t axis = node.axis;
      const double c = q[axis], parent_gap = p.gap[axis];
      // the gap of each child along the axis: wider than the parent's only beyond the child's end
      const double left_gap = c > node.left_end ? c - node.left_end : parent_gap;
      const double right_gap = c < node.right_begin ? node.right_begin - c : parent_gap;
      const bool left_first = left_gap <= right_gap;
      Pending far = p;
      far.node = left_first ? node.begin : p.node + 1;
      far.gap[axis] = left_first ? right_gap : left_gap;
      far.lower = far.gap[0] * far.gap[0] + far.gap[1] * far.gap[1] + far.gap[2] * far.gap[2];
      if(far.lower <= bound())
      {
        CGAL_assertion(top <= MAX_DEPTH);
        stack[top++] = far;
      }
      p.node = left_first ? p.node + 1 : node.begin;
      const double near_gap = left_first ? left_gap : right_gap;
      if(near_gap == parent_gap) // q within the nearer child's slab: the same bound, already tested
        continue;
      p.gap[axis] = near_gap;
      p.lower = p.gap[0] * p.gap[0] + p.gap[1] * p.gap[1] + p.gap[2] * p.gap[2];
      if(!(p.lower <= bound()))
      {
        reached = false;
        break;
      }
    }
    if(reached)
      visit(nodes[p.node].begin, nodes[p.node].end);
  }
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

// the squared distance from q to p, as every query computes it
inline double squared_distance_to(const Double_point& p, const double* q)
{
  const double dx = p.x() - q[0], dy = p.y() - q[1], dz = p.z() - q[2];
  return dx * dx + dy * dy + dz * dz;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION void Point_kd_tree::nearest_to(const double* q, std::uint32_t i, std::size_t k,
                                                                       std::vector<Neighbor>& result,
                                                                       double squared_bound) const
{
  if(k == 0)
  {
    result.clear();
    return;
  }
  const std::uint32_t* index = m_index.data();
  const Double_point* points = m_points->data();
  if(k <= SORTED_INSERTION_K)
  {
    // few neighbors: kept sorted in local arrays, each candidate inserted in place
    double distance[SORTED_INSERTION_K];
    std::uint32_t nearest[SORTED_INSERTION_K];
    std::size_t size = 0;
    double threshold = squared_bound;
    auto visit = [&](std::uint32_t begin, std::uint32_t end) {
      for(std::uint32_t e = begin; e < end; ++e)
      {
        const std::uint32_t j = index[e];
        const double d2 = squared_distance_to(points[j], q);
        if(d2 > threshold || j == i)
          continue;
        if(size == k)
        {
          // d2 is at most the k-th distance: nearer, unless it ties and loses by index
          if(d2 == distance[k - 1] && j > nearest[k - 1])
            continue;
          --size;
        }
        std::size_t hole = size;
        for(; hole > 0 && (distance[hole - 1] > d2 || (distance[hole - 1] == d2 && nearest[hole - 1] > j)); --hole)
        {
          distance[hole] = distance[hole - 1];
          nearest[hole] = nearest[hole - 1];
        }
        distance[hole] = d2;
        nearest[hole] = j;
        if(++size == k)
          threshold = distance[k - 1];
      }
    };
    walk(q, visit, [&] { return threshold; });
    if(size < k) // the caller's bound was too small
    {
      nearest_to(q, i, k, result, (std::numeric_limits<double>::infinity)());
      return;
    }
    result.resize(k); // nothing to do when the previous query's result had k too
    for(std::size_t e = 0; e < k; ++e)
      result[e] = Neighbor{nearest[e], distance[e]};
    return;
  }
  result.clear();
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
      const std::uint32_t j = index[e];
      const double d2 = squared_distance_to(points[j], q);
      if(d2 <= threshold && j != i)
        result.push_back(Neighbor{j, d2});
    }
    if(result.size() >= cut_at)
      keep_nearest();
  };
  walk(q, visit, [&] { return threshold; });
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
  const std::uint32_t* index = m_index.data();
  const Double_point* points = m_points->data();
  auto visit = [&](std::uint32_t begin, std::uint32_t end) {
    for(std::uint32_t e = begin; e < end; ++e)
    {
      const std::uint32_t j = index[e];
      const double d2 = squared_distance_to(points[j], q);
      if(d2 <= squared_radius && j != i)
        result.push_back(Neighbor{j, d2});
    }
  };
  walk(q, visit, [squared_radius] { return squared_radius; });
  sort_by_nearness(result);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_KD_TREE_IMPL_H
