// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_ESTIMATE_NORMALS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_ESTIMATE_NORMALS_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>

#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// CGAL's jet fitting of degree 2 needs 6 points (a precondition of `Monge_via_jet_fitting`).
constexpr std::size_t FEWEST_POINTS_TO_ESTIMATE_NORMALS = 6;
// Jet fitting divides by the square of the extent of a point's neighbors; below this extent it
// underflows to 0, the least-squares matrix gets NaN, and Eigen 3.4's JacobiSVD, which leaves its
// rank undefined on non-finite input, reads out of bounds (a crash found by fuzzing).
constexpr double SMALLEST_NEIGHBORHOOD_EXTENT = 1e-150;

// Refuses points whose `neighbors` nearest other points are too close for jet fitting.
inline void check_neighborhood_extents(const std::vector<Oriented_point_set::Point_3>& input, unsigned int neighbors)
{
  std::vector<Double_point> points;
  points.reserve(input.size());
  for(const auto& p : input)
    points.emplace_back(p.x(), p.y(), p.z());
  const Neighbor_query query(points);
  std::vector<Neighbor> found;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    // the farthest of the `neighbors` nearest other points, as CGAL's query finds them
    query.query(std::uint32_t(i), neighbors, found);
    if(found.empty() ||
       !(found.back().squared_distance >= SMALLEST_NEIGHBORHOOD_EXTENT * SMALLEST_NEIGHBORHOOD_EXTENT))
      throw Input_error("point " + std::to_string(i) + " and its " + std::to_string(neighbors) +
                        " nearest points lie within 1e-150 of each other: too close to estimate normals");
  }
}

// Jet fitting and MST orientation (CGAL's Point_set_processing_3), in input order.
inline void estimate_normals(Oriented_point_set& out, unsigned int neighbors)
{
  check_neighborhood_extents(out.points, neighbors);
  typedef std::tuple<Oriented_point_set::Point_3, Oriented_point_set::Vector_3, std::size_t> Item;
  std::vector<Item> items;
  for(std::size_t i = 0; i < out.points.size(); ++i)
    items.emplace_back(out.points[i], CGAL::NULL_VECTOR, i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Item>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Item>());
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(items, neighbors, np);
  const auto unoriented = CGAL::mst_orient_normals(items, neighbors, np);
  out.unoriented_normals = std::size_t(std::distance(unoriented, items.end()));
  std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return std::get<2>(x) < std::get<2>(y); });
  out.normals.clear();
  for(const Item& item : items)
    out.normals.push_back(std::get<1>(item));
  out.normals_estimated = true;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_ESTIMATE_NORMALS_H
