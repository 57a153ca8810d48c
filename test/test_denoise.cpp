// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// denoise_point_set(): Yadav et al.'s three stages on analytic cases (a noisy plane, a cube edge, a
// cube corner), its invariants, the overloads and bad inputs.

#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/compute_mean_neighbor_distance.h>
#include "experiments/normal_noise.h"
#include <CGAL/Sigmoid_neighborhoods/Point_set_3.h>
#include "experiments/subdivided_polyhedra.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <utility>
#include <vector>

namespace {

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef std::pair<Point, Vector> Point_with_normal;
typedef std::vector<Point_with_normal> Points;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

auto maps() { return CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); }

// The plane z = 0 sampled on a unit grid, moved along z by N(0, sigma^2), with the exact normals.
Points noisy_plane(int size, double sigma, std::uint64_t seed)
{
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> noise(0., sigma);
  Points points;
  for(int i = 0; i < size; ++i)
    for(int j = 0; j < size; ++j)
      points.emplace_back(Point(i, j, noise(engine)), Vector(0, 0, 1));
  return points;
}

// The corner x, y, z <= 0 of a cube: three unit-grid faces (x = 0, y = 0, z = 0), moved along their
// normals by N(0, sigma^2), with the exact normals. The distance of a point to the clean surface is
// that of its coordinates to the faces.
Points noisy_corner(int size, double sigma, std::uint64_t seed)
{
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> noise(0., sigma);
  Points points;
  for(int a = 0; a < size; ++a)
    for(int b = 0; b < size; ++b)
    {
      points.emplace_back(Point(-a, -b, noise(engine)), Vector(0, 0, 1));
      if(a > 0)
        points.emplace_back(Point(noise(engine), -a, -b), Vector(1, 0, 0));
      if(a > 0 && b > 0)
        points.emplace_back(Point(-b, noise(engine), -a), Vector(0, 1, 0));
    }
  return points;
}

// The distance of a point to the boundary of the octant x, y, z <= 0.
double corner_distance(const Point& p)
{
  const double x = p.x(), y = p.y(), z = p.z();
  if(x <= 0 && y <= 0 && z <= 0)
    return (std::min)({-x, -y, -z});
  const double ox = (std::max)(x, 0.), oy = (std::max)(y, 0.), oz = (std::max)(z, 0.);
  return std::sqrt(ox * ox + oy * oy + oz * oz);
}

// A Fibonacci sphere of n points moved along their exact normals by N(0, sigma^2).
Points noisy_sphere(int n, double radius, double sigma, std::uint64_t seed)
{
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> noise(0., sigma);
  Points points;
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = i * 2.399963229728653;
    const Vector normal(r * std::cos(phi), r * std::sin(phi), z);
    points.emplace_back(CGAL::ORIGIN + (radius + noise(engine)) * normal, normal);
  }
  return points;
}

double rms_z(const Points& points)
{
  double sum = 0.;
  for(const auto& p : points)
    sum += p.first.z() * p.first.z();
  return std::sqrt(sum / double(points.size()));
}

double mean_corner_distance(const Points& points)
{
  double sum = 0.;
  for(const auto& p : points)
    sum += corner_distance(p.first);
  return sum / double(points.size());
}

} // namespace

TEST_CASE("denoise: a noisy plane becomes flat, moving along the normal only", "[denoise]")
{
  const double sigma = 0.3;
  Points points = noisy_plane(30, sigma, 1);
  const Points input = points;
  const double before = rms_z(points);
  const SN::Point_set_denoising_summary s =
    SN::denoise_point_set<CGAL::Sequential_tag>(points, SNP::jet_vertex_update(false, maps()));
  CHECK(s.points == 900);
  // The estimated noise level is the true one, up to the sample and the fits.
  CHECK(s.noise_estimate > 0.8 * sigma);
  CHECK(s.noise_estimate < 1.2 * sigma);
  // On a plane the points converge: they never move by more than the noise, and all iterations run.
  CHECK_FALSE(s.stopped_at_noise_level);
  CHECK(s.iterations == SN::defaults::FILTER_ITERATIONS);
  CHECK(rms_z(points) < 0.2 * before);
  double tangential = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
    tangential = (std::max)(tangential, std::abs(points[i].first.x() - input[i].first.x()) +
                                          std::abs(points[i].first.y() - input[i].first.y()));
  CHECK(tangential < 1e-9);
  CHECK(s.largest_displacement < s.maximum_deviation);
  CHECK(s.maximum_deviation == Approx(SN::internal::DEVIATION_SCALE_FACTOR * s.scale));
  CHECK(s.planar + s.edges + s.corners + s.unclassified == points.size());
  CHECK(s.planar > 800);
  for(const auto& p : points)
    CHECK(p.second.squared_length() == Approx(1.).epsilon(1e-14));
}

TEST_CASE("denoise: on a sphere the iterations stop at the noise level", "[denoise]")
{
  // A Fibonacci sphere of radius 12 (spacing about 1) with noise 0.3 along the normals: the filtered
  // normals turn into facets and the points drift; the discrepancy rule stops them.
  const int n = 1800;
  const double sigma = 0.3;
  Points points = noisy_sphere(n, 12., sigma, 11);
  const Points input = points;
  // the planar rule's drift; the jet update's smooth points do not drift (the tests [jet] below)
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(points, SNP::jet_vertex_update(false, maps()));
  double squares = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
    squares += CGAL::squared_distance(points[i].first, input[i].first);
  const double rms_displacement = std::sqrt(squares / double(n));
  CHECK(s.noise_estimate > 0.8 * sigma);
  CHECK(s.noise_estimate < 1.3 * sigma);
  REQUIRE(s.stopped_at_noise_level);
  CHECK(s.iterations < SN::defaults::FILTER_ITERATIONS);
  CHECK(rms_displacement >= SN::internal::DISCREPANCY_FACTOR * s.noise_estimate);
  // One iteration less has not reached it.
  Points fewer = input;
  SN::denoise_point_set<CGAL::Sequential_tag>(
    fewer, SNP::jet_vertex_update(false, SNP::stop_at_noise_level(false, CGAL::parameters::number_of_iterations(
                                                                            s.iterations - 1)
                                                                            .point_map(Point_map())
                                                                            .normal_map(Normal_map()))));
  squares = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
    squares += CGAL::squared_distance(fewer[i].first, input[i].first);
  CHECK(std::sqrt(squares / double(n)) < SN::internal::DISCREPANCY_FACTOR * s.noise_estimate);
  // Without the rule all iterations run.
  Points all = input;
  const auto s_all = SN::denoise_point_set<CGAL::Sequential_tag>(
    all, SNP::stop_at_noise_level(false, SNP::jet_vertex_update(false, maps())));
  CHECK(s_all.iterations == SN::defaults::FILTER_ITERATIONS);
  CHECK_FALSE(s_all.stopped_at_noise_level);
  CHECK(s_all.noise_estimate == 0.);
}

TEST_CASE("denoise: a cube corner gets closer to the clean surface, closer than by the authors' rules", "[denoise]")
{
  Points points = noisy_corner(14, 0.3, 2);
  const double before = mean_corner_distance(points);
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(points, maps());
  CHECK(mean_corner_distance(points) < 0.6 * before);
  CHECK(s.planar + s.edges + s.corners == points.size());
  // The authors' stage 3 (unweighted metrics, full steps, no rank test) on the same input moves the
  // edge and corner points by up to epsilon in one step: it ends farther from the surface.
  Points authors = noisy_corner(14, 0.3, 2);
  SN::denoise_point_set<CGAL::Sequential_tag>(authors, SNP::authors_vertex_update(true, SNP::rank_threshold(0., maps())));
  CHECK(mean_corner_distance(authors) > mean_corner_distance(points));
}

TEST_CASE("denoise: the rank test keeps a point where the planes do not constrain it", "[denoise]")
{
  // On a plane a corner's metric sum n_j n_j^T has rank 1: x and y are not solved for.
  const std::vector<Eigen::Vector3d> normals(4, Eigen::Vector3d(0, 0, 1));
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  const double heights[4] = {0.1, -0.3, 0.2, 0.4};
  for(int j = 0; j < 4; ++j)
  {
    a += normals[j] * normals[j].transpose();
    b += normals[j] * heights[j];
  }
  a(0, 0) = 1e-14; // what rounding leaves: the literal inverse would move x by 1e14 times nothing
  bool deficient = false;
  const Eigen::Vector3d x = SN::internal::qem_offset(a, b + Eigen::Vector3d(1e-3, 0, 0), SN::defaults::RANK_THRESHOLD,
                                                     deficient);
  CHECK(deficient);
  CHECK(x[0] == 0.);
  CHECK(x[1] == 0.);
  CHECK(x[2] == Approx(0.1)); // the mean height
  const Eigen::Vector3d literal = SN::internal::qem_offset(a, b + Eigen::Vector3d(1e-3, 0, 0), 0., deficient);
  CHECK(std::abs(literal[0]) > 1e10);
}

TEST_CASE("denoise: bit-identical on 1 and 2 threads and sequentially, in place differs", "[denoise][parallel]")
{
  const Points input = noisy_corner(12, 0.3, 3);
  Points sequential = input, one = input, two = input, adaptive_one = input, adaptive_two = input, in_place = input;
  SN::denoise_point_set<CGAL::Sequential_tag>(sequential, maps());
  SN::denoise_point_set<CGAL::Parallel_tag>(one, SNP::number_of_threads(1, maps()));
  SN::denoise_point_set<CGAL::Parallel_tag>(two, SNP::number_of_threads(2, maps()));
  SN::denoise_point_set<CGAL::Parallel_tag>(adaptive_one,
                                            SNP::adaptive_neighborhood_size(true, SNP::number_of_threads(1, maps())));
  SN::denoise_point_set<CGAL::Parallel_tag>(adaptive_two,
                                            SNP::adaptive_neighborhood_size(true, SNP::number_of_threads(2, maps())));
  const auto s = SN::denoise_point_set<CGAL::Parallel_tag>(in_place, SNP::in_place_updates(true, maps()));
  std::size_t equal = 0, adaptive_equal = 0, adaptive_differs = 0, in_place_differs = 0;
  for(std::size_t i = 0; i < input.size(); ++i)
  {
    equal += (sequential[i] == one[i] && one[i] == two[i]);
    adaptive_equal += (adaptive_one[i] == adaptive_two[i]);
    adaptive_differs += (adaptive_one[i].first != one[i].first);
    in_place_differs += (in_place[i].first != one[i].first);
  }
  CHECK(equal == input.size());
  CHECK(adaptive_equal == input.size());
  CHECK(adaptive_differs > 0);
  CHECK(in_place_differs > 0);
  CHECK(mean_corner_distance(in_place) < mean_corner_distance(input));
  CHECK(s.iterations >= 1);
}

TEST_CASE("denoise: a refused move leaves the point where it is", "[denoise]")
{
  Points points = noisy_plane(12, 0.3, 4);
  const Points input = points;
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(
    points, SNP::maximum_deviation(1e-9, SNP::stop_at_noise_level(false, CGAL::parameters::number_of_iterations(3)
                                                                             .point_map(Point_map())
                                                                             .normal_map(Normal_map()))));
  CHECK(s.refused > 0);
  CHECK(s.largest_displacement < 1e-9);
  for(std::size_t i = 0; i < points.size(); ++i)
    CHECK(CGAL::squared_distance(points[i].first, input[i].first) < 1e-18);
}

TEST_CASE("denoise: the callback reports progress and can stop", "[denoise]")
{
  Points points = noisy_plane(12, 0.3, 5);
  std::vector<double> reported;
  const std::function<bool(double)> stop_after_two = [&](double fraction) {
    reported.push_back(fraction);
    return reported.size() < 2;
  };
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(
    points, SNP::stop_at_noise_level(false, CGAL::parameters::number_of_iterations(10)
                                              .callback(stop_after_two)
                                              .point_map(Point_map())
                                              .normal_map(Normal_map())));
  CHECK(s.interrupted);
  CHECK(s.iterations == 2);
  REQUIRE(reported.size() == 2);
  CHECK(reported[0] == Approx(0.1));
  CHECK(reported[1] == Approx(0.2));
}

TEST_CASE("denoise: the mesh and Point_set_3 overloads equal the point range", "[denoise][mesh][point_set]")
{
  Mesh mesh;
  SN::make_subdivided_cube(8, mesh);
  auto normals = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:normal", CGAL::NULL_VECTOR).first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  auto vertices = mesh.vertices();
  SN::add_normal_noise(vertices, 0.02, 6, CGAL::parameters::point_map(mesh.points()).normal_map(normals));
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  Points points;
  std::vector<Point> input;
  CGAL::Point_set_3<Point, Vector> point_set;
  point_set.add_normal_map();
  for(auto v : mesh.vertices())
  {
    points.emplace_back(mesh.point(v), normals[v]);
    input.push_back(mesh.point(v));
    point_set.insert(mesh.point(v), normals[v]);
  }
  const std::size_t faces = mesh.number_of_faces();
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(mesh, CGAL::parameters::vertex_normal_map(normals));
  SN::denoise_point_set<CGAL::Sequential_tag>(points, maps());
  SN::denoise_point_set<CGAL::Sequential_tag>(point_set);
  CHECK(s.mesh.points == mesh.number_of_vertices());
  CHECK(mesh.number_of_faces() == faces);
  CHECK(mesh.is_valid());
  std::size_t i = 0, equal = 0, moved = 0;
  for(auto v : mesh.vertices())
  {
    const auto index = *(point_set.begin() + std::ptrdiff_t(i));
    equal += (mesh.point(v) == points[i].first && point_set.point(index) == points[i].first &&
              point_set.normal(index) == points[i].second);
    moved += (mesh.point(v) != input[i]);
    ++i;
  }
  CHECK(equal == mesh.number_of_vertices());
  CHECK(moved > mesh.number_of_vertices() / 2);
  CGAL::Point_set_3<Point, Vector> no_normals;
  no_normals.insert(Point(0, 0, 0));
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(no_normals), Catch::Contains("no normal map"));
}

TEST_CASE("denoise: bad inputs", "[denoise][errors]")
{
  Points few = noisy_plane(3, 0.1, 8); // 9 points: the scale needs 13
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(few, maps()), Catch::Contains("at least 13 points"));
  Points zero = noisy_plane(5, 0.1, 9);
  zero[7].second = CGAL::NULL_VECTOR;
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(zero, maps()), Catch::Contains("point 7 has a zero normal"));
  Points nan = noisy_plane(5, 0.1, 9);
  nan[3].first = Point(std::nan(""), 0, 0);
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(nan, maps()), Catch::Contains("point 3 has a non-finite"));
  Points ok = noisy_plane(5, 0.1, 9);
  const Points unchanged = ok;
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(ok, SNP::step_size(-1., maps())),
                    Catch::Contains("step size"));
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(ok, SNP::rank_threshold(2., maps())),
                    Catch::Contains("rank threshold"));
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(ok, SNP::maximum_deviation(-1., maps())),
                    Catch::Contains("maximum deviation"));
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(ok, SNP::planar_weight_radius(std::nan(""), maps())),
                    Catch::Contains("planar weight radius"));
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(ok, SNP::normal_cut_off(1.5, maps())),
                    Catch::Contains("cut-off must lie in [-1, 1]"));
  CHECK(ok == unchanged); // nothing written on an error
  // Duplicate points: the covariance of a neighborhood of one position has no extent; nothing moves.
  Points duplicates(20, Point_with_normal(Point(1, 2, 3), Vector(0, 0, 1)));
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(duplicates, SNP::stop_at_noise_level(false, maps()));
  CHECK(s.unclassified == 20);
  for(const auto& p : duplicates)
    CHECK(p.first == Point(1, 2, 3));
}

TEST_CASE("denoise: the optimal sigmoid weights in the vote", "[denoise][parallel]")
{
  const Points input = noisy_corner(12, 0.3, 12);
  const double before = mean_corner_distance(input);
  Points one = input, two = input, plain = input;
  const auto s = SN::denoise_point_set<CGAL::Parallel_tag>(
    one, SNP::optimal_vote_weights(true, SNP::number_of_threads(1, maps())));
  SN::denoise_point_set<CGAL::Parallel_tag>(two, SNP::optimal_vote_weights(true, SNP::number_of_threads(2, maps())));
  SN::denoise_point_set<CGAL::Sequential_tag>(plain, maps());
  std::size_t equal = 0;
  for(std::size_t i = 0; i < input.size(); ++i)
    equal += (one[i] == two[i]);
  CHECK(equal == input.size());
  // The corner's exact normals are 0 or 90 degrees apart: there the weights vote as the cut-off does.
  // On a sphere the normals turn continuously, and the weights change the votes.
  Points sphere = noisy_sphere(600, 7., 0.2, 14), sphere_plain = sphere;
  SN::denoise_point_set<CGAL::Sequential_tag>(sphere, SNP::optimal_vote_weights(true, maps()));
  SN::denoise_point_set<CGAL::Sequential_tag>(sphere_plain, maps());
  std::size_t differs = 0;
  for(std::size_t i = 0; i < sphere.size(); ++i)
    differs += (sphere[i].second != sphere_plain[i].second);
  CHECK(differs > sphere.size() / 2);
  CHECK(s.cut_off_votes < input.size() / 10);
  CHECK(mean_corner_distance(one) < 0.6 * before);
  // The search needs k_max + 1 points.
  Points few = noisy_plane(4, 0.1, 13); // 16 points: enough for the scale, not for k_max = 20
  CHECK_THROWS_WITH(SN::denoise_point_set<CGAL::Sequential_tag>(few, SNP::optimal_vote_weights(true, maps())),
                    Catch::Contains("optimal vote weights"));
  CHECK_NOTHROW(SN::denoise_point_set<CGAL::Sequential_tag>(
    few, SNP::optimal_vote_weights(true, SNP::k_min(4, SNP::k_max(10, maps())))));
}

namespace {

double mean_sphere_distance(const Points& points, double radius)
{
  double sum = 0.;
  for(const auto& p : points)
    sum += std::abs(std::sqrt((p.first - CGAL::ORIGIN).squared_length()) - radius);
  return sum / double(points.size());
}

} // namespace

TEST_CASE("denoise: the jet update follows a curved surface closer than the plane update", "[denoise][jet]")
{
  // A sphere of radius 6 at spacing about 1: stage 1 turns its normals into facets, stage 2 calls
  // many of them edges, and the planar rule pulls the points into the chords.
  const Points input = noisy_sphere(500, 6., 0.3, 21);
  Points jet = input, plane = input;
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(jet, maps());
  SN::denoise_point_set<CGAL::Sequential_tag>(plane, SNP::jet_vertex_update(false, maps()));
  const double before = mean_sphere_distance(input, 6.), after = mean_sphere_distance(jet, 6.);
  CHECK(after < 0.6 * before);
  CHECK(after < 0.85 * mean_sphere_distance(plane, 6.));
  CHECK(s.smooth > input.size() / 2);
  CHECK(s.degenerate_fits == 0);
  CHECK(s.noise_estimate > 0.);
}

TEST_CASE("denoise: the jet update keeps a cube corner's edges", "[denoise][jet]")
{
  // The corner's faces meet at 90 degrees: the sigmoid keeps each fit on its face, and the edge and
  // corner points keep the restricted quadratic error metrics.
  const Points input = noisy_corner(14, 0.3, 2);
  Points jet = input, plane = input;
  SN::denoise_point_set<CGAL::Sequential_tag>(jet, maps());
  SN::denoise_point_set<CGAL::Sequential_tag>(plane, SNP::jet_vertex_update(false, maps()));
  const double before = mean_corner_distance(input);
  CHECK(mean_corner_distance(jet) < 0.6 * before);
  CHECK(mean_corner_distance(jet) < 1.25 * mean_corner_distance(plane));
  // The points within one spacing of an edge (two coordinates near 0) end as close as the others.
  double edge = 0., face = 0.;
  std::size_t edges = 0, faces = 0;
  for(std::size_t i = 0; i < input.size(); ++i)
  {
    const Point& p = input[i].first;
    const int near = (std::abs(p.x()) < 1.) + (std::abs(p.y()) < 1.) + (std::abs(p.z()) < 1.);
    (near >= 2 ? edge : face) += corner_distance(jet[i].first);
    ++(near >= 2 ? edges : faces);
  }
  CHECK(edge / double(edges) < 1.5 * face / double(faces));
}

TEST_CASE("denoise: a degenerate jet fit leaves the point where it is", "[denoise][jet]")
{
  // 30 points on a line, moved along z: a stage-2 edge whose normals all agree (a smooth strip), whose
  // quadric has no y: the fit's normal equations are singular and every point stays.
  std::mt19937_64 engine(5);
  std::normal_distribution<double> noise(0., 0.2);
  Points line;
  for(int i = 0; i < 30; ++i)
    line.emplace_back(Point(i, 0, noise(engine)), Vector(0, 0, 1));
  const Points input = line;
  const auto s = SN::denoise_point_set<CGAL::Sequential_tag>(line, maps());
  CHECK(s.degenerate_fits > 0);
  CHECK(s.smooth == line.size());
  CHECK(s.iterations == 1); // the stopping rule has no other point to watch
  for(std::size_t i = 0; i < line.size(); ++i)
    CHECK(line[i].first == input[i].first);
  // The plane update moves them.
  Points plane = input;
  SN::denoise_point_set<CGAL::Sequential_tag>(plane, SNP::jet_vertex_update(false, maps()));
  std::size_t moved = 0;
  for(std::size_t i = 0; i < plane.size(); ++i)
    moved += plane[i].first != input[i].first;
  CHECK(moved > 0);
}

TEST_CASE("denoise: the jet update is bit-identical on 1 and 2 threads", "[denoise][jet][parallel]")
{
  for(const Points& input : {noisy_sphere(700, 7., 0.3, 22), noisy_corner(10, 0.3, 23)})
  {
    Points one = input, two = input, sequential = input;
    const auto s1 = SN::denoise_point_set<CGAL::Parallel_tag>(one, SNP::number_of_threads(1, maps()));
    const auto s2 = SN::denoise_point_set<CGAL::Parallel_tag>(two, SNP::number_of_threads(2, maps()));
    SN::denoise_point_set<CGAL::Sequential_tag>(sequential, maps());
    std::size_t equal = 0;
    for(std::size_t i = 0; i < input.size(); ++i)
      equal += (one[i] == two[i] && one[i] == sequential[i]);
    CHECK(equal == input.size());
    CHECK(s1.iterations == s2.iterations);
    CHECK(s1.smooth == s2.smooth);
  }
}
