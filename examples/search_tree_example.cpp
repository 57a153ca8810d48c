// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One CGAL kd-tree for a whole pipeline: the tree a CGAL program already holds over a Point_set_3
// (its own k-nearest-neighbor queries) is handed to the package with the named parameter
// `search_tree`, so that no call builds another; the results are those of the calls' own trees.

#include <CGAL/Sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3.h>
#include <CGAL/Sigmoid_neighborhoods/search_tree.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Random.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Point_set_3<Point_3, Vector_3> Point_set;

// CGAL's search over the point set's indices, as Point_set_processing_3 builds it
typedef CGAL::Search_traits_adapter<Point_set::Index, Point_set::Point_map, CGAL::Search_traits_3<Kernel>> Traits;
typedef CGAL::Kd_tree<Traits> Tree;
typedef CGAL::Orthogonal_k_neighbor_search<Traits> Neighbor_search;

namespace SN = CGAL::Sigmoid_neighborhoods;

int main()
{
  // a unit sphere with radial normals
  CGAL::Random random(7);
  Point_set points(true);
  for(int i = 0; i < 3000; ++i)
  {
    const Vector_3 v(random.get_double(-1., 1.), random.get_double(-1., 1.), random.get_double(-1., 1.));
    const double length = std::sqrt(v.squared_length());
    if(length < 1e-3)
      continue;
    points.insert(CGAL::ORIGIN + v / length, v / length);
  }

  const Tree tree(points.begin(), points.end(), Tree::Splitter(), Traits(points.point_map()));

  // the program's own use of the tree: the nearest point to the north pole
  const Neighbor_search nearest(tree, Point_3(0., 0., 1.), 1, 0., true,
                                Neighbor_search::Distance(points.point_map()));
  std::cout << "nearest to the north pole: point " << std::size_t(nearest.begin()->first) << "\n";

  // the package's calls on the same tree
  std::vector<std::uint32_t> indices, own_indices;
  std::vector<std::size_t> offsets, own_offsets;
  SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(
    points, 12, indices, offsets, SN::parameters::search_tree(tree).point_map(points.point_map()));
  SN::compute_k_nearest_neighbors<CGAL::Sequential_tag>(points, 12, own_indices, own_offsets,
                                                        CGAL::parameters::point_map(points.point_map()));

  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(records),
                                                                  SN::parameters::search_tree(tree));
  std::size_t failures = 0;
  for(const SN::Optimal_sigmoid_neighborhood& r : records)
    failures += r.is_failure() ? 1 : 0;

  std::cout << points.size() << " points, one tree for every step; rows of 12 neighbors "
            << (indices == own_indices && offsets == own_offsets ? "equal" : "DIFFERENT")
            << " to a call's own tree; optimal search: " << records.size() << " records, " << failures
            << " failures\n";
  return indices == own_indices && offsets == own_offsets ? 0 : 1;
}
