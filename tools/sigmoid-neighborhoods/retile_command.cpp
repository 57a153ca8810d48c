// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods catalog retile`: one LAS or LAZ file cut into square tiles, a catalog for
// `optimal --catalog`. Two streamed passes, so that the memory does not grow with the input: the
// input's records (decoded by chunks on --threads when compressed) go to one temporary file of raw
// records per tile, each tile's records waiting in a bounded buffer and a bounded number of those
// files open at once (the others reopened to append); then every tile is written from its
// temporary by the package's LAS 1.4 or LAZ writer, tiles in parallel. A tile holds the input's
// point format, scale, offset, VLRs and EVLRs (las_output_layout_like()), its own records byte for
// byte in the input's order, and its own counts and bounds.
//
// A translation unit of its own: the LAZ decoder and encoder it instantiates compile beside
// `catalog list` and `merge`, not after them.

#include "commands.h"

#include "command_line.h"
#include "phase_times.h"

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Lidar_io/Las_writer.h>
#include <Lidar_io/Laz_writer.h>
#include <Lidar_io/las_output_layout_like.h>
#include <Lidar_io/little_endian.h>
#include <Lidar_io/read_las_records.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <unistd.h>

namespace sigmoid_tool {
namespace {

// What bounds the memory and the open files of a retile, whatever the size of the input.
constexpr std::size_t RETILE_READ_BYTES = std::size_t(1) << 22;        // records read at a time
constexpr std::size_t RETILE_TILE_BUFFER_BYTES = std::size_t(1) << 20; // one tile's records before a write, at most
constexpr double RETILE_DEFAULT_BUFFER_MIB = 64.;                       // all tiles' records waiting, together
constexpr unsigned int RETILE_DEFAULT_OPEN_FILES = 64;                  // far below the usual limit of 1024
constexpr std::size_t RETILE_LARGEST_TILE_COUNT = 100000;              // files in one folder
constexpr double RETILE_LARGEST_CELL_INDEX = 1e15;                     // the names stay short

// --buffer and --open-files: the memory of the records waiting to be written, all tiles together,
// and the tile files open at once.
struct Retile_limits
{
  std::size_t waiting_bytes = std::size_t(RETILE_DEFAULT_BUFFER_MIB * 1024 * 1024);
  std::size_t open_files = RETILE_DEFAULT_OPEN_FILES;

  // A tile writes its records once it holds an eighth of the buffer (a few writes of many tiles
  // share it), 1 MiB at most.
  std::size_t tile_bytes() const { return (std::min)(RETILE_TILE_BUFFER_BYTES, waiting_bytes / 8); }
};

// How the cell indices of one axis are written in the tile names: zero-padded to one width, so that
// the bytewise order of the names is the order of the indices. When an index of the axis is
// negative, every index of the axis is written plus 10^w, w the digits of the largest magnitude,
// on w + 1 digits.
struct Cell_index_format
{
  std::uint64_t bias = 0;
  int width = 1;

  Cell_index_format(std::int64_t lowest, std::int64_t highest)
  {
    const std::uint64_t largest = (std::max)(lowest < 0 ? std::uint64_t(-(lowest + 1)) + 1 : std::uint64_t(lowest),
                                             highest < 0 ? std::uint64_t(-(highest + 1)) + 1 : std::uint64_t(highest));
    std::uint64_t power = 10;
    for(width = 1; largest >= power; ++width)
      power *= 10;
    if(lowest < 0)
    {
      bias = power;
      ++width;
    }
  }

  std::string text(std::int64_t index) const
  {
    const std::uint64_t shifted = index < 0 ? bias - (std::uint64_t(-(index + 1)) + 1) : bias + std::uint64_t(index);
    std::string digits = std::to_string(shifted);
    return std::string(std::size_t((std::max)(0, width - int(digits.size()))), '0') + digits;
  }
};

// One output tile while the input streams: its records waiting, the temporary file of its raw
// records, then the temporary of the tile as written.
struct Retiled_tile
{
  std::int64_t i = 0, j = 0;
  std::string records_path, tile_path;
  std::uint64_t count = 0;
  std::vector<unsigned char> waiting;
  std::unique_ptr<std::ofstream> file; // null while closed
  std::uint64_t last_use = 0;
  bool records_started = false, tile_started = false; // the temporaries exist
};

// The tiles of one retile, written in the folder under temporary names; a failure (an exception,
// the destructor without commit()) removes every one of them.
class Retiled_tiles
{
public:
  Retiled_tiles(std::size_t record_length, const std::string& folder, const std::string& stem,
                const Retile_limits& limits)
    : m_record_length(record_length), m_folder(folder), m_stem(stem), m_limits(limits)
  {
  }

  Retiled_tiles(const Retiled_tiles&) = delete;
  Retiled_tiles& operator=(const Retiled_tiles&) = delete;

  ~Retiled_tiles()
  {
    for(Retiled_tile& t : m_tiles)
    {
      t.file.reset();
      if(t.records_started)
        std::remove(t.records_path.c_str());
      if(t.tile_started)
        std::remove(t.tile_path.c_str());
    }
    for(const std::string& path : m_committed_on_failure)
      std::remove(path.c_str());
  }

  std::size_t size() const { return m_tiles.size(); }

  void add(std::int64_t i, std::int64_t j, const unsigned char* record)
  {
    Retiled_tile& t = tile(i, j);
    ++t.count;
    const std::size_t held = t.waiting.capacity();
    t.waiting.insert(t.waiting.end(), record, record + m_record_length);
    m_held += t.waiting.capacity() - held;
    if(t.waiting.size() >= m_limits.tile_bytes())
      write_waiting(t);
    if(m_held >= m_limits.waiting_bytes)
      release_largest_buffers();
  }

  // Writes what waits; every tile's raw records are then in its temporary, complete.
  void finish_records()
  {
    for(Retiled_tile& t : m_tiles)
      write_waiting(t);
    for(Retiled_tile& t : m_tiles)
      close(t);
    for(Retiled_tile& t : m_tiles)
      std::vector<unsigned char>().swap(t.waiting);
  }

  // Writes every tile with the layout `layout` (LAZ when `compressed`) from its raw records, tiles
  // on `threads` threads (or, with fewer tiles than threads, one tile at a time on all of them),
  // and removes the raw records.
  void write_tiles(const Lidar_io::Las_output_layout& layout, bool compressed,
                   unsigned int threads)
  {
    const bool tiles_in_parallel = m_tiles.size() >= threads;
    for(Retiled_tile& t : m_tiles)
      t.tile_path = t.records_path + (compressed ? ".laz" : ".las");
    std::string failure;
    const std::int64_t n = std::int64_t(m_tiles.size());
#pragma omp parallel for schedule(dynamic) num_threads(tiles_in_parallel ? int(threads) : 1)
    for(std::int64_t k = 0; k < n; ++k)
    {
      std::string message;
      try
      {
        write_tile(m_tiles[std::size_t(k)], layout, compressed, tiles_in_parallel ? 1u : threads);
      }
      catch(const std::exception& e)
      {
        message = e.what();
      }
      if(!message.empty())
      {
#pragma omp critical(sigmoid_neighborhoods_retile_failure)
        if(failure.empty())
          failure = message;
      }
    }
    if(!failure.empty())
      throw Usage_error(failure);
  }

  // Renames the tiles' temporaries to their names, STEM_I_J.las (or .laz): the tiles are there,
  // complete; `note` receives how the indices are written when an axis has negative ones.
  void commit(const std::string& extension, std::string& note)
  {
    std::int64_t i_low = m_tiles.front().i, i_high = i_low, j_low = m_tiles.front().j, j_high = j_low;
    for(const Retiled_tile& t : m_tiles)
    {
      i_low = (std::min)(i_low, t.i);
      i_high = (std::max)(i_high, t.i);
      j_low = (std::min)(j_low, t.j);
      j_high = (std::max)(j_high, t.j);
    }
    const Cell_index_format i_format(i_low, i_high), j_format(j_low, j_high);
    for(const auto& axis : {std::make_pair('i', i_format), std::make_pair('j', j_format)})
      if(axis.second.bias != 0)
        note += std::string(", ") + axis.first + " + " + std::to_string(axis.second.bias) + " in the names";
    for(Retiled_tile& t : m_tiles)
    {
      const std::string name = (std::filesystem::path(m_folder) /
                                (m_stem + "_" + i_format.text(t.i) + "_" + j_format.text(t.j) + "." + extension))
                                 .string();
      if(std::rename(t.tile_path.c_str(), name.c_str()) != 0)
        throw write_error(name);
      t.tile_started = false;
      m_committed_on_failure.push_back(name);
    }
    m_committed_on_failure.clear();
  }

private:
  static Usage_error write_error(const std::string& path)
  {
    return Usage_error("cannot write " + path + ": " + (errno != 0 ? std::strerror(errno) : "write error"));
  }

  // The tile `t` written whole from its raw records (RETILE_READ_BYTES at a time), which are then removed.
  void write_tile(Retiled_tile& t, const Lidar_io::Las_output_layout& layout, bool compressed,
                  unsigned int threads) const
  {
    namespace SN = CGAL::Sigmoid_neighborhoods;
    std::ifstream records(t.records_path, std::ios::binary);
    if(!records)
      throw Usage_error("cannot read " + t.records_path + " back: " + std::strerror(errno));
    errno = 0;
    t.tile_started = true;
    std::ofstream out(t.tile_path, std::ios::binary | std::ios::trunc);
    if(!out)
      throw write_error(t.tile_path);
    auto copy = [&](auto& writer) {
      std::vector<unsigned char> block;
      const std::uint64_t block_records = (std::max)(std::size_t(1), RETILE_READ_BYTES / m_record_length);
      for(std::uint64_t left = t.count; left != 0;)
      {
        const std::size_t count = std::size_t((std::min)(left, block_records));
        block.resize(count * m_record_length);
        if(!records.read(reinterpret_cast<char*>(block.data()), std::streamsize(block.size())))
          throw Usage_error(t.records_path + ": the tile's records read back short");
        writer.write(block.data(), count);
        left -= count;
      }
      writer.close();
    };
    try
    {
      if(compressed)
      {
        Lidar_io::Laz_writer<> writer(out, layout, threads);
        copy(writer);
      }
      else
      {
        Lidar_io::Las_writer writer(out, layout);
        copy(writer);
      }
    }
    catch(const std::ios_base::failure&)
    {
      throw write_error(t.tile_path);
    }
    out.close();
    if(out.fail())
      throw write_error(t.tile_path);
    records.close();
    std::remove(t.records_path.c_str());
    t.records_started = false;
  }

  Retiled_tile& tile(std::int64_t i, std::int64_t j)
  {
    if(m_last < m_tiles.size() && m_tiles[m_last].i == i && m_tiles[m_last].j == j)
      return m_tiles[m_last]; // the records of a scan come mostly in runs of one tile
    const auto found = m_index.emplace(std::make_pair(i, j), m_tiles.size());
    if(found.second)
    {
      if(m_tiles.size() == RETILE_LARGEST_TILE_COUNT)
        throw Usage_error("more than " + std::to_string(RETILE_LARGEST_TILE_COUNT) +
                          " tiles: choose a larger --size");
      m_tiles.emplace_back();
      Retiled_tile& t = m_tiles.back();
      t.i = i;
      t.j = j;
      t.records_path = (std::filesystem::path(m_folder) / (m_stem + ".retile" + std::to_string(m_tiles.size() - 1) +
                                                           TEMPORARY_SUFFIX + std::to_string(::getpid())))
                         .string();
    }
    m_last = found.first->second;
    return m_tiles[m_last];
  }

  // Writes the records of the tiles that hold the most memory and frees it, down to half the buffer.
  void release_largest_buffers()
  {
    std::vector<std::size_t> order;
    for(std::size_t k = 0; k < m_tiles.size(); ++k)
      if(m_tiles[k].waiting.capacity() != 0)
        order.push_back(k);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return m_tiles[a].waiting.capacity() > m_tiles[b].waiting.capacity();
    });
    for(std::size_t k : order)
    {
      if(m_held <= m_limits.waiting_bytes / 2)
        break;
      Retiled_tile& t = m_tiles[k];
      write_waiting(t);
      m_held -= t.waiting.capacity();
      std::vector<unsigned char>().swap(t.waiting);
    }
  }

  void write_waiting(Retiled_tile& t)
  {
    if(t.waiting.empty())
      return;
    std::ofstream& out = open(t);
    errno = 0;
    if(!out.write(reinterpret_cast<const char*>(t.waiting.data()), std::streamsize(t.waiting.size())))
      throw write_error(t.records_path);
    t.waiting.clear(); // its memory kept for the next records, counted in m_held
  }

  std::ofstream& open(Retiled_tile& t)
  {
    t.last_use = ++m_clock;
    if(t.file)
      return *t.file;
    if(m_open.size() >= m_limits.open_files)
    {
      const auto oldest = std::min_element(m_open.begin(), m_open.end(), [&](std::size_t a, std::size_t b) {
        return m_tiles[a].last_use < m_tiles[b].last_use;
      });
      close(m_tiles[*oldest]);
    }
    errno = 0;
    t.file.reset(
      new std::ofstream(t.records_path, std::ios::binary | (t.records_started ? std::ios::app : std::ios::trunc)));
    t.records_started = true;
    if(!*t.file)
      throw write_error(t.records_path);
    m_open.push_back(std::size_t(&t - m_tiles.data()));
    return *t.file;
  }

  void close(Retiled_tile& t)
  {
    if(!t.file)
      return;
    errno = 0;
    t.file->close();
    const bool failed = t.file->fail();
    t.file.reset();
    m_open.erase(std::find(m_open.begin(), m_open.end(), std::size_t(&t - m_tiles.data())));
    if(failed)
      throw write_error(t.records_path);
  }

  std::size_t m_record_length;
  std::string m_folder, m_stem;
  Retile_limits m_limits;
  std::vector<Retiled_tile> m_tiles;
  std::map<std::pair<std::int64_t, std::int64_t>, std::size_t> m_index;
  std::size_t m_last = std::size_t(-1);
  std::vector<std::size_t> m_open; // the tiles whose file is open
  std::uint64_t m_clock = 0;
  std::size_t m_held = 0; // the memory of the tiles' buffers: what --buffer bounds
  std::vector<std::string> m_committed_on_failure;
};
// --origin X Y, taken out of the arguments: Arguments reads options of one or of three values.
std::vector<char*> take_origin(int argc, char** argv, double& x, double& y)
{
  std::vector<char*> rest(argv, argv + argc);
  for(std::size_t k = FIRST_COMMAND_ARGUMENT + 1; k < rest.size(); ++k)
  {
    if(std::string(rest[k]) != "--origin")
      continue;
    double values[2];
    for(int c = 0; c < 2; ++c)
    {
      const char* text = k + 1 + c < rest.size() ? rest[k + 1 + c] : "";
      char* end = nullptr;
      values[c] = std::strtod(text, &end);
      if(*text == '\0' || *end != '\0' || !std::isfinite(values[c]))
        throw Usage_error("--origin needs two finite numbers: --origin X Y");
    }
    x = values[0];
    y = values[1];
    rest.erase(rest.begin() + std::ptrdiff_t(k), rest.begin() + std::ptrdiff_t(k) + 3);
    --k;
  }
  return rest;
}

// A folder that holds no tiles yet: the tiles of another cut in it would join this catalog.
void check_retile_folder(const std::string& folder)
{
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if(ec)
    throw Usage_error("cannot create " + folder + ": " + ec.message());
  for(std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
  {
    const std::string extension = CGAL::Sigmoid_neighborhoods::lower_case_extension(it->path().string());
    if(extension == "las" || extension == "laz" || extension == "ply" || extension == "xyz" || extension == "pwn")
      throw Usage_error(folder + " already holds tiles (" + it->path().filename().string() +
                        "): retile into a new or an empty folder");
  }
  if(ec)
    throw Usage_error(folder + ": cannot list the folder (" + ec.message() + ")");
}

// What the arguments ask for.
struct Retile_request
{
  std::string input, folder, format; // format: las or laz, the tiles' compression
  double size = 0., origin_x = 0., origin_y = 0.;
  Retile_limits limits;
  unsigned int threads = 1;
};

Retile_request read_retile_request(const Arguments& args, double origin_x, double origin_y)
{
  if(args.positional().size() != 1)
    throw Usage_error("catalog retile needs exactly one INPUT.las or INPUT.laz");
  Retile_request r;
  r.origin_x = origin_x;
  r.origin_y = origin_y;
  r.input = args.positional()[0];
  r.folder = args.output();
  if(r.folder.empty())
    throw Usage_error("catalog retile needs -o DIR");
  if(!args.has("--size"))
    throw Usage_error("catalog retile needs --size S");
  r.size = args.get_double("--size", 0.);
  if(!(r.size > 0.) || !std::isfinite(r.size))
    throw Usage_error("--size must be a positive, finite tile side, got '" + args.get("--size") + "'");
  const double buffer = args.get_double("--buffer", RETILE_DEFAULT_BUFFER_MIB);
  if(!(buffer >= 0.01 && buffer <= 1024. * 1024.))
    throw Usage_error("--buffer must be 0.01 to 1048576 MiB, got '" + args.get("--buffer") + "'");
  r.limits.waiting_bytes = std::size_t(buffer * 1024 * 1024);
  r.limits.open_files = args.get_unsigned("--open-files", RETILE_DEFAULT_OPEN_FILES);
  if(r.limits.open_files == 0)
    throw Usage_error("--open-files must be at least 1");
  r.threads = resolved_threads(read_threads(args));

  const std::string extension = CGAL::Sigmoid_neighborhoods::lower_case_extension(r.input);
  if(extension != "las" && extension != "laz")
    throw Usage_error(r.input + ": not a .las or .laz file");
  // The tiles are compressed as the input is, unless --format says otherwise.
  r.format = args.has("--format") ? args.get("--format") : extension;
  if(r.format != "las" && r.format != "laz")
    throw Usage_error("--format must be las or laz, got '" + r.format + "'");
  return r;
}

// The input's header and the layout its tiles are written with, refused when no tile can be written.
void read_retile_input(const Retile_request& r, Lidar_io::Las_header& header, Lidar_io::Las_output_layout& layout)
{
  try
  {
    header = Lidar_io::read_las_header(r.input);
    layout = Lidar_io::las_output_layout_like(r.input, {});
  }
  catch(const CGAL::Sigmoid_neighborhoods::Input_error& e)
  {
    throw Usage_error(r.input + ": " + e.what());
  }
  if(header.point_count == 0)
    throw Usage_error(r.input + ": no points, no tile to write");
  const unsigned int f = header.point_format;
  if(r.format == "laz" && Lidar_io::las_format_has_wave_packets(f))
    throw Usage_error(r.input + ": point format " + std::to_string(f) +
                      " refers to waveform packets, which LAZ tiles are not written with: --format las");
}

// The first pass: every record of the input into its tile's buffer, full buffers written as they
// fill. Returns the seconds spent sorting the records, apart from decoding them.
double sort_into_tiles(const Retile_request& r, const Lidar_io::Las_header& header, Retiled_tiles& tiles)
{
  double tiling_seconds = 0.;
  try
  {
    Lidar_io::read_las_records(
      r.input,
      [&](std::size_t first, const unsigned char* records, std::size_t count) {
        const auto start = std::chrono::steady_clock::now();
        for(std::size_t k = 0; k < count; ++k)
        {
          const unsigned char* record = records + k * header.record_length;
          std::int64_t cell[2];
          for(int c = 0; c < 2; ++c)
          {
            // The cells of compute_height_features(), shifted by the origin: floor((x - ox) / S).
            const double coordinate =
              double(Lidar_io::load_little_endian<std::int32_t>(record + 4 * c)) * header.scale[c] + header.offset[c];
            const double index = std::floor((coordinate - (c == 0 ? r.origin_x : r.origin_y)) / r.size);
            if(!(std::abs(index) < RETILE_LARGEST_CELL_INDEX))
              throw Usage_error(r.input + ": point " + std::to_string(first + k) + " lies " +
                                (std::isfinite(index) ? "more than 1e15 tiles from the origin"
                                                      : "at a non-finite coordinate"));
            cell[c] = std::int64_t(index);
          }
          tiles.add(cell[0], cell[1], record);
        }
        tiling_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      },
      r.threads);
  }
  catch(const CGAL::Sigmoid_neighborhoods::Input_error& e)
  {
    throw Usage_error(r.input + ": " + e.what());
  }
  return tiling_seconds;
}

int run_retile(int argc, char** argv, const char* usage)
{
  Phase_times times;
  double origin_x = 0., origin_y = 0.;
  std::vector<char*> rest = take_origin(argc, argv, origin_x, origin_y);
  const Arguments args(int(rest.size()), rest.data(), FIRST_COMMAND_ARGUMENT + 1,
                       {"-o", "--output", "--size", "--buffer", "--open-files", "--format", "--threads"},
                       {"-h", "--help"});
  if(print_help(args, usage))
    return EXIT_OK;
  const Retile_request r = read_retile_request(args, origin_x, origin_y);
  Lidar_io::Las_header header;
  Lidar_io::Las_output_layout layout;
  read_retile_input(r, header, layout);
  check_retile_folder(r.folder);

  Retiled_tiles tiles(header.record_length, r.folder, std::filesystem::path(r.input).stem().string(), r.limits);
  const double tiling_seconds = sort_into_tiles(r, header, tiles);
  times.end("reading");
  times.move("reading", "tiling", tiling_seconds);
  tiles.finish_records();
  tiles.write_tiles(layout, r.format == "laz", r.threads);
  std::string note;
  tiles.commit(r.format, note);
  times.end("writing");
  char timing[32];
  std::snprintf(timing, sizeof(timing), "%.1f s", times.total());
  std::cerr << r.folder << ": " << header.point_count << " points of " << r.input << " in " << tiles.size()
            << (tiles.size() == 1 ? " tile" : " tiles") << " of side " << number17(r.size)
            << (r.format == "laz" ? " (LAZ)" : "")
            << (!layout.evlrs.empty()
                  ? ", its EVLRs and waveform data (" + std::to_string(layout.evlrs.size()) + " bytes) in every tile"
                  : std::string())
            << note << ", " << timing << " (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace

int run_catalog_retile(int argc, char** argv, const char* usage) { return run_retile(argc, argv, usage); }

} // namespace sigmoid_tool
