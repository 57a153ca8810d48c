// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optimal sigmoid weights and neighborhood size of every point of a point set with normals.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <cstdlib>
#include <iostream>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef std::pair<Kernel::Point_3, Kernel::Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
namespace SN = CGAL::Sigmoid_neighborhoods;

int main(int argc, char** argv)
{
  std::vector<Point_with_normal> points;
  if(argc > 1) // a file of "x y z nx ny nz" lines
  {
    if(!CGAL::IO::read_points(argv[1], std::back_inserter(points),
                              CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())))
    {
      std::cerr << "cannot read " << argv[1] << std::endl;
      return EXIT_FAILURE;
    }
  }
  else // a unit sphere, normals pointing out
    for(int i = 0; i < 2000; ++i)
    {
      const double z = 1. - (2. * i + 1.) / 2000., r = std::sqrt(1. - z * z), phi = 2.399963 * i;
      const Kernel::Point_3 p(r * std::cos(phi), r * std::sin(phi), z);
      points.emplace_back(p, p - CGAL::ORIGIN);
    }

  std::vector<SN::Optimal_sigmoid_neighborhood> optimal;
  SN::compute_optimal_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(
    points, std::back_inserter(optimal),
    SN::parameters::k_min(6, SN::parameters::k_max(20)).point_map(Point_map()).normal_map(Normal_map()));

  double sum_optimal = 0., sum_equal = 0.;
  std::size_t failures = 0;
  for(const SN::Optimal_sigmoid_neighborhood& r : optimal)
  {
    if(r.is_failure())
    {
      ++failures;
      continue;
    }
    sum_optimal += r.error();
    sum_equal += r.error_equal;
  }
  const double n = double(optimal.size() - failures);
  std::cout << optimal.size() << " points, " << failures << " failures\n"
            << "mean E_dim with equal weights:   " << sum_equal / n << "\n"
            << "mean E_dim with optimal (a,b,k): " << sum_optimal / n << std::endl;
  return sum_optimal <= sum_equal ? EXIT_SUCCESS : EXIT_FAILURE;
}
