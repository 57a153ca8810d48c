// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_READ_TILE_CATALOG_H
#define SIGMOID_NEIGHBORHOODS_READERS_READ_TILE_CATALOG_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <Lidar_io/Tile_catalog.h>
#include <Lidar_io/read_tile_catalog.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Bbox_3.h>

#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

// Lidar_io::read_tile_catalog() with every tile format the readers know: the extent of a PLY, XYZ
// or PWN tile is found by reading its points.
inline Lidar_io::Tile_catalog read_tile_catalog(const std::string& folder_or_list)
{
  return Lidar_io::read_tile_catalog(folder_or_list, [](const std::string& path, Lidar_io::Catalog_tile& tile) {
    const Oriented_point_set points = read_oriented_point_set(path, 0); // points only
    const CGAL::Bbox_3 box = CGAL::bbox_3(points.points.begin(), points.points.end());
    tile.extent = CGAL::Bbox_2(box.xmin(), box.ymin(), box.xmax(), box.ymax());
    tile.points = points.points.size();
  });
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_READ_TILE_CATALOG_H
