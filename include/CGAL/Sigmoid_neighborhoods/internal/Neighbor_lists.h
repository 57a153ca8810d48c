// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Neighbor lists of all points, one after the other (compressed rows, pgeof's `nn` / `nn_ptr`):
// the neighbors of point i are indices[offsets[i]] ... indices[offsets[i + 1] - 1].
struct Neighbor_lists
{
  std::vector<std::size_t> offsets{0};
  std::vector<std::uint32_t> indices;

  std::size_t size() const { return offsets.size() - 1; }
  std::size_t count(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
  const std::uint32_t* begin(std::size_t i) const { return indices.data() + offsets[i]; }
  const std::uint32_t* end(std::size_t i) const { return indices.data() + offsets[i + 1]; }
};

template <typename Index>
bool index_in_range(Index j, std::size_t n)
{
  if constexpr(std::is_signed<Index>::value)
    if(j < 0)
      return false;
  return std::size_t(j) < n;
}

// Appends the caller's list of point i to `result`, checked: indices in range, never i itself.
template <typename List>
void append_checked_list(const List& list, std::size_t i, std::size_t n, Neighbor_lists& result)
{
  for(const auto& j : list)
  {
    if(!index_in_range(j, n))
      throw std::invalid_argument("neighborhood of point " + std::to_string(i) + ": index " + std::to_string(j) +
                                  " is out of range (" + std::to_string(n) + " points)");
    if(std::size_t(j) == i)
      throw std::invalid_argument("neighborhood of point " + std::to_string(i) + " contains the point itself");
    result.indices.push_back(static_cast<std::uint32_t>(j));
  }
  result.offsets.push_back(result.indices.size());
}

// The caller's neighborhoods as a range of ranges of indices, checked.
template <typename Lists>
Neighbor_lists neighbor_lists(const Lists& lists, std::size_t n)
{
  if(std::size_t(std::distance(std::begin(lists), std::end(lists))) != n)
    throw std::invalid_argument("the neighborhoods must hold one list per point (" + std::to_string(n) + ")");
  Neighbor_lists result;
  std::size_t i = 0;
  for(const auto& list : lists)
    append_checked_list(list, i++, n, result);
  return result;
}

// Checks the caller's compressed rows (random-access ranges): n + 1 non-decreasing offsets from 0
// to the number of indices, every index in range and none its own row's point. Sound rows are
// checked on `threads` threads (0: the default); where a row is not, a pass in order finds the
// first fault, so that the message does not depend on the threads.
template <typename Indices, typename Offsets>
void check_neighbor_rows(const Indices& indices, const Offsets& offsets, std::size_t n, unsigned int threads = 1)
{
  const auto index = std::begin(indices);
  const auto offset = std::begin(offsets);
  const std::size_t index_count = std::size_t(std::distance(index, std::end(indices)));
  const std::size_t offset_count = std::size_t(std::distance(offset, std::end(offsets)));
  if(offset_count != n + 1)
    throw std::invalid_argument("the neighbor offsets must hold one entry per point and one more (" +
                                std::to_string(n + 1) + "), got " + std::to_string(offset_count));
  if(std::size_t(offset[0]) != 0 || std::size_t(offset[n]) != index_count)
    throw std::invalid_argument("the neighbor offsets must start at 0 and end at the number of neighbor indices (" +
                                std::to_string(index_count) + ")");
  if(threads != 1 && n >= 4096)
  {
    std::atomic<bool> sound(true);
    for_each_index<Parallel_if_available_tag>(n, threads, [] { return 0; }, [&](std::size_t i, int) {
      // a row past the indices is a fault too: the offsets' order is not known yet
      if(offset[i + 1] < offset[i] || std::size_t(offset[i + 1]) > index_count)
      {
        sound.store(false, std::memory_order_relaxed);
        return;
      }
      for(auto j = index + std::ptrdiff_t(offset[i]); j != index + std::ptrdiff_t(offset[i + 1]); ++j)
        if(!index_in_range(*j, n) || std::size_t(*j) == i)
        {
          sound.store(false, std::memory_order_relaxed);
          return;
        }
    }, 4096);
    if(sound.load())
      return;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(offset[i + 1] < offset[i])
      throw std::invalid_argument("the neighbor offsets must not decrease (at point " + std::to_string(i) + ")");
  for(std::size_t i = 0; i < n; ++i)
    for(auto j = index + std::ptrdiff_t(offset[i]); j != index + std::ptrdiff_t(offset[i + 1]); ++j)
    {
      if(!index_in_range(*j, n))
        throw std::invalid_argument("neighborhood of point " + std::to_string(i) + ": index " + std::to_string(*j) +
                                    " is out of range (" + std::to_string(n) + " points)");
      if(std::size_t(*j) == i)
        throw std::invalid_argument("neighborhood of point " + std::to_string(i) + " contains the point itself");
    }
}

// The caller's compressed rows, checked, as Neighbor_lists.
template <typename Indices, typename Offsets>
Neighbor_lists neighbor_lists(const Indices& indices, const Offsets& offsets, std::size_t n)
{
  check_neighbor_rows(indices, offsets, n);
  Neighbor_lists result;
  result.offsets.assign(std::begin(offsets), std::end(offsets));
  result.indices.assign(std::begin(indices), std::end(indices));
  return result;
}

// Rows in the package's own types are read where they are (no copy); others are converted.
template <typename Indices, typename Offsets>
constexpr bool is_native_rows = std::is_same<Indices, std::vector<std::uint32_t>>::value &&
                                std::is_same<Offsets, std::vector<std::size_t>>::value;

// The caller's neighborhoods of the named parameters `neighborhoods` (one list per point) or
// `neighbor_indices` and `neighbor_offsets` (compressed rows), checked; none when neither is given.
template <typename NamedParameters>
std::optional<Neighbor_lists> given_neighborhoods(const NamedParameters& np, std::size_t n)
{
  using CGAL::parameters::get_parameter_reference;
  using CGAL::parameters::is_default_parameter;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::neighborhoods_t>::value)
    return neighbor_lists(get_parameter_reference(np, internal_np::neighborhoods), n);
  else if constexpr(!is_default_parameter<NamedParameters, internal_np::neighbor_indices_t>::value)
    return neighbor_lists(get_parameter_reference(np, internal_np::neighbor_indices),
                          get_parameter_reference(np, internal_np::neighbor_offsets), n);
  else
    return std::nullopt;
}

// The caller's search tree of `np` (search_tree), else the structure of neighbor_search(np) built on
// the threads of a call of `ConcurrencyTag`.
template <typename ConcurrencyTag, typename NamedParameters>
Neighbor_query tree_query(const std::vector<Double_point>& points, const NamedParameters& np)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::search_tree_t>::value)
  {
    return Neighbor_query(points,
                          caller_tree_search(CGAL::parameters::get_parameter(np, internal_np::search_tree).get(),
                                             points.size()));
  }
  else
    return Neighbor_query(points,
                          kernel_threads<ConcurrencyTag>(CGAL::parameters::choose_parameter(
                            CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 0u)),
                          neighbor_search(np));
}

// The neighborhoods of `np` (neighbor_indices and neighbor_offsets), else tree_query().
template <typename ConcurrencyTag, typename NamedParameters>
Neighbor_query neighbor_query(const std::vector<Double_point>& points, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter_reference;
  using CGAL::parameters::is_default_parameter;
  constexpr bool has_indices = !is_default_parameter<NamedParameters, internal_np::neighbor_indices_t>::value;
  constexpr bool has_offsets = !is_default_parameter<NamedParameters, internal_np::neighbor_offsets_t>::value;
  static_assert(has_indices == has_offsets, "neighbor_indices and neighbor_offsets are given together");
  static_assert(!has_indices || is_default_parameter<NamedParameters, internal_np::search_tree_t>::value,
                "search_tree and neighbor_indices exclude each other: given rows need no search");
  if constexpr(has_indices)
  {
    // CGAL's packs hold copies, except of parameters given with std::cref(): those are read in place
    decltype(auto) indices = get_parameter_reference(np, internal_np::neighbor_indices);
    decltype(auto) offsets = get_parameter_reference(np, internal_np::neighbor_offsets);
    typedef decltype(indices) Indices_reference;
    typedef decltype(offsets) Offsets_reference;
    constexpr bool native = is_native_rows<std::decay_t<Indices_reference>, std::decay_t<Offsets_reference>>;
    const unsigned int threads = kernel_threads<ConcurrencyTag>(
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 0u));
    if constexpr(native && std::is_lvalue_reference<Indices_reference>::value &&
                 std::is_lvalue_reference<Offsets_reference>::value)
    {
      check_neighbor_rows(indices, offsets, points.size(), threads);
      return Neighbor_query(points, offsets.data(), indices.data());
    }
    else if constexpr(native)
    {
      check_neighbor_rows(indices, offsets, points.size(), threads);
      return Neighbor_query(points, std::vector<std::size_t>(std::move(offsets)),
                            std::vector<std::uint32_t>(std::move(indices)));
    }
    else
    {
      Neighbor_lists rows = neighbor_lists(indices, offsets, points.size());
      return Neighbor_query(points, std::move(rows.offsets), std::move(rows.indices));
    }
  }
  else
    return tree_query<ConcurrencyTag>(points, np);
}

// The k nearest other points of every point of `query` in rows of min(k, n - 1), ordered by
// is_nearer(), on `threads` threads (kernel_threads()): compute_k_nearest_neighbors(), and what the
// spanning forest's sequential walk reads. A kernel (config.h).
CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION Neighbor_lists nearest_neighbor_rows(const Neighbor_query& query, unsigned int k,
                                                                        unsigned int threads);

// N_i(k) of every point needs k neighbors: rows the caller gave may be shorter.
inline void check_neighborhood_size(const Neighbor_query& query, unsigned int k)
{
  if(query.is_given() && query.fewest_neighbors() < k)
    throw std::invalid_argument("the given neighborhoods need at least " + std::to_string(k) +
                                " neighbors per point, one has " + std::to_string(query.fewest_neighbors()));
}

// The ball neighborhoods {j != i : |p_j - p_i| <= radius} of all points, from the shared query.
template <typename ConcurrencyTag>
Neighbor_lists ball_neighborhoods(const Neighbor_query& query, double radius, unsigned int threads)
{
  const std::size_t n = query.size();
  std::vector<std::vector<std::uint32_t>> lists(n);
  for_each_index<ConcurrencyTag>(
    n, threads, [] { return std::vector<Neighbor>(); },
    [&](std::size_t i, std::vector<Neighbor>& found) {
      query.query_ball(static_cast<std::uint32_t>(i), radius, found);
      lists[i].reserve(found.size());
      for(const Neighbor& x : found)
        lists[i].push_back(x.index);
    });
  Neighbor_lists result;
  result.offsets.reserve(n + 1);
  for(const auto& list : lists)
  {
    result.indices.insert(result.indices.end(), list.begin(), list.end());
    result.offsets.push_back(result.indices.size());
  }
  return result;
}

// The mean over all points of their mean distance to their k nearest other points.
// (CGAL::compute_average_spacing() divides the sum of the k distances by k + 1, counting the
// point itself: it is k / (k + 1) times this value.) Per-point means are summed in index order.
template <typename ConcurrencyTag>
double mean_neighbor_distance(const Neighbor_query& query, unsigned int k, unsigned int threads)
{
  const std::size_t n = query.size();
  if(k < 1)
    throw std::invalid_argument("the number of neighbors for the mean neighbor distance must be at least 1");
  if(n < std::size_t(k) + 1)
    throw std::invalid_argument("the mean distance to the " + std::to_string(k) + " nearest neighbors needs at least " +
                                std::to_string(k + 1) + " points, got " + std::to_string(n));
  std::vector<double> means(n);
  for_each_index<ConcurrencyTag>(
    n, threads, [] { return std::vector<Neighbor>(); },
    [&](std::size_t i, std::vector<Neighbor>& found) {
      query.query(static_cast<std::uint32_t>(i), k, found);
      double sum = 0.;
      for(const Neighbor& x : found)
        sum += std::sqrt(x.squared_distance);
      means[i] = sum / double(found.size());
    });
  double sum = 0.;
  for(double m : means)
    sum += m;
  return sum / double(n);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_NEIGHBOR_LISTS_H
