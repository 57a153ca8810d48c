// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_BALL_NEIGHBORHOODS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_BALL_NEIGHBORHOODS_H

#include <CGAL/Sigmoid_neighborhoods/internal/K_neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Fixed neighbor lists of all points, one after the other (compressed rows): the neighbors of
// point i are indices[offsets[i]] ... indices[offsets[i + 1] - 1].
struct Neighbor_lists
{
  std::vector<std::size_t> offsets{0};
  std::vector<std::uint32_t> indices;

  std::size_t size() const { return offsets.size() - 1; }
  std::size_t count(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
  const std::uint32_t* begin(std::size_t i) const { return indices.data() + offsets[i]; }
  const std::uint32_t* end(std::size_t i) const { return indices.data() + offsets[i + 1]; }
};

// The points within a distance of a point, by index, with CGAL's kd-tree and Fuzzy_sphere.
class Ball_neighbor_query
{
  typedef CGAL::Search_traits_3<Double_kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<std::uint32_t, Index_to_point_map, Base_traits> Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

  // Keeps the points found within the exact radius (assignable, as the tree's output iterator must be).
  struct Collector
  {
    const std::vector<Double_point>* points;
    std::uint32_t i;
    double squared_radius;
    std::vector<Neighbor>* result;
    void operator()(std::uint32_t j) const
    {
      if(j == i)
        return;
      const Double_point &p = (*points)[i], &q = (*points)[j];
      const double dx = q.x() - p.x(), dy = q.y() - p.y(), dz = q.z() - p.z();
      const double d2 = dx * dx + dy * dy + dz * dz;
      if(d2 <= squared_radius)
        result->push_back(Neighbor{j, d2});
    }
  };

public:
  // `points` must outlive the query.
  explicit Ball_neighbor_query(const std::vector<Double_point>& points)
    : m_points(points), m_map{&points}, m_traits(m_map),
      m_tree(boost::counting_iterator<std::uint32_t>(0),
             boost::counting_iterator<std::uint32_t>(std::uint32_t(points.size())), Tree::Splitter(), m_traits)
  {
    m_tree.build(); // before any parallel query: queries on a built tree are read-only
  }

  // The points j != i with |p_j - p_i|^2 <= radius^2, ordered by squared distance, ties by index.
  // Fuzzy_sphere decides points on its boundary differently on its two code paths (`<=` and `<`),
  // so the tree is asked for a slightly larger ball and the decision is taken here, exactly.
  void query(std::uint32_t i, double radius, std::vector<Neighbor>& result) const
  {
    result.clear();
    const double squared_radius = radius * radius;
    const Sphere sphere(i, radius * (1. + 1e-9), 0., m_traits);
    m_tree.search(boost::make_function_output_iterator(Collector{&m_points, i, squared_radius, &result}), sphere);
    std::sort(result.begin(), result.end(), [](const Neighbor& x, const Neighbor& y) {
      return x.squared_distance < y.squared_distance ||
             (x.squared_distance == y.squared_distance && x.index < y.index);
    });
  }

private:
  const std::vector<Double_point>& m_points;
  Index_to_point_map m_map;
  Traits m_traits;
  Tree m_tree;
};

// The ball neighborhoods {j != i : |p_j - p_i| <= radius} of all points, built once.
template <typename ConcurrencyTag>
Neighbor_lists ball_neighborhoods(const std::vector<Double_point>& points, double radius)
{
  const Ball_neighbor_query query(points);
  std::vector<std::vector<std::uint32_t>> lists(points.size());
  for_each_index<ConcurrencyTag>(
    points.size(), [] { return std::vector<Neighbor>(); },
    [&](std::size_t i, std::vector<Neighbor>& found) {
      query.query(static_cast<std::uint32_t>(i), radius, found);
      lists[i].reserve(found.size());
      for(const Neighbor& x : found)
        lists[i].push_back(x.index);
    });
  Neighbor_lists result;
  result.offsets.reserve(points.size() + 1);
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
double mean_neighbor_distance(const std::vector<Double_point>& points, unsigned int k)
{
  if(k < 1)
    throw std::invalid_argument("the number of neighbors for the mean neighbor distance must be at least 1");
  if(points.size() < std::size_t(k) + 1)
    throw std::invalid_argument("the mean distance to the " + std::to_string(k) + " nearest neighbors needs at least " +
                                std::to_string(k + 1) + " points, got " + std::to_string(points.size()));
  const K_neighbor_query query(points);
  std::vector<double> means(points.size());
  for_each_index<ConcurrencyTag>(
    points.size(), [] { return std::vector<Neighbor>(); },
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
  return sum / double(points.size());
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_BALL_NEIGHBORHOODS_H
