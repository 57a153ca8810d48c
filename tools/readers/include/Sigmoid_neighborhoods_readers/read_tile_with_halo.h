// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_READ_TILE_WITH_HALO_H
#define SIGMOID_NEIGHBORHOODS_READERS_READ_TILE_WITH_HALO_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Lidar_io/Tile_catalog.h>
#include <Sigmoid_neighborhoods_readers/config.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  one tile of a `Lidar_io::Tile_catalog` with its halo, as `read_tile_with_halo()` reads it.
*/
struct Tile_with_halo
{
  /// the tile's points and its halo's, distinct, in the catalog's global order, with their normals
  /// and the neighbor rows of the search (`Oriented_point_set::neighbor_indices`)
  Oriented_point_set points;
  std::size_t first = 0; ///< the tile's own points are `points.points[first]` ... `[last - 1]`
  std::size_t last = 0;  ///< see `first`
  double halo_width = 0.;         ///< how far beyond the tile's extent the halo reaches, in `x` and `y`
  unsigned int readings = 0;      ///< the halos read until one held every neighborhood
  std::size_t seam_duplicates = 0; ///< the tile's points merged into an earlier tile's point at their position
  std::size_t input_points = 0;    ///< the points of the tile's file (LAS: its records), before any merge
  /// for a LAS or LAZ tile, each record of its file, in the file's order: its point in `points` (one of
  /// the tile's own, or the earlier tile's point that a seam duplicate was merged into), so that a
  /// copy of the file's records can carry the results of their points; empty for other formats and
  /// for a tile without points of its own
  std::vector<std::size_t> point_of_record;
  /// the records of the tile's points are those of the union, bit for bit: every orientation but
  /// `Normal_orientation::SPANNING_FOREST`, whose forest crosses the tiles' seams
  bool exact = true;

  /// the number of the tile's own points; without any, `points` is empty
  std::size_t size() const { return last - first; }
};

/*!
  how wide `read_tile_with_halo()` starts its halo.
*/
struct Halo_options
{
  /// the first halo (0: four times where the neighbors of evenly spread points would reach, from
  /// the tile's density); when it does not hold every neighborhood, the next is computed from its rows
  double initial_width = 0.;
  /// the halo is never narrower: what a computation needs beyond neighborhoods, e.g. the side of the
  /// cells of `compute_height_features()`, whose cells then lie in the tile and its halo
  double minimum_width = 0.;
};


/*!
  \brief reads all the tiles of `catalog` as one point set, in the catalog's global order (see
  `Lidar_io::Tile_catalog`): the union that `read_tile_with_halo()` reproduces one tile at a time.

  Normals as `read_oriented_point_set()` gives them: the files' (every tile with normals, or none),
  or estimated and oriented on the union. `options.kept_neighbors` rows are kept for the steps after.

  \throws Input_error on an unusable tile (prefixed with its file), tiles whose per-point fields
  differ, a point outside its tile's extent, fewer points than the estimation needs.
*/
SIGMOID_NEIGHBORHOODS_READERS_FUNCTION Oriented_point_set
read_catalog_union(const Lidar_io::Tile_catalog& catalog, const Normal_options& options);

/*!
  \brief reads tile `tile` of `catalog` with a halo of points of the other tiles that holds the `k`
  nearest neighbors of every point of the tile, and what their normals need, in the union: the
  records of the tile's points computed on the result equal, bit for bit, those of the same points
  computed on `read_catalog_union()`.

  The halo is every point of the catalog within `halo_width` of the tile's extent in `x` and `y`.
  It starts at `halo.initial_width` (0: from the tile's density, four times where the neighbors of
  evenly spread points would reach), at least `halo.minimum_width`, and grows until it provably holds
  (the next halo computed from the rows of one too narrow holds, so a tile is read at most twice
  unless it has fewer points than `k`):
  - the `k` nearest neighbors, in the union, of every point of the tile: the `k`-th one found is
    nearer than any point outside the halo can be (the tiles' extents bound where those are);
  - when normals are estimated, the `options.neighbors` nearest neighbors of those points too, so that
    their normals are the union's.
  Only the tiles whose extents meet the halo are read, a LAS file a chunk at a time, so memory holds
  the tile and its halo, not the catalog. The points are in the catalog's global order; duplicates
  are merged into the first (a point of the tile at the position of an earlier tile's point is that
  point, counted in `Tile_with_halo::seam_duplicates`, and not one of the tile's own).

  Orientation: `Normal_orientation::UPWARD`, `VIEWPOINT` and `NONE` orient each normal alone, so the
  result is exact. `SPANNING_FOREST` grows its forest over the tile and its halo, every component
  from its highest point, as in one file; a component that crosses a seam may be oriented otherwise in
  the union: `Tile_with_halo::exact` is then false.

  \param catalog the tiles
  \param tile the position of the tile in `catalog.tiles`
  \param k the neighbors of the computation after (`k_max` of the optimal search); the result keeps
  the rows of `max(k, options.neighbors, options.kept_neighbors)` nearest neighbors
  \param options the normals, as for `read_catalog_union()`
  \param halo the first and the narrowest halo

  \throws Input_error as `read_catalog_union()` does, and when no halo within 64 readings holds the
  neighborhoods
  \throws std::invalid_argument when `tile` is not a position in `catalog.tiles`, `k` is 0 or a
  width of `halo` is negative or not finite
*/
SIGMOID_NEIGHBORHOODS_READERS_FUNCTION Tile_with_halo
read_tile_with_halo(const Lidar_io::Tile_catalog& catalog, std::size_t tile, unsigned int k,
                    const Normal_options& options, const Halo_options& halo = Halo_options());

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef SIGMOID_NEIGHBORHOODS_READERS_COMPILED
#include <Sigmoid_neighborhoods_readers/internal/read_tile_with_halo_impl.h>
#endif

#endif // SIGMOID_NEIGHBORHOODS_READERS_READ_TILE_WITH_HALO_H
