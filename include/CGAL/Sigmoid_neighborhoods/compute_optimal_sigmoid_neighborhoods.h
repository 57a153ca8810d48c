// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Optimal_search.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes, for every point, the sigmoid parameters and neighborhood size
  `(a*, b*, k*)` of least classification error `E_dim` over a grid (the paper's Equation 9),
  and the best error with equal weights (`a = b = pi`, best `k`) in the same pass.

  The neighborhood of point `i` is `i` and its `k` nearest other points (ties by index), the
  weights `w_ij = sig_{a,b}(angle(n_i, n_j))`. Triples are visited `a` ascending, `b` ascending,
  `k` ascending, and one replaces the best only when smaller by more than `1e-12`. A point whose
  every triple is degenerate is a failure (`k == 0`, error `+inf`).
  One kd-tree is built and queried once per point for `k_max` neighbors. The results are the
  same, bit for bit, for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Sigmoid_neighborhoods::Parallel_if_available_tag` (OpenMP)
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam OutputIterator an output iterator accepting `Optimal_sigmoid_neighborhood`

  \param points the input points, with oriented normals
  \param output receives one record per point, in the order of `points`
  \param np optional named parameters:
    - `point_map`, `normal_map` (CGAL): the position and the oriented normal of an element
      (normals need not be unit; a zero or non-finite normal is an error);
      `normal_map` is required;
    - `geom_traits` (CGAL): the kernel of the maps' values;
    - `Sigmoid_neighborhoods::parameters::k_min`, `k_max`: the sizes `K = {k_min, ..., k_max}`
      (defaults 6 and 20);
    - `a_grid`, `b_grid`: `std::vector<double>` in `[0, pi]` (default `{0, pi/6, ..., pi}`);
      pairs with `a <= b` are searched;
    - `barycenter`: `Barycenter::WEIGHTED` (default) or `Barycenter::UNWEIGHTED`;
    - `angle_tolerance`: angles up to it count as 0 (default `1e-6`).
    Our parameters come first in a chain, CGAL's after.

  \pre at least `k_max + 1` points; finite coordinates; non-zero finite normals.
  Violations throw `std::invalid_argument` with a message naming the point.
  \return the output iterator past the last record
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
OutputIterator compute_optimal_sigmoid_neighborhoods(const PointRange& points, OutputIterator output,
                                                     const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "compute_optimal_sigmoid_neighborhoods() needs a normal map");
  const auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np));
  internal::optimal_search_all<ConcurrencyTag>(
    input, internal::search_settings(np),
    [&output](std::size_t, const Optimal_sigmoid_neighborhood& r) { *output++ = r; });
  return output;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief the same search on the vertices of a `Surface_mesh` (SPEC §1): vertex normals from
  `Polygon_mesh_processing::compute_vertex_normals()` unless `vertex_normal_map` is given,
  vertices at one position merged (the smallest index kept, its copies get its record),
  vertices without a face or with an undefined normal left out (they get a failure record).

  \tparam VertexRecordMap a `WritablePropertyMap` from vertex descriptors to `Optimal_sigmoid_neighborhood`

  \param np the parameters of the point range version but `point_map`/`normal_map`; and
    `vertex_normal_map` (CGAL): a `ReadablePropertyMap` to the oriented vertex normals.
  \return how vertices became points
*/
template <typename ConcurrencyTag, typename Point, typename VertexRecordMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Mesh_points_summary compute_optimal_sigmoid_neighborhoods(const CGAL::Surface_mesh<Point>& mesh,
                                                          VertexRecordMap vertex_records,
                                                          const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  const auto mesh_points = internal::mesh_points(mesh, np);
  std::vector<Optimal_sigmoid_neighborhood> records(mesh_points.input.size());
  internal::optimal_search_all<ConcurrencyTag>(
    mesh_points.input, internal::search_settings(np),
    [&records](std::size_t i, const Optimal_sigmoid_neighborhood& r) { records[i] = r; });
  for(auto v : mesh.vertices())
  {
    const std::uint32_t i = mesh_points.point_of_vertex[std::size_t(v)];
    put(vertex_records, v, i == internal::NO_POINT ? Optimal_sigmoid_neighborhood() : records[i]);
  }
  return mesh_points.summary;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H
