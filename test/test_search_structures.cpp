// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's spatial searching under the package: the caller's CGAL::Kd_tree taken with the named
// parameter `search_tree`, and the free functions on other kernels and on Point_set_3, all against
// the rows and records of the call's own search on the same coordinates.

#include <CGAL/Sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

// A folded sheet on a grid of 1/64 steps, with a duplicated point and ties at every grid distance:
// coordinates and normals exactly representable in float, so that every kernel holds the same values.
struct Sample
{
  double x, y, z, nx, ny, nz;
};

std::vector<Sample> folded_grid()
{
  std::vector<Sample> result;
  for(int i = 0; i < 24; ++i)
    for(int j = 0; j < 24; ++j)
    {
      const double x = i / 64., y = j / 64.;
      const double z = x < 0.25 ? 0. : (x - 0.25);
      // normals of length sqrt(2) on the slope, exact in float too (the package makes them unit)
      result.push_back(x < 0.25 ? Sample{x, y, z, 0., 0., 1.} : Sample{x, y, z, -1., 0., 1.});
    }
  result.push_back(result[37]); // a duplicate: a tie at distance 0
  return result;
}

template <typename K>
std::vector<std::pair<typename K::Point_3, typename K::Vector_3>> points_in(const std::vector<Sample>& samples)
{
  std::vector<std::pair<typename K::Point_3, typename K::Vector_3>> result;
  for(const Sample& s : samples)
    result.emplace_back(typename K::Point_3(s.x, s.y, s.z), typename K::Vector_3(s.nx, s.ny, s.nz));
  return result;
}

template <typename K>
std::vector<SN::Optimal_sigmoid_neighborhood> optimal_records(const std::vector<Sample>& samples)
{
  typedef std::pair<typename K::Point_3, typename K::Vector_3> Pair;
  const auto points = points_in<K>(samples);
  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    points, std::back_inserter(records),
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pair>())
      .normal_map(CGAL::Second_of_pair_property_map<Pair>()));
  return records;
}

bool same_records(const std::vector<SN::Optimal_sigmoid_neighborhood>& x,
                  const std::vector<SN::Optimal_sigmoid_neighborhood>& y)
{
  if(x.size() != y.size())
    return false;
  for(std::size_t i = 0; i < x.size(); ++i)
    if(std::memcmp(&x[i].a, &y[i].a, sizeof(double)) != 0 || std::memcmp(&x[i].b, &y[i].b, sizeof(double)) != 0 ||
       x[i].k != y[i].k || x[i].k_equal != y[i].k_equal || x[i].error() != y[i].error() ||
       x[i].error_equal != y[i].error_equal || x[i].features.eigenvalues != y[i].features.eigenvalues)
      return false;
  return true;
}

// The position of point i of a vector: the point map of a tree over indices.
template <typename Point>
struct Index_map
{
  typedef std::size_t key_type;
  typedef Point value_type;
  typedef const Point& reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<std::pair<Point, typename CGAL::Kernel_traits<Point>::Kernel::Vector_3>>* points;
  friend reference get(const Index_map& map, std::size_t i) { return (*map.points)[i].first; }
};

} // namespace

TEST_CASE("search_tree: the caller's CGAL kd-tree gives the call's own rows and records", "[neighbors][search-tree]")
{
  typedef std::pair<Epick::Point_3, Epick::Vector_3> Pair;
  typedef Index_map<Epick::Point_3> Map;
  typedef CGAL::Search_traits_adapter<std::size_t, Map, CGAL::Search_traits_3<Epick>> Traits;
  typedef CGAL::Kd_tree<Traits> Tree; // CGAL's defaults: sliding midpoint, buckets of 10, no cache

  const std::vector<Sample> samples = folded_grid();
  const auto points = points_in<Epick>(samples);
  const Map map{&points};
  const Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(points.size()),
                  Tree::Splitter(), Traits(map));
  const auto maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pair>())
                      .normal_map(CGAL::Second_of_pair_property_map<Pair>());

  // rows with ties at every grid distance, 1 to 128 neighbors, on 1 and 2 threads
  for(unsigned int k : {1u, 4u, 8u, 9u, 20u, 64u, 128u})
    for(unsigned int threads : {1u, 2u})
    {
      CAPTURE(k, threads);
      std::vector<std::uint32_t> own_indices, given_indices;
      std::vector<std::size_t> own_offsets, given_offsets;
      SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(points, k, own_indices, own_offsets,
                                                                     SNP::number_of_threads(threads, maps));
      SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(
        points, k, given_indices, given_offsets, SNP::search_tree(tree, SNP::number_of_threads(threads, maps)));
      CHECK(own_offsets == given_offsets);
      CHECK(own_indices == given_indices);
    }

  std::vector<SN::Optimal_sigmoid_neighborhood> own, given;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(own), maps);
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(given),
                                                                  SNP::search_tree(tree, maps));
  REQUIRE(own.size() == points.size());
  CHECK(same_records(own, given));

  // a tree over other points is refused with a message
  std::vector<Pair> fewer(points.begin(), points.end() - 1);
  std::vector<SN::Optimal_sigmoid_neighborhood> none;
  CHECK_THROWS_AS(SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
                    fewer, std::back_inserter(none), SNP::search_tree(tree, maps)),
                  std::invalid_argument);
}

TEST_CASE("search_tree: a Point_set_3's own CGAL kd-tree over its indices", "[neighbors][search-tree][point-set]")
{
  typedef CGAL::Point_set_3<Epick::Point_3, Epick::Vector_3> Point_set;
  typedef CGAL::Search_traits_adapter<Point_set::Index, Point_set::Point_map, CGAL::Search_traits_3<Epick>> Traits;
  typedef CGAL::Kd_tree<Traits, CGAL::Sliding_midpoint<Traits>, CGAL::Tag_true, CGAL::Tag_true> Tree;

  Point_set points(true);
  for(const Sample& s : folded_grid())
    points.insert(Epick::Point_3(s.x, s.y, s.z), Epick::Vector_3(s.nx, s.ny, s.nz));
  const Tree tree(points.begin(), points.end(), CGAL::Sliding_midpoint<Traits>(4), Traits(points.point_map()));

  std::vector<SN::Optimal_sigmoid_neighborhood> own, given;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(own));
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(given),
                                                                  SNP::search_tree(tree));
  REQUIRE(own.size() == points.size());
  CHECK(same_records(own, given));
}

TEST_CASE("any kernel: the same records on the same coordinates", "[kernels]")
{
  const std::vector<Sample> samples = folded_grid();
  const auto reference = optimal_records<CGAL::Simple_cartesian<double>>(samples);
  REQUIRE(reference.size() == samples.size());
  std::size_t successes = 0;
  for(const auto& r : reference)
    successes += r.is_failure() ? 0 : 1;
  CHECK(successes > samples.size() / 2);

  CHECK(same_records(reference, optimal_records<Epick>(samples)));
  // computed in double from the exact kernel's and the float kernel's coordinates (the same values)
  CHECK(same_records(reference, optimal_records<CGAL::Exact_predicates_exact_constructions_kernel>(samples)));
  CHECK(same_records(reference, optimal_records<CGAL::Simple_cartesian<float>>(samples)));

  CGAL::Point_set_3<Epick::Point_3, Epick::Vector_3> point_set(true);
  for(const Sample& s : samples)
    point_set.insert(Epick::Point_3(s.x, s.y, s.z), Epick::Vector_3(s.nx, s.ny, s.nz));
  std::vector<SN::Optimal_sigmoid_neighborhood> from_point_set;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(point_set, std::back_inserter(from_point_set));
  CHECK(same_records(reference, from_point_set));
}

TEST_CASE("neighbor_search: the package's kd-tree gives CGAL's rows, balls and nearest positions, bit for bit",
          "[neighbors][search-tree]")
{
  typedef std::pair<Epick::Point_3, Epick::Vector_3> Pair;
  // a grid (ties at every distance), random points and duplicates, shuffled
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0., 4.);
  std::vector<Pair> points;
  for(int x = 0; x < 10; ++x)
    for(int y = 0; y < 10; ++y)
      for(int z = 0; z < 3; ++z)
        points.emplace_back(Epick::Point_3(x, y, z), Epick::Vector_3(0., 0., 1.));
  for(int i = 0; i < 400; ++i)
    points.emplace_back(Epick::Point_3(unit(rng), unit(rng), unit(rng) / 8.), Epick::Vector_3(0., 0., 1.));
  for(int d = 0; d < 40; ++d)
    points.push_back(points[std::size_t(29 * d) % points.size()]);
  std::shuffle(points.begin(), points.end(), rng);
  const auto maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pair>());

  for(unsigned int k : {1u, 2u, 7u, 32u, 33u, 100u, 128u})
    for(unsigned int threads : {1u, 2u})
    {
      CAPTURE(k, threads);
      std::vector<std::uint32_t> cgal_indices, package_indices;
      std::vector<std::size_t> cgal_offsets, package_offsets;
      SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(
        points, k, cgal_indices, cgal_offsets,
        SNP::neighbor_search(SN::Neighbor_search::CGAL_KD_TREE, SNP::number_of_threads(threads, maps)));
      SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(
        points, k, package_indices, package_offsets,
        SNP::neighbor_search(SN::Neighbor_search::PACKAGE_KD_TREE, SNP::number_of_threads(threads, maps)));
      CHECK(cgal_offsets == package_offsets);
      CHECK(cgal_indices == package_indices);
    }

  std::vector<SN::internal::Double_point> copy;
  for(const Pair& p : points)
    copy.emplace_back(p.first.x(), p.first.y(), p.first.z());
  const SN::internal::Neighbor_query cgal(copy, 1, SN::Neighbor_search::CGAL_KD_TREE);
  const SN::internal::Neighbor_query package(copy, 2, SN::Neighbor_search::PACKAGE_KD_TREE);
  auto same = [](const std::vector<SN::internal::Neighbor>& x, const std::vector<SN::internal::Neighbor>& y) {
    if(x.size() != y.size())
      return false;
    for(std::size_t e = 0; e < x.size(); ++e)
      if(x[e].index != y[e].index || x[e].squared_distance != y[e].squared_distance)
        return false;
    return true;
  };
  std::vector<SN::internal::Neighbor> from_cgal, from_package;
  std::size_t mismatches = 0, balls = 0;
  for(std::uint32_t i = 0; i < copy.size(); i += 3)
  {
    for(double radius : {0., 1., 1.5}) // 1: the grid's neighbors on the sphere
    {
      cgal.query_ball(i, radius, from_cgal);
      package.query_ball(i, radius, from_package);
      mismatches += same(from_cgal, from_package) ? 0 : 1;
      balls += from_cgal.size();
    }
    // a position between points: ties between the two sides
    const SN::internal::Double_point q(std::floor(copy[i].x()) + 0.5, std::floor(copy[i].y()), copy[i].z());
    for(unsigned int k : {1u, 9u, 64u})
    {
      cgal.query_position(q, k, from_cgal);
      package.query_position(q, k, from_package);
      mismatches += same(from_cgal, from_package) && from_cgal.size() == k ? 0 : 1;
    }
  }
  CHECK(mismatches == 0);
  CHECK(balls > copy.size());
}
