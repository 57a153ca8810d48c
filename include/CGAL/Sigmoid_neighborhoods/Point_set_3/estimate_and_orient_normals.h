// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_ESTIMATE_AND_ORIENT_NORMALS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_ESTIMATE_AND_ORIENT_NORMALS_H

#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Point_set_3_maps.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_3.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `estimate_normals()` on a `CGAL::Point_set_3`, then orientation: its normal map (added when
  it has none) receives normals estimated on the `k` nearest points and oriented by
  `orient_normals_by_spanning_forest()`, both on one k-nearest-neighbor structure.

  \param points the point set
  \param k the neighbors of the estimation and of the spanning forest
  \param np the named parameters of `estimate_normals()` (`normal_estimation_method`,
  `degree_fitting`, `number_of_threads`) but the maps
  \return the number of trees of the spanning forest (connected components)
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t estimate_and_orient_normals(CGAL::Point_set_3<Point, Vector>& points, unsigned int k,
                                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  if(!points.has_normal_map())
    points.add_normal_map();
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  const auto maps = internal::with_point_set_maps(points, np);
  auto range = internal::point_set_indices(points);
  compute_k_nearest_neighbors<ConcurrencyTag>(range, k, indices, offsets, maps);
  const auto rows = parameters::neighbor_indices(std::cref(indices), parameters::neighbor_offsets(std::cref(offsets), maps));
  estimate_normals<ConcurrencyTag>(range, k, rows);
  return orient_normals_by_spanning_forest<ConcurrencyTag>(range, k, rows);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_ESTIMATE_AND_ORIENT_NORMALS_H
