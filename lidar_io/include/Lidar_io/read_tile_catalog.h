// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_READ_TILE_CATALOG_H
#define LIDAR_IO_READ_TILE_CATALOG_H

#include <Lidar_io/Input_error.h>
#include <Lidar_io/Tile_catalog.h>
#include <Lidar_io/config.h>

#include <functional>
#include <string>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  finds the extent in `x` and `y` and the number of points of a tile that is not a LAS file (a PLY
  or XYZ file has no header that gives them), by reading it: sets `tile.extent` and `tile.points`,
  and throws `Input_error` when the file cannot be read.
*/
typedef std::function<void(const std::string& path, Catalog_tile& tile)> Tile_extent_reader;

/*!
  \ingroup PkgLidarIo
  \brief indexes the tiles of a survey: their names, files and extents, in the catalog's order.

  \param folder_or_list a folder, whose `.las`, `.ply`, `.xyz` and `.pwn` files are the tiles in the
  order of their names (bytewise), or a text file listing one tile per line (paths relative to its
  folder, `#` comments), in the order listed

  \param read_other_format finds the extent of a tile of another format than LAS (PLY, XYZ, PWN);
  without it, such a tile is an `Input_error`

  LAS extents come from the headers, widened by one scale step against rounding in the writer, and
  are trusted for the tiles a computation does not read; every tile a computation reads is checked
  against its extent (`Input_error` when a point lies outside). The other formats have no header
  that gives an extent: `read_other_format` reads them once, one at a time, to find it.

  \throws Input_error when the catalog is empty, a file is unreadable, or two tiles have one name
*/
LIDAR_IO_FUNCTION Tile_catalog
read_tile_catalog(const std::string& folder_or_list, const Tile_extent_reader& read_other_format = {});

} // namespace Lidar_io

#ifndef LIDAR_IO_COMPILED
#include <Lidar_io/internal/read_tile_catalog_impl.h>
#endif

#endif // LIDAR_IO_READ_TILE_CATALOG_H
