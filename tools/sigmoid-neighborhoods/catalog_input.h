// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input of a command run on a catalog of tiles (--catalog, --tile, --halo): one tile with its
// halo, or the union of all tiles; and the description of a tile's output that `catalog merge` checks.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_INPUT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_INPUT_H

#include "command_line.h"
#include "model_input.h"
#include "phase_times.h"

#include <Sigmoid_neighborhoods_readers/read_tile_catalog.h>
#include <Sigmoid_neighborhoods_readers/read_tile_with_halo.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;

const std::vector<std::string> CATALOG_OPTIONS = {"--catalog", "--tile", "--halo"};

inline const char* CATALOG_USAGE =
  "  catalog: --catalog SOURCE instead of INPUT: the tiles of a survey (SOURCE: a folder of .las .ply .xyz\n"
  "      files, in name order, or a text file listing them) processed as one point set;\n"
  "      --tile NAME: that tile alone, with a halo of the other tiles' points that provably holds\n"
  "      every neighborhood, so that its rows are those of the union, bit for bit (orientation mst\n"
  "      excepted); writes OUT's rows and, next to it, OUT without extension + .tile.json for\n"
  "      'catalog merge'; without --tile, the union in one run; --halo WIDTH: the first halo (default:\n"
  "      from the tile's density; when it does not hold every neighborhood, a second one computed from\n"
  "      its rows does); estimated normals are\n"
  "      oriented upwards (--orientation up) unless --orientation or --viewpoint says otherwise\n";

std::vector<std::string> with_catalog_options(std::vector<std::string> valued);

std::vector<std::string> without_catalog_options(std::vector<std::string> valued);

// The points a command computes on: a model, a catalog's union or a tile with its halo. Its rows are
// model.points[first] ... [last - 1]; the others are the halo.
struct Input_points
{
  SN::Oriented_point_set model;
  std::size_t first = 0, last = 0;
  std::size_t halo_points = 0;       // the points read around the tile (the model may move on)
  std::string source;                // what was read, for the messages
  bool is_tile = false;
  SN::Tile_with_halo halo;           // when is_tile: everything but its points
  CGAL::Bbox_2 tile_extent;          // when is_tile: the tile's extent in x and y, which the halo widens
  std::string tile_name;
  std::string catalog_fingerprint;   // the tiles, their order and their sizes
  std::size_t catalog_tiles = 0;
};

// The tiles of SOURCE, in order, with their point counts: two runs of one catalog agree on it.
std::string catalog_fingerprint(const Lidar_io::Tile_catalog& catalog);

Lidar_io::Tile_catalog read_catalog_argument(const std::string& source);

// The points of the command: INPUT, or --catalog with or without --tile; `k` is the neighbors of the
// computation (the halo holds them), `minimum_halo` what else it needs around the tile, `leading`
// the positional arguments before INPUT (classify predict's MODEL).
Input_points read_input_points(const Arguments& args, const std::string& command, unsigned int k,
                                      const SN::Normal_options& normals, double minimum_halo = 0.,
                                      std::size_t leading = 0);

// The line of the halo for the command's message: "tile T: N points, halo W m (R readings, H points)".
std::string halo_description(const Input_points& in);

// The file `catalog merge` reads next to a tile's output OUT: OUT without extension + ".tile.json".
std::string tile_description_path(const std::string& output);

// The options that decide a tile's rows: every option but the outputs, the tile and the threads.
std::string settings_text(const Arguments& args);

// What `catalog merge` checks of a tile's output: which tile, of which catalog, computed how, rows.
// `more_settings`: what else decides the rows, e.g. a model read from a file.
// `times`: the run's wall time ("seconds") and its phases ("phases")
void write_tile_description(const std::string& output, const std::string& command, const Arguments& args,
                                   const Input_points& in, const Phase_times& times,
                                   const std::string& more_settings = std::string());

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_INPUT_H
