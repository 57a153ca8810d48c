// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// generate_survey: a synthetic airborne lidar survey written as adjacent LAS 1.4 tiles (point format
// 6, scale 0.01 m), a catalog for `sigmoid-neighborhoods optimal --catalog`: smooth terrain, box
// buildings with flat or gabled roofs and their walls, trees with ellipsoid crowns (two returns
// where a pulse reaches the ground through a crown), small noise, ASPRS classes 2 (ground),
// 5 (vegetation) and 6 (building).
//
// The objects come from a global grid of cells, each drawn from its own generator seeded by the
// seed and the cell, and lie inside their cell: a tile sees the same buildings and trees as its
// neighbors across a seam. Each tile is scanned in lines (the order of an airborne scanner),
// written a chunk at a time: the memory does not grow with the survey. The same seed writes the
// same bytes.

#include <Lidar_io/Las_writer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

const char* const USAGE =
  "usage: generate_survey POINTS DIR [--tile-size S] [--density D] [--seed SEED] [--origin X Y] [--name STEM]\n"
  "  about POINTS points (150e6 is read) in m x m square tiles of side S metres (default 500), m the\n"
  "      nearest to sqrt(POINTS / D) / S, D about D points per square metre (default 15; the density\n"
  "      written is POINTS / (m S)^2, within a few percent)\n"
  "  DIR: created; one LAS 1.4 file per tile, DIR/STEM_I_J.las (default STEM: survey), I and J\n"
  "      zero-padded so that name order is a catalog's order; tile (I, J) covers\n"
  "      [X + I S, X + (I+1) S) x [Y + J S, Y + (J+1) S), --origin X Y (default 650000 6860000)\n"
  "  --seed: the same seed writes the same files (default 1)\n";

constexpr double PI = 3.14159265358979323846;
constexpr double SCALE = 0.01;
constexpr double OBJECT_CELL = 40.;      // the side of the cells the buildings and trees are drawn in
constexpr double WALL_REACH = 0.5;       // pulses this close outside a footprint may hit its wall
constexpr double NOISE = 0.03;           // standard deviation of the heights, metres
constexpr std::size_t CHUNK_POINTS = 1 << 16;
constexpr int CALIBRATION_PULSES = 4096; // pulses sampled per tile for its points per pulse
constexpr std::uint16_t RECORD_BYTES = 30;

struct Failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// splitmix64: a generator specified here, so the same seed gives the same survey everywhere.
std::uint64_t mix(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

struct Random
{
  std::uint64_t state;
  explicit Random(std::uint64_t seed) : state(seed) {}
  Random(std::uint64_t seed, std::uint64_t purpose, std::int64_t a, std::int64_t b)
    : state(mix(mix(mix(seed ^ mix(purpose)) ^ std::uint64_t(a)) ^ std::uint64_t(b)))
  {
  }
  std::uint64_t next() { return mix(state += 0x9E3779B97F4A7C15ull); }
  double uniform() { return double(next() >> 11) * (1. / 9007199254740992.); } // [0, 1)
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  double normal() // Box-Muller
  {
    const double u = 1. - uniform(), v = uniform();
    return std::sqrt(-2. * std::log(u)) * std::cos(2. * PI * v);
  }
};

enum Purpose : std::uint64_t { TERRAIN = 1, OBJECTS, CALIBRATION, SCAN };
enum Class : std::uint8_t { GROUND = 2, VEGETATION = 5, BUILDING = 6 };

struct Terrain
{
  double phase[4];
  explicit Terrain(std::uint64_t seed)
  {
    Random r(seed, TERRAIN, 0, 0);
    for(double& p : phase)
      p = r.uniform(0., 2. * PI);
  }
  // Local coordinates (metres from the origin): smooth hills, slopes of a few percent.
  double height(double x, double y) const
  {
    return 120. + 6. * std::sin(x / 173. + phase[0]) * std::cos(y / 211. + phase[1]) +
           2.5 * std::sin((x - y) / 97. + phase[2]) + 0.8 * std::sin(x / 31. + phase[3]) * std::cos(y / 43.);
  }
};

struct Building
{
  double x, y, cos_angle, sin_angle, half_length, half_width, base, eave, ridge_rise; // ridge_rise 0: flat
};

struct Tree
{
  double x, y, radius, crown_center, crown_half_height;
};

struct Cell_objects
{
  bool has_building = false;
  Building building{};
  std::vector<Tree> trees;
};

// The buildings and trees of object cell (cx, cy), inside it, from its own generator: a forest
// factor varying slowly over the cells makes woods and built-up areas.
Cell_objects cell_objects(std::uint64_t seed, const Terrain& terrain, std::int64_t cx, std::int64_t cy)
{
  Random r(seed, OBJECTS, cx, cy);
  Cell_objects o;
  const double forest = 0.5 + 0.5 * std::sin(double(cx) * 0.37 + terrain.phase[0]) *
                                    std::cos(double(cy) * 0.29 + terrain.phase[1]);
  const double x0 = double(cx) * OBJECT_CELL, y0 = double(cy) * OBJECT_CELL;
  double building_reach = 0.;
  if(r.uniform() < 0.55 * (1. - forest))
  {
    Building& b = o.building;
    o.has_building = true;
    b.half_length = r.uniform(5., 11.);
    b.half_width = r.uniform(4., std::min(8., b.half_length));
    building_reach = std::hypot(b.half_length, b.half_width) + WALL_REACH;
    b.x = x0 + r.uniform(building_reach + 0.5, OBJECT_CELL - building_reach - 0.5);
    b.y = y0 + r.uniform(building_reach + 0.5, OBJECT_CELL - building_reach - 0.5);
    const double angle = r.uniform(0., PI);
    b.cos_angle = std::cos(angle);
    b.sin_angle = std::sin(angle);
    b.base = terrain.height(b.x, b.y);
    b.eave = r.uniform(3., 10.);
    b.ridge_rise = r.uniform() < 0.6 ? r.uniform(1.5, 4.) : 0.;
  }
  const int trees = int(r.uniform() * (o.has_building ? 4. : 2. + 12. * forest));
  for(int t = 0; t < trees; ++t)
  {
    Tree tree;
    tree.radius = r.uniform(1.5, 4.5);
    tree.x = x0 + r.uniform(tree.radius + 0.5, OBJECT_CELL - tree.radius - 0.5);
    tree.y = y0 + r.uniform(tree.radius + 0.5, OBJECT_CELL - tree.radius - 0.5);
    tree.crown_half_height = tree.radius * r.uniform(1., 1.6);
    tree.crown_center = terrain.height(tree.x, tree.y) + r.uniform(1.5, 5.) + tree.crown_half_height;
    if(o.has_building &&
       std::hypot(tree.x - o.building.x, tree.y - o.building.y) < building_reach + tree.radius + 0.5)
      continue; // no tree in a house
    o.trees.push_back(tree);
  }
  return o;
}

struct Return
{
  double x, y, z;
  Class label;
  int number, of;
};

// One tile: its objects, and the returns of a pulse at (x, y).
class Tile_scene
{
public:
  Tile_scene(std::uint64_t seed, const Terrain& terrain, double x0, double y0, double side)
    : m_terrain(terrain), m_x0(x0), m_y0(y0), m_side(side)
  {
    m_cx0 = std::int64_t(std::floor(x0 / OBJECT_CELL));
    m_cy0 = std::int64_t(std::floor(y0 / OBJECT_CELL));
    m_columns = std::int64_t(std::floor((x0 + side) / OBJECT_CELL)) - m_cx0 + 1;
    const std::int64_t rows = std::int64_t(std::floor((y0 + side) / OBJECT_CELL)) - m_cy0 + 1;
    for(std::int64_t cy = 0; cy < rows; ++cy)
      for(std::int64_t cx = 0; cx < m_columns; ++cx)
        m_cells.push_back(cell_objects(seed, terrain, m_cx0 + cx, m_cy0 + cy));
  }

  bool inside(double x, double y) const
  {
    return x >= m_x0 && x < m_x0 + m_side && y >= m_y0 && y < m_y0 + m_side;
  }

  // The returns of a vertical pulse at (x, y) in the tile: 1, or 2 through a crown.
  int pulse(double x, double y, Random& r, Return* out) const
  {
    const std::int64_t cx = std::int64_t(std::floor(x / OBJECT_CELL)) - m_cx0;
    const std::int64_t cy = std::int64_t(std::floor(y / OBJECT_CELL)) - m_cy0;
    const Cell_objects& o = m_cells[std::size_t(cy * m_columns + cx)];
    const double ground = m_terrain.height(x, y) + NOISE * r.normal();
    if(o.has_building)
    {
      const Building& b = o.building;
      const double dx = x - b.x, dy = y - b.y;
      const double u = b.cos_angle * dx + b.sin_angle * dy, v = -b.sin_angle * dx + b.cos_angle * dy;
      if(std::abs(u) <= b.half_length && std::abs(v) <= b.half_width)
      {
        const double roof = b.base + b.eave + b.ridge_rise * (1. - std::abs(v) / b.half_width);
        out[0] = {x, y, roof + NOISE * r.normal(), BUILDING, 1, 1};
        return 1;
      }
      if(std::abs(u) <= b.half_length + WALL_REACH && std::abs(v) <= b.half_width + WALL_REACH && r.uniform() < 0.6)
      {
        // A slanted pulse hits the nearest wall, somewhere between the ground and the eave.
        const double wu = std::clamp(u, -b.half_length, b.half_length), wv = std::clamp(v, -b.half_width, b.half_width);
        const double wx = b.x + b.cos_angle * wu - b.sin_angle * wv, wy = b.y + b.sin_angle * wu + b.cos_angle * wv;
        if(inside(wx, wy))
        {
          const double foot = m_terrain.height(wx, wy);
          out[0] = {wx, wy, foot + r.uniform() * (b.base + b.eave - foot), BUILDING, 1, 1};
          return 1;
        }
      }
    }
    const Tree* hit = nullptr;
    double top = -1e300, chord = 0.;
    for(const Tree& t : o.trees)
    {
      const double q = ((x - t.x) * (x - t.x) + (y - t.y) * (y - t.y)) / (t.radius * t.radius);
      if(q >= 1.)
        continue;
      const double half_chord = t.crown_half_height * std::sqrt(1. - q);
      if(t.crown_center + half_chord > top)
      {
        hit = &t;
        top = t.crown_center + half_chord;
        chord = 2. * half_chord;
      }
    }
    if(hit != nullptr && r.uniform() >= 0.15) // else the pulse passes through a gap to the ground
    {
      const double depth = r.uniform();
      const double crown = top - depth * depth * chord + NOISE * r.normal();
      if(r.uniform() < 0.5)
      {
        out[0] = {x, y, crown, VEGETATION, 1, 2};
        out[1] = {x, y, ground, GROUND, 2, 2};
        return 2;
      }
      out[0] = {x, y, crown, VEGETATION, 1, 1};
      return 1;
    }
    out[0] = {x, y, ground, GROUND, 1, 1};
    return 1;
  }

private:
  const Terrain& m_terrain;
  double m_x0, m_y0, m_side;
  std::int64_t m_cx0 = 0, m_cy0 = 0, m_columns = 0;
  std::vector<Cell_objects> m_cells;
};

struct Survey
{
  std::uint64_t points = 0;
  std::string folder, stem = "survey";
  double tile_size = 500., density = 15.;
  std::uint64_t seed = 1;
  double origin_x = 650000., origin_y = 6860000.;
};

// A local engineering CRS: the coordinates are synthetic, in metres.
const std::string WKT = "LOCAL_CS[\"synthetic survey\",LOCAL_DATUM[\"none\",0],UNIT[\"metre\",1],"
                        "AXIS[\"X\",EAST],AXIS[\"Y\",NORTH]]";

// The layout of a tile: point format 6, centimetres from the survey's origin, its CRS as a WKT VLR,
// a fixed creation date (the files repeat bit for bit).
Lidar_io::Las_output_layout tile_layout(const Survey& s)
{
  Lidar_io::Las_output_layout l = Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{0., 0., 0.}}, {}, 6);
  l.scale = {{SCALE, SCALE, SCALE}};
  l.offset = {{s.origin_x, s.origin_y, 0.}};
  unsigned char* h = l.header.data();
  Lidar_io::store_little_endian<std::uint16_t>(h + 6, 0x11); // adjusted standard GPS time, WKT
  std::memset(h + 26, 0, 64);
  std::strncpy(reinterpret_cast<char*>(h + 26), "synthetic survey", 32);
  std::strncpy(reinterpret_cast<char*>(h + 58), "generate_survey", 32);
  Lidar_io::store_little_endian<std::uint16_t>(h + 90, 1);
  Lidar_io::store_little_endian<std::uint16_t>(h + 92, 2026);
  Lidar_io::add_las_vlr(l, "LASF_Projection", 2112, "OGC WKT",
                  std::vector<unsigned char>(WKT.c_str(), WKT.c_str() + WKT.size() + 1)); // with its null
  return l;
}

std::string zero_padded(std::int64_t value, int width)
{
  std::string digits = std::to_string(value);
  return std::string(std::size_t(std::max(0, width - int(digits.size()))), '0') + digits;
}

// Writes tile (i, j) of `tiles` x `tiles`, about `budget` points, through a temporary and a rename.
std::uint64_t write_tile(const Survey& s, const Terrain& terrain, std::int64_t i, std::int64_t j, int tiles,
                         std::uint64_t budget)
{
  const double side = s.tile_size;
  const double x0 = double(i) * side, y0 = double(j) * side;
  const Tile_scene scene(s.seed, terrain, x0, y0, side);
  Return returns[2];

  // The pulses that give about `budget` points: the tile's points per pulse, sampled.
  Random calibration(s.seed, CALIBRATION, i, j);
  std::uint64_t sampled = 0;
  for(int p = 0; p < CALIBRATION_PULSES; ++p)
    sampled += std::uint64_t(scene.pulse(x0 + calibration.uniform() * side, y0 + calibration.uniform() * side,
                                         calibration, returns));
  const double points_per_pulse = double(sampled) / CALIBRATION_PULSES;
  const std::uint64_t pulses = std::max<std::uint64_t>(1, std::uint64_t(std::llround(double(budget) / points_per_pulse)));
  const std::uint64_t lines = std::max<std::uint64_t>(1, std::uint64_t(std::llround(std::sqrt(double(pulses)))));

  const int width = int(std::to_string(tiles - 1).size());
  const std::string name = s.stem + "_" + zero_padded(i, width) + "_" + zero_padded(j, width) + ".las";
  const std::string path = (std::filesystem::path(s.folder) / name).string();
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  std::ofstream out(temporary, std::ios::binary);
  const auto fail = [&](const std::string& what) {
    out.close();
    std::remove(temporary.c_str());
    return Failure("cannot write " + path + ": " + what + (errno != 0 ? std::string(" (") + std::strerror(errno) + ")" : ""));
  };
  std::uint64_t written = 0;
  try
  {
  Lidar_io::Las_writer writer(out, tile_layout(s));

  // Integer coordinates of the tile's cell, [X0, X0 + cells): every point inside it.
  const std::int64_t cells = std::llround(side / SCALE);
  const std::int64_t first_x = i * cells, first_y = j * cells;
  std::vector<unsigned char> chunk;
  chunk.reserve(CHUNK_POINTS * RECORD_BYTES);
  Random r(s.seed, SCAN, i, j);
  const double tile_index = double(j * tiles + i);
  std::uint64_t pulse = 0;
  for(std::uint64_t line = 0; line < lines; ++line)
  {
    const std::uint64_t in_line = pulses / lines + (line < pulses % lines ? 1 : 0);
    const double line_spacing = side / double(lines), step = side / double(in_line);
    const bool backwards = line % 2 == 1; // the mirror sweeps one way, then the other
    for(std::uint64_t p = 0; p < in_line; ++p, ++pulse)
    {
      const double along = (double(backwards ? in_line - 1 - p : p) + 0.5 + 0.6 * (r.uniform() - 0.5)) * step;
      const double across = (double(line) + 0.5 + 0.5 * (r.uniform() - 0.5)) * line_spacing;
      const int n = scene.pulse(x0 + along, y0 + across, r, returns);
      const double gps_time = 3.0e8 + tile_index * 1000. + double(pulse) * 1e-5;
      for(int k = 0; k < n; ++k)
      {
        const Return& ret = returns[k];
        unsigned char record[RECORD_BYTES] = {};
        const std::int64_t xyz[3] = {
          std::clamp<std::int64_t>(std::llround(ret.x / SCALE), first_x, first_x + cells - 1),
          std::clamp<std::int64_t>(std::llround(ret.y / SCALE), first_y, first_y + cells - 1),
          std::llround(ret.z / SCALE)};
        for(int c = 0; c < 3; ++c)
          Lidar_io::store_little_endian<std::int32_t>(record + 4 * c, std::int32_t(xyz[c]));
        const double brightness = ret.label == BUILDING ? 14000. : ret.label == VEGETATION ? 5000. : 9000.;
        Lidar_io::store_little_endian<std::uint16_t>(record + 12, std::uint16_t(std::clamp(brightness + 1500. * r.normal(), 0., 65535.)));
        record[14] = std::uint8_t(ret.number | (ret.of << 4));
        record[15] = std::uint8_t(backwards ? 0 : 0x40); // scan direction flag
        record[16] = ret.label;
        Lidar_io::store_little_endian<std::int16_t>(record + 18, std::int16_t(std::lround((along / side - 0.5) * 20. / 0.006)));
        Lidar_io::store_little_endian<std::uint16_t>(record + 20, std::uint16_t(1 + j % 65535)); // a flight line per row of tiles
        Lidar_io::store_little_endian<double>(record + 22, gps_time);
        chunk.insert(chunk.end(), record, record + RECORD_BYTES);
      }
      if(chunk.size() >= CHUNK_POINTS * RECORD_BYTES)
      {
        writer.write(chunk.data(), chunk.size() / RECORD_BYTES);
        chunk.clear();
      }
    }
  }
  writer.write(chunk.data(), chunk.size() / RECORD_BYTES);
  writer.close();
  written = writer.summary().count;
  }
  catch(const std::ios_base::failure&)
  {
    throw fail("points");
  }
  out.close();
  if(out.fail())
    throw fail("close");
  if(std::rename(temporary.c_str(), path.c_str()) != 0)
    throw fail("rename");
  return written;
}

double number(const std::string& option, const char* text)
{
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if(*text == '\0' || *end != '\0' || !std::isfinite(v))
    throw Failure(option + " needs a number, got '" + text + "'");
  return v;
}

Survey read_arguments(int argc, char** argv)
{
  Survey s;
  std::vector<std::string> positional;
  for(int k = 1; k < argc; ++k)
  {
    const std::string a = argv[k];
    const auto value = [&](int n) {
      if(k + n >= argc)
        throw Failure(a + " needs " + std::to_string(n) + (n == 1 ? " value" : " values"));
      k += n;
      return argv[k - n + 1];
    };
    if(a == "-h" || a == "--help")
    {
      std::cout << USAGE;
      std::exit(0);
    }
    else if(a == "--tile-size")
      s.tile_size = number(a, value(1));
    else if(a == "--density")
      s.density = number(a, value(1));
    else if(a == "--seed")
      s.seed = std::uint64_t(number(a, value(1)));
    else if(a == "--name")
      s.stem = value(1);
    else if(a == "--origin")
    {
      const char* x = value(2);
      s.origin_x = number(a, x);
      s.origin_y = number(a, argv[k]);
    }
    else if(a.size() > 1 && a[0] == '-')
      throw Failure("unknown option " + a);
    else
      positional.push_back(a);
  }
  if(positional.size() != 2)
    throw Failure("needs POINTS and DIR\n" + std::string(USAGE));
  const double points = number("POINTS", positional[0].c_str());
  if(!(points >= 1. && points < 1e12))
    throw Failure("POINTS must be between 1 and 1e12");
  s.points = std::uint64_t(std::llround(points));
  s.folder = positional[1];
  if(!(s.tile_size >= 1. && s.tile_size <= 10000.) || std::abs(s.tile_size / SCALE - std::round(s.tile_size / SCALE)) > 1e-6)
    throw Failure("--tile-size must be 1 to 10000 metres, a multiple of 0.01");
  if(!(s.density > 0.))
    throw Failure("--density must be positive");
  if(s.stem.empty() || s.stem.find('/') != std::string::npos)
    throw Failure("--name must be a file name stem");
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const auto start = std::chrono::steady_clock::now();
    const Survey s = read_arguments(argc, argv);
    const int tiles =
      std::max(1, int(std::llround(std::sqrt(double(s.points) / s.density) / s.tile_size)));
    if(double(tiles) * s.tile_size / SCALE >= 2147483647.)
      throw Failure("the survey is wider than LAS coordinates of scale 0.01 reach: choose fewer points or a "
                    "smaller --tile-size");
    std::error_code ec;
    std::filesystem::create_directories(s.folder, ec);
    if(ec)
      throw Failure("cannot create " + s.folder + ": " + ec.message());
    const Terrain terrain(s.seed);
    const std::uint64_t count = std::uint64_t(tiles) * std::uint64_t(tiles);
    std::uint64_t written = 0;
    for(std::int64_t j = 0; j < tiles; ++j)
      for(std::int64_t i = 0; i < tiles; ++i)
      {
        const std::uint64_t index = std::uint64_t(j * tiles + i);
        written += write_tile(s, terrain, i, j, tiles, s.points / count + (index < s.points % count ? 1 : 0));
      }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "%s: %llu points in %d x %d tiles of %g m, %.1f points per square metre, %.1f s\n",
                 s.folder.c_str(), static_cast<unsigned long long>(written), tiles, tiles, s.tile_size,
                 double(written) / (double(count) * s.tile_size * s.tile_size), seconds);
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "generate_survey: " << e.what() << '\n';
    return 2;
  }
}
