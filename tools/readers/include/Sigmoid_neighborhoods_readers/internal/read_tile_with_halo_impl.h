// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The definitions of read_tile_with_halo.h: inline in the header-only build, compiled once into the
// library Sigmoid_neighborhoods_readers otherwise (config.h).

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_TILE_WITH_HALO_IMPL_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_TILE_WITH_HALO_IMPL_H

#include <Sigmoid_neighborhoods_readers/read_tile_with_halo.h>

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Lidar_io/Tile_catalog.h>
#include <Sigmoid_neighborhoods_readers/internal/catalog_points.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

namespace internal {

constexpr unsigned int MAXIMUM_HALO_READINGS = 64;

// What no halo has read: the catalog's tiles that reach beyond `region`. For a point in `region`,
// margin() bounds from below its distance to every point of the catalog outside `region`, or says
// it exceeds `reach`: the tiles farther than `reach` from `region` are left out (a survey of
// thousands of tiles has a few near any tile).
class Unread_space
{
public:
  Unread_space(const Lidar_io::Tile_catalog& catalog, const CGAL::Bbox_2& region,
               double reach = std::numeric_limits<double>::infinity())
    : m_region(region)
  {
    for(const Lidar_io::Catalog_tile& t : catalog.tiles)
    {
      const CGAL::Bbox_2& b = t.extent;
      const double dx = (std::max)({b.xmin() - region.xmax(), 0., region.xmin() - b.xmax()});
      const double dy = (std::max)({b.ymin() - region.ymax(), 0., region.ymin() - b.ymax()});
      if(t.points > 0 && !(b.xmin() >= region.xmin() && b.xmax() <= region.xmax() && b.ymin() >= region.ymin() &&
                           b.ymax() <= region.ymax()) &&
         !(std::sqrt(dx * dx + dy * dy) > reach))
        m_beyond.push_back(b);
    }
  }

  bool empty() const { return m_beyond.empty(); }

  // A point outside `region` in the tile of extent B lies beyond one of the region's sides that B
  // crosses, and within B: its distance to p is at least the larger of the two bounds.
  double margin(double x, double y) const
  {
    double margin = std::numeric_limits<double>::infinity();
    for(const CGAL::Bbox_2& b : m_beyond)
    {
      double side = std::numeric_limits<double>::infinity();
      if(b.xmin() < m_region.xmin())
        side = (std::min)(side, x - m_region.xmin());
      if(b.xmax() > m_region.xmax())
        side = (std::min)(side, m_region.xmax() - x);
      if(b.ymin() < m_region.ymin())
        side = (std::min)(side, y - m_region.ymin());
      if(b.ymax() > m_region.ymax())
        side = (std::min)(side, m_region.ymax() - y);
      const double dx = (std::max)({b.xmin() - x, 0., x - b.xmax()});
      const double dy = (std::max)({b.ymin() - y, 0., y - b.ymax()});
      margin = (std::min)(margin, (std::max)(side, std::sqrt(dx * dx + dy * dy)));
    }
    return margin;
  }

private:
  CGAL::Bbox_2 m_region;
  std::vector<CGAL::Bbox_2> m_beyond;
};

inline CGAL::Bbox_2 widened(const CGAL::Bbox_2& b, double width)
{
  return CGAL::Bbox_2(b.xmin() - width, b.ymin() - width, b.xmax() + width, b.ymax() + width);
}

// How far the `k` nearest neighbors of a tile's point reach if its points spread evenly over its
// extent.
inline double even_reach(const Lidar_io::Catalog_tile& tile, unsigned int k)
{
  const double area = (tile.extent.xmax() - tile.extent.xmin()) * (tile.extent.ymax() - tile.extent.ymin());
  if(!(area > 0.) || tile.points == 0)
    return 1.;
  return std::sqrt(double(k) * area / (3.14159265358979323846 * double(tile.points)));
}

// The first halo, before any neighborhood says how far it reaches: four times what evenly spread
// points would need (see sufficient_halo_width()), as densities vary (roofs, canopy and ground of
// a survey), so that most tiles are read once. Every reading costs about as much as the first (the
// neighbor tiles are streamed whole, every row is computed), while a wider halo adds few points.
inline double first_halo_width(const Lidar_io::Catalog_tile& tile, unsigned int k, unsigned int estimation_neighbors)
{
  const double reach = even_reach(tile, k);
  return 4. * (estimation_neighbors == 0 ? reach : 2. * reach + even_reach(tile, estimation_neighbors));
}

// How much farther than `margin` the point at (x, y) needs to see to see its neighbor at
// `distance` (at most 0 when it sees it), with a slack against the rounding of both.
inline double shortfall(double distance, double margin, double x, double y)
{
  const double slack = 1e-9 * (distance + std::abs(x) + std::abs(y));
  return distance + slack - margin;
}

// The distance from point i to its m-th neighbor in its row; infinity when the row is shorter.
inline double neighbor_distance(const Oriented_point_set& s, std::size_t i, unsigned int m)
{
  if(s.neighbor_offsets[i + 1] - s.neighbor_offsets[i] < m)
    return std::numeric_limits<double>::infinity();
  return std::sqrt(CGAL::squared_distance(s.points[i], s.points[s.neighbor_indices[s.neighbor_offsets[i] + m - 1]]));
}

// The most a point of `needed` lacks to see its `k`-th neighbor among the read points (0: every one
// sees it, so its row is the union's); infinity when a row is short while some points are unread.
inline double largest_shortfall(const Oriented_point_set& s, const std::vector<std::size_t>& needed, unsigned int k,
                                const Lidar_io::Tile_catalog& catalog, const CGAL::Bbox_2& region)
{
  std::vector<double> distances(needed.size());
  double farthest = 0.;
  for(std::size_t n = 0; n < needed.size(); ++n)
  {
    distances[n] = neighbor_distance(s, needed[n], k);
    if(!std::isfinite(distances[n]))
      return distances[n];
    const auto& p = s.points[needed[n]];
    farthest = (std::max)(farthest, shortfall(distances[n], 0., p.x(), p.y())); // the reach it needs
  }
  // a tile farther from the region than every distance and its slack cannot hold a nearer point
  const Unread_space unread(catalog, region, farthest * (1. + 1e-6) + 1e-6);
  double largest = 0.;
  for(std::size_t n = 0; n < needed.size(); ++n)
  {
    const auto& p = s.points[needed[n]];
    largest = (std::max)(largest, shortfall(distances[n], unread.margin(p.x(), p.y()), p.x(), p.y()));
  }
  return largest;
}

// A halo that holds the neighborhoods, from the rows of a narrower one. Points added to a read set
// only bring neighbors nearer, so the distances read bound the union's from above: the union's `k`
// neighbors of a tile's point p lie within d_k(p) of it, and (when normals are estimated on `n`
// neighbors) the `n` neighbors of each of them within |pq| + d_n(q) of p, or, for a neighbor q not
// read yet, within d_k(p) + d_n(p) (the ball of radius d_n(p) around p holds n points besides q). A
// halo that holds that ball around every point of the tile passes the check of the next reading.
// Infinity when a row is short (too few points read to bound anything).
inline double sufficient_halo_width(const Oriented_point_set& s, std::pair<std::size_t, std::size_t> own,
                                    unsigned int k, unsigned int estimation_neighbors, const CGAL::Bbox_2& extent)
{
  double width = 0.;
  for(std::size_t i = own.first; i < own.second; ++i)
  {
    const double d_k = neighbor_distance(s, i, k);
    double needed = d_k;
    if(estimation_neighbors > 0)
    {
      needed = d_k + neighbor_distance(s, i, estimation_neighbors);
      for(std::size_t r = s.neighbor_offsets[i]; std::isfinite(needed) && r < s.neighbor_offsets[i] + k; ++r)
      {
        const std::size_t q = s.neighbor_indices[r];
        needed = (std::max)(needed, std::sqrt(CGAL::squared_distance(s.points[i], s.points[q])) +
                                      neighbor_distance(s, q, estimation_neighbors));
      }
    }
    if(!std::isfinite(needed))
      return needed;
    const auto& p = s.points[i]; // in the tile's extent: `inside` is at least 0
    const double inside = (std::min)({p.x() - extent.xmin(), extent.xmax() - p.x(), p.y() - extent.ymin(),
                                      extent.ymax() - p.y()});
    // twice the check's slack, so that rounding cannot fail it again
    width = (std::max)(width, shortfall(needed * (1. + 1e-9), inside, p.x(), p.y()) +
                                1e-9 * (needed + std::abs(p.x()) + std::abs(p.y())));
  }
  return width;
}

} // namespace internal

SIGMOID_NEIGHBORHOODS_READERS_FUNCTION Oriented_point_set
read_catalog_union(const Lidar_io::Tile_catalog& catalog, const Normal_options& options)
{
  internal::Catalog_points read = internal::read_catalog_points(catalog, nullptr);
  internal::finish_catalog_points(read, options);
  return std::move(read.set);
}

SIGMOID_NEIGHBORHOODS_READERS_FUNCTION Tile_with_halo
read_tile_with_halo(const Lidar_io::Tile_catalog& catalog, std::size_t tile, unsigned int k,
                    const Normal_options& options, const Halo_options& halo)
{
  if(tile >= catalog.tiles.size())
    throw std::invalid_argument("read_tile_with_halo: tile " + std::to_string(tile) + " of a catalog of " +
                                std::to_string(catalog.tiles.size()));
  if(k == 0)
    throw std::invalid_argument("read_tile_with_halo: k must be at least 1");
  const Lidar_io::Catalog_tile& own = catalog.tiles[tile];
  Normal_options o = options;
  o.kept_neighbors = (std::max)(k, o.kept_neighbors);

  Tile_with_halo result;
  result.exact = true;
  if(!(halo.initial_width >= 0. && halo.minimum_width >= 0. && std::isfinite(halo.initial_width) &&
       std::isfinite(halo.minimum_width)))
    throw std::invalid_argument("read_tile_with_halo: halo widths must be finite and at least 0");
  const bool may_estimate = o.source != Normal_source::FROM_FILE;
  double width = halo.initial_width > 0. ? halo.initial_width
                                         : internal::first_halo_width(own, k, may_estimate ? o.neighbors : 0);
  width = (std::max)(width, halo.minimum_width);
  for(result.readings = 1;; ++result.readings)
  {
    const CGAL::Bbox_2 region = internal::widened(own.extent, width);
    // the rows first: a halo too narrow is seen on them, before any normal is estimated
    internal::Catalog_points read = internal::read_catalog_points(catalog, &region);
    if(read.range_of(tile).first == read.range_of(tile).second)
    {
      // no point of its own (an empty file, or one of seam duplicates): nothing to compute, no halo
      result.seam_duplicates = read.merged_into_earlier_tiles(tile);
      result.input_points = read.input_points_of(tile);
      return result;
    }
    const bool estimated = internal::estimates_normals(read, o);
    internal::compute_catalog_rows(read, o);
    const auto own_range = read.range_of(tile);
    const Oriented_point_set& s = read.set;
    const internal::Unread_space unread(catalog, region);

    // the rows the records read: the tile's points' (k), those of the earlier tiles' points that its
    // seam duplicates were merged into (their records carry those points' results), and those of
    // their normals (the estimation's)
    double largest = 0.;
    if(!unread.empty() && own_range.first < own_range.second)
    {
      std::vector<std::size_t> needed;
      for(std::size_t i = own_range.first; i < own_range.second; ++i)
        needed.push_back(i);
      for(std::size_t r = read.tile_starts[tile]; r < read.tile_starts[tile + 1]; ++r)
        if(read.merged.position_of[r] < own_range.first)
          needed.push_back(read.merged.position_of[r]);
      largest = internal::largest_shortfall(s, needed, k, catalog, region);
      if(estimated && largest <= 0.)
      {
        std::vector<char> is_needed(s.points.size(), 0);
        for(std::size_t i : needed)
        {
          is_needed[i] = 1;
          for(std::size_t r = s.neighbor_offsets[i]; r < s.neighbor_offsets[i] + k; ++r)
            is_needed[s.neighbor_indices[r]] = 1;
        }
        needed.clear();
        for(std::size_t i = 0; i < s.points.size(); ++i)
          if(is_needed[i])
            needed.push_back(i);
        largest = internal::largest_shortfall(s, needed, o.neighbors, catalog, region);
      }
    }
    if(largest <= 0.)
    {
      internal::finish_catalog_points(read, o);
      const std::string extension = lower_case_extension(own.path);
      if(extension == "las" || extension == "laz") // read whole, record by record: one point each before the merge
        for(std::size_t r = read.tile_starts[tile]; r < read.tile_starts[tile + 1]; ++r)
          result.point_of_record.push_back(read.merged.position_of[r]);
      result.points = std::move(read.set);
      result.first = own_range.first;
      result.last = own_range.second;
      result.seam_duplicates = read.merged_into_earlier_tiles(tile);
      result.input_points = read.input_points_of(tile);
      result.halo_width = width;
      result.exact = o.orientation != Normal_orientation::SPANNING_FOREST || !result.points.normals_estimated;
      return result;
    }
    if(result.readings == internal::MAXIMUM_HALO_READINGS)
      throw Input_error(own.path + ": no halo up to " + std::to_string(width) + " holds the neighborhoods of the tile");
    const double sufficient =
      std::isfinite(largest)
        ? internal::sufficient_halo_width(s, own_range, k, estimated ? o.neighbors : 0, own.extent)
        : largest;
    width = std::isfinite(sufficient) ? (std::max)(sufficient, width + largest) : 2. * width;
  }
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_TILE_WITH_HALO_IMPL_H
