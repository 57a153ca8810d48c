// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SPATIAL_SEARCH_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SPATIAL_SEARCH_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

// The interface of a search structure and SPEC §2's tie rule on its results, without CGAL's
// spatial searching, which Kd_tree_search.h includes: a translation unit that links the compiled
// kernels (config.h) does not parse it.

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// What Neighbor_query asks of a search structure; it applies the tie rule to the results.
class Spatial_search
{
public:
  virtual ~Spatial_search() = default;
  // the min(count, n) nearest points to `q` by increasing squared distance (one choice among points
  // tied at the last distance, ties in any order)
  virtual void nearest(const Double_point& q, std::size_t count, std::vector<Neighbor>& found) const = 0;
  // the points at distance at most `radius` from `q`, in any order, their distances not set
  virtual void ball(const Double_point& q, double radius, std::vector<Neighbor>& found) const = 0;
  // the point indices in the order of the tree's leaves
  virtual std::vector<std::uint32_t> leaf_order() const = 0;
};

// The search of a caller's CGAL::Kd_tree over the `n` points (Kd_tree_search.h, which
// <CGAL/Sigmoid_neighborhoods/search_tree.h> includes with the named parameter).
template <typename Tree>
std::unique_ptr<const Spatial_search> caller_tree_search(const Tree& tree, std::size_t n);

// SPEC §2's tie rule on a search that breaks ties arbitrarily: the min(k, n - 1) nearest points to
// point `self` other than itself (self == NO_POINT: the min(k, n) nearest to `q`), ordered by
// is_nearer(). It asks for EXTRA_NEIGHBORS more than it needs and asks again, twice as many, only
// when the last one asked ties with the k-th: then points at that distance may be missing.
constexpr std::size_t EXTRA_NEIGHBORS = 1;

inline void nearest_by_tie_rule(const Spatial_search& search, const std::vector<Double_point>& points,
                                const Double_point& q, std::uint32_t self, std::size_t k,
                                std::vector<Neighbor>& result)
{
  const std::size_t n = points.size();
  k = (std::min)(k, self == NO_POINT ? n : n - 1);
  result.clear();
  if(k == 0)
    return;
  std::size_t asked = (std::min)(n, k + (self == NO_POINT ? 0 : 1) + EXTRA_NEIGHBORS);
  for(;;)
  {
    search.nearest(q, asked, result);
    if(self != NO_POINT)
    {
      const auto found_self =
        std::find_if(result.begin(), result.end(), [self](const Neighbor& x) { return x.index == self; });
      if(found_self != result.end())
        result.erase(found_self);
    }
    // ties by index: an insertion sort, linear on results sorted by distance
    for(std::size_t e = 1; e < result.size(); ++e)
    {
      const Neighbor x = result[e];
      std::size_t f = e;
      for(; f > 0 && is_nearer(x, result[f - 1]); --f)
        result[f] = result[f - 1];
      result[f] = x;
    }
    // every point was found, or none left out can be nearer than the last one found, which is
    // farther than the k-th
    if(asked == n || (result.size() > k && result[k].squared_distance > result[k - 1].squared_distance))
    {
      result.resize(k);
      return;
    }
    asked = (std::min)(n, 2 * asked);
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SPATIAL_SEARCH_H
