// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "commands.h"

#include "catalog_input.h"
#include "command_line.h"
#include "json.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const CATALOG_COMMAND_USAGE =
  "usage: sigmoid-neighborhoods catalog list SOURCE [--names]\n"
  "       sigmoid-neighborhoods catalog merge SOURCE DIR... -o OUT.csv\n"
  "       sigmoid-neighborhoods catalog retile INPUT.las|INPUT.laz --size S -o DIR [--origin X Y]\n"
  "         [--format las|laz] [--threads N] [--buffer 64] [--open-files 64]\n"
  "  SOURCE: a folder of tiles (.las .laz .ply .xyz .pwn, in name order) or a text file listing them\n"
  "  list: one line per tile, in the catalog's order: name,points,xmin,ymin,xmax,ymax,path\n"
  "      (--names: the names alone, for GNU parallel or a Slurm array)\n"
  "  merge: the CSV outputs NAME.csv of 'optimal --catalog SOURCE --tile NAME', found in the\n"
  "      folders DIR, checked (every tile of SOURCE exactly once, computed on this catalog with the\n"
  "      same settings, its rows all there) and concatenated in the catalog's order: the CSV of the\n"
  "      union in one run\n"
  "  retile: INPUT (LAS or LAZ) cut into the square cells [ox + i S, ox + (i+1) S) x [oy + j S,\n"
  "      oy + (j+1) S) (origin 0 0 by default), streamed in bounded memory; DIR (created; holding no\n"
  "      tiles) receives one DIR/STEM_I_J.las (or .laz) per cell holding points, a LAS 1.4 file with\n"
  "      the input's point format, scale, offset, VLRs and EVLRs, its records byte for byte in the\n"
  "      input's order, its own counts and bounds. --format: las or laz (default: as the input is);\n"
  "      --threads: LAZ chunks decoded and tiles written in parallel (default: every core).\n"
  "      I and J are zero-padded so that name order is (i, j) order; an axis with a negative index\n"
  "      is written plus 10^w (w: the digits of its largest index), which the summary line says;\n"
  "      --buffer: MiB of records waiting to be written, all tiles together; --open-files: tile files\n"
  "      open at once (the others are reopened to append)\n";

int run_list(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1, {}, {"-h", "--help", "--names"});
  if(print_help(args, CATALOG_COMMAND_USAGE))
    return EXIT_OK;
  if(args.positional().size() != 1)
    throw Usage_error("catalog list needs SOURCE");
  const Lidar_io::Tile_catalog catalog = read_catalog_argument(args.positional()[0]);
  for(const Lidar_io::Catalog_tile& t : catalog.tiles)
  {
    if(args.has("--names"))
    {
      std::cout << t.name << '\n';
      continue;
    }
    std::cout << t.name << ',' << t.points;
    for(double v : {t.extent.xmin(), t.extent.ymin(), t.extent.xmax(), t.extent.ymax()})
    {
      std::cout << ',';
      print_number(std::cout, v);
    }
    std::cout << ',' << t.path << '\n';
  }
  return EXIT_OK;
}

// The largest tile description read: some 400 bytes are written.
constexpr std::uintmax_t LARGEST_TILE_DESCRIPTION = std::uintmax_t(1) << 16;

struct Tile_output
{
  std::string csv, description;
  std::uint64_t rows = 0;
  std::string command, settings;
};

Tile_output read_tile_output(const std::string& folder, const Lidar_io::Catalog_tile& tile, const std::string& fingerprint,
                             std::size_t tiles)
{
  Tile_output t;
  t.csv = (std::filesystem::path(folder) / (tile.name + ".csv")).string();
  t.description = tile_description_path(t.csv);
  const Json_value j = read_json_file(t.description, LARGEST_TILE_DESCRIPTION);
  const Json_object d(j, t.description);
  if(d.string("tile") != tile.name)
    throw Usage_error(t.description + ": describes tile '" + d.string("tile") + "', not " + tile.name);
  if(d.integer("catalog_tiles") != tiles || d.string("catalog_fingerprint") != fingerprint)
    throw Usage_error(t.description + ": computed on another catalog (other tiles or other sizes)");
  if(!d.boolean("exact"))
    std::cerr << "sigmoid-neighborhoods catalog merge: " << tile.name
              << ": normals oriented by a spanning forest, whose signs may differ from the union's across seams\n";
  t.rows = d.integer("rows");
  t.command = d.string("command");
  t.settings = d.string("settings");
  return t;
}

// Copies the rows of `t` after its header to `out`, checking the header and the count.
void append_rows(const Tile_output& t, std::string& header, std::ostream& out)
{
  std::ifstream in(t.csv, std::ios::binary);
  if(!in)
    throw Usage_error(t.csv + ": cannot open the file (its description is there: the tile's output is incomplete)");
  std::string line;
  if(!std::getline(in, line))
    throw Usage_error(t.csv + ": empty, expected a header and " + std::to_string(t.rows) + " rows");
  if(header.empty())
  {
    header = line;
    out << header << '\n';
  }
  else if(line != header)
    throw Usage_error(t.csv + ": its header differs from the first tile's");
  std::uint64_t rows = 0;
  while(std::getline(in, line))
  {
    out << line << '\n';
    ++rows;
  }
  if(in.bad())
    throw Usage_error(t.csv + ": read error");
  if(rows != t.rows)
    throw Usage_error(t.csv + ": " + std::to_string(rows) + " rows, its description says " + std::to_string(t.rows));
}

int run_merge_tiles(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1, {"-o", "--output"}, {"-h", "--help"});
  if(print_help(args, CATALOG_COMMAND_USAGE))
    return EXIT_OK;
  if(args.positional().size() < 2)
    throw Usage_error("catalog merge needs SOURCE and at least one DIR");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error("catalog merge needs -o OUT.csv");
  const Lidar_io::Tile_catalog catalog = read_catalog_argument(args.positional()[0]);
  const std::vector<std::string> folders(args.positional().begin() + 1, args.positional().end());
  const std::string fingerprint = catalog_fingerprint(catalog);

  // Every description in the folders names a tile of the catalog; every tile is there once.
  std::map<std::string, std::string> folder_of;
  for(const std::string& folder : folders)
  {
    std::error_code ec;
    if(!std::filesystem::is_directory(folder, ec))
      throw Usage_error(folder + ": not a folder");
    for(std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    {
      const std::string file = it->path().filename().string();
      const std::string suffix = ".tile.json";
      if(file.size() <= suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      const std::string name = file.substr(0, file.size() - suffix.size());
      const auto inserted = folder_of.emplace(name, folder);
      if(!inserted.second)
        throw Usage_error("tile " + name + " is in two folders: " + inserted.first->second + " and " + folder);
    }
    if(ec)
      throw Usage_error(folder + ": cannot list the folder (" + ec.message() + ")");
  }
  std::vector<std::string> missing;
  for(const Lidar_io::Catalog_tile& t : catalog.tiles)
    if(folder_of.count(t.name) == 0)
      missing.push_back(t.name);
  if(!missing.empty())
  {
    std::string list;
    for(std::size_t i = 0; i < missing.size() && i < 10; ++i)
      list += (i == 0 ? "" : ", ") + missing[i];
    throw Usage_error(std::to_string(missing.size()) + " of " + std::to_string(catalog.tiles.size()) +
                      " tiles have no output: " + list + (missing.size() > 10 ? ", ..." : ""));
  }
  if(folder_of.size() != catalog.tiles.size())
    for(const auto& f : folder_of)
    {
      bool known = false;
      for(const Lidar_io::Catalog_tile& t : catalog.tiles)
        known = known || t.name == f.first;
      if(!known)
        throw Usage_error(f.second + ": " + f.first + ".tile.json is not a tile of " + args.positional()[0]);
    }

  std::vector<Tile_output> outputs;
  for(const Lidar_io::Catalog_tile& t : catalog.tiles)
  {
    outputs.push_back(read_tile_output(folder_of[t.name], t, fingerprint, catalog.tiles.size()));
    if(outputs.back().command != outputs.front().command || outputs.back().settings != outputs.front().settings)
      throw Usage_error(outputs.back().description + ": computed by '" + outputs.back().command + " " +
                        outputs.back().settings + "', the first tile by '" + outputs.front().command + " " +
                        outputs.front().settings + "'");
  }
  std::uint64_t rows = 0;
  write_file_atomically(output, [&](std::ofstream& out) {
    std::string header;
    for(const Tile_output& t : outputs)
    {
      append_rows(t, header, out);
      rows += t.rows;
    }
  });
  std::cerr << output << ": " << rows << " rows of " << outputs.size() << " tiles\n";
  return EXIT_OK;
}

} // namespace

int run_catalog(int argc, char** argv)
{
  const std::string sub = argc > 2 ? argv[2] : "";
  if(sub == "list")
    return run_list(argc, argv);
  if(sub == "merge")
    return run_merge_tiles(argc, argv);
  if(sub == "retile")
    return run_catalog_retile(argc, argv, CATALOG_COMMAND_USAGE);
  if(sub == "-h" || sub == "--help")
  {
    std::cout << CATALOG_COMMAND_USAGE;
    return EXIT_OK;
  }
  throw Usage_error("catalog needs list, merge or retile\n" + std::string(CATALOG_COMMAND_USAGE));
}

} // namespace sigmoid_tool
