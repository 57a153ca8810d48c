// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_EVALUATION_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_EVALUATION_H

#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>

#include <limits>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsEvaluation
  everything the evaluation of the paper's Section 5 needs at one point: the optimal triple with
  the equal-weights baseline, the sharp cut-off `a = b = cut_off_angle` at its best `k`, equal
  weights at a fixed `k`, and the Table 3 lowering tests. Written by
  `evaluate_sigmoid_neighborhoods()`.
*/
struct Point_evaluation
{
  /// the outcome of lowering `a*` (or `b*`) to the next smaller grid value at the same `k*`:
  /// the columns `a-` / `not a-` (`b-` / `not b-`) of the paper's Table 3.
  enum class Lowering
  {
    AT_BOTTOM,  ///< `a* = 0` (column `a = 0`), or `b* = a*` (column `b = a`)
    STILL_VALID,///< the lowered triple does not fail (`a-`, `b-`)
    FAILS       ///< the lowered triple is degenerate (`not a-`, `not b-`)
  };

  Optimal_sigmoid_neighborhood optimal;                   ///< `(a*, b*, k*)` and equal weights at their best `k`
  Dimensionality equal_label = Dimensionality::DEGENERATE; ///< the label with equal weights at `k_equal`
  double error_cut_off = std::numeric_limits<double>::infinity(); ///< least `E_dim` of the cut-off over `K`
  unsigned int k_cut_off = 0;                              ///< its `k`, 0 when it fails at every `k`
  /// the label of the cut-off at `k_cut_off`, `DEGENERATE` when it fails at every `k`
  Dimensionality cut_off_label = Dimensionality::DEGENERATE;
  double error_fixed_k = std::numeric_limits<double>::infinity(); ///< `E_dim` with equal weights at `fixed_k`
  /// the label with equal weights at `fixed_k`
  Dimensionality fixed_k_label = Dimensionality::DEGENERATE;
  Lowering a_lowering = Lowering::AT_BOTTOM; ///< meaningless for a failure
  Lowering b_lowering = Lowering::AT_BOTTOM; ///< meaningless for a failure
};

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_EVALUATION_H
