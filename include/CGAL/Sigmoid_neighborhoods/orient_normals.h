// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_ORIENT_NORMALS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_ORIENT_NORMALS_H

#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Prim's algorithm on Hoppe's graph with its weights 1 - |n_i . n_j|, from the highest point not yet
// reached as long as one is left: a minimum spanning forest, each tree seeded with its highest point
// turned towards +z. A point's normal is turned to agree with its parent's when the point leaves the
// heap, as CGAL's breadth-first walk of the tree turns it. Returns the number of trees. A kernel
// (config.h), in orient_normals_impl.h.
CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::size_t orient_along_spanning_forest(const std::vector<Double_point>& points,
                                                                            const Neighbor_query& query, unsigned int k,
                                                                            std::vector<Eigen::Vector3d>& normals,
                                                                            unsigned int threads);

template <typename PointRange, typename NamedParameters>
Oriented_points checked_oriented_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  static_assert(NP_helper::has_normal_map(), "orienting normals needs a normal map");
  return copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                              NP_helper::get_normal_map(points, np));
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief orients the normals of `points` along a minimum spanning forest of their `k`-nearest-neighbor
  graph, and returns the number of its trees (the graph's connected components).

  As `CGAL::mst_orient_normals()` (Hoppe et al. 1992): edge `i-j` when either point is among the `k`
  nearest other points of the other (SPEC §2's ties by index), weight `1 - |n_i . n_j|`; the tree
  is walked from its highest point, turned towards `+z`, each normal turned to agree with its
  parent's. Unlike CGAL's, every connected component is a tree of its own seeded the same way, so that
  every point is oriented; a point set with more than one component reports it in the result. The
  neighbors come from the package's kd-tree, or from `neighbor_indices` and `neighbor_offsets` (the
  first `k` entries of each row): the ones `estimate_normals()` used, so that both steps share one
  neighbor structure (pass them with `std::cref()`: CGAL's named parameters copy what they hold).
  The forest is the minimum one in the total order of the edges by weight, then by their endpoints'
  indices (ties broken by index), found by Boruvka's rounds in the package's parallel loop: the
  result is the same for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `Range` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters

  \param points the points
  \param k the number of neighbors of each point in the graph
  \param np `point_map`, `normal_map` (required, read and written: normals up to sign, e.g. from
  `estimate_normals()`, written back as unit vectors), `number_of_threads`, `neighbor_indices` and
  `neighbor_offsets` (rows of at least `min(k, n - 1)` neighbors)

  \pre `k >= 1`; finite coordinates; nonzero finite normals; otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t orient_normals_by_spanning_forest(PointRange& points, unsigned int k,
                                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  if(k < 1)
    throw std::invalid_argument("orient_normals_by_spanning_forest(): k must be at least 1");
  internal::Oriented_points input = internal::checked_oriented_points(points, np);
  if(input.size() == 0)
    return 0;
  const unsigned int threads = internal::number_of_threads(np);
  std::size_t trees = 0;
  {
    const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(input.points, np);
    internal::check_neighborhood_size(query, (std::min)(k, unsigned(input.size() - 1)));
    if(query.is_given())
      trees = internal::orient_along_spanning_forest(input.points, query, k, input.normals,
                                                     internal::kernel_threads<ConcurrencyTag>(threads));
    else
    {
      // the walk reads the rows of every point twice and sequentially: computed once, in parallel
      const internal::Neighbor_lists rows = internal::nearest_neighbor_rows(query, k, internal::kernel_threads<ConcurrencyTag>(threads));
      const internal::Neighbor_query given(input.points, rows.offsets.data(), rows.indices.data());
      trees = internal::orient_along_spanning_forest(input.points, given, k, input.normals,
                                                     internal::kernel_threads<ConcurrencyTag>(threads));
    }
  }
  internal::write_normals(points, input.normals, np);
  return trees;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief turns every normal of `points` towards `viewpoint` (the position of the scanner of a
  terrestrial scan): a normal `n` at `p` is reversed where its dot product with `viewpoint - p` is
  negative. A normal perpendicular to the line of sight is left as it is.

  \param points the points
  \param viewpoint the position the normals face, a `Point_3` of a CGAL kernel
  \param np `point_map` and `normal_map` (required, read and written back as unit vectors)

  \pre finite coordinates; nonzero finite normals; otherwise `std::invalid_argument`
*/
template <typename PointRange, typename Point, typename CGAL_NP_TEMPLATE_PARAMETERS>
void orient_normals_towards_viewpoint(PointRange& points, const Point& viewpoint,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::Oriented_points input = internal::checked_oriented_points(points, np);
  const Eigen::Vector3d eye(CGAL::to_double(viewpoint.x()), CGAL::to_double(viewpoint.y()),
                            CGAL::to_double(viewpoint.z()));
  if(!eye.allFinite())
    throw std::invalid_argument("orient_normals_towards_viewpoint(): the viewpoint has a non-finite coordinate");
  for(std::size_t i = 0; i < input.size(); ++i)
  {
    const internal::Double_point& p = input.points[i];
    const Eigen::Vector3d sight = eye - Eigen::Vector3d(p.x(), p.y(), p.z());
    if(input.normals[i].dot(sight) < 0.)
      input.normals[i] = -input.normals[i];
  }
  internal::write_normals(points, input.normals, np);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/orient_normals_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_ORIENT_NORMALS_H
