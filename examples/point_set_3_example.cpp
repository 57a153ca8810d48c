// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A scan in a CGAL::Point_set_3: read with CGAL::IO::read_point_set(), normals estimated and
// oriented when it has none, the optimal sigmoid neighborhoods written to its properties, and a
// binary PLY that CloudCompare opens with every field (scalar_a, scalar_b, scalar_k, scalar_error ...).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;
namespace SN = CGAL::Sigmoid_neighborhoods;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: point_set_3_example SCAN [OUT.ply]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string output = argc > 2 ? argv[2] : "optimal.ply";
  Point_set points;
  if(!CGAL::IO::read_point_set(argv[1], points) || points.empty())
  {
    std::cerr << "cannot read " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }
  if(!points.has_normal_map())
  {
    const std::size_t trees = SN::estimate_and_orient_normals<SN::Parallel_if_available_tag>(points, 18);
    std::cout << "normals estimated and oriented in " << trees << " trees" << std::endl;
  }

  const std::size_t failures = SN::compute_optimal_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(points);

  std::ofstream out(output, std::ios::binary);
  CGAL::IO::set_binary_mode(out);
  if(!CGAL::IO::write_PLY(out, points))
  {
    std::cerr << "cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points, " << failures << " failures, written to " << output << std::endl;
  return EXIT_SUCCESS;
}
