// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_POINT_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_POINT_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/optimal_search_all.h>
#include <CGAL/Sigmoid_neighborhoods/internal/point_features_of.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

inline std::vector<unsigned int> checked_sizes(std::vector<unsigned int> sizes)
{
  if(sizes.empty())
    throw std::invalid_argument("no neighborhood size given");
  for(unsigned int k : sizes)
    if(k < 1)
      throw std::invalid_argument("the neighborhood size k must be at least 1");
  return sizes;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the `Point_features` of every point for one fixed sigmoid `(a, b)` at several
  neighborhood sizes (scales), all from one query of the largest size per point.

  The neighborhood of point `i` at size `k` is `i` and its `k` nearest other points (ties by index),
  the weights `w_ij = sigmoid(angle(n_i, n_j))`. The eigenvalue features are bit for bit those of
  `compute_sigmoid_features()` at the same `(a, b, k)`; the results are the same for any number of
  threads. Passing the named parameters `neighbor_indices` and `neighbor_offsets` (rows of at least
  the largest size) reuses a neighbor structure computed once for every call.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam OutputIterator an output iterator accepting `std::vector<Point_features>`: one per point,
         in the order of `points`, holding one record per size, in the order of `sizes`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param sigmoid the weights `sig_{a,b}` (`Cosine_sigmoid(CGAL_PI, CGAL_PI)`: equal weights)
  \param sizes the neighborhood sizes, each at least 1, in any order
  \param output receives the records
  \param np an optional sequence of named parameters: `point_map`, `normal_map`, `barycenter`,
    `line_angles`, `number_of_threads`, `neighbor_indices` and `neighbor_offsets`, as for
    `compute_sigmoid_features()`

  \pre at least `max(sizes) + 1` points; finite coordinates; non-zero finite normals
       (otherwise `std::invalid_argument`)
  \return the output iterator past the last record
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_point_features(const PointRange& points, const Cosine_sigmoid& sigmoid, const std::vector<unsigned int>& sizes,
                       OutputIterator output, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "compute_point_features() needs a normal map");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::vector<unsigned int> ks = internal::checked_sizes(sizes);
  const unsigned int k_max = *std::max_element(ks.begin(), ks.end());
  const auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np),
                                                    internal::line_angles(np));
  const Barycenter barycenter = choose_parameter(get_parameter(np, internal_np::barycenter), Barycenter::WEIGHTED);
  internal::check_enough_points(input.points.size(), k_max);
  const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(input.points, np);
  internal::check_neighborhood_size(query, k_max);
  internal::for_each_neighborhood<ConcurrencyTag, std::vector<Point_features>>(
    input, query, k_max, internal::number_of_threads(np), [] { return std::vector<double>(); },
    [&](std::size_t i, const internal::Local_neighborhood& local, std::vector<double>& w) {
      w.resize(local.size());
      local.weights(sigmoid, w.data());
      std::vector<Point_features> result;
      result.reserve(ks.size());
      for(unsigned int k : ks)
        result.push_back(internal::point_features_of(local, w.data(), k, barycenter, sigmoid, input.normals[i].z()));
      return result;
    },
    [&output](std::size_t, const std::vector<Point_features>& f) { *output++ = f; });
  return output;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief runs the optimal search of `compute_optimal_sigmoid_neighborhoods()` and gives every point
  the `Point_features` of its optimal neighborhood `(a*, b*, k*)`, in the search's own pass (one
  neighbor query; per point, the weights and covariance of the optimum once more and a closed-form
  eigenvector for the verticality).

  The named parameters select the search as for `compute_optimal_sigmoid_neighborhoods()`: the grid
  (`a_grid`, `b_grid`, `k_min`, `k_max`) and the `criterion`. Two of its special cases are the
  classical optimal neighborhoods: `a_grid` and `b_grid` `{pi}` with `Neighborhood_criterion::EIGENENTROPY`
  is the eigenentropy-optimal `k` of Weinmann et al. (2015), with the default criterion the
  `E_dim`-optimal `k` of Demantke et al. (2011), both with equal weights.
  The eigenvalue features, `k`, `a` and `b` are bit for bit those of the search's record. A point
  where every triple is degenerate (a failure) gets a degenerate record with `k = 0`.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam OutputIterator an output iterator accepting `Point_features`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param output receives one record per point, in the order of `points`
  \param np the named parameters of `compute_optimal_sigmoid_neighborhoods()`

  \return the output iterator past the last record
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_optimal_point_features(const PointRange& points, OutputIterator output,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  auto discard = boost::make_function_output_iterator([](const Optimal_sigmoid_neighborhood&) {});
  return compute_optimal_point_features<ConcurrencyTag>(points, discard, output, np).second;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief the same pass, writing each point's search record as well: what
  `compute_optimal_sigmoid_neighborhoods()` writes (with `error_equal` and `k_equal`) and the
  `Point_features` of the optimum, from one neighbor query and one search.

  \tparam RecordOutputIterator an output iterator accepting `Optimal_sigmoid_neighborhood`
  \tparam FeatureOutputIterator an output iterator accepting `Point_features`

  \param points the input points, with oriented normals
  \param records receives one search record per point, in the order of `points`, bit for bit those
         of `compute_optimal_sigmoid_neighborhoods()` with the same named parameters
  \param features receives one `Point_features` per point, in the order of `points`
  \param np the named parameters of `compute_optimal_sigmoid_neighborhoods()`

  \return both output iterators past their last record
*/
template <typename ConcurrencyTag, typename PointRange, typename RecordOutputIterator, typename FeatureOutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
std::pair<RecordOutputIterator, FeatureOutputIterator>
#else
std::enable_if_t<internal::is_range<PointRange>::value, std::pair<RecordOutputIterator, FeatureOutputIterator>>
#endif
compute_optimal_point_features(const PointRange& points, RecordOutputIterator records, FeatureOutputIterator features,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "compute_optimal_point_features() needs a normal map");
  const auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np),
                                                    internal::line_angles(np));
  const internal::Search_settings settings = internal::search_settings(np);
  internal::check_enough_points(input.size(), settings.k_max);
  const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(input.points, np);
  internal::check_neighborhood_size(query, settings.k_max);
  internal::optimal_point_features_all<ConcurrencyTag>(
    input, query, settings, [&](std::size_t, const Optimal_sigmoid_neighborhood& record, const Point_features& f) {
      *records++ = record;
      *features++ = f;
    });
  return {records, features};
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_POINT_FEATURES_H
