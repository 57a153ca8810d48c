// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COSINE_SIGMOID_H
#define CGAL_SIGMOID_NEIGHBORHOODS_COSINE_SIGMOID_H

#include <CGAL/Sigmoid_neighborhoods/config.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>
#include <CGAL/number_type_config.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {
// Margin in cosine space outside which the dot-product path decides without acos:
// far above the few-ulp errors of cos and acos, far below any useful angle step.
constexpr double COSINE_DECISION_MARGIN = 1e-9;
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief the cosine sigmoid `sig_{a,b}` of the paper's Definition 1, a weight in `[0, 1]`
  for the angle `x` between two unit normals.

  - `x < a`: 1;
  - `a <= x <= b`, `a < b`: `1/2 cos(pi (x - a) / (b - a)) + 1/2`;
  - `x <= a`, `a = b`: 1 (the sharp cut-off keeps `x = a`);
  - `x > b`: 0.

  Angles `x <= angle_tolerance` count as exactly 0, so that vertex normals that differ by
  rounding on one flat face always get weight 1. `a = b = pi` gives equal weights,
  `a = b = arccos(rho)` the sharp cut-off of a dot-product threshold `rho`.

  The weights of the paper are `w_ij = sig_{a,b}(angle(n_i, n_j))` for unit normals `n_i`, `n_j`:
  `sigmoid(normal_angle(n_i, n_j))`, or `sigmoid.weight_from_cosine(n_i * n_j)` without computing
  the angle.

  \sa `normal_angle()`, `compute_sigmoid_features()`
*/
class Cosine_sigmoid
{
public:
  /*!
    creates the sigmoid `sig_{a,b}`.
    \param a the angle (radians) up to which the weight is 1
    \param b the angle (radians) beyond which the weight is 0
    \param angle_tolerance angles up to it count as 0 (radians)
    \pre `0 <= a <= b <= pi` and `0 <= angle_tolerance < pi`, checked: otherwise
    `std::invalid_argument`.
  */
  Cosine_sigmoid(double a, double b, double angle_tolerance = defaults::ANGLE_TOLERANCE)
    : m_a(a), m_b(b), m_tolerance(angle_tolerance)
  {
    if(!(a >= 0. && a <= b && b <= CGAL_PI))
      throw std::invalid_argument("sigmoid parameters must satisfy 0 <= a <= b <= pi, got a = " +
                                  std::to_string(a) + ", b = " + std::to_string(b));
    if(!(angle_tolerance >= 0. && angle_tolerance < CGAL_PI))
      throw std::invalid_argument("angle tolerance must be in [0, pi), got " +
                                  std::to_string(angle_tolerance));
    // Above cos(max(a, tol)) every weight is 1, below cos(max(b, tol)) every weight is 0.
    m_cos_one = std::cos(std::max(a, angle_tolerance)) + internal::COSINE_DECISION_MARGIN;
    m_cos_zero = std::cos(std::max(b, angle_tolerance)) - internal::COSINE_DECISION_MARGIN;
  }

  /// the angle `a` (radians) up to which the weight is 1.
  double a() const { return m_a; }
  /// the angle `b` (radians) beyond which the weight is 0.
  double b() const { return m_b; }
  /// the angle (radians) up to which angles count as 0.
  double angle_tolerance() const { return m_tolerance; }

  /// returns `true` when all weights are 1 (`a = b = pi`).
  bool is_equal_weights() const { return m_a == CGAL_PI && m_b == CGAL_PI; }

  /// the weight of the angle `x` in `[0, pi]` (the reference formulation).
  double operator()(double x) const { return weight_of_argument(transition_argument(x)); }

  /// \cond SKIP_IN_MANUAL
  // The weight of x is 1, 0, or 1/2 cos(t) + 1/2 with the argument t in [0, pi] returned here
  // (WEIGHT_ONE and WEIGHT_ZERO, both negative, stand for the first two): the one place where
  // the case and the argument of the cosine are decided, so that a path evaluating the cosine
  // differently (internal::approximate_cosine()) agrees with this one on both, and equal
  // arguments mean equal weights.
  static constexpr double WEIGHT_ONE = -1., WEIGHT_ZERO = -2.;

  double transition_argument(double x) const
  {
    if(x <= m_tolerance || x < m_a)
      return WEIGHT_ONE;
    if(m_a == m_b)
      return x <= m_a ? WEIGHT_ONE : WEIGHT_ZERO;
    if(x > m_b)
      return WEIGHT_ZERO;
    return CGAL_PI * (x - m_a) / (m_b - m_a);
  }

  // transition_argument() of x[0, n) into t, bit for bit, without branches: a loop the compiler
  // vectorizes (angles fall on either side of a and b at random, so branches mispredict). The
  // argument is computed in every lane and kept in the band only; a step (a = b) divides by 1, never
  // by 0, and a NaN angle gets WEIGHT_ZERO from a step and NaN otherwise, as above.
  CGAL_SIGMOID_NEIGHBORHOODS_VECTORIZED_SELECTS void transition_arguments(const double* x, std::size_t n,
                                                                           double* t) const
  {
    const double a = m_a, b = m_b, tolerance = m_tolerance;
    const bool step = a == b;
    const double width = step ? 1. : b - a;
    for(std::size_t j = 0; j < n; ++j)
    {
      const double v = x[j];
      const bool one = (v <= tolerance) | (v < a) | (step & (v <= a));
      const bool zero = (v > b) | (step & !one);
      double argument = CGAL_PI * (v - a) / width;
      argument = zero ? WEIGHT_ZERO : argument;
      t[j] = one ? WEIGHT_ONE : argument;
    }
  }

  static double weight_of_argument(double t)
  {
    if(t == WEIGHT_ONE)
      return 1.;
    if(t == WEIGHT_ZERO)
      return 0.;
    return 0.5 * std::cos(t) + 0.5;
  }
  /// \endcond

  /*!
    the weight of two unit normals given their dot product `c`: the same value as
    `operator()(std::acos(c))`, bit for bit, but `acos` is only evaluated in the transition band.
  */
  double weight_from_cosine(double c) const
  {
    if(c > m_cos_one)
      return 1.;
    if(c < m_cos_zero)
      return 0.;
    return (*this)(std::acos(std::clamp(c, -1., 1.)));
  }

private:
  double m_a, m_b, m_tolerance;
  double m_cos_one, m_cos_zero;
};

/// \cond SKIP_IN_MANUAL
namespace internal {
// The cosine whose arc cosine is normal_angle(n, m), or normal_line_angle(n, m) with `line`: the
// dot product clamped as they clamp it, so that a caller may take the arc cosine only where it
// needs the angle (Cosine_sigmoid::weight_from_cosine()) and still get the same bits.
template <typename Vector>
double normal_cosine(const Vector& n, const Vector& m, bool line)
{
  const double c = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
  return line ? (std::min)(std::abs(c), 1.) : std::clamp(c, -1., 1.);
}
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the angle in `[0, pi]` between two unit vectors given as coordinate triples:
  `acos` of their dot product clamped to `[-1, 1]` (SPEC §3).

  \tparam Vector a type whose coordinates are read as `n[0]`, `n[1]`, `n[2]` and convert to
          `double`, such as a CGAL `Vector_3` of a kernel with `double` coordinates or
          `Eigen::Vector3d`
  \param n, m unit vectors; they are not normalised
*/
template <typename Vector>
double normal_angle(const Vector& n, const Vector& m)
{
  return std::acos(internal::normal_cosine(n, m, false));
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the angle between the lines of two unit vectors, in `[0, pi/2]`: the arc cosine of the absolute
  value of their dot product, clamped to 1. It is the angle of the weights with the named parameter
  `line_angles`, for normals whose signs mean nothing (see the specification, "Line angles").
*/
template <typename Vector>
double normal_line_angle(const Vector& n, const Vector& m)
{
  return std::acos(internal::normal_cosine(n, m, true));
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_COSINE_SIGMOID_H
