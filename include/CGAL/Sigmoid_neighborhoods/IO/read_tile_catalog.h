// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_TILE_CATALOG_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_TILE_CATALOG_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Tile_catalog.h>
#include <CGAL/Sigmoid_neighborhoods/IO/config.h>

#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {


/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  \brief indexes the tiles of a survey: their names, files and extents, in the catalog's order.

  \param folder_or_list a folder, whose `.las`, `.ply`, `.xyz` and `.pwn` files are the tiles in the
  order of their names (bytewise), or a text file listing one tile per line (paths relative to its
  folder, `#` comments), in the order listed

  LAS extents come from the headers, widened by one scale step against rounding in the writer, and
  are trusted for the tiles a computation does not read; every tile a computation reads is checked
  against its extent (`Input_error` when a point lies outside). PLY and XYZ files have no header
  that gives an extent: they are read once, one at a time, to find it.

  \throws Input_error when the catalog is empty, a file is unreadable or compressed (LAZ), or two
  tiles have one name
*/
CGAL_SIGMOID_NEIGHBORHOODS_IO_FUNCTION Tile_catalog
read_tile_catalog(const std::string& folder_or_list);

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_tile_catalog_impl.h>
#endif

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_TILE_CATALOG_H
