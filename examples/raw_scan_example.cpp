// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A scan without normals: the k nearest neighbors computed once, normals estimated and oriented on
// them, then the optimal sigmoid neighborhoods searched on the same rows.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef std::pair<Kernel::Point_3, Kernel::Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = SN::parameters;

int main(int argc, char** argv)
{
  std::vector<Point_with_normal> points;
  if(argc > 1) // a file of "x y z" lines
  {
    if(!CGAL::IO::read_points(argv[1], std::back_inserter(points), CGAL::parameters::point_map(Point_map())))
    {
      std::cerr << "cannot read " << argv[1] << std::endl;
      return EXIT_FAILURE;
    }
  }
  else // two noisy unit spheres apart: two components, no normals
  {
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0., 0.003);
    for(double shift : {0., 5.})
      for(int i = 0; i < 2000; ++i)
      {
        const double z = 1. - (2. * i + 1.) / 2000., r = std::sqrt(1. - z * z), phi = 2.399963 * i;
        points.emplace_back(Kernel::Point_3(shift + r * std::cos(phi) + noise(rng), r * std::sin(phi) + noise(rng),
                                            z + noise(rng)),
                            CGAL::NULL_VECTOR);
      }
  }

  // One neighbor structure: 20 nearest neighbors, enough for the normals (18) and the search (k_max 20).
  // Passed with std::cref: CGAL's named parameters would copy the rows otherwise.
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  const auto maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(points, 20, indices, offsets, maps);
  const auto rows = SNP::neighbor_indices(std::cref(indices), SNP::neighbor_offsets(std::cref(offsets), maps));

  SN::estimate_normals<SN::Parallel_if_available_tag>(points, 18, rows); // PCA, unoriented
  const std::size_t trees = SN::orient_normals_by_spanning_forest<SN::Parallel_if_available_tag>(points, 18, rows);

  std::vector<SN::Optimal_sigmoid_neighborhood> optimal;
  SN::compute_optimal_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(points, std::back_inserter(optimal), rows);

  const auto failures = std::count_if(optimal.begin(), optimal.end(), [](const auto& r) { return r.is_failure(); });
  std::cout << points.size() << " points, normals oriented in " << trees << " trees, " << failures << " failures"
            << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
