// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SYMMETRIC_EIGENVALUES_3_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SYMMETRIC_EIGENVALUES_3_H

#include <CGAL/Sigmoid_neighborhoods/internal/Vector_lanes.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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
// The two others are written without selecting on the sign of beta0: with m = r (t / 2 - h) >= 0
// and h = r sqrt(3 (4 - t^2)) / 2, the middle root is -sign(beta0) m and the outer two are
// (D - mu2) / 2 and -(D + mu2) / 2 with D = r (3 t / 2 + h) for either sign. So the same code
// runs on a double and, elementwise, on an Eigen array, where Eigen vectorizes it: its only
// operations are arithmetic, sqrt, abs, min and max.
//
// The core expects a trace in (1e-90, 1e90), where beta0, cubic in C, neither overflows nor underflows.
inline bool has_unscaled_eigenvalues(double trace) { return trace > 1e-90 && trace < 1e90; }

inline double elementwise_max(double a, double b) { return (std::max)(a, b); }
inline double elementwise_min(double a, double b) { return (std::min)(a, b); }
inline double elementwise_abs(double a) { return std::abs(a); }
inline double elementwise_sqrt(double a) { return std::sqrt(a); }
template <typename A, typename B>
typename A::PlainObject elementwise_max(const Eigen::ArrayBase<A>& a, const B& b) { return a.max(b); }
template <typename A, typename B>
typename A::PlainObject elementwise_min(const Eigen::ArrayBase<A>& a, const B& b) { return a.min(b); }
template <typename A>
typename A::PlainObject elementwise_abs(const Eigen::ArrayBase<A>& a) { return a.abs(); }
template <typename A>
typename A::PlainObject elementwise_sqrt(const Eigen::ArrayBase<A>& a) { return a.sqrt(); }

// T: double, a fixed-size Eigen array of doubles (one matrix per coefficient), or lanes of
// Vector_lanes.h (inside a function compiled for their instruction set)
template <typename T>
void unscaled_symmetric_eigenvalues_3(const T& c00, const T& c10, const T& c20, const T& c11, const T& c21,
                                      const T& c22, T& lambda1, T& lambda2, T& lambda3)
{
  const T mean = (c00 + c11 + c22) * (1. / 3.);
  const T b00 = c00 - mean, b11 = c11 - mean, b22 = c22 - mean;
  const T beta1 = b00 * b11 + b00 * b22 + b11 * b22 - c10 * c10 - c20 * c20 - c21 * c21;
  const T beta0 = b00 * (b11 * b22 - c21 * c21) - c10 * (c10 * b22 - c21 * c20) + c20 * (c10 * c21 - b11 * c20);
  const T r2 = elementwise_max(T(beta1 * (-1. / 3.)), 0.), r = elementwise_sqrt(r2);
  const double tiny = (std::numeric_limits<double>::min)();
  // r = 0: three equal eigenvalues; q is then irrelevant (every mu below is 0)
  const T q = elementwise_min(T(elementwise_abs(beta0) / elementwise_max(T(r2 * r), tiny)), 2.);
  // least-squares fit through 400 Chebyshev nodes of t(q) = 2 cos(acos(q / 2) / 3) on [0, 2],
  // evaluated in Estrin's scheme (a short chain of dependent operations)
  const T q2 = q * q, q4 = q2 * q2;
  const T low = (1.7320508296149817 + 0.16666519134177962 * q) + q2 * (-0.0240398239046335 + 0.006101460145035424 * q);
  const T high = (-0.0017909121341702422 + 0.000482425847425983 * q) + q2 * (-9.256209220942216e-05 + 8.65124695484629e-06 * q);
  const T t0 = low + q4 * high;
  const T t = t0 - ((t0 * t0 - 3.) * t0 - q) / (3. * t0 * t0 - 3.);
  const T h = 0.5 * r * elementwise_sqrt(elementwise_max(T(3. * (4. - t * t)), 0.));
  const T rt = r * t;
  const T m = 0.5 * rt - h, spread = 1.5 * rt + h;
  // -1 or 1 (beta0 = 0 gives 0, where m is 0 as well: q = 0, t = sqrt 3)
  const T sign = beta0 / elementwise_max(elementwise_abs(beta0), tiny);
  const T mu2 = -(sign * m);
  const T mu1 = 0.5 * (spread - mu2), mu3 = -0.5 * (spread + mu2);
  lambda1 = mu1 + mean;
  lambda2 = elementwise_min(elementwise_max(mu2, mu3), mu1) + mean;
  lambda3 = mu3 + mean;
}

// A bound on the error of unscaled_symmetric_eigenvalues_3() relative to lambda1, given the
// smaller of the two gaps lambda1 - lambda2 and lambda2 - lambda3 relative to lambda1, both as the
// closed form gives them: rounding (at most 2.6e-15), then the loss near a double eigenvalue (at
// most 8.6e-16 / gap, and 1.4e-8 in all: the Newton step leaves t to rounding, which
// sqrt(4 - t^2) amplifies), as measured on millions of matrices of every shape. The bound keeps a
// factor 10 above those figures (the test [eigenvalues] checks a factor 8); a gap is taken 5e-7
// smaller than the closed form says, which covers the gap's own error wherever 1e-14 / gap applies.
template <typename T>
T closed_form_relative_error(const T& relative_gap)
{
  return 3e-14 + elementwise_min(T(1e-14 / elementwise_max(T(relative_gap - 5e-7), 0.)), 2e-7);
}

inline std::array<double, 3> symmetric_eigenvalues_3(const Eigen::Matrix3d& c)
{
  const double trace = c(0, 0) + c(1, 1) + c(2, 2);
  if(!has_unscaled_eigenvalues(trace))
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
  std::array<double, 3> result;
  unscaled_symmetric_eigenvalues_3<double>(c(0, 0), c(1, 0), c(2, 0), c(1, 1), c(2, 1), c(2, 2), result[0], result[1],
                                           result[2]);
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SYMMETRIC_EIGENVALUES_3_H
