// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_SEARCH_TREE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_SEARCH_TREE_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Kd_tree_search.h>

#include <CGAL/Named_function_parameters.h>

#include <functional>

namespace CGAL {
namespace Sigmoid_neighborhoods {

namespace parameters {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the named parameter `search_tree`: a `CGAL::Kd_tree` the caller already holds over the same points,
  searched instead of a tree built by the call (the pack holds a reference: the tree must outlive the
  call, and no copy is made).

  Its items are the indices `0, ..., n - 1` of the input range, in the range's order (`std::size_t`,
  `std::uint32_t`, or `Point_set_3::Index` of a point set without removed points), through
  `CGAL::Search_traits_adapter` on a point map into `CGAL::Search_traits_3` of a kernel of double
  coordinates (`Epick`, `Simple_cartesian<double>`): as CGAL's own Point_set_processing_3 builds its
  trees. Any splitter, bucket size and points cache. A tree with another number of points is refused
  with `std::invalid_argument`; the other requirements by a `static_assert`. The results are those of
  the call's own tree, bit for bit: the call applies SPEC §2's tie rule to the tree's searches.

  In its own header, `<CGAL/Sigmoid_neighborhoods/search_tree.h>`, which includes CGAL's spatial
  searching (a program that holds a tree has it already). Taken by the functions on point ranges and
  `Point_set_3` that search neighbors:
  `compute_k_nearest_neighbors()`, `compute_optimal_sigmoid_neighborhoods()`, `compute_sigmoid_features()`,
  `compute_point_features()`, `evaluate_sigmoid_neighborhoods()`, `estimate_normals()` and
  `orient_normals()`. Not with `neighbor_indices`: rows already given need no search.
*/
template <typename Tree>
CGAL::Named_function_parameters<std::reference_wrapper<const Tree>, internal_np::search_tree_t>
search_tree(const Tree& tree)
{
  return CGAL::Named_function_parameters<std::reference_wrapper<const Tree>, internal_np::search_tree_t>(
    std::cref(tree));
}

/// \cond SKIP_IN_MANUAL
template <typename Tree, typename NP_T, typename NP_Tag, typename NP_Base>
CGAL::Named_function_parameters<std::reference_wrapper<const Tree>, internal_np::search_tree_t,
                                CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>
search_tree(const Tree& tree, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np)
{
  return CGAL::Named_function_parameters<std::reference_wrapper<const Tree>, internal_np::search_tree_t,
                                         CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>(std::cref(tree), np);
}
/// \endcond

} // namespace parameters

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_SEARCH_TREE_H
