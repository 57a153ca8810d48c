// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_K_NEIGHBOR_QUERY_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_K_NEIGHBOR_QUERY_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Kd_tree.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

typedef CGAL::Simple_cartesian<double> Double_kernel;
typedef Double_kernel::Point_3 Double_point;

struct Neighbor
{
  std::uint32_t index;
  double squared_distance;
};

// The point of an index, for CGAL's kd-trees over indices (Search_traits_adapter).
struct Index_to_point_map
{
  typedef std::uint32_t key_type;
  typedef Double_point value_type;
  typedef const Double_point& reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<Double_point>* points = nullptr;
  friend reference get(const Index_to_point_map& map, key_type i) { return (*map.points)[i]; }
};

// k nearest neighbors by index with CGAL's kd-tree, ordered by distance and then by index,
// so that the neighborhoods do not depend on the tree's traversal (SPEC §2).
class K_neighbor_query
{
  typedef CGAL::Search_traits_3<Double_kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<std::uint32_t, Index_to_point_map, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Base_search;
  typedef Base_search::Tree Tree;
  typedef Tree::Splitter Splitter;
  typedef Base_search::Distance Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> Search;

public:
  // `points` must outlive the query.
  explicit K_neighbor_query(const std::vector<Double_point>& points)
    : m_points(points), m_map{&points},
      m_tree(boost::counting_iterator<std::uint32_t>(0),
             boost::counting_iterator<std::uint32_t>(std::uint32_t(points.size())), Splitter(),
             Traits(m_map))
  {
    m_tree.build(); // before any parallel query: queries on a built tree are read-only
  }

  // The `k` nearest points of point `i` other than `i` itself (|result| = min(k, n - 1)),
  // ordered by squared distance, ties by index. Thread-safe.
  void query(std::uint32_t i, unsigned int k, std::vector<Neighbor>& result) const
  {
    const std::size_t n = m_points.size();
    const std::size_t wanted = (std::min)(std::size_t(k), n - 1);
    // One more than needed (k others + i itself + 1) tells whether a tie crosses the boundary.
    std::size_t asked = (std::min)(wanted + 2, n);
    for(;;)
    {
      result.clear();
      // unsorted: the one sort is ours, with the tie rule
      Search search(m_tree, m_points[i], static_cast<unsigned int>(asked), 0., true, Distance(m_map), false);
      for(const auto& found : search)
        result.push_back(Neighbor{found.first, found.second});
      std::sort(result.begin(), result.end(), [](const Neighbor& x, const Neighbor& y) {
        return x.squared_distance < y.squared_distance ||
               (x.squared_distance == y.squared_distance && x.index < y.index);
      });
      const double farthest = result.empty() ? 0. : result.back().squared_distance;
      result.erase(std::remove_if(result.begin(), result.end(),
                                  [i](const Neighbor& x) { return x.index == i; }),
                   result.end());
      // Every point closer than the farthest returned one is in `result`. The selection is
      // exact unless points at the k-th distance may remain outside: then ask for more.
      if(wanted == 0 || asked >= n || result.size() < wanted ||
         result[wanted - 1].squared_distance < farthest)
        break;
      asked = (std::min)(2 * asked, n);
    }
    result.resize((std::min)(result.size(), wanted));
  }

  std::size_t size() const { return m_points.size(); }

private:
  const std::vector<Double_point>& m_points;
  Index_to_point_map m_map;
  Tree m_tree;
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_K_NEIGHBOR_QUERY_H
