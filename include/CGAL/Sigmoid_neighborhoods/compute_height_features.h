// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_HEIGHT_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_HEIGHT_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the height features of a point in its horizontal cell, as CGAL's `Point_set_feature_generator`
  computes them on its planimetric grid (`Height_below`, `Height_above`, `Vertical_range`): what
  separates ground, low and high vegetation and roofs in airborne scans, where the eigenvalues alone
  cannot.
*/
struct Height_features
{
  double height_above_lowest = 0.;  ///< `z - min z` over the cell
  double height_below_highest = 0.; ///< `max z - z` over the cell
  double vertical_range = 0.;       ///< `max z - min z` over the cell
};

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the `Height_features` of every point in square horizontal cells of side
  `cell_size`.

  The cells are `[i c, (i + 1) c) x [j c, (j + 1) c)` for integers `i`, `j`: anchored at the
  origin, not at the data, so that adjacent tiles of one survey get the same cells as their union.
  `z` is the up axis.

  \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
  \tparam OutputIterator an output iterator accepting `Height_features`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points
  \param cell_size the side of the cells, in the unit of the coordinates
  \param output receives one record per point, in the order of `points`
  \param np an optional sequence of named parameters: `point_map` (CGAL's)

  \pre `cell_size` positive and finite; finite coordinates; every cell index fits in 64 bits
       (otherwise `std::invalid_argument`)
  \return the output iterator past the last record
*/
template <typename PointRange, typename OutputIterator, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
OutputIterator
#else
std::enable_if_t<internal::is_range<PointRange>::value, OutputIterator>
#endif
compute_height_features(const PointRange& points, double cell_size, OutputIterator output,
                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  if(!(cell_size > 0.) || !std::isfinite(cell_size))
    throw std::invalid_argument("the cell size must be positive and finite, got " + std::to_string(cell_size));
  const auto point_map = NP_helper::get_const_point_map(points, np);
  struct Cell_hash
  {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& c) const
    {
      return std::hash<std::int64_t>()(c.first) ^ (std::hash<std::int64_t>()(c.second) * 0x9E3779B97F4A7C15ull);
    }
  };
  const double largest_index = 9.2e18; // below 2^63
  std::vector<std::pair<std::int64_t, std::int64_t>> cell_of;
  std::vector<double> heights;
  std::size_t i = 0;
  for(const auto& item : points)
  {
    const internal::Double_point p = internal::checked_point(get(point_map, item), "point", i++);
    const double cx = std::floor(p.x() / cell_size), cy = std::floor(p.y() / cell_size);
    if(!(std::abs(cx) < largest_index && std::abs(cy) < largest_index))
      throw std::invalid_argument("point " + std::to_string(i - 1) + " lies beyond the cells' 64-bit range");
    cell_of.emplace_back(std::int64_t(cx), std::int64_t(cy));
    heights.push_back(p.z());
  }
  std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::pair<double, double>, Cell_hash> range;
  for(std::size_t j = 0; j < heights.size(); ++j)
  {
    auto inserted = range.emplace(cell_of[j], std::make_pair(heights[j], heights[j]));
    std::pair<double, double>& r = inserted.first->second;
    r.first = (std::min)(r.first, heights[j]);
    r.second = (std::max)(r.second, heights[j]);
  }
  for(std::size_t j = 0; j < heights.size(); ++j)
  {
    const std::pair<double, double>& r = range.find(cell_of[j])->second;
    Height_features h;
    h.height_above_lowest = heights[j] - r.first;
    h.height_below_highest = r.second - heights[j];
    h.vertical_range = r.second - r.first;
    *output++ = h;
  }
  return output;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_HEIGHT_FEATURES_H
