// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Parallel_tag in a build without OpenMP where CGAL is linked with TBB: the TBB loop, with
// the sequential results bit for bit, threads per call, and an exception passed to the caller.

#include <CGAL/Sigmoid_neighborhoods.h>

#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#if defined(_OPENMP) || !defined(CGAL_LINKED_WITH_TBB)
#error "this test is built with TBB and without OpenMP"
#endif

namespace SN = CGAL::Sigmoid_neighborhoods;

int main()
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::pair<K::Point_3, K::Vector_3> Point_with_normal;
  std::vector<Point_with_normal> points;
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  for(int i = 0; i < 3000; ++i)
  {
    K::Vector_3 v(g(rng), g(rng), 0.2 * g(rng));
    v = v / std::sqrt(v.squared_length());
    points.emplace_back(CGAL::ORIGIN + v, v);
  }
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                    .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>());
  std::vector<SN::Optimal_sigmoid_neighborhood> sequential, parallel, two_threads;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(sequential), np);
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(points, std::back_inserter(parallel), np);
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(points, std::back_inserter(two_threads),
                                                                SN::parameters::number_of_threads(2u, np));
  std::size_t differ = 0;
  for(std::size_t i = 0; i < sequential.size(); ++i)
    for(const auto* r : {&parallel[i], &two_threads[i]})
      differ += !(r->k == sequential[i].k &&
                  std::memcmp(&r->features.error, &sequential[i].features.error, sizeof(double)) == 0);
  bool caught = false;
  try
  {
    SN::internal::for_each_index<CGAL::Parallel_tag>(1000, 2, [] { return 0; }, [](std::size_t i, int&) {
      if(i == 377)
        throw std::domain_error("index 377");
    });
  }
  catch(const std::domain_error& e)
  {
    caught = std::string(e.what()) == "index 377";
  }
  std::cout << "TBB: " << differ << " records differ from the sequential ones, exception "
            << (caught ? "passed" : "lost") << std::endl;
  return differ == 0 && caught ? 0 : 1;
}
