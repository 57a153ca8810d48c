// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_TIE_RULE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_TIE_RULE_H

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A candidate replaces the best one only when its error is smaller by more than this (SPEC §5):
// the tie rule of every scan over `(a, b, k)` or over `k`, so that errors equal up to rounding keep
// the first candidate visited.
constexpr double TIE_TOLERANCE = 1e-12;

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_TIE_RULE_H
