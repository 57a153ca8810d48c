// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Neighborhoods, the optimal search and the fixed-triple features on point ranges and meshes,
// against a plain reference loop written here from SPEC.md.

#include "test_models.h"

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <CGAL/Sigmoid_neighborhoods.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <CGAL/Sigmoid_neighborhoods/Normal_estimation_method.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/property_map.h>
#include <CGAL/Random.h>

#include <catch2/catch.hpp>


#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <map>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;
namespace PMP = CGAL::Polygon_mesh_processing;

static const double pi = CGAL_PI;
static const double inf = std::numeric_limits<double>::infinity();

static Point_list mesh_point_list(const Mesh& mesh)
{
  std::map<Mesh::Vertex_index, Vector_3> normals;
  PMP::compute_vertex_normals(mesh, boost::make_assoc_property_map(normals));
  Point_list result;
  for(auto v : mesh.vertices())
    result.emplace_back(mesh.point(v), normals[v]);
  return result;
}

// A noisy, curved patch with a crease: enough variety for every grid value to matter.
static Point_list folded_sheet(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0., 0.01);
  Point_list result;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const double x = double(i) / n - 0.5, y = double(j) / n - 0.5;
      const double z = 0.4 * std::abs(x) + 0.2 * y * y + noise(rng);
      Vector_3 normal(x < 0 ? 0.4 : -0.4, -0.4 * y, 1.);
      normal = normal + Vector_3(noise(rng), noise(rng), noise(rng)) * 5.;
      result.emplace_back(Point_3(x + noise(rng), y + noise(rng), z), normal);
    }
  return result;
}

// ---------------------------------------------------------------------------------------------
// The plain reference: brute-force neighbors, every triple through the public covariance.

static std::vector<std::size_t> brute_force_neighborhood(const Point_list& points, std::size_t i, unsigned k)
{
  std::vector<std::size_t> order;
  for(std::size_t j = 0; j < points.size(); ++j)
    if(j != i)
      order.push_back(j);
  auto d2 = [&](std::size_t j) {
    const double dx = points[j].first.x() - points[i].first.x();
    const double dy = points[j].first.y() - points[i].first.y();
    const double dz = points[j].first.z() - points[i].first.z();
    return dx * dx + dy * dy + dz * dz;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d2(a) < d2(b); });
  order.resize(k);
  order.insert(order.begin(), i);
  return order;
}

static SN::Dimensionality_features plain_features(const Point_list& points, std::size_t i, double a, double b,
                                                  unsigned k, SN::Barycenter bary)
{
  const SN::Cosine_sigmoid sigmoid(a, b);
  const auto hood = brute_force_neighborhood(points, i, k);
  std::vector<Point_3> ps;
  std::vector<double> ws;
  Eigen::Vector3d ni(points[i].second.x(), points[i].second.y(), points[i].second.z());
  ni.normalize();
  for(std::size_t j : hood)
  {
    Eigen::Vector3d nj(points[j].second.x(), points[j].second.y(), points[j].second.z());
    nj.normalize();
    ps.push_back(points[j].first);
    ws.push_back(sigmoid(SN::normal_angle(ni, nj)));
  }
  return SN::dimensionality_features(SN::weighted_covariance(ps, ws, bary));
}

static SN::Optimal_sigmoid_neighborhood
plain_optimal(const Point_list& points, std::size_t i, SN::Barycenter bary,
              SN::Neighborhood_criterion criterion = SN::Neighborhood_criterion::DIMENSIONALITY)
{
  SN::Optimal_sigmoid_neighborhood best;
  best.criterion = criterion;
  const auto grid = SN::defaults::angle_grid();
  for(double a : grid)
    for(double b : grid)
    {
      if(a > b)
        continue;
      for(unsigned k = 6; k <= 20; ++k)
      {
        const auto f = plain_features(points, i, a, b, k, bary);
        const double error = SN::criterion_value(f, criterion);
        if(error < best.error() - 1e-12)
        {
          best.a = a;
          best.b = b;
          best.k = k;
          best.features = f;
        }
        if(a == pi && b == pi && error < best.error_equal - 1e-12)
        {
          best.error_equal = error;
          best.k_equal = k;
        }
      }
    }
  return best;
}

static bool same_record(const SN::Optimal_sigmoid_neighborhood& r, const SN::Optimal_sigmoid_neighborhood& s)
{
  return same_bits(r.a, s.a) && same_bits(r.b, s.b) && r.k == s.k && same_bits(r.error(), s.error()) &&
         same_bits(r.features.linearity, s.features.linearity) &&
         same_bits(r.features.planarity, s.features.planarity) &&
         same_bits(r.features.scattering, s.features.scattering) && r.features.label == s.features.label &&
         same_bits(r.features.error, s.features.error) && same_bits(r.features.eigenentropy, s.features.eigenentropy) &&
         r.criterion == s.criterion &&
         same_bits(r.error_equal, s.error_equal) && r.k_equal == s.k_equal;
}

// The path of the search's batched eigenvalues in these tests: ctest runs the [optimal] tests once
// more on each path (the test harness's variable SN_TEST_VECTOR_INSTRUCTIONS, read here, never by
// the package), and every path must give the plain loop's records bit for bit. A path the processor
// lacks: the widest it has.
static SN::Vector_instructions tested_vector_instructions()
{
  if(const char* forced = std::getenv("SN_TEST_VECTOR_INSTRUCTIONS"))
    for(SN::Vector_instructions v :
        {SN::Vector_instructions::PORTABLE, SN::Vector_instructions::AVX2, SN::Vector_instructions::AVX512})
      if(std::string(forced) == SN::vector_instructions_name(v) && SN::has_vector_instructions(v))
        return v;
  return SN::widest_vector_instructions();
}

static std::vector<SN::Optimal_sigmoid_neighborhood>
optimal(const Point_list& points, SN::Barycenter bary = SN::Barycenter::WEIGHTED,
        SN::Neighborhood_criterion criterion = SN::Neighborhood_criterion::DIMENSIONALITY,
        SN::Vector_instructions path = tested_vector_instructions())
{
  std::vector<SN::Optimal_sigmoid_neighborhood> result;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    points, std::back_inserter(result),
    SNP::vector_instructions(path, SNP::criterion(criterion, SNP::barycenter(bary)))
      .point_map(Point_map())
      .normal_map(Normal_map()));
  return result;
}

// ---------------------------------------------------------------------------------------------

TEST_CASE("k nearest neighbors are ordered by distance, ties by index", "[neighbors]")
{
  // a regular grid is full of ties
  std::vector<SN::internal::Double_point> points;
  for(int i = 0; i < 9; ++i)
    for(int j = 0; j < 9; ++j)
      points.emplace_back(i, j, 0.);
  // shuffle indices so that index order is not the grid order
  std::mt19937_64 rng(5);
  std::shuffle(points.begin(), points.end(), rng);
  const SN::internal::Neighbor_query query(points);
  std::vector<SN::internal::Neighbor> found;
  for(std::uint32_t i = 0; i < points.size(); ++i)
    for(unsigned k : {1u, 4u, 8u, 12u, 20u, 70u}) // beyond 64 neighbors, another sort
    {
      query.query(i, k, found);
      std::vector<std::uint32_t> expected;
      for(std::uint32_t j = 0; j < points.size(); ++j)
        if(j != i)
          expected.push_back(j);
      auto d2 = [&](std::uint32_t j) { return CGAL::squared_distance(points[i], points[j]); };
      std::stable_sort(expected.begin(), expected.end(),
                       [&](std::uint32_t a, std::uint32_t b) { return d2(a) < d2(b); });
      REQUIRE(found.size() == k);
      for(unsigned t = 0; t < k; ++t)
        CHECK(found[t].index == expected[t]);
    }
}

// The optimal search takes the weights of a pair whose a exceeds every angle of the neighborhood
// as all ones without evaluating the sigmoid; that must be what the sigmoid gives, bit for bit.
TEST_CASE("all-ones weights are recognised exactly where the sigmoid gives 1 everywhere", "[optimal][sigmoid]")
{
  const Point_list points = folded_sheet(12, 3);
  const SN::internal::Oriented_points input =
    SN::internal::copy_oriented_points(points, Point_map(), Normal_map());
  const SN::internal::Neighbor_query query(input.points);
  std::vector<SN::internal::Neighbor> neighbors;
  SN::internal::Local_neighborhood local;
  const double pi = CGAL_PI;
  std::size_t all_ones = 0, evaluated = 0;
  for(std::uint32_t i = 0; i < input.size(); i += 5)
  {
    query.query(i, 20, neighbors);
    local.assign(input, i, neighbors);
    double largest = 0.;
    std::vector<double> angles(1, 0.);
    for(const auto& n : neighbors)
    {
      angles.push_back(SN::normal_angle(input.normals[i], input.normals[n.index]));
      largest = (std::max)(largest, angles.back());
    }
    // the angles taken from the cosines kept: normal_angle()'s bits
    REQUIRE(local.angles().size() == angles.size());
    CHECK(std::memcmp(local.angles().data(), angles.data(), angles.size() * sizeof(double)) == 0);
    // a just below, at and above the largest angle, and the tolerance on both sides of it
    for(double a : {0., largest * (1. - 1e-12), largest, std::nextafter(largest, 4.), pi / 6, pi})
      for(double tolerance : {0., largest, 1e-6})
      {
        if(a > pi || tolerance >= pi)
          continue;
        const SN::Cosine_sigmoid sigmoid(a, (std::max)(a, pi / 2), tolerance);
        std::vector<double> w(angles.size());
        local.weights(sigmoid, w.data());
        // the optimal search's form: cosine arguments, then weights
        std::vector<double> t(angles.size());
        const bool ones = local.transition_arguments(sigmoid, t.data());
        bool every_one = true;
        for(std::size_t j = 0; j < angles.size(); ++j)
        {
          const double expected = sigmoid(angles[j]);
          CHECK(std::memcmp(&w[j], &expected, sizeof(double)) == 0);
          every_one = every_one && expected == 1.;
        }
        if(ones)
          CHECK(every_one);
        ones ? ++all_ones : ++evaluated;
        for(std::size_t j = 0; j < angles.size(); ++j)
        {
          const double v = SN::Cosine_sigmoid::weight_of_argument(t[j]);
          CHECK(std::memcmp(&w[j], &v, sizeof(double)) == 0);
        }
      }
  }
  CHECK(all_ones > 0);
  CHECK(evaluated > 0);

  // with line angles (normals with any sign): normal_line_angle()'s bits, and its weights
  const SN::internal::Oriented_points lines =
    SN::internal::copy_oriented_points(points, Point_map(), Normal_map(), true);
  const SN::Cosine_sigmoid band(0., pi / 3);
  for(std::uint32_t i = 0; i < lines.size(); i += 5)
  {
    query.query(i, 20, neighbors);
    local.assign(lines, i, neighbors);
    std::vector<double> angles(1, 0.), w(neighbors.size() + 1);
    for(const auto& n : neighbors)
      angles.push_back(SN::normal_line_angle(lines.normals[i], lines.normals[n.index]));
    REQUIRE(local.angles().size() == angles.size());
    CHECK(std::memcmp(local.angles().data(), angles.data(), angles.size() * sizeof(double)) == 0);
    local.weights(band, w.data());
    for(std::size_t j = 0; j < angles.size(); ++j)
    {
      const double expected = band(angles[j]);
      CHECK(std::memcmp(&w[j], &expected, sizeof(double)) == 0);
    }
  }
}

TEST_CASE("optimal search equals the plain loop over all 420 triples", "[optimal]")
{
  const Point_list points = folded_sheet(15, 1);
  for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
  {
    const auto fast = optimal(points, bary);
    REQUIRE(fast.size() == points.size());
    std::size_t first_pair = 0, checked = 0;
    for(std::size_t i = 0; i < points.size(); i += 3, ++checked)
    {
      const auto plain = plain_optimal(points, i, bary);
      CHECK(same_record(fast[i], plain));
      first_pair += (fast[i].a == 0. && fast[i].b == 0.);
    }
    if(bary == SN::Barycenter::WEIGHTED)
      CHECK(first_pair < checked / 2); // the noisy normals exercise the whole grid
    else
      CHECK(first_pair == checked); // SPEC 4: the lone point gives a rank-one matrix, E = 0
  }
}

TEST_CASE("vector instructions: every path the processor has gives the portable path's records", "[optimal][vector-instructions]")
{
  using SN::Vector_instructions;
  CHECK(SN::has_vector_instructions(Vector_instructions::PORTABLE));
  CHECK(SN::has_vector_instructions(SN::widest_vector_instructions()));
  INFO("the widest path here: " << SN::vector_instructions_name(SN::widest_vector_instructions()));
  Point_list sheet = folded_sheet(9, 5);
  sheet[40].second = -sheet[40].second; // a flipped normal: failures for some pairs
  std::size_t paths = 0;
  for(Vector_instructions v : {Vector_instructions::AVX2, Vector_instructions::AVX512})
  {
    if(!SN::has_vector_instructions(v))
    {
      CHECK_THROWS_AS(optimal(sheet, SN::Barycenter::WEIGHTED, SN::Neighborhood_criterion::DIMENSIONALITY, v),
                      std::invalid_argument);
      continue;
    }
    ++paths;
    for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
      for(auto criterion : {SN::Neighborhood_criterion::DIMENSIONALITY, SN::Neighborhood_criterion::EIGENENTROPY})
      {
        const auto portable = optimal(sheet, bary, criterion, Vector_instructions::PORTABLE);
        const auto wide = optimal(sheet, bary, criterion, v);
        REQUIRE(wide.size() == portable.size());
        std::size_t same = 0;
        for(std::size_t i = 0; i < wide.size(); ++i)
          same += same_record(wide[i], portable[i]);
        CHECK(same == wide.size());
      }
  }
  if(paths == 0)
    WARN("this processor has no AVX2: only the portable path was run");
}

TEST_CASE("eigenentropy: analytic values, scale invariance, no additive constant", "[features][criterion]")
{
  // a line, a plane with equal spread, an isotropic volume
  CHECK(SN::internal::eigenentropy(1., 0., 0.) == 0.);
  CHECK(SN::internal::eigenentropy(2., 2., 0.) == Approx(std::log(2.)).epsilon(1e-15));
  CHECK(SN::internal::eigenentropy(3., 3., 3.) == Approx(std::log(3.)).epsilon(1e-15));
  // e = (1/2, 1/4, 1/4): 1/2 ln 2 + 2 (1/4 ln 4) = 1.5 ln 2
  CHECK(SN::internal::eigenentropy(2., 1., 1.) == Approx(1.5 * std::log(2.)).epsilon(1e-15));
  // the same shape at any scale (pgeof's + 1e-3 would make the tiny one nearly isotropic)
  CHECK(SN::internal::eigenentropy(2e-8, 1e-8, 1e-8) == Approx(1.5 * std::log(2.)).epsilon(1e-14));
  const SN::Dimensionality_features f = SN::dimensionality_features_from_eigenvalues(4., 1., 0.);
  CHECK(f.eigenentropy == Approx(-(0.8 * std::log(0.8) + 0.2 * std::log(0.2))).epsilon(1e-15));
  CHECK(SN::criterion_value(f, SN::Neighborhood_criterion::EIGENENTROPY) == f.eigenentropy);
  CHECK(SN::criterion_value(f, SN::Neighborhood_criterion::DIMENSIONALITY) == f.error);
  CHECK(std::isinf(SN::dimensionality_features_from_eigenvalues(0., 0., 0.).eigenentropy));
  CHECK(SN::criterion_from_name("eigenentropy") == SN::Neighborhood_criterion::EIGENENTROPY);
  CHECK(std::string(SN::criterion_name(SN::Neighborhood_criterion::DIMENSIONALITY)) == "dimensionality");
  CHECK_THROWS_WITH(SN::criterion_from_name("entropy"), Catch::Contains("expected dimensionality or eigenentropy"));
}

// The names the tool and the Python module parse: each value's name gives it back, and any other
// name is refused with the names expected.
TEST_CASE("option names: every value round-trips, others are refused", "[names]")
{
  for(SN::Barycenter b : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
    CHECK(SN::barycenter_from_name(SN::barycenter_name(b)) == b);
  CHECK(std::string(SN::barycenter_name(SN::Barycenter::UNWEIGHTED)) == "unweighted");
  CHECK_THROWS_WITH(SN::barycenter_from_name("Weighted"), Catch::Contains("expected weighted or unweighted"));
  for(SN::Normal_estimation_method m : {SN::Normal_estimation_method::PCA, SN::Normal_estimation_method::JET})
    CHECK(SN::normal_estimation_method_from_name(SN::normal_estimation_method_name(m)) == m);
  CHECK(std::string(SN::normal_estimation_method_name(SN::Normal_estimation_method::JET)) == "jet");
  CHECK_THROWS_WITH(SN::normal_estimation_method_from_name("svd"), Catch::Contains("expected pca or jet"));
  for(SN::Normal_source s : {SN::Normal_source::AUTO, SN::Normal_source::FROM_FILE, SN::Normal_source::PCA,
                             SN::Normal_source::JET})
    CHECK(SN::normal_source_from_name(SN::normal_source_name(s)) == s);
  CHECK(std::string(SN::normal_source_name(SN::Normal_source::FROM_FILE)) == "file");
  CHECK_THROWS_WITH(SN::normal_source_from_name(""), Catch::Contains("expected auto, file, pca or jet"));
  for(SN::Normal_orientation o : {SN::Normal_orientation::SPANNING_FOREST, SN::Normal_orientation::VIEWPOINT,
                                  SN::Normal_orientation::UPWARD, SN::Normal_orientation::NONE})
    CHECK(SN::normal_orientation_from_name(SN::normal_orientation_name(o)) == o);
  CHECK(std::string(SN::normal_orientation_name(SN::Normal_orientation::UPWARD)) == "up");
  CHECK_THROWS_WITH(SN::normal_orientation_from_name("spanning_forest"),
                    Catch::Contains("expected mst, viewpoint, up or none"));
}

TEST_CASE("eigenentropy criterion: the search equals the plain loop", "[optimal][criterion]")
{
  const auto eigenentropy = SN::Neighborhood_criterion::EIGENENTROPY;
  for(double scale : {1., 1e-150, 1e120})
  {
    Point_list points = folded_sheet(13, 4);
    for(auto& p : points)
      p.first = Point_3(p.first.x() * scale, p.first.y() * scale, p.first.z() * scale);
    for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
    {
      if(scale != 1. && bary == SN::Barycenter::UNWEIGHTED)
        continue;
      const auto fast = optimal(points, bary, eigenentropy);
      const auto dimensionality = optimal(points, bary);
      REQUIRE(fast.size() == points.size());
      std::size_t finite = 0, other_triple = 0;
      for(std::size_t i = 0; i < points.size(); i += 3)
      {
        const auto plain = plain_optimal(points, i, bary, eigenentropy);
        CHECK(same_record(fast[i], plain));
        CHECK(fast[i].criterion == eigenentropy);
        CHECK(same_bits(fast[i].error(), fast[i].features.eigenentropy));
        finite += std::isfinite(fast[i].error());
        other_triple += fast[i].k != dimensionality[i].k || fast[i].a != dimensionality[i].a ||
                        fast[i].b != dimensionality[i].b;
      }
      CHECK(finite > 0);
      // the two criteria disagree somewhere: the parameter is read (with the plain mean as barycenter,
      // the point alone at (0, 0) has a rank-one matrix, 0 for both criteria: both stop there)
      if(bary == SN::Barycenter::WEIGHTED)
        CHECK(other_triple > 0);
      else
        CHECK(other_triple == 0);
    }
  }
}

TEST_CASE("equal weights alone: the search is the full search's equal-weights part", "[optimal][equal]")
{
  // a = b = pi only: no angle is computed and the one scan gives both records
  const Point_list points = folded_sheet(15, 1);
  const std::vector<double> pi{CGAL_PI};
  for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
  {
    const auto full = optimal(points, bary);
    std::vector<SN::Optimal_sigmoid_neighborhood> equal;
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
      points, std::back_inserter(equal),
      SNP::a_grid(pi, SNP::b_grid(pi, SNP::barycenter(bary))).point_map(Point_map()).normal_map(Normal_map()));
    REQUIRE(equal.size() == full.size());
    std::size_t sizes_differ = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const auto& e = equal[i];
      CHECK(e.a == CGAL_PI);
      CHECK(e.b == CGAL_PI);
      CHECK(e.k == full[i].k_equal);
      CHECK(std::memcmp(&e.features.error, &full[i].error_equal, sizeof(double)) == 0);
      CHECK(e.k_equal == e.k);
      CHECK(std::memcmp(&e.error_equal, &e.features.error, sizeof(double)) == 0);
      // the features are those of a plain evaluation at (pi, pi, k)
      const auto plain = plain_features(points, i, CGAL_PI, CGAL_PI, e.k, bary);
      CHECK(std::memcmp(&e.features.error, &plain.error, sizeof(double)) == 0);
      sizes_differ += (e.k != full[i].k);
    }
    CHECK(sizes_differ > 0); // the sheet's folds make the weighted optimum differ somewhere
  }
}

TEST_CASE("optimal search equals the plain loop where band weights round to 0 and 1", "[optimal][sigmoid]")
{
  // Normal angles within 1e-10 of the grid's values: inside the transition band of some pairs,
  // the weight 1/2 cos(t) + 1/2 then rounds to exactly 0 (t near pi) or 1 (t near 0), which the
  // search, deciding cases from the arguments, does not recognise as repeats; the outcome must
  // not change.
  Point_list points = folded_sheet(14, 7);
  std::mt19937_64 rng(7);
  const std::vector<double> tilts{0., pi / 3 - 1e-10, pi / 6 + 1e-10, pi / 2 - 3e-10, pi / 3 + 2e-11, 1e-7};
  for(auto& p : points)
  {
    const double tilt = tilts[rng() % tilts.size()];
    p.second = Vector_3(0., std::sin(tilt), std::cos(tilt));
  }
  for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
  {
    const auto fast = optimal(points, bary);
    REQUIRE(fast.size() == points.size());
    std::size_t finite = 0;
    for(std::size_t i = 0; i < points.size(); i += 4)
    {
      const auto plain = plain_optimal(points, i, bary);
      CHECK(same_record(fast[i], plain));
      finite += std::isfinite(fast[i].error());
    }
    CHECK(finite > 0);
  }
}

TEST_CASE("optimal search equals the plain loop at tiny and huge scales", "[optimal][scale]")
{
  // The approximations work on offsets scaled to a unit radius, the exact path at the input's
  // scale: the comparisons they decide must come out the same from 1e-150 to 1e120.
  for(double scale : {1e-150, 1e-60, 1e120})
  {
    Point_list points = folded_sheet(12, 3);
    for(auto& p : points)
      p.first = Point_3(p.first.x() * scale, p.first.y() * scale, p.first.z() * scale);
    const auto fast = optimal(points, SN::Barycenter::WEIGHTED);
    REQUIRE(fast.size() == points.size());
    std::size_t finite = 0;
    for(std::size_t i = 0; i < points.size(); i += 5)
    {
      const auto plain = plain_optimal(points, i, SN::Barycenter::WEIGHTED);
      CHECK(same_record(fast[i], plain));
      finite += std::isfinite(fast[i].error());
    }
    CHECK(finite > 0);
  }
}

TEST_CASE("fixed triple features equal the optimal record at its own triple", "[features][optimal]")
{
  const Point_list points = folded_sheet(12, 2);
  const auto records = optimal(points);
  for(std::size_t i = 0; i < points.size(); i += 7)
  {
    const auto& r = records[i];
    REQUIRE_FALSE(r.is_failure());
    std::vector<SN::Dimensionality_features> features;
    SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, SN::Cosine_sigmoid(r.a, r.b), r.k,
                                                       std::back_inserter(features), maps());
    CHECK(same_bits(features[i].error, r.error()));
    CHECK(same_bits(features[i].linearity, r.features.linearity));
    CHECK(features[i].label == r.features.label);
  }
}

TEST_CASE("a plane: every pair gives the same weights, ties go to a = b = 0", "[optimal][ties]")
{
  Point_list points;
  for(int i = 0; i < 10; ++i)
    for(int j = 0; j < 10; ++j)
      points.emplace_back(Point_3(0.1 * i + 0.013 * (j % 3), 0.1 * j + 0.007 * (i % 4), 1.), Vector_3(0, 0, 2));
  for(const auto& r : optimal(points))
  {
    CHECK(r.a == 0.);
    CHECK(r.b == 0.);
    CHECK(same_bits(r.error(), r.error_equal));
    CHECK(r.k == r.k_equal);
    CHECK(r.features.scattering == Approx(0.).margin(1e-12));
  }
}

TEST_CASE("a line: every triple has E = 0, so the first triple (0, 0, k_min) wins", "[optimal][ties]")
{
  Point_list points;
  for(int i = 0; i < 40; ++i)
    points.emplace_back(Point_3(0.5 * i, 0.25 * i, 3.), Vector_3(0, 0, 1));
  for(const auto& r : optimal(points))
  {
    CHECK(r.a == 0.);
    CHECK(r.b == 0.);
    CHECK(r.k == 6);
    CHECK(r.k_equal == 6);
    CHECK(r.error() == Approx(0.).margin(1e-12));
    CHECK(r.features.label == SN::Dimensionality::LINEAR);
  }
}

TEST_CASE("a flipped normal fails for a = b = 0 but not for equal weights", "[degenerate]")
{
  Point_list points = folded_sheet(8, 3);
  points[27].second = -points[27].second;
  std::vector<SN::Dimensionality_features> cut, cut_unweighted, equal;
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, SN::Cosine_sigmoid(0., pi / 2), 10,
                                                     std::back_inserter(cut), maps());
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(
    points, SN::Cosine_sigmoid(0., pi / 2), 10, std::back_inserter(cut_unweighted),
    SNP::barycenter(SN::Barycenter::UNWEIGHTED).point_map(Point_map()).normal_map(Normal_map()));
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, SN::Cosine_sigmoid(pi, pi), 10,
                                                     std::back_inserter(equal), maps());
  CHECK(cut[27].is_degenerate());
  CHECK(cut[27].error == inf);
  CHECK_FALSE(cut_unweighted[27].is_degenerate()); // the literal formula never vanishes
  CHECK_FALSE(equal[27].is_degenerate());
  const auto records = optimal(points);
  CHECK_FALSE(records[27].is_failure());
  CHECK(records[27].b > pi / 2);
}

TEST_CASE("more duplicates than k: every triple fails, the point is a failure", "[degenerate]")
{
  Point_list points;
  for(int i = 0; i < 25; ++i)
    points.emplace_back(Point_3(1, 1, 1), Vector_3(0, 0, 1));
  for(int i = 0; i < 30; ++i)
    points.emplace_back(Point_3(5 + i, 2. * (i % 2), 0.3 * (i % 5)), Vector_3(0, 0, 1));
  for(auto bary : {SN::Barycenter::WEIGHTED, SN::Barycenter::UNWEIGHTED})
  {
    const auto records = optimal(points, bary);
    for(int i = 0; i < 25; ++i)
    {
      CHECK(records[i].is_failure());
      CHECK(records[i].error() == inf);
      CHECK(std::isnan(records[i].a));
      CHECK(records[i].k_equal == 0);
      CHECK(records[i].error_equal == inf);
      CHECK(records[i].features.label == SN::Dimensionality::DEGENERATE);
    }
    CHECK_FALSE(records[40].is_failure());
  }
}

TEST_CASE("named parameters: explicit defaults equal the defaults, grids and sizes are honoured", "[parameters]")
{
  const Point_list points = folded_sheet(9, 4);
  const auto defaults = optimal(points);
  std::vector<SN::Optimal_sigmoid_neighborhood> explicit_defaults, narrow;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    points, std::back_inserter(explicit_defaults),
    SNP::k_min(6u, SNP::k_max(20u, SNP::a_grid(SN::defaults::angle_grid(), SNP::b_grid(SN::defaults::angle_grid(),
      SNP::angle_tolerance(1e-6, SNP::barycenter(SN::Barycenter::WEIGHTED)))))).point_map(Point_map()).normal_map(Normal_map()));
  for(std::size_t i = 0; i < points.size(); ++i)
    CHECK(same_record(defaults[i], explicit_defaults[i]));

  // a grid without pi: the equal-weights baseline is still computed, and only grid values come out
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    points, std::back_inserter(narrow),
    SNP::k_min(8u, SNP::k_max(10u, SNP::a_grid(std::vector<double>{0.5, 0.1}, SNP::b_grid(std::vector<double>{1.0, 0.5}))))
      .point_map(Point_map()).normal_map(Normal_map()));
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(narrow[i].is_failure())
      continue;
    CHECK((narrow[i].a == 0.1 || narrow[i].a == 0.5));
    CHECK((narrow[i].b == 0.5 || narrow[i].b == 1.0));
    CHECK(narrow[i].k >= 8);
    CHECK(narrow[i].k <= 10);
    CHECK(narrow[i].k_equal >= 8);
    CHECK(narrow[i].k_equal <= 10);
    CHECK(narrow[i].error_equal == Approx(plain_features(points, i, pi, pi, narrow[i].k_equal,
                                                          SN::Barycenter::WEIGHTED).error).epsilon(0));
  }
}

TEST_CASE("bad input throws std::invalid_argument with a message", "[bad-input]")
{
  Point_list points = folded_sheet(6, 5);
  std::vector<SN::Optimal_sigmoid_neighborhood> out;
  auto run = [&](const Point_list& p) {
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(p, std::back_inserter(out), maps());
  };
  Point_list nan_point = points;
  nan_point[3].first = Point_3(std::nan(""), 0, 0);
  CHECK_THROWS_WITH(run(nan_point), Catch::Contains("point 3") && Catch::Contains("non-finite"));
  Point_list zero_normal = points;
  zero_normal[4].second = CGAL::NULL_VECTOR;
  CHECK_THROWS_WITH(run(zero_normal), Catch::Contains("point 4") && Catch::Contains("zero normal"));
  Point_list inf_normal = points;
  inf_normal[5].second = Vector_3(inf, 0, 0);
  CHECK_THROWS_AS(run(inf_normal), std::invalid_argument);
  CHECK_THROWS_WITH(run(Point_list(points.begin(), points.begin() + 20)), Catch::Contains("at least"));
  CHECK_NOTHROW(run(Point_list(points.begin(), points.begin() + 21)));
  CHECK_THROWS_AS(run(Point_list()), std::invalid_argument);
  CHECK_THROWS_AS(SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
                    points, std::back_inserter(out), SNP::k_min(9u, SNP::k_max(8u)).point_map(Point_map()).normal_map(Normal_map())),
                  std::invalid_argument);
  CHECK_THROWS_AS(SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
                    points, std::back_inserter(out), SNP::a_grid(std::vector<double>{4.}).point_map(Point_map()).normal_map(Normal_map())),
                  std::invalid_argument);
  CHECK_THROWS_AS(SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
                    points, std::back_inserter(out),
                    SNP::a_grid(std::vector<double>{2.}, SNP::b_grid(std::vector<double>{1.})).point_map(Point_map()).normal_map(Normal_map())),
                  std::invalid_argument);
}

TEST_CASE("point range and Surface_mesh give the same numbers", "[mesh]")
{
  Mesh cube = make_grid_cube(4, 0.25);
  const Point_list points = mesh_point_list(cube);
  const auto from_range = optimal(points);
  auto records = cube.add_property_map<Mesh::Vertex_index, SN::Optimal_sigmoid_neighborhood>("v:optimal").first;
  const auto summary = SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(cube, records);
  CHECK(summary.vertices == 98);
  CHECK(summary.points == 98);
  CHECK(summary.merged_duplicates == 0);
  CHECK(summary.dropped_vertices() == 0);
  std::size_t i = 0, edges = 0, corners = 0;
  for(auto v : cube.vertices())
  {
    CHECK(same_record(records[v], from_range[i]));
    ++i;
  }
  // fixed triple on the mesh equals the range version
  auto features = cube.add_property_map<Mesh::Vertex_index, SN::Dimensionality_features>("v:features").first;
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(cube, SN::Cosine_sigmoid(0., pi / 3), 12, features);
  std::vector<SN::Dimensionality_features> range_features;
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, SN::Cosine_sigmoid(0., pi / 3), 12,
                                                     std::back_inserter(range_features), maps());
  i = 0;
  for(auto v : cube.vertices())
  {
    CHECK(same_bits(features[v].error, range_features[i].error));
    const Point_3& p = cube.point(v);
    const int on_border = (p.x() == 0 || p.x() == 1) + (p.y() == 0 || p.y() == 1) + (p.z() == 0 || p.z() == 1);
    const auto& r = records[v];
    if(on_border == 2)
    {
      // a sharp edge: the cut-off a = b = 0 keeps the edge vertices only, a line
      ++edges;
      CHECK(r.a == 0.);
      CHECK(r.b == 0.);
      CHECK(r.k == 6);
      CHECK(r.error() == Approx(0.).margin(1e-12));
      CHECK(r.features.label == SN::Dimensionality::LINEAR);
      CHECK(r.error_equal > 0.5);
    }
    if(on_border == 3)
    {
      // the cube's symmetry: all corners alike, and better than equal weights
      ++corners;
      CHECK(r.error() == Approx(records[*cube.vertices().begin()].error()).epsilon(1e-12));
      CHECK(r.error() < r.error_equal);
    }
    ++i;
  }
  CHECK(edges == 12 * 3);
  CHECK(corners == 8);
}

TEST_CASE("Surface_mesh: duplicate vertices are merged, isolated vertices left out", "[mesh]")
{
  Mesh cube = make_grid_cube(3, 1.);
  const std::size_t n = cube.number_of_vertices();
  // a separate triangle whose corners repeat three cube vertices, and one isolated vertex
  auto v0 = cube.add_vertex(Point_3(0, 0, 0));
  auto v1 = cube.add_vertex(Point_3(1, 0, 0));
  auto v2 = cube.add_vertex(Point_3(0, 1, 0));
  cube.add_face(v0, v1, v2);
  auto lonely = cube.add_vertex(Point_3(9, 9, 9));
  auto records = cube.add_property_map<Mesh::Vertex_index, SN::Optimal_sigmoid_neighborhood>("v:optimal").first;
  const auto summary = SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(cube, records);
  CHECK(summary.vertices == n + 4);
  CHECK(summary.points == n);
  CHECK(summary.merged_duplicates == 3);
  CHECK(summary.isolated_vertices == 1);
  CHECK(records[lonely].is_failure());
  for(auto v : cube.vertices())
    if(v != v0 && v != v1 && v != v2 && cube.point(v) == cube.point(v0))
      CHECK(same_record(records[v], records[v0]));
}

TEST_CASE("1 and 2 threads give bit-identical results", "[threads]")
{
  const Point_list points = folded_sheet(20, 6);
  const auto sequential = optimal(points);
#ifdef _OPENMP
  for(unsigned int threads : {1u, 2u, 3u})
  {
    std::vector<SN::Optimal_sigmoid_neighborhood> parallel;
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(
      points, std::back_inserter(parallel), SN::parameters::number_of_threads(threads, maps()));
    REQUIRE(parallel.size() == sequential.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      CHECK(same_record(parallel[i], sequential[i]));
  }
#else
  WARN("built without OpenMP: only the sequential path is tested");
#endif
}

// An input in an order without locality is searched in the tree's leaf order (its records held
// until all are done) and must give the records of the plain loop, on any number of threads.
TEST_CASE("a shuffled input: detected, searched in spatial order, the plain loop's records", "[neighbors]")
{
  // 10,000 points: a shuffled order then puts consecutive points ~50 spacings apart
  const Point_list ordered = folded_sheet(100, 7);
  Point_list shuffled = ordered;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
  auto positions = [](const Point_list& list) {
    std::vector<SN::internal::Double_point> result;
    for(const auto& p : list)
      result.emplace_back(p.first.x(), p.first.y(), p.first.z());
    return result;
  };
  const auto ordered_positions = positions(ordered), shuffled_positions = positions(shuffled);
  CHECK_FALSE(SN::internal::Neighbor_query(ordered_positions).has_scattered_order());
  CHECK(SN::internal::Neighbor_query(shuffled_positions).has_scattered_order());

  const auto records = optimal(shuffled);
  REQUIRE(records.size() == shuffled.size());
  for(std::size_t i = 0; i < shuffled.size(); i += 1000)
    CHECK(same_record(records[i], plain_optimal(shuffled, i, SN::Barycenter::WEIGHTED)));
#ifdef _OPENMP
  std::vector<SN::Optimal_sigmoid_neighborhood> parallel;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(shuffled, std::back_inserter(parallel),
                                                                SN::parameters::number_of_threads(2, maps()));
  REQUIRE(parallel.size() == records.size());
  for(std::size_t i = 0; i < records.size(); ++i)
    CHECK(same_record(parallel[i], records[i]));
#endif
}

// The k_max nearest other points of every point by brute force (SPEC §2: distance, then index),
// in compressed rows as a caller (pgeof, Open3D, a GPU k-NN) would hand them over.
static void brute_force_rows(const Point_list& points, unsigned int k, std::vector<std::uint32_t>& indices,
                             std::vector<std::size_t>& offsets)
{
  indices.clear();
  offsets.assign(1, 0);
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    std::vector<std::pair<double, std::uint32_t>> all;
    for(std::size_t j = 0; j < points.size(); ++j)
      if(j != i)
        all.emplace_back(CGAL::squared_distance(points[i].first, points[j].first), std::uint32_t(j));
    std::sort(all.begin(), all.end());
    for(unsigned int t = 0; t < k; ++t)
      indices.push_back(all[t].second);
    offsets.push_back(indices.size());
  }
}

TEST_CASE("caller-computed neighborhoods in compressed rows give the kd-tree's results", "[neighborhoods]")
{
  const Point_list points = folded_sheet(12, 4);
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  brute_force_rows(points, 24, indices, offsets); // longer rows than k_max: their first k_max count

  const auto tree = optimal(points);
  std::vector<SN::Optimal_sigmoid_neighborhood> given;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    points, std::back_inserter(given), SNP::neighbor_indices(indices, SNP::neighbor_offsets(offsets, maps())));
  REQUIRE(given.size() == tree.size());
  for(std::size_t i = 0; i < tree.size(); ++i)
    CHECK(same_record(given[i], tree[i]));

  std::vector<SN::Dimensionality_features> tree_features, given_features;
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, SN::Cosine_sigmoid(0., pi / 3), 9,
                                                     std::back_inserter(tree_features), maps());
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(
    points, SN::Cosine_sigmoid(0., pi / 3), 9, std::back_inserter(given_features),
    SNP::neighbor_indices(indices, SNP::neighbor_offsets(offsets, maps())));
  REQUIRE(given_features.size() == tree_features.size());
  for(std::size_t i = 0; i < tree_features.size(); ++i)
    CHECK(std::memcmp(&given_features[i].error, &tree_features[i].error, sizeof(double)) == 0);

  // Rows in another order are another neighborhood: the caller's order is N_i(k)'s.
  std::vector<std::uint32_t> reversed = indices;
  for(std::size_t i = 0; i + 1 < offsets.size(); ++i)
    std::reverse(reversed.begin() + std::ptrdiff_t(offsets[i]), reversed.begin() + std::ptrdiff_t(offsets[i + 1]));
  std::vector<SN::Dimensionality_features> far_features;
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(
    points, SN::Cosine_sigmoid(0., pi / 3), 9, std::back_inserter(far_features),
    SNP::neighbor_indices(reversed, SNP::neighbor_offsets(offsets, maps())));
  std::size_t differ = 0;
  for(std::size_t i = 0; i < tree_features.size(); ++i)
    differ += far_features[i].eigenvalues != tree_features[i].eigenvalues;
  CHECK(differ > tree_features.size() / 2);
}

TEST_CASE("caller-computed neighborhoods are checked", "[neighborhoods][bad-input]")
{
  const Point_list points = folded_sheet(6, 2);
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  brute_force_rows(points, 20, indices, offsets);
  auto run = [&](const std::vector<std::uint32_t>& ind, const std::vector<std::size_t>& off) {
    std::vector<SN::Optimal_sigmoid_neighborhood> out;
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
      points, std::back_inserter(out), SNP::neighbor_indices(ind, SNP::neighbor_offsets(off, maps())));
    return out.size();
  };
  CHECK(run(indices, offsets) == points.size());
  // rows shorter than k_max
  std::vector<std::uint32_t> short_indices;
  std::vector<std::size_t> short_offsets;
  brute_force_rows(points, 10, short_indices, short_offsets);
  CHECK_THROWS_WITH(run(short_indices, short_offsets), Catch::Contains("at least 20 neighbors per point, one has 10"));
  // an offset missing, a decreasing offset, an index out of range, the point itself
  std::vector<std::size_t> missing(offsets.begin(), offsets.end() - 1);
  CHECK_THROWS_WITH(run(indices, missing), Catch::Contains("one entry per point and one more"));
  std::vector<std::size_t> decreasing = offsets;
  std::swap(decreasing[3], decreasing[4]);
  CHECK_THROWS_WITH(run(indices, decreasing), Catch::Contains("must not decrease"));
  std::vector<std::uint32_t> out_of_range = indices;
  out_of_range[25] = std::uint32_t(points.size());
  CHECK_THROWS_WITH(run(out_of_range, offsets), Catch::Contains("neighborhood of point 1: index") &&
                                                    Catch::Contains("is out of range"));
  std::vector<std::uint32_t> itself = indices;
  itself[offsets[2]] = 2;
  CHECK_THROWS_WITH(run(itself, offsets), Catch::Contains("neighborhood of point 2 contains the point itself"));
}

TEST_CASE("caller-computed neighborhoods: checked on threads, the first fault named whatever their number",
          "[neighborhoods][bad-input][threads]")
{
  const std::size_t n = 5000; // above the size checked in parallel
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets{0};
  for(std::size_t i = 0; i < n; ++i)
  {
    indices.push_back(std::uint32_t((i + 1) % n));
    indices.push_back(std::uint32_t((i + 2) % n));
    offsets.push_back(indices.size());
  }
  auto message = [&](const std::vector<std::uint32_t>& ind, const std::vector<std::size_t>& off, unsigned int threads) {
    try
    {
      SN::internal::check_neighbor_rows(ind, off, n, threads);
      return std::string("sound");
    }
    catch(const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
  };
  std::vector<std::uint32_t> two_faults = indices;
  two_faults[2 * 4300] = 4300;             // the point itself, in row 4300
  two_faults[2 * 4200 + 1] = std::uint32_t(n); // out of range, in row 4200: the first named
  std::vector<std::size_t> past_end = offsets; // row 2000 runs past the indices, row 2001 goes back
  past_end[2001] = indices.size() + 10;
  for(unsigned int threads : {1u, 2u, 3u})
  {
    CHECK(message(indices, offsets, threads) == "sound");
    CHECK(message(two_faults, offsets, threads) == "neighborhood of point 4200: index 5000 is out of range (5000 points)");
    CHECK(message(indices, past_end, threads) == "the neighbor offsets must not decrease (at point 2001)");
  }
}

TEST_CASE("for_each_index_in_blocks: results in order, and an exception of the smallest index, on any thread count",
          "[threads]")
{
  const std::size_t n = 10000; // several blocks of 1,024 points per thread
  struct Compute_error : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };
  struct Sink_error : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };
  // compute(i) = 3 i + 1, throwing at `compute_fails`; the sink records the indices it is given and
  // throws at `sink_fails`
  auto run = [&](unsigned int threads, std::size_t compute_fails, std::size_t sink_fails, std::vector<std::size_t>& sunk) {
    sunk.clear();
    SN::internal::for_each_index_in_blocks<SN::Parallel_if_available_tag, std::size_t>(
      n, threads, [] { return std::vector<int>(8); },
      [&](std::size_t i, std::vector<int>& scratch) {
        scratch[i % 8] = int(i); // a scratch per thread, whatever it holds
        if(i == compute_fails)
          throw Compute_error("compute " + std::to_string(i));
        return 3 * i + 1;
      },
      [&](std::size_t i, std::size_t result) {
        if(i == sink_fails)
          throw Sink_error("sink " + std::to_string(i));
        CHECK(result == 3 * i + 1);
        sunk.push_back(i);
      });
  };
  const std::size_t none = std::size_t(-1);
  for(unsigned int threads : {1u, 2u, 3u})
  {
    std::vector<std::size_t> sunk;
    run(threads, none, none, sunk);
    std::vector<std::size_t> all(n);
    std::iota(all.begin(), all.end(), std::size_t(0));
    CHECK(sunk == all);
    // a result that fails: the blocks before its block are given, none after
    const std::size_t block = 1024 * threads, failing = 5000, given = failing / block * block;
    CHECK_THROWS_WITH(run(threads, failing, none, sunk), "compute 5000");
    CHECK(sunk == std::vector<std::size_t>(all.begin(), all.begin() + std::ptrdiff_t(given)));
    // a sink that fails: what came before it, then its exception
    CHECK_THROWS_AS(run(threads, none, 3000, sunk), Sink_error);
    CHECK(sunk == std::vector<std::size_t>(all.begin(), all.begin() + 3000));
    // both: the smaller index's
    CHECK_THROWS_WITH(run(threads, 4500, 3000, sunk), "sink 3000");
    CHECK_THROWS_WITH(run(threads, 2500, 3000, sunk), "compute 2500");
  }
}

TEST_CASE("Parallel_tag: an exception at one index reaches the caller as that exception", "[threads]")
{
  struct Custom_error : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };
  std::vector<unsigned char> visited(1000, 0);
  auto body = [&](std::size_t i, int&) {
    if(i == 377)
      throw Custom_error("index 377");
    visited[i] = 1;
  };
  for(unsigned int threads : {1u, 2u})
  {
    try
    {
      SN::internal::for_each_index<SN::Parallel_if_available_tag>(1000, threads, [] { return 0; }, body);
      FAIL("no exception");
    }
    catch(const Custom_error& e)
    {
      CHECK(std::string(e.what()) == "index 377");
    }
  }
  // a std::bad_alloc in a thread's scratch space, too
  CHECK_THROWS_AS(SN::internal::for_each_index<SN::Parallel_if_available_tag>(
                    100, 2, []() -> std::vector<double> { throw std::bad_alloc(); },
                    [](std::size_t, std::vector<double>&) {}),
                  std::bad_alloc);
  CHECK(SN::internal::thread_count<SN::Parallel_if_available_tag>(3) ==
        (std::is_same<SN::Parallel_if_available_tag, CGAL::Parallel_tag>::value ? 3u : 1u));
  CHECK(SN::internal::thread_count<CGAL::Sequential_tag>(3) == 1u);
}

TEST_CASE("meshes: any FaceListGraph, Polyhedron_3 as Surface_mesh", "[mesh]")
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor Polyhedron_vertex;
  Mesh cube = make_grid_cube(3, 1.);
  // a separate triangle whose corners repeat three cube vertices: merged
  cube.add_face(cube.add_vertex(Point_3(0, 0, 0)), cube.add_vertex(Point_3(1, 0, 0)), cube.add_vertex(Point_3(0, 1, 0)));
  Polyhedron polyhedron;
  std::map<Mesh::Vertex_index, Polyhedron_vertex> copy_of;
  CGAL::copy_face_graph(cube, polyhedron,
                        CGAL::parameters::vertex_to_vertex_output_iterator(std::inserter(copy_of, copy_of.end())));
  REQUIRE(num_vertices(polyhedron) == cube.number_of_vertices());
  // the Surface_mesh's indices, so that the same vertex of each duplicate group is kept
  std::map<Polyhedron_vertex, std::size_t> index_of;
  for(auto v : cube.vertices())
    index_of[copy_of[v]] = std::size_t(v);
  const auto indices = CGAL::parameters::vertex_index_map(boost::make_assoc_property_map(index_of));

  auto records = cube.add_property_map<Mesh::Vertex_index, SN::Optimal_sigmoid_neighborhood>("v:optimal").first;
  std::map<Polyhedron_vertex, SN::Optimal_sigmoid_neighborhood> polyhedron_records;
  const auto summary = SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(cube, records);
  const auto polyhedron_summary = SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    polyhedron, boost::make_assoc_property_map(polyhedron_records), indices);
  CHECK(summary.vertices == polyhedron_summary.vertices);
  CHECK(summary.points == polyhedron_summary.points);
  CHECK(summary.merged_duplicates == 3);
  CHECK(polyhedron_summary.merged_duplicates == 3);
  for(auto v : cube.vertices())
    CHECK(same_record(records[v], polyhedron_records[copy_of[v]]));

  auto features = cube.add_property_map<Mesh::Vertex_index, SN::Dimensionality_features>("v:features").first;
  std::map<Polyhedron_vertex, SN::Dimensionality_features> polyhedron_features;
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(cube, SN::Cosine_sigmoid(0., pi / 3), 10, features);
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(polyhedron, SN::Cosine_sigmoid(0., pi / 3), 10,
                                                     boost::make_assoc_property_map(polyhedron_features), indices);
  for(auto v : cube.vertices())
    CHECK(std::memcmp(&features[v].error, &polyhedron_features[copy_of[v]].error, sizeof(double)) == 0);

  // positions through vertex_point_map: the cube scaled by 2 has the same optimal triples, errors
  // within rounding
  std::map<Polyhedron_vertex, Point_3> scaled;
  for(auto v : vertices(polyhedron))
    scaled[v] = CGAL::ORIGIN + 2. * (v->point() - CGAL::ORIGIN);
  std::map<Polyhedron_vertex, SN::Optimal_sigmoid_neighborhood> scaled_records;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    polyhedron, boost::make_assoc_property_map(scaled_records),
    indices.vertex_point_map(boost::make_assoc_property_map(scaled)));
  for(auto v : cube.vertices())
  {
    const auto& r = scaled_records[copy_of[v]];
    CHECK(r.k == records[v].k);
    CHECK(r.error() == Approx(records[v].error()).margin(1e-12));
  }
}

// Whether two kd-trees over the same points give every `step`-th point the same k nearest, indices and
// squared distances.
static bool same_nearest(const SN::internal::Point_kd_tree& a, const SN::internal::Point_kd_tree& b, std::size_t n,
                         std::size_t k, std::uint32_t step)
{
  std::vector<SN::internal::Neighbor> from_a, from_b;
  bool same = true;
  for(std::uint32_t i = 0; i < n; i += step)
  {
    a.nearest(i, k, from_a);
    b.nearest(i, k, from_b);
    same = same && from_a.size() == (std::min)(k, n - 1) &&
           std::equal(from_a.begin(), from_a.end(), from_b.begin(), from_b.end(), [](const auto& x, const auto& y) {
             return x.index == y.index && x.squared_distance == y.squared_distance;
           });
  }
  return same;
}

// The kd-tree against brute force where its shortcuts could go wrong: a flat slab of random points
// (the airborne case), a grid (ties at every distance, some on the pruning bound), exact duplicates
// (distance 0), few neighbors (kept sorted) and many (selected in bulk, each query starting from its
// predecessor's bound), on one thread and two.
TEST_CASE("the kd-tree's k nearest and balls equal brute force", "[neighbors]")
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> along(0., 30.), height(0., 0.5);
  Point_list points;
  for(int i = 0; i < 1200; ++i)
    points.emplace_back(Point_3(along(rng), along(rng), height(rng)), Vector_3(0, 0, 1));
  for(int x = 0; x < 12; ++x)
    for(int y = 0; y < 12; ++y)
      points.emplace_back(Point_3(40. + x, y, 0.), Vector_3(0, 0, 1));
  for(int d = 0; d < 30; ++d)
    points.push_back(points[std::size_t(37 * d) % points.size()]);
  std::shuffle(points.begin(), points.end(), rng);

  std::vector<std::uint32_t> expected_indices, indices;
  std::vector<std::size_t> expected_offsets, offsets;
  brute_force_rows(points, 200, expected_indices, expected_offsets);
  // both sides of the tree's SORTED_INSERTION_K (128)
  for(unsigned int k : {1u, 7u, 32u, 33u, 100u, 128u, 129u, 200u})
    for(unsigned int threads : {1u, 2u})
    {
      CAPTURE(k, threads);
      SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(
        points, k, indices, offsets,
        SN::parameters::number_of_threads(threads, CGAL::parameters::point_map(Point_map())));
      REQUIRE(offsets.size() == points.size() + 1);
      bool all_equal = true;
      for(std::size_t i = 0; i < points.size(); ++i)
        all_equal = all_equal && std::equal(indices.begin() + offsets[i], indices.begin() + offsets[i + 1],
                                            expected_indices.begin() + expected_offsets[i]) &&
                    offsets[i + 1] - offsets[i] == k;
      CHECK(all_equal);
    }

  std::vector<SN::internal::Double_point> copy;
  for(const auto& p : points)
    copy.emplace_back(p.first.x(), p.first.y(), p.first.z());
  const SN::internal::Neighbor_query query(copy);
  std::vector<SN::internal::Neighbor> found;
  std::size_t on_boundary = 0; // neighbors at exactly the radius: the `<=` of the ball decided them
  for(double radius : {0., 1., 2., 2.5}) // the grid's distances 1 and 2 fall on the ball's boundary
    for(std::uint32_t i = 0; i < copy.size(); i += 7)
    {
      query.query_ball(i, radius, found);
      std::vector<std::pair<double, std::uint32_t>> expected;
      for(std::uint32_t j = 0; j < copy.size(); ++j)
      {
        const double d2 = CGAL::squared_distance(points[i].first, points[j].first);
        if(j != i && d2 <= radius * radius)
          expected.emplace_back(d2, j);
        if(j != i && radius > 0. && d2 == radius * radius)
          ++on_boundary;
      }
      std::sort(expected.begin(), expected.end());
      REQUIRE(found.size() == expected.size());
      for(std::size_t t = 0; t < found.size(); ++t)
        REQUIRE(found[t].index == expected[t].second);
    }
  CHECK(on_boundary > 0);

  // the tree built on several threads (the top levels split level by level, then subtrees) is the one
  // built on one: the same positions in its leaves, the same neighbors
  const SN::internal::Point_kd_tree on_one_thread(copy);
  const SN::internal::Neighbor_query package_query(copy, 1, SN::Neighbor_search::PACKAGE_KD_TREE);
  for(unsigned int threads : {2u, 3u, 0u})
  {
    const SN::internal::Point_kd_tree tree(copy, threads);
    CHECK(tree.leaf_order() == package_query.spatial_order());
    CHECK(same_nearest(on_one_thread, tree, copy.size(), 33, 5));
  }
}

TEST_CASE("the kd-tree on a single point, on a pair and on a hundred copies of one point", "[neighbors][bad-input]")
{
  std::vector<SN::internal::Double_point> one{{1., 2., 3.}};
  const SN::internal::Neighbor_query single(one);
  std::vector<SN::internal::Neighbor> found{{7, 1.}};
  single.query(0, 5, found);
  CHECK(found.empty());
  single.query_ball(0, 10., found);
  CHECK(found.empty());

  std::vector<SN::internal::Double_point> two{{0., 0., 0.}, {3., 4., 0.}};
  const SN::internal::Neighbor_query pair(two);
  pair.query(1, 3, found);
  REQUIRE(found.size() == 1);
  CHECK(found[0].index == 0);
  CHECK(found[0].squared_distance == 25.);
  pair.query_ball(0, 5., found); // on the boundary: kept
  CHECK(found.size() == 1);
  pair.query_ball(0, std::nextafter(5., 0.), found);
  CHECK(found.empty());

  // every distance 0: the neighbors are the other indices in order, whatever the tree's splits
  std::vector<SN::internal::Double_point> copies(100, SN::internal::Double_point(0.5, -2., 7.));
  const SN::internal::Neighbor_query same(copies);
  for(unsigned int k : {1u, 10u, 40u, 99u, 150u})
    for(std::uint32_t i : {0u, 37u, 99u})
    {
      same.query(i, k, found);
      REQUIRE(found.size() == std::min(k, 99u));
      std::uint32_t expected = 0;
      for(const auto& n : found)
      {
        if(expected == i)
          ++expected;
        CHECK(n.index == expected);
        CHECK(n.squared_distance == 0.);
        ++expected;
      }
    }
}

// Points at 1, 2, 4, ... along two axes: each cut at the middle of a cell splits off one of them, so
// that a tree of middle cuts alone would be hundreds of levels deep. Deep down, the tree keeps a
// quarter of the points on each side, and its walk (a stack of bounded depth) still finds every
// neighbor; the tree built on several threads is the same.
TEST_CASE("the kd-tree on points that middle cuts would split off one at a time", "[neighbors][bad-input]")
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0., 1.);
  Point_list points;
  for(int e = 0; e < 400; ++e)
  {
    points.emplace_back(Point_3(std::ldexp(1., e), 0., 0.), Vector_3(0, 0, 1));
    points.emplace_back(Point_3(0., std::ldexp(1., e), 0.5), Vector_3(0, 0, 1));
  }
  for(int i = 0; i < 400; ++i)
    points.emplace_back(Point_3(unit(rng), unit(rng), unit(rng)), Vector_3(0, 0, 1));
  std::shuffle(points.begin(), points.end(), rng);

  std::vector<std::uint32_t> expected_indices, indices;
  std::vector<std::size_t> expected_offsets, offsets;
  brute_force_rows(points, 40, expected_indices, expected_offsets);
  for(unsigned int k : {1u, 10u, 40u})
    for(unsigned int threads : {1u, 3u})
    {
      CAPTURE(k, threads);
      SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(
        points, k, indices, offsets,
        SN::parameters::number_of_threads(threads, CGAL::parameters::point_map(Point_map())));
      bool all_equal = true;
      for(std::size_t i = 0; i < points.size(); ++i)
        all_equal = all_equal && std::equal(indices.begin() + offsets[i], indices.begin() + offsets[i + 1],
                                            expected_indices.begin() + expected_offsets[i]);
      CHECK(all_equal);
    }

  std::vector<SN::internal::Double_point> copy;
  for(const auto& p : points)
    copy.emplace_back(p.first.x(), p.first.y(), p.first.z());
  const SN::internal::Point_kd_tree tree(copy);
  std::vector<SN::internal::Neighbor> found;
  for(std::uint32_t i = 0; i < copy.size(); i += 3)
  {
    const double radius = std::sqrt(copy[i].x() * copy[i].x() + copy[i].y() * copy[i].y()) + 1.;
    tree.ball(i, radius * radius, found);
    std::size_t expected = 0;
    for(std::uint32_t j = 0; j < copy.size(); ++j)
      expected += std::size_t(j != i && CGAL::squared_distance(points[i].first, points[j].first) <= radius * radius);
    REQUIRE(found.size() == expected);
  }
  // a ball holding every point: each node on the deepest paths leaves its other child to visit
  for(std::uint32_t i = 0; i < copy.size(); i += 50)
  {
    tree.ball(i, std::ldexp(1., 820), found);
    REQUIRE(found.size() == copy.size() - 1);
  }
  // built on threads: the same tree, the same neighbors
  for(unsigned int threads : {2u, 3u, 0u})
  {
    const SN::internal::Point_kd_tree on_threads(copy, threads);
    CHECK(on_threads.leaf_order() == tree.leaf_order());
    CHECK(same_nearest(tree, on_threads, copy.size(), 25, 11));
    bool whole = true;
    for(std::uint32_t i = 0; i < copy.size(); i += 11)
    {
      on_threads.ball(i, std::ldexp(1., 820), found);
      whole = whole && found.size() == copy.size() - 1;
    }
    CHECK(whole);
  }

  // One chain of 300 points: on 2 and 3 threads, the subtree below the top levels holds leaves of one
  // point, more nodes than the room its slice has (leaves of 8 points on average), and the tree is put
  // together from copies; the same tree and the nearest points of brute force.
  std::vector<SN::internal::Double_point> chain;
  for(int e = 0; e < 300; ++e)
    chain.emplace_back(std::ldexp(1., e), double(e % 3), 0.);
  const SN::internal::Point_kd_tree chain_tree(chain);
  for(unsigned int threads : {2u, 3u})
  {
    const SN::internal::Point_kd_tree on_threads(chain, threads);
    CHECK(on_threads.leaf_order() == chain_tree.leaf_order());
    CHECK(same_nearest(chain_tree, on_threads, chain.size(), 25, 1));
  }
  bool chain_nearest = true;
  for(std::uint32_t i = 0; i < chain.size(); ++i)
  {
    chain_tree.nearest(i, 5, found);
    std::vector<std::pair<double, std::uint32_t>> expected;
    for(std::uint32_t j = 0; j < chain.size(); ++j)
      if(j != i)
      {
        const double dx = chain[j].x() - chain[i].x(), dy = chain[j].y() - chain[i].y();
        expected.emplace_back(dx * dx + dy * dy, j);
      }
    std::sort(expected.begin(), expected.end());
    for(std::size_t t = 0; t < 5; ++t)
      chain_nearest = chain_nearest && found.size() == 5 && found[t].index == expected[t].second;
  }
  CHECK(chain_nearest);

  // coordinates at the ends of the doubles: the middle of a cell is taken without overflow (its
  // distances overflow to infinity, ties decided by index)
  const double big = (std::numeric_limits<double>::max)();
  std::vector<SN::internal::Double_point> extreme;
  for(int i = 0; i < 300; ++i)
    extreme.emplace_back(i % 3 == 0 ? big : i % 3 == 1 ? -big : unit(rng), i % 5 == 0 ? -big : unit(rng) * 1e300,
                         double(i % 7));
  const SN::internal::Point_kd_tree extreme_tree(extreme, 2);
  bool same = true;
  for(std::uint32_t i = 0; i < extreme.size(); ++i)
  {
    extreme_tree.nearest(i, 12, found);
    std::vector<std::pair<double, std::uint32_t>> expected;
    for(std::uint32_t j = 0; j < extreme.size(); ++j)
      if(j != i)
      {
        const double dx = extreme[j].x() - extreme[i].x(), dy = extreme[j].y() - extreme[i].y(),
                     dz = extreme[j].z() - extreme[i].z();
        expected.emplace_back(dx * dx + dy * dy + dz * dz, j);
      }
    std::sort(expected.begin(), expected.end());
    same = same && found.size() == 12;
    for(std::size_t t = 0; same && t < 12; ++t)
      same = found[t].index == expected[t].second;
  }
  CHECK(same);
  CHECK(extreme_tree.leaf_order() == SN::internal::Point_kd_tree(extreme).leaf_order());
}

TEST_CASE("compute_k_nearest_neighbors: SPEC §2's rows, shared by several calls", "[neighborhoods]")
{
  // a grid: many ties at equal distances, decided by index
  Point_list grid;
  for(int x = 0; x < 6; ++x)
    for(int y = 0; y < 6; ++y)
      grid.emplace_back(Point_3(x, y, 0.1 * ((x * y) % 3)), Vector_3(0, 0, 1));
  std::vector<std::uint32_t> expected_indices, indices;
  std::vector<std::size_t> expected_offsets, offsets;
  brute_force_rows(grid, 20, expected_indices, expected_offsets);
  SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(grid, 20, indices, offsets,
                                                                  CGAL::parameters::point_map(Point_map()));
  CHECK(indices == expected_indices);
  CHECK(offsets == expected_offsets);
  // more neighbors than there are other points: every other point
  SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(grid, 100, indices, offsets,
                                                        CGAL::parameters::point_map(Point_map()));
  CHECK(offsets.back() == grid.size() * (grid.size() - 1));
  CHECK_THROWS_AS(SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(grid, 0, indices, offsets,
                                                                        CGAL::parameters::point_map(Point_map())),
                  std::invalid_argument);

  // one computation, three algorithms: the results without the rows, bit for bit
  const Point_list points = folded_sheet(14, 9);
  SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(points, 20, indices, offsets,
                                                                  CGAL::parameters::point_map(Point_map()));
  const auto rows = SNP::neighbor_indices(std::cref(indices), SNP::neighbor_offsets(std::cref(offsets), maps()));
  std::vector<SN::Optimal_sigmoid_neighborhood> with_rows;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(with_rows), rows);
  const auto without_rows = optimal(points);
  REQUIRE(with_rows.size() == without_rows.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    CHECK(same_record(with_rows[i], without_rows[i]));
  std::vector<SN::Point_evaluation> evaluated_with, evaluated_without;
  SN::evaluate_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(evaluated_with), rows);
  SN::evaluate_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(evaluated_without), maps());
  REQUIRE(evaluated_with.size() == evaluated_without.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    CHECK(same_record(evaluated_with[i].optimal, evaluated_without[i].optimal));
    CHECK(std::memcmp(&evaluated_with[i].error_cut_off, &evaluated_without[i].error_cut_off, sizeof(double)) == 0);
    CHECK(evaluated_with[i].k_cut_off == evaluated_without[i].k_cut_off);
    CHECK(std::memcmp(&evaluated_with[i].error_fixed_k, &evaluated_without[i].error_fixed_k, sizeof(double)) == 0);
  }
}
