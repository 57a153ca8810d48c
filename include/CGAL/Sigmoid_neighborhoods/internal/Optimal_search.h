// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_H

#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// A triple replaces the best one only when its error is smaller by more than this (SPEC §5).
constexpr double TIE_TOLERANCE = 1e-12;

namespace internal {

// The search of SPEC §5 at every point: one k_max query per point, every (a, b, k) of the grid
// evaluated from it. Pairs whose weights agree on N_i(k) share the result of the first of them:
// the same inputs through the same code give the same bits, so this changes nothing but time.
class Optimal_search
{
public:
  struct Scratch
  {
    std::vector<Neighbor> neighbors;
    Local_neighborhood local;
    std::vector<double> weights; // pair-major, k_max + 1 per pair
    std::vector<double> errors;  // pair-major, one per k
  };

  Optimal_search(const Oriented_points& input, const Search_settings& settings)
    : m_input(input), m_settings(settings), m_sigmoids(settings.sigmoids()), m_query(input.points)
  {
    for(std::size_t p = 0; p < m_sigmoids.size(); ++p)
      if(m_sigmoids[p].is_equal_weights())
        m_equal_pair = static_cast<int>(p);
  }

  Scratch make_scratch() const
  {
    Scratch s;
    s.weights.resize(m_sigmoids.size() * (m_settings.k_max + 1));
    s.errors.resize(m_sigmoids.size() * m_settings.number_of_sizes());
    return s;
  }

  Optimal_sigmoid_neighborhood operator()(std::uint32_t i, Scratch& s) const
  {
    const unsigned int k_min = m_settings.k_min, k_max = m_settings.k_max;
    const std::size_t m = k_max + 1, sizes = m_settings.number_of_sizes();
    m_query.query(i, k_max, s.neighbors);
    s.local.assign(m_input, i, s.neighbors);

    double best = std::numeric_limits<double>::infinity();
    std::size_t best_pair = 0;
    unsigned int best_k = 0;
    for(std::size_t p = 0; p < m_sigmoids.size(); ++p)
    {
      double* w = &s.weights[p * m];
      s.local.weights(m_sigmoids[p], w);
      // The earlier pair sharing the longest prefix of weights with this one.
      std::size_t shared = 0, source = 0;
      for(std::size_t q = 0; q < p && shared < m; ++q)
      {
        const double* v = &s.weights[q * m];
        std::size_t l = 0;
        while(l < m && v[l] == w[l])
          ++l;
        if(l > shared)
        {
          shared = l;
          source = q;
        }
      }
      for(unsigned int k = k_min; k <= k_max; ++k)
      {
        const std::size_t slot = k - k_min;
        const double error = (std::size_t(k) + 1 <= shared)
                               ? s.errors[source * sizes + slot]
                               : s.local.features(w, k, m_settings.barycenter).error;
        s.errors[p * sizes + slot] = error;
        if(error < best - TIE_TOLERANCE)
        {
          best = error;
          best_pair = p;
          best_k = k;
        }
      }
    }

    Optimal_sigmoid_neighborhood result;
    if(best_k != 0)
    {
      result.a = m_sigmoids[best_pair].a();
      result.b = m_sigmoids[best_pair].b();
      result.k = best_k;
      result.features = s.local.features(&s.weights[best_pair * m], best_k, m_settings.barycenter);
    }

    // Equal weights, best k with the same tie rule.
    const double* equal_errors = nullptr;
    if(m_equal_pair >= 0)
      equal_errors = &s.errors[std::size_t(m_equal_pair) * sizes];
    else
    {
      const std::vector<double> ones(m, 1.);
      for(unsigned int k = k_min; k <= k_max; ++k)
        s.errors[k - k_min] = s.local.features(ones.data(), k, m_settings.barycenter).error;
      equal_errors = s.errors.data();
    }
    for(unsigned int k = k_min; k <= k_max; ++k)
      if(equal_errors[k - k_min] < result.error_equal - TIE_TOLERANCE)
      {
        result.error_equal = equal_errors[k - k_min];
        result.k_equal = k;
      }
    return result;
  }

  std::size_t size() const { return m_input.size(); }

private:
  const Oriented_points& m_input;
  Search_settings m_settings;
  std::vector<Cosine_sigmoid> m_sigmoids;
  int m_equal_pair = -1;
  K_neighbor_query m_query;
};

// Runs the search on every point; `sink(i, record)` is called in index order.
template <typename ConcurrencyTag, typename Sink>
void optimal_search_all(const Oriented_points& input, const Search_settings& settings, const Sink& sink)
{
  check_enough_points(input.size(), settings.k_max);
  const Optimal_search search(input, settings);
  std::vector<Optimal_sigmoid_neighborhood> results(input.size());
  for_each_index<ConcurrencyTag>(
    input.size(), [&search] { return search.make_scratch(); },
    [&search, &results](std::size_t i, Optimal_search::Scratch& s) {
      results[i] = search(static_cast<std::uint32_t>(i), s);
    });
  for(std::size_t i = 0; i < results.size(); ++i)
    sink(i, results[i]);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_H
