// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_PARAMETERS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>


namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  selects the barycenter `c_i` of the covariance matrix (SPEC §4): the value type of the named
  parameter `barycenter` and the third argument of `weighted_covariance()`.
*/
enum class Barycenter
{
  WEIGHTED,  ///< `c_i = sum w_ij p_j / sum w_ij` (default: the paper's degenerate cases need it)
  UNWEIGHTED ///< `c_i = (1 / |N_i|) sum p_j`, the paper's literal formula
};

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the search structure a call builds for its neighborhoods: the value type of the named parameter
  `neighbor_search`. Both give the same rows, bit for bit (SPEC §2: by distance, ties by index).
*/
enum class Neighbor_search
{
  /// `CGAL::Kd_tree` (sliding midpoint) searched with `CGAL::Orthogonal_k_neighbor_search` and
  /// `CGAL::Fuzzy_sphere`, SPEC §2's tie rule applied to their results (default)
  CGAL_KD_TREE,
  /// the package's own kd-tree, which selects the `k` nearest with the tie rule itself: 1.3 to 1.5
  /// times faster for 20 to 100 neighbors (\ref SN_Neighborhoods)
  PACKAGE_KD_TREE
};

// CGAL 5.5 generates chainable members only for its own tags, so ours are free
// functions returning a CGAL pack: our parameters first, CGAL's chained after,
// e.g. `parameters::k_max(12).point_map(pm)`. The two-argument form pushes a
// value on top of an existing pack: `parameters::k_min(8, parameters::k_max(12))`.
#define CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(TAG, NAME)                                  \
  namespace internal_np {                                                                          \
  enum TAG { NAME };                                                                               \
  }                                                                                                \
  namespace parameters {                                                                           \
  template <typename T>                                                                            \
  CGAL::Named_function_parameters<T, internal_np::TAG> NAME(const T& value)                        \
  {                                                                                                \
    return CGAL::Named_function_parameters<T, internal_np::TAG>(value);                            \
  }                                                                                                \
  template <typename T, typename NP_T, typename NP_Tag, typename NP_Base>                          \
  CGAL::Named_function_parameters<T, internal_np::TAG,                                             \
                                  CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >         \
  NAME(const T& value, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np)           \
  {                                                                                                \
    return CGAL::Named_function_parameters<                                                        \
      T, internal_np::TAG, CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >(value, np);    \
  }                                                                                                \
  }

/// \cond SKIP_IN_MANUAL
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(k_min_t, k_min)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(k_max_t, k_max)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(a_grid_t, a_grid)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(b_grid_t, b_grid)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(barycenter_t, barycenter)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(angle_tolerance_t, angle_tolerance)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(cut_off_angle_t, cut_off_angle)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(fixed_k_t, fixed_k)
// the optimal search: what it minimises (Neighborhood_criterion)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(criterion_t, criterion)
// every algorithm: the threads of one call with `CGAL::Parallel_tag` (0: the OpenMP or TBB default)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(number_of_threads_t, number_of_threads)
// the optimal search: the vector instructions of its batched eigenvalues (Vector_instructions)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(vector_instructions_t, vector_instructions)
// the search, the features, the evaluation and the filter: weights on the angle between normal lines
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(line_angles_t, line_angles)
// estimate_normals()
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(normal_estimation_method_t, normal_estimation_method)
// the functions on point ranges that search neighbors: CGAL's kd-tree or the package's (Neighbor_search)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(neighbor_search_t, neighbor_search)
// caller-computed neighborhoods in compressed rows (pgeof's `nn` / `nn_ptr`)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(neighbor_indices_t, neighbor_indices)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(neighbor_offsets_t, neighbor_offsets)
// filter_normals()
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(normal_cut_off_t, normal_cut_off)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(eigenvalue_threshold_t, eigenvalue_threshold)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(damping_factor_t, damping_factor)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(neighborhoods_t, neighborhoods)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(adaptive_neighborhood_size_t, adaptive_neighborhood_size)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(neighborhood_size_range_t, neighborhood_size_range)
// denoise_point_set()
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(step_size_t, step_size)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(maximum_deviation_t, maximum_deviation)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(planar_weight_radius_t, planar_weight_radius)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(rank_threshold_t, rank_threshold)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(in_place_updates_t, in_place_updates)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(authors_vertex_update_t, authors_vertex_update)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(jet_vertex_update_t, jet_vertex_update)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(stop_at_noise_level_t, stop_at_noise_level)
CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER(optimal_vote_weights_t, optimal_vote_weights)
/// \endcond

#undef CGAL_SIGMOID_NEIGHBORHOODS_ADD_NAMED_PARAMETER

/// \cond SKIP_IN_MANUAL
// the named parameter of search_tree.h
namespace internal_np {
enum search_tree_t { search_tree };
}
/// \endcond

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_PARAMETERS_H
