// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Must not compile: CGAL::Parallel_tag in a build without OpenMP and without TBB (CGAL's contract).
// With SN_SEQUENTIAL defined (the control), it must.

#include <CGAL/Sigmoid_neighborhoods.h>

#include <CGAL/Simple_cartesian.h>

#include <iterator>
#include <utility>
#include <vector>

int main()
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::pair<K::Point_3, K::Vector_3> Point_with_normal;
  std::vector<Point_with_normal> points;
  std::vector<CGAL::Sigmoid_neighborhoods::Optimal_sigmoid_neighborhood> out;
#ifdef SN_SEQUENTIAL
  typedef CGAL::Sequential_tag Tag;
#else
  typedef CGAL::Parallel_tag Tag;
#endif
  CGAL::Sigmoid_neighborhoods::compute_optimal_sigmoid_neighborhoods<Tag>(
    points, std::back_inserter(out),
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
  return 0;
}
