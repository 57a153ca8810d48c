// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_IS_POLYGON_MESH_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_IS_POLYGON_MESH_H

#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Fewer corners than this are checked on one thread: a region would cost more than it saves, and a
// forked child (the readers' limit tests) cannot start one.
constexpr std::size_t PARALLEL_MESH_CHECK_CORNERS = std::size_t(1) << 15;

// A corner of a polygon seen from its vertex: the vertices before and after it in the polygon.
struct Vertex_corner
{
  std::size_t previous, next;
};

// Whether `polygons` is a polygon mesh: the answer of CGAL's
// `Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`, in time linear in the corners and
// on `threads` threads (0: the default) rather than through ordered sets on one thread, where a
// 40,000-vertex mesh took a quarter of a second. CGAL asks that every polygon have three corners
// or more, all distinct; that no directed edge appear twice (so no edge has more than two
// polygons, and two polygons sharing an edge agree on its orientation); and that the polygons
// around each vertex be one fan, open or closed. Around a vertex v, a polygon with the edge
// v -> x is followed by the one with x -> v, if any; directed edges being unique, each polygon has
// at most one follower and one predecessor, so the polygons around v form paths and cycles, and
// v is regular when they form just one.
template <typename PolygonRange>
bool is_polygon_mesh(const PolygonRange& polygons, unsigned int threads = 0)
{
  if(polygons.empty())
    return true;
  std::size_t vertex_count = 0, corner_count = 0;
  std::vector<std::size_t> sorted;
  for(const auto& polygon : polygons)
  {
    if(polygon.size() < 3)
      return false;
    for(std::size_t v : polygon)
      vertex_count = (std::max)(vertex_count, v + 1);
    corner_count += polygon.size();
    sorted.assign(polygon.begin(), polygon.end());
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return false; // a vertex twice in one polygon
  }

  // Each vertex's corners, contiguous: counted, then placed.
  std::vector<std::size_t> first_corner(vertex_count + 1, 0);
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
      ++first_corner[v + 1];
  for(std::size_t v = 0; v < vertex_count; ++v)
    first_corner[v + 1] += first_corner[v];
  std::vector<Vertex_corner> corners(corner_count);
  {
    std::vector<std::size_t> placed(first_corner.begin(), first_corner.end() - 1);
    for(const auto& polygon : polygons)
    {
      const std::size_t size = polygon.size();
      for(std::size_t j = 0; j < size; ++j)
        corners[placed[polygon[j]]++] = Vertex_corner{polygon[(j + size - 1) % size], polygon[(j + 1) % size]};
    }
  }

  // Per vertex v: its corners sorted by the vertex after them and by the one before. An edge
  // v -> x or x -> v met twice gives two equal keys. Otherwise the corner that follows one with
  // next x around v is the one with previous x.
  struct Scratch
  {
    std::vector<std::pair<std::size_t, std::size_t>> by_next, by_previous;
  };
  std::atomic<bool> is_mesh{true};
  auto check_vertex = [&](std::size_t v, Scratch& s) {
    const std::size_t begin = first_corner[v], degree = first_corner[v + 1] - begin;
    if(degree == 0 || !is_mesh.load(std::memory_order_relaxed))
      return;
    s.by_next.clear();
    s.by_previous.clear();
    for(std::size_t i = 0; i < degree; ++i)
    {
      s.by_next.emplace_back(corners[begin + i].next, i);
      s.by_previous.emplace_back(corners[begin + i].previous, i);
    }
    std::sort(s.by_next.begin(), s.by_next.end());
    std::sort(s.by_previous.begin(), s.by_previous.end());
    for(std::size_t i = 1; i < degree; ++i)
      if(s.by_next[i].first == s.by_next[i - 1].first || s.by_previous[i].first == s.by_previous[i - 1].first)
      {
        is_mesh.store(false, std::memory_order_relaxed);
        return;
      }
    auto find = [](const std::vector<std::pair<std::size_t, std::size_t>>& keys, std::size_t key) {
      const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, std::size_t(0)));
      return (it != keys.end() && it->first == key) ? it->second : std::size_t(-1);
    };
    // The start of the fan: a corner without predecessor, at most one; any corner if it is closed.
    std::size_t start = 0, starts = 0;
    for(std::size_t i = 0; i < degree; ++i)
      if(find(s.by_next, corners[begin + i].previous) == std::size_t(-1))
      {
        start = i;
        if(++starts > 1)
        {
          is_mesh.store(false, std::memory_order_relaxed);
          return;
        }
      }
    std::size_t walked = 1;
    for(std::size_t i = find(s.by_previous, corners[begin + start].next); i != std::size_t(-1) && i != start;
        i = find(s.by_previous, corners[begin + i].next))
      ++walked;
    if(walked != degree)
      is_mesh.store(false, std::memory_order_relaxed);
  };
  auto scratch = [] { return Scratch(); };
  if(corner_count < PARALLEL_MESH_CHECK_CORNERS)
    for_each_index<CGAL::Sequential_tag>(vertex_count, 1, scratch, check_vertex);
  else
    for_each_index<Parallel_if_available_tag>(vertex_count, threads, scratch, check_vertex, 64);
  return is_mesh.load();
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_IS_POLYGON_MESH_H
