// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_TILE_CATALOG_H
#define LIDAR_IO_TILE_CATALOG_H

#include <Lidar_io/Input_error.h>

#include <CGAL/Bbox_2.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  one file of a `Tile_catalog`: a part of a survey cut in `x` and `y`.
*/
struct Catalog_tile
{
  std::string name;         ///< the file name without folder and extension; unique in its catalog
  std::string path;         ///< the file
  CGAL::Bbox_2 extent;      ///< holds every point of the file, in `x` and `y`
  std::uint64_t points = 0; ///< LAS: the records its header announces; other formats: the distinct points
  bool extent_from_header = false; ///< LAS: the header's bounding box, widened by one scale step
};

/*!
  \ingroup PkgLidarIo
  adjacent tiles processed as one point set, the union of their points; made by
  `read_tile_catalog()`, read by `read_tile_with_halo()` and `read_catalog_union()`.

  The **global order** of the union, which breaks the ties of distances and decides which of the
  points at one position is kept, is the catalog's order, then each file's own order: the points of
  `tiles[0]` in their file's order, then those of `tiles[1]`, and so on. Points at one position, in
  one tile or in two (a seam), are merged into the first in that order.
*/
struct Tile_catalog
{
  std::vector<Catalog_tile> tiles; ///< in the catalog's order

  /// the position of the tile named `name` in `tiles`, or `Input_error`
  std::size_t index_of(const std::string& name) const
  {
    for(std::size_t i = 0; i < tiles.size(); ++i)
      if(tiles[i].name == name)
        return i;
    throw Input_error("no tile named '" + name + "' in the catalog");
  }
};

} // namespace Lidar_io

#endif // LIDAR_IO_TILE_CATALOG_H
