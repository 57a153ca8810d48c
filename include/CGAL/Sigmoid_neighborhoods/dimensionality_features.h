// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_DIMENSIONALITY_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_DIMENSIONALITY_FEATURES_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the dimensionality label of a point: the largest of linearity, planarity and scattering
  (ties to the first), or `DEGENERATE` when the covariance matrix vanishes.
*/
enum class Dimensionality
{
  /// linearity is the largest: the point lies on a curve
  LINEAR,
  /// planarity is the largest: the point lies on a surface
  PLANAR,
  /// scattering is the largest: the neighborhood fills a volume
  SCATTERED,
  /// the covariance matrix vanishes: no features
  DEGENERATE
};

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the eigenvalue features of one weighted neighborhood (the paper's Section 4).
  A degenerate neighborhood has `error = eigenentropy = +inf`, all other values 0 and the label `DEGENERATE`.
*/
struct Dimensionality_features
{
  std::array<double, 3> eigenvalues{{0., 0., 0.}}; ///< `lambda1 >= lambda2 >= lambda3 >= 0`
  double linearity = 0.;                          ///< `(lambda1 - lambda2) / lambda1`
  double planarity = 0.;                          ///< `(lambda2 - lambda3) / lambda1`
  double scattering = 0.;                         ///< `lambda3 / lambda1`
  /// `E_dim = -L ln L - P ln P - S ln S` (`0 ln 0 = 0`) of the linearity `L`, planarity `P` and
  /// scattering `S`: the Shannon entropy of the dimensionality, in `[0, ln 3]`
  double error = std::numeric_limits<double>::infinity();
  /// the eigenentropy of Weinmann et al. (2015), `-sum e_i ln e_i` with `e_i = lambda_i / (lambda1 +
  /// lambda2 + lambda3)`, in `[0, ln 3]` and invariant under a scaling of the neighborhood. Nothing is
  /// added to the eigenvalues (pgeof adds an absolute `1e-3` to each, which makes its value depend on
  /// the unit of the coordinates).
  double eigenentropy = std::numeric_limits<double>::infinity();
  /// the largest of linearity, planarity and scattering (ties to the first), or `DEGENERATE`
  Dimensionality label = Dimensionality::DEGENERATE;

  /// `true` for the record of a degenerate neighborhood (`label == Dimensionality::DEGENERATE`).
  bool is_degenerate() const { return label == Dimensionality::DEGENERATE; }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// the Shannon entropy `E_dim = -L ln L - P ln P - S ln S`, with `0 ln 0 = 0`, of linearity `L`,
// planarity `P` and scattering `S`
inline double dimensionality_error(double linearity, double planarity, double scattering)
{
  auto term = [](double x) { return x > 0. ? -x * std::log(x) : 0.; };
  return term(linearity) + term(planarity) + term(scattering);
}

// the eigenentropy of Weinmann et al. (2015) (see Dimensionality_features::eigenentropy); the
// eigenvalues non-negative with a positive sum (not checked)
inline double eigenentropy(double lambda1, double lambda2, double lambda3)
{
  const double inverse_sum = 1. / (lambda1 + lambda2 + lambda3);
  return dimensionality_error(lambda1 * inverse_sum, lambda2 * inverse_sum, lambda3 * inverse_sum);
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the features of eigenvalues `lambda1 >= lambda2 >= lambda3` (negative values from rounding
  are clamped to 0). Returns a degenerate record when `lambda1 <= 0`.
  \pre the eigenvalues are sorted in decreasing order (not checked)
*/
inline Dimensionality_features dimensionality_features_from_eigenvalues(double lambda1, double lambda2,
                                                                        double lambda3)
{
  Dimensionality_features f;
  lambda1 = (std::max)(lambda1, 0.);
  lambda2 = (std::max)(lambda2, 0.);
  lambda3 = (std::max)(lambda3, 0.);
  if(!(lambda1 > 0.))
    return f;
  f.eigenvalues = {{lambda1, lambda2, lambda3}};
  f.linearity = (lambda1 - lambda2) / lambda1;
  f.planarity = (lambda2 - lambda3) / lambda1;
  f.scattering = lambda3 / lambda1;
  f.error = internal::dimensionality_error(f.linearity, f.planarity, f.scattering);
  f.eigenentropy = internal::eigenentropy(lambda1, lambda2, lambda3);
  f.label = Dimensionality::LINEAR;
  if(f.planarity > f.linearity)
    f.label = Dimensionality::PLANAR;
  if(f.scattering > (std::max)(f.linearity, f.planarity))
    f.label = Dimensionality::SCATTERED;
  return f;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the features of a symmetric positive semi-definite 3x3 matrix (only its lower triangle is read).
  The eigenvalues come from Eigen's iterative `SelfAdjointEigenSolver::compute()`, accurate to about
  `1e-12 lambda1` even when two eigenvalues nearly coincide, which closed-form solvers are not (SPEC §4).
  The matrix is not tested for degeneracy: use the overload for `Weighted_covariance` for that.
  \param covariance a covariance matrix, such as `Weighted_covariance::matrix`
*/
inline Dimensionality_features dimensionality_features(const Eigen::Matrix3d& covariance)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.compute(covariance, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d& ev = solver.eigenvalues(); // ascending
  return dimensionality_features_from_eigenvalues(ev[2], ev[1], ev[0]);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_DIMENSIONALITY_FEATURES_H
