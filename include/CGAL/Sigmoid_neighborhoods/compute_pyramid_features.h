// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_PYRAMID_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_PYRAMID_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/thin_on_voxel_grid.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  one level of a point pyramid (`build_point_pyramid()`): the point set thinned on a voxel grid and
  the `k` nearest other representatives of every representative, in compressed rows of positions in
  `thinning.representatives` (as `compute_k_nearest_neighbors()` writes them).
*/
struct Pyramid_level
{
  Voxel_thinning thinning;                     ///< the representatives and every point's nearest one
  std::vector<std::uint32_t> neighbor_indices; ///< the rows among the representatives
  std::vector<std::size_t> neighbor_offsets;   ///< their `m + 1` offsets, `m` representatives
};

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief builds a pyramid of `points`: per cell size, the points thinned on a voxel grid with
  `thin_on_voxel_grid()` and the `k` nearest neighbors of each representative among the
  representatives, with `compute_k_nearest_neighbors()`: one neighbor structure per level.

  Scales in the unit of the coordinates rather than in neighbor counts: a level's neighborhoods
  have about the same extent at any density above one point per cell, so that features computed on
  them transfer between surveys of different densities (Hackel et al. 2016). The result is the same
  for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
  \tparam NamedParameters a sequence of named parameters

  \param points the input points
  \param cell_sizes the cell sizes of the levels, each positive and finite, in any order
  \param k the number of neighbors of a representative on its level
  \param np optional: `point_map` (CGAL's), `number_of_threads` and `neighbor_search`

  \pre `k >= 1`; at least `k + 1` representatives on every level; the preconditions of
       `thin_on_voxel_grid()` (otherwise `std::invalid_argument`)
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
std::vector<Pyramid_level>
#else
std::enable_if_t<internal::is_range<PointRange>::value, std::vector<Pyramid_level>>
#endif
build_point_pyramid(const PointRange& points, const std::vector<double>& cell_sizes, unsigned int k,
                    const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  if(cell_sizes.empty())
    throw std::invalid_argument("a pyramid needs at least one cell size");
  if(k < 1)
    throw std::invalid_argument("the number of neighbors k must be at least 1");
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const unsigned int threads = internal::number_of_threads(np);
  std::vector<Pyramid_level> levels;
  levels.reserve(cell_sizes.size());
  for(double cell_size : cell_sizes)
  {
    Pyramid_level level;
    level.thinning = thin_on_voxel_grid<ConcurrencyTag>(
      points, cell_size, parameters::number_of_threads(threads, CGAL::parameters::point_map(point_map)));
    const std::vector<std::uint32_t>& representatives = level.thinning.representatives;
    if(representatives.size() < std::size_t(k) + 1)
      throw std::invalid_argument("the pyramid level of cell size " + std::to_string(cell_size) + " has " +
                                  std::to_string(representatives.size()) + " representatives, fewer than k + 1 = " +
                                  std::to_string(k + 1));
    std::vector<typename boost::property_traits<decltype(point_map)>::value_type> positions;
    positions.reserve(representatives.size());
    auto item = std::begin(points);
    std::size_t at = 0;
    for(std::uint32_t r : representatives)
    {
      std::advance(item, std::ptrdiff_t(r - at));
      at = r;
      positions.push_back(get(point_map, *item));
    }
    std::vector<std::size_t> range(positions.size());
    for(std::size_t i = 0; i < range.size(); ++i)
      range[i] = i;
    compute_k_nearest_neighbors<ConcurrencyTag>(
      range, k, level.neighbor_indices, level.neighbor_offsets,
      parameters::neighbor_search(internal::neighbor_search(np),
                                  parameters::number_of_threads(
                                    threads, CGAL::parameters::point_map(CGAL::make_property_map(positions)))));
    levels.push_back(std::move(level));
  }
  return levels;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the `Point_features` of the representatives of every level of a pyramid: on each
  level, `compute_point_features()` at size `k` on the level's rows (weights `sigmoid` between the
  representatives' normals, the normals of the original points).

  A point's record on level `l` is `result[l][levels[l].thinning.nearest_representative[i]]`: what
  `compute_pyramid_features()` gives every point, without a vector of levels per point (a caller
  that stores the features by column reads them so, in parallel). The records are bit for bit those
  of `compute_point_features()` at `k` on the representatives alone, for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param levels the pyramid of `points` (`build_point_pyramid()`), rows of at least `k` neighbors
  \param k the neighborhood size on every level
  \param sigmoid the weights `sig_{a,b}` (`Cosine_sigmoid(CGAL_PI, CGAL_PI)`: equal weights)
  \param np an optional sequence of named parameters: `point_map`, `normal_map`, `barycenter`,
    `line_angles` and `number_of_threads`, as for `compute_point_features()`

  \pre `levels` built on `points`; finite coordinates; non-zero finite normals (otherwise
       `std::invalid_argument`)
  \return per level, the records of its representatives, in the order of `thinning.representatives`
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<std::vector<Point_features>>
compute_pyramid_level_features(const PointRange& points, const std::vector<Pyramid_level>& levels, unsigned int k,
                               const Cosine_sigmoid& sigmoid,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "the pyramid's features need a normal map");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const auto normal_map = NP_helper::get_normal_map(points, np);
  const Barycenter barycenter = choose_parameter(get_parameter(np, internal_np::barycenter), Barycenter::WEIGHTED);
  const bool line_angles = internal::line_angles(np);
  const unsigned int threads = internal::number_of_threads(np);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));

  std::vector<std::vector<Point_features>> per_level(levels.size());
  for(std::size_t l = 0; l < levels.size(); ++l)
  {
    const Pyramid_level& level = levels[l];
    if(level.thinning.nearest_representative.size() != n)
      throw std::invalid_argument("compute_pyramid_features(): a level of another point set");
    const std::vector<std::uint32_t>& representatives = level.thinning.representatives;
    std::vector<typename boost::property_traits<decltype(point_map)>::value_type> positions;
    std::vector<typename boost::property_traits<decltype(normal_map)>::value_type> normals;
    positions.reserve(representatives.size());
    normals.reserve(representatives.size());
    auto item = std::begin(points);
    std::size_t at = 0;
    for(std::uint32_t r : representatives)
    {
      std::advance(item, std::ptrdiff_t(r - at));
      at = r;
      positions.push_back(get(point_map, *item));
      normals.push_back(get(normal_map, *item));
    }
    std::vector<std::size_t> range(positions.size());
    for(std::size_t i = 0; i < range.size(); ++i)
      range[i] = i;
    std::vector<std::vector<Point_features>> records;
    records.reserve(range.size());
    compute_point_features<ConcurrencyTag>(
      range, sigmoid, std::vector<unsigned int>{k}, std::back_inserter(records),
      parameters::neighbor_indices(
        std::cref(level.neighbor_indices),
        parameters::neighbor_offsets(
          std::cref(level.neighbor_offsets),
          parameters::barycenter(
            barycenter,
            parameters::line_angles(
              line_angles, parameters::number_of_threads(threads, CGAL::parameters::point_map(
                                                                    CGAL::make_property_map(positions))
                                                                    .normal_map(CGAL::make_property_map(normals))))))));
    per_level[l].reserve(records.size());
    for(const std::vector<Point_features>& r : records)
      per_level[l].push_back(r.front());
  }
  return per_level;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the `Point_features` of every point on every level of a pyramid: on each level,
  those of the representatives with `compute_point_features()` at size `k` on the level's rows
  (weights `sigmoid` between the representatives' normals, the normals of the original points), and
  every point given the record of its nearest representative (`Voxel_thinning::nearest_representative`).

  Each level's records are bit for bit those of `compute_point_features()` at `k` on the
  representatives alone (`compute_pyramid_level_features()`); the results are the same for any
  number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam OutputIterator an output iterator accepting `std::vector<Point_features>`: one per point,
         in the order of `points`, holding one record per level, in the order of `levels`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param levels the pyramid of `points` (`build_point_pyramid()`), rows of at least `k` neighbors
  \param k the neighborhood size on every level
  \param sigmoid the weights `sig_{a,b}` (`Cosine_sigmoid(CGAL_PI, CGAL_PI)`: equal weights)
  \param output receives the records
  \param np an optional sequence of named parameters: `point_map`, `normal_map`, `barycenter`,
    `line_angles` and `number_of_threads`, as for `compute_point_features()`

  \pre `levels` built on `points`; finite coordinates; non-zero finite normals (otherwise
       `std::invalid_argument`)
  \return the output iterator past the last record
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_pyramid_features(const PointRange& points, const std::vector<Pyramid_level>& levels, unsigned int k,
                         const Cosine_sigmoid& sigmoid, OutputIterator output,
                         const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  const std::vector<std::vector<Point_features>> per_level =
    compute_pyramid_level_features<ConcurrencyTag>(points, levels, k, sigmoid, np);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  std::vector<Point_features> point(levels.size());
  for(std::size_t i = 0; i < n; ++i)
  {
    for(std::size_t l = 0; l < levels.size(); ++l)
      point[l] = per_level[l][levels[l].thinning.nearest_representative[i]];
    *output++ = point;
  }
  return output;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief the same on a pyramid built here: `build_point_pyramid()` with `cell_sizes` and `k`, then
  `compute_pyramid_features()` on it.

  \param points the input points, with oriented normals
  \param cell_sizes the cell sizes of the levels (e.g. `base * 2^l`, `l = 0 ... L - 1`)
  \param k the neighborhood size on every level
  \param sigmoid the weights `sig_{a,b}` (`Cosine_sigmoid(CGAL_PI, CGAL_PI)`: equal weights)
  \param output receives one `std::vector<Point_features>` per point, one record per cell size
  \param np the named parameters of both
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_pyramid_features(const PointRange& points, const std::vector<double>& cell_sizes, unsigned int k,
                         const Cosine_sigmoid& sigmoid, OutputIterator output,
                         const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return compute_pyramid_features<ConcurrencyTag>(points, build_point_pyramid<ConcurrencyTag>(points, cell_sizes, k, np),
                                                  k, sigmoid, output, np);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_PYRAMID_FEATURES_H
