// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/optimal_search_all.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

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
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param output receives one record per point, in the order of `points`
  \param np an optional sequence of named parameters among the ones listed below: CGAL's
    (`CGAL::parameters`) and the package's (`CGAL::Sigmoid_neighborhoods::parameters`, which come
    first in a chain, see \ref Sigmoid_neighborhoods_named_parameters)

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Point_3` of a CGAL kernel}
      \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
      \cgalParamExtra{coordinates are converted to `double`; they must be finite}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map associating oriented normals to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Vector_3` of a CGAL kernel}
      \cgalParamDefault{none: required (a static assertion fails without it), except for a
        `CGAL::Point_set_3`, whose normal map is the default}
      \cgalParamExtra{normals need not be unit length; a zero or non-finite normal is an error}
    \cgalParamNEnd
    \cgalParamNBegin{k_min}
      \cgalParamDescription{the smallest neighborhood size of the search, `K = {k_min, ..., k_max}`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::K_MIN` (6)}
      \cgalParamExtra{`1 <= k_min <= k_max`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{k_max}
      \cgalParamDescription{the largest neighborhood size of the search}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::K_MAX` (20)}
      \cgalParamExtra{at least `k_max + 1` points are needed}
    \cgalParamNEnd
    \cgalParamNBegin{a_grid}
      \cgalParamDescription{the values of `a` (radians) that the search visits}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{`defaults::angle_grid()`: `{0, pi/6, pi/3, pi/2, 2pi/3, 5pi/6, pi}`}
      \cgalParamExtra{values in `[0, pi]`, sorted and deduplicated; only pairs with `a <= b` are searched}
    \cgalParamNEnd
    \cgalParamNBegin{b_grid}
      \cgalParamDescription{the values of `b` (radians) that the search visits}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{`defaults::angle_grid()`}
      \cgalParamExtra{as `a_grid`; at least one pair `a <= b` must exist}
    \cgalParamNEnd
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
    \cgalParamNBegin{criterion}
      \cgalParamDescription{what the search minimises: `E_dim` or the eigenentropy}
      \cgalParamType{`Neighborhood_criterion`}
      \cgalParamDefault{`Neighborhood_criterion::DIMENSIONALITY`}
    \cgalParamNEnd
    \cgalParamNBegin{angle_tolerance}
      \cgalParamDescription{angles between normals up to it (radians) count as 0}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::ANGLE_TOLERANCE` (`1e-6`)}
      \cgalParamExtra{in `[0, pi)`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{vector_instructions}
      \cgalParamDescription{the vector instructions of the batched eigenvalues; the records are the same bits on each}
      \cgalParamType{`Vector_instructions`}
      \cgalParamDefault{`widest_vector_instructions()`}
      \cgalParamExtra{one that `has_vector_instructions()` allows, otherwise `std::invalid_argument`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre at least `k_max + 1` points; finite coordinates; non-zero finite normals.
  Violations throw `std::invalid_argument` with a message naming the point.
  \return the output iterator past the last record
  \sa `compute_sigmoid_features()` for one fixed sigmoid, `evaluate_sigmoid_neighborhoods()` for
  the evaluation of the paper's Section 5
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_optimal_sigmoid_neighborhoods(const PointRange& points, OutputIterator output,
                                                     const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "compute_optimal_sigmoid_neighborhoods() needs a normal map");
  const auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np),
                                                    internal::line_angles(np));
  const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(input.points, np);
  internal::optimal_search_all<ConcurrencyTag>(
    input, query, internal::search_settings(np),
    [&output](std::size_t, const Optimal_sigmoid_neighborhood& r) { *output++ = r; });
  return output;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief the same search on the vertices of a mesh, a `Surface_mesh`, a `Polyhedron_3` or any `FaceListGraph` (SPEC §1): vertex normals from
  `Polygon_mesh_processing::compute_vertex_normals()` unless `vertex_normal_map` is given,
  vertices at one position merged (the smallest index kept, its copies get its record),
  vertices without a face or with an undefined normal left out (they get a failure record).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Sigmoid_neighborhoods::Parallel_if_available_tag`
  \tparam PolygonMesh a model of `FaceListGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3` ...)
  \tparam VertexRecordMap a model of `WritablePropertyMap` with the mesh's vertex descriptor as key
          type and `Optimal_sigmoid_neighborhood` as value type
  \tparam NamedParameters a sequence of named parameters

  \param mesh the input mesh; vertex positions are read from `vertex_point_map`
  \param vertex_records receives the record of every vertex
  \param np an optional sequence of named parameters among the ones listed below: CGAL's
    (`CGAL::parameters`) and the package's (`CGAL::Sigmoid_neighborhoods::parameters`, which come
    first in a chain, see \ref Sigmoid_neighborhoods_named_parameters)

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as key type and
        a `Point_3` of a CGAL kernel as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{a property map associating to each vertex of `mesh` a unique index}
      \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as key type and
        `std::size_t` as value type}
      \cgalParamDefault{an automatically indexed internal map}
      \cgalParamExtra{vertices at one position are merged into the one of smallest index}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{a property map associating oriented normals to the vertices of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as key type and
        a `Vector_3` of the kernel of `Point` as value type}
      \cgalParamDefault{the normals of `CGAL::Polygon_mesh_processing::compute_vertex_normals()`}
      \cgalParamExtra{a vertex whose normal is zero or not finite is left out}
    \cgalParamNEnd
    \cgalParamNBegin{k_min}
      \cgalParamDescription{the smallest neighborhood size of the search, `K = {k_min, ..., k_max}`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::K_MIN` (6)}
      \cgalParamExtra{`1 <= k_min <= k_max`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{k_max}
      \cgalParamDescription{the largest neighborhood size of the search}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::K_MAX` (20)}
      \cgalParamExtra{at least `k_max + 1` points are needed}
    \cgalParamNEnd
    \cgalParamNBegin{a_grid}
      \cgalParamDescription{the values of `a` (radians) that the search visits}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{`defaults::angle_grid()`: `{0, pi/6, pi/3, pi/2, 2pi/3, 5pi/6, pi}`}
      \cgalParamExtra{values in `[0, pi]`, sorted and deduplicated; only pairs with `a <= b` are searched}
    \cgalParamNEnd
    \cgalParamNBegin{b_grid}
      \cgalParamDescription{the values of `b` (radians) that the search visits}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{`defaults::angle_grid()`}
      \cgalParamExtra{as `a_grid`; at least one pair `a <= b` must exist}
    \cgalParamNEnd
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
    \cgalParamNBegin{criterion}
      \cgalParamDescription{what the search minimises: `E_dim` or the eigenentropy}
      \cgalParamType{`Neighborhood_criterion`}
      \cgalParamDefault{`Neighborhood_criterion::DIMENSIONALITY`}
    \cgalParamNEnd
    \cgalParamNBegin{angle_tolerance}
      \cgalParamDescription{angles between normals up to it (radians) count as 0}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::ANGLE_TOLERANCE` (`1e-6`)}
      \cgalParamExtra{in `[0, pi)`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre at least `k_max + 1` points after merging; finite coordinates
  (otherwise `std::invalid_argument`)
  \return how vertices became points
*/
template <typename ConcurrencyTag, typename PolygonMesh, typename VertexRecordMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Mesh_points_summary
#else
std::enable_if_t<!internal::is_range<PolygonMesh>::value, Mesh_points_summary>
#endif
compute_optimal_sigmoid_neighborhoods(const PolygonMesh& mesh, VertexRecordMap vertex_records,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  const auto mesh_points = internal::mesh_points(mesh, np);
  std::vector<Optimal_sigmoid_neighborhood> records(mesh_points.input.size());
  const internal::Neighbor_query query(mesh_points.input.points);
  internal::optimal_search_all<ConcurrencyTag>(
    mesh_points.input, query, internal::search_settings(np),
    [&records](std::size_t i, const Optimal_sigmoid_neighborhood& r) { records[i] = r; });
  std::size_t t = 0;
  for(auto v : vertices(mesh))
  {
    const std::uint32_t i = mesh_points.point_in_vertex_order[t++];
    put(vertex_records, v, i == internal::NO_POINT ? Optimal_sigmoid_neighborhood() : records[i]);
  }
  return mesh_points.summary;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_OPTIMAL_SIGMOID_NEIGHBORHOODS_H
