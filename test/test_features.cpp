// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sigmoid, the weighted covariance and the eigenvalue features on analytic cases.

#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Symmetric_eigenvalues_3.h>
#include <CGAL/Sigmoid_neighborhoods/internal/approximate_cosine.h>
#include <CGAL/Simple_cartesian.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;
typedef CGAL::Simple_cartesian<double>::Point_3 Point;

static const double pi = CGAL_PI;

TEST_CASE("sigmoid below, at and above a and b", "[sigmoid]")
{
  const SN::Cosine_sigmoid s(pi / 6, pi / 2);
  CHECK(s(0.) == 1.);
  CHECK(s(pi / 6 - 1e-3) == 1.);
  CHECK(s(pi / 6) == 1.);                          // x = a: cos(0) / 2 + 1/2
  CHECK(s(pi / 3) == Approx(0.5).epsilon(1e-15)); // middle of the band
  CHECK(s(pi / 6 + (pi / 3) / 4) == Approx(0.5 * std::cos(pi / 4) + 0.5).epsilon(1e-15));
  CHECK(s(pi / 2) == Approx(0.).margin(1e-16));   // x = b: cos(pi) / 2 + 1/2
  CHECK(s(pi / 2 + 1e-9) == 0.);
  CHECK(s(pi) == 0.);
}

TEST_CASE("sigmoid is monotone and C1 across the band", "[sigmoid]")
{
  const SN::Cosine_sigmoid s(0.2, 1.7);
  double previous = 1.;
  for(int i = 0; i <= 1000; ++i)
  {
    const double w = s(pi * i / 1000.);
    CHECK(w <= previous);
    CHECK(w >= 0.);
    previous = w;
  }
  // one-sided slopes at a and b vanish
  CHECK((s(0.2 + 1e-6) - s(0.2)) / 1e-6 == Approx(0.).margin(1e-5));
  CHECK((s(1.7) - s(1.7 - 1e-6)) / 1e-6 == Approx(0.).margin(1e-5));
}

TEST_CASE("sharp cut-off a = b keeps x = a", "[sigmoid]")
{
  const double c = std::acos(0.9);
  const SN::Cosine_sigmoid s(c, c);
  CHECK(s(c - 1e-12) == 1.);
  CHECK(s(c) == 1.);
  CHECK(s(std::nextafter(c, 4.)) == 0.);
  CHECK(s(pi) == 0.);
}

TEST_CASE("equal weights a = b = pi and a = b = 0", "[sigmoid]")
{
  const SN::Cosine_sigmoid equal(pi, pi);
  CHECK(equal.is_equal_weights());
  for(double x : {0., 1., 3., pi})
    CHECK(equal(x) == 1.);
  const SN::Cosine_sigmoid zero(0., 0.);
  CHECK(zero(0.) == 1.);
  CHECK(zero(1e-7) == 1.);  // within the default angle tolerance 1e-6
  CHECK(zero(2e-6) == 0.);
  const SN::Cosine_sigmoid strict(0., 0., 0.);
  CHECK(strict(1e-7) == 0.);
  CHECK(strict(0.) == 1.);
}

TEST_CASE("sigmoid rejects invalid parameters", "[sigmoid][bad-input]")
{
  CHECK_THROWS_AS(SN::Cosine_sigmoid(0.5, 0.4), std::invalid_argument);
  CHECK_THROWS_AS(SN::Cosine_sigmoid(-0.1, 0.4), std::invalid_argument);
  CHECK_THROWS_AS(SN::Cosine_sigmoid(0.1, 3.2), std::invalid_argument);
  CHECK_THROWS_AS(SN::Cosine_sigmoid(std::nan(""), 1.), std::invalid_argument);
  CHECK_THROWS_AS(SN::Cosine_sigmoid(0.1, 1., -1e-3), std::invalid_argument);
}

TEST_CASE("dot-product form equals the angle form bit for bit", "[sigmoid]")
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1., 1.);
  const std::vector<double> grid = {0., pi / 6, pi / 3, pi / 2, 2 * pi / 3, 5 * pi / 6, pi, std::acos(0.9)};
  std::size_t compared = 0;
  for(double a : grid)
    for(double b : grid)
    {
      if(a > b)
        continue;
      const SN::Cosine_sigmoid s(a, b);
      std::vector<double> cosines = {1., -1., 0., std::cos(a), std::cos(b), std::nextafter(1., 0.),
                                     std::cos(a) + 1e-9, std::cos(b) - 1e-9, std::cos(1e-6), std::cos(2e-6)};
      for(int i = 0; i < 2000; ++i)
        cosines.push_back(unit(rng));
      for(double c : cosines)
      {
        const double x = std::acos(std::clamp(c, -1., 1.));
        CHECK(s.weight_from_cosine(c) == s(x));
        ++compared;
      }
    }
  CHECK(compared > 50000);
}

// w_ij = w_ji needs no test: normal_cosine() is one product sum, which commutes bit for bit. What can
// go wrong is the line form: the angle between lines is the smaller of the angles to m and to -m.
TEST_CASE("line angles: the smaller angle to m and -m, in both forms", "[sigmoid]")
{
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  const SN::Cosine_sigmoid s(pi / 6, 2 * pi / 3);
  for(int i = 0; i < 1000; ++i)
  {
    Eigen::Vector3d n(g(rng), g(rng), g(rng)), m(g(rng), g(rng), g(rng));
    n.normalize();
    m.normalize();
    const double line = SN::normal_line_angle(n, m);
    CHECK(line <= pi / 2);
    CHECK(line == (std::min)(SN::normal_angle(n, m), SN::normal_angle(n, Eigen::Vector3d(-m))));
    const double c = n[0] * m[0] + n[1] * m[1] + n[2] * m[2]; // the package's order of the sum
    CHECK(s.weight_from_cosine((std::min)(std::abs(c), 1.)) == s(line));
  }
}

TEST_CASE("collinear points: L = 1, E = 0", "[features]")
{
  std::vector<Point> points;
  for(int i = 0; i < 7; ++i)
    points.emplace_back(1. + 0.5 * i, 2. + 0.25 * i, -1. + i);
  for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
  {
    const auto cov = SN::weighted_covariance(points, std::vector<double>(7, 1.), bary);
    const auto f = SN::dimensionality_features(cov);
    CHECK(f.linearity == Approx(1.).margin(1e-14));
    CHECK(f.error == Approx(0.).margin(1e-13));
    CHECK(f.label == SN::Dimensionality::LINEAR);
  }
}

TEST_CASE("regular disk: lambda1 = lambda2, E = 0, planar", "[features]")
{
  std::vector<Point> points = {Point(0.5, -0.25, 2.)};
  for(int i = 0; i < 12; ++i)
    points.emplace_back(0.5 + std::cos(2 * pi * i / 12), -0.25 + std::sin(2 * pi * i / 12), 2.);
  const auto cov = SN::weighted_covariance(points, std::vector<double>(13, 1.));
  const auto f = SN::dimensionality_features(cov);
  // sum of cos^2 over 12 equally spaced angles = 6
  CHECK(f.eigenvalues[0] == Approx(6.).epsilon(1e-13));
  CHECK(f.eigenvalues[1] == Approx(6.).epsilon(1e-13));
  CHECK(f.eigenvalues[2] == Approx(0.).margin(1e-13));
  CHECK(f.error == Approx(0.).margin(1e-12));
  CHECK(f.planarity == Approx(1.).margin(1e-13));
  CHECK(f.label == SN::Dimensionality::PLANAR);
}

TEST_CASE("cube corner: three edges give three equal eigenvalues", "[features]")
{
  // the corner and two points on each of the three edges, equal weights, unweighted or not:
  // the covariance is symmetric under permutation of the axes
  std::vector<Point> points = {Point(0, 0, 0)};
  for(double t : {1., 2.})
  {
    points.emplace_back(t, 0, 0);
    points.emplace_back(0, t, 0);
    points.emplace_back(0, 0, t);
  }
  const auto f = SN::dimensionality_features(SN::weighted_covariance(points, std::vector<double>(7, 1.)));
  // centre (3/7)(1,1,1): diagonal 5 - 9/7, off-diagonal -9/7, so the eigenvalues are
  // 5 (twice, across the diagonal) and 5 - 27/7 = 8/7 (along (1,1,1))
  CHECK(f.eigenvalues[0] == Approx(5.).epsilon(1e-13));
  CHECK(f.eigenvalues[1] == Approx(5.).epsilon(1e-13));
  CHECK(f.eigenvalues[2] == Approx(8. / 7.).epsilon(1e-13));
  CHECK(f.planarity == Approx(1. - 8. / 35.).epsilon(1e-13));
  CHECK(f.label == SN::Dimensionality::PLANAR);
  // with a sharp cut-off keeping one edge only, the corner neighborhood becomes linear
  const auto line = SN::dimensionality_features(
    SN::weighted_covariance(points, std::vector<double>{1., 1., 0., 0., 1., 0., 0.}));
  CHECK(line.linearity == Approx(1.).margin(1e-14));
  CHECK(line.error == Approx(0.).margin(1e-13));
}

TEST_CASE("equal eigenvalues (rho, rho, rho) give E = 0 and scattered", "[features]")
{
  const auto f = SN::dimensionality_features_from_eigenvalues(2., 2., 2.);
  CHECK(f.error == 0.);
  CHECK(f.scattering == 1.);
  CHECK(f.label == SN::Dimensionality::SCATTERED);
  CHECK(SN::dimensionality_features_from_eigenvalues(3., 0., 0.).error == 0.);
  CHECK(SN::dimensionality_features_from_eigenvalues(3., 3., 0.).error == 0.);
  CHECK(SN::dimensionality_features_from_eigenvalues(3., 3., -1e-18).scattering == 0.); // clamped
  CHECK(SN::dimensionality_features_from_eigenvalues(0., 0., 0.).is_degenerate());
  // E is largest, ln 3, for L = P = S = 1/3: eigenvalues (3, 2, 1)
  CHECK(SN::dimensionality_features_from_eigenvalues(3., 2., 1.).error == Approx(std::log(3.)).epsilon(1e-15));
}

TEST_CASE("label ties go to the first of linear, planar, scattered", "[features]")
{
  // L = P = 1/2, S = 0
  CHECK(SN::dimensionality_features_from_eigenvalues(2., 1., 0.).label == SN::Dimensionality::LINEAR);
  // P = S = 1/2, L = 0
  CHECK(SN::dimensionality_features_from_eigenvalues(2., 2., 1.).label == SN::Dimensionality::PLANAR);
  // L = S = 1/2, P = 0
  CHECK(SN::dimensionality_features_from_eigenvalues(2., 1., 1.).label == SN::Dimensionality::LINEAR);
}

TEST_CASE("L + P + S = 1 and 0 <= E <= ln 3 on random neighborhoods", "[features]")
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1., 1.), w01(0., 1.);
  for(int trial = 0; trial < 2000; ++trial)
  {
    std::vector<Point> points;
    std::vector<double> weights;
    const int m = 3 + trial % 18;
    for(int j = 0; j < m; ++j)
    {
      points.emplace_back(u(rng) * (1 + trial % 3), u(rng), u(rng) * 0.01 * (trial % 5));
      weights.push_back(j == 0 ? 1. : w01(rng));
    }
    for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
    {
      const auto f = SN::dimensionality_features(SN::weighted_covariance(points, weights, bary));
      REQUIRE_FALSE(f.is_degenerate());
      CHECK(f.linearity + f.planarity + f.scattering == Approx(1.).epsilon(1e-14));
      CHECK(f.error >= 0.);
      CHECK(f.error <= std::log(3.) + 1e-15);
      CHECK(f.eigenvalues[0] >= f.eigenvalues[1]);
      CHECK(f.eigenvalues[1] >= f.eigenvalues[2]);
      CHECK(f.eigenvalues[2] >= 0.);
    }
  }
}

TEST_CASE("degenerate cases of SPEC 4 with both barycenters", "[features][degenerate]")
{
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0.1)};
  SECTION("all weights zero")
  {
    // cannot happen through the sigmoid (w_ii = 1) but the covariance must still say so
    for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
    {
      const auto cov = SN::weighted_covariance(points, std::vector<double>(4, 0.), bary);
      CHECK(cov.weight_sum == 0.);
      CHECK(cov.is_degenerate());
      CHECK(SN::dimensionality_features(cov).error == std::numeric_limits<double>::infinity());
    }
  }
  SECTION("flipped normal or too small b: only the point itself keeps weight")
  {
    const std::vector<double> w = {1., 0., 0., 0.};
    const auto weighted = SN::weighted_covariance(points, w, SN::Barycenter::WEIGHTED);
    CHECK(weighted.trace() == 0.);
    CHECK(weighted.is_degenerate());
    CHECK(SN::dimensionality_features(weighted).label == SN::Dimensionality::DEGENERATE);
    // the literal formula keeps C != 0 through the point's offset from the plain mean
    const auto unweighted = SN::weighted_covariance(points, w, SN::Barycenter::UNWEIGHTED);
    CHECK(unweighted.trace() == Approx(0.5 + 0.025 * 0.025).epsilon(1e-14)); // |p_i - mean|^2
    CHECK_FALSE(unweighted.is_degenerate());
    CHECK(SN::dimensionality_features(unweighted).error == Approx(0.).margin(1e-13)); // rank one
  }
  SECTION("duplicates: all points at one position")
  {
    const std::vector<Point> same(5, Point(0.3, 0.3, 0.3));
    for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
    {
      const auto cov = SN::weighted_covariance(same, std::vector<double>(5, 1.), bary);
      CHECK(cov.squared_radius == 0.);
      CHECK(cov.is_degenerate());
    }
  }
  SECTION("relative threshold: a trace at 1e-13 of the radius is degenerate, at 1e-11 it is not")
  {
    // two heavy points at the centre, one far point with a tiny weight
    const std::vector<Point> p = {Point(0, 0, 0), Point(0, 0, 0), Point(1, 0, 0)};
    CHECK(SN::weighted_covariance(p, std::vector<double>{1., 1., 1e-13}).is_degenerate());
    CHECK_FALSE(SN::weighted_covariance(p, std::vector<double>{1., 1., 1e-11}).is_degenerate());
  }
}

// The optimal search's approximations use the fast closed form; SPEC 4 trusts an approximation of
// E_dim only to 1e-5, so the eigenvalues must be as accurate as Eigen's own closed form.
TEST_CASE("fast 3x3 eigenvalues agree with the iterative solver", "[features][eigenvalues]")
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::normal_distribution<double> normal;
  double worst_separated = 0., worst_any = 0., worst_over_bound = 0.;
  int separated = 0;
  for(int trial = 0; trial < 200000; ++trial)
  {
    // eigenvalues of every shape: linear, planar, near-double, triple, rank 1 and 2, and any scale
    std::array<double, 3> wanted{{unit(rng), unit(rng), unit(rng)}};
    switch(trial % 6)
    {
      case 0: wanted[1] = wanted[2] = 0.; break;                              // rank 1
      case 1: wanted[2] = 0.; break;                                          // rank 2
      case 2: wanted[1] = wanted[0] * (1. - std::pow(10., -12. * unit(rng))); break; // near-double
      case 3: wanted[2] = wanted[1] * (1. - std::pow(10., -12. * unit(rng))); break;
      case 4: wanted[1] = wanted[2] = wanted[0]; break;                        // triple
      default: break;
    }
    const double scale = std::pow(10., 400. * unit(rng) - 200.); // both sides of the rescaling at 1e+-90
    const Eigen::Matrix3d rotation =
      Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    const Eigen::Matrix3d c =
      rotation * Eigen::Vector3d(wanted[0], wanted[1], wanted[2]).asDiagonal() * rotation.transpose() * scale;
    const std::array<double, 3> fast = SN::internal::symmetric_eigenvalues_3(c);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(c, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d& ev = solver.eigenvalues();
    const double trace = c.trace();
    REQUIRE(fast[0] >= fast[1]);
    REQUIRE(fast[1] >= fast[2]);
    double error = 0.;
    for(int i = 0; i < 3; ++i)
      error = (std::max)(error, std::abs(fast[i] - ev[2 - i]) / trace);
    worst_any = (std::max)(worst_any, error);
    // the error bound that the optimal search's margins rest on, with a factor 8 to spare
    const double relative_gap = (std::min)(fast[0] - fast[1], fast[1] - fast[2]) / fast[0];
    worst_over_bound = (std::max)(
      worst_over_bound, error * trace / (fast[0] * SN::internal::closed_form_relative_error(relative_gap)));
    // eigenvalues at least 1e-3 of the trace apart: the closed form is exact to rounding
    if(ev[2] - ev[1] > 1e-3 * trace && ev[1] - ev[0] > 1e-3 * trace)
    {
      ++separated;
      worst_separated = (std::max)(worst_separated, error);
    }
  }
  CHECK(separated > 20000);
  CHECK(worst_separated < 1e-12); // SPEC 4's accuracy of the iterative solver
  CHECK(worst_any < 1e-7); // nearly coincident eigenvalues: what every closed form loses (SPEC 4)
  CHECK(worst_over_bound < 1. / 8.);
  // a zero matrix
  const std::array<double, 3> zero = SN::internal::symmetric_eigenvalues_3(Eigen::Matrix3d::Zero());
  CHECK(zero[0] == 0.);
  CHECK(zero[2] == 0.);
}

TEST_CASE("the polynomial cosine of the approximations is within 6e-16 of std::cos", "[features][cosine]")
{
  // the bound of internal/approximate_cosine.h, and the weight error the margins assume with a factor 4
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(0., CGAL_PI);
  double worst_cosine = 0., worst_weight = 0.;
  for(int i = 0; i <= 2000000; ++i)
  {
    const double t = i <= 1000000 ? i * (CGAL_PI / 1000000) : angle(rng);
    const double fast = SN::internal::approximate_cosine(t), exact = std::cos(t);
    worst_cosine = (std::max)(worst_cosine, std::abs(fast - exact));
    worst_weight = (std::max)(worst_weight, std::abs((0.5 * fast + 0.5) - (0.5 * exact + 0.5)));
  }
  CHECK(worst_cosine <= 6e-16);
  CHECK(worst_weight <= SN::internal::APPROXIMATE_WEIGHT_ERROR / 4);
  // vectorized, the same values
  Eigen::Array<double, 8, 1> t;
  t << 0., 0.1, 0.5, 1., 1.5707963267948966, 2., 3., CGAL_PI;
  const Eigen::Array<double, 8, 1> batch = SN::internal::approximate_cosine<Eigen::Array<double, 8, 1>>(t);
  for(int i = 0; i < 8; ++i)
    CHECK(std::abs(batch[i] - std::cos(t[i])) <= 6e-16);
  CHECK(batch[0] == 1.);
  CHECK(batch[7] == -1.);
}

TEST_CASE("the arguments of many angles at once are transition_argument's, bit for bit", "[sigmoid]")
{
  typedef SN::Cosine_sigmoid S;
  const double pi = CGAL_PI, nan = std::numeric_limits<double>::quiet_NaN();
  // the grid's values and their neighbors, the tolerance's, 0, pi and NaN; 37 angles (no whole batch)
  std::vector<double> x = {0., std::nextafter(0., 1.), 1e-7, 1e-6, std::nextafter(1e-6, 1.), pi, nan};
  for(int i = 1; i < 6; ++i)
    for(double v : {i * pi / 6, std::nextafter(i * pi / 6, 0.), std::nextafter(i * pi / 6, 4.)})
      x.push_back(v);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0., pi);
  while(x.size() < 37)
    x.push_back(angle(random));
  std::size_t band = 0, ones = 0, zeros = 0;
  for(double tolerance : {0., 1e-6, pi / 6})
    for(int i = 0; i <= 6; ++i)
      for(int j = i; j <= 6; ++j)
      {
        const S sigmoid(i == 6 ? pi : i * pi / 6, j == 6 ? pi : j * pi / 6, tolerance);
        std::vector<double> t(x.size(), 5.);
        sigmoid.transition_arguments(x.data(), x.size(), t.data());
        for(std::size_t e = 0; e < x.size(); ++e)
        {
          const double expected = sigmoid.transition_argument(x[e]);
          CHECK(std::memcmp(&t[e], &expected, sizeof(double)) == 0);
          expected == S::WEIGHT_ONE ? ++ones : expected == S::WEIGHT_ZERO ? ++zeros : ++band;
        }
      }
  // every case taken (the grid's steps a = b among the pairs)
  CHECK(band > 0);
  CHECK(ones > 0);
  CHECK(zeros > 0);
}

TEST_CASE("sigmoid cases and cosine arguments", "[sigmoid]")
{
  typedef SN::Cosine_sigmoid S;
  const S band(CGAL_PI / 6, CGAL_PI / 2);
  CHECK(band.transition_argument(0.) == S::WEIGHT_ONE);
  CHECK(band.transition_argument(0.5) == S::WEIGHT_ONE);
  CHECK(band.transition_argument(CGAL_PI / 6) == 0.);
  CHECK(band.transition_argument(CGAL_PI / 3) == Approx(CGAL_PI / 2).epsilon(1e-15));
  CHECK(band.transition_argument(CGAL_PI / 2) == Approx(CGAL_PI).epsilon(1e-15));
  CHECK(band.transition_argument(2.) == S::WEIGHT_ZERO);
  const S sharp(1., 1.);
  CHECK(sharp.transition_argument(1.) == S::WEIGHT_ONE);
  CHECK(sharp.transition_argument(std::nextafter(1., 2.)) == S::WEIGHT_ZERO);
  CHECK(S::weight_of_argument(S::WEIGHT_ONE) == 1.);
  CHECK(S::weight_of_argument(S::WEIGHT_ZERO) == 0.);
  CHECK(S::weight_of_argument(CGAL_PI / 2) == 0.5);
  // the weight of an angle is the weight of its argument, bit for bit
  for(double x = 0.; x <= CGAL_PI; x += 0.01)
  {
    const double w = band(x), v = S::weight_of_argument(band.transition_argument(x));
    CHECK(std::memcmp(&w, &v, sizeof(double)) == 0);
  }
}
