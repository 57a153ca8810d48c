// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Zero normals in a point set's file (SPEC §1): with Normal_source::AUTO, all zero is a file
// without normals, a few zero ones are estimated and take their neighbors' sign; with
// Normal_source::FROM_FILE both are an error.

#include <CGAL/Sigmoid_neighborhoods/IO/read_oriented_point_set.h>

#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

// A noisy-free sphere of `n` points, `x y z nx ny nz` with outward normals but at the indices of
// `zero` (all when `all_zero`), written to a scratch file.
std::string sphere_file(const std::string& name, int n, const std::set<int>& zero, bool all_zero = false)
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("sn_zero_normals_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string file = (dir / name).string();
  std::ofstream out(file);
  out.precision(17);
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = 2.399963229728653 * i;
    const double x = r * std::cos(phi), y = r * std::sin(phi);
    out << x << ' ' << y << ' ' << z << ' ';
    if(all_zero || zero.count(i))
      out << "0 0 0\n";
    else
      out << x << ' ' << y << ' ' << z << '\n';
  }
  return file;
}

SN::Normal_options options(SN::Normal_source source)
{
  SN::Normal_options o;
  o.source = source;
  return o;
}

} // namespace

TEST_CASE("zero normals: a point set whose normals are all zero is a file without normals", "[io][normals]")
{
  const std::string file = sphere_file("all_zero.xyz", 300, {}, true);
  const SN::Oriented_point_set m = SN::read_oriented_point_set(file, options(SN::Normal_source::AUTO));
  CHECK(m.normals_estimated);
  CHECK(m.zero_normals == 300);
  REQUIRE(m.normals.size() == 300);
  for(std::size_t i = 0; i < m.points.size(); ++i)
  {
    CHECK(std::abs(m.normals[i].squared_length() - 1.) < 1e-12);
    // a sphere's estimated normals, oriented by the spanning forest, are outward or inward as one
    CHECK(std::abs(m.normals[i] * (m.points[i] - CGAL::ORIGIN)) > 0.99);
  }
  // without estimation (0 neighbors), as a file without normals: no normals
  CHECK(SN::read_oriented_point_set(file, 0).normals.empty());
  // with --normals file, an error as before
  CHECK_THROWS_WITH(SN::read_oriented_point_set(file, options(SN::Normal_source::FROM_FILE)),
                    Catch::Contains("point 0 has a zero normal"));
}

TEST_CASE("zero normals: a few zero normals are estimated and agree in sign with their neighbors", "[io][normals]")
{
  const std::set<int> zero = {17, 150, 151};
  const std::string file = sphere_file("three_zero.xyz", 400, zero);
  const SN::Oriented_point_set m = SN::read_oriented_point_set(file, options(SN::Normal_source::AUTO));
  CHECK_FALSE(m.normals_estimated);
  CHECK(m.zero_normals == 3);
  REQUIRE(m.normals.size() == 400);
  for(std::size_t i = 0; i < m.points.size(); ++i)
  {
    INFO("point " << i);
    const SN::Oriented_point_set::Vector_3 outward = m.points[i] - CGAL::ORIGIN;
    CHECK(std::abs(m.normals[i].squared_length() - 1.) < 1e-12);
    if(zero.count(int(i)))
      CHECK(m.normals[i] * outward > 0.99); // estimated, with the outward sign of the neighbors' file normals
    else
      CHECK(m.normals[i] * outward == Approx(1.).epsilon(1e-12)); // the file's, untouched
  }
  // the same with the file's normals inward: the estimated ones turn inward too
  {
    const std::string inward_file = sphere_file("three_zero_inward.xyz", 400, zero);
    std::ifstream in(inward_file);
    std::string text, line;
    while(std::getline(in, line))
    {
      double v[6];
      std::sscanf(line.c_str(), "%lf %lf %lf %lf %lf %lf", v, v + 1, v + 2, v + 3, v + 4, v + 5);
      char buffer[256];
      std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g %.17g %.17g %.17g\n", v[0], v[1], v[2], -v[3], -v[4], -v[5]);
      text += buffer;
    }
    in.close();
    std::ofstream(inward_file) << text;
    const SN::Oriented_point_set inward = SN::read_oriented_point_set(inward_file, options(SN::Normal_source::AUTO));
    CHECK(inward.zero_normals == 3);
    for(int i : zero)
      CHECK(inward.normals[std::size_t(i)] * (inward.points[std::size_t(i)] - CGAL::ORIGIN) < -0.99);
  }
  // with --normals file, an error as before
  CHECK_THROWS_WITH(SN::read_oriented_point_set(file, options(SN::Normal_source::FROM_FILE)),
                    Catch::Contains("point 17 has a zero normal"));
  // without estimation (0 neighbors), a zero normal cannot be replaced: an error as before
  CHECK_THROWS_WITH(SN::read_oriented_point_set(file, 0), Catch::Contains("point 17 has a zero normal"));
  // a file with normals and none zero counts none
  CHECK(SN::read_oriented_point_set(sphere_file("no_zero.xyz", 100, {})).zero_normals == 0);
}
