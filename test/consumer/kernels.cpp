// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The kernels on one point set, every number printed to the last bit: built once header-only and once
// against the installed CGAL::Sigmoid_neighborhoods_core, the two outputs must be the same bytes.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iterator>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef std::pair<Kernel::Point_3, Kernel::Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
namespace SN = CGAL::Sigmoid_neighborhoods;

int main()
{
  // a cube corner of 3 x 200 points, slightly perturbed: planes, creases and a corner
  std::vector<Point_with_normal> points;
  for(int face = 0; face < 3; ++face)
    for(int i = 0; i < 200; ++i)
    {
      const double u = (i % 20) / 20. + 0.013 * std::sin(7. * i), v = (i / 20) / 10. + 0.011 * std::cos(5. * i);
      const double w = 0.002 * std::sin(3. * i + face);
      const double c[3] = {face == 0 ? w : u, face == 1 ? w : (face == 0 ? u : v), face == 2 ? w : v};
      points.emplace_back(Kernel::Point_3(c[0], c[1], c[2]), Kernel::Vector_3(0., 0., 0.));
    }
  const auto maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());

  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(points, 20, indices, offsets, maps);
  const auto rows =
    SN::parameters::neighbor_indices(std::cref(indices), SN::parameters::neighbor_offsets(std::cref(offsets), maps));
  SN::estimate_normals<SN::Parallel_if_available_tag>(points, 12, rows);
  SN::orient_normals_by_spanning_forest<SN::Parallel_if_available_tag>(points, 12, rows);
  std::vector<SN::Optimal_sigmoid_neighborhood> optimal;
  SN::compute_optimal_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(
    points, std::back_inserter(optimal), SN::parameters::k_min(6, SN::parameters::k_max(20, rows)));

  for(std::size_t i = 0; i < points.size(); ++i)
  {
    std::printf("%zu", i);
    for(std::size_t e = offsets[i]; e < offsets[i + 1]; ++e)
      std::printf(" %u", unsigned(indices[e]));
    const Kernel::Vector_3& n = points[i].second;
    std::printf(" | %a %a %a | %a %a %u %a\n", n.x(), n.y(), n.z(), optimal[i].a, optimal[i].b, unsigned(optimal[i].k),
                optimal[i].error());
  }
  return 0;
}
