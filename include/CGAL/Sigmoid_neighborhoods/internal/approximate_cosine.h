// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_APPROXIMATE_COSINE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_APPROXIMATE_COSINE_H

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// cos(t) for t in [0, pi] within 6e-16 of std::cos (the test [cosine] checks it), with
// arithmetic only, so that Eigen vectorizes it over an array (Eigen 3.4 vectorizes the cosine of
// floats, not of doubles), and without the rounding-mode save and restore of the C library's
// cosine: cos(t) = sin(u) with u = pi/2 - t in [-pi/2, pi/2], from its Taylor series up to u^21
// (the next term is below 1.2e-18) in Horner's scheme. The optimal search uses it for the weights
// of its approximations only; every exact value still goes through std::cos.
// T: double, or an Eigen array of doubles.
template <typename T>
T approximate_cosine(const T& t)
{
  const T u = 1.5707963267948966 - t, u2 = u * u;
  // (-1)^n / (2n + 1)!, n = 10 down to 1
  T p = u2 * 1.9572941063391263e-20 - 8.2206352466243295e-18;
  p = u2 * p + 2.8114572543455206e-15;
  p = u2 * p - 7.6471637318198164e-13;
  p = u2 * p + 1.6059043836821613e-10;
  p = u2 * p - 2.5052108385441720e-08;
  p = u2 * p + 2.7557319223985893e-06;
  p = u2 * p - 1.9841269841269841e-04;
  p = u2 * p + 8.3333333333333333e-03;
  p = u2 * p - 1.6666666666666666e-01;
  return u + u * (u2 * p);
}

// Weights 1/2 c + 1/2 from approximate_cosine() are within this of those from std::cos: four
// times the largest difference measured (2.2e-16; the test [cosine] checks a factor 4).
constexpr double APPROXIMATE_WEIGHT_ERROR = 1e-15;

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_APPROXIMATE_COSINE_H
