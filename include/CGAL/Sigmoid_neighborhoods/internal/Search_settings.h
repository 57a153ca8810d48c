// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SEARCH_SETTINGS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SEARCH_SETTINGS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/Neighborhood_criterion.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>
#include <CGAL/Sigmoid_neighborhoods/vector_instructions.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

namespace internal {

struct Search_settings
{
  std::vector<double> a_grid, b_grid;
  unsigned int k_min = defaults::K_MIN, k_max = defaults::K_MAX;
  Barycenter barycenter = Barycenter::WEIGHTED;
  Neighborhood_criterion criterion = Neighborhood_criterion::DIMENSIONALITY;
  double angle_tolerance = defaults::ANGLE_TOLERANCE;
  unsigned int threads = 0; // of a call with Parallel_tag; 0: the default
  Vector_instructions instructions = widest_vector_instructions();

  // The (a, b) pairs with a <= b, a ascending then b ascending: the visiting order of SPEC §5.
  std::vector<Cosine_sigmoid> sigmoids() const
  {
    std::vector<Cosine_sigmoid> result;
    for(double a : a_grid)
      for(double b : b_grid)
        if(a <= b)
          result.emplace_back(a, b, angle_tolerance);
    return result;
  }

  unsigned int number_of_sizes() const { return k_max - k_min + 1; }
};

inline std::vector<double> checked_grid(std::vector<double> grid, const char* name)
{
  for(double v : grid)
    if(!(v >= 0. && v <= CGAL_PI))
      throw std::invalid_argument(std::string(name) + " grid values must lie in [0, pi], got " + std::to_string(v));
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  if(grid.empty())
    throw std::invalid_argument(std::string(name) + " grid is empty");
  return grid;
}

// The named parameter `number_of_threads`, 0 (the OpenMP or TBB default) when absent.
template <typename NamedParameters>
unsigned int number_of_threads(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 0u);
}

// The named parameter `line_angles`, false (the paper's oriented angle) when absent.
template <typename NamedParameters>
bool line_angles(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::line_angles), false);
}

template <typename NamedParameters>
Search_settings search_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Search_settings s;
  s.k_min = choose_parameter(get_parameter(np, internal_np::k_min), defaults::K_MIN);
  s.k_max = choose_parameter(get_parameter(np, internal_np::k_max), defaults::K_MAX);
  s.a_grid = checked_grid(choose_parameter(get_parameter(np, internal_np::a_grid), defaults::angle_grid()), "a");
  s.b_grid = checked_grid(choose_parameter(get_parameter(np, internal_np::b_grid), defaults::angle_grid()), "b");
  s.barycenter = choose_parameter(get_parameter(np, internal_np::barycenter), Barycenter::WEIGHTED);
  s.criterion = choose_parameter(get_parameter(np, internal_np::criterion), Neighborhood_criterion::DIMENSIONALITY);
  s.angle_tolerance = choose_parameter(get_parameter(np, internal_np::angle_tolerance), defaults::ANGLE_TOLERANCE);
  s.threads = number_of_threads(np);
  s.instructions = choose_parameter(get_parameter(np, internal_np::vector_instructions), widest_vector_instructions());
  if(!has_vector_instructions(s.instructions))
    throw std::invalid_argument(std::string("this processor cannot run the vector instructions ") +
                                internal::vector_instructions_name(s.instructions));
  if(!(s.k_min >= 1 && s.k_min <= s.k_max))
    throw std::invalid_argument("the neighborhood sizes must satisfy 1 <= k_min <= k_max, got k_min = " +
                                std::to_string(s.k_min) + ", k_max = " + std::to_string(s.k_max));
  if(!(s.angle_tolerance >= 0. && s.angle_tolerance < CGAL_PI))
    throw std::invalid_argument("angle tolerance must be in [0, pi), got " + std::to_string(s.angle_tolerance));
  if(s.a_grid.front() > s.b_grid.back())
    throw std::invalid_argument("the a and b grids have no pair with a <= b");
  return s;
}

inline void check_enough_points(std::size_t n, unsigned int k_max)
{
  if(n < std::size_t(k_max) + 1)
    throw std::invalid_argument("needs at least k_max + 1 = " + std::to_string(k_max + 1) +
                                " points, got " + std::to_string(n));
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SEARCH_SETTINGS_H
