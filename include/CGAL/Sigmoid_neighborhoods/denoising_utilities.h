// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_DENOISING_UTILITIES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_DENOISING_UTILITIES_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  \brief the mean over all points of their mean distance to their `k` nearest other points: the
  spacing `l` of the denoising experiment with `k = 6` (SPEC §7), the scale `m` of the normal filter
  with `k = 12`.

  Unlike `CGAL::compute_average_spacing()`, which divides the sum of the `k` distances by `k + 1`
  (the point itself counts), this is the mean of the `k` distances. Per-point means are summed in
  the order of `points`: the value is the same for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of `point_map`
  \tparam NamedParameters a sequence of named parameters
  \param points the points
  \param k the number of neighbors of each point
  \param np optional: `point_map` (CGAL), as in `compute_optimal_sigmoid_neighborhoods()`
  \pre `k >= 1`, at least `k + 1` points with finite coordinates; otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
double compute_mean_neighbor_distance(const PointRange& points, unsigned int k,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  const unsigned int threads = internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np));
  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np), threads);
  return internal::mean_neighbor_distance<ConcurrencyTag>(internal::Neighbor_query(copy, threads), k,
                                                          internal::number_of_threads(np));
}

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  \brief moves every point along its unit normal by a Gaussian offset: `p_i <- p_i + e_i n_i`,
  `e_i ~ N(0, standard_deviation^2)` (SPEC §7).

  The offsets are drawn in the order of `points`, one per point, from `std::mt19937_64(seed)`
  through `std::normal_distribution<double>`: the same seed gives the same points (with one
  standard library; the distribution's algorithm is implementation-defined).

  \tparam PointRange a model of `Range` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters
  \param points the points, moved in place through `point_map`
  \param standard_deviation the standard deviation of the offsets, finite and `>= 0`
  \param seed the seed of the random engine
  \param np `point_map` (CGAL, a `ReadWritePropertyMap`), `normal_map` (CGAL, required): the
         direction of the offset, normalised here
  \pre non-zero finite normals; otherwise `std::invalid_argument`
*/
template <typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
void add_normal_noise(PointRange& points, double standard_deviation, std::uint64_t seed,
                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "add_normal_noise() needs a normal map");
  typedef typename NP_helper::Point_map Point_map;
  typedef typename boost::property_traits<Point_map>::value_type Point;
  if(!(standard_deviation >= 0. && std::isfinite(standard_deviation)))
    throw std::invalid_argument("the noise standard deviation must be finite and >= 0, got " +
                                std::to_string(standard_deviation));
  Point_map point_map = NP_helper::get_point_map(points, np);
  const auto normal_map = NP_helper::get_normal_map(points, np);
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> offset(0., standard_deviation);
  std::size_t i = 0;
  for(auto& item : points)
  {
    const auto& n = get(normal_map, item);
    const double nx = CGAL::to_double(n.x()), ny = CGAL::to_double(n.y()), nz = CGAL::to_double(n.z());
    const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
    if(!(length > 0.) || !std::isfinite(length))
      throw std::invalid_argument("point " + std::to_string(i) + " has a zero or non-finite normal");
    const double e = standard_deviation > 0. ? offset(engine) : 0.;
    const Point p = get(point_map, item);
    put(point_map, item,
        Point(CGAL::to_double(p.x()) + e * (nx / length), CGAL::to_double(p.y()) + e * (ny / length),
              CGAL::to_double(p.z()) + e * (nz / length)));
    ++i;
  }
}

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  `|n - m|^2` for two vectors whose coordinates are read as `v[0]`, `v[1]`, `v[2]`
  (a CGAL `Vector_3`, `Eigen::Vector3d`).
*/
template <typename Vector1, typename Vector2>
double normal_squared_error(const Vector1& n, const Vector2& m)
{
  const double dx = CGAL::to_double(n[0]) - CGAL::to_double(m[0]);
  const double dy = CGAL::to_double(n[1]) - CGAL::to_double(m[1]);
  const double dz = CGAL::to_double(n[2]) - CGAL::to_double(m[2]);
  return dx * dx + dy * dy + dz * dz;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  \brief the mean squared error `(1/n) sum_i |n_i - m_i|^2` of normals against reference normals
  (SPEC §7), summed in order. For unit normals it lies in `[0, 4]`: 0 for equal normals, 4 for
  opposite ones.
  \pre both ranges hold the same number `n >= 1` of vectors; otherwise `std::invalid_argument`
*/
template <typename VectorRange1, typename VectorRange2>
double normal_mse(const VectorRange1& reference, const VectorRange2& normals)
{
  auto r = std::begin(reference);
  auto m = std::begin(normals);
  double sum = 0.;
  std::size_t count = 0;
  for(; r != std::end(reference) && m != std::end(normals); ++r, ++m, ++count)
    sum += normal_squared_error(*r, *m);
  if(r != std::end(reference) || m != std::end(normals))
    throw std::invalid_argument("normal_mse(): the two ranges have different sizes");
  if(count == 0)
    throw std::invalid_argument("normal_mse(): no normals");
  return sum / double(count);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_DENOISING_UTILITIES_H
