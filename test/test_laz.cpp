// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// LAZ input: every LAZ file of the shared data decodes to the SHA-256 of its records that an
// independent LASzip implementation gave (../shared/data/laz/README.md), on one thread and on
// several; reads like its uncompressed twin through read_oriented_point_set(); damaged files (cut,
// bytes flipped in a chunk, a lying chunk table, empty chunks, a layer that overruns its chunk) give
// an Input_error naming the chunk, never a crash. LAZ output: every shared file written again gives
// its records back and, where LASzip or PDAL wrote it, its point data byte for byte; made-up records
// of every compressed format (scanner channels, GPS time sequences, extra bytes, small chunks) come
// back equal for any thread count. The shared files are skipped when ../shared/data is not there.

#include <Lidar_io/Laz_writer.h>
#include <Lidar_io/internal/laz/decode_chunks.h>
#include <Lidar_io/las_output_layout_like.h>
#include <Lidar_io/read_las_records.h>
#include <Sigmoid_neighborhoods_readers/internal/read_las.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include "test_scratch.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <random>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

const std::string LAZ_DIR = SN_SHARED_DATA_DIR "/laz/";

// The test cases tagged [shared-data] run as ctest entries of their own, reported as skipped where
// ../shared/data/laz is missing (test/CMakeLists.txt); run anyway, they fail.
bool have_laz_data()
{
  return std::filesystem::exists(LAZ_DIR + "simple.laz");
}

// This file's folder of the run's scratch folder.
const std::string& laz_scratch()
{
  static const std::string dir = scratch_folder("laz");
  return dir;
}

std::string file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string write_bytes(const std::string& name, const std::string& bytes)
{
  const std::string path = laz_scratch() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  return path;
}

// coreutils' SHA-256 of `bytes`, in hexadecimal.
std::string sha256(const std::string& bytes)
{
  const std::string path = write_bytes("records.bin", bytes);
  FILE* pipe = ::popen(("sha256sum '" + path + "'").c_str(), "r");
  REQUIRE(pipe != nullptr);
  char hex[65] = {};
  const std::size_t read = std::fread(hex, 1, 64, pipe);
  ::pclose(pipe);
  REQUIRE(read == 64);
  return hex;
}

// The point records of a LAS or LAZ file as an uncompressed file stores them, decoded on `threads`.
std::string decoded_records(const std::string& path, unsigned int threads)
{
  std::ifstream in(path, std::ios::binary);
  const Lidar_io::Las_header h = Lidar_io::internal::read_las_header(in, std::filesystem::file_size(path));
  std::string records;
  std::size_t next = 0;
  Lidar_io::internal::for_each_las_record_block(in, h, threads,
                                          [&](std::size_t first, const unsigned char* r, std::size_t count) {
                                            CHECK(first == next);
                                            next = first + count;
                                            records.append(reinterpret_cast<const char*>(r), count * h.record_length);
                                          });
  CHECK(next == h.point_count);
  return records;
}

std::string input_error(const std::string& path)
{
  try
  {
    SN::read_oriented_point_set(path, 0);
  }
  catch(const SN::Input_error& e)
  {
    return e.what();
  }
  return "read";
}

struct Laz_file
{
  const char* name;
  unsigned int format;
  std::uint64_t points;
  const char* records_sha256;
};

// ../shared/data/laz/README.md's table.
const Laz_file LAZ_FILES[] = {
  {"1_4_w_evlr.laz", 6, 1000, "923571fd0bdbfdc886522adcb5fccaa6462642142937b1a3c490519155d447ba"},
  {"autzen_trim.laz", 3, 110000, "f4eb6d80bf1fa507ffdcdaa73606d09041982659a50ee3895957e0b2b347f54b"},
  {"extra.laz", 3, 1065, "c98294910637458e4b55447460f2dece893aca5990f4fd5624fec7d570783c31"},
  {"las_with_several_extra_byte_bloc.laz", 8, 697721,
   "c19b99bc99062598ede4bed3bc6648832211f51b80ac22c8095cb547d8836406"},
  {"plane.laz", 3, 28185, "933d0f7f9519699d14522520a7bb36e798bb07b9a7d60aab2a8b7e98a4d94e6b"},
  {"simple.copc.laz", 7, 1065, "361eda6829430490b1bba3a2665408642d16211f6c349b2f11edf451c8164422"},
  {"simple.laz", 3, 1065, "0717948a72e6bf719db8d96ded1e76b760d73fb683347ebe3dd603832e3d5015"},
  {"test_data_0436_6384_LA93_IGN69_single_point.laz", 8, 1,
   "3ac60a853fa91bd5cc1b633c518167590ea5734ae284efce064a4fe4628ece8c"},
  {"test_data_77050_627755_LA93_IGN69.laz", 8, 73355,
   "ebc159a692f984483c7cb52debad805d39e49831735476fa65c2ec031ba5a388"},
  {"test_data_77050_627760_LA93_IGN69.laz", 8, 56035,
   "257b6e0ed581860897019032e168985a2ae185105d55b4256fdd3a35fe31d978"},
  {"test_data_77055_627755_LA93_IGN69.laz", 8, 72770,
   "3e31031b3ace1abacd5305abd7afdd9a1e050e0d63e6a04fb01ccbb1a3c3e76f"},
  {"test_data_77055_627755_LA93_IGN69_extra_dims.laz", 8, 72770,
   "7e8ee68b5fd2ed04ddca8f46afde17cf8e3494c6cc978cd640c6052e9ebb9240"},
  {"test_data_77055_627760_LA93_IGN69.laz", 8, 60653,
   "9bffe76250c4c2352b182b8f98beaa5e576259d18b876601b292807e85512e28"},
  {"test_data_77060_627755_LA93_IGN69.laz", 8, 83518,
   "128aebd5e28db9faa0e354442d6a2518df093dde581d74cb5c457064fd986a5d"},
  {"test_data_77060_627760_LA93_IGN69.laz", 8, 59606,
   "98b571773ae9c4e5b7f2f94fbe93a8e2293a1be2e0c5ca8cc53917addfff532c"},
  {"test_semis_2023_0292_6833_LA93_IGN69.laz", 6, 289055,
   "230742cf40d7f525ba1dd2cc11025236f75a6b2eebc9baf4aa88ea3477c0e88b"},
  {"test_semis_2023_0292_6833_LA93_IGN69_extra_dims.laz", 6, 289055,
   "c391f323ff92be83e89bd5651e1c76fc7e9681d99ca12a5e5583a3cd33531ff1"},
};

void check_same_points(const SN::Oriented_point_set& a, const SN::Oriented_point_set& b)
{
  REQUIRE(a.points.size() == b.points.size());
  CHECK(a.points == b.points);
  CHECK(a.labels == b.labels);
  CHECK(a.intensities == b.intensities);
  CHECK(a.return_numbers == b.return_numbers);
  CHECK(a.numbers_of_returns == b.numbers_of_returns);
  CHECK(a.gps_times == b.gps_times);
  CHECK(a.merged_duplicates == b.merged_duplicates);
}

} // namespace

// The LASzip-written files of test/data/laz are decoded against their hashes by the lidar IO
// library's own test (lidar_io/test/test_lidar_io.cpp), which needs no ../shared/data.

TEST_CASE("LAZ: every file of the shared data decodes to its records' SHA-256, on 1 and 3 threads", "[laz][io][shared-data]")
{
  REQUIRE(have_laz_data());
  for(const Laz_file& f : LAZ_FILES)
  {
    INFO(f.name);
    const std::string path = LAZ_DIR + f.name;
    const Lidar_io::Las_header h = Lidar_io::read_las_header(path);
    CHECK(h.compressed);
    CHECK(h.point_format == f.format);
    CHECK(h.point_count == f.points);
    const std::string one = decoded_records(path, 1);
    CHECK(one.size() == f.points * h.record_length);
    CHECK(sha256(one) == f.records_sha256);
    if(f.points > 50000) // several chunks
      CHECK(decoded_records(path, 3) == one);
  }
}

TEST_CASE("LAZ: reads like its uncompressed twin, through read_oriented_point_set()", "[laz][io][shared-data]")
{
  REQUIRE(have_laz_data());
  const std::pair<std::string, std::string> twins[] = {
    {LAZ_DIR + "simple.laz", LAZ_DIR + "simple.las"},
    {LAZ_DIR + "1_4_w_evlr.laz", LAZ_DIR + "1_4_w_evlr.las"},
    {LAZ_DIR + "extra.laz", LAZ_DIR + "extrabytes.las"},
  };
  std::vector<std::pair<std::string, std::string>> all(std::begin(twins), std::end(twins));
  for(const char* tile : {"77050_627755", "77050_627760", "77055_627755", "77055_627760", "77060_627755", "77060_627760"})
    all.emplace_back(LAZ_DIR + "test_data_" + tile + "_LA93_IGN69.laz",
                     std::string(SN_SHARED_DATA_DIR "/labeled/ign_lidarhd_") + tile + ".las");
  for(const auto& twin : all)
  {
    INFO(twin.first);
    if(!std::filesystem::exists(twin.second))
      continue;
    CHECK(decoded_records(twin.first, 2) == decoded_records(twin.second, 2));
    SN::Normal_options options;
    options.neighbors = 0;
    options.threads = 2;
    const SN::Oriented_point_set laz = SN::read_oriented_point_set(twin.first, options);
    options.threads = 1;
    const SN::Oriented_point_set las = SN::read_oriented_point_set(twin.second, options);
    CHECK(!laz.labels.empty());
    check_same_points(laz, las);
  }
  // The IGN tile's classes, as its twin has them (2 ground, 3-5 vegetation, 6 building...)
  const SN::Oriented_point_set tile = SN::read_oriented_point_set(LAZ_DIR + "test_data_77050_627755_LA93_IGN69.laz", 0);
  CHECK(tile.points.size() + tile.merged_duplicates == 73355);
}

TEST_CASE("LAZ: wave packets are refused with a message that says so", "[laz][io][shared-data]")
{
  REQUIRE(have_laz_data());
  const std::string message = input_error(LAZ_DIR + "fullwave.laz");
  INFO(message);
  CHECK(message.find("wave packets") != std::string::npos);
}

TEST_CASE("LAZ: damaged files are refused with the chunk named, never a crash", "[laz][io][limits][shared-data]")
{
  REQUIRE(have_laz_data());
  const auto has = [](const std::string& message, const std::string& piece) {
    INFO(message);
    CHECK(message.find(piece) != std::string::npos);
  };
  // A damage that may decode to other points (LAZ has no checksums) or be caught: never a crash,
  // and when caught, the chunk is named.
  const auto refused_or_read = [](const std::string& message) {
    INFO(message);
    CHECK((message == "read" || message.find("chunk") != std::string::npos));
  };
  const auto put32 = [](std::string& b, std::size_t at, std::uint32_t v) {
    for(int i = 0; i < 4; ++i)
      b[at + i] = char((v >> (8 * i)) & 0xFF);
  };
  const auto get32 = [](const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    for(int i = 4; i-- > 0;)
      v = (v << 8) | std::uint8_t(b[at + i]);
    return v;
  };

  for(const char* name : {"simple.laz", "test_data_77050_627755_LA93_IGN69.laz"})
  {
    INFO(name);
    const std::string good = file_bytes(LAZ_DIR + name);
    const std::uint32_t points_at = get32(good, 96);
    const std::uint32_t table = get32(good, points_at); // below 2^32 in these files
    const std::size_t record = std::uint8_t(good[105]) | (std::size_t(std::uint8_t(good[106])) << 8);
    const std::size_t first_chunk = points_at + 8;
    const auto spoiled = [&](const std::string& file, const std::function<void(std::string&)>& spoil) {
      std::string b = good;
      spoil(b);
      return input_error(write_bytes(file, b));
    };

    CHECK(spoiled("good.laz", [](std::string&) {}) == "read");
    // streamed: the table's offset -1 at the start, the offset in the file's last 8 bytes
    {
      std::string b = good;
      for(int i = 0; i < 8; ++i)
        b[points_at + i] = char(0xFF);
      for(int i = 0; i < 8; ++i)
        b.push_back(char(i < 4 ? (table >> (8 * i)) & 0xFF : 0));
      CHECK(decoded_records(write_bytes("streamed.laz", b), 2) == decoded_records(LAZ_DIR + name, 1));
    }
    // cut in the chunks: the chunk table is gone
    has(spoiled("cut.laz", [&](std::string& b) { b.resize(first_chunk + (table - first_chunk) / 2); }),
        "past the end of a file of");
    // cut in the chunk table
    has(spoiled("cut_table.laz", [&](std::string& b) { b.resize(table + 6); }), "past the end of a file of");
    // the table's offset into the header, past the end, and to itself (a writer that stopped)
    has(spoiled("table_in_header.laz", [&](std::string& b) { put32(b, points_at, 100); }),
        "a chunk table at byte 100, before the first chunk");
    has(spoiled("table_past_end.laz", [&](std::string& b) { put32(b, points_at, std::uint32_t(good.size() + 10)); }),
        "past the end of a file of");
    has(spoiled("no_table.laz", [&](std::string& b) { put32(b, points_at, points_at); }), "no chunk table");
    // a chunk count of 2^32 - 1, and one more chunk than the points need
    has(spoiled("chunks_max.laz", [&](std::string& b) { put32(b, table + 4, 0xFFFFFFFFu); }),
        "a chunk table of 4294967295 chunks");
    has(spoiled("chunks_more.laz", [&](std::string& b) { put32(b, table + 4, get32(good, table + 4) + 1); }),
        "chunks");
    has(spoiled("table_version.laz", [&](std::string& b) { put32(b, table, 7); }), "chunk table version 7");
    // the chunk table's coded sizes replaced: sizes that overrun, or none that fits
    has(spoiled("table_garbage.laz", [&](std::string& b) {
          for(std::size_t i = table + 8; i < b.size() && i < table + 24; ++i)
            b[i] = char(0xFF);
        }),
        "chunk 0 of");
    has(spoiled("table_zeros.laz", [&](std::string& b) {
          for(std::size_t i = table + 8; i < b.size(); ++i)
            b[i] = 0;
        }),
        "chunk 0 of");
    // bytes flipped in the first chunk's coded part, and the chunk's coded part zeroed
    for(std::size_t at : {first_chunk + record + 2, first_chunk + record + 40, (first_chunk + table) / 2})
      refused_or_read(spoiled("flipped.laz", [&](std::string& b) {
        for(std::size_t i = at; i < at + 16 && i < table; ++i)
          b[i] = char(~b[i]);
      }));
    refused_or_read(spoiled("zeroed.laz", [&](std::string& b) {
      for(std::size_t i = first_chunk + record; i < table; ++i)
        b[i] = 0;
    }));
    // a point more in the header than in the chunks: the last chunk runs out of bytes (point-wise) or
    // holds another count (layered)
    has(spoiled("more_points.laz", [&](std::string& b) {
          put32(b, 107, get32(good, 107) + 1);
          if(b[25] == 4)
            put32(b, 247, get32(good, 247) + 1);
        }),
        std::string(name) == "simple.laz" ? "chunk 0 of 1, bytes 341 to 18203: the arithmetic decoder reads past"
                                          : "chunk 1 of 2, bytes 216823 to 309595: the chunk says it holds 23355 points");
    // no LASzip record: its record id changed
    has(spoiled("no_laszip.laz", [&](std::string& b) {
          const std::size_t header = std::uint8_t(b[94]) | (std::size_t(std::uint8_t(b[95])) << 8);
          for(std::size_t at = header; at + 54 <= points_at;)
          {
            if(std::uint8_t(b[at + 18]) == 0xBC && std::uint8_t(b[at + 19]) == 0x56)
              b[at + 18] = 0;
            at += 54 + (std::uint8_t(b[at + 20]) | (std::size_t(std::uint8_t(b[at + 21])) << 8));
          }
        }),
        "without the LASzip record");
  }

  // The layered compressor: a layer size past the chunk's bytes. In the IGN tile, the first chunk
  // holds its first point raw (38 bytes), its point count, then the layers' sizes.
  {
    const std::string good = file_bytes(LAZ_DIR + "test_data_77050_627755_LA93_IGN69.laz");
    const std::uint32_t points_at = get32(good, 96);
    const std::size_t sizes = points_at + 8 + 38 + 4;
    for(std::size_t layer : {0, 1, 9})
    {
      std::string b = good;
      put32(b, sizes + 4 * layer, 0x7FFFFFF0u);
      const std::string message = input_error(write_bytes("layer_overrun.laz", b));
      has(message, "chunk 0 of 2");
    }
    std::string b = good;
    put32(b, points_at + 8 + 38, 49999); // the chunk's own point count
    has(input_error(write_bytes("chunk_count.laz", b)), "chunk 0 of 2");
  }

  // Chunks of no bytes and of a few, straight to the decoders: the coder reads past its bytes.
  {
    std::ifstream in(LAZ_DIR + "simple.laz", std::ios::binary);
    const Lidar_io::Las_header h = Lidar_io::internal::read_las_header(in, std::filesystem::file_size(LAZ_DIR + "simple.laz"));
    Lidar_io::internal::laz::Layout layout = Lidar_io::internal::read_laz_layout(in, h);
    REQUIRE(layout.chunk_count() == 1);
    for(std::uint64_t bytes : {std::uint64_t(0), std::uint64_t(h.record_length), std::uint64_t(h.record_length + 5)})
    {
      Lidar_io::internal::laz::Layout cut = layout;
      cut.chunk_starts[1] = cut.chunk_starts[0] + bytes;
      CHECK_THROWS_WITH(Lidar_io::internal::laz::for_each_decoded_chunk(in, cut, h.record_length, 1,
                                                                 [](std::size_t, const unsigned char*, std::size_t) {}),
                        Catch::Contains("chunk 0 of 1"));
    }
  }
}

namespace {

// The compressed point data of a LAZ file: from after the chunk table's offset to the table.
std::string laz_point_data(const std::string& bytes)
{
  std::uint32_t at = 0;
  std::uint64_t table = 0;
  std::memcpy(&at, bytes.data() + 96, 4);
  std::memcpy(&table, bytes.data() + at, 8);
  REQUIRE(table > at + 8);
  REQUIRE(table <= bytes.size());
  return bytes.substr(at + 8, std::size_t(table - at - 8));
}

// Writes `records` as a LAZ file laid out by `layout`, `block` records per write() call.
std::string write_laz(const std::string& name, const Lidar_io::Las_output_layout& layout, const std::string& records,
                      unsigned int threads, std::uint32_t chunk_size = 50000, std::size_t block = 65536)
{
  const std::string path = laz_scratch() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  Lidar_io::Laz_writer<> writer(out, layout, threads, chunk_size);
  const std::size_t length = layout.record_length;
  for(std::size_t first = 0; first < records.size() / length; first += block)
  {
    const std::size_t count = (std::min)(block, records.size() / length - first);
    writer.write(reinterpret_cast<const unsigned char*>(records.data()) + first * length, count);
  }
  writer.close();
  REQUIRE(out.good());
  return path;
}

} // namespace

TEST_CASE("LAZ out: every shared file written again reads back its records, its point data as LASzip wrote it",
          "[laz][io][laz-out][shared-data]")
{
  REQUIRE(have_laz_data());
  for(const Laz_file& f : LAZ_FILES)
  {
    INFO(f.name);
    const std::string path = LAZ_DIR + f.name;
    const std::string records = decoded_records(path, 2);
    const Lidar_io::Las_output_layout layout = Lidar_io::las_output_layout_like(path, {});
    const std::string written = write_laz("again.laz", layout, records, 2);
    CHECK(decoded_records(written, 2) == records);
    const std::string bytes = file_bytes(written);
    CHECK(std::uint8_t(bytes[104]) == (f.format | 0x80u));
    // COPC's chunks follow its octree, with their own point counts: written again in chunks of 50,000
    if(std::string(f.name) != "simple.copc.laz")
      CHECK(laz_point_data(bytes) == laz_point_data(file_bytes(path)));
    if(f.points > 50000)
      CHECK(file_bytes(write_laz("again3.laz", layout, records, 3, 50000, 7919)) == bytes);
  }
}

TEST_CASE("LAZ out: made-up records of formats 0-3 and 6-8 come back equal, for any thread count and chunk size",
          "[laz][io][laz-out]")
{
  std::mt19937 random(2026);
  auto uniform = [&](std::uint32_t n) { return std::uint32_t(random() % n); };
  for(unsigned int format : {0u, 1u, 2u, 3u, 6u, 7u, 8u})
    for(std::size_t extra : {std::size_t(0), std::size_t(5)})
    {
      INFO("format " << format << ", " << extra << " extra bytes");
      Lidar_io::Las_output_layout layout;
      layout.point_format = format;
      layout.copied_record_length = std::uint16_t(Lidar_io::internal::LAS_POINT_RECORD_BYTES[format] + extra);
      layout.record_length = layout.copied_record_length;
      std::memcpy(layout.header.data(), "LASF", 4);
      layout.scale = {{0.01, 0.01, 0.01}};
      const std::size_t length = layout.record_length, points = 5003;
      std::string records(points * length, '\0');
      // unsigned: the walks wrap around 32 bits as the coders' differences do, without overflow
      std::uint32_t x = 1000, y = std::uint32_t(-2000), z = 300;
      std::uint64_t times[4] = {0x41D0000000000000ull, 0x41E0000000000000ull, 0x4000000000000000ull, 0};
      std::uint32_t series = 0;
      for(std::size_t p = 0; p < points; ++p)
      {
        unsigned char* r = reinterpret_cast<unsigned char*>(&records[p * length]);
        // runs of small steps, jumps now and then, all 32 bits at times
        x += std::uint32_t(uniform(21)) - 10u + (uniform(50) == 0 ? std::uint32_t(random()) : 0u);
        y += std::uint32_t(uniform(7)) - 3u;
        z = uniform(30) == 0 ? std::uint32_t(random()) : z + std::uint32_t(uniform(5)) - 2u;
        Lidar_io::store_little_endian<std::uint32_t>(r, x);
        Lidar_io::store_little_endian<std::uint32_t>(r + 4, y);
        Lidar_io::store_little_endian<std::uint32_t>(r + 8, z);
        Lidar_io::store_little_endian<std::uint16_t>(r + 12, std::uint16_t(uniform(4) == 0 ? random() : 200 + uniform(3)));
        const unsigned n = 1 + uniform(format >= 6 ? 15 : 7), ret = 1 + uniform(n);
        // GPS time: steps in one of four interleaved series, the same time again, far jumps
        const std::uint32_t event = uniform(100);
        if(event < 3)
          series = uniform(4);
        if(event == 5)
          times[series] = (std::uint64_t(random()) << 32) | random();
        else if(event > 20)
          times[series] += 1000 + uniform(event > 90 ? 100000 : 3);
        const std::size_t time_at = format >= 6 ? 22 : 20;
        if(format >= 6)
        {
          r[14] = std::uint8_t(ret | (n << 4));
          const unsigned channel = uniform(10) == 0 ? uniform(4) : (p / 500) % 4;
          const unsigned flags = uniform(20) == 0 ? unsigned(random()) & ~0x30u : uniform(10) == 0 ? 0x40u : 0u;
          r[15] = std::uint8_t(flags | (channel << 4));
          r[16] = std::uint8_t(uniform(5) == 0 ? uniform(256) : 2);
          r[17] = std::uint8_t(uniform(3) == 0 ? uniform(256) : 7);
          Lidar_io::store_little_endian<std::int16_t>(r + 18, std::int16_t(uniform(8) == 0 ? random() : -300));
          Lidar_io::store_little_endian<std::uint16_t>(r + 20, std::uint16_t(p / 1000));
        }
        else
        {
          r[14] = std::uint8_t(ret | (n << 3) | (uniform(2) << 6) | (uniform(40) == 0 ? 0x80 : 0));
          r[15] = std::uint8_t(uniform(5) == 0 ? uniform(256) : 2);
          r[16] = std::uint8_t(std::int8_t(uniform(4) == 0 ? int(uniform(181)) - 90 : 10));
          r[17] = std::uint8_t(uniform(3) == 0 ? uniform(256) : 7);
          Lidar_io::store_little_endian<std::uint16_t>(r + 18, std::uint16_t(p / 1000));
        }
        if(format == 1 || format == 3 || format >= 6)
          Lidar_io::store_little_endian<std::uint64_t>(r + time_at, times[series]);
        const std::size_t colour_at = format == 2 ? 20 : format == 3 ? 28 : format >= 7 ? 30 : 0;
        if(colour_at != 0)
        {
          const bool grey = uniform(3) == 0;
          const std::uint16_t red = std::uint16_t(uniform(6) == 0 ? random() : 256 * 40 + uniform(4));
          for(std::size_t c = 0; c < (format == 8 ? 4u : 3u); ++c)
            Lidar_io::store_little_endian<std::uint16_t>(r + colour_at + 2 * c,
                                                   grey && c < 3 ? red : std::uint16_t(red + uniform(600)));
        }
        for(std::size_t e = 0; e < extra; ++e)
          r[length - extra + e] = std::uint8_t(e == 0 ? p : uniform(4) == 0 ? uniform(256) : 9);
      }
      const std::string one = write_laz("made_up.laz", layout, records, 1, 1000, 777);
      CHECK(decoded_records(one, 1) == records);
      CHECK(decoded_records(one, 3) == records);
      CHECK(Lidar_io::read_las_header(one).point_count == points);
      // 6 chunks, the last of 3 records; another block size and thread count: the same bytes
      CHECK(file_bytes(write_laz("made_up_3.laz", layout, records, 3, 1000, 1)) == file_bytes(one));
      // chunks of 2,501: the last holds one record (5,003 = 2 x 2,501 + 1)
      CHECK(decoded_records(write_laz("made_up_one.laz", layout, records, 2, 2501), 2) == records);
    }
}

TEST_CASE("LAZ out: wave packets, empty and one-point files", "[laz][io][laz-out]")
{
  for(unsigned int format : {4u, 5u, 9u, 10u})
  {
    Lidar_io::Las_output_layout layout;
    layout.point_format = format;
    layout.record_length = Lidar_io::internal::LAS_POINT_RECORD_BYTES[format];
    std::ostringstream out;
    CHECK_THROWS_WITH(Lidar_io::Laz_writer<>(out, layout), Catch::Contains("wave packets"));
  }
  std::vector<unsigned int> with_wave_packets;
  for(unsigned int format = 0; format <= 10; ++format)
    if(Lidar_io::las_format_has_wave_packets(format))
      with_wave_packets.push_back(format);
  CHECK(with_wave_packets == std::vector<unsigned int>{4, 5, 9, 10});
  Lidar_io::Las_output_layout layout = Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{1., 1., 1.}}, {});
  layout.record_length = layout.copied_record_length;
  const std::string empty = write_laz("empty.laz", layout, "", 2);
  CHECK(Lidar_io::read_las_header(empty).point_count == 0);
  CHECK(decoded_records(empty, 2).empty());
  std::string one(layout.record_length, '\7');
  CHECK(decoded_records(write_laz("one.laz", layout, one, 2), 1) == one);
}
