// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading and writing on every thread, with the results of the sequential code: binary PLY point
// sets read from their records against CGAL's point set reader, ASCII OFF and OBJ files against
// CGAL's readers, the mesh check and the vertex normals against CGAL's functions, and the tool's
// text rows (the shortest text of each double) read back to the same doubles, the same bytes for any
// thread count.

#include <Sigmoid_neighborhoods_readers/internal/is_polygon_mesh.h>
#include <Sigmoid_neighborhoods_readers/internal/mesh_to_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_ascii_ply_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_binary_ply_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/text_blocks.h>

#include "test_scratch.h"
#include "text_rows.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace SN = CGAL::Sigmoid_neighborhoods;
typedef SN::Oriented_point_set::Point_3 Point;
typedef SN::Oriented_point_set::Vector_3 Vector;

// One to three random edits of `text` at or after `first`: a character of `alphabet` put in place of
// one, inserted, a character removed, or the text cut there.
void mutate(std::string& text, std::size_t first, const std::string& alphabet, std::mt19937& rng)
{
  for(std::size_t edits = 1 + rng() % 3; edits > 0 && text.size() > first; --edits)
  {
    const std::size_t at = first + rng() % (text.size() - first);
    const char c = alphabet[rng() % alphabet.size()];
    switch(rng() % 4)
    {
    case 0: text[at] = c; break;
    case 1: text.insert(text.begin() + std::ptrdiff_t(at), c); break;
    case 2: text.erase(at, 1); break;
    default: text.resize(at); break;
    }
  }
}

struct Read
{
  bool taken = false; // by the binary path
  std::vector<Point> points;
  std::vector<Vector> normals;
  bool has_normals = false;
  std::vector<int> labels;
};

Read read_binary(const std::string& path, unsigned int threads)
{
  Read r;
  r.taken = SN::internal::read_binary_ply_points(SN::internal::open_input_file(path, {"ply"}, ".ply"), r.points,
                                                 r.normals, r.has_normals, r.labels, threads);
  return r;
}

Read read_ascii(const std::string& path, unsigned int threads)
{
  Read r;
  r.taken = SN::internal::read_ascii_ply_points(SN::internal::open_input_file(path, {"ply"}, ".ply"), r.points,
                                                r.normals, r.has_normals, r.labels, threads);
  return r;
}

Read read_by_cgal(const std::string& path)
{
  Read r;
  SN::internal::read_points_without_faces(SN::internal::open_input_file(path, {"ply"}, ".ply"), r.points, r.normals,
                                          r.has_normals, &r.labels);
  return r;
}

void check_same(const Read& fast, const Read& cgal)
{
  REQUIRE(fast.taken);
  CHECK(fast.points == cgal.points);
  CHECK(fast.normals == cgal.normals);
  CHECK(fast.has_normals == cgal.has_normals);
  CHECK(fast.labels == cgal.labels);
}

template <typename T>
void put(std::ofstream& out, T value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

// A PLY point set, binary little-endian or ASCII: x y z of `Real`, normals of `NormalReal` when
// asked, a uchar `label` or a float `class` (1.5 every 7th point: no labels then), and an int
// property between (negative for half the points).
template <typename Real, typename NormalReal>
std::string write_ply(const std::string& name, std::size_t n, bool normals, const std::string& label_kind,
                      bool ascii = false)
{
  const std::string path = scratch_folder("parallel_io") + "/" + name;
  std::ofstream out(path, std::ios::binary);
  const char* real = sizeof(Real) == 4 ? "float" : "double";
  const char* normal_real = sizeof(NormalReal) == 4 ? "float" : "double";
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\ncomment test\nelement vertex " << n
      << "\nproperty " << real << " x\nproperty " << real << " y\nproperty int extra\nproperty " << real << " z\n";
  if(normals)
    out << "property " << normal_real << " nx\nproperty " << normal_real << " ny\nproperty " << normal_real
        << " nz\n";
  if(label_kind == "label")
    out << "property uchar label\n";
  else if(label_kind == "class")
    out << "property float class\n";
  out << "end_header\n";
  out.precision(17);
  // a value in binary, or in ASCII its text and a space
  auto value = [&](auto v) {
    if(!ascii)
      put(out, v);
    else if constexpr(sizeof(v) == 1)
      out << int(v) << ' ';
    else
      out << v << ' ';
  };
  std::mt19937_64 rng(n);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for(std::size_t i = 0; i < n; ++i)
  {
    value(Real(u(rng)));
    value(Real(u(rng)));
    value(std::int32_t(i) - std::int32_t(n / 2));
    value(Real(u(rng) * 1e-3));
    if(normals)
      for(int c = 0; c < 3; ++c)
        value(NormalReal(u(rng) / 1e3));
    if(label_kind == "label")
      value(std::uint8_t(i % 9));
    else if(label_kind == "class")
      value(float(i % 7 == 6 ? 1.5 : double(i % 4)));
    if(ascii)
      out << (i % 11 == 0 ? "\r\n\n" : "\n");
  }
  return path;
}

// The PLY files of the readers' tests, binary or ASCII: float with normals and labels (`first_size`
// points), double with float normals, double with a class that is no label, one float point.
std::vector<std::string> ply_test_files(bool ascii, std::size_t first_size)
{
  const std::string prefix = ascii ? "ascii_" : "";
  return {write_ply<float, float>(prefix + "float_normals_label.ply", first_size, true, "label", ascii),
          write_ply<double, float>(prefix + "double_float_normals.ply", 3001, true, "none", ascii),
          write_ply<double, double>(prefix + "double_class.ply", 777, false, "class", ascii),
          write_ply<float, float>(prefix + "float_no_normals.ply", 1, false, "none", ascii)};
}

// Each file read by `read` on 1, 2 and 3 threads gives what CGAL's point set reader gives.
void check_reader_on_threads(const std::vector<std::string>& files, Read (*read)(const std::string&, unsigned int))
{
  for(const std::string& path : files)
  {
    INFO(path);
    const Read cgal = read_by_cgal(path);
    for(unsigned int threads : {1u, 2u, 3u})
      check_same(read(path, threads), cgal);
  }
}

} // namespace

TEST_CASE("binary PLY: the records read on any thread count equal CGAL's point set reader", "[io][ply][parallel]")
{
  const std::vector<std::string> files = ply_test_files(false, 5000);
  check_reader_on_threads(files, read_binary);
  CHECK(read_by_cgal(files[0]).labels.size() == 5000);
  CHECK(read_by_cgal(files[2]).labels.empty()); // a class of 1.5 is no label
  CHECK(read_by_cgal(files[0]).points[2].x() != 0.);
}

TEST_CASE("binary PLY: other files are left to CGAL's readers", "[io][ply][parallel]")
{
  const std::string folder = scratch_folder("parallel_io");
  {
    std::ofstream ascii(folder + "/ascii.ply");
    ascii << "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
             "end_header\n0 0 0\n1 1 1\n";
  }
  {
    std::ofstream mesh(folder + "/mesh.ply", std::ios::binary);
    mesh << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    for(float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
      put(mesh, v);
    put(mesh, std::uint8_t(3));
    for(std::int32_t i : {0, 1, 2})
      put(mesh, i);
  }
  {
    std::ofstream integers(folder + "/integers.ply", std::ios::binary);
    integers << "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty int x\nproperty int y\n"
                "property int z\nend_header\n";
    for(std::int32_t v : {1, 2, 3})
      put(integers, v);
  }
  for(const char* name : {"ascii.ply", "mesh.ply"})
  {
    INFO(name);
    CHECK_FALSE(read_binary(folder + "/" + name, 2).taken);
  }
  // the header's checks come first, as on CGAL's path
  CHECK_THROWS_WITH(read_binary(folder + "/integers.ply", 2), Catch::Contains("must be float or double"));
  // a file shorter than its header says: the same error as CGAL's path (the checks come first)
  const std::string full = write_ply<float, float>("short.ply", 100, true, "none");
  std::filesystem::resize_file(full, std::filesystem::file_size(full) - 5);
  CHECK_THROWS_WITH(read_binary(full, 2), Catch::Contains("element 'vertex'"));
}

TEST_CASE("ASCII PLY: the values read on any thread count equal CGAL's point set reader", "[io][ply][parallel]")
{
  const std::vector<std::string> files = ply_test_files(true, 30000);
  REQUIRE(std::filesystem::file_size(files[0]) > 4 * SN::internal::TEXT_SMALLEST_BLOCK_BYTES);
  check_reader_on_threads(files, read_ascii);
  CHECK(read_by_cgal(files[0]).labels.size() == 30000);
  CHECK(read_by_cgal(files[2]).labels.empty()); // a class of 1.5 is no label
  CHECK_FALSE(read_ascii(write_ply<float, float>("binary.ply", 10, true, "none"), 2).taken);
}

TEST_CASE("ASCII PLY: files it might read otherwise are left to CGAL's readers, and mutated files", "[io][ply][parallel]")
{
  const std::string folder = scratch_folder("parallel_io");
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nproperty uchar label\nproperty short s\nend_header\n";
  const std::vector<std::pair<std::string, bool>> bodies{
    {"0 0 0 1 -2\n1 0 0 2 3\n0 1 0 255 -32768\n", true},
    {"0 0 0 1 -2 1 0 0 2 3\n0 1 0 255 -32768\n", false}, // two vertices on a line
    {"0 0 0 1 -2\n1 0 0 2 3 7\n0 1 0 255 -32768\n", false}, // a token more
    {"0 0 0 1 -2\n1 0 0 2.5 3\n0 1 0 255 -32768\n", false}, // a float for a uchar
    {"0 0 0 1 -2\n1 0 0 300 3\n0 1 0 255 -32768\n", false}, // beyond a uchar
    {"0 0 0 1 -2\n1 0 0 -1 3\n0 1 0 255 -32768\n", false}, // a sign for a uchar
    {"0 0 0 1 -2\n1 0 0 2 +3\n0 1 0 255 -32768\n", false}, // '+'
    {"0 0 0 1 -2\n1 0 0 2 3\n", false}}; // cut short
  for(std::size_t b = 0; b < bodies.size(); ++b)
  {
    INFO(bodies[b].first);
    const std::string path = folder + "/ascii_case.ply";
    std::ofstream(path, std::ios::binary) << header << bodies[b].first;
    const Read fast = read_ascii(path, 2);
    CHECK(fast.taken == bodies[b].second);
    if(fast.taken)
      check_same(fast, read_by_cgal(path));
    else
      CHECK(fast.points.empty());
  }

  // Mutants of two files: where taken, CGAL's values (read after the checks of its path)
  const std::vector<std::string> seeds{
    header + "8.19821 -21.7553 7.88123 1 16\n1e-3 .5 -0 0 -7\n-3.08065 21.6219 -1.45825 9 1\n",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
    "property float nx\nproperty float ny\nproperty float nz\nproperty float class\nelement face 0\n"
    "property list uchar int vertex_indices\nend_header\n0.1 0.2 0.3 0 0 1 1\n1.5 2.5 3.5 0 1 0 2.5\n\n"
    "-1e2 4 5 1 0 0 3\n"};
  const std::string alphabet = " \t\n\r-+.e0123456789x";
  std::mt19937 rng(5);
  std::size_t taken = 0, left = 0, mutants = 3000;
  for(std::size_t m = 0; m < mutants; ++m)
  {
    std::string text = seeds[m % seeds.size()];
    mutate(text, text.find("end_header") + 11, alphabet, rng);
    const std::string path = folder + "/ascii_mutant.ply";
    std::ofstream(path, std::ios::binary) << text;
    const Read fast = read_ascii(path, unsigned(1 + m % 3));
    if(!fast.taken)
    {
      ++left;
      CHECK(fast.points.empty());
      continue;
    }
    ++taken;
    const SN::internal::Input_file file = SN::internal::open_input_file(path, {"ply"}, ".ply");
    Read cgal;
    bool cgal_read = true;
    try
    {
      SN::internal::check_ply_counts(file);
      cgal = read_by_cgal(path);
    }
    catch(const SN::Input_error&)
    {
      cgal_read = false;
    }
    if(!cgal_read || fast.points != cgal.points || fast.normals != cgal.normals ||
       fast.has_normals != cgal.has_normals || fast.labels != cgal.labels)
      FAIL("mutant " << m << ": the fast reader differs from CGAL's on\n" << text);
  }
  CHECK(taken > mutants / 10);
  CHECK(left > mutants / 10);
}

TEST_CASE("binary PLY: the lone-star scan of the shared data, as CGAL reads it", "[io][ply][parallel][shared-data]")
{
  const std::string scan = std::string(SN_SHARED_DATA_DIR) + "/scanned/lone-star_tls.ply";
  REQUIRE(std::filesystem::exists(scan)); // a ctest entry of its own, skipped without it
  check_same(read_binary(scan, 2), read_by_cgal(scan));
}

TEST_CASE("text rows: the shortest text reads back to the same double, the same bytes on any thread count",
          "[io][csv][parallel]")
{
  std::mt19937_64 rng(5);
  std::vector<double> values = {0., -0., 1., 0.1, 1e-320, -1e300, std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::denorm_min(), 1. / 3., 123456789.125};
  std::uniform_int_distribution<std::uint64_t> bits;
  while(values.size() < 20000)
  {
    const std::uint64_t b = bits(rng);
    double v;
    std::memcpy(&v, &b, sizeof(v));
    if(std::isfinite(v))
      values.push_back(v);
  }
  auto text = [&](unsigned int threads) {
    std::ostringstream out;
    sigmoid_tool::write_text_rows(out, 0, values.size(), threads, [&](sigmoid_tool::Text_rows& rows, std::size_t i) {
      rows.number(values[i]).put(',').integer(std::int64_t(i) - 7).put('\n');
    });
    return out.str();
  };
  const std::string one = text(1);
  CHECK(text(2) == one);
  CHECK(text(3) == one);
  std::istringstream in(one);
  std::string line;
  std::size_t i = 0;
  for(; std::getline(in, line); ++i)
  {
    const std::size_t comma = line.find(',');
    const double v = std::strtod(line.substr(0, comma).c_str(), nullptr);
    REQUIRE(std::memcmp(&v, &values[i], sizeof(v)) == 0);
    REQUIRE(std::stoll(line.substr(comma + 1)) == std::int64_t(i) - 7);
  }
  CHECK(i == values.size());
  std::ostringstream special;
  sigmoid_tool::write_text_rows(special, 0, 1, 2, [](sigmoid_tool::Text_rows& rows, std::size_t) {
    rows.number(std::numeric_limits<double>::infinity()).put(',').number(0.1).put(',').number(1e-5);
  });
  CHECK(special.str() == "inf,0.1,1e-05");
}

namespace {

typedef std::vector<std::vector<std::size_t>> Polygons;

// The eight faces of an octahedron on vertices `first` to `first + 5`, outward.
void add_octahedron(Polygons& polygons, std::size_t first)
{
  const std::size_t faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for(const auto& f : faces)
    polygons.push_back({first + f[0], first + f[1], first + f[2]});
}

bool cgal_says_mesh(const Polygons& polygons)
{
  return CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
}

} // namespace

TEST_CASE("is_polygon_mesh: the answer of CGAL's check on named cases", "[io][mesh][parallel]")
{
  Polygons closed;
  add_octahedron(closed, 0);
  Polygons two_cones = closed; // two octahedra sharing vertex 0: a singular vertex
  add_octahedron(two_cones, 6);
  for(auto& p : two_cones)
    for(auto& v : p)
      if(v == 6)
        v = 0;
  Polygons flipped = closed;
  std::reverse(flipped[3].begin(), flipped[3].end());
  Polygons open_fan = closed;
  open_fan.erase(open_fan.begin() + 5); // a hole: every vertex still one fan
  const Polygons bowtie{{0, 1, 2}, {0, 3, 4}};
  const Polygons repeated_corner{{0, 1, 0, 2}};
  const Polygons two_corners{{0, 1}, {0, 1, 2}};
  Polygons twice = closed;
  twice.push_back(closed[2]);
  const Polygons quad_and_triangles{{0, 1, 2, 3}, {1, 0, 4}, {2, 1, 4}, {3, 2, 4}, {0, 3, 4}};

  const std::vector<std::pair<const char*, const Polygons*>> cases{
    {"closed", &closed},   {"two cones", &two_cones},        {"flipped", &flipped},
    {"open fan", &open_fan}, {"bowtie", &bowtie},           {"repeated corner", &repeated_corner},
    {"two corners", &two_corners}, {"face twice", &twice}, {"quad and triangles", &quad_and_triangles}};
  const std::vector<bool> expected{true, false, false, true, false, false, false, false, true};
  for(std::size_t c = 0; c < cases.size(); ++c)
    for(unsigned int threads = 1; threads <= 3; ++threads)
    {
      INFO(cases[c].first << " on " << threads << " threads");
      CHECK(cgal_says_mesh(*cases[c].second) == expected[c]);
      CHECK(SN::internal::is_polygon_mesh(*cases[c].second, threads) == expected[c]);
    }
  CHECK(SN::internal::is_polygon_mesh(Polygons()));
}

TEST_CASE("is_polygon_mesh: CGAL's answer on random soups of glued, cut and flipped octahedra", "[io][mesh][parallel]")
{
  std::mt19937 rng(7);
  std::size_t meshes = 0, rounds = 20000;
  for(std::size_t round = 0; round < rounds; ++round)
  {
    Polygons polygons;
    const std::size_t copies = 1 + rng() % 3;
    for(std::size_t c = 0; c < copies; ++c)
      add_octahedron(polygons, 6 * c);
    if(rng() % 4 == 0) // a quad
    {
      polygons[0] = {0, 2, 1, 4};
      polygons.erase(polygons.begin() + 1);
    }
    std::vector<std::size_t> relabel(6 * copies);
    for(std::size_t i = 0; i < relabel.size(); ++i)
      relabel[i] = i;
    for(std::size_t g = rng() % 3; g > 0; --g) // glued vertices
      relabel[rng() % relabel.size()] = rng() % relabel.size();
    for(auto& p : polygons)
      for(auto& v : p)
        v = relabel[v];
    for(std::size_t d = rng() % 4; d > 0 && !polygons.empty(); --d)
      polygons.erase(polygons.begin() + std::ptrdiff_t(rng() % polygons.size()));
    if(rng() % 3 == 0 && !polygons.empty())
    {
      auto& p = polygons[rng() % polygons.size()];
      std::reverse(p.begin(), p.end());
    }
    if(rng() % 10 == 0 && !polygons.empty())
      polygons.push_back(polygons[rng() % polygons.size()]);
    std::shuffle(polygons.begin(), polygons.end(), rng);
    for(auto& p : polygons)
      std::rotate(p.begin(), p.begin() + std::ptrdiff_t(rng() % p.size()), p.end());
    const bool expected = cgal_says_mesh(polygons);
    meshes += expected;
    const unsigned int threads = unsigned(1 + round % 3);
    if(SN::internal::is_polygon_mesh(polygons, threads) != expected)
    {
      std::ostringstream soup;
      for(const auto& p : polygons)
      {
        for(std::size_t v : p)
          soup << v << ' ';
        soup << "| ";
      }
      FAIL("round " << round << ", " << threads << " threads: CGAL says " << expected << " for " << soup.str());
    }
  }
  // both answers are common
  CHECK(meshes > rounds / 10);
  CHECK(meshes < rounds * 9 / 10);
}

TEST_CASE("is_polygon_mesh: CGAL's answer on a torus of 28,800 triangles, cut, glued and flipped, on 1-3 threads",
          "[io][mesh][parallel]")
{
  const std::size_t n = 120;
  auto vertex = [&](std::size_t i, std::size_t j) { return (i % n) * n + (j % n); };
  Polygons torus;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
    {
      torus.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      torus.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  REQUIRE(3 * torus.size() >= SN::internal::PARALLEL_MESH_CHECK_CORNERS);
  Polygons cut = torus;
  cut.erase(cut.begin() + 1000);
  Polygons glued = torus; // two vertices far apart made one: a singular vertex
  for(auto& p : glued)
    for(auto& v : p)
      if(v == vertex(n / 2, n / 2))
        v = vertex(0, 0);
  Polygons flipped = torus;
  std::reverse(flipped[5000].begin(), flipped[5000].end());
  const std::vector<std::pair<const Polygons*, bool>> cases{{&torus, true}, {&cut, true}, {&glued, false}, {&flipped, false}};
  for(const auto& c : cases)
  {
    CHECK(cgal_says_mesh(*c.first) == c.second);
    for(unsigned int threads = 1; threads <= 3; ++threads)
      CHECK(SN::internal::is_polygon_mesh(*c.first, threads) == c.second);
  }
}

namespace {

struct Soups
{
  bool fast_taken = false, cgal_read = false;
  SN::internal::Polygon_soup fast, cgal;
};

// The soup of an OFF or OBJ file by the fast reader on `threads` threads and by CGAL's.
Soups read_soups(const std::string& path, unsigned int threads)
{
  const SN::internal::Input_file file = SN::internal::open_input_file(path, {"off", "obj"}, ".off or .obj");
  Soups s;
  s.fast_taken = file.extension == "off" ? SN::internal::read_ascii_off_soup(file, s.fast, threads)
                                         : SN::internal::read_obj_soup(file, s.fast, threads);
  SN::internal::Captured_cerr quiet;
  try
  {
    s.cgal_read = file.extension == "off" ? SN::internal::read_off_soup(file, s.cgal)
                                          : CGAL::IO::read_OBJ(file.name, s.cgal.points, s.cgal.polygons);
  }
  catch(const SN::Input_error&) // a count beyond the file's bytes
  {
  }
  return s;
}

// A torus of n x n quads, as an OFF file with comments, colors and blank lines, and as an OBJ file
// with CRLF line ends, texture and normal indices, groups and comments.
std::pair<std::string, std::string> write_torus(std::size_t n)
{
  const std::string folder = scratch_folder("parallel_io");
  std::mt19937_64 rng(n);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  std::vector<std::array<double, 3>> points;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
    {
      const double u = 2 * M_PI * double(i) / double(n), v = 2 * M_PI * double(j) / double(n);
      points.push_back({(3 + std::cos(v)) * std::cos(u) + jitter(rng), (3 + std::cos(v)) * std::sin(u) + jitter(rng),
                        std::sin(v) + jitter(rng)});
    }
  auto vertex = [&](std::size_t i, std::size_t j) { return (i % n) * n + (j % n); };
  std::ofstream off(folder + "/torus.off"), obj(folder + "/torus.obj");
  off << "COFF\n# a torus\n" << points.size() << ' ' << n * n << " 0\n";
  obj << "# a torus\r\nmtllib none.mtl\r\no torus\r\n";
  off.precision(17);
  obj.precision(17);
  for(std::size_t k = 0; k < points.size(); ++k)
  {
    const auto& p = points[k];
    off << p[0] << ' ' << p[1] << "\t" << p[2] << " 200 100 50 255" << (k % 97 == 0 ? "  # note\n\n" : "\n");
    obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << "\r\nvt 0.5 0.5\r\n";
  }
  obj << "vn 0 0 1\r\ng faces\r\n";
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t q[4] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      off << "4 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << (j % 5 == 0 ? " 255 0 0\n" : "\n");
      obj << "f " << q[0] + 1 << "/1/1 " << q[1] + 1 << "/1/1  " << q[2] + 1 << "//1 " << q[3] + 1 << "\r\n";
    }
  return {folder + "/torus.off", folder + "/torus.obj"};
}

} // namespace

TEST_CASE("OFF and OBJ: a torus of 40,000 quads read on the threads equals CGAL's reading", "[io][off][obj][parallel]")
{
  const auto paths = write_torus(200);
  REQUIRE(std::filesystem::file_size(paths.first) > 4 * SN::internal::TEXT_SMALLEST_BLOCK_BYTES);
  for(const std::string& path : {paths.first, paths.second})
    for(unsigned int threads = 1; threads <= 3; ++threads)
    {
      INFO(path << " on " << threads << " threads");
      const Soups s = read_soups(path, threads);
      REQUIRE(s.fast_taken);
      REQUIRE(s.cgal_read);
      CHECK(s.fast.points.size() == 40000);
      CHECK(s.fast.polygons.size() == 40000);
      CHECK(s.fast.points == s.cgal.points);
      CHECK(s.fast.polygons == s.cgal.polygons);
    }
}

TEST_CASE("OFF and OBJ: on mutated files the fast readers give CGAL's soup or leave the file to CGAL",
          "[io][off][obj][parallel]")
{
  const std::string folder = scratch_folder("parallel_io");
  const std::vector<std::pair<std::string, std::string>> seeds{
    {"off", "OFF\n# c\n5 3 0\n0 0 0\n1 0 0  \n0 1.5 0 # x\n\n1e-3 -2 .5\n-0 0 1\n3 0 1 2\n3 0 2 3 255 0 0\n4 0 1 3 4\n"},
    {"off", "COFF\n4 2 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n1 1 0 1 1 1 1\n3 0 1 2\n3 1 3 2\n"},
    {"obj", "# obj\nv 0 0 0\nv 1 0 0\nv 0 1 0 1.0\nvn 0 0 1\nvt 0 0\ng grp\nusemtl m\nf 1 2 3\nf 1/1/1 3/1/1 "
            "4/1/1\nv 1 1 0\nf 2//1 4//1 3//1\ns off\n"},
    {"obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 1\r\nf 1 2 3\r\nf 2 4 3\r\n"}};
  const std::string alphabet = " \t\n\r#-+.e0123456789/fvx";
  std::mt19937 rng(3);
  std::size_t taken = 0, left = 0, mutants = 4000;
  for(std::size_t m = 0; m < mutants; ++m)
  {
    const auto& seed = seeds[m % seeds.size()];
    std::string text = seed.second;
    mutate(text, 0, alphabet, rng);
    if(text.empty())
      continue;
    const std::string path = folder + "/mutant." + seed.first;
    std::ofstream(path, std::ios::binary) << text;
    const Soups s = read_soups(path, unsigned(1 + m % 3));
    if(s.fast_taken)
    {
      ++taken;
      if(!s.cgal_read || s.fast.points != s.cgal.points || s.fast.polygons != s.cgal.polygons)
        FAIL("mutant " << m << ": the fast reader differs from CGAL's on\n" << text);
    }
    else
    {
      ++left;
      CHECK(s.fast.points.empty());
      CHECK(s.fast.polygons.empty());
    }
  }
  // both outcomes are common
  CHECK(taken > mutants / 10);
  CHECK(left > mutants / 10);
}

TEST_CASE("mesh vertex normals on the threads: CGAL's compute_vertex_normals() bit for bit", "[io][mesh][parallel]")
{
  // the torus of the OFF test, quads and all, past the size computed on one thread
  const auto paths = write_torus(120);
  SN::internal::Polygon_soup soup;
  REQUIRE(SN::internal::read_ascii_off_soup(SN::internal::open_input_file(paths.first, {"off"}, ".off"), soup, 1));
  typedef CGAL::Surface_mesh<Point> Mesh;
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  REQUIRE(mesh.number_of_faces() >= SN::internal::PARALLEL_NORMAL_FACES);
  auto expected = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:expected").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, expected);
  for(unsigned int threads = 1; threads <= 3; ++threads)
  {
    Mesh copy = mesh;
    const auto normals = SN::internal::vertex_normals_on_threads(copy, threads);
    std::size_t differ = 0;
    for(Mesh::Vertex_index v : mesh.vertices())
      differ += normals[v] != expected[v];
    CHECK(differ == 0);
  }
}
