// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lidar IO library alone: its target's include path holds nothing of the geometry package, so
// this unit compiles only while the library depends on none of it. The LAZ decoder against the
// LASzip-written files of test/data/laz; LAS and LAZ written and read back; tile catalogs; refusals.

#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <Lidar_io/Las_writer.h>
#include <Lidar_io/Laz_writer.h>
#include <Lidar_io/read_las_records.h>
#include <Lidar_io/read_tile_catalog.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

const std::string LAZ_DIR = LIDAR_IO_TEST_DATA_DIR "/laz/";

std::string scratch(const std::string& name)
{
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "lidar_io_test";
  std::filesystem::create_directories(folder);
  return (folder / name).string();
}

// coreutils' SHA-256 of `bytes`, in hexadecimal
std::string sha256(const std::string& bytes)
{
  const std::string path = scratch("records.bin");
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  FILE* pipe = ::popen(("sha256sum '" + path + "'").c_str(), "r");
  REQUIRE(pipe != nullptr);
  char hex[65] = {};
  const std::size_t read = std::fread(hex, 1, 64, pipe);
  ::pclose(pipe);
  return std::string(hex, read);
}

// the point records of a LAS or LAZ file, concatenated as an uncompressed file stores them
std::string records_of(const std::string& path, unsigned int threads)
{
  const std::size_t length = Lidar_io::read_las_header(path).record_length;
  std::string all;
  std::size_t expected_first = 0;
  Lidar_io::read_las_records(
    path,
    [&](std::size_t first, const unsigned char* records, std::size_t count) {
      CHECK(first == expected_first); // in order
      expected_first += count;
      all.append(reinterpret_cast<const char*>(records), count * length);
    },
    threads);
  return all;
}

// `n` records of point format 6 on a diagonal, with return numbers and GPS times
std::string made_up_records(const Lidar_io::Las_output_layout& layout, std::size_t n)
{
  std::string records(n * layout.record_length, '\0');
  for(std::size_t i = 0; i < n; ++i)
  {
    unsigned char* r = reinterpret_cast<unsigned char*>(&records[i * layout.record_length]);
    Lidar_io::store_las_coordinates(r, layout, {{0.5 * double(i), 0.25 * double(i), 1. + 0.125 * double(i % 7)}});
    r[14] = std::uint8_t(0x11); // return 1 of 1
    const double time = 1000. + double(i);
    std::memcpy(r + 22, &time, 8);
  }
  return records;
}

template <typename Writer, typename... Arguments>
void write_file(const std::string& path, const Lidar_io::Las_output_layout& layout, const std::string& records,
                Arguments... arguments)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  Writer writer(out, layout, arguments...);
  writer.write(reinterpret_cast<const unsigned char*>(records.data()), records.size() / layout.record_length);
  writer.close();
}

} // namespace

TEST_CASE("LAZ: the LASzip-written files decode to their records' SHA-256, on 1 and 2 threads", "[laz]")
{
  struct File
  {
    const char* name;
    unsigned int format;
    std::uint64_t points;
    const char* records_sha256; // test/data/laz/README.md
  };
  const File files[] = {
    {"simple.laz", 3, 1065, "0717948a72e6bf719db8d96ded1e76b760d73fb683347ebe3dd603832e3d5015"},
    {"1_4_w_evlr.laz", 6, 1000, "923571fd0bdbfdc886522adcb5fccaa6462642142937b1a3c490519155d447ba"},
    {"simple.copc.laz", 7, 1065, "361eda6829430490b1bba3a2665408642d16211f6c349b2f11edf451c8164422"},
  };
  for(const File& f : files)
  {
    INFO(f.name);
    const Lidar_io::Las_header h = Lidar_io::read_las_header(LAZ_DIR + f.name);
    CHECK(h.compressed);
    CHECK(h.point_format == f.format);
    CHECK(h.point_count == f.points);
    const std::string one = records_of(LAZ_DIR + f.name, 1);
    CHECK(one.size() == f.points * h.record_length);
    CHECK(sha256(one) == f.records_sha256);
    CHECK(records_of(LAZ_DIR + f.name, 2) == one);
  }
}

TEST_CASE("LAS and LAZ written, read back: the same records, the header's counts and box", "[las][laz]")
{
  const std::time_t day = 1767225600; // 2026-01-01 UTC
  const Lidar_io::Las_output_layout layout =
    Lidar_io::las_output_layout_for({{0., 0., 1.}}, {{2500., 1250., 2.}}, {}, 6, day);
  CHECK(layout.point_format == 6);
  const std::string records = made_up_records(layout, 5000);
  write_file<Lidar_io::Las_writer>(scratch("made_up.las"), layout, records);
  write_file<Lidar_io::Laz_writer<>>(scratch("made_up.laz"), layout, records, 2u);
  for(const char* name : {"made_up.las", "made_up.laz"})
  {
    INFO(name);
    const Lidar_io::Las_header h = Lidar_io::read_las_header(scratch(name));
    CHECK(h.compressed == (std::string(name) == "made_up.laz"));
    CHECK(h.version_minor == 4);
    CHECK(h.point_count == 5000);
    CHECK(h.min[0] == Approx(0.).margin(1e-6));
    CHECK(h.max[0] == Approx(0.5 * 4999).epsilon(1e-12));
    CHECK(records_of(scratch(name), 1) == records);
    CHECK(records_of(scratch(name), 3) == records);
  }
  // the creation date is the one given: the same bytes twice
  write_file<Lidar_io::Las_writer>(scratch("again.las"), layout, records);
  std::ifstream a(scratch("made_up.las"), std::ios::binary), b(scratch("again.las"), std::ios::binary);
  CHECK(std::string(std::istreambuf_iterator<char>(a), {}) == std::string(std::istreambuf_iterator<char>(b), {}));
}

TEST_CASE("tile catalog: LAS extents from the headers, other formats through a reader", "[catalog]")
{
  const std::filesystem::path folder = scratch("catalog");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  for(int t = 0; t < 2; ++t)
  {
    const double x0 = 100. * t;
    const Lidar_io::Las_output_layout layout =
      Lidar_io::las_output_layout_for({{x0, 0., 0.}}, {{x0 + 99.5 * 0.5, 50., 2.}}, {}, 6, 0);
    std::string records(100 * layout.record_length, '\0');
    for(std::size_t i = 0; i < 100; ++i)
      Lidar_io::store_las_coordinates(reinterpret_cast<unsigned char*>(&records[i * layout.record_length]), layout,
                                      {{x0 + 0.5 * double(i), 0.5 * double(i), 1.}});
    write_file<Lidar_io::Las_writer>((folder / ("tile_" + std::to_string(t) + ".las")).string(), layout, records);
  }
  const Lidar_io::Tile_catalog catalog = Lidar_io::read_tile_catalog(folder.string());
  REQUIRE(catalog.tiles.size() == 2);
  CHECK(catalog.tiles[0].name == "tile_0");
  CHECK(catalog.tiles[1].points == 100);
  CHECK(catalog.tiles[1].extent_from_header);
  CHECK(catalog.tiles[1].extent.xmin() <= 100.);
  CHECK(catalog.tiles[1].extent.xmax() >= 149.5);
  CHECK(catalog.index_of("tile_1") == 1);
  CHECK_THROWS_AS(catalog.index_of("tile_2"), Lidar_io::Input_error);

  // a PLY tile: refused without a reader, read by the caller's
  std::ofstream(folder / "tile_2.ply") << "ply\n";
  CHECK_THROWS_WITH(Lidar_io::read_tile_catalog(folder.string()), Catch::Contains("no reader for .ply tiles"));
  const Lidar_io::Tile_catalog with_ply =
    Lidar_io::read_tile_catalog(folder.string(), [](const std::string&, Lidar_io::Catalog_tile& tile) {
      tile.extent = CGAL::Bbox_2(200., 0., 210., 10.);
      tile.points = 7;
    });
  REQUIRE(with_ply.tiles.size() == 3);
  CHECK(with_ply.tiles[2].points == 7);
  CHECK_FALSE(with_ply.tiles[2].extent_from_header);
}

TEST_CASE("refusals: missing, empty and truncated files, with a message", "[las][bad-input]")
{
  CHECK_THROWS_AS(Lidar_io::read_las_header(scratch("missing.las")), Lidar_io::Input_error);
  std::ofstream(scratch("empty.las"), std::ios::binary | std::ios::trunc).flush();
  CHECK_THROWS_AS(Lidar_io::read_las_header(scratch("empty.las")), Lidar_io::Input_error);
  std::ifstream in(LAZ_DIR + "simple.laz", std::ios::binary);
  std::string bytes(std::istreambuf_iterator<char>(in), {});
  bytes.resize(bytes.size() / 2); // half its chunks
  std::ofstream(scratch("half.laz"), std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  CHECK_THROWS_AS(records_of(scratch("half.laz"), 1), Lidar_io::Input_error);
  CHECK_THROWS_AS(Lidar_io::read_tile_catalog(scratch("no_such_folder")), Lidar_io::Input_error);
}

TEST_CASE("refusals: a point count the file cannot hold, before anything is sized to it", "[las][bad-input]")
{
  // 2,000,000,000 records of 20 bytes announced in a file of 287 bytes
  const std::string file = LIDAR_IO_TEST_DATA_DIR "/bad/las_count_beyond_file.las";
  try
  {
    Lidar_io::read_las_header(file);
    FAIL("the header was accepted");
  }
  catch(const Lidar_io::Input_error& e)
  {
    CHECK(std::string(e.what()) ==
          "cannot parse the file as las (the header announces 2000000000 points of 20 bytes from byte 227, more than "
          "a file of 287 bytes can hold: 60 bytes left, at least 20 bytes each)");
  }
}
