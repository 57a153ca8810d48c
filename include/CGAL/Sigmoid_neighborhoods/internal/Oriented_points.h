// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENTED_POINTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENTED_POINTS_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/number_utils.h>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The one place that owns the input of every algorithm: coordinates checked and converted to
// double, normals checked and made unit, each written once.
// The input as the computation sees it: double coordinates and unit normals.
struct Oriented_points
{
  std::vector<Double_point> points;
  std::vector<Eigen::Vector3d> normals;
  // The weights' angle is the one between the normals' lines, arccos |n_i . n_j| (named parameter
  // `line_angles`): for normals whose signs mean nothing.
  bool line_angles = false;
  std::size_t size() const { return points.size(); }

  // n_i . n_j, or its absolute value with line angles
  double cosine(std::size_t i, std::size_t j) const
  {
    const double c = normals[i].dot(normals[j]);
    return line_angles ? std::abs(c) : c;
  }
};

// Beyond this, squared distances overflow.
constexpr double LARGEST_COORDINATE = 1e150;
// Normals unit to this are used as given: normalising again would move their last bit.
constexpr double UNIT_NORMAL_TOLERANCE = 1e-12;

// The one check of a point's coordinates: finite and within LARGEST_COORDINATE; `what` and `i`
// name it in the message ("point 3", "vertex 3").
// `Error` is the exception type: the readers throw their Input_error.
template <typename Error = std::invalid_argument, typename Point>
Double_point checked_point(const Point& p, const char* what, std::size_t i)
{
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
  if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
    throw Error(std::string(what) + " " + std::to_string(i) + " has a non-finite coordinate");
  if(std::abs(x) > LARGEST_COORDINATE || std::abs(y) > LARGEST_COORDINATE || std::abs(z) > LARGEST_COORDINATE)
    throw Error(std::string(what) + " " + std::to_string(i) +
                " has a coordinate beyond 1e150, where squared distances overflow");
  return Double_point(x, y, z);
}

// The positions of a point range through its map, each checked by checked_point(): a range of
// random access on `threads` threads (0: the default) when every point is sound; otherwise, and
// for other ranges, in order, so that the message names the first fault whatever the threads.
template <typename PointRange, typename PointMap>
std::vector<Double_point> checked_points(const PointRange& range, PointMap point_map, unsigned int threads = 1)
{
  const std::size_t n = std::size_t(std::distance(std::begin(range), std::end(range)));
  typedef typename std::iterator_traits<decltype(std::begin(range))>::iterator_category Category;
  if constexpr(std::is_convertible<Category, std::random_access_iterator_tag>::value)
  {
    if(threads != 1 && n >= 4096)
    {
      std::vector<Double_point> result(n);
      std::atomic<bool> sound(true);
      const auto first = std::begin(range);
      for_each_index<Parallel_if_available_tag>(n, threads, [] { return 0; }, [&](std::size_t i, int) {
        try
        {
          result[i] = checked_point(get(point_map, *(first + std::ptrdiff_t(i))), "point", i);
        }
        catch(const std::invalid_argument&)
        {
          sound.store(false, std::memory_order_relaxed);
        }
      }, 4096);
      if(sound.load())
        return result;
    }
  }
  std::vector<Double_point> result;
  result.reserve(n);
  for(const auto& item : range)
    result.push_back(checked_point(get(point_map, item), "point", result.size()));
  return result;
}

// A normal as a unit vector in double, or false when it is zero or not finite (its squared
// length included: a normal too long to square is as unusable as an infinite one).
template <typename Vector>
bool unit_normal(const Vector& n, Eigen::Vector3d& normal)
{
  normal = Eigen::Vector3d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
  const double squared_norm = normal.squaredNorm();
  if(!normal.allFinite() || !std::isfinite(squared_norm) || !(squared_norm > 0.))
    return false;
  if(std::abs(squared_norm - 1.) > UNIT_NORMAL_TOLERANCE)
    normal /= std::sqrt(squared_norm);
  return true;
}

// True for a point range (std::begin() and std::end() apply), false for a mesh (a FaceListGraph such
// as Surface_mesh or Polyhedron_3): what tells the overloads of every algorithm apart.
template <typename T, typename = void>
struct is_range : std::false_type
{};
template <typename T>
struct is_range<T, std::void_t<decltype(std::begin(std::declval<const T&>())), decltype(std::end(std::declval<const T&>()))>>
  : std::true_type
{};

// Copies a point range through its maps, rejecting what the paper's features are undefined for.
template <typename PointRange, typename PointMap, typename NormalMap>
Oriented_points copy_oriented_points(const PointRange& range, PointMap point_map, NormalMap normal_map,
                                     bool line_angles = false)
{
  Oriented_points result;
  result.line_angles = line_angles;
  // reserved: growing by doubling would hold the old and the new buffer at once
  const auto size = std::distance(std::begin(range), std::end(range));
  result.points.reserve(std::size_t(size));
  result.normals.reserve(std::size_t(size));
  std::size_t i = 0;
  for(const auto& item : range)
  {
    result.points.push_back(checked_point(get(point_map, item), "point", i));
    Eigen::Vector3d normal;
    if(!unit_normal(get(normal_map, item), normal))
      throw std::invalid_argument("point " + std::to_string(i) + " has a " +
                                  (normal.isZero(0.) ? "zero" : "non-finite") +
                                  " normal");
    result.normals.push_back(normal);
    ++i;
  }
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIENTED_POINTS_H
