// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_SIGMOID_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_SIGMOID_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename ConcurrencyTag>
std::vector<Dimensionality_features> features_all(const Oriented_points& input, const Neighbor_query& query,
                                                  const Cosine_sigmoid& sigmoid, unsigned int k,
                                                  Barycenter barycenter, unsigned int threads)
{
  if(k < 1)
    throw std::invalid_argument("the neighborhood size k must be at least 1");
  check_enough_points(input.size(), k);
  check_neighborhood_size(query, k);
  std::vector<Dimensionality_features> result(input.size());
  for_each_neighborhood<ConcurrencyTag, Dimensionality_features>(
    input, query, k, threads, [] { return std::vector<double>(); },
    [&](std::size_t, const Local_neighborhood& local, std::vector<double>& weights) {
      weights.resize(local.size());
      local.weights(sigmoid, weights.data());
      return local.features(weights.data(), k, barycenter);
    },
    [&result](std::size_t i, const Dimensionality_features& f) { result[i] = f; });
  return result;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the dimensionality features (eigenvalues, linearity, planarity, scattering,
  `E_dim`, label) of every point for one fixed sigmoid `(a, b)` and neighborhood size `k`.

  The neighborhood of point `i` is `i` and its `k` nearest other points (ties by index), the
  weights `w_ij = sigmoid(angle(n_i, n_j))`. The angle tolerance is the one of `sigmoid`.
  A degenerate neighborhood gives a record with `error = +inf` and the label
  `Dimensionality::DEGENERATE`. The results are the same, bit for bit, for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Sigmoid_neighborhoods::Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam OutputIterator an output iterator accepting `Dimensionality_features`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param sigmoid the weights `sig_{a,b}`
  \param k the number of neighbors of each point
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
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre at least `k + 1` points, `k >= 1`; finite coordinates; non-zero finite normals
       (otherwise `std::invalid_argument`)
  \return the output iterator past the last record
  \sa `compute_optimal_sigmoid_neighborhoods()`, which searches `(a, b, k)` for every point
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_sigmoid_features(const PointRange& points, const Cosine_sigmoid& sigmoid, unsigned int k,
                                        OutputIterator output,
                                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "compute_sigmoid_features() needs a normal map");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np),
                                                    internal::line_angles(np));
  const Barycenter barycenter = choose_parameter(get_parameter(np, internal_np::barycenter), Barycenter::WEIGHTED);
  const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(input.points, np);
  for(const Dimensionality_features& f : internal::features_all<ConcurrencyTag>(input, query, sigmoid, k, barycenter,
                                                                                internal::number_of_threads(np)))
    *output++ = f;
  return output;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the same features on the vertices of a mesh (any `FaceListGraph`), with the vertex
  handling of `compute_optimal_sigmoid_neighborhoods()`: vertex normals from
  `CGAL::Polygon_mesh_processing::compute_vertex_normals()` unless `vertex_normal_map` is given,
  vertices at one position merged (the smallest index is computed, its copies get its record),
  vertices without a face or with an undefined normal left out (they get a degenerate record).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Sigmoid_neighborhoods::Parallel_if_available_tag`
  \tparam PolygonMesh a model of `FaceListGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3` ...)
  \tparam VertexFeatureMap a model of `WritablePropertyMap` with the mesh's vertex descriptor as
          key type and `Dimensionality_features` as value type
  \tparam NamedParameters a sequence of named parameters

  \param mesh the input mesh; vertex positions are read from `vertex_point_map`
  \param sigmoid the weights `sig_{a,b}`
  \param k the number of neighbors of each point
  \param vertex_features receives the record of every vertex
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
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre at least `k + 1` points after merging, `k >= 1`; finite coordinates
       (otherwise `std::invalid_argument`)
  \return how the vertices became points
*/
template <typename ConcurrencyTag, typename PolygonMesh, typename VertexFeatureMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Mesh_points_summary
#else
std::enable_if_t<!internal::is_range<PolygonMesh>::value, Mesh_points_summary>
#endif
compute_sigmoid_features(const PolygonMesh& mesh, const Cosine_sigmoid& sigmoid,
                                             unsigned int k, VertexFeatureMap vertex_features,
                                             const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto mesh_points = internal::mesh_points(mesh, np);
  const Barycenter barycenter = choose_parameter(get_parameter(np, internal_np::barycenter), Barycenter::WEIGHTED);
  const internal::Neighbor_query query(mesh_points.input.points);
  const auto features = internal::features_all<ConcurrencyTag>(mesh_points.input, query, sigmoid, k, barycenter,
                                                               internal::number_of_threads(np));
  std::size_t t = 0;
  for(auto v : vertices(mesh))
  {
    const std::uint32_t i = mesh_points.point_in_vertex_order[t++];
    put(vertex_features, v, i == internal::NO_POINT ? Dimensionality_features() : features[i]);
  }
  return mesh_points.summary;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_SIGMOID_FEATURES_H
