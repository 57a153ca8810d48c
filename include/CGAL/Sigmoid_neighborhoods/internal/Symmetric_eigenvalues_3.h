// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SYMMETRIC_EIGENVALUES_3_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SYMMETRIC_EIGENVALUES_3_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The eigenvalues lambda1 >= lambda2 >= lambda3 of a symmetric positive semi-definite 3x3 matrix
// (its lower triangle is read), as accurate as Eigen's closed form (`computeDirect`) at a fraction
// of its cost: the trigonometric root formula's atan2, cos and sin are replaced by a polynomial
// and one Newton step.
//
// With B = C - tr(C) I / 3, the characteristic polynomial of B is x^3 - 3 r^2 x - beta0 with
// r^2 = -beta1 / 3 (beta1 the sum of B's principal 2x2 minors) and beta0 = det B; x = r t turns it
// into t^3 - 3 t - q, q = beta0 / r^3 in [-2, 2], whatever the scale of C. For q >= 0 (the middle
// eigenvalue at most the mean) the largest root is the isolated one, t in [sqrt 3, 2], where t(q)
// is analytic and the cubic well conditioned (its derivative is at least 6): a degree-7 fit of t(q)
// is within 2.3e-8 and one Newton step brings that to rounding. For q < 0 the mirror image gives
// the smallest root. The two others follow from their sum, -r t, and their difference,
// r sqrt(3 (4 - t^2)), which loses what every closed form loses when they nearly coincide (about
// 1e-8 of the trace).
inline std::array<double, 3> symmetric_eigenvalues_3(const Eigen::Matrix3d& c)
{
  const double trace = c(0, 0) + c(1, 1) + c(2, 2);
  // beta0 is cubic in C: beyond these scales it would overflow or underflow
  if(!(trace > 1e-90 && trace < 1e90))
  {
    if(trace > 0. && std::isfinite(trace))
    {
      const std::array<double, 3> scaled = symmetric_eigenvalues_3(c / trace);
      return {{scaled[0] * trace, scaled[1] * trace, scaled[2] * trace}};
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(c, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d& ev = solver.eigenvalues(); // ascending
    return {{ev[2], ev[1], ev[0]}};
  }
  const double mean = trace * (1. / 3.);
  const double b00 = c(0, 0) - mean, b11 = c(1, 1) - mean, b22 = c(2, 2) - mean;
  const double b10 = c(1, 0), b20 = c(2, 0), b21 = c(2, 1);
  const double beta1 = b00 * b11 + b00 * b22 + b11 * b22 - b10 * b10 - b20 * b20 - b21 * b21;
  const double beta0 = b00 * (b11 * b22 - b21 * b21) - b10 * (b10 * b22 - b21 * b20) + b20 * (b10 * b21 - b11 * b20);
  const double r2 = (std::max)(-beta1 / 3., 0.), r = std::sqrt(r2);
  if(!(r > 0.))
    return {{mean, mean, mean}};
  const double q = (std::min)(std::abs(beta0) / (r2 * r), 2.);
  // least-squares fit through 400 Chebyshev nodes of t(q) = 2 cos(acos(q / 2) / 3) on [0, 2],
  // evaluated in Estrin's scheme (a short chain of dependent operations)
  const double q2 = q * q, q4 = q2 * q2;
  const double low = (1.7320508296149817 + 0.16666519134177962 * q) + q2 * (-0.0240398239046335 + 0.006101460145035424 * q);
  const double high = (-0.0017909121341702422 + 0.000482425847425983 * q) + q2 * (-9.256209220942216e-05 + 8.65124695484629e-06 * q);
  double t = low + q4 * high;
  t -= ((t * t - 3.) * t - q) / (3. * t * t - 3.);
  const double half_difference = 0.5 * r * std::sqrt((std::max)(3. * (4. - t * t), 0.));
  const double isolated = r * t, middle = 0.5 * isolated;
  std::array<double, 3> mu;
  if(beta0 >= 0.)
    mu = {{isolated, -middle + half_difference, -middle - half_difference}};
  else
    mu = {{middle + half_difference, middle - half_difference, -isolated}};
  mu[1] = (std::min)(mu[1], mu[0]);
  mu[1] = (std::max)(mu[1], mu[2]);
  return {{mu[0] + mean, mu[1] + mean, mu[2] + mean}};
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SYMMETRIC_EIGENVALUES_3_H
