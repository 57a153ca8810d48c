// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_NORMALS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_NORMALS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

inline Normal_estimation_method estimation_method(Normal_source source)
{
  return source == Normal_source::JET ? Normal_estimation_method::JET
         : source == Normal_source::PCA ? Normal_estimation_method::PCA
                                        : defaults::NORMAL_ESTIMATION_METHOD;
}

// The fewest neighbors a fit of `method` takes (estimate_normals()'s precondition, degree 2 jets).
inline unsigned int fewest_estimation_neighbors(Normal_estimation_method method)
{
  return method == Normal_estimation_method::PCA ? 2u : (defaults::JET_DEGREE + 1) * (defaults::JET_DEGREE + 2) / 2 - 1;
}

// Estimates and orients the normals of `out` on one k-nearest-neighbor structure, computed once
// and shared by both steps (and kept for later ones when `o.kept_neighbors` asks for it).
// Wall-clock seconds since `start`, and `start` moved to now: the steps' durations in turn.
inline double seconds_since(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

inline void estimate_normals(Oriented_point_set& out, const Normal_options& o)
{
  const Normal_estimation_method method = estimation_method(o.source);
  const std::size_t n = out.points.size();
  if(n < std::size_t(fewest_estimation_neighbors(method)) + 1)
    throw Input_error("too few distinct points (" + std::to_string(n) + ") to estimate normals");
  const unsigned int k = unsigned((std::min)(std::size_t(o.neighbors), n - 1));
  const unsigned int rows = unsigned((std::min)(std::size_t((std::max)(o.neighbors, o.kept_neighbors)), n - 1));

  std::vector<std::uint32_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::uint32_t(0));
  out.normals.assign(n, CGAL::NULL_VECTOR);
  const auto maps = parameters::neighbor_search(
    o.neighbor_search,
    parameters::number_of_threads(o.threads, CGAL::parameters::point_map(CGAL::make_property_map(out.points))
                                               .normal_map(CGAL::make_property_map(out.normals))));
  auto clock = std::chrono::steady_clock::now();
  try
  {
    // rows the caller computed on these points already (a tile's halo checks them first) are reused
    if(out.neighbor_offsets.size() != n + 1 || out.neighbor_offsets[1] != rows)
      compute_k_nearest_neighbors<Parallel_if_available_tag>(indices, rows, out.neighbor_indices, out.neighbor_offsets, maps);
    out.seconds.neighbor_rows += seconds_since(clock);
    // read in place: CGAL's named parameters copy what they hold unless given a reference
    const auto np = parameters::neighbor_indices(std::cref(out.neighbor_indices),
                                                 parameters::neighbor_offsets(std::cref(out.neighbor_offsets), maps));
    Sigmoid_neighborhoods::estimate_normals<Parallel_if_available_tag>(indices, k,
                                                                       parameters::normal_estimation_method(method, np));
    out.seconds.normal_estimation += seconds_since(clock);
    out.orientation_components = 0;
    if(o.orientation == Normal_orientation::SPANNING_FOREST)
      out.orientation_components = orient_normals_by_spanning_forest<Parallel_if_available_tag>(indices, k, np);
    else if(o.orientation == Normal_orientation::VIEWPOINT)
      orient_normals_towards_viewpoint(indices, o.viewpoint, maps);
    else if(o.orientation == Normal_orientation::UPWARD)
      for(Oriented_point_set::Vector_3& n : out.normals)
        if(n.z() < 0.)
          n = -n;
    out.seconds.orientation += seconds_since(clock);
  }
  catch(const std::invalid_argument& e)
  {
    // what the file's points cannot give: a line, coincident points (estimate_normals()'s checks)
    throw Input_error(e.what());
  }
  out.normals_estimated = true;
  out.estimation_method = method;
  out.estimation_neighbors = k;
  out.orientation = o.orientation;
  if(o.kept_neighbors == 0)
  {
    std::vector<std::uint32_t>().swap(out.neighbor_indices);
    std::vector<std::size_t>().swap(out.neighbor_offsets);
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_ESTIMATE_NORMALS_H
