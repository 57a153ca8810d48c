// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The definitions of read_tile_catalog.h: inline in the header-only build, compiled once into the
// library Lidar_io::compiled otherwise (config.h).

#ifndef LIDAR_IO_INTERNAL_READ_TILE_CATALOG_IMPL_H
#define LIDAR_IO_INTERNAL_READ_TILE_CATALOG_IMPL_H

#include <Lidar_io/read_tile_catalog.h>

#include <Lidar_io/Input_error.h>
#include <Lidar_io/Tile_catalog.h>
#include <Lidar_io/lower_case_extension.h>
#include <Lidar_io/internal/read_las_header.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace Lidar_io {

namespace internal {

inline bool is_tile_format(const std::string& extension)
{
  return extension == "las" || extension == "laz" || extension == "ply" || extension == "xyz" ||
         extension == "pwn";
}

// The tiles named in the list file `list`, one path per line relative to the list's folder
// (blank lines and lines starting with '#' skipped), in its order.
inline std::vector<std::string> read_tile_list(const std::string& list)
{
  std::ifstream in(list);
  if(!in)
    throw Input_error(list + ": cannot open the file");
  const std::filesystem::path folder = std::filesystem::path(list).parent_path();
  std::vector<std::string> paths;
  std::string line;
  while(std::getline(in, line))
  {
    const auto first = line.find_first_not_of(" \t\r");
    if(first == std::string::npos || line[first] == '#')
      continue;
    const auto last = line.find_last_not_of(" \t\r");
    const std::filesystem::path path(line.substr(first, last - first + 1));
    paths.push_back((path.is_absolute() ? path : folder / path).string());
  }
  if(in.bad())
    throw Input_error(list + ": read error");
  return paths;
}

// The point files of `folder` (by extension), sorted by name, byte by byte.
inline std::vector<std::string> list_tile_folder(const std::string& folder)
{
  std::vector<std::string> paths;
  std::error_code ec;
  for(std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if(it->is_regular_file(ec) && is_tile_format(lower_case_extension(it->path().string())))
      paths.push_back(it->path().string());
  if(ec)
    throw Input_error(folder + ": cannot list the folder (" + ec.message() + ")");
  std::sort(paths.begin(), paths.end(), [](const std::string& a, const std::string& b) {
    return std::filesystem::path(a).filename().string() < std::filesystem::path(b).filename().string();
  });
  return paths;
}

} // namespace internal

LIDAR_IO_FUNCTION Tile_catalog
read_tile_catalog(const std::string& folder_or_list, const Tile_extent_reader& read_other_format)
{
  std::error_code ec;
  const bool is_folder = std::filesystem::is_directory(folder_or_list, ec);
  if(!is_folder && !std::filesystem::exists(folder_or_list, ec))
    throw Input_error(folder_or_list + ": no such folder or file");
  const std::vector<std::string> paths =
    is_folder ? internal::list_tile_folder(folder_or_list) : internal::read_tile_list(folder_or_list);
  if(paths.empty())
    throw Input_error(folder_or_list + ": no tiles (.las, .ply, .xyz or .pwn files)");

  Tile_catalog catalog;
  std::map<std::string, std::string> path_of_name;
  for(const std::string& path : paths)
  {
    Catalog_tile tile;
    tile.path = path;
    tile.name = std::filesystem::path(path).stem().string();
    const auto named = path_of_name.emplace(tile.name, path);
    if(!named.second)
      throw Input_error(path + ": a second tile named '" + tile.name + "' (the first: " + named.first->second + ")");
    try
    {
      if(lower_case_extension(path) == "las" || lower_case_extension(path) == "laz")
      {
        const Las_header h = internal::read_las_header(path);
        for(int c = 0; c < 2; ++c)
          if(!(std::isfinite(h.min[c]) && std::isfinite(h.max[c])))
            throw Input_error("the header's bounding box is not finite");
        tile.extent = CGAL::Bbox_2(h.min[0] - std::abs(h.scale[0]), h.min[1] - std::abs(h.scale[1]),
                                   h.max[0] + std::abs(h.scale[0]), h.max[1] + std::abs(h.scale[1]));
        tile.points = h.point_count;
        tile.extent_from_header = true;
      }
      else if(read_other_format)
        read_other_format(path, tile);
      else
        throw Input_error("no reader for ." + lower_case_extension(path) + " tiles (only LAS)");
    }
    catch(const Input_error& e)
    {
      throw Input_error(path + ": " + e.what());
    }
    catalog.tiles.push_back(tile);
  }
  return catalog;
}

} // namespace Lidar_io

#endif // LIDAR_IO_INTERNAL_READ_TILE_CATALOG_IMPL_H
