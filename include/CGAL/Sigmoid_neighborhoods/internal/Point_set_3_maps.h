// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// What the overloads on CGAL::Point_set_3 share: its maps and its properties.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_SET_3_MAPS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_SET_3_MAPS_H

#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/Iterator_range.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

template <typename Point, typename Vector>
void require_normal_map(const CGAL::Point_set_3<Point, Vector>& points, const char* function)
{
  if(!points.has_normal_map())
    throw std::invalid_argument(std::string(function) +
                                "(): the point set has no normal map (estimate_normals() adds and fills one)");
}

// The indices of the point set as a plain range: what the range overloads take (not these ones).
template <typename Point, typename Vector>
auto point_set_indices(const CGAL::Point_set_3<Point, Vector>& points)
{
  return CGAL::make_range(points.begin(), points.end());
}

// The point set's own maps on top of the caller's parameters.
template <typename Point, typename Vector, typename NamedParameters>
auto with_point_set_maps(const CGAL::Point_set_3<Point, Vector>& points, const NamedParameters& np)
{
  return np.point_map(points.point_map()).normal_map(points.normal_map());
}

// The prefix of the properties the `CGAL::Point_set_3` overloads add: CloudCompare loads a PLY
// property `scalar_<name>` as the scalar field `<name>`, so that `CGAL::IO::write_PLY()` of the point
// set gives a file CloudCompare opens with every field, and `CGAL::IO::read_PLY()` gives the names back.
const std::string POINT_SET_PROPERTY_PREFIX = "scalar_";

// The property `name` (prefixed): the existing one, else added with `value`; one of that name
// and another type is an error (it would be left as it is).
template <typename T, typename Point, typename Vector>
typename CGAL::Point_set_3<Point, Vector>::template Property_map<T>
point_set_property(CGAL::Point_set_3<Point, Vector>& points, const std::string& name, const T& value)
{
  const std::string full_name = POINT_SET_PROPERTY_PREFIX + name;
  // CGAL keeps properties of one name and several types side by side: a PLY would get both
  const std::vector<std::string> names = points.properties();
  if(std::find(names.begin(), names.end(), full_name) != names.end() &&
     !points.template property_map<T>(full_name).second)
    throw std::invalid_argument("the point set has a property " + full_name + " of another type");
  return points.template add_property_map<T>(full_name, value).first;
}

template <typename Point, typename Vector>
void write_features(CGAL::Point_set_3<Point, Vector>& points, const std::vector<Dimensionality_features>& features)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto linearity = point_set_property<double>(points, "linearity", nan);
  auto planarity = point_set_property<double>(points, "planarity", nan);
  auto scattering = point_set_property<double>(points, "scattering", nan);
  auto error = point_set_property<double>(points, "error", nan);
  auto label = point_set_property<std::uint8_t>(points, "label", std::uint8_t(Dimensionality::DEGENERATE));
  std::size_t i = 0;
  for(const auto index : points)
  {
    const Dimensionality_features& f = features[i++];
    // a degenerate neighborhood has no features: NaN, as in the tool's PLY
    linearity[index] = f.is_degenerate() ? nan : f.linearity;
    planarity[index] = f.is_degenerate() ? nan : f.planarity;
    scattering[index] = f.is_degenerate() ? nan : f.scattering;
    error[index] = f.error;
    label[index] = std::uint8_t(f.label);
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_POINT_SET_3_MAPS_H
