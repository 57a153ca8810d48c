// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_KD_TREE_SEARCH_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_KD_TREE_SEARCH_H

#include <CGAL/Sigmoid_neighborhoods/config.h>

#include <CGAL/Sigmoid_neighborhoods/internal/Spatial_search.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The position of a point index in the package's copy of the points: the point map of its tree.
struct Point_by_index_map
{
  typedef std::uint32_t key_type;
  typedef Double_point value_type;
  typedef const Double_point& reference;
  typedef boost::readable_property_map_tag category;

  const Double_point* points = nullptr;

  friend reference get(const Point_by_index_map& map, std::uint32_t i) { return map.points[i]; }
};

// The search structure a call builds when the caller gives none: CGAL's kd-tree over the point
// indices, through Search_traits_adapter on the package's copy (as Point_set_processing_3 builds
// its own), with sliding-midpoint splits. No points cache: with it the tree held 25 MB instead of
// 13 MB on a scan of 519,000 points, for the same speed at 10 and 20 neighbors (10 % less at 100).
typedef CGAL::Search_traits_3<Double_kernel> Double_search_traits;
typedef CGAL::Search_traits_adapter<std::uint32_t, Point_by_index_map, Double_search_traits> Index_search_traits;
typedef CGAL::Sliding_midpoint<Index_search_traits> Index_splitter;
typedef CGAL::Kd_tree<Index_search_traits, Index_splitter, CGAL::Tag_true, CGAL::Tag_false> Index_kd_tree;

template <typename Traits>
struct Adapter_parts
{
  static constexpr bool is_adapter = false;
};

template <typename Key, typename PointMap, typename BaseTraits>
struct Adapter_parts<CGAL::Search_traits_adapter<Key, PointMap, BaseTraits>>
{
  static constexpr bool is_adapter = true;
  typedef Key key_type;
  typedef PointMap Point_map;
  typedef BaseTraits Base_traits;
};

// CGAL's Orthogonal_k_neighbor_search and Fuzzy_sphere on a CGAL::Kd_tree whose items are the point
// indices 0..n-1 of the input (any key type that converts to std::size_t: std::size_t, std::uint32_t,
// Point_set_3::Index) through Search_traits_adapter on a point map, the base traits those of a
// kernel of double coordinates. The tree is held by reference: it must outlive the search.
template <typename Tree>
class Kd_tree_spatial_search final : public Spatial_search
{
  typedef typename Tree::Traits Traits;
  typedef Adapter_parts<Traits> Parts;
  static_assert(Parts::is_adapter,
                "the search tree's items must be the point indices: its traits a CGAL::Search_traits_adapter "
                "on the point map of the indices");

public:
  typedef typename Parts::key_type key_type;
  typedef typename Parts::Base_traits Base_traits;
  typedef typename Base_traits::Point_d Base_point;
  static_assert(std::is_same<typename Base_traits::FT, double>::value,
                "the search tree's coordinates must be double (Search_traits_3 of Epick or "
                "Simple_cartesian<double>): the package's distances and tie rule are computed in double");
  static_assert(Base_traits::Dimension::value == 3, "the search tree must be three-dimensional");

  typedef CGAL::Distance_adapter<key_type, typename Parts::Point_map, CGAL::Euclidean_distance<Base_traits>> Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, typename Tree::Splitter, Tree> K_neighbor_search;

  // `n`: the number of points the tree must hold, checked (a tree of other points is refused)
  Kd_tree_spatial_search(const Tree& tree, std::size_t n) : m_tree(tree), m_size(n)
  {
    if(tree.size() != n)
      throw std::invalid_argument("the given search tree holds " + std::to_string(tree.size()) +
                                  " points, the input has " + std::to_string(n));
    if(n > 0)
      tree.root(); // built here, once: a const query would build it, and not thread-safely
  }

  void nearest(const Double_point& q, std::size_t count, std::vector<Neighbor>& found) const override
  {
    found.clear();
    if(m_size == 0)
      return;
    // CGAL's squared distances are the package's: (dx^2 + dy^2) + dz^2 in double (Neighbor.h)
    K_neighbor_search search(m_tree, Base_point(q.x(), q.y(), q.z()), static_cast<unsigned int>(count), 0., true,
                             Distance(m_tree.traits().point_property_map()), true);
    for(auto it = search.begin(); it != search.end(); ++it)
      found.push_back(Neighbor{index_of(it->first), it->second});
  }

  void ball(const Double_point& q, double radius, std::vector<Neighbor>& found) const override
  {
    found.clear();
    if(m_size == 0)
      return;
    const CGAL::Fuzzy_sphere<Traits> sphere(Base_point(q.x(), q.y(), q.z()), radius, 0., m_tree.traits());
    m_tree.search(boost::make_function_output_iterator(Append_index{this, &found}), sphere);
  }

  std::vector<std::uint32_t> leaf_order() const override
  {
    std::vector<std::uint32_t> order;
    order.reserve(m_size);
    if(m_size > 0)
      m_tree.root()->tree_items(boost::make_function_output_iterator(Append_leaf_index{this, &order}));
    return order;
  }

private:
  // appends a found item's index (the output iterators of CGAL's searches are assigned: no lambda)
  struct Append_index
  {
    const Kd_tree_spatial_search* search;
    std::vector<Neighbor>* found;
    void operator()(const key_type& key) const { found->push_back(Neighbor{search->index_of(key), 0.}); }
  };
  struct Append_leaf_index
  {
    const Kd_tree_spatial_search* search;
    std::vector<std::uint32_t>* order;
    void operator()(const key_type& key) const { order->push_back(search->index_of(key)); }
  };

  std::uint32_t index_of(const key_type& key) const
  {
    const std::size_t i = static_cast<std::size_t>(key);
    if(i >= m_size)
      throw std::invalid_argument("the given search tree holds the point index " + std::to_string(i) +
                                  ", beyond the input's " + std::to_string(m_size) + " points");
    return static_cast<std::uint32_t>(i);
  }

  const Tree& m_tree;
  std::size_t m_size;
};

// CGAL's kd-tree over the package's copy of the points, owned: the default search structure.
class Index_kd_tree_search final : public Spatial_search
{
public:
  // leaves of up to this many points: on a scan's 10, 20 and 100 nearest 16 was 1-3 % faster than
  // CGAL's default of 10 and than 32, 12 % faster than 5; the tree held 13 MB (10: 16 MB, 32: 11 MB)
  static constexpr unsigned int BUCKET_SIZE = 16;

  explicit Index_kd_tree_search(const std::vector<Double_point>& points, unsigned int threads = 1)
    : m_tree(index_begin(), index_end(checked_size(points)), Index_splitter(BUCKET_SIZE),
             Index_search_traits(Point_by_index_map{points.data()})),
      m_built(build(m_tree, points.size(), threads)), m_search(m_tree, points.size())
  {}

  void nearest(const Double_point& q, std::size_t count, std::vector<Neighbor>& found) const override
  {
    m_search.nearest(q, count, found);
  }
  void ball(const Double_point& q, double radius, std::vector<Neighbor>& found) const override
  {
    m_search.ball(q, radius, found);
  }
  std::vector<std::uint32_t> leaf_order() const override { return m_search.leaf_order(); }

private:
  static std::size_t checked_size(const std::vector<Double_point>& points)
  {
    if(points.size() > (std::numeric_limits<std::uint32_t>::max)())
      throw std::invalid_argument("the neighbor search holds at most 2^32 - 1 points");
    return points.size();
  }
  // built once, on the threads of the call where CGAL can (with TBB)
  static bool build(Index_kd_tree& tree, std::size_t n, unsigned int threads)
  {
    if(n == 0)
      return false;
#if defined(CGAL_LINKED_WITH_TBB)
    if(threads > 1)
    {
      tree.template build<CGAL::Parallel_tag>();
      return true;
    }
#endif
    (void)threads;
    tree.build();
    return true;
  }
  static boost::counting_iterator<std::uint32_t> index_begin() { return boost::counting_iterator<std::uint32_t>(0); }
  static boost::counting_iterator<std::uint32_t> index_end(std::size_t n)
  {
    return boost::counting_iterator<std::uint32_t>(static_cast<std::uint32_t>(n));
  }

  Index_kd_tree m_tree;
  bool m_built; // before m_search, which would otherwise build the tree on one thread
  Kd_tree_spatial_search<Index_kd_tree> m_search;
};

// declared in Spatial_search.h: the caller's tree of the named parameter search_tree
template <typename Tree>
std::unique_ptr<const Spatial_search> caller_tree_search(const Tree& tree, std::size_t n)
{
  return std::make_unique<const Kd_tree_spatial_search<Tree>>(tree, n);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_KD_TREE_SEARCH_H
