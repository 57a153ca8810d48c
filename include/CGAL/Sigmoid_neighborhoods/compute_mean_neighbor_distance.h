// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_MEAN_NEIGHBOR_DISTANCE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_MEAN_NEIGHBOR_DISTANCE_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>


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

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_MEAN_NEIGHBOR_DISTANCE_H
