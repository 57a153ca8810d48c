// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bounded memory on hostile input: every count a file announces (PLY element counts and list
// lengths in ASCII and both binary byte orders, OFF vertex, face and corner counts, STL triangle
// counts) is refused when the rest of the file cannot hold it, before anything is sized to it,
// and the readers stay within 256 MiB and 5 s on every such file; out of memory in the tool is one
// line and exit code 3, inside the parallel search too, and `evaluate` goes on after it. XYZ files
// parsed in parallel give the points and the first error of a sequential reading.

#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/read_polygon_mesh.h>
#include <Sigmoid_neighborhoods_readers/internal/read_xyz.h>
#include <CGAL/Surface_mesh.h>

#include "test_models.h"
#include "test_scratch.h"

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

// AddressSanitizer reserves terabytes of address space at start: no address-space limit then, and
// its allocator refuses huge sizes by itself.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool ADDRESS_SANITIZER = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool ADDRESS_SANITIZER = true;
#else
constexpr bool ADDRESS_SANITIZER = false;
#endif
#else
constexpr bool ADDRESS_SANITIZER = false;
#endif

// The bounds of the issue: no file under 1 MiB makes a reader use more memory, or time, than this.
constexpr std::size_t MEMORY_LIMIT_BYTES = std::size_t(256) << 20;
constexpr unsigned int CPU_LIMIT_SECONDS = 5;

// This file's folder of the run's scratch folder.
const std::string& scratch()
{
  static const std::string dir = scratch_folder("limits");
  return dir;
}

std::string path(const std::string& name) { return scratch() + "/" + name; }

std::string write_file(const std::string& name, const std::string& bytes)
{
  std::ofstream(path(name), std::ios::binary) << bytes;
  return path(name);
}

std::string read_text(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The address space this process holds now (/proc/self/statm: its first number, in pages).
std::size_t address_space_bytes()
{
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  return pages * std::size_t(::sysconf(_SC_PAGESIZE));
}

// Runs `f` in a child process that may take MEMORY_LIMIT_BYTES more address space and
// CPU_LIMIT_SECONDS of processor time; returns what `f` returned, "bad_alloc", "exception: ...", or
// how the child ended. The child runs no OpenMP region: a fork of a process with OpenMP threads
// cannot start one.
std::string run_limited(const std::function<std::string()>& f)
{
  int channel[2];
  REQUIRE(::pipe(channel) == 0);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if(pid == 0)
  {
    ::close(channel[0]);
    if(!ADDRESS_SANITIZER)
    {
      const rlim_t bytes = rlim_t(address_space_bytes() + MEMORY_LIMIT_BYTES);
      const struct rlimit memory = {bytes, bytes};
      ::setrlimit(RLIMIT_AS, &memory);
    }
    const struct rlimit cpu = {CPU_LIMIT_SECONDS, CPU_LIMIT_SECONDS};
    ::setrlimit(RLIMIT_CPU, &cpu);
    std::string result;
    try
    {
      result = f();
    }
    catch(const std::bad_alloc&)
    {
      result = "bad_alloc";
    }
    catch(const std::exception& e)
    {
      result = std::string("exception: ") + e.what();
    }
    const char* at = result.data();
    for(std::size_t left = result.size(); left > 0;)
    {
      const ssize_t written = ::write(channel[1], at, left);
      if(written <= 0)
        break;
      at += written;
      left -= std::size_t(written);
    }
    ::_exit(0);
  }
  ::close(channel[1]);
  std::string result;
  char buffer[4096];
  for(ssize_t got; (got = ::read(channel[0], buffer, sizeof(buffer))) > 0;)
    result.append(buffer, std::size_t(got));
  ::close(channel[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if(WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGXCPU ? " (over the CPU time limit)" : "");
  return result;
}

// What both readers say of `file`, within the limits: "read", "Input_error: <message>", or what
// run_limited() says. Normals are not estimated: the counts are all read before.
std::string read_limited(const std::string& file)
{
  return run_limited([&] {
    std::string outcome;
    try
    {
      SN::read_oriented_point_set(file, 0);
      outcome = "read";
    }
    catch(const SN::Input_error& e)
    {
      outcome = std::string("Input_error: ") + e.what();
    }
    try
    {
      CGAL::Surface_mesh<SN::Oriented_point_set::Point_3> mesh;
      SN::read_polygon_mesh(file, mesh);
    }
    catch(const SN::Input_error& e)
    {
      // read_polygon_mesh() refuses point sets; a count it refuses, read_oriented_point_set() refused
      if(outcome == "read" && std::string(e.what()).find("announces") != std::string::npos)
        outcome = std::string("only read_polygon_mesh() refused: ") + e.what();
    }
    return outcome;
  });
}

// ------------------------------------------------------------------------------------------------
// Hostile files: valid headers, a few hundred bytes, counts of billions.

enum class Ply_format
{
  ASCII,
  LITTLE_ENDIAN_BINARY,
  BIG_ENDIAN_BINARY
};

const char* format_name(Ply_format f)
{
  return f == Ply_format::ASCII                  ? "ascii"
         : f == Ply_format::LITTLE_ENDIAN_BINARY ? "binary_little_endian"
                                                 : "binary_big_endian";
}

// A PLY body in one of the three formats.
class Ply_body
{
public:
  explicit Ply_body(Ply_format format) : m_format(format) {}

  template <typename T>
  Ply_body& add(T value)
  {
    if(m_format == Ply_format::ASCII)
    {
      std::ostringstream text;
      if(std::is_floating_point<T>::value)
        text.precision(17);
      text << (sizeof(T) == 1 ? +value : value) << ' ';
      m_bytes += text.str();
      return *this;
    }
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if(m_format == Ply_format::BIG_ENDIAN_BINARY) // this machine is little-endian (x86, ARM Linux)
      std::reverse(raw, raw + sizeof(T));
    m_bytes.append(raw, sizeof(T));
    return *this;
  }
  Ply_body& end_line()
  {
    if(m_format == Ply_format::ASCII)
      m_bytes += '\n';
    return *this;
  }
  const std::string& bytes() const { return m_bytes; }

private:
  Ply_format m_format;
  std::string m_bytes;
};

std::string ply_header(Ply_format format, const std::string& elements)
{
  return std::string("ply\nformat ") + format_name(format) + " 1.0\n" + elements + "end_header\n";
}

const char* const THREE_VERTICES = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

void add_three_vertices(Ply_body& body)
{
  body.add(0.f).add(0.f).add(0.f).end_line();
  body.add(1.f).add(0.f).add(0.f).end_line();
  body.add(0.f).add(1.f).add(0.f).end_line();
}

// A list `name` of length type `Length` that announces `length` entries and holds three, in the
// element `where`: "vertex" (a point set), "face" (a mesh) or "material" (an element CGAL skips).
template <typename Length>
std::string ply_with_huge_list(Ply_format format, const std::string& where, Length length)
{
  const std::string length_type = std::is_same<Length, std::uint8_t>::value    ? "uchar"
                                  : std::is_same<Length, std::uint16_t>::value ? "ushort"
                                  : std::is_same<Length, std::uint32_t>::value ? "uint"
                                                                               : "int";
  Ply_body body(format);
  std::string elements;
  auto list = [&] { body.add(length).add(std::int32_t(0)).add(std::int32_t(1)).add(std::int32_t(2)).end_line(); };
  if(where == "vertex")
  {
    elements = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty list " + length_type +
               " int extra\n";
    body.add(0.f).add(0.f).add(0.f);
    list();
  }
  else
  {
    elements = std::string(THREE_VERTICES) + "element " + where + " 1\nproperty list " + length_type + " int " +
               (where == "face" ? "vertex_indices" : "data") + "\n";
    add_three_vertices(body);
    list();
  }
  return ply_header(format, elements) + body.bytes();
}

struct Hostile_file
{
  std::string name, bytes;
  std::string expected; // a piece of the message, besides the file's size
};

std::vector<Hostile_file> hostile_files()
{
  std::vector<Hostile_file> files;
  for(Ply_format format : {Ply_format::ASCII, Ply_format::LITTLE_ENDIAN_BINARY, Ply_format::BIG_ENDIAN_BINARY})
  {
    const std::string f = format_name(format);
    for(const std::string where : {"vertex", "face", "material"})
    {
      const std::string name = where == "vertex" ? "extra" : where == "face" ? "vertex_indices" : "data";
      const std::string list = "of element '" + where + "' announces a list '" + name + "' of ";
      files.push_back({f + "_" + where + "_uint.ply", ply_with_huge_list(format, where, std::uint32_t(4000000000u)),
                       list + "4000000000 entries"});
      files.push_back({f + "_" + where + "_negative_int.ply", ply_with_huge_list(format, where, std::int32_t(-1)),
                       list + "18446744073709551615 entries"});
      files.push_back({f + "_" + where + "_ushort.ply", ply_with_huge_list(format, where, std::uint16_t(65535)),
                       list + "65535 entries"});
    }
    // 255, the largest uchar length, over and over: each one more than the few bytes left
    {
      Ply_body body(format);
      add_three_vertices(body);
      for(int i = 0; i < 5; ++i)
        body.add(std::uint8_t(255)).add(std::int32_t(0)).add(std::int32_t(1)).add(std::int32_t(2)).end_line();
      files.push_back({f + "_uchar_255_repeated.ply",
                       ply_header(format, std::string(THREE_VERTICES) +
                                            "element face 5\nproperty list uchar int vertex_indices\n") +
                         body.bytes(),
                       "item 0 of element 'face' announces a list 'vertex_indices' of 255 entries"});
    }
    Ply_body three(format);
    add_three_vertices(three);
    files.push_back({f + "_vertex_count.ply",
                     ply_header(format,
                                "element vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\n") +
                       three.bytes(),
                     "the header announces 2000000000 items of element 'vertex'"});
    files.push_back({f + "_face_count.ply",
                     ply_header(format, std::string(THREE_VERTICES) +
                                          "element face 1000000000\nproperty list uchar int vertex_indices\n") +
                       three.bytes(),
                     "the header announces 1000000000 items of element 'face'"});
    files.push_back({f + "_no_property_count.ply",
                     ply_header(format, std::string(THREE_VERTICES) + "element nothing 3000000000\n") + three.bytes(),
                     "the header announces 3000000000 items of element 'nothing'"});
    // cut right before a list's length: CGAL would take whatever its buffer held for it
    files.push_back({f + "_cut_before_list.ply",
                     ply_header(format, std::string(THREE_VERTICES) +
                                          "element face 2\nproperty list uint int vertex_indices\n") +
                       Ply_body(three).add(std::uint32_t(3)).add(0).add(1).add(2).bytes(),
                     "ends in item 1 of element 'face', property 'vertex_indices'"});
  }

  files.push_back({"vertex_count.off", "OFF\n2000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                   "the header announces 2000000000 vertices"});
  files.push_back({"face_count.off", "OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                   "the header announces 2000000000 faces after 3 vertices"});
  files.push_back({"face_size.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n",
                   "face 0 announces 2000000000 corners"});
  // binary OFF: big-endian 32-bit counts, floats and corners
  auto big_endian = [](std::int32_t v) {
    std::string s(4, '\0');
    for(int i = 0; i < 4; ++i)
      s[std::size_t(i)] = char((std::uint32_t(v) >> (24 - 8 * i)) & 0xff);
    return s;
  };
  const std::string binary_vertices = std::string(36, '\0');
  files.push_back({"binary_face_size.off",
                   "OFF BINARY\n" + big_endian(3) + big_endian(1) + big_endian(0) + binary_vertices +
                     big_endian(2000000000) + big_endian(0) + big_endian(1) + big_endian(2),
                   "face 0 announces 2000000000 corners"});
  files.push_back({"binary_vertex_count.off",
                   "OFF BINARY\n" + big_endian(2000000000) + big_endian(1) + big_endian(0) + binary_vertices,
                   "the header announces 2000000000 vertices"});
  // binary STL: an 80-byte header, a little-endian count, 50 bytes a triangle
  std::string stl(80, '\0');
  stl += std::string("\xff\xff\xff\xff", 4) + std::string(50, '\0');
  files.push_back({"binary_triangle_count.stl", stl, "the header announces 4294967295 triangles"});
  return files;
}

} // namespace

TEST_CASE("Input limits: every count is bounded by the bytes left, before anything is sized to it", "[io][limits]")
{
  std::size_t cases = 0;
  for(const Hostile_file& h : hostile_files())
  {
    INFO(h.name);
    REQUIRE(h.bytes.size() < 1024);
    const std::string file = write_file(h.name, h.bytes);
    const std::string outcome = read_limited(file);
    CHECK(outcome.rfind("Input_error: ", 0) == 0);
    CHECK(outcome.find(h.expected) != std::string::npos);
    CHECK(outcome.find("a file of " + std::to_string(h.bytes.size()) + " bytes") != std::string::npos);
    ++cases;
  }
  CHECK(cases == 3 * 14 + 6);
}

TEST_CASE("Input limits: files that fill their counts exactly are read, one byte less is refused", "[io][limits]")
{
  // a pyramid of 5 vertices, 4 triangles and a quad; binary, each list exactly as long as it says
  for(Ply_format format : {Ply_format::ASCII, Ply_format::LITTLE_ENDIAN_BINARY, Ply_format::BIG_ENDIAN_BINARY})
  {
    INFO(format_name(format));
    Ply_body body(format);
    const float v[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}};
    for(const auto& p : v)
      body.add(p[0]).add(p[1]).add(p[2]).end_line();
    body.add(std::uint8_t(4)).add(0).add(3).add(2).add(1).end_line();
    const int t[4][3] = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    for(const auto& f : t)
      body.add(std::uint8_t(3)).add(f[0]).add(f[1]).add(f[2]).end_line();
    const std::string ply =
      ply_header(format, "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                         "element face 5\nproperty list uchar int vertex_indices\n") +
      body.bytes();
    const std::string whole = write_file(std::string("exact_") + format_name(format) + ".ply", ply);
    CHECK(read_limited(whole) == "read");
    CHECK(SN::read_oriented_point_set(whole).points.size() == 5);
    const std::string cut =
      write_file(std::string("cut_") + format_name(format) + ".ply", ply.substr(0, ply.size() - 4));
    CHECK(read_limited(cut).rfind("Input_error: cannot parse the file as ply", 0) == 0);
  }
  // a point set whose vertices carry a list of 255 entries, the most a uchar length says
  Ply_body body(Ply_format::LITTLE_ENDIAN_BINARY);
  for(int i = 0; i < 30; ++i)
  {
    body.add(float(i % 5)).add(float(i / 5)).add(float(i % 3)).add(0.f).add(0.f).add(1.f).add(std::uint8_t(255));
    for(int j = 0; j < 255; ++j)
      body.add(std::uint8_t(j));
  }
  const std::string lists = write_file(
    "vertex_lists.ply",
    ply_header(Ply_format::LITTLE_ENDIAN_BINARY,
               "element vertex 30\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
               "property float ny\nproperty float nz\nproperty list uchar uchar bytes\n") +
      body.bytes());
  CHECK(read_limited(lists) == "read");
  CHECK(SN::read_oriented_point_set(lists).points.size() == 30);
  // a point set of 256 properties per vertex is read, one more is refused (CGAL's point set reader
  // takes a time quadratic in their number)
  for(const int properties : {256, 257})
  {
    std::string header = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
    for(int p = 3; p < properties; ++p)
      header += "property uchar p" + std::to_string(p) + "\n";
    Ply_body points(Ply_format::LITTLE_ENDIAN_BINARY);
    for(int i = 0; i < 4; ++i)
    {
      points.add(float(i)).add(float(i * i)).add(0.f);
      for(int p = 3; p < properties; ++p)
        points.add(std::uint8_t(p));
    }
    const std::string file = write_file("properties_" + std::to_string(properties) + ".ply",
                                        ply_header(Ply_format::LITTLE_ENDIAN_BINARY, header) + points.bytes());
    if(properties == 256)
      CHECK(read_limited(file) == "read");
    else
      CHECK(read_limited(file).find("a point set of 257 properties per vertex, more than 256") != std::string::npos);
  }
  // an OFF face with many corners, with and without a line end
  std::string off = "OFF\n200 1 0\n";
  for(int i = 0; i < 200; ++i)
    off += std::to_string(std::cos(i * 0.0314159)) + " " + std::to_string(std::sin(i * 0.0314159)) + " 0\n";
  off += "200";
  for(int i = 0; i < 200; ++i)
    off += " " + std::to_string(i);
  CHECK(read_limited(write_file("polygon.off", off + "\n")) == "read");
  CHECK(read_limited(write_file("polygon_no_line_end.off", off)) == "read");
  // a binary STL tetrahedron: its count exact, then one triangle more than the file holds
  const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int triangles[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  for(const std::uint32_t count : {4u, 5u})
  {
    Ply_body stl(Ply_format::LITTLE_ENDIAN_BINARY); // the same little-endian numbers
    stl.add(count);
    for(const auto& t : triangles)
    {
      stl.add(0.f).add(0.f).add(0.f);
      for(int c : t)
        stl.add(corners[c][0]).add(corners[c][1]).add(corners[c][2]);
      stl.add(std::uint16_t(0));
    }
    const std::string file =
      write_file("tetrahedron_" + std::to_string(count) + ".stl", std::string(80, '\0') + stl.bytes());
    if(count == 4)
      CHECK(read_limited(file) == "read");
    else
      CHECK(read_limited(file).find("the header announces 5 triangles, more than a file of 284 bytes") !=
            std::string::npos);
  }
}

TEST_CASE("Input limits: every file of the bad corpus and every fuzzing finding within 256 MiB and 5 s",
          "[io][limits]")
{
  namespace fs = std::filesystem;
  const char* const EXTENSIONS[] = {"off", "obj", "ply", "stl", "xyz", "pwn"}; // the fuzz target's selector byte
  std::size_t files = 0;
  for(const std::string folder : {"bad", "../fuzz/regressions", "../fuzz/seeds"})
  {
    const fs::path dir = fs::path(SN_TEST_DATA_DIR) / folder;
    REQUIRE(fs::is_directory(dir));
    for(const auto& entry : fs::directory_iterator(dir))
    {
      if(!entry.is_regular_file() || entry.path().filename() == "EXPECTED.txt")
        continue;
      INFO(entry.path().string());
      CHECK(entry.file_size() < (std::uintmax_t(1) << 20));
      std::string file = entry.path().string();
      if(folder != "bad")
      {
        const std::string bytes = read_text(file);
        REQUIRE(!bytes.empty());
        // as the fuzz target does: an input with the LAS signature goes to a .las file
        const bool las = bytes.compare(1, 4, "LASF") == 0;
        file = write_file("fuzz_input." + std::string(las ? "las" : EXTENSIONS[std::uint8_t(bytes[0]) % 6]),
                          bytes.substr(1));
      }
      const std::string outcome = read_limited(file);
      CHECK((outcome == "read" || outcome.rfind("Input_error: ", 0) == 0));
      ++files;
    }
  }
  CHECK(files >= 100);
}

// ------------------------------------------------------------------------------------------------
// XYZ files parsed in parallel, a block of lines a thread: the same points and the same first error.

namespace {

// A comment that makes a few thousand lines span several of the reader's 1 MiB blocks.
const std::string XYZ_PADDING = "  # " + std::string(700, '.');

// `n` lines of a point each, in turns of notations, separators, line ends, comment and empty
// lines; `tokens` gets each point's numbers as written. Two lines of known values come first, a
// line without '\n' last.
std::string mixed_xyz(int n, std::vector<std::array<std::string, 3>>& tokens)
{
  std::string text = "1e-3\t+2.5 -0x1p-2\n# a comment line\n\n  .5 -0 1E2\r\n";
  tokens = {{"1e-3", "+2.5", "-0x1p-2"}, {".5", "-0", "1E2"}};
  for(int i = 0; i < n; ++i)
  {
    const double v = std::sin(i * 0.7) * std::pow(10., i % 41 - 20);
    char numbers[3][64];
    std::snprintf(numbers[0], sizeof(numbers[0]), "%.17g", v);
    std::snprintf(numbers[1], sizeof(numbers[1]), i % 2 ? "%+.3f" : "%.3f", v * 1e20); // '+': not from_chars'
    std::snprintf(numbers[2], sizeof(numbers[2]), i % 3 ? "%.6E" : "%a", -v);          // hex: not from_chars'
    tokens.push_back({numbers[0], numbers[1], numbers[2]});
    const char* const separator = i % 4 ? " " : "\t ";
    text += std::string(numbers[0]) + separator + numbers[1] + separator + numbers[2];
    text += i % 5 == 1 ? std::string() : XYZ_PADDING;
    text += i % 7 == 0 ? "\r\n" : "\n";
    if(i % 11 == 0)
      text += "# " + XYZ_PADDING + (i % 2 ? "\n" : "\n\n");
  }
  tokens.push_back({"7", "8", "9"});
  return text + "7 8 9";
}

std::vector<SN::Oriented_point_set::Point_3> read_xyz_points(const std::string& file, unsigned int threads)
{
  std::vector<SN::Oriented_point_set::Point_3> points;
  std::vector<SN::Oriented_point_set::Vector_3> normals;
  bool has_normals = true;
  SN::internal::read_xyz(file, points, normals, has_normals, threads);
  CHECK(normals.empty());
  CHECK_FALSE(has_normals);
  return points;
}

} // namespace

TEST_CASE("Parallel XYZ reading: the points of a sequential reading, bit for bit, on any number of threads",
          "[io][xyz]")
{
  std::vector<std::array<std::string, 3>> tokens;
  const std::string text = mixed_xyz(6000, tokens);
  REQUIRE(text.size() > (std::size_t(3) << 20)); // several blocks
  const std::string file = write_file("mixed.xyz", text);
  for(unsigned int threads : {1u, 2u, 5u})
  {
    INFO("threads: " << threads);
    const auto points = read_xyz_points(file, threads);
    REQUIRE(points.size() == tokens.size());
    // each number as std::strtod reads its text, as the sequential reader did
    std::size_t different = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
      for(int c = 0; c < 3; ++c)
        if(!same_bits(points[i][c], std::strtod(tokens[i][std::size_t(c)].c_str(), nullptr)))
          ++different;
    CHECK(different == 0);
    CHECK(points[0] == SN::Oriented_point_set::Point_3(0.001, 2.5, -0.25));
    CHECK(points[1] == SN::Oriented_point_set::Point_3(0.5, 0., 100.));
    CHECK(std::signbit(points[1].y()));
    CHECK(points.back() == SN::Oriented_point_set::Point_3(7, 8, 9));
  }
}

TEST_CASE("Parallel XYZ reading: the file's first error, with its line number, on any number of threads",
          "[io][xyz]")
{
  // 5000 lines in several blocks (of about 1700 lines): points, comments only in lines
  // [first_comment, last_comment], normals too from line `first_normal` on; some lines replaced
  // (numbered from 1)
  auto xyz = [](const std::vector<std::pair<int, std::string>>& replaced, int first_comment = 0,
                int last_comment = 0, int first_normal = 5001) {
    std::string text;
    for(int line = 1; line <= 5000; ++line)
    {
      auto r = std::find_if(replaced.begin(), replaced.end(), [&](const auto& p) { return p.first == line; });
      text += r != replaced.end() ? r->second
              : line >= first_comment && line <= last_comment
                ? std::string()
                : std::to_string(line) + (line >= first_normal ? " 0.5 -1 0 0 1" : " 0.5 -1");
      text += XYZ_PADDING + "\n";
    }
    return text;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
    {xyz({{4321, "1 2 oops"}}), "line 4321: 'oops' is not a number"},
    {xyz({{4321, "1 inf 2"}, {4322, "x"}}), "line 4321: non-finite value 'inf'"},
    {xyz({{4999, "1 2 3 4"}}), "line 4999: expected 3 (x y z) or 6 (x y z nx ny nz) numbers, got 4"},
    {xyz({{3000, "1 2 3 4 5 6"}, {4500, "nan 1 2"}}), "line 3000: 6 numbers where earlier lines have 3"},
    // the first line with numbers far into the file, in a later block
    {xyz({{4800, "1 2 3"}}, 1, 4000, 1), "line 4800: 3 numbers where earlier lines have 6"},
    {xyz({{4001, "1 2 3 4 5 6"}}, 1, 4000), "line 4002: 3 numbers where earlier lines have 6"},
    // a block whose first line with numbers disagrees with an earlier block's, its own error later
    {xyz({{4500, "x"}}, 1001, 4000, 4001), "line 4001: 6 numbers where earlier lines have 3"},
    // a non-number before the first line with numbers of its block
    {xyz({{20, "# 1 2 3"}, {3999, "1 2 ?"}}, 1, 4000, 1), "line 3999: '?' is not a number"},
  };
  for(std::size_t i = 0; i < cases.size(); ++i)
  {
    const std::string file = write_file("error_" + std::to_string(i) + ".xyz", cases[i].first);
    for(unsigned int threads : {1u, 4u})
    {
      INFO("case " << i << ", threads: " << threads);
      CHECK_THROWS_WITH(read_xyz_points(file, threads), cases[i].second);
    }
  }
}

// ------------------------------------------------------------------------------------------------
// Out of memory in the tool: `sh -c 'ulimit -v ...'` around it.

namespace {

struct Tool_run
{
  int exit_code;
  std::string err;
};

// The tool with `arguments`, its address space limited to `kibibytes` (ulimit -v), on 2 threads.
Tool_run run_tool_limited(std::size_t kibibytes, const std::string& arguments)
{
  const std::string err = path("tool_stderr.txt");
  const std::string command = "OMP_NUM_THREADS=2 sh -c 'ulimit -v " + std::to_string(kibibytes) +
                              " && exec \"$0\" \"$@\"' " + SN_TOOL_PATH + " " + arguments + " 2> " + err +
                              " > /dev/null";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(err)};
}

// `n` points of a unit sphere with their normals, as a binary PLY point set.
std::string sphere_ply(const std::string& name, int n)
{
  Ply_body body(Ply_format::LITTLE_ENDIAN_BINARY);
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = 2.399963229728653 * i;
    const float x = float(r * std::cos(phi)), y = float(r * std::sin(phi));
    body.add(x).add(y).add(float(z)).add(x).add(y).add(float(z));
  }
  return write_file(name, ply_header(Ply_format::LITTLE_ENDIAN_BINARY,
                                     "element vertex " + std::to_string(n) +
                                       "\nproperty float x\nproperty float y\nproperty float z\n"
                                       "property float nx\nproperty float ny\nproperty float nz\n") +
                            body.bytes());
}

// The points and k_max of a search whose per-thread scratch (some kilobytes per neighbor) is
// gigabytes, while the points themselves take a few megabytes: out of memory inside the parallel
// loop, in every thread's scratch, under a limit that reading the points stays well within.
constexpr int OUT_OF_MEMORY_POINTS = 100001;
constexpr std::size_t OUT_OF_MEMORY_LIMIT_KIB = 256 * 1024;

} // namespace

TEST_CASE("Out of memory: one line, exit code 3, no output, inside the parallel search too", "[cli][limits]")
{
  if(ADDRESS_SANITIZER)
  {
    WARN("skipped: AddressSanitizer needs more address space than any limit here");
    return;
  }
  const std::string big = sphere_ply("oom_sphere.ply", OUT_OF_MEMORY_POINTS);
  const std::string k_max = " --k-max " + std::to_string(OUT_OF_MEMORY_POINTS - 1);
  const std::string csv = path("oom.csv");
  const Tool_run oom = run_tool_limited(OUT_OF_MEMORY_LIMIT_KIB, "optimal " + big + " -o " + csv + " --ply " + csv +
                                                                   ".ply" + k_max);
  CHECK(oom.exit_code == 3);
  CHECK(oom.err == "sigmoid-neighborhoods optimal: out of memory while running optimal\n");
  CHECK_FALSE(std::filesystem::exists(csv));
  CHECK_FALSE(std::filesystem::exists(csv + ".ply"));
  // the same limit is plenty for the usual search on these points: the limit is not the reason
  const Tool_run usual = run_tool_limited(OUT_OF_MEMORY_LIMIT_KIB, "optimal " + big + " -o " + csv + " --k-max 8");
  CHECK(usual.exit_code == 0);
  CHECK(std::filesystem::exists(csv));
}

TEST_CASE("Out of memory: evaluate records the model as failed with the message and goes on", "[cli][limits]")
{
  if(ADDRESS_SANITIZER)
  {
    WARN("skipped: AddressSanitizer needs more address space than any limit here");
    return;
  }
  namespace fs = std::filesystem;
  const std::string models = path("oom_models");
  fs::create_directories(models);
  sphere_ply("oom_models/a_big.ply", OUT_OF_MEMORY_POINTS);
  sphere_ply("oom_models/b_big.ply", OUT_OF_MEMORY_POINTS);
  sphere_ply("oom_models/c_small.ply", 50);
  const std::string out = path("oom_evaluation");
  const Tool_run run = run_tool_limited(OUT_OF_MEMORY_LIMIT_KIB, "evaluate " + models + " -o " + out + " --k-max " +
                                                                   std::to_string(OUT_OF_MEMORY_POINTS - 1));
  CHECK(run.exit_code == 0);
  const std::string failures = read_text(out + "/failures.json");
  INFO(failures);
  CHECK(failures.find("a_big.ply") != std::string::npos);
  CHECK(failures.find("b_big.ply") != std::string::npos);
  CHECK(failures.find("c_small.ply") != std::string::npos); // reached after two models out of memory
  std::size_t out_of_memory = 0;
  for(std::size_t at = failures.find("out of memory while evaluating the model"); at != std::string::npos;
      at = failures.find("out of memory while evaluating the model", at + 1))
    ++out_of_memory;
  CHECK(out_of_memory == 2);
  CHECK(failures.find("bad_alloc") == std::string::npos);
  CHECK(fs::exists(out + "/summary.json"));
  CHECK_FALSE(fs::exists(out + "/models/a_big.ply.json"));
}
