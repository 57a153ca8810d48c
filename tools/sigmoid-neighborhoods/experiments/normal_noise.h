// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise and the error measure of the denoising experiments (SPEC §7): Gaussian offsets along
// the normals, and the mean squared error of normals against reference normals.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_NORMAL_NOISE_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_NORMAL_NOISE_H

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*
  moves every point along its unit normal by a Gaussian offset: `p_i <- p_i + e_i n_i`,
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

/*
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

/*
  the mean squared error `(1/n) sum_i |n_i - m_i|^2` of normals against reference normals
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

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_NORMAL_NOISE_H
