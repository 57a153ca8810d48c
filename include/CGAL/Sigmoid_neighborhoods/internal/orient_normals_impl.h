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

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Hoppe et al.'s graph is undirected (edge i-j when either point is among the k nearest of the
// other): the rows give the edges out of a point, and these reversed rows the edges into it, each in
// increasing order. The indices are left uninitialised until placed: zeroing them first, a pass of
// 4 k bytes per point on one thread, took as long as placing them.
struct Reversed_rows
{
  std::vector<std::size_t> offsets;
  std::unique_ptr<std::uint32_t[]> indices;

  const std::uint32_t* begin(std::size_t i) const { return indices.get() + offsets[i]; }
  const std::uint32_t* end(std::size_t i) const { return indices.get() + offsets[i + 1]; }
};

// The reversed rows of `query`'s given rows (orient_normals_by_spanning_forest() makes them), on
// `threads` threads (0: the default): the rows cut into blocks, at most 8, that count their entries
// per point (4 bytes per point and block), then place them; a point's entries come block after
// block, so in the order of one pass over the rows, whatever the threads.
inline Reversed_rows reversed_neighbor_rows(const Neighbor_query& query, unsigned int k, unsigned int threads)
{
  const std::size_t n = query.size();
  const std::size_t blocks =
    n < (std::size_t(1) << 15) ? 1 : (std::min)(thread_count<Parallel_if_available_tag>(threads), std::size_t(8));
  auto block_begin = [&](std::size_t b) { return n * b / blocks; };
  std::vector<std::vector<std::uint32_t>> counts(blocks);
  for_each_index<Parallel_if_available_tag>(
    blocks, threads, [] { return 0; },
    [&](std::size_t b, int) {
      counts[b].assign(n, 0);
      for(std::size_t i = block_begin(b); i < block_begin(b + 1); ++i)
        for(const std::uint32_t* j = query.given_row_begin(i); j != query.given_row_end(i, k); ++j)
          ++counts[b][*j];
    },
    1);
  // per point, its number of entries, and each block's first place among them
  Reversed_rows reversed;
  reversed.offsets.resize(n + 1);
  reversed.offsets[0] = 0;
  for_each_index<Parallel_if_available_tag>(
    n, threads, [] { return 0; },
    [&](std::size_t j, int) {
      std::uint32_t entries = 0;
      for(std::size_t b = 0; b < blocks; ++b)
      {
        const std::uint32_t c = counts[b][j];
        counts[b][j] = entries;
        entries += c;
      }
      reversed.offsets[j + 1] = entries;
    },
    4096);
  std::partial_sum(reversed.offsets.begin(), reversed.offsets.end(), reversed.offsets.begin());
  reversed.indices.reset(new std::uint32_t[reversed.offsets[n]]);
  for_each_index<Parallel_if_available_tag>(
    blocks, threads, [] { return 0; },
    [&](std::size_t b, int) {
      for(std::size_t i = block_begin(b); i < block_begin(b + 1); ++i)
        for(const std::uint32_t* j = query.given_row_begin(i); j != query.given_row_end(i, k); ++j)
          reversed.indices[reversed.offsets[*j] + counts[b][*j]++] = static_cast<std::uint32_t>(i);
    },
    1);
  return reversed;
}

// An edge of the graph in the forest's total order: the lighter first, then by its endpoints, so
// that the minimum spanning forest is unique and Boruvka's rounds find it whatever the threads do.
struct Forest_edge
{
  double weight = 2.; // above every weight: no edge
  std::uint32_t low = std::uint32_t(-1), high = std::uint32_t(-1);

  bool operator<(const Forest_edge& e) const
  {
    return weight < e.weight || (weight == e.weight && (low < e.low || (low == e.low && high < e.high)));
  }
  bool exists() const { return low != std::uint32_t(-1); }
};

inline Forest_edge forest_edge(std::uint32_t u, std::uint32_t v, const std::vector<Eigen::Vector3d>& normals)
{
  // |n_u . n_v| is the same bits either way round, and whatever the normals' signs
  return Forest_edge{(std::max)(0., 1. - std::abs(normals[u].dot(normals[v]))), (std::min)(u, v), (std::max)(u, v)};
}

// The minimum spanning forest of the graph, as pairs of points, by Boruvka's rounds: in each, every
// point finds in parallel its lightest edge to another component, each component keeps the lightest
// of its points', and those edges join the components (each is in the forest: the order is total).
// A point without an edge out of its component never has one again: it leaves the rounds.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>>
minimum_spanning_forest(const Neighbor_query& query, const Reversed_rows& reversed, unsigned int k,
                        const std::vector<Eigen::Vector3d>& normals, unsigned int threads)
{
  const std::size_t n = query.size();
  std::vector<std::uint32_t> parent(n), component(n), active(n);
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  std::iota(active.begin(), active.end(), std::uint32_t(0));
  auto find = [&parent](std::uint32_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<Forest_edge> lightest(n), lightest_of_component(n);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> forest;
  forest.reserve(n);
  while(!active.empty())
  {
    for(std::size_t v = 0; v < n; ++v)
      component[v] = find(std::uint32_t(v));
    for_each_index<Parallel_if_available_tag>(
      active.size(), threads, [] { return 0; },
      [&](std::size_t a, int) {
        const std::uint32_t u = active[a], own = component[u];
        // the edges out of the component only ever become fewer: one still out is still the lightest
        const Forest_edge& previous = lightest[u];
        if(previous.exists() && component[previous.low] != component[previous.high])
          return;
        Forest_edge best;
        auto consider = [&](const std::uint32_t* v, const std::uint32_t* end) {
          for(; v != end; ++v)
            if(component[*v] != own)
            {
              const Forest_edge e = forest_edge(u, *v, normals);
              if(e < best)
                best = e;
            }
        };
        consider(query.given_row_begin(u), query.given_row_end(u, k));
        consider(reversed.begin(u), reversed.end(u));
        lightest[u] = best;
      },
      1024);
    for(std::uint32_t u : active)
      lightest_of_component[component[u]] = Forest_edge();
    for(std::uint32_t u : active)
      if(lightest[u] < lightest_of_component[component[u]])
        lightest_of_component[component[u]] = lightest[u];
    for(std::uint32_t u : active)
    {
      const Forest_edge& e = lightest_of_component[component[u]];
      if(!e.exists())
        continue;
      const std::uint32_t a = find(e.low), b = find(e.high);
      if(a == b)
        continue; // joined already: by this edge, from its other end or an earlier point of the component
      parent[(std::max)(a, b)] = (std::min)(a, b);
      forest.emplace_back(e.low, e.high);
    }
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::uint32_t u) { return !lightest[u].exists(); }),
                 active.end());
  }
  return forest;
}

CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::size_t orient_along_spanning_forest(const std::vector<Double_point>& points,
                                                                            const Neighbor_query& query, unsigned int k,
                                                                            std::vector<Eigen::Vector3d>& normals,
                                                                            unsigned int threads)
{
  const std::size_t n = points.size();
  const Reversed_rows reversed = reversed_neighbor_rows(query, k, threads);
  const auto forest = minimum_spanning_forest(query, reversed, k, normals, threads);

  // The forest's edges out of each point, and the seed of each tree: its highest point, the first
  // of the highest by index (as CGAL's mst_orient_normals() takes it).
  std::vector<std::uint32_t> root(n); // before the offsets' n + 1: GCC 12 then sees no size overflow to warn of
  Neighbor_lists tree;
  tree.offsets.assign(n + 1, 0);
  std::iota(root.begin(), root.end(), std::uint32_t(0));
  auto find = [&root](std::uint32_t v) {
    while(root[v] != v)
      v = root[v] = root[root[v]];
    return v;
  };
  for(const auto& e : forest)
  {
    ++tree.offsets[e.first + 1];
    ++tree.offsets[e.second + 1];
    const std::uint32_t a = find(e.first), b = find(e.second);
    root[(std::max)(a, b)] = (std::min)(a, b);
  }
  std::partial_sum(tree.offsets.begin(), tree.offsets.end(), tree.offsets.begin());
  tree.indices.resize(tree.offsets[n]);
  {
    std::vector<std::size_t> next(tree.offsets.begin(), tree.offsets.end() - 1);
    for(const auto& e : forest)
    {
      tree.indices[next[e.first]++] = e.second;
      tree.indices[next[e.second]++] = e.first;
    }
  }
  constexpr std::uint32_t NONE = std::uint32_t(-1);
  std::vector<std::uint32_t> seed(n, NONE);
  for(std::uint32_t v = 0; v < n; ++v)
  {
    std::uint32_t& s = seed[find(v)];
    if(s == NONE || points[v].z() > points[s].z())
      s = v; // equal heights: the first by index stays
  }

  // Each tree walked from its seed, turned towards +z, each normal turned to agree with its
  // parent's: O(n), a small part of the forest's time.
  std::vector<bool> done(n, false);
  std::vector<std::uint32_t> stack;
  std::size_t trees = 0;
  for(std::uint32_t s : seed)
  {
    if(s == NONE)
      continue;
    ++trees;
    if(normals[s].z() < 0.)
      normals[s] = -normals[s];
    done[s] = true;
    stack.push_back(s);
    while(!stack.empty())
    {
      const std::uint32_t u = stack.back();
      stack.pop_back();
      for(const std::uint32_t* v = tree.begin(u); v != tree.end(u); ++v)
        if(!done[*v])
        {
          done[*v] = true;
          if(normals[*v].dot(normals[u]) < 0.)
            normals[*v] = -normals[*v];
          stack.push_back(*v);
        }
    }
  }
  return trees;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENT_NORMALS_IMPL_H
