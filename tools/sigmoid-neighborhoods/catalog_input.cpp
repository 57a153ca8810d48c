// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// catalog_input.h, compiled once for the tool.

#include "catalog_input.h"

namespace sigmoid_tool {

std::vector<std::string> with_catalog_options(std::vector<std::string> valued)
{
  valued.insert(valued.end(), CATALOG_OPTIONS.begin(), CATALOG_OPTIONS.end());
  return valued;
}

std::vector<std::string> without_catalog_options(std::vector<std::string> valued)
{
  valued.erase(std::remove_if(valued.begin(), valued.end(),
                              [](const std::string& o) {
                                return std::find(CATALOG_OPTIONS.begin(), CATALOG_OPTIONS.end(), o) !=
                                       CATALOG_OPTIONS.end();
                              }),
               valued.end());
  return valued;
}

std::string catalog_fingerprint(const Lidar_io::Tile_catalog& catalog)
{
  std::string text;
  for(const Lidar_io::Catalog_tile& t : catalog.tiles)
    text += t.name + ':' + std::to_string(t.points) + ';';
  std::uint64_t hash = 14695981039346656037ull; // FNV-1a: the same on every machine and build
  for(unsigned char c : text)
    hash = (hash ^ c) * 1099511628211ull;
  return std::to_string(hash);
}

Lidar_io::Tile_catalog read_catalog_argument(const std::string& source)
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

Input_points read_input_points(const Arguments& args, const std::string& command, unsigned int k,
                                      const SN::Normal_options& normals, double minimum_halo,
                                      std::size_t leading)
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
  const Lidar_io::Tile_catalog catalog = read_catalog_argument(source);
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
  in.tile_extent = catalog.tiles[tile].extent;
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

std::string halo_description(const Input_points& in)
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

std::string tile_description_path(const std::string& output)
{
  const std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + ".tile.json")).string();
}

std::string settings_text(const Arguments& args)
{
  std::string text;
  for(const auto& option : args.options())
    if(option.first != "-o" && option.first != "--output" && option.first != "--ply" && option.first != "--tile" &&
       option.first != "--threads" && option.first != "--halo" && option.first != "--color" &&
       option.first != "--catalog")
      text += (text.empty() ? "" : " ") + option.first + (option.second.empty() ? "" : " " + option.second);
  return text;
}

void write_tile_description(const std::string& output, const std::string& command, const Arguments& args,
                                   const Input_points& in, const Phase_times& times,
                                   const std::string& more_settings)
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
  d["seconds"] = times.total();
  d["phases"] = times.json();
  write_file_atomically(tile_description_path(output), [&](std::ofstream& out) { out << d.dump(2) << '\n'; });
}
} // namespace sigmoid_tool
