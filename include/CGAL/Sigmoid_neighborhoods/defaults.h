// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_DEFAULTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_DEFAULTS_H

#include <CGAL/Sigmoid_neighborhoods/Normal_estimation_method.h>

#include <CGAL/number_type_config.h>

#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the values the named parameters take when a call leaves them out (\ref
  Sigmoid_neighborhoods_named_parameters): one place to read them from, for a program that shows
  them to its users or passes them on explicitly.
*/
namespace defaults {

/// the grid of `a` and `b`: `{0, pi/6, pi/3, pi/2, 2pi/3, 5pi/6, pi}` (SPEC §5)
inline std::vector<double> angle_grid()
{
  std::vector<double> grid;
  for(int i = 0; i <= 6; ++i)
    grid.push_back(i == 6 ? CGAL_PI : i * CGAL_PI / 6.); // pi itself, not 6 pi / 6 rounded
  return grid;
}

/// the smallest `k` of the search (SPEC §5)
constexpr unsigned int K_MIN = 6;
/// the largest `k` of the search (SPEC §5)
constexpr unsigned int K_MAX = 20;
/// `1e-6` radians: angles between normals up to it count as exactly 0, so that vertex normals that
/// differ by rounding on one flat face get weight 1 (SPEC §3)
constexpr double ANGLE_TOLERANCE = 1e-6;

/// the method of `estimate_normals()` and of `estimate_and_orient_normals()`
constexpr Normal_estimation_method NORMAL_ESTIMATION_METHOD = Normal_estimation_method::PCA;
/// the degree of the jet of `Normal_estimation_method::JET`, CGAL's
constexpr unsigned int JET_DEGREE = 2;

/// the number of sweeps `p` of `filter_normals()` (the authors' code)
constexpr unsigned int FILTER_ITERATIONS = 50;
/// the dot-product cut-off `rho` of `filter_normals()`: neighbor `j` votes for `i` when `n_i * n_j > rho`
constexpr double NORMAL_CUT_OFF = 0.9;
/// the eigenvalue threshold `tau` of the filter's binary eigenvalue optimisation
constexpr double EIGENVALUE_THRESHOLD = 0.25;
/// the damping factor `d` of the filter's update `n <- normalize(T n + d n)`
constexpr double DAMPING_FACTOR = 3.;
/// the half width of the filter's adaptive sizes `{k_i - 10, ..., k_i + 10}` (SPEC §7)
constexpr unsigned int NEIGHBORHOOD_SIZE_RANGE = 10;

/// the step `alpha` of the denoiser's planar rule (the authors' code): a tenth of the way to the
/// weighted mean plane per iteration, so that the normals, filtered at the same pace, lead
constexpr double PLANAR_STEP_SIZE = 0.1;
/// the rank threshold of the denoiser's edge and corner solves: a direction whose eigenvalue of the
/// quadratic error metric is below this fraction of the largest is not solved for (the point keeps
/// its coordinate along it); 0 solves every direction of non-zero eigenvalue, as the authors' code
constexpr double RANK_THRESHOLD = 0.1;

} // namespace defaults

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_DEFAULTS_H
