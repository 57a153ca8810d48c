// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_ESTIMATE_NORMALS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_ESTIMATE_NORMALS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Normal_estimation_method.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The unit normal of every point of `query` from its k nearest other points, on `threads` threads
// (kernel_threads()): the kernel (config.h) of estimate_normals(), in estimate_normals_impl.h.
CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION std::vector<Eigen::Vector3d>
estimate_normals_all(const Neighbor_query& query, unsigned int k, Normal_estimation_method method, unsigned int degree,
                     unsigned int threads);

// Writes one unit normal per item of `points` through the normal map of `np`.
template <typename PointRange, typename NamedParameters>
void write_normals(PointRange& points, const std::vector<Eigen::Vector3d>& normals, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename boost::property_traits<typename NP_helper::Normal_map>::value_type Vector;
  const auto normal_map = NP_helper::get_normal_map(points, np);
  std::size_t i = 0;
  for(auto& item : points)
  {
    const Eigen::Vector3d& n = normals[i++];
    put(normal_map, item, Vector(n[0], n[1], n[2]));
  }
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief estimates an unoriented unit normal at every point from the point and its `k` nearest other
  points (ties by index, SPEC §2; CGAL's convention for `k`), and writes it to `normal_map`.

  `Normal_estimation_method::PCA` (the default): the eigenvector of the smallest eigenvalue of the
  covariance of the `k + 1` points, from Eigen's iterative solver (SPEC §4), as
  `CGAL::pca_estimate_normals()`; `Normal_estimation_method::JET`: the normal of the jet of degree
  `degree_fitting` fitted by `CGAL::Monge_via_jet_fitting`, as `CGAL::jet_estimate_normals()`. PCA is
  the default for its speed (4 to 5 times jet fitting's) and its accuracy on noisy data
  (`benchmark/README.md`, "Normal estimation"); jet fitting is more accurate on curved surfaces
  without noise. On the same
  neighbors, both give CGAL's normals up to rounding and sign. The neighbors come from the
  package's kd-tree, or from `neighbor_indices` and `neighbor_offsets` (the first `k` entries
  of each row). Every point is computed on its own, in the package's parallel loop: the normals
  are the same, bit for bit, for any number of threads. Their sign is not decided (orientation is
  a separate step).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `Range` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters

  \param points the points
  \param k the number of neighbors of each point: each fit takes `k + 1` points
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose value type is a `Point_3` of a CGAL kernel}
      \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map receiving the unit normals}
      \cgalParamType{a model of `WritablePropertyMap` whose value type is a `Vector_3` of a CGAL kernel}
      \cgalParamDefault{none: required (a static assertion fails without it)}
    \cgalParamNEnd
    \cgalParamNBegin{normal_estimation_method}
      \cgalParamDescription{PCA or jet fitting}
      \cgalParamType{`Normal_estimation_method`}
      \cgalParamDefault{`Normal_estimation_method::PCA`}
    \cgalParamNEnd
    \cgalParamNBegin{degree_fitting}
      \cgalParamDescription{the degree of the jet (CGAL's named parameter)}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::JET_DEGREE` (2)}
      \cgalParamExtra{jet fitting needs `k + 1 >= (d + 1)(d + 2) / 2` points}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_threads}
      \cgalParamDescription{the threads of a call with `CGAL::Parallel_tag`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{0: OpenMP's or TBB's default}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `k >= 2` (PCA) or `k + 1 >= (d + 1)(d + 2) / 2` (jet); at least `k + 1` points; finite coordinates;
  no point whose neighbors coincide with it or lie on a line (PCA) or within `1e-150` of it (jet): otherwise
  `std::invalid_argument`, never a zero normal
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
void estimate_normals(PointRange& points, unsigned int k, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "estimate_normals() needs a normal map");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Normal_estimation_method method =
    choose_parameter(get_parameter(np, internal_np::normal_estimation_method), defaults::NORMAL_ESTIMATION_METHOD);
  const unsigned int degree =
    choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), defaults::JET_DEGREE);
  // points per fit: a plane needs 3, a jet of degree d its (d + 1)(d + 2) / 2 coefficients
  const unsigned int fewest = method == Normal_estimation_method::PCA ? 3u : (degree + 1) * (degree + 2) / 2;
  if(std::size_t(k) + 1 < fewest)
    throw std::invalid_argument("estimate_normals(): " +
                                std::string(method == Normal_estimation_method::PCA ? "pca" : "jet fitting of degree " +
                                                                                                  std::to_string(degree)) +
                                " needs at least " + std::to_string(fewest - 1) + " neighbors per point, got k = " +
                                std::to_string(k));

  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np),
                             internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np)));
  if(copy.size() < std::size_t(k) + 1)
    throw std::invalid_argument("estimate_normals(): needs at least k + 1 = " + std::to_string(k + 1) +
                                " points, got " + std::to_string(copy.size()));
  const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(copy, np);
  internal::check_neighborhood_size(query, k);

  const std::vector<Eigen::Vector3d> normals = internal::estimate_normals_all(
    query, k, method, degree, internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np)));
  internal::write_normals(points, normals, np);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/estimate_normals_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_ESTIMATE_NORMALS_H
