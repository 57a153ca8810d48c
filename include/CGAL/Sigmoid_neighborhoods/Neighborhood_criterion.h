// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_NEIGHBORHOOD_CRITERION_H
#define CGAL_SIGMOID_NEIGHBORHOODS_NEIGHBORHOOD_CRITERION_H

#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>


namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  what the optimal search minimises over the grid (the named parameter `criterion`). Both are
  Shannon entropies in `[0, ln 3]`, `+inf` for a degenerate neighborhood, and both go through the
  same visiting order and tie rule (SPEC §5).
*/
enum class Neighborhood_criterion
{
  /// the paper's `E_dim`, the entropy of linearity, planarity and scattering (Demantke et al. 2011)
  DIMENSIONALITY,
  /// the eigenentropy, the entropy of the eigenvalues divided by their sum (Weinmann et al. 2015;
  /// what pgeof's `compute_features_optimal` and PDAL's `filters.optimalneighborhood` minimise)
  EIGENENTROPY
};

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the value of criterion `c` for the features `f`: `f.error` (`E_dim`) or `f.eigenentropy`,
  `+inf` for a degenerate neighborhood.
*/
inline double criterion_value(const Dimensionality_features& f, Neighborhood_criterion c)
{
  return c == Neighborhood_criterion::EIGENENTROPY ? f.eigenentropy : f.error;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_NEIGHBORHOOD_CRITERION_H
