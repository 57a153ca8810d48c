// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The features a classifier takes (Point_features, Height_features) on analytic neighborhoods,
// their equality with the search's records, their entry into CGAL's Classification package, and the
// tool's build of CGAL's own generator (its scales side by side) against the generator.

#include "test_models.h"
#include "classification/cgal_features.h"
#include "classification/classifier_model.h"
#include "classification/classify_common.h"

#include <CGAL/Sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/Ethz_forest.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/add_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/compute_anchored_cgal_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Classification/ETHZ/Random_forest_classifier.h>
#include <CGAL/Classification/Label_set.h>
#include <CGAL/Classification/classify.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;

namespace {

// The bytes of a forest of CGAL 5.5's ETHZ format (Ethz_forest::problem()) with the split feature and
// threshold of its leaves zeroed: CGAL leaves them uninitialised, so that they may differ between two
// trainings of the same trees.
std::string with_leaves_masked(std::string bytes, std::size_t labels)
{
  std::uint32_t trees = 0;
  std::memcpy(&trees, bytes.data() + 32, 4);
  std::size_t at = 36;
  const std::size_t node_bytes = 17 + 4 * labels;
  for(std::uint32_t t = 0; t < trees; ++t)
    for(std::size_t pending = 1; pending > 0; --pending, at += node_bytes)
      if(bytes.at(at) != 0)
        std::fill_n(bytes.begin() + std::ptrdiff_t(at + 9), 8, '\0');
      else
        pending += 2;
  REQUIRE(at == bytes.size());
  return bytes;
}

// An n x n grid of spacing 1 in the plane spanned by u and v, normals `normal`.
Point_list grid(int n, const Vector_3& u, const Vector_3& v, const Vector_3& normal)
{
  Point_list result;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      result.emplace_back(CGAL::ORIGIN + i * u + j * v, normal);
  return result;
}

// A roof-like fold over noisy ground with a noisy tree-like blob: every feature varies.
Point_list scene(unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0., 0.02);
  std::uniform_real_distribution<double> unit(-1., 1.);
  Point_list result;
  for(int i = 0; i < 20; ++i)
    for(int j = 0; j < 20; ++j)
    {
      const double x = 0.25 * i, y = 0.25 * j;
      const double roof = x < 2.5 ? 0.5 * x : 2.5 - 0.5 * (x - 2.5);
      result.emplace_back(Point_3(x, y, roof + noise(rng)),
                          Vector_3(x < 2.5 ? -0.45 : 0.45, 0., 0.9) + Vector_3(noise(rng), noise(rng), noise(rng)));
    }
  for(int i = 0; i < 200; ++i)
  {
    const Vector_3 n(unit(rng), unit(rng), unit(rng) + 1.5);
    result.emplace_back(Point_3(7. + unit(rng), 2. + unit(rng), 3. + unit(rng)), n);
  }
  return result;
}

std::vector<SN::Point_features> features_at(const Point_list& points, const SN::Cosine_sigmoid& sigmoid, unsigned k)
{
  std::vector<std::vector<SN::Point_features>> multi;
  SN::compute_point_features<CGAL::Sequential_tag>(points, sigmoid, {k}, std::back_inserter(multi), maps());
  std::vector<SN::Point_features> result;
  for(const auto& m : multi)
    result.push_back(m.at(0));
  return result;
}

} // namespace

TEST_CASE("point features of a horizontal plane, a wall and a line", "[features][classification]")
{
  const SN::Cosine_sigmoid equal(CGAL_PI, CGAL_PI);
  // the centre of a 9 x 9 grid with its 8 nearest neighbors: a 3 x 3 square, lambda1 = lambda2
  const Point_list plane = grid(9, Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1));
  const SN::Point_features p = features_at(plane, equal, 8)[40];
  CHECK(p.k == 8);
  CHECK(p.a == CGAL_PI);
  CHECK(p.radius == Approx(std::sqrt(2.)).epsilon(1e-15));
  CHECK(p.dimensionality.linearity == Approx(0.).margin(1e-12));
  CHECK(p.dimensionality.planarity == Approx(1.).epsilon(1e-12));
  CHECK(p.dimensionality.eigenentropy == Approx(std::log(2.)).epsilon(1e-12));
  CHECK(p.anisotropy == Approx(1.).epsilon(1e-12));
  CHECK(p.omnivariance == Approx(0.).margin(1e-5));
  CHECK(p.change_of_curvature == Approx(0.).margin(1e-12));
  CHECK(p.verticality == Approx(0.).margin(1e-12));
  CHECK(p.normal_z == 1.);
  // 9 points at squared distances 0, 1 (4 times), 2 (4 times) from the barycenter: mean 12 / 9
  CHECK(p.sum_of_eigenvalues == Approx(12. / 9.).epsilon(1e-12));

  const Point_list wall = grid(9, Vector_3(1, 0, 0), Vector_3(0, 0, 1), Vector_3(0, 1, 0));
  const SN::Point_features w = features_at(wall, equal, 8)[40];
  CHECK(w.verticality == Approx(1.).epsilon(1e-12));
  CHECK(w.normal_z == 0.);

  // a plane tilted by 30 degrees: verticality 1 - cos 30
  const double c = std::cos(CGAL_PI / 6), s = std::sin(CGAL_PI / 6);
  const Point_list tilted = grid(9, Vector_3(c, 0, s), Vector_3(0, 1, 0), Vector_3(-s, 0, c));
  const SN::Point_features t = features_at(tilted, equal, 8)[40];
  CHECK(t.verticality == Approx(1. - c).epsilon(1e-12));
  CHECK(t.normal_z == Approx(c).epsilon(1e-15));

  Point_list line;
  for(int i = 0; i < 30; ++i)
    line.emplace_back(Point_3(i, 0., 0.), Vector_3(0, 0, 1));
  const SN::Point_features l = features_at(line, equal, 6)[15];
  CHECK(l.dimensionality.linearity == Approx(1.).epsilon(1e-12));
  CHECK(l.dimensionality.eigenentropy == Approx(0.).margin(1e-12));
  CHECK(l.dimensionality.error == Approx(0.).margin(1e-12));
  CHECK(l.change_of_curvature == Approx(0.).margin(1e-12));
  CHECK(l.value(SN::Point_feature::LINEARITY) == l.dimensionality.linearity);
  CHECK(l.value(SN::Point_feature::NEIGHBORHOOD_SIZE) == 6.);
  CHECK(l.value(SN::Point_feature::RADIUS) == l.radius);
}

TEST_CASE("point features: invariants, several scales on one query, equal to the fixed-triple features",
          "[features][classification]")
{
  const Point_list points = scene(3);
  const SN::Cosine_sigmoid sigmoid(CGAL_PI / 6, CGAL_PI / 3);
  const std::vector<unsigned int> sizes{30, 8, 16};
  std::vector<std::vector<SN::Point_features>> multi;
  SN::compute_point_features<CGAL::Sequential_tag>(points, sigmoid, sizes, std::back_inserter(multi), maps());
  REQUIRE(multi.size() == points.size());
  for(std::size_t s = 0; s < sizes.size(); ++s)
  {
    std::vector<SN::Dimensionality_features> plain;
    SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, sigmoid, sizes[s], std::back_inserter(plain), maps());
    const auto single = features_at(points, sigmoid, sizes[s]);
    std::size_t degenerate = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const SN::Point_features& f = multi[i][s];
      REQUIRE(f.k == sizes[s]);
      CHECK(same_bits(f.dimensionality.error, plain[i].error));
      CHECK(same_bits(f.dimensionality.linearity, plain[i].linearity));
      CHECK(same_bits(f.verticality, single[i].verticality));
      CHECK(same_bits(f.radius, single[i].radius));
      if(f.dimensionality.is_degenerate())
      {
        ++degenerate;
        continue;
      }
      const auto& d = f.dimensionality;
      CHECK(d.linearity + d.planarity + d.scattering == Approx(1.).epsilon(1e-12));
      CHECK(d.eigenentropy >= 0.);
      CHECK(d.eigenentropy <= std::log(3.) + 1e-12);
      CHECK(f.omnivariance >= 0.);
      CHECK(f.omnivariance <= 1. / 3. + 1e-12); // at most for three equal shares
      CHECK(f.anisotropy == Approx(d.linearity + d.planarity).epsilon(1e-12));
      CHECK(f.change_of_curvature <= 1. / 3. + 1e-12);
      CHECK(f.verticality >= 0.);
      CHECK(f.verticality <= 1.);
      CHECK(f.sum_of_eigenvalues > 0.);
      CHECK(f.radius > 0.);
    }
    CHECK(degenerate < points.size() / 10); // the blob's scattered normals leave a few points alone
  }
  // a larger neighborhood never has a smaller radius
  for(const auto& m : multi)
    CHECK((m[1].radius <= m[2].radius && m[2].radius <= m[0].radius));
  CHECK_THROWS_WITH(SN::compute_point_features<CGAL::Sequential_tag>(points, sigmoid, {}, std::back_inserter(multi),
                                                                     maps()),
                    "no neighborhood size given");
  CHECK_THROWS_WITH(SN::compute_point_features<CGAL::Sequential_tag>(points, sigmoid, std::vector<unsigned int>{unsigned(points.size())},
                                                                     std::back_inserter(multi), maps()),
                    Catch::Contains("needs at least k_max + 1"));
}

TEST_CASE("optimal point features are those of the search's optimum, for both criteria and equal weights",
          "[features][classification][criterion]")
{
  const Point_list points = scene(5);
  const std::vector<double> pi{CGAL_PI};
  for(auto criterion : {SN::Neighborhood_criterion::DIMENSIONALITY, SN::Neighborhood_criterion::EIGENENTROPY})
    for(bool equal_only : {false, true})
    {
      std::vector<SN::Optimal_sigmoid_neighborhood> records;
      std::vector<SN::Point_features> features;
      const auto grid = equal_only ? pi : SN::defaults::angle_grid();
      const auto np = SNP::criterion(criterion, SNP::a_grid(grid, SNP::b_grid(grid))).point_map(Point_map())
                        .normal_map(Normal_map());
      SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(records), np);
      SN::compute_optimal_point_features<CGAL::Sequential_tag>(points, std::back_inserter(features), np);
      REQUIRE(features.size() == points.size());
      for(std::size_t i = 0; i < points.size(); ++i)
      {
        const auto& r = records[i];
        const auto& f = features[i];
        REQUIRE(f.k == r.k);
        CHECK(same_bits(f.a, r.a));
        CHECK(same_bits(f.b, r.b));
        CHECK(same_bits(f.dimensionality.error, r.features.error));
        CHECK(same_bits(f.dimensionality.eigenentropy, r.features.eigenentropy));
        CHECK(same_bits(f.dimensionality.planarity, r.features.planarity));
        CHECK(same_bits(SN::criterion_value(f.dimensionality, criterion), r.error()));
      }
    }
}

TEST_CASE("height features in cells anchored at the origin", "[features][classification][height]")
{
  // two cells of side 2: [0, 2) and [2, 4) in x
  const std::vector<Point_3> points{Point_3(0.5, 0.5, 10.), Point_3(1.5, 1.9, 13.), Point_3(1.9, 0.1, 11.),
                                    Point_3(2.1, 0.5, 20.), Point_3(3.9, 1.5, 21.5), Point_3(-0.1, 0.5, 7.)};
  std::vector<SN::Height_features> h;
  SN::compute_height_features(points, 2., std::back_inserter(h));
  REQUIRE(h.size() == points.size());
  CHECK(h[0].height_above_lowest == 0.);
  CHECK(h[0].height_below_highest == 3.);
  CHECK(h[1].vertical_range == 3.);
  CHECK(h[2].height_above_lowest == 1.);
  CHECK(h[3].height_below_highest == 1.5);
  CHECK(h[4].height_above_lowest == 1.5);
  CHECK(h[5].vertical_range == 0.); // alone in [-2, 0)
  CHECK_THROWS_WITH(SN::compute_height_features(points, 0., std::back_inserter(h)),
                    Catch::Contains("cell size must be positive"));
  const std::vector<Point_3> far{Point_3(1e140, 0., 0.)};
  CHECK_THROWS_WITH(SN::compute_height_features(far, 1e-10, std::back_inserter(h)), Catch::Contains("64-bit range"));
}

TEST_CASE("point features enter a CGAL Feature_set and train CGAL's random forest", "[classification]")
{
  const Point_list points = scene(7);
  std::vector<SN::Point_features> features;
  SN::compute_optimal_point_features<CGAL::Sequential_tag>(points, std::back_inserter(features), maps());
  std::vector<Point_3> positions;
  for(const auto& p : points)
    positions.push_back(p.first);
  std::vector<SN::Height_features> heights;
  SN::compute_height_features(positions, 1., std::back_inserter(heights));

  CGAL::Classification::Feature_set feature_set;
  SN::Classification::add_point_features(feature_set, features, SN::Classification::default_point_features(),
                                         "_optimal");
  SN::Classification::add_point_features(feature_set, features, {SN::Point_feature::DIMENSIONALITY_ERROR});
  SN::Classification::add_height_features(feature_set, heights);
  REQUIRE(feature_set.size() == 10 + 1 + 3);
  CHECK(feature_set[0]->name() == "linearity_optimal");
  CHECK(feature_set[9]->name() == "normal_z_optimal");
  CHECK(feature_set[10]->name() == "error");
  CHECK(feature_set[13]->name() == "vertical_range");
  CHECK(feature_set[3]->value(17) == float(features[17].omnivariance));
  CHECK(feature_set[11]->value(2) == float(heights[2].height_above_lowest));

  // a non-finite value (a degenerate neighborhood's entropy) is stored below every range
  SN::Classification::Feature_values infinite({1., std::numeric_limits<double>::infinity(), 0.5}, "x");
  CHECK(infinite.value(1) == SN::Classification::Feature_values::NON_FINITE_VALUE);
  CHECK(infinite.value(2) == 0.5f);

  // the roof (first 400 points) against the blob: separable by these features alone
  CGAL::Classification::Label_set labels;
  labels.add("roof");
  labels.add("tree");
  std::vector<int> truth(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    truth[i] = i < 400 ? 0 : 1;
  CGAL::Classification::ETHZ::Random_forest_classifier classifier(labels, feature_set);
  classifier.train(truth, true, 10, 10);
  std::vector<int> predicted(points.size(), -1);
  CGAL::Classification::classify<CGAL::Sequential_tag>(points, labels, classifier, predicted);
  std::size_t correct = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    correct += predicted[i] == truth[i];
  CHECK(correct >= points.size() * 98 / 100);

  // The tool's prediction (the forest's trees on the package's loop) equals CGAL's classify() with
  // the confidences, on any thread count, a non-finite value included
  namespace SNT = sigmoid_tool::classification;
  SNT::Featured_file file;
  file.path = "scene";
  file.model.points = positions;
  sigmoid_tool::Classifier_settings settings;
  settings.labels.names = {"roof", "tree"};
  for(std::size_t f = 0; f < feature_set.size(); ++f)
  {
    sigmoid_tool::Feature_column column{feature_set[f]->name(), {}};
    for(std::size_t i = 0; i < points.size(); ++i)
      column.values.push_back(feature_set[f]->value(i));
    settings.feature_names.push_back(column.name);
    file.columns.push_back(column);
  }
  file.columns[3].values[17] = std::numeric_limits<double>::quiet_NaN();
  CGAL::Classification::Feature_set with_nan;
  sigmoid_tool::fill_feature_set(file.columns, settings.feature_names, with_nan);
  CGAL::Classification::ETHZ::Random_forest_classifier cgal_forest(labels, with_nan);
  std::stringstream bytes;
  classifier.save_configuration(bytes);
  cgal_forest.load_configuration(bytes);
  std::vector<int> cgal_classes(points.size(), -1);
  std::vector<std::vector<float>> cgal_confidence(2, std::vector<float>(points.size()));
  CGAL::Classification::classify<CGAL::Sequential_tag>(points, labels, cgal_forest, cgal_classes, cgal_confidence);
  for(const unsigned int threads : {1u, 2u, 3u})
  {
    settings.features.threads = threads;
    const SNT::Prediction p = SNT::predict(file, settings, bytes.str(), nullptr, 0.);
    CHECK(p.classes == cgal_classes);
    CHECK(p.confidence == cgal_confidence);
    // from a forest in memory, as classify experiment hands it
    const SN::Classification::Ethz_forest in_memory(bytes.str(), 2, settings.feature_names.size());
    const SNT::Prediction q = SNT::predict(file, settings, std::string(), &in_memory, 0.);
    CHECK(q.classes == cgal_classes);
  }
  // the public forest alone, on values handed by a functor
  const SN::Classification::Ethz_forest public_forest(bytes.str(), 2, settings.feature_names.size());
  CHECK(public_forest.number_of_labels() == 2);
  CHECK(public_forest.number_of_features() == 14);
  for(const unsigned int threads : {1u, 3u})
  {
    std::vector<int> classes;
    std::vector<std::vector<float>> confidence;
    public_forest.classify<CGAL::Parallel_if_available_tag>(
      points.size(), [&](std::size_t i, std::size_t f) { return file.columns[f].values[i]; }, classes, confidence,
      SN::parameters::number_of_threads(threads));
    CHECK(classes == cgal_classes);
    CHECK(confidence == cgal_confidence);
  }
  std::stringstream rewritten;
  public_forest.save_configuration(rewritten);
  CHECK(rewritten.str() == bytes.str());
  // a damaged or forged forest: a message, no crash (CGAL's reader would allocate without bound, or
  // the forest read past the sample)
  auto refusal = [&](const std::string& forest) {
    try
    {
      SN::Classification::Ethz_forest damaged(forest, settings.labels.names.size(), 14);
    }
    catch(const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string forest = bytes.str();
  CHECK(refusal(forest.substr(0, 40)) == "it ends in tree 1 of 10");
  CHECK(refusal(forest.substr(0, 20)) == "it ends in its parameters");
  CHECK(refusal(forest + "x") == "1 bytes follow its last tree");
  std::string forged = forest;
  REQUIRE(forged[36] == 0); // the first tree's root splits
  const std::int32_t far = 9999;
  std::memcpy(&forged[36 + 9], &far, 4);
  CHECK(refusal(forged) == "tree 1 splits on feature 9999 of 14");
  CHECK(refusal(forest) == "accepted");
  // the tool says which file
  try
  {
    SNT::predict(file, settings, forest.substr(0, 40), nullptr, 0.);
    FAIL("a truncated forest was read");
  }
  catch(const sigmoid_tool::Usage_error& e)
  {
    CHECK(std::string(e.what()) == "scene: not a usable classifier model: its forest cannot be read "
                                   "(it ends in tree 1 of 10)");
  }
  settings.labels.names.push_back("car");
  CHECK(refusal(forest) == "it votes for 2 classes, the model names 3");
}

TEST_CASE("Ethz_forest::train: CGAL's Random_forest_classifier::train() bit for bit, on any thread count",
          "[classification]")
{
  // three classes along two of six features, with noise, a non-finite value and skipped items
  const std::size_t n = 600, width = 6;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::vector<std::vector<double>> columns(width, std::vector<double>(n));
  std::vector<int> truth(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    for(std::size_t f = 0; f < width; ++f)
      columns[f][i] = uniform(rng);
    truth[i] = columns[1][i] + 0.2 * uniform(rng) < 0.4 ? 0 : columns[4][i] < 0.5 ? 1 : 2;
    if(i % 17 == 3)
      truth[i] = -1; // not a training item
  }
  columns[2][10] = std::numeric_limits<double>::quiet_NaN();
  columns[5][11] = std::numeric_limits<double>::infinity();

  CGAL::Classification::Label_set labels;
  for(const char* name : {"a", "b", "c"})
    labels.add(name);
  CGAL::Classification::Feature_set features;
  for(std::size_t f = 0; f < width; ++f)
    features.add<SN::Classification::Feature_values>(columns[f], "f" + std::to_string(f));
  CGAL::Classification::ETHZ::Random_forest_classifier classifier(labels, features);
  classifier.train<CGAL::Sequential_tag>(truth, true, 7, 9);
  std::stringstream cgal_bytes;
  classifier.save_configuration(cgal_bytes);

  std::vector<float> rows{0.f}; // the float read before the first row
  std::vector<int> row_labels;
  for(std::size_t i = 0; i < n; ++i)
    if(truth[i] >= 0)
    {
      for(std::size_t f = 0; f < width; ++f)
        rows.push_back(SN::Classification::Feature_values::stored_value(columns[f][i]));
      row_labels.push_back(truth[i]);
    }
  REQUIRE(std::count(rows.begin(), rows.end(), SN::Classification::Feature_values::NON_FINITE_VALUE) == 2);
  std::string first;
  for(const unsigned int threads : {1u, 2u, 3u})
  {
    const SN::Classification::Ethz_forest forest = SN::Classification::Ethz_forest::train<SN::Parallel_if_available_tag>(
      rows, row_labels, 3, 7, 9, SN::parameters::number_of_threads(threads));
    CHECK(forest.number_of_labels() == 3);
    CHECK(forest.number_of_features() == width);
    std::stringstream bytes;
    forest.save_configuration(bytes);
    CHECK(with_leaves_masked(bytes.str(), 3) == with_leaves_masked(cgal_bytes.str(), 3));
    if(first.empty())
      first = bytes.str();
    CHECK(bytes.str() == first); // every byte: no split left uninitialised
  }
  const SN::Classification::Ethz_forest sequential =
    SN::Classification::Ethz_forest::train<CGAL::Sequential_tag>(rows, row_labels, 3, 7, 9);
  std::stringstream bytes;
  sequential.save_configuration(bytes);
  CHECK(with_leaves_masked(bytes.str(), 3) == with_leaves_masked(cgal_bytes.str(), 3));
  // and the same votes as CGAL's forest on every item, the skipped ones too
  const SN::Classification::Ethz_forest cgal_forest(cgal_bytes.str(), 3, width);
  auto value = [&](std::size_t i, std::size_t f) { return columns[f][i]; };
  std::vector<int> ours_labels, cgal_labels;
  std::vector<std::vector<float>> ours_votes, cgal_votes;
  sequential.classify<CGAL::Sequential_tag>(n, value, ours_labels, ours_votes);
  cgal_forest.classify<CGAL::Sequential_tag>(n, value, cgal_labels, cgal_votes);
  CHECK(ours_labels == cgal_labels);
  CHECK(ours_votes == cgal_votes);
  // a forest that learned something: the training items mostly right
  std::vector<int> predicted;
  std::vector<std::vector<float>> confidence;
  sequential.classify<CGAL::Sequential_tag>(
    row_labels.size(), [&](std::size_t i, std::size_t f) { return rows[1 + i * width + f]; }, predicted, confidence);
  std::size_t right = 0;
  for(std::size_t i = 0; i < row_labels.size(); ++i)
    right += predicted[i] == row_labels[i];
  CHECK(right > row_labels.size() * 9 / 10);

  rows.pop_back();
  CHECK_THROWS_AS(SN::Classification::Ethz_forest::train<CGAL::Sequential_tag>(rows, row_labels, 3, 7, 9),
                  std::invalid_argument);
  rows.erase(rows.begin()); // the rows without the float before them
  rows.push_back(0.f);
  CHECK_THROWS_AS(SN::Classification::Ethz_forest::train<CGAL::Sequential_tag>(rows, row_labels, 3, 7, 9),
                  std::invalid_argument);
  CHECK_THROWS_AS(SN::Classification::Ethz_forest::train<CGAL::Sequential_tag>(std::vector<float>(), {}, 3, 7, 9), std::invalid_argument);
}

TEST_CASE("Ethz_forest::train: a node no split separates reads the float before the rows and a threshold of 0",
          "[classification]")
{
  // Items equal in every feature and of two classes: every split proposal fails, and CGAL 5.5 keeps
  // the default split (feature -1), sending each item by the float before its row (for item 0, the
  // float before the rows) at a threshold CGAL leaves uninitialised. Here the threshold is 0 and the
  // float the caller's: the trees are the same bytes every time, and a read before the rows would
  // stop the sanitized build. 40 items: CGAL draws every tree's items with one fixed seed, and for 40
  // they include item 0.
  const std::size_t n = 40, width = 3;
  std::vector<int> labels(n);
  for(std::size_t i = 0; i < n; ++i)
    labels[i] = int(i % 2);
  auto trained = [&](float before_rows, unsigned int threads) {
    std::vector<float> rows(1 + n * width, 0.5f);
    rows[0] = before_rows;
    const SN::Classification::Ethz_forest forest = SN::Classification::Ethz_forest::train<SN::Parallel_if_available_tag>(
      rows, labels, 2, 5, 6, SN::parameters::number_of_threads(threads));
    std::stringstream bytes;
    forest.save_configuration(bytes);
    return bytes.str();
  };
  const std::string first = trained(0.f, 1);
  for(const unsigned int threads : {2u, 3u, 1u})
    CHECK(trained(0.f, threads) == first);
  CHECK(trained(1.f, 1) != first); // the float is read: above the threshold, item 0 goes right
  // the first tree's root: a split (leaf flag 0) on feature -1 at threshold 0
  const std::size_t root = 36;
  REQUIRE(first.size() > root + 17);
  std::int32_t feature = 0;
  float threshold = 1.f;
  std::memcpy(&feature, first.data() + root + 9, 4);
  std::memcpy(&threshold, first.data() + root + 13, 4);
  CHECK(first[root] == 0);
  CHECK(feature == -1);
  CHECK(threshold == 0.f);
  // the model reads back, and classify() puts 0 before each item, as before item 0 here: every item
  // goes left at each such split, to the leaf of item 0 alone (class 0)
  const SN::Classification::Ethz_forest forest(first, 2, width);
  std::vector<int> predicted;
  std::vector<std::vector<float>> confidence;
  forest.classify<CGAL::Sequential_tag>(
    2, [&](std::size_t, std::size_t) { return 0.5; }, predicted, confidence);
  CHECK(predicted == std::vector<int>{0, 0});
  CHECK(confidence[0] == std::vector<float>{1.f, 1.f});
  CHECK(confidence[1] == std::vector<float>{0.f, 0.f});
}

TEST_CASE("the groups cgal, cgal-metric and cgal-grid: CGAL's generator bit for bit, on any thread count",
          "[classification][cgal]")
{
  // on one thread append_cgal_features() runs CGAL's Point_set_feature_generator itself: the reference
  auto same_value = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  SN::Oriented_point_set model;
  for(const auto& p : scene(11))
    model.points.emplace_back(p.first.x(), p.first.y(), p.first.z());

  for(const double voxel : {0., 0.4})
  {
    std::vector<sigmoid_tool::Feature_column> expected;
    sigmoid_tool::append_cgal_features(model, 3, voxel, 1, expected);
    REQUIRE(expected.size() == 3 * 10); // per scale: 3 eigenvalues, distance to plane, dispersion, 4 heights, verticality
    CHECK(expected.front().name == "eigenvalue0_0");
    CHECK(expected.back().name == "verticality_2");
    for(const unsigned int threads : {2u, 3u, 0u})
    {
      std::vector<sigmoid_tool::Feature_column> columns;
      sigmoid_tool::append_cgal_features(model, 3, voxel, threads, columns);
      REQUIRE(columns.size() == expected.size());
      std::size_t equal = 0;
      for(std::size_t f = 0; f < columns.size(); ++f)
      {
        CHECK(columns[f].name == expected[f].name);
        for(std::size_t i = 0; i < model.points.size(); ++i)
          equal += same_value(columns[f].values[i], expected[f].values[i]);
      }
      CHECK(equal == columns.size() * model.points.size());
    }
    if(voxel == 0.)
      continue;
    // the grids' features alone: the generator's columns of those names, equal
    std::vector<sigmoid_tool::Feature_column> grid;
    sigmoid_tool::append_cgal_features(model, 3, voxel, 2, grid, true);
    REQUIRE(grid.size() == 3 * 5);
    CHECK(grid.front().name == "vertical_dispersion_0");
    CHECK(grid.back().name == "vertical_range_2");
    for(const auto& c : grid)
    {
      std::size_t f = 0;
      while(f < expected.size() && expected[f].name != c.name)
        ++f;
      REQUIRE(f < expected.size());
      std::size_t equal = 0;
      for(std::size_t i = 0; i < model.points.size(); ++i)
        equal += same_value(c.values[i], expected[f].values[i]);
      CHECK(equal == model.points.size());
    }
  }
}

TEST_CASE("cgal-metric with grids anchored at the origin: CGAL's generator where the anchors agree, a tile the "
          "union's values",
          "[classification][cgal]")
{
  namespace SNC = SN::Classification;
  auto same_column = [](const std::vector<double>& x, const std::vector<double>& y) {
    if(x.size() != y.size())
      return false;
    for(std::size_t i = 0; i < x.size(); ++i)
      if(!same_bits(x[i], y[i]))
        return false;
    return true;
  };
  // The scene moved so that its lowest x and y are 0: CGAL's grids, anchored at the bounding box,
  // then have the origin's cells (the voxel a power of two, its coarsest cell 2 m)
  SN::Oriented_point_set model;
  const Point_list points = scene(11);
  double min_x = points.front().first.x(), min_y = points.front().first.y();
  for(const auto& p : points)
  {
    min_x = std::min(min_x, p.first.x());
    min_y = std::min(min_y, p.first.y());
  }
  for(const auto& p : points)
    model.points.emplace_back(p.first.x() - min_x, p.first.y() - min_y, p.first.z());
  std::vector<sigmoid_tool::Feature_column> expected;
  sigmoid_tool::append_cgal_features(model, 3, 0.5, 1, expected);
  const std::size_t n = model.points.size();
  for(const unsigned int threads : {1u, 2u, 3u})
  {
    std::vector<sigmoid_tool::Feature_column> columns;
    sigmoid_tool::append_anchored_cgal_features(model, 3, 0.5, threads, columns, false);
    REQUIRE(columns.size() == expected.size());
    for(std::size_t f = 0; f < columns.size(); ++f)
    {
      INFO(columns[f].name);
      REQUIRE(columns[f].name == expected[f].name);
      // the terrain model in float, not in 256 steps of the height range; the height above in double
      const bool elevation = columns[f].name.rfind("elevation", 0) == 0;
      const bool above = columns[f].name.rfind("height_above", 0) == 0;
      std::size_t equal = 0;
      double largest = 0.;
      for(std::size_t i = 0; i < n; ++i)
      {
        const double a = columns[f].values[i], b = expected[f].values[i];
        equal += a == b;
        largest = std::max(largest, std::abs(a - b));
      }
      if(elevation)
        CHECK(largest <= 4. / 255. + 1e-4); // the scene's heights span about 4 m
      else if(above)
        CHECK(largest <= 1e-5);
      else
        CHECK(equal == n);
    }
  }
  // the grids alone: the same columns
  std::vector<sigmoid_tool::Feature_column> all, grids;
  sigmoid_tool::append_anchored_cgal_features(model, 3, 0.5, 2, all, false);
  sigmoid_tool::append_anchored_cgal_features(model, 3, 0.5, 2, grids, true);
  REQUIRE(grids.size() == 3 * 5);
  CHECK(grids.front().name == "vertical_dispersion_0");
  for(const auto& g : grids)
  {
    std::size_t f = 0;
    while(f < all.size() && all[f].name != g.name)
      ++f;
    REQUIRE(f < all.size());
    CHECK(same_column(g.values, all[f].values));
  }

  // A tile of a larger terrain (houses of 8 m, trees, noise, coordinates far from the origin as a
  // survey's) read with the halo of its points' reach: the union's values, bit for bit
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> across(0., 64.), unit(0., 1.);
  std::normal_distribution<double> noise(0., 0.05);
  SN::Oriented_point_set survey;
  for(int i = 0; i < 9000; ++i)
  {
    const double x = across(rng), y = across(rng);
    double z = 0.05 * x + 0.5 * std::sin(0.2 * y) + noise(rng);
    if(std::fmod(x, 16.) < 8. && std::fmod(y, 16.) < 8.)
      z += 6.;
    else if(unit(rng) < 0.2)
      z += 10. * unit(rng);
    survey.points.emplace_back(652000.25 + x, 6862000.75 + y, 120. + z);
  }
  const CGAL::Bbox_2 tile(652024., 6862024., 652040., 6862040.);
  auto in_box = [](const SN::Oriented_point_set::Point_3& p, const CGAL::Bbox_2& b, double halo) {
    return p.x() >= b.xmin() - halo && p.x() < b.xmax() + halo && p.y() >= b.ymin() - halo && p.y() < b.ymax() + halo;
  };
  // the union's points ordered with the tile's first, as a tile reads them: [0, core) the tile's
  SN::Oriented_point_set ordered;
  std::size_t core = 0;
  for(int pass = 0; pass < 2; ++pass)
    for(const auto& p : survey.points)
      if(in_box(p, tile, 0.) == (pass == 0))
      {
        ordered.points.push_back(p);
        core += pass == 0;
      }
  const double halo = sigmoid_tool::anchored_cgal_halo_width(ordered, 3, 0.5, false, 2, tile, 0, core);
  const double grid_reach = SNC::anchored_cgal_grid_reach(0.5f, 3);
  CHECK(grid_reach == 14.); // the elevation's 6 cells of 2 m and the point's own
  CHECK(halo >= grid_reach);
  CHECK(halo < 20.);
  SN::Oriented_point_set read;
  for(const auto& p : ordered.points)
    if(in_box(p, tile, halo))
      read.points.push_back(p);
  REQUIRE(read.points.size() < ordered.points.size());
  std::vector<sigmoid_tool::Feature_column> whole, part;
  sigmoid_tool::append_anchored_cgal_features(ordered, 3, 0.5, 2, whole, false);
  sigmoid_tool::append_anchored_cgal_features(read, 3, 0.5, 1, part, false);
  REQUIRE(whole.size() == part.size());
  for(std::size_t f = 0; f < whole.size(); ++f)
  {
    INFO(whole[f].name);
    const std::vector<double> tile_values(part[f].values.begin(), part[f].values.begin() + std::ptrdiff_t(core));
    const std::vector<double> union_values(whole[f].values.begin(), whole[f].values.begin() + std::ptrdiff_t(core));
    CHECK(same_column(tile_values, union_values));
  }
  // a narrower halo loses the terrain model of some points (the test can fail)
  SN::Oriented_point_set narrow;
  for(const auto& p : ordered.points)
    if(in_box(p, tile, 4.))
      narrow.points.push_back(p);
  std::vector<sigmoid_tool::Feature_column> cut;
  sigmoid_tool::append_anchored_cgal_features(narrow, 3, 0.5, 2, cut, true);
  REQUIRE(cut[5].name == "elevation_2");
  std::size_t elevation = 0;
  while(whole[elevation].name != "elevation_2")
    ++elevation;
  std::size_t differing = 0;
  for(std::size_t i = 0; i < core; ++i)
    differing += !same_bits(cut[5].values[i], whole[elevation].values[i]);
  CHECK(differing > 0);
}

TEST_CASE("CGAL's voxel representatives: the same on any thread count, sorted in parallel past 2^16 points",
          "[classification][concurrency]")
{
  // 100,000 points on a lattice of 0.1 with every tenth one repeated: many voxels, ties in voxel
  // and in distance to the centroid, broken by index whatever the sort
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(0, 199);
  std::vector<SN::internal::Double_point> points;
  for(std::size_t i = 0; i < 100000; ++i)
    points.emplace_back(points.size() % 10 == 9 ? points.back()
                                                 : SN::internal::Double_point(0.1 * cell(rng), 0.1 * cell(rng), 0.1 * (cell(rng) % 4)));
  const std::vector<std::uint32_t> sequential =
    SN::internal::voxel_representatives<CGAL::Sequential_tag>(points, 0.35f, 1);
  CHECK(sequential.size() > 1000);
  for(unsigned int threads : {1u, 2u, 3u})
    CHECK(SN::internal::voxel_representatives<CGAL::Parallel_tag>(points, 0.35f, threads) == sequential);
  // each a point of its voxel: the first point of every voxel by index is one of them or tied with one
  std::vector<bool> chosen(points.size(), false);
  for(std::uint32_t r : sequential)
    chosen[r] = true;
  for(std::size_t i = 9; i < points.size(); i += 10)
    CHECK(!chosen[i]); // a repeated point ties with the one before it, which comes first
}
