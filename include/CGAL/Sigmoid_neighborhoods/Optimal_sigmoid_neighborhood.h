// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_OPTIMAL_SIGMOID_NEIGHBORHOOD_H
#define CGAL_SIGMOID_NEIGHBORHOODS_OPTIMAL_SIGMOID_NEIGHBORHOOD_H

#include <CGAL/Sigmoid_neighborhoods/Neighborhood_criterion.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>

#include <limits>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the result of the optimal parameter search at one point (the paper's Equation 9), written by
  `compute_optimal_sigmoid_neighborhoods()`.

  The search minimises `criterion`'s value: `E_dim` by default, or the eigenentropy; `error()` and
  `error_equal` are values of that criterion, and `features` holds both.

  When every triple fails, `k == 0`, `a` and `b` are NaN and `error()` is `+inf`:
  the point is a *failure*. A default-constructed record is a failure; the mesh version of
  `compute_optimal_sigmoid_neighborhoods()` gives one to the vertices it leaves out.
*/
struct Optimal_sigmoid_neighborhood
{
  double a = std::numeric_limits<double>::quiet_NaN(); ///< `a*`, radians
  double b = std::numeric_limits<double>::quiet_NaN(); ///< `b*`, radians
  unsigned int k = 0;                                  ///< `k*`, 0 for a failure
  Dimensionality_features features;                    ///< at `(a*, b*, k*)`
  double error_equal = std::numeric_limits<double>::infinity(); ///< least criterion value with equal weights
  unsigned int k_equal = 0;                                     ///< its `k`, 0 when all fail
  /// what `error()` and `error_equal` measure (the named parameter `criterion`)
  Neighborhood_criterion criterion = Neighborhood_criterion::DIMENSIONALITY;

  /// the criterion's value at the optimum (`E_dim` by default), `+inf` for a failure
  double error() const { return criterion_value(features, criterion); }
  /// `true` when every triple is degenerate at this point (`k == 0`).
  bool is_failure() const { return k == 0; }
};

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_OPTIMAL_SIGMOID_NEIGHBORHOOD_H
