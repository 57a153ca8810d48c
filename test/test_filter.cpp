// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal voting tensor filter, its adaptive variant, the denoising utilities and the generated
// cube and octahedron, on analytic cases.

#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>
#include <CGAL/Sigmoid_neighborhoods/compute_mean_neighbor_distance.h>
#include "experiments/normal_noise.h"
#include "experiments/subdivided_polyhedra.h"
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <sstream>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <tuple>
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

const double pi = CGAL_PI;

double angle(const Vector& n, const Vector& m)
{
  return SN::normal_angle(n, m);
}

// `n` tilted by an angle up to `max_tilt` about a random axis orthogonal to it.
Vector tilted(const Vector& n, double max_tilt, std::mt19937_64& engine)
{
  std::uniform_real_distribution<double> u(0., 1.);
  const Vector a = std::abs(n.x()) < 0.9 ? Vector(1, 0, 0) : Vector(0, 1, 0);
  Vector t1 = CGAL::cross_product(n, a);
  t1 = t1 / std::sqrt(t1.squared_length());
  const Vector t2 = CGAL::cross_product(n, t1);
  const double phi = 2 * pi * u(engine), theta = max_tilt * u(engine);
  return std::cos(theta) * n + std::sin(theta) * (std::cos(phi) * t1 + std::sin(phi) * t2);
}

// A grid of the plane z = 0 with step 1 and normals tilted by up to `max_tilt`.
Points noisy_plane(int size, double max_tilt, std::uint64_t seed)
{
  std::mt19937_64 engine(seed);
  Points points;
  for(int i = 0; i < size; ++i)
    for(int j = 0; j < size; ++j)
      points.emplace_back(Point(i, j, 0), tilted(Vector(0, 0, 1), max_tilt, engine));
  return points;
}

// A convex cube edge: the faces z = 0 (x <= 0, normal +z) and x = 0 (z < 0, normal +x).
Points noisy_edge(double max_tilt, std::uint64_t seed, std::vector<Vector>& truth)
{
  std::mt19937_64 engine(seed);
  Points points;
  truth.clear();
  for(int y = 0; y <= 12; ++y)
  {
    for(int x = -12; x <= 0; ++x)
    {
      truth.emplace_back(0, 0, 1);
      points.emplace_back(Point(x, y, 0), tilted(truth.back(), max_tilt, engine));
    }
    for(int z = -12; z <= -1; ++z)
    {
      truth.emplace_back(1, 0, 0);
      points.emplace_back(Point(0, y, z), tilted(truth.back(), max_tilt, engine));
    }
  }
  return points;
}

std::vector<Vector> normals_of(const Points& points)
{
  std::vector<Vector> result;
  for(const auto& p : points)
    result.push_back(p.second);
  return result;
}

auto maps() { return CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); }

// The ball neighborhoods computed by brute force, ordered by distance then index.
std::vector<std::vector<std::size_t>> brute_force_balls(const Points& points, double radius)
{
  std::vector<std::vector<std::size_t>> lists(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    std::vector<std::pair<double, std::size_t>> found;
    for(std::size_t j = 0; j < points.size(); ++j)
    {
      const double dx = points[j].first.x() - points[i].first.x(), dy = points[j].first.y() - points[i].first.y(),
                   dz = points[j].first.z() - points[i].first.z();
      const double d2 = dx * dx + dy * dy + dz * dz;
      if(j != i && d2 <= radius * radius)
        found.emplace_back(d2, j);
    }
    std::sort(found.begin(), found.end());
    for(const auto& f : found)
      lists[i].push_back(f.second);
  }
  return lists;
}

} // namespace

TEST_CASE("filter: a plane with noisy normals converges to the plane normal", "[filter]")
{
  Points points = noisy_plane(20, 0.25, 1);
  const double before = SN::normal_mse(std::vector<Vector>(points.size(), Vector(0, 0, 1)), normals_of(points));
  const SN::Normal_filter_summary summary = SN::filter_normals<CGAL::Sequential_tag>(points, maps());
  double worst = 0.;
  for(const auto& p : points)
  {
    worst = (std::max)(worst, angle(p.second, Vector(0, 0, 1)));
    CHECK(p.second.squared_length() == Approx(1.).epsilon(1e-14));
  }
  CHECK(worst < 0.01); // the noise was up to 0.25 rad; what is left is the sample's mean tilt
  CHECK(SN::normal_mse(std::vector<Vector>(points.size(), Vector(0, 0, 1)), normals_of(points)) < before / 100.);
  CHECK(summary.iterations == SN::defaults::FILTER_ITERATIONS);
  CHECK(summary.points == 400);
  // m = mean 12-NN distance of a unit grid: the radius 5 m holds far more than 12 neighbors.
  CHECK(summary.radius > 5.);
  CHECK(summary.mean_neighbors > 40.);
  CHECK(summary.empty_cones == 0);
}

TEST_CASE("filter: a cube edge keeps two normal clusters", "[filter]")
{
  std::vector<Vector> truth;
  Points points = noisy_edge(0.15, 2, truth);
  Points blurred = points;
  SN::filter_normals<CGAL::Sequential_tag>(points, maps());
  double worst = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
    worst = (std::max)(worst, angle(points[i].second, truth[i]));
  CHECK(worst < 0.02);
  // Without the cut-off (every neighbor votes) normals next to the edge are pulled off their face
  // (less than one might think: the binary eigenvalue optimisation keeps both directions where the
  // two faces are about equally represented).
  SN::filter_normals<CGAL::Sequential_tag>(blurred, SNP::normal_cut_off(-1., maps()));
  double worst_blurred = 0.;
  for(std::size_t i = 0; i < blurred.size(); ++i)
    worst_blurred = (std::max)(worst_blurred, angle(blurred[i].second, truth[i]));
  CHECK(worst_blurred > 0.1);
  CHECK(worst_blurred > 5 * worst);
}

TEST_CASE("filter: an empty cone keeps the normal", "[filter]")
{
  Points points = {{Point(0, 0, 0), Vector(1, 0, 0)}, {Point(1, 0, 0), Vector(0, 1, 0)},
                   {Point(0, 1, 0), Vector(0, 0, 1)}};
  const Points before = points;
  const std::vector<std::vector<int>> all = {{1, 2}, {0, 2}, {0, 1}};
  const auto summary = SN::filter_normals<CGAL::Sequential_tag>(
    points, SNP::neighborhoods(all, CGAL::parameters::number_of_iterations(7).point_map(Point_map()).normal_map(Normal_map())));
  for(std::size_t i = 0; i < points.size(); ++i)
    CHECK(points[i].second == before[i].second);
  CHECK(summary.empty_cones == 21);
}

TEST_CASE("filter: the damped update contracts tan(phi) by d / (d + 1) for a fixed tensor", "[filter]")
{
  for(double damping : {3., 1.})
    for(double phi : {0.1, 0.7, 1.2})
    {
      // Point 0 tilted by phi; its neighbors all have the normal e = +z, so T = e e^T.
      Points points = {{Point(0, 0, 0), Vector(std::sin(phi), 0, std::cos(phi))}};
      for(int j = 1; j <= 5; ++j)
        points.emplace_back(Point(j, 0, 0), Vector(0, 0, 1));
      const std::vector<std::vector<int>> lists = {{1, 2, 3, 4, 5}, {}, {}, {}, {}, {}};
      SN::filter_normals<CGAL::Sequential_tag>(
        points, SNP::neighborhoods(lists, SNP::normal_cut_off(0., SNP::damping_factor(damping,
                    CGAL::parameters::number_of_iterations(1).point_map(Point_map()).normal_map(Normal_map())))));
      const Vector& n = points[0].second;
      CHECK(n.y() == 0.);
      CHECK(n.x() / n.z() == Approx(damping / (damping + 1.) * std::tan(phi)).epsilon(1e-13));
      CHECK(n.squared_length() == Approx(1.).epsilon(1e-15));
    }
}

TEST_CASE("filter: the eigenvalue threshold keeps a second direction", "[filter]")
{
  // Half the neighbors along +z, half along x: eigenvalues (0, 1/2, 1/2). With tau <= 1/2 the
  // tensor becomes the projection onto the xz plane and a normal in that plane stays put.
  Points points = {{Point(0, 0, 0), Vector(std::sqrt(0.5), 0, std::sqrt(0.5))}};
  for(int j = 1; j <= 4; ++j)
    points.emplace_back(Point(j, 0, 0), j % 2 ? Vector(0, 0, 1) : Vector(1, 0, 0));
  const std::vector<std::vector<int>> lists = {{1, 2, 3, 4}, {}, {}, {}, {}};
  Points kept = points;
  SN::filter_normals<CGAL::Sequential_tag>(
    kept, SNP::neighborhoods(lists, SNP::normal_cut_off(0.5, SNP::eigenvalue_threshold(0.4,
            CGAL::parameters::number_of_iterations(1).point_map(Point_map()).normal_map(Normal_map())))));
  CHECK(kept[0].second.x() == Approx(std::sqrt(0.5)).epsilon(1e-12));
  CHECK(kept[0].second.z() == Approx(std::sqrt(0.5)).epsilon(1e-12));
}

TEST_CASE("filter: the caller's neighborhoods give the internal result when they are the same", "[filter]")
{
  Points points = noisy_plane(12, 0.3, 3);
  for(auto& p : points) // a little relief, so that distances differ
    p.first = Point(p.first.x(), p.first.y(), 0.05 * std::sin(p.first.x() + 2 * p.first.y()));
  for(bool adaptive : {false, true})
  {
    Points internal = points, given = points;
    const auto summary = SN::filter_normals<CGAL::Sequential_tag>(
      internal, SNP::adaptive_neighborhood_size(adaptive, CGAL::parameters::number_of_iterations(10)
                                                            .point_map(Point_map()).normal_map(Normal_map())));
    const auto lists = brute_force_balls(points, summary.radius);
    SN::filter_normals<CGAL::Sequential_tag>(
      given, SNP::neighborhoods(std::cref(lists), SNP::adaptive_neighborhood_size(adaptive,
               CGAL::parameters::number_of_iterations(10).point_map(Point_map()).normal_map(Normal_map()))));
    std::size_t equal = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
      equal += (internal[i].second == given[i].second);
    CHECK(equal == points.size());
    // the same lists in compressed rows (neighbor_indices, neighbor_offsets)
    std::vector<int> indices;
    std::vector<std::size_t> offsets(1, 0);
    for(const auto& list : lists)
    {
      indices.insert(indices.end(), list.begin(), list.end());
      offsets.push_back(indices.size());
    }
    Points rows = points;
    SN::filter_normals<CGAL::Sequential_tag>(
      rows, SNP::neighbor_indices(indices, SNP::neighbor_offsets(offsets, SNP::adaptive_neighborhood_size(adaptive,
              CGAL::parameters::number_of_iterations(10).point_map(Point_map()).normal_map(Normal_map())))));
    equal = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
      equal += (internal[i].second == rows[i].second);
    CHECK(equal == points.size());
  }
}

TEST_CASE("filter: a given neighbor radius", "[filter]")
{
  Points points = noisy_plane(10, 0.2, 4);
  Points given = points;
  const auto summary = SN::filter_normals<CGAL::Sequential_tag>(points, maps());
  const auto summary2 = SN::filter_normals<CGAL::Sequential_tag>(
    given, CGAL::parameters::neighbor_radius(summary.radius).point_map(Point_map()).normal_map(Normal_map()));
  CHECK(summary2.radius == summary.radius);
  for(std::size_t i = 0; i < points.size(); ++i)
    CHECK(points[i].second == given[i].second);
  const auto small = SN::filter_normals<CGAL::Sequential_tag>(
    given, CGAL::parameters::neighbor_radius(1.).point_map(Point_map()).normal_map(Normal_map()));
  CHECK(small.mean_neighbors == Approx(4. * 10 * 9 / 100.)); // grid neighbors at distance 1
}

TEST_CASE("filter: adaptive sizes with range 0 are the default filter", "[filter][adaptive]")
{
  // With r = 0 each point takes k_i, its k_i nearest neighbors are its ball in the same order,
  // and no point is degenerate on a noisy plane.
  Points points = noisy_plane(12, 0.2, 5);
  Points adaptive = points;
  SN::filter_normals<CGAL::Sequential_tag>(points, CGAL::parameters::number_of_iterations(5)
                                                     .point_map(Point_map()).normal_map(Normal_map()));
  const auto summary = SN::filter_normals<CGAL::Sequential_tag>(
    adaptive, SNP::adaptive_neighborhood_size(true, SNP::neighborhood_size_range(0u,
                CGAL::parameters::number_of_iterations(5).point_map(Point_map()).normal_map(Normal_map()))));
  for(std::size_t i = 0; i < points.size(); ++i)
    CHECK(points[i].second == adaptive[i].second);
  CHECK(summary.fallbacks == 0);
  CHECK(summary.mean_selected_size == Approx(summary.mean_neighbors));
}

TEST_CASE("filter: adaptive sizes choose the least E_dim and stay inside the range", "[filter][adaptive]")
{
  std::vector<Vector> truth;
  Points points = noisy_edge(0.1, 6, truth);
  Points adaptive = points;
  const auto summary = SN::filter_normals<CGAL::Sequential_tag>(
    adaptive, SNP::adaptive_neighborhood_size(true, CGAL::parameters::number_of_iterations(20)
                                                      .point_map(Point_map()).normal_map(Normal_map())));
  CHECK(summary.fallbacks == 0);
  CHECK(summary.mean_selected_size >= summary.mean_neighbors - 10.);
  CHECK(summary.mean_selected_size <= summary.mean_neighbors + 10.);
  double worst = 0.;
  for(std::size_t i = 0; i < adaptive.size(); ++i)
    worst = (std::max)(worst, angle(adaptive[i].second, truth[i]));
  CHECK(worst < 0.05);
}

TEST_CASE("filter: a degenerate point falls back to its default neighborhood with equal weights", "[filter][adaptive]")
{
  // Point 0 has normal +z, all its neighbors m at 60 degrees: no neighbor passes the cut-off 0.9
  // at any k, so it votes with all of them: n <- normalize((m.n) m + 3 n). The default filter
  // keeps it (empty cone).
  const Vector m(std::sin(pi / 3), 0, std::cos(pi / 3));
  Points points = {{Point(0, 0, 0), Vector(0, 0, 1)}};
  for(int i = -3; i <= 3; ++i)
    for(int j = -3; j <= 3; ++j)
      if(i != 0 || j != 0)
        points.emplace_back(Point(i, j, 0), m);
  Points fixed = points;
  const auto summary = SN::filter_normals<CGAL::Sequential_tag>(
    points, SNP::adaptive_neighborhood_size(true, CGAL::parameters::number_of_iterations(1)
                                                    .neighbor_radius(2.).point_map(Point_map()).normal_map(Normal_map())));
  CHECK(summary.fallbacks == 1);
  const Vector expected = (m * Vector(0, 0, 1)) * m + 3 * Vector(0, 0, 1);
  const Vector e = expected / std::sqrt(expected.squared_length());
  CHECK(points[0].second.x() == Approx(e.x()).epsilon(1e-12));
  CHECK(points[0].second.z() == Approx(e.z()).epsilon(1e-12));
  const auto summary_fixed = SN::filter_normals<CGAL::Sequential_tag>(
    fixed, CGAL::parameters::number_of_iterations(1).neighbor_radius(2.).point_map(Point_map()).normal_map(Normal_map()));
  CHECK(fixed[0].second == Vector(0, 0, 1));
  CHECK(summary_fixed.empty_cones == 1);
}

TEST_CASE("filter: bit-identical on 1 and 2 threads and sequentially", "[filter][parallel]")
{
  std::vector<Vector> truth;
  const Points points = noisy_edge(0.2, 7, truth);
  for(bool adaptive : {false, true})
  {
    auto run = [&](unsigned int threads, bool parallel) {
      Points copy = points;
      const auto np = SNP::number_of_threads(
        threads, SNP::adaptive_neighborhood_size(
                   adaptive, CGAL::parameters::number_of_iterations(8).point_map(Point_map()).normal_map(Normal_map())));
      if(parallel)
        SN::filter_normals<SN::Parallel_if_available_tag>(copy, np);
      else
        SN::filter_normals<CGAL::Sequential_tag>(copy, np);
      return normals_of(copy);
    };
    const auto one = run(1, true), two = run(2, true), sequential = run(1, false);
    CHECK(one == two);
    CHECK(one == sequential);
  }
}

TEST_CASE("filter: the mesh overload equals the point range on the mesh's vertices", "[filter][mesh]")
{
  Mesh mesh;
  SN::make_subdivided_cube(4, mesh);
  auto normals = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:normal", CGAL::NULL_VECTOR).first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  Points points;
  for(auto v : mesh.vertices())
    points.emplace_back(mesh.point(v), normals[v]);
  auto filtered = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:filtered", CGAL::NULL_VECTOR).first;
  const auto summary = SN::filter_normals<CGAL::Sequential_tag>(mesh, filtered, SNP::normal_cut_off(0.95));
  SN::filter_normals<CGAL::Sequential_tag>(points, SNP::normal_cut_off(0.95, maps()));
  CHECK(summary.mesh.points == mesh.number_of_vertices());
  std::size_t i = 0, equal = 0;
  for(auto v : mesh.vertices())
    equal += (filtered[v] == points[i++].second);
  CHECK(equal == mesh.number_of_vertices());
  // The vertex neighborhoods path: the mesh's 1-rings.
  std::vector<std::vector<std::size_t>> rings(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    for(auto u : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
      rings[std::size_t(v)].push_back(std::size_t(u));
  auto ring_filtered = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:ring", CGAL::NULL_VECTOR).first;
  const auto ring_summary = SN::filter_normals<CGAL::Sequential_tag>(
    mesh, ring_filtered, SNP::neighborhoods(rings, CGAL::parameters::vertex_normal_map(normals)));
  CHECK(ring_summary.radius == 0.);
  CHECK(ring_summary.mean_neighbors < 7.);
}

TEST_CASE("filter: bad inputs", "[filter][errors]")
{
  Points none;
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(none, maps()), Catch::Contains("no points"));
  Points few = noisy_plane(3, 0.1, 8); // 9 points: the 12-NN scale needs 13
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(few, maps()), Catch::Contains("at least 13 points"));
  CHECK_NOTHROW(SN::filter_normals<CGAL::Sequential_tag>(
    few, CGAL::parameters::neighbor_radius(1.5).point_map(Point_map()).normal_map(Normal_map())));
  Points zero = noisy_plane(5, 0.1, 9);
  zero[7].second = CGAL::NULL_VECTOR;
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(zero, maps()), Catch::Contains("point 7 has a zero normal"));
  Points nan = noisy_plane(5, 0.1, 9);
  nan[3].first = Point(std::nan(""), 0, 0);
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(nan, maps()), Catch::Contains("point 3 has a non-finite"));
  Points ok = noisy_plane(5, 0.1, 9);
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(ok, SNP::normal_cut_off(1.5, maps())),
                    Catch::Contains("cut-off must lie in [-1, 1]"));
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(ok, SNP::damping_factor(-1., maps())),
                    Catch::Contains("damping factor"));
  const std::vector<std::vector<int>> self = {{0}};
  Points one = {{Point(0, 0, 0), Vector(0, 0, 1)}};
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(one, SNP::neighborhoods(self, maps())),
                    Catch::Contains("contains the point itself"));
  const std::vector<std::vector<int>> out_of_range = {{1}};
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(one, SNP::neighborhoods(out_of_range, maps())),
                    Catch::Contains("out of range"));
  const std::vector<std::vector<int>> two_lists = {{}, {}};
  CHECK_THROWS_WITH(SN::filter_normals<CGAL::Sequential_tag>(one, SNP::neighborhoods(two_lists, maps())),
                    Catch::Contains("one list per point"));
}

TEST_CASE("utilities: the mean neighbor distance of a regular grid is its step", "[utilities]")
{
  // On a cubic grid every point has at least 3 neighbors at the step, on a square grid 2.
  std::vector<Point> cubic, square;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j)
    {
      square.emplace_back(0.25 * i, 0.25 * j, 1.);
      for(int k = 0; k < 6; ++k)
        cubic.emplace_back(0.5 * i, 0.5 * j, 0.5 * k);
    }
  CHECK(SN::compute_mean_neighbor_distance<CGAL::Sequential_tag>(cubic, 3) == Approx(0.5).epsilon(1e-15));
  CHECK(SN::compute_mean_neighbor_distance<CGAL::Sequential_tag>(square, 2) == Approx(0.25).epsilon(1e-15));
  // 4 neighbors at the step and 2 at sqrt(2) steps for the interior of a square grid.
  CHECK(SN::compute_mean_neighbor_distance<CGAL::Sequential_tag>(square, 6) > 0.25);
  // CGAL's average spacing counts the point itself: k / (k + 1) of ours on distinct points.
  std::mt19937_64 engine(10);
  std::uniform_real_distribution<double> u(0., 1.);
  std::vector<Point> random;
  for(int i = 0; i < 500; ++i)
    random.emplace_back(u(engine), u(engine), u(engine));
  const double ours = SN::compute_mean_neighbor_distance<SN::Parallel_if_available_tag>(random, 6);
  CHECK(ours == Approx(7. / 6. * CGAL::compute_average_spacing<CGAL::Sequential_tag>(random, 6)).epsilon(1e-12));
  CHECK_THROWS_WITH(SN::compute_mean_neighbor_distance<CGAL::Sequential_tag>(square, 36),
                    Catch::Contains("needs at least 37 points"));
}

TEST_CASE("utilities: noise along the normals is reproducible and has the requested sd", "[utilities]")
{
  Points base;
  for(int i = 0; i < 20000; ++i)
  {
    const double t = 0.001 * i;
    base.emplace_back(Point(std::cos(t), std::sin(t), t), Vector(std::cos(t), std::sin(t), 0.5) * 2.);
  }
  Points a = base, b = base, c = base;
  SN::add_normal_noise(a, 0.3, 42, maps());
  SN::add_normal_noise(b, 0.3, 42, maps());
  SN::add_normal_noise(c, 0.3, 43, maps());
  double sum = 0., sum2 = 0., tangential = 0.;
  std::size_t same = 0, same_c = 0;
  for(std::size_t i = 0; i < base.size(); ++i)
  {
    same += (a[i].first == b[i].first);
    same_c += (a[i].first == c[i].first);
    const Vector d = a[i].first - base[i].first;
    const Vector n = base[i].second / std::sqrt(base[i].second.squared_length());
    const double e = d * n;
    sum += e;
    sum2 += e * e;
    tangential = (std::max)(tangential, std::sqrt((d - e * n).squared_length()));
  }
  const double count = double(base.size());
  const double mean = sum / count, sd = std::sqrt(sum2 / count - mean * mean);
  CHECK(same == base.size());
  CHECK(same_c == 0);
  CHECK(std::abs(mean) < 0.01);
  CHECK(sd == Approx(0.3).epsilon(0.02));
  CHECK(tangential < 1e-12);
  Points zero = base;
  SN::add_normal_noise(zero, 0., 1, maps());
  CHECK(zero == base);
  zero[5].second = CGAL::NULL_VECTOR;
  CHECK_THROWS_WITH(SN::add_normal_noise(zero, 0.1, 1, maps()), Catch::Contains("point 5 has a zero"));
  CHECK_THROWS_WITH(SN::add_normal_noise(a, -1., 1, maps()), Catch::Contains("standard deviation"));
}

TEST_CASE("utilities: normal MSE", "[utilities]")
{
  const std::vector<Vector> n = {Vector(0, 0, 1), Vector(1, 0, 0), Vector(0, 1, 0)};
  const std::vector<Vector> opposite = {Vector(0, 0, -1), Vector(-1, 0, 0), Vector(0, -1, 0)};
  const std::vector<Vector> one_orthogonal = {Vector(0, 0, 1), Vector(1, 0, 0), Vector(1, 0, 0)};
  CHECK(SN::normal_mse(n, n) == 0.);
  CHECK(SN::normal_mse(n, opposite) == 4.);
  CHECK(SN::normal_mse(n, one_orthogonal) == Approx(2. / 3.));
  CHECK_THROWS_WITH(SN::normal_mse(n, std::vector<Vector>(2, Vector(0, 0, 1))), Catch::Contains("different sizes"));
  CHECK_THROWS_WITH(SN::normal_mse(std::vector<Vector>(), std::vector<Vector>()), Catch::Contains("no normals"));
}

TEST_CASE("subdivided cube and octahedron: counts, closed, outward", "[shapes]")
{
  for(unsigned int m : {1u, 3u, 18u})
  {
    Mesh cube;
    SN::make_subdivided_cube(m, cube);
    CHECK(cube.number_of_vertices() == 6 * m * m + 2);
    CHECK(cube.number_of_faces() == 12 * m * m);
    CHECK(CGAL::is_closed(cube));
    CHECK(CGAL::Polygon_mesh_processing::is_outward_oriented(cube));
  }
  for(unsigned int m : {1u, 5u, 64u})
  {
    Mesh octahedron;
    SN::make_subdivided_octahedron(m, octahedron);
    CHECK(octahedron.number_of_vertices() == 4 * m * m + 2);
    CHECK(octahedron.number_of_faces() == 8 * m * m);
    CHECK(CGAL::is_closed(octahedron));
    CHECK(CGAL::Polygon_mesh_processing::is_outward_oriented(octahedron));
  }
  Mesh empty;
  CHECK_THROWS(SN::make_subdivided_cube(0, empty));
}

namespace {

// Points on a wavy surface with a little noise: no two neighbors at one distance, so that CGAL's
// kd-tree and the package's find the same neighbors.
Points wavy_surface(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1., 1.);
  std::normal_distribution<double> noise(0., 0.002);
  Points points;
  for(int i = 0; i < n; ++i)
  {
    const double x = u(rng), y = u(rng);
    points.emplace_back(Point(x, y, 0.3 * std::sin(2 * x) * std::cos(y) + noise(rng)), Vector(0, 0, 0));
  }
  return points;
}

// The angle between the lines of two vectors, accurate near 0 (acos of a cosine near 1 is not).
double unoriented_angle(const Vector& n, const Vector& m)
{
  return std::atan2(std::sqrt(CGAL::cross_product(n, m).squared_length()), std::abs(n * m));
}

} // namespace

TEST_CASE("estimate_normals: a plane, exactly, with both methods", "[normals]")
{
  Points points = wavy_surface(400, 1);
  for(auto& p : points) // the plane z = 0.3 x - 0.2 y + 1
    p.first = Point(p.first.x(), p.first.y(), 0.3 * p.first.x() - 0.2 * p.first.y() + 1.);
  const Vector truth = Vector(-0.3, 0.2, 1.) / std::sqrt(1.13);
  for(SN::Normal_estimation_method method : {SN::Normal_estimation_method::PCA, SN::Normal_estimation_method::JET})
  {
    SN::estimate_normals<CGAL::Sequential_tag>(points, 12, SNP::normal_estimation_method(method, maps()));
    double worst = 0.;
    for(const auto& p : points)
    {
      worst = std::max(worst, unoriented_angle(p.second, truth));
      CHECK(p.second.squared_length() == Approx(1.).epsilon(1e-14));
    }
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("estimate_normals: CGAL's pca_estimate_normals and jet_estimate_normals, up to rounding", "[normals]")
{
  const Points points = wavy_surface(3000, 2);
  for(unsigned int k : {8u, 18u})
  {
    Points cgal_pca = points, cgal_jet = points, pca = points, jet = points;
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(cgal_pca, k, maps());
    CGAL::jet_estimate_normals<CGAL::Sequential_tag>(cgal_jet, k, maps());
    SN::estimate_normals<CGAL::Sequential_tag>(pca, k, maps()); // PCA: the default
    SN::estimate_normals<CGAL::Sequential_tag>(jet, k,
                                               SNP::normal_estimation_method(SN::Normal_estimation_method::JET, maps()));
    double worst_pca = 0., worst_jet = 0.;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      worst_pca = std::max(worst_pca, unoriented_angle(pca[i].second, cgal_pca[i].second));
      worst_jet = std::max(worst_jet, unoriented_angle(jet[i].second, cgal_jet[i].second));
    }
    CHECK(worst_pca < 1e-7);
    CHECK(worst_jet < 1e-7);
  }
}

TEST_CASE("estimate_normals: bit-identical on 1 and 2 threads, caller rows, bad input", "[normals][parallel]")
{
  const Points points = wavy_surface(2000, 3);
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(points, 14, indices, offsets, maps());
  for(SN::Normal_estimation_method method : {SN::Normal_estimation_method::PCA, SN::Normal_estimation_method::JET})
  {
    const auto np = SNP::normal_estimation_method(method, maps());
    Points sequential = points, one = points, two = points, copied_rows = points, rows_in_place = points;
    SN::estimate_normals<CGAL::Sequential_tag>(sequential, 10, np);
    SN::estimate_normals<SN::Parallel_if_available_tag>(one, 10, SNP::number_of_threads(1u, np));
    SN::estimate_normals<SN::Parallel_if_available_tag>(two, 10, SNP::number_of_threads(2u, np));
    // rows of 14, of which the first 10 are used: copied into the pack, or read in place (std::cref)
    SN::estimate_normals<CGAL::Sequential_tag>(copied_rows, 10, SNP::neighbor_indices(indices, SNP::neighbor_offsets(offsets, np)));
    SN::estimate_normals<CGAL::Sequential_tag>(
      rows_in_place, 10, SNP::neighbor_indices(std::cref(indices), SNP::neighbor_offsets(std::cref(offsets), np)));
    CHECK(normals_of(one) == normals_of(sequential));
    CHECK(normals_of(two) == normals_of(sequential));
    CHECK(normals_of(copied_rows) == normals_of(sequential));
    CHECK(normals_of(rows_in_place) == normals_of(sequential));
  }

  // too few points per fit for the jet, a line for PCA, fewer points than k, a NaN
  Points copy = points;
  CHECK_THROWS_WITH(SN::estimate_normals<CGAL::Sequential_tag>(
                      copy, 4, SNP::normal_estimation_method(SN::Normal_estimation_method::JET, maps())),
                    Catch::Contains("jet fitting of degree 2 needs at least 5 neighbors per point, got k = 4"));
  CHECK_THROWS_WITH(SN::estimate_normals<CGAL::Sequential_tag>(copy, 1, maps()),
                    Catch::Contains("pca needs at least 2 neighbors per point, got k = 1"));
  // a patch 1e-170 across, whose squared offsets underflow: scaled, PCA still finds its normal (on
  // the neighbors of the patch at scale 1, since the kd-tree's squared distances underflow too)
  Points tiny = points;
  for(auto& p : tiny)
    p.first = Point(p.first.x() * 1e-170, p.first.y() * 1e-170, p.first.z() * 1e-170);
  SN::estimate_normals<CGAL::Sequential_tag>(
    tiny, 10, SNP::neighbor_indices(std::cref(indices), SNP::neighbor_offsets(std::cref(offsets), maps())));
  Points reference = points;
  SN::estimate_normals<CGAL::Sequential_tag>(reference, 10, maps());
  double worst_tiny = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
    worst_tiny = std::max(worst_tiny, unoriented_angle(tiny[i].second, reference[i].second));
  CHECK(worst_tiny < 1e-6);
  Points stacked(12, Points::value_type(Point(1, 2, 3), Vector(0, 0, 0)));
  CHECK_THROWS_WITH(SN::estimate_normals<CGAL::Sequential_tag>(stacked, 6, maps()),
                    Catch::Contains("nearest points coincide: no normal (pca)"));
  Points line;
  for(int i = 0; i < 30; ++i)
    line.emplace_back(Point(i, 2 * i, 0), Vector(0, 0, 0));
  CHECK_THROWS_WITH(SN::estimate_normals<CGAL::Sequential_tag>(
                      line, 6, SNP::normal_estimation_method(SN::Normal_estimation_method::PCA, maps())),
                    Catch::Contains("lie on a line: no normal (pca)"));
  Points few(points.begin(), points.begin() + 4);
  CHECK_THROWS_WITH(SN::estimate_normals<CGAL::Sequential_tag>(few, 6, maps()),
                    Catch::Contains("needs at least k + 1 = 7 points, got 4"));
  copy[7].first = Point(std::nan(""), 0, 0);
  CHECK_THROWS_WITH(SN::estimate_normals<CGAL::Sequential_tag>(copy, 10, maps()),
                    Catch::Contains("point 7 has a non-finite coordinate"));
}

namespace {

// Two unit spheres, 10 apart (so that no k-NN edge joins them), the second lower; radial normals
// with random signs.
Points two_spheres(int n_each, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution flip(0.5);
  Points points;
  const double golden = CGAL_PI * (3. - std::sqrt(5.));
  for(const Vector center : {Vector(0, 0, 0), Vector(10, 0, -3)})
    for(int i = 0; i < n_each; ++i)
    {
      const double z = 1. - 2. * (i + 0.5) / n_each, r = std::sqrt(1. - z * z);
      const Vector radial(r * std::cos(golden * i), r * std::sin(golden * i), z);
      points.emplace_back(CGAL::ORIGIN + center + radial, flip(rng) ? -radial : radial);
    }
  return points;
}

bool points_inward(const Points& points, std::size_t i, int n_each)
{
  const Vector center = i < std::size_t(n_each) ? Vector(0, 0, 0) : Vector(10, 0, -3);
  return (points[i].first - (CGAL::ORIGIN + center)) * points[i].second < 0.;
}

// The number of normals pointing into their sphere.
std::size_t inward_normals(const Points& points, int n_each)
{
  std::size_t inward = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    inward += points_inward(points, i, n_each);
  return inward;
}

} // namespace

TEST_CASE("orient_normals_by_spanning_forest: every component seeded, as CGAL's MST on one", "[normals][orientation]")
{
  const int n_each = 1500;
  Points points = two_spheres(n_each, 4);
  Points forest = points;
  CHECK(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(forest, 10, maps()) == 2);
  CHECK(inward_normals(forest, n_each) == 0);

  // CGAL orients the component of the highest point only
  Points cgal = points;
  const auto unoriented = CGAL::mst_orient_normals(cgal, 10, maps());
  CHECK(std::size_t(std::distance(unoriented, cgal.end())) == std::size_t(n_each));
  for(auto it = cgal.begin(); it != unoriented; ++it)
  {
    const auto& same = *std::find_if(forest.begin(), forest.end(), [&](const auto& p) { return p.first == it->first; });
    CHECK(same.second == it->second);
  }

  // one and two threads, the caller's rows: the same normals, bit for bit
  Points two = points, rows = points;
  CHECK(SN::orient_normals_by_spanning_forest<SN::Parallel_if_available_tag>(two, 10, SNP::number_of_threads(2u, maps())) == 2);
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(points, 14, indices, offsets, maps());
  CHECK(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(
          rows, 10, SNP::neighbor_indices(std::cref(indices), SNP::neighbor_offsets(std::cref(offsets), maps()))) == 2);
  CHECK(normals_of(two) == normals_of(forest));
  CHECK(normals_of(rows) == normals_of(forest));

  // k = 1: the nearest-neighbor graph falls apart into many trees, each seeded
  Points pairs = points;
  CHECK(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(pairs, 1, maps()) > 2);

  Points bad = points;
  bad[3].second = Vector(0, 0, 0);
  CHECK_THROWS_WITH(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(bad, 10, maps()),
                    Catch::Contains("point 3 has a zero normal"));
  CHECK_THROWS_WITH(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(bad, 0, maps()),
                    Catch::Contains("k must be at least 1"));
  std::vector<std::size_t> short_offsets(points.size() + 1, 0);
  std::vector<std::uint32_t> no_indices;
  CHECK_THROWS_WITH(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(
                      pairs, 10, SNP::neighbor_indices(no_indices, SNP::neighbor_offsets(short_offsets, maps()))),
                    Catch::Contains("need at least 10 neighbors per point"));
}

TEST_CASE("orient_normals_by_spanning_forest after estimate_normals: a closed sphere outward", "[normals][orientation]")
{
  Points points = two_spheres(2000, 5);
  points.resize(2000);
  SN::estimate_normals<CGAL::Sequential_tag>(points, 12, maps());
  CHECK(SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(points, 12, maps()) == 1);
  CHECK(inward_normals(points, 2000) == 0);
}

namespace {

// The oriented normals that SPEC's spanning forest gives, written plainly: Kruskal's algorithm on the
// edges sorted by (weight, lower index, higher index), each tree walked from its highest point.
std::vector<Vector> kruskal_oriented_normals(const Points& points, unsigned int k)
{
  const std::size_t n = points.size();
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(points, k, indices, offsets, maps());
  std::vector<Eigen::Vector3d> normal(n);
  for(std::size_t i = 0; i < n; ++i)
    normal[i] = Eigen::Vector3d(points[i].second.x(), points[i].second.y(), points[i].second.z());
  std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> edges;
  for(std::uint32_t i = 0; i < n; ++i)
    for(std::size_t e = offsets[i]; e < offsets[i] + k; ++e)
    {
      const std::uint32_t j = indices[e];
      edges.emplace_back((std::max)(0., 1. - std::abs(normal[i].dot(normal[j]))), (std::min)(i, j), (std::max)(i, j));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<std::uint32_t> root(n);
  std::iota(root.begin(), root.end(), 0u);
  std::function<std::uint32_t(std::uint32_t)> find = [&](std::uint32_t v) { return root[v] == v ? v : root[v] = find(root[v]); };
  std::vector<std::vector<std::uint32_t>> tree(n);
  for(const auto& e : edges)
  {
    const std::uint32_t a = find(std::get<1>(e)), b = find(std::get<2>(e));
    if(a == b)
      continue;
    root[a] = b;
    tree[std::get<1>(e)].push_back(std::get<2>(e));
    tree[std::get<2>(e)].push_back(std::get<1>(e));
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return points[i].first.z() > points[j].first.z(); });
  std::vector<bool> done(n, false);
  for(std::uint32_t seed : order)
  {
    if(done[seed])
      continue;
    if(normal[seed].z() < 0.)
      normal[seed] = -normal[seed];
    done[seed] = true;
    std::vector<std::uint32_t> queue{seed};
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(std::uint32_t v : tree[queue[q]])
        if(!done[v])
        {
          done[v] = true;
          if(normal[v].dot(normal[queue[q]]) < 0.)
            normal[v] = -normal[v];
          queue.push_back(v);
        }
  }
  std::vector<Vector> result;
  for(const auto& v : normal)
    result.emplace_back(v.x(), v.y(), v.z());
  return result;
}

} // namespace

TEST_CASE("orient_normals_by_spanning_forest: the forest of the total order, on any number of threads", "[normals][orientation]")
{
  // a grid folded at x = 15 (distances and weights tied everywhere: weight 0 on each flat side, one
  // weight across the fold), a few tilted normals, signs at random, and a second sheet apart
  std::mt19937_64 rng(11);
  std::bernoulli_distribution flip(0.5), tilt(0.1);
  std::uniform_real_distribution<double> small(-0.2, 0.2);
  Points points;
  for(int sheet = 0; sheet < 2; ++sheet)
    for(int x = 0; x < 30; ++x)
      for(int y = 0; y < 25; ++y)
      {
        const double z = x > 15 ? double(x - 15) : 0.;
        Eigen::Vector3d n = x > 15 ? Eigen::Vector3d(-1., 0., 1.).normalized() : Eigen::Vector3d(0., 0., 1.);
        if(tilt(rng))
          n = (n + Eigen::Vector3d(small(rng), small(rng), small(rng))).normalized();
        if(flip(rng))
          n = -n;
        points.emplace_back(Point(x, y + 100. * sheet, z), Vector(n.x(), n.y(), n.z()));
      }
  const std::vector<Vector> expected = kruskal_oriented_normals(points, 8);
  for(unsigned int threads : {1u, 2u, 3u})
  {
    Points oriented = points;
    CHECK(SN::orient_normals_by_spanning_forest<SN::Parallel_if_available_tag>(
            oriented, 8, SNP::number_of_threads(threads, maps())) == 2);
    CHECK(normals_of(oriented) == expected);
  }
  // the flat parts face +z, the fold's side faces its tilt
  Points oriented = points;
  SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(oriented, 8, maps());
  CHECK(oriented[0].second.z() > 0.);
  CHECK(oriented[29 * 25].second.z() > 0.);
}

TEST_CASE("orient_normals_by_spanning_forest: past 2^15 points the reversed rows in blocks, the same forest",
          "[normals][orientation]")
{
  // two wavy sheets of 130 x 130 points, signs at random: the reversed rows are built in one block
  // per thread (at most 8) above 2^15 points
  std::mt19937_64 rng(5);
  std::bernoulli_distribution flip(0.5);
  Points points;
  for(int sheet = 0; sheet < 2; ++sheet)
    for(int x = 0; x < 130; ++x)
      for(int y = 0; y < 130; ++y)
      {
        const double z = 3. * std::sin(0.1 * x) * std::cos(0.07 * y);
        Eigen::Vector3d n(-0.3 * std::cos(0.1 * x) * std::cos(0.07 * y), 0.21 * std::sin(0.1 * x) * std::sin(0.07 * y), 1.);
        n.normalize();
        if(flip(rng))
          n = -n;
        points.emplace_back(Point(x, y + 1000. * sheet, z), Vector(n.x(), n.y(), n.z()));
      }
  REQUIRE(points.size() > (std::size_t(1) << 15));
  const std::vector<Vector> expected = kruskal_oriented_normals(points, 8);
  for(unsigned int threads : {1u, 2u, 3u, 9u})
  {
    Points oriented = points;
    CHECK(SN::orient_normals_by_spanning_forest<SN::Parallel_if_available_tag>(
            oriented, 8, SNP::number_of_threads(threads, maps())) == 2);
    CHECK(normals_of(oriented) == expected);
  }
}

TEST_CASE("orient_normals_towards_viewpoint: every normal faces the scanner", "[normals][orientation]")
{
  Points points = wavy_surface(500, 6);
  SN::estimate_normals<CGAL::Sequential_tag>(points, 10, maps());
  const Point scanner(0.2, -0.1, -4.);
  SN::orient_normals_towards_viewpoint(points, scanner, maps());
  for(const auto& p : points)
    CHECK((scanner - p.first) * p.second > 0.);
  CHECK_THROWS_WITH(SN::orient_normals_towards_viewpoint(points, Point(std::nan(""), 0, 0), maps()),
                    Catch::Contains("the viewpoint has a non-finite coordinate"));
}

TEST_CASE("line_angles: the search and the filter blind to the normals' signs", "[normals][line_angles]")
{
  const int n_each = 600;
  const Points flipped = two_spheres(n_each, 7);
  Points outward = flipped;
  for(std::size_t i = 0; i < outward.size(); ++i)
    if(points_inward(outward, i, n_each))
      outward[i].second = -outward[i].second;
  REQUIRE(inward_normals(outward, n_each) == 0);

  auto search = [](const Points& points, bool line_angles) {
    std::vector<SN::Optimal_sigmoid_neighborhood> records;
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(records),
                                                                     SNP::line_angles(line_angles, maps()));
    return records;
  };
  const auto lines_flipped = search(flipped, true), lines_outward = search(outward, true);
  const auto oriented_outward = search(outward, false), oriented_flipped = search(flipped, false);
  std::size_t differ_oriented = 0;
  for(std::size_t i = 0; i < flipped.size(); ++i)
  {
    // the same angles, so the same records, bit for bit; and on a sphere with outward normals every
    // angle is below pi/2, so the oriented angle gives them too
    CHECK(lines_flipped[i].a == lines_outward[i].a);
    CHECK(lines_flipped[i].b == lines_outward[i].b);
    CHECK(lines_flipped[i].k == lines_outward[i].k);
    CHECK(lines_flipped[i].error() == lines_outward[i].error());
    CHECK(lines_outward[i].error() == oriented_outward[i].error());
    differ_oriented += oriented_flipped[i].error() != oriented_outward[i].error();
  }
  CHECK(differ_oriented > flipped.size() / 2); // without the option, flips change the result

  // the filter: flipping an input normal flips its filtered normal, nothing else
  Points filtered_flipped = flipped, filtered_outward = outward;
  SN::filter_normals<CGAL::Sequential_tag>(filtered_flipped, SNP::line_angles(true, maps()));
  SN::filter_normals<CGAL::Sequential_tag>(filtered_outward, SNP::line_angles(true, maps()));
  for(std::size_t i = 0; i < flipped.size(); ++i)
  {
    const bool was_flipped = flipped[i].second != outward[i].second;
    CHECK(filtered_flipped[i].second == (was_flipped ? -filtered_outward[i].second : filtered_outward[i].second));
  }
}

namespace {

typedef CGAL::Point_set_3<Point, Vector> Point_set;

Point_set point_set_of(const Points& points, bool with_normals)
{
  Point_set ps(with_normals);
  for(const auto& p : points)
    if(with_normals)
      ps.insert(p.first, p.second);
    else
      ps.insert(p.first);
  return ps;
}

template <typename T>
std::vector<T> property_values(const Point_set& ps, const std::string& name)
{
  const auto map = ps.property_map<T>(name);
  REQUIRE(map.second);
  std::vector<T> values;
  for(const auto index : ps)
    values.push_back(map.first[index]);
  return values;
}

// Equal, NaN equal to NaN.
bool same_values(const std::vector<double>& x, const std::vector<double>& y)
{
  if(x.size() != y.size())
    return false;
  for(std::size_t i = 0; i < x.size(); ++i)
    if(!(x[i] == y[i] || (std::isnan(x[i]) && std::isnan(y[i]))))
      return false;
  return true;
}

} // namespace

TEST_CASE("Point_set_3: the search, the features and the filter write its properties", "[point_set]")
{
  Points points = two_spheres(400, 8);
  for(std::size_t i = 0; i < points.size(); ++i) // outward normals, a few flipped: some failures
    if(points_inward(points, i, 400) != (i % 97 == 0))
      points[i].second = -points[i].second;
  Point_set ps = point_set_of(points, true);

  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(records), maps());
  const std::size_t failures = SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(ps);
  std::size_t expected_failures = 0;
  std::vector<double> a, error, linearity;
  std::vector<int> k;
  for(const auto& r : records)
  {
    expected_failures += r.is_failure();
    a.push_back(r.a);
    error.push_back(r.error());
    linearity.push_back(r.is_failure() ? std::nan("") : r.features.linearity);
    k.push_back(int(r.k));
  }
  CHECK(failures == expected_failures);
  CHECK(same_values(property_values<double>(ps, "scalar_a"), a));
  CHECK(same_values(property_values<double>(ps, "scalar_error"), error));
  CHECK(same_values(property_values<double>(ps, "scalar_linearity"), linearity));
  CHECK(property_values<int>(ps, "scalar_k") == k);

  // a binary PLY of the point set: CGAL reads every property back by its name
  std::stringstream ply;
  CGAL::IO::set_binary_mode(ply);
  REQUIRE(CGAL::IO::write_PLY(ply, ps));
  Point_set back;
  REQUIRE(CGAL::IO::read_PLY(ply, back));
  CHECK(same_values(property_values<double>(back, "scalar_error"), error));
  CHECK(property_values<int>(back, "scalar_k") == k);
  CHECK(property_values<std::uint8_t>(back, "scalar_label") == property_values<std::uint8_t>(ps, "scalar_label"));

  // the features of one sigmoid replace the search's
  std::vector<SN::Dimensionality_features> features;
  const SN::Cosine_sigmoid sigmoid(0., CGAL_PI / 3.);
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(points, sigmoid, 12, std::back_inserter(features), maps());
  SN::compute_sigmoid_features<CGAL::Sequential_tag>(ps, sigmoid, 12);
  std::vector<double> feature_error;
  for(const auto& f : features)
    feature_error.push_back(f.error);
  CHECK(same_values(property_values<double>(ps, "scalar_error"), feature_error));

  // the filter, in place
  Points filtered = points;
  SN::filter_normals<CGAL::Sequential_tag>(
    filtered, CGAL::parameters::number_of_iterations(3).point_map(Point_map()).normal_map(Normal_map()));
  SN::filter_normals<CGAL::Sequential_tag>(ps, CGAL::parameters::number_of_iterations(3));
  std::vector<Vector> ps_normals;
  for(const auto index : ps)
    ps_normals.push_back(ps.normal(index));
  CHECK(ps_normals == normals_of(filtered));

  // no normals; a property of the same name and another type
  Point_set bare = point_set_of(points, false);
  CHECK_THROWS_WITH(SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(bare),
                    Catch::Contains("the point set has no normal map"));
  Point_set other = point_set_of(points, true);
  other.add_property_map<float>("scalar_b", 0.f);
  CHECK_THROWS_WITH(SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(other),
                    Catch::Contains("the point set has a property scalar_b of another type"));
}

TEST_CASE("Point_set_3: normals estimated and oriented on one neighbor structure", "[point_set][normals]")
{
  const int n_each = 800;
  const Points points = two_spheres(n_each, 9);
  Point_set ps = point_set_of(points, false);
  CHECK(SN::estimate_and_orient_normals<CGAL::Sequential_tag>(ps, 12) == 2);
  REQUIRE(ps.has_normal_map());
  Points estimated;
  for(const auto index : ps)
    estimated.emplace_back(ps.point(index), ps.normal(index));
  CHECK(inward_normals(estimated, n_each) == 0);
  // as the range functions give them
  Points range = points;
  SN::estimate_normals<CGAL::Sequential_tag>(range, 12, maps());
  SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(range, 12, maps());
  CHECK(normals_of(estimated) == normals_of(range));
}
