// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The point pyramid: voxel thinning (the representative rule, the nearest-representative mapping),
// the features per level equal to those computed on the thinned set alone, bit-identical for any
// thread count, nearly independent of the density at levels coarser than the spacing; and the
// classifier model file that stores the pyramid's scales.

#include "test_models.h"
#include "test_scratch.h"

#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_pyramid_features.h>
#include <CGAL/Sigmoid_neighborhoods/thin_on_voxel_grid.h>
#include <CGAL/property_map.h>

#include "classification/classifier_settings.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;

namespace {

bool same_record(const SN::Point_features& x, const SN::Point_features& y)
{
  for(std::size_t f = 0; f < SN::internal::NUMBER_OF_POINT_FEATURES; ++f)
    if(!same_bits(x.value(SN::Point_feature(f)), y.value(SN::Point_feature(f))))
      return false;
  return true;
}

// A wavy surface over [0, side]^2 with random positions and slightly noisy normals, and a blob above it.
Point_list wavy(std::size_t n, double side, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0., 1.);
  Point_list result;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double x = side * unit(rng), y = side * unit(rng);
    const double z = 0.3 * std::sin(x) * std::cos(0.7 * y);
    const Vector_3 n(-0.3 * std::cos(x) * std::cos(0.7 * y), 0.21 * std::sin(x) * std::sin(0.7 * y), 1.);
    result.emplace_back(Point_3(x, y, z), n / std::sqrt(n.squared_length()));
  }
  return result;
}

Point_list scene(unsigned seed)
{
  Point_list result = wavy(3000, 10., seed);
  std::mt19937_64 rng(seed + 1);
  std::uniform_real_distribution<double> unit(-1., 1.);
  for(int i = 0; i < 300; ++i)
    result.emplace_back(Point_3(5. + unit(rng), 5. + unit(rng), 3. + unit(rng)),
                        Vector_3(unit(rng), unit(rng), unit(rng) + 1.5));
  return result;
}

typedef std::array<long long, 3> Cell;

Cell cell_of(const Point_3& p, double c)
{
  return {(long long)std::floor(p.x() / c), (long long)std::floor(p.y() / c), (long long)std::floor(p.z() / c)};
}

} // namespace

TEST_CASE("voxel thinning: one representative per cell, nearest to its centre, ties to the smallest index",
          "[pyramid][classification]")
{
  // cells of side 1 anchored at the origin
  const std::vector<Point_3> points{
    Point_3(0.1, 0.1, 0.1),    // 0: cell (0,0,0), far from the centre
    Point_3(0.5, 0.4, 0.5),    // 1: cell (0,0,0), 0.1 from the centre: its representative
    Point_3(1.25, 0.5, 0.5),   // 2: cell (1,0,0), 0.25 from the centre
    Point_3(1.75, 0.5, 0.5),   // 3: cell (1,0,0), 0.25 from the centre too: the tie goes to 2
    Point_3(-0.25, 0.5, 0.5),  // 4: cell (-1,0,0), alone: anchored at the origin, not at the data
    Point_3(0.95, 0.5, 0.5),   // 5: cell (0,0,0), but nearer to 2 (0.3) than to 1 (0.46)
    Point_3(2.5, 2.5, 2.5)};   // 6: cell (2,2,2), alone, at its centre
  const SN::Voxel_thinning t = SN::thin_on_voxel_grid<CGAL::Sequential_tag>(points, 1.);
  CHECK(t.cell_size == 1.);
  CHECK(t.representatives == std::vector<std::uint32_t>{1, 2, 4, 6});
  // positions in `representatives`: 1 -> 0, 2 -> 1, 4 -> 2, 6 -> 3
  CHECK(t.nearest_representative == std::vector<std::uint32_t>{0, 0, 1, 1, 2, 1, 3});

  // cells of side 2: (0,0,0) holds 0, 1, 2, 3, 5, centre (1,1,1): squared distances 2.43, 0.86, 0.5625,
  // 1.0625 and 0.5025: 5 represents it; 0 is nearer to 4 (0.4425) than to 5 (1.0425)
  const SN::Voxel_thinning t2 = SN::thin_on_voxel_grid<CGAL::Sequential_tag>(points, 2.);
  CHECK(t2.representatives == std::vector<std::uint32_t>{4, 5, 6});
  CHECK(t2.nearest_representative == std::vector<std::uint32_t>{0, 1, 1, 1, 0, 1, 2});

  CHECK_THROWS_AS(SN::thin_on_voxel_grid<CGAL::Sequential_tag>(points, 0.), std::invalid_argument);
  CHECK_THROWS_AS(SN::thin_on_voxel_grid<CGAL::Sequential_tag>(points, std::nan("")), std::invalid_argument);
}

TEST_CASE("voxel thinning: the rule and the mapping against brute force, for any thread count",
          "[pyramid][classification]")
{
  const Point_list points = scene(7);
  for(double c : {0.3, 1., 2.5})
  {
    const SN::Voxel_thinning t = SN::thin_on_voxel_grid<CGAL::Sequential_tag>(points, c, maps());
    // the rule: per cell, the point nearest to the centre, ties to the smallest index
    std::map<Cell, std::size_t> best;
    auto centre_distance = [&](std::size_t i) {
      const Cell v = cell_of(points[i].first, c);
      const Point_3 centre((v[0] + 0.5) * c, (v[1] + 0.5) * c, (v[2] + 0.5) * c);
      return CGAL::squared_distance(points[i].first, centre);
    };
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const auto it = best.emplace(cell_of(points[i].first, c), i).first;
      if(centre_distance(i) < centre_distance(it->second))
        it->second = i;
    }
    std::vector<std::uint32_t> expected;
    for(const auto& b : best)
      expected.push_back(std::uint32_t(b.second));
    std::sort(expected.begin(), expected.end());
    REQUIRE(t.representatives == expected);
    // the mapping: the nearest representative, ties to the smallest index
    std::size_t other_cell = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      std::size_t nearest = 0;
      for(std::size_t r = 1; r < expected.size(); ++r)
        if(CGAL::squared_distance(points[i].first, points[expected[r]].first) <
           CGAL::squared_distance(points[i].first, points[expected[nearest]].first))
          nearest = r;
      REQUIRE(t.nearest_representative[i] == nearest);
      other_cell += cell_of(points[expected[nearest]].first, c) != cell_of(points[i].first, c);
    }
    CHECK(other_cell > 0); // the nearest is not always the own cell's: the mapping is not the cell's
    for(unsigned threads : {1u, 2u, 3u})
    {
      const SN::Voxel_thinning p =
        SN::thin_on_voxel_grid<CGAL::Parallel_tag>(points, c, SNP::number_of_threads(threads, maps()));
      CHECK(p.representatives == t.representatives);
      CHECK(p.nearest_representative == t.nearest_representative);
    }
  }
}

TEST_CASE("voxel thinning: bad points named by the first, on any thread count", "[pyramid][bad-input][threads]")
{
  // above the size checked on threads: the points and their voxels are checked in parallel, and a
  // fault sends the check through the points in order
  const Point_list sound = wavy(6000, 10., 3);
  auto message = [](const Point_list& points, double cell, unsigned int threads) {
    try
    {
      SN::thin_on_voxel_grid<CGAL::Parallel_tag>(points, cell, SNP::number_of_threads(threads, maps()));
      return std::string("sound");
    }
    catch(const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
  };
  Point_list not_finite = sound;
  not_finite[4300].first = Point_3(std::nan(""), 0., 0.);
  not_finite[4200].first = Point_3(0., std::numeric_limits<double>::infinity(), 0.);
  Point_list far = sound; // within the coordinates' range, beyond the voxels' at a cell of 1e-10
  far[5000].first = Point_3(1e140, 0., 0.);
  far[4999].first = Point_3(0., -1e140, 0.);
  for(unsigned int threads : {1u, 2u, 3u})
  {
    CHECK(message(sound, 0.5, threads) == "sound");
    CHECK(message(not_finite, 0.5, threads) == "point 4200 has a non-finite coordinate");
    CHECK(message(far, 1e-10, threads) == "point 4999 lies beyond the voxels' 64-bit range");
  }
}

TEST_CASE("pyramid features: each level's equal to the features of the thinned set alone, bit for bit",
          "[pyramid][classification]")
{
  const Point_list points = scene(11);
  const std::vector<double> cells{0.25, 0.5, 1.};
  const unsigned int k = 10;
  for(const SN::Cosine_sigmoid& sigmoid : {SN::Cosine_sigmoid(CGAL_PI, CGAL_PI), SN::Cosine_sigmoid(CGAL_PI / 6, CGAL_PI / 3)})
  {
    std::vector<std::vector<SN::Point_features>> pyramid;
    SN::compute_pyramid_features<CGAL::Sequential_tag>(points, cells, k, sigmoid, std::back_inserter(pyramid), maps());
    REQUIRE(pyramid.size() == points.size());
    for(std::size_t l = 0; l < cells.size(); ++l)
    {
      const SN::Voxel_thinning t = SN::thin_on_voxel_grid<CGAL::Sequential_tag>(points, cells[l], maps());
      Point_list thinned;
      for(std::uint32_t r : t.representatives)
        thinned.push_back(points[r]); // the original points' normals
      CHECK(thinned.size() < points.size());
      std::vector<std::vector<SN::Point_features>> direct;
      SN::compute_point_features<CGAL::Sequential_tag>(thinned, sigmoid, {k}, std::back_inserter(direct), maps());
      std::size_t same = 0;
      for(std::size_t i = 0; i < points.size(); ++i)
        same += same_record(pyramid[i].at(l), direct[t.nearest_representative[i]].at(0));
      CHECK(same == points.size());
      CHECK(pyramid[t.representatives[5]].at(l).k == k);
    }
  }
  CHECK_THROWS_AS(SN::build_point_pyramid<CGAL::Sequential_tag>(points, {100.}, k, maps()), std::invalid_argument);
  CHECK_THROWS_AS(SN::build_point_pyramid<CGAL::Sequential_tag>(points, {}, k, maps()), std::invalid_argument);
}

TEST_CASE("pyramid features: bit-identical for any thread count", "[pyramid][classification][concurrency]")
{
  const Point_list points = scene(5);
  const std::vector<double> cells{0.25, 0.5, 1., 2.};
  const SN::Cosine_sigmoid sigmoid(CGAL_PI / 6, CGAL_PI / 3);
  std::vector<std::vector<SN::Point_features>> sequential;
  SN::compute_pyramid_features<CGAL::Sequential_tag>(points, cells, 10, sigmoid, std::back_inserter(sequential), maps());
  for(unsigned threads : {1u, 2u, 3u})
  {
    std::vector<std::vector<SN::Point_features>> parallel;
    SN::compute_pyramid_features<CGAL::Parallel_tag>(points, cells, 10, sigmoid, std::back_inserter(parallel),
                                                     SNP::number_of_threads(threads, maps()));
    REQUIRE(parallel.size() == sequential.size());
    std::size_t differing = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
      for(std::size_t l = 0; l < cells.size(); ++l)
        differing += !same_record(parallel[i][l], sequential[i][l]);
    CHECK(differing == 0);
  }
  // the per-level records, read through each point's nearest representative, are the same
  const std::vector<SN::Pyramid_level> levels = SN::build_point_pyramid<CGAL::Sequential_tag>(points, cells, 10, maps());
  for(unsigned threads : {1u, 2u, 3u})
  {
    const std::vector<std::vector<SN::Point_features>> per_level = SN::compute_pyramid_level_features<CGAL::Parallel_tag>(
      points, levels, 10, sigmoid, SNP::number_of_threads(threads, maps()));
    REQUIRE(per_level.size() == cells.size());
    std::size_t differing = 0;
    for(std::size_t l = 0; l < cells.size(); ++l)
    {
      REQUIRE(per_level[l].size() == levels[l].thinning.representatives.size());
      for(std::size_t i = 0; i < points.size(); ++i)
        differing += !same_record(per_level[l][levels[l].thinning.nearest_representative[i]], sequential[i][l]);
    }
    CHECK(differing == 0);
  }
  std::vector<SN::Pyramid_level> other = levels;
  other[1].thinning.nearest_representative.pop_back();
  CHECK_THROWS_AS(SN::compute_pyramid_level_features<CGAL::Sequential_tag>(points, other, 10, sigmoid, maps()),
                  std::invalid_argument);
}

TEST_CASE("pyramid features: nearly the same on a surface thinned 4x, at the levels coarser than its spacing",
          "[pyramid][classification]")
{
  // 100 points/m^2 (spacing 0.1 m) and its first quarter, 25 points/m^2 (spacing 0.2 m)
  const Point_list dense = wavy(40000, 20., 3);
  const Point_list sparse(dense.begin(), dense.begin() + 10000);
  const std::vector<double> cells{0.05, 0.1, 0.2, 0.4, 0.8, 1.6};
  const SN::Cosine_sigmoid equal(CGAL_PI, CGAL_PI);
  std::vector<std::vector<SN::Point_features>> d, s;
  SN::compute_pyramid_features<SN::Parallel_if_available_tag>(dense, cells, 10, equal, std::back_inserter(d), maps());
  SN::compute_pyramid_features<SN::Parallel_if_available_tag>(sparse, cells, 10, equal, std::back_inserter(s), maps());
  // Per point, the split between linearity and planarity of 11 nearly regular representatives swings
  // with which of the equidistant ones come in (mean |difference| 0.08 to 0.16 here), so the scale
  // features are compared as means, the shape per point through the eigenentropy.
  for(std::size_t l = 0; l < cells.size(); ++l)
  {
    double radius[2] = {0., 0.}, sum[2] = {0., 0.}, scattering[2] = {0., 0.}, planarity[2] = {0., 0.}, entropy = 0.;
    std::size_t count = 0;
    for(std::size_t i = 0; i < sparse.size(); ++i)
    {
      const Point_3& p = sparse[i].first;
      if(p.x() < 4. || p.x() > 16. || p.y() < 4. || p.y() > 16.) // away from the borders
        continue;
      ++count;
      const SN::Point_features* f[2] = {&s[i][l], &d[i][l]};
      for(int j = 0; j < 2; ++j)
      {
        radius[j] += f[j]->radius;
        sum[j] += f[j]->sum_of_eigenvalues;
        scattering[j] += f[j]->dimensionality.scattering;
        planarity[j] += f[j]->dimensionality.planarity;
      }
      entropy += std::abs(f[0]->dimensionality.eigenentropy - f[1]->dimensionality.eigenentropy);
    }
    entropy /= double(count);
    INFO("cell " << cells[l] << ": mean radius " << radius[0] / count << " sparse, " << radius[1] / count
                 << " dense; sum of eigenvalues " << sum[0] / count << ", " << sum[1] / count << "; scattering "
                 << scattering[0] / count << ", " << scattering[1] / count << "; planarity " << planarity[0] / count
                 << ", " << planarity[1] / count << "; eigenentropy |difference| " << entropy);
    if(cells[l] < 0.1) // finer than both spacings: k = 10 reaches twice as far on the sparse set
    {
      CHECK(radius[0] / radius[1] > 1.6);
      CHECK(sum[0] / sum[1] > 2.5);
      CHECK(scattering[0] / scattering[1] > 2.5);
    }
    if(cells[l] >= 0.4) // coarser than both: the same extent and nearly the same shape
    {
      CHECK(radius[0] / radius[1] == Approx(1.).margin(0.05));
      CHECK(sum[0] / sum[1] == Approx(1.).margin(0.08));
      CHECK(scattering[0] / scattering[1] == Approx(1.).margin(0.08));
      CHECK(std::abs(planarity[0] - planarity[1]) / double(count) < 0.07);
      CHECK(entropy < 0.03);
    }
  }
}

TEST_CASE("classifier model: the pyramid's cell sizes and k round trip, and old models load without them",
          "[pyramid][classification]")
{
  using namespace sigmoid_tool;
  Classifier_settings s;
  s.labels = parse_label_mapping("ground=2,building=6");
  s.features.groups = {"pyramid", "height"};
  s.features.pyramid_cell = 0.25;
  s.features.pyramid_levels = 3;
  s.features.pyramid_k = 12;
  s.feature_names = {"linearity_pyr0.25"};
  nlohmann::json j = settings_json(s);
  CHECK(j["features"]["pyramid"]["cell_sizes"] == nlohmann::json({0.25, 0.5, 1.}));
  const Classifier_settings back = settings_from_json(nlohmann::json::parse(j.dump()), "model.bin");
  CHECK(back.features.groups == s.features.groups);
  CHECK(back.features.pyramid_cell == 0.25);
  CHECK(back.features.pyramid_levels == 3);
  CHECK(back.features.pyramid_k == 12);
  CHECK(back.features.pyramid_cell_sizes() == std::vector<double>{0.25, 0.5, 1.});

  nlohmann::json old = j;
  old["features"].erase("pyramid");
  old["features"]["groups"] = {"height"};
  const Classifier_settings defaults = settings_from_json(old, "old.bin");
  CHECK(defaults.features.pyramid_cell_sizes() == Feature_options().pyramid_cell_sizes());

  nlohmann::json bad = j;
  bad["features"]["pyramid"]["cell"] = -1.;
  CHECK_THROWS_AS(settings_from_json(bad, "bad.bin"), Usage_error);
  bad = j;
  bad["features"]["pyramid"]["cell_sizes"] = {0.25, 0.5, 2.};
  CHECK_THROWS_AS(settings_from_json(bad, "bad.bin"), Usage_error);
}

TEST_CASE("feature groups: one table gives the names, the help, the needs and the checks", "[classification]")
{
  using namespace sigmoid_tool;
  const std::vector<Feature_group>& table = feature_groups();
  REQUIRE(table.size() == 12);
  const std::string usage = feature_groups_usage();
  for(const Feature_group& g : table)
  {
    CHECK(find_feature_group(g.name) == &g);
    CHECK(usage.find("      " + std::string(g.name) + " ") != std::string::npos);
    CHECK((g.help != nullptr && g.neighbors != nullptr && g.halo != nullptr && g.on_tiles != nullptr &&
           g.compute != nullptr));
  }
  CHECK(find_feature_group("colour") == nullptr);

  auto refusal = [](const std::function<void()>& f) {
    try
    {
      f();
    }
    catch(const Usage_error& e)
    {
      return std::string(e.what());
    }
    return std::string("no refusal");
  };
  CHECK(refusal([] { parse_feature_groups("k20,colour"); }) ==
        "--features: unknown group 'colour': expected cgal, cgal-metric, cgal-grid, k20, eigenentropy, dimensionality, "
        "optimal, multiscale, multiscale-sigmoid, height, pyramid or pyramid-sigmoid");
  CHECK(refusal([] { parse_feature_groups("k20,height,k20"); }) == "--features: group 'k20' given twice");
  CHECK(refusal([] { parse_feature_groups("cgal-grid,k20,cgal"); }) ==
        "--features: cgal, cgal-metric and cgal-grid share CGAL's features: give one of them");
  CHECK(refusal([] { parse_feature_groups(""); }) == "--features: no group");
  CHECK(parse_feature_groups(DEFAULT_FEATURE_GROUPS) ==
        std::vector<std::string>{"cgal-metric", "multiscale-sigmoid", "pyramid"});

  // what a set needs: the largest of its groups'
  Feature_options o;
  o.groups = {"k20", "multiscale", "height"};
  CHECK(largest_neighborhood(o) == 100);
  CHECK(cell_halo(o) == 10. * (1. + 1e-6));
  o.groups = {"optimal", "cgal"};
  CHECK(largest_neighborhood(o) == o.k_max);
  CHECK(cell_halo(o) == 0.);
  CHECK(whole_set_groups(o) == "cgal");
  o.groups = {"pyramid", "pyramid-sigmoid"}; // cells 0.5 ... 8 m
  CHECK(largest_neighborhood(o) == 0);
  CHECK(cell_halo(o) == 32.);
  CHECK(cell_halo(o, false) == 8. * (1. + 1e-6));
  CHECK(whole_set_groups(o) == "");
  o.groups = {"height", "cgal-metric"};
  CHECK(cell_halo(o) > 10.);
  CHECK(whole_set_groups(o) == "");
  o.cgal_grids_at_origin = false; // an older model's grids, anchored at the bounding box
  CHECK(cell_halo(o) == 10. * (1. + 1e-6));
  CHECK(whole_set_groups(o) == "cgal-metric");
}

TEST_CASE("feature options: the command line and a model file refused by the same rules", "[classification]")
{
  using namespace sigmoid_tool;
  Classifier_settings s;
  s.labels = parse_label_mapping("ground=2,building=6");
  s.features.groups = {"pyramid-sigmoid", "multiscale"};
  s.feature_names = {"linearity_pyr0.5"};
  const nlohmann::json written = nlohmann::json::parse(settings_json(s).dump());
  REQUIRE_NOTHROW(settings_from_json(written, "model.bin"));
  REQUIRE_NOTHROW(s.features.check(Feature_options::COMMAND_LINE));

  auto message = [](const std::function<void()>& f) {
    try
    {
      f();
    }
    catch(const Usage_error& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // one bad setting at a time: its option's message on the command line, its key's in the model file
  struct Case
  {
    std::function<void(Feature_options&)> set;
    std::function<void(nlohmann::json&)> write;
    std::string command_line, model_file;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases{
    {[](Feature_options& f) { f.pyramid_levels = 33; }, [](nlohmann::json& j) { j["pyramid"]["levels"] = 33; },
     "--pyramid-levels must be 1 to 32", "features.pyramid.levels must be 1 to 32"},
    {[](Feature_options& f) { f.cgal_scales = 0; }, [](nlohmann::json& j) { j["cgal_scales"] = 0; },
     "--cgal-scales must be 1 to 32", "features.cgal_scales must be 1 to 32"},
    {[&](Feature_options& f) { f.cgal_voxel = nan; }, [](nlohmann::json& j) { j["cgal_voxel"] = nullptr; },
     "--cgal-voxel must be a positive voxel size in metres", "features.cgal_voxel must be a positive voxel size in metres"},
    {[](Feature_options& f) { f.scales = {50, 10}; }, [](nlohmann::json& j) { j["scales"] = {50, 10}; },
     "--scales must be ascending neighbor counts of 1 to 10000 (the columns are named by k)",
     "features.scales must be ascending neighbor counts of 1 to 10000 (the columns are named by k)"},
    {[](Feature_options& f) { f.sigmoid_a = 1.; f.sigmoid_b = 0.5; }, [](nlohmann::json& j) { j["sigmoid"] = {1., 0.5}; },
     "--sigmoid must be two angles 0 <= a <= b <= pi", "features.sigmoid must be two angles 0 <= a <= b <= pi"},
    {[](Feature_options& f) { f.pyramid_sigmoid_cells = {3.}; }, [](nlohmann::json& j) { j["pyramid"]["sigmoid_cells"] = {3.}; },
     "--pyramid-sigmoid-cells: 3 is not a cell size of the pyramid (--pyramid-cell x 2^l)",
     "features.pyramid.sigmoid_cells: 3 is not a cell size of the pyramid (features.pyramid.cell x 2^l)"},
    {[](Feature_options& f) { f.groups = {"cgal", "cgal-grid"}; }, [](nlohmann::json& j) { j["groups"] = {"cgal", "cgal-grid"}; },
     "--features: cgal, cgal-metric and cgal-grid share CGAL's features: give one of them",
     "features.groups: cgal, cgal-metric and cgal-grid share CGAL's features: give one of them"},
    {[](Feature_options& f) { f.pyramid_k = 0; }, [](nlohmann::json& j) { j["pyramid"]["k"] = 0; },
     "features.pyramid.k must be 1 to 10000", "features.pyramid.k must be 1 to 10000"}};
  for(const Case& c : cases)
  {
    Feature_options o = s.features;
    c.set(o);
    CHECK(message([&] { o.check(Feature_options::COMMAND_LINE); }) == c.command_line);
    nlohmann::json j = written;
    c.write(j["features"]);
    j = nlohmann::json::parse(j.dump()); // as a file reads: counts unsigned
    CHECK(message([&] { settings_from_json(j, "model.bin"); }) ==
          "model.bin: not a usable classifier model: " + c.model_file);
  }
  // the types, by the tool's JSON reader
  nlohmann::json j = written;
  j["features"]["k_max"] = "twenty";
  CHECK(message([&] { settings_from_json(j, "model.bin"); }) ==
        "model.bin: not a usable classifier model: features.k_max is a string, expected an integer");
  j = written;
  j["features"]["fixed_k"] = -3;
  CHECK(message([&] { settings_from_json(j, "model.bin"); }) ==
        "model.bin: not a usable classifier model: features.fixed_k is -3, expected a count (an integer >= 0)");

  // a settings line nested deeper than the tool's files is refused before the parser sees it
  const std::string path = scratch_folder("pyramid") + "/deep_model.bin";
  {
    std::ofstream out(path, std::ios::binary);
    out << CLASSIFIER_MODEL_MAGIC << '\n' << std::string(5000, '[') << std::string(5000, ']') << "\nforest";
  }
  std::string forest;
  CHECK(message([&] { read_classifier_settings(path, forest); }) ==
        path + ": not a usable classifier model: arrays or objects nested deeper than 16: not a file of the tool");
  std::filesystem::remove(path);
}
