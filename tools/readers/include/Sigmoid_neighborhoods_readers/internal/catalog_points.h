// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CATALOG_POINTS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CATALOG_POINTS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Lidar_io/Tile_catalog.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/estimate_normals.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/merge_equal_positions.h>
#include <Sigmoid_neighborhoods_readers/internal/read_las.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

inline bool holds(const CGAL::Bbox_2& box, double x, double y)
{
  return box.xmin() <= x && x <= box.xmax() && box.ymin() <= y && y <= box.ymax();
}

inline bool do_meet(const CGAL::Bbox_2& a, const CGAL::Bbox_2& b)
{
  return a.xmin() <= b.xmax() && b.xmin() <= a.xmax() && a.ymin() <= b.ymax() && b.ymin() <= a.ymax();
}

inline Input_error outside_extent(const Lidar_io::Catalog_tile& tile, std::size_t point, double x, double y)
{
  return Input_error(tile.path + ": point " + std::to_string(point) + " at x " + std::to_string(x) + ", y " +
                     std::to_string(y) + " lies outside the tile's extent in the catalog" +
                     (tile.extent_from_header ? " (the header's bounding box is wrong)" : ""));
}

// The points of a catalog's tiles within a region, in the global order, merged.
struct Catalog_points
{
  Oriented_point_set set;
  bool has_normals = false;
  std::vector<std::size_t> tile_starts; // per tile, then one more: its first point before the merge
  std::vector<std::size_t> merged_in_files; // per tile read whole: merged by the file's reader (PLY, XYZ)
  Merged_positions merged;

  // The tile's points after the merge (its points that no earlier tile has): [first, second).
  std::pair<std::size_t, std::size_t> range_of(std::size_t tile) const
  {
    const auto at = [&](std::size_t start) {
      return std::size_t(std::lower_bound(merged.first.begin(), merged.first.end(), start) - merged.first.begin());
    };
    return {at(tile_starts[tile]), at(tile_starts[tile + 1])};
  }

  // The points of the tile's file, with those its reader merged.
  std::size_t input_points_of(std::size_t tile) const
  {
    return tile_starts[tile + 1] - tile_starts[tile] + merged_in_files[tile];
  }

  // The tile's points merged into a point of an earlier tile.
  std::size_t merged_into_earlier_tiles(std::size_t tile) const
  {
    const std::size_t first = range_of(tile).first;
    std::size_t count = 0;
    for(std::size_t i = tile_starts[tile]; i < tile_starts[tile + 1]; ++i)
      count += merged.position_of[i] < first;
    return count;
  }
};

// Every per-point field that the tiles before had, this one has, and no other (a label column in
// one tile only would shift the labels of the union).
inline void check_same_fields(const Oriented_point_set& s, const Lidar_io::Catalog_tile& tile)
{
  const std::size_t n = s.points.size();
  const std::size_t sizes[] = {s.labels.size(), s.intensities.size(), s.return_numbers.size(),
                               s.numbers_of_returns.size(), s.gps_times.size()};
  for(std::size_t size : sizes)
    if(size != 0 && size != n)
      throw Input_error(tile.path + ": its per-point fields (labels, LAS intensities, returns, GPS times) differ "
                                    "from those of the tiles before it in the catalog");
}

// Appends the points of `tile` within `region` (all of them when null), checked against its extent.
inline void append_tile_points(const Lidar_io::Catalog_tile& tile, const CGAL::Bbox_2* region, Catalog_points& out, bool first)
{
  const auto keep = [&](std::size_t point, double x, double y) {
    if(!holds(tile.extent, x, y))
      throw outside_extent(tile, point, x, y);
    return region == nullptr || holds(*region, x, y);
  };
  Oriented_point_set& s = out.set;
  bool has_normals = false;
  try
  {
    const std::string extension = lower_case_extension(tile.path);
    if(extension == "las" || extension == "laz")
    {
      const Input_file file = open_input_file(tile.path, {"las", "laz"}, ".las or .laz");
      read_las(file, s, [&](std::size_t point, const double* xyz) { return keep(point, xyz[0], xyz[1]); });
    }
    else
    {
      Oriented_point_set file = read_oriented_point_set(tile.path, 0); // the file's normals, if any
      has_normals = !file.normals.empty();
      if(region == nullptr || (region->xmin() <= tile.extent.xmin() && tile.extent.xmax() <= region->xmax() &&
                               region->ymin() <= tile.extent.ymin() && tile.extent.ymax() <= region->ymax()))
        out.merged_in_files.back() = file.merged_duplicates; // the whole file is read: its count is the read part's
      for(std::size_t i = 0; i < file.points.size(); ++i)
      {
        const auto& p = file.points[i];
        if(!keep(i, p.x(), p.y()))
          continue;
        s.points.push_back(p);
        if(has_normals)
          s.normals.push_back(file.normals[i]);
        if(!file.labels.empty())
          s.labels.push_back(file.labels[i]);
      }
    }
  }
  catch(const Input_error& e)
  {
    const std::string what = e.what();
    throw what.compare(0, tile.path.size(), tile.path) == 0 ? e : Input_error(tile.path + ": " + what);
  }
  if(first)
    out.has_normals = has_normals;
  else if(has_normals != out.has_normals)
    throw Input_error(tile.path + (has_normals ? ": has normals, the tiles before it have none"
                                               : ": has no normals, the tiles before it have"));
  check_same_fields(s, tile);
}

// The points of the tiles of `catalog` within `region` (all when null), in the global order:
// merged, without normals yet.
inline Catalog_points read_catalog_points(const Lidar_io::Tile_catalog& catalog, const CGAL::Bbox_2* region)
{
  Catalog_points out;
  bool first = true;
  for(const Lidar_io::Catalog_tile& tile : catalog.tiles)
  {
    out.tile_starts.push_back(out.set.points.size());
    out.merged_in_files.push_back(0);
    if(region == nullptr || do_meet(tile.extent, *region))
    {
      append_tile_points(tile, region, out, first);
      first = false;
    }
  }
  out.tile_starts.push_back(out.set.points.size());
  out.set.input_vertices = out.set.points.size();
  out.merged = merge_duplicate_points(out.set, out.has_normals);
  for(std::size_t merged : out.merged_in_files)
  {
    out.set.merged_duplicates += merged;
    out.set.input_vertices += merged;
  }
  return out;
}

// Whether the normals of the read points are estimated (else the files').
inline bool estimates_normals(const Catalog_points& read, const Normal_options& o)
{
  if(read.set.points.empty())
    throw Input_error("no points in the catalog's tiles");
  if(!read.has_normals && o.source == Normal_source::FROM_FILE)
    throw Input_error("the tiles have no normals");
  const bool estimated = !read.has_normals || o.source == Normal_source::PCA || o.source == Normal_source::JET;
  if(estimated && o.neighbors == 0)
    throw Input_error("the tiles have no normals, and none are estimated");
  return estimated;
}

// The rows of the steps after and of the estimation, as estimate_normals() computes them, so that
// it reuses them.
inline void compute_catalog_rows(Catalog_points& read, const Normal_options& o)
{
  Oriented_point_set& s = read.set;
  const unsigned int wanted = estimates_normals(read, o) ? (std::max)(o.neighbors, o.kept_neighbors) : o.kept_neighbors;
  if(wanted == 0 || s.points.size() < 2)
    return;
  compute_k_nearest_neighbors<Parallel_if_available_tag>(
    s.points, unsigned((std::min)(std::size_t(wanted), s.points.size() - 1)), s.neighbor_indices, s.neighbor_offsets,
    parameters::number_of_threads(o.threads, CGAL::parameters::point_map(CGAL::Identity_property_map<Oriented_point_set::Point_3>())));
}

// Normals as read_oriented_point_set() gives them, on the read points, and the rows of
// `o.kept_neighbors` neighbors (those of compute_catalog_rows() when computed).
inline void finish_catalog_points(Catalog_points& read, const Normal_options& o)
{
  if(estimates_normals(read, o))
    estimate_normals(read.set, o);
  else if(read.set.neighbor_offsets.empty())
    compute_catalog_rows(read, o);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CATALOG_POINTS_H
