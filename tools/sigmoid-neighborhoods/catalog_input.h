// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input of a command run on a catalog of tiles (--catalog, --tile, --halo): one tile with its
// halo, or the union of all tiles; and the description of a tile's output that `catalog merge` checks.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_INPUT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_INPUT_H

#include "command_line.h"
#include "model_input.h"

#include <CGAL/Sigmoid_neighborhoods/IO/read_tile_catalog.h>
#include <CGAL/Sigmoid_neighborhoods/IO/read_tile_with_halo.h>

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

inline std::vector<std::string> with_catalog_options(std::vector<std::string> valued)
{
  valued.insert(valued.end(), CATALOG_OPTIONS.begin(), CATALOG_OPTIONS.end());
  return valued;
}

inline std::vector<std::string> without_catalog_options(std::vector<std::string> valued)
{
  valued.erase(std::remove_if(valued.begin(), valued.end(),
                              [](const std::string& o) {
                                return std::find(CATALOG_OPTIONS.begin(), CATALOG_OPTIONS.end(), o) !=
                                       CATALOG_OPTIONS.end();
                              }),
               valued.end());
  return valued;
}

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
  std::string tile_name;
  std::string catalog_fingerprint;   // the tiles, their order and their sizes
  std::size_t catalog_tiles = 0;
};

// The tiles of SOURCE, in order, with their point counts: two runs of one catalog agree on it.
inline std::string catalog_fingerprint(const SN::Tile_catalog& catalog)
{
  std::string text;
  for(const SN::Catalog_tile& t : catalog.tiles)
    text += t.name + ':' + std::to_string(t.points) + ';';
  std::uint64_t hash = 14695981039346656037ull; // FNV-1a: the same on every machine and build
  for(unsigned char c : text)
    hash = (hash ^ c) * 1099511628211ull;
  return std::to_string(hash);
}

inline SN::Tile_catalog read_catalog_argument(const std::string& source)
{
  try
  {
    return SN::read_tile_catalog(source);
  }
  catch(const SN::Input_error& e)
  {
    throw Usage_error(std::string("--catalog: ") + e.what());
  }
}

// The points of the command: INPUT, or --catalog with or without --tile; `k` is the neighbors of the
// computation (the halo holds them), `minimum_halo` what else it needs around the tile, `leading`
// the positional arguments before INPUT (classify predict's MODEL).
inline Input_points read_input_points(const Arguments& args, const std::string& command, unsigned int k,
                                      const SN::Normal_options& normals, double minimum_halo = 0.,
                                      std::size_t leading = 0)
{
  Input_points in;
  if(!args.has("--catalog"))
  {
    if(args.has("--tile") || args.has("--halo"))
      throw Usage_error("--tile and --halo go with --catalog");
    if(args.positional().size() != leading + 1)
      throw Usage_error(command + " needs exactly one INPUT, or --catalog SOURCE");
    in.source = args.positional()[leading];
    in.model = read_input(in.source, [&] { return read_model(in.source, k, normals); });
    in.last = in.model.points.size();
    return in;
  }
  if(args.positional().size() != leading)
    throw Usage_error(command + " takes --catalog SOURCE or INPUT, not both");
  const std::string source = args.get("--catalog");
  const SN::Tile_catalog catalog = read_catalog_argument(source);
  in.catalog_fingerprint = catalog_fingerprint(catalog);
  in.catalog_tiles = catalog.tiles.size();
  SN::Normal_options o = normals;
  o.kept_neighbors = k;
  // surveys cut into tiles are airborne: upwards, which is exact per tile, unless asked otherwise
  if(!args.has("--orientation") && !args.has("--viewpoint"))
    o.orientation = SN::Normal_orientation::UPWARD;
  if(!args.has("--tile"))
  {
    if(args.has("--halo"))
      throw Usage_error("--halo goes with --tile");
    in.source = source;
    in.model = read_input(source, [&] { return SN::read_catalog_union(catalog, o); });
    if(in.model.points.size() < std::size_t(k) + 1)
      throw Usage_error(source + ": needs at least " + std::to_string(k + 1) + " distinct points, got " +
                        std::to_string(in.model.points.size()));
    in.last = in.model.points.size();
    return in;
  }
  in.tile_name = args.get("--tile");
  const double halo = args.get_double("--halo", 0.);
  if(!(halo >= 0.) || !std::isfinite(halo))
    throw Usage_error("--halo must be a width of at least 0");
  std::size_t tile = 0;
  try
  {
    tile = catalog.index_of(in.tile_name);
  }
  catch(const SN::Input_error& e)
  {
    throw Usage_error(source + ": " + e.what());
  }
  in.source = catalog.tiles[tile].path;
  in.is_tile = true;
  SN::Halo_options halo_options;
  halo_options.initial_width = halo;
  halo_options.minimum_width = minimum_halo;
  // k = 0 (no neighborhood, e.g. heights alone): the halo still starts from the nearest neighbor
  in.halo = read_input(source, [&] {
    return SN::read_tile_with_halo(catalog, tile, (std::max)(k, 1u), o, halo_options);
  });
  in.model = std::move(in.halo.points);
  in.first = in.halo.first;
  in.last = in.halo.last;
  in.halo_points = in.model.points.size() - (in.last - in.first);
  if(in.first < in.last && in.model.points.size() < std::size_t(k) + 1)
    throw Usage_error(source + ": needs at least " + std::to_string(k + 1) + " distinct points, got " +
                      std::to_string(in.model.points.size()));
  return in;
}

// The line of the halo for the command's message: "tile T: N points, halo W m (R readings, H points)".
inline std::string halo_description(const Input_points& in)
{
  if(!in.is_tile)
    return std::string();
  char width[32];
  std::snprintf(width, sizeof(width), "%.3g", in.halo.halo_width);
  return ", tile " + in.tile_name + ": " + std::to_string(in.last - in.first) + " points, halo " + width + " (" +
         std::to_string(in.halo.readings) + (in.halo.readings == 1 ? " reading, " : " readings, ") +
         std::to_string(in.halo_points) + " points)" +
         (in.halo.seam_duplicates == 0 ? std::string()
                                       : ", " + std::to_string(in.halo.seam_duplicates) + " seam duplicates") +
         (in.halo.exact ? std::string() : ", orientation mst: not exact across seams");
}

// The file `catalog merge` reads next to a tile's output OUT: OUT without extension + ".tile.json".
inline std::string tile_description_path(const std::string& output)
{
  const std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + ".tile.json")).string();
}

// The options that decide a tile's rows: every option but the outputs, the tile and the threads.
inline std::string settings_text(const Arguments& args)
{
  std::string text;
  for(const auto& option : args.options())
    if(option.first != "-o" && option.first != "--output" && option.first != "--ply" && option.first != "--tile" &&
       option.first != "--threads" && option.first != "--halo" && option.first != "--color" &&
       option.first != "--catalog")
      text += (text.empty() ? "" : " ") + option.first + (option.second.empty() ? "" : " " + option.second);
  return text;
}

// What `catalog merge` checks of a tile's output: which tile, of which catalog, computed how, rows.
// `more_settings`: what else decides the rows, e.g. a model read from a file.
inline void write_tile_description(const std::string& output, const std::string& command, const Arguments& args,
                                   const Input_points& in, double seconds,
                                   const std::string& more_settings = std::string())
{
  if(!in.is_tile)
    return;
  nlohmann::ordered_json d;
  d["tile"] = in.tile_name;
  d["command"] = command;
  const std::string settings = settings_text(args);
  d["settings"] = more_settings.empty() ? settings : settings + (settings.empty() ? "" : " ") + more_settings;
  d["catalog_tiles"] = in.catalog_tiles;
  d["catalog_fingerprint"] = in.catalog_fingerprint;
  d["rows"] = in.last - in.first;
  d["halo_points"] = in.halo_points;
  d["halo_width"] = in.halo.halo_width;
  d["readings"] = in.halo.readings;
  d["seam_duplicates"] = in.halo.seam_duplicates;
  d["exact"] = in.halo.exact;
  d["seconds"] = seconds;
  write_file_atomically(tile_description_path(output), [&](std::ofstream& out) { out << d.dump(2) << '\n'; });
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CATALOG_INPUT_H
