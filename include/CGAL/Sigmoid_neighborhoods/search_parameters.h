// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The defaults of the optimal search's grid and its tie rule (SPEC §5).

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_SEARCH_PARAMETERS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_SEARCH_PARAMETERS_H

#include <CGAL/number_type_config.h>

#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the default grid of `a` and `b`: `{0, pi/6, pi/3, pi/2, 2pi/3, 5pi/6, pi}` (SPEC §5).
*/
inline std::vector<double> default_angle_grid()
{
  std::vector<double> grid;
  for(int i = 0; i <= 6; ++i)
    grid.push_back(i == 6 ? CGAL_PI : i * CGAL_PI / 6.); // pi itself, not 6 pi / 6 rounded
  return grid;
}

/// \ingroup PkgSigmoidNeighborhoodsRef
/// The default smallest `k` (SPEC §5).
constexpr unsigned int DEFAULT_K_MIN = 6;
/// \ingroup PkgSigmoidNeighborhoodsRef
/// The default largest `k` (SPEC §5).
constexpr unsigned int DEFAULT_K_MAX = 20;

/// \ingroup PkgSigmoidNeighborhoodsRef
/// A candidate replaces the best one only when its error is smaller by more than this (SPEC §5):
/// the tie rule of every scan over `(a, b, k)` or over `k`, so that errors equal up to rounding
/// keep the first candidate visited.
constexpr double TIE_TOLERANCE = 1e-12;

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_SEARCH_PARAMETERS_H
