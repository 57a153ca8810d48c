// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_K_NEAREST_NEIGHBORS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_K_NEAREST_NEIGHBORS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief computes the `k` nearest other points of every point, in compressed rows: the
  neighborhoods of SPEC §2, computed once and passed to every algorithm with the named parameters
  `neighbor_indices` and `neighbor_offsets`, so that several calls on one point set share them.

  Row `i` is `indices[offsets[i]]` ... `indices[offsets[i + 1] - 1]`: the `min(k, n - 1)` nearest
  points other than `i`, ordered by distance and then by index (SPEC §2's tie rule applied to
  `CGAL::Orthogonal_k_neighbor_search`, so that an algorithm given these rows computes what it
  computes without them, bit for bit). The result is the same for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of `point_map`
  \tparam NamedParameters a sequence of named parameters

  \param points the points
  \param k the number of neighbors of each point
  \param indices receives the neighbor indices (pgeof's `nn`), replacing its content
  \param offsets receives the `n + 1` row offsets (pgeof's `nn_ptr`), replacing its content
  \param np optional: `point_map` (CGAL), `number_of_threads` and `search_tree`

  \pre `k >= 1`; finite coordinates; fewer than `2^32` points; otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
void compute_k_nearest_neighbors(const PointRange& points, unsigned int k, std::vector<std::uint32_t>& indices,
                                 std::vector<std::size_t>& offsets,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  if(k < 1)
    throw std::invalid_argument("the number of neighbors k must be at least 1");
  const unsigned int threads = internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np));
  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np), threads);
  if(copy.size() > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw std::invalid_argument("compute_k_nearest_neighbors(): more than 2^32 - 1 points");
  const internal::Neighbor_query query = internal::tree_query<ConcurrencyTag>(copy, np);
  internal::Neighbor_lists rows =
    internal::nearest_neighbor_rows(query, k, threads);
  indices = std::move(rows.indices);
  offsets = std::move(rows.offsets);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COMPUTE_K_NEAREST_NEIGHBORS_H
