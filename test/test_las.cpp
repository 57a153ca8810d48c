// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// LAS input: files written here byte by byte (ASPRS LAS 1.4 R15 layout) for every version 1.0-1.4
// and point data format 0-10, read back to the exact coordinates (X * scale + offset in double),
// classification, intensity, returns and GPS time; hostile headers refused with a message before
// anything is sized to them; the IGN LiDAR HD tile of the shared data when present;
// labels of PLY point sets; zero normals in point-set files under Normal_source::AUTO.

#include <Lidar_io/Las_writer.h>
#include <Lidar_io/las_output_layout_like.h>
#include <Sigmoid_neighborhoods_readers/internal/read_las.h>
#include <Lidar_io/read_las_records.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include "test_scratch.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

// This file's folder of the run's scratch folder.
const std::string& las_scratch()
{
  static const std::string dir = scratch_folder("las");
  return dir;
}

std::string write_bytes(const std::string& name, const std::string& bytes)
{
  const std::string path = las_scratch() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  return path;
}

// Little-endian numbers written into `bytes` at `at`, whatever the machine's byte order.
template <typename T>
void put(std::string& bytes, std::size_t at, T value)
{
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  std::uint64_t u = 0;
  for(std::size_t i = sizeof(T); i-- > 0;) // the value as an unsigned integer, host order
    u = (u << 8) | raw[i];
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  if(first != 1) // big-endian host: the bytes were read in reverse
  {
    u = 0;
    for(std::size_t i = 0; i < sizeof(T); ++i)
      u = (u << 8) | raw[i];
  }
  REQUIRE(at + sizeof(T) <= bytes.size());
  for(std::size_t i = 0; i < sizeof(T); ++i)
    bytes[at + i] = char((u >> (8 * i)) & 0xFF);
}

struct Las_point
{
  std::int32_t X = 0, Y = 0, Z = 0;
  std::uint16_t intensity = 0;
  unsigned int return_number = 1, number_of_returns = 1;
  unsigned int classification = 0;
  double gps_time = 0.;
};

const std::uint16_t BASE_RECORD[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

// A LAS file of `points`: the header of its version (227 bytes for 1.0-1.2, 235 for 1.3, 375 for
// 1.4), `vlr_bytes` of padding where the VLRs go, then the records of `format` with `extra_bytes`
// more each. The other fields of the records (flags, scan angle, colors, wave packets, extra bytes)
// are filled with 0xA5 bytes that the reader must not take for anything. Fields can be spoiled after.
struct Las_file
{
  unsigned int minor = 2, format = 0;
  std::uint16_t extra_bytes = 0, vlr_bytes = 0;
  double scale[3] = {0.01, 0.01, 0.01}, offset[3] = {0., 0., 0.};
  std::vector<Las_point> points;

  std::size_t header_size() const { return minor <= 2 ? 227 : minor == 3 ? 235 : 375; }
  std::size_t record_length() const { return BASE_RECORD[format] + extra_bytes; }
  std::size_t point_data() const { return header_size() + vlr_bytes; }

  std::string bytes() const
  {
    std::string b(point_data() + points.size() * record_length(), char(0));
    std::memcpy(&b[0], "LASF", 4);
    b[24] = char(1);
    b[25] = char(minor);
    put<std::uint16_t>(b, 94, std::uint16_t(header_size()));
    put<std::uint32_t>(b, 96, std::uint32_t(point_data()));
    put<std::uint8_t>(b, 104, std::uint8_t(format));
    put<std::uint16_t>(b, 105, std::uint16_t(record_length()));
    const bool extended = format >= 6;
    put<std::uint32_t>(b, 107, minor == 4 && extended ? 0u : std::uint32_t(points.size()));
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for(const Las_point& p : points)
    {
      const std::int32_t raw[3] = {p.X, p.Y, p.Z};
      for(int c = 0; c < 3; ++c)
      {
        lo[c] = (std::min)(lo[c], double(raw[c]) * scale[c] + offset[c]);
        hi[c] = (std::max)(hi[c], double(raw[c]) * scale[c] + offset[c]);
      }
    }
    for(int c = 0; c < 3; ++c)
    {
      put<double>(b, 131 + 8 * c, scale[c]);
      put<double>(b, 155 + 8 * c, offset[c]);
      put<double>(b, 179 + 16 * c, hi[c]);
      put<double>(b, 187 + 16 * c, lo[c]);
    }
    if(minor == 4)
      put<std::uint64_t>(b, 247, std::uint64_t(points.size()));
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const Las_point& p = points[i];
      const std::size_t r = point_data() + i * record_length();
      std::fill(b.begin() + std::ptrdiff_t(r), b.begin() + std::ptrdiff_t(r + record_length()), char(0xA5));
      put<std::int32_t>(b, r, p.X);
      put<std::int32_t>(b, r + 4, p.Y);
      put<std::int32_t>(b, r + 8, p.Z);
      put<std::uint16_t>(b, r + 12, p.intensity);
      if(extended)
      {
        put<std::uint8_t>(b, r + 14, std::uint8_t(p.return_number | p.number_of_returns << 4));
        put<std::uint8_t>(b, r + 15, std::uint8_t(0xFF)); // classification flags, channel, scan direction, edge
        put<std::uint8_t>(b, r + 16, std::uint8_t(p.classification));
        put<double>(b, r + 22, p.gps_time);
      }
      else
      {
        // scan direction and edge of flight line set; synthetic, key-point and withheld set
        put<std::uint8_t>(b, r + 14, std::uint8_t(p.return_number | p.number_of_returns << 3 | 0xC0));
        put<std::uint8_t>(b, r + 15, std::uint8_t(p.classification | 0xE0));
        if(format != 0 && format != 2)
          put<double>(b, r + 20, p.gps_time);
      }
    }
    return b;
  }
};

// Points with negative, zero and large raw values and every field varied.
std::vector<Las_point> sample_points(unsigned int format, std::size_t n)
{
  const bool extended = format >= 6;
  std::vector<Las_point> points;
  for(std::size_t i = 0; i < n; ++i)
  {
    Las_point p;
    p.X = std::int32_t(i * 7919 % 2001) - 1000 + (i == 1 ? 2000000000 : 0);
    p.Y = std::int32_t(i * 104729 % 3001) - 1500 - (i == 2 ? 2000000000 : 0);
    p.Z = std::int32_t(i * 31 % 97) * (i % 2 == 0 ? 1 : -1);
    p.intensity = std::uint16_t(i == 3 ? 65535 : i * 1237 % 65536);
    p.number_of_returns = extended ? unsigned(1 + i % 15) : unsigned(1 + i % 7);
    p.return_number = 1 + unsigned(i / 3) % p.number_of_returns;
    p.classification = extended ? unsigned(i * 37 % 256) : unsigned(i * 5 % 32);
    p.gps_time = 3.0646e8 + 0.0123456789 * double(i);
    points.push_back(p);
  }
  return points;
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

SN::Oriented_point_set read_las_points(const std::string& path)
{
  SN::internal::Input_file file;
  file.name = path;
  file.extension = SN::lower_case_extension(path);
  file.size = std::filesystem::file_size(path);
  SN::Oriented_point_set out;
  SN::internal::read_las(file, out);
  return out;
}

} // namespace

TEST_CASE("LAS: every version 1.0-1.4 and point data format 0-10 read exactly", "[las][io]")
{
  for(unsigned int minor = 0; minor <= 4; ++minor)
    for(unsigned int format = 0; format <= 10; ++format)
      for(std::uint16_t extra : {std::uint16_t(0), std::uint16_t(5)})
      {
        INFO("LAS 1." << minor << ", format " << format << ", " << extra << " extra bytes");
        Las_file las;
        las.minor = minor;
        las.format = format;
        las.extra_bytes = extra;
        las.vlr_bytes = std::uint16_t(extra * 11); // something between the header and the points
        las.scale[0] = 0.01;
        las.scale[1] = 0.001;
        las.scale[2] = 0.25;
        las.offset[0] = 770000.;
        las.offset[1] = -6277500.5;
        las.offset[2] = 12.125;
        las.points = sample_points(format, 37);
        const std::string path = write_bytes("v1" + std::to_string(minor) + "_f" + std::to_string(format) + ".las",
                                             las.bytes());

        const Lidar_io::Las_header h = Lidar_io::read_las_header(path);
        CHECK(h.version_major == 1);
        CHECK(h.version_minor == minor);
        CHECK(h.point_format == format);
        CHECK(h.header_size == las.header_size());
        CHECK(h.offset_to_point_data == las.point_data());
        CHECK(h.record_length == las.record_length());
        CHECK(h.point_count == 37u);
        CHECK(h.scale[1] == 0.001);
        CHECK(h.offset[1] == -6277500.5);

        const SN::Oriented_point_set out = read_las_points(path);
        REQUIRE(out.points.size() == 37);
        REQUIRE(out.labels.size() == 37);
        REQUIRE(out.intensities.size() == 37);
        REQUIRE(out.return_numbers.size() == 37);
        REQUIRE(out.numbers_of_returns.size() == 37);
        CHECK(out.normals.empty());
        const bool has_gps = format != 0 && format != 2;
        REQUIRE(out.gps_times.size() == (has_gps ? 37u : 0u));
        double lo_x = 1e300, hi_x = -1e300;
        for(std::size_t i = 0; i < 37; ++i)
        {
          const Las_point& p = las.points[i];
          CHECK(out.points[i].x() == double(p.X) * 0.01 + 770000.);
          CHECK(out.points[i].y() == double(p.Y) * 0.001 + -6277500.5);
          CHECK(out.points[i].z() == double(p.Z) * 0.25 + 12.125);
          CHECK(out.labels[i] == int(p.classification));
          CHECK(out.intensities[i] == p.intensity);
          CHECK(out.return_numbers[i] == p.return_number);
          CHECK(out.numbers_of_returns[i] == p.number_of_returns);
          if(has_gps)
            CHECK(out.gps_times[i] == p.gps_time);
          lo_x = (std::min)(lo_x, out.points[i].x());
          hi_x = (std::max)(hi_x, out.points[i].x());
        }
        CHECK(h.min[0] == lo_x);
        CHECK(h.max[0] == hi_x);
      }
}

TEST_CASE("LAS: spot values of the record layouts", "[las][io]")
{
  // Raw values chosen by hand: classification 200 only fits formats 6-10; 31 and flags in 0-5.
  Las_file legacy;
  legacy.format = 1;
  legacy.scale[0] = legacy.scale[1] = legacy.scale[2] = 0.01;
  legacy.offset[0] = 100.;
  Las_point p;
  p.X = 12345;
  p.Y = -1;
  p.Z = 2147483647;
  p.intensity = 513;
  p.return_number = 7;
  p.number_of_returns = 7;
  p.classification = 31;
  p.gps_time = -1.5;
  legacy.points = {p};
  SN::Oriented_point_set a = read_las_points(write_bytes("spot_legacy.las", legacy.bytes()));
  REQUIRE(a.points.size() == 1);
  CHECK(a.points[0].x() == 12345. * 0.01 + 100.);
  CHECK(a.points[0].x() == Approx(223.45).margin(1e-12));
  CHECK(a.points[0].y() == -0.01);
  CHECK(a.points[0].z() == 2147483647. * 0.01);
  CHECK(a.labels[0] == 31);
  CHECK(a.intensities[0] == 513);
  CHECK(a.return_numbers[0] == 7);
  CHECK(a.numbers_of_returns[0] == 7);
  CHECK(a.gps_times[0] == -1.5);

  Las_file extended;
  extended.minor = 4;
  extended.format = 8;
  p.classification = 200;
  p.return_number = 3;
  p.number_of_returns = 15;
  p.intensity = 65535;
  extended.points = {p};
  SN::Oriented_point_set b = read_las_points(write_bytes("spot_extended.las", extended.bytes()));
  REQUIRE(b.points.size() == 1);
  CHECK(b.labels[0] == 200);
  CHECK(b.return_numbers[0] == 3);
  CHECK(b.numbers_of_returns[0] == 15);
  CHECK(b.intensities[0] == 65535);
  CHECK(b.gps_times[0] == -1.5);
}

TEST_CASE("LAS: the 64-bit count of LAS 1.4 and the legacy count", "[las][io]")
{
  Las_file las;
  las.minor = 4;
  las.format = 1;
  las.points = sample_points(1, 10);
  std::string bytes = las.bytes();
  // the legacy count only (64-bit 0): read
  put<std::uint64_t>(bytes, 247, 0);
  CHECK(read_las_points(write_bytes("legacy_only.las", bytes)).points.size() == 10);
  // the 64-bit count wins when not 0
  put<std::uint32_t>(bytes, 107, 3);
  put<std::uint64_t>(bytes, 247, 10);
  CHECK(read_las_points(write_bytes("count64.las", bytes)).points.size() == 10);
  // in LAS 1.2 there is no 64-bit count: bytes 247.. are VLRs or points
  Las_file old;
  old.minor = 2;
  old.vlr_bytes = 200;
  old.points = sample_points(0, 4);
  bytes = old.bytes();
  put<std::uint64_t>(bytes, 247, 99);
  CHECK(read_las_points(write_bytes("no_count64.las", bytes)).points.size() == 4);
}

TEST_CASE("LAS: through read_oriented_point_set, normals estimated, extras kept through merging", "[las][io]")
{
  Las_file las;
  las.minor = 3;
  las.format = 3;
  las.scale[0] = las.scale[1] = las.scale[2] = 0.001;
  for(int i = 0; i < 12; ++i)
    for(int j = 0; j < 12; ++j)
    {
      Las_point p;
      p.X = 1000 * i;
      p.Y = 1000 * j;
      p.Z = (i * 7 + j * 3) % 5 * 10; // a rough plane
      p.classification = unsigned(i % 2 == 0 ? 2 : 6);
      p.intensity = std::uint16_t(i * 12 + j);
      p.gps_time = double(i * 12 + j);
      las.points.push_back(p);
    }
  // duplicates of points 5 and 17 at the end, with other values: merged into the first
  Las_point d = las.points[5];
  d.classification = 9;
  d.intensity = 9999;
  las.points.push_back(d);
  d = las.points[17];
  d.classification = 9;
  las.points.push_back(d);
  const std::string path = write_bytes("grid.las", las.bytes());

  const SN::Oriented_point_set with_normals = SN::read_oriented_point_set(path);
  CHECK(with_normals.input_vertices == 146);
  CHECK(with_normals.merged_duplicates == 2);
  REQUIRE(with_normals.points.size() == 144);
  CHECK(with_normals.normals.size() == 144);
  CHECK(with_normals.normals_estimated);
  CHECK_FALSE(with_normals.is_mesh);
  REQUIRE(with_normals.labels.size() == 144);
  REQUIRE(with_normals.intensities.size() == 144);
  REQUIRE(with_normals.return_numbers.size() == 144);
  REQUIRE(with_normals.numbers_of_returns.size() == 144);
  REQUIRE(with_normals.gps_times.size() == 144);
  for(std::size_t k = 0; k < 144; ++k)
  {
    CHECK(with_normals.labels[k] == (k / 12 % 2 == 0 ? 2 : 6));
    CHECK(with_normals.intensities[k] == k);
    CHECK(with_normals.gps_times[k] == double(k));
    CHECK(with_normals.points[k].x() == double(1000 * int(k / 12)) * 0.001);
    CHECK(std::abs(with_normals.normals[k].z()) > 0.9); // a plane near z = const
  }

  // without estimation (0 neighbors): no normals, the same extras; FROM_FILE refuses
  const SN::Oriented_point_set plain = SN::read_oriented_point_set(path, 0);
  CHECK(plain.normals.empty());
  CHECK(plain.labels == with_normals.labels);
  SN::Normal_options from_file;
  from_file.source = SN::Normal_source::FROM_FILE;
  CHECK_THROWS_WITH(SN::read_oriented_point_set(path, from_file), "the file has no normals");

  // upper-case extension
  const std::string upper = write_bytes("GRID.LAS", las.bytes());
  CHECK(SN::read_oriented_point_set(upper, 0).points.size() == 144);
}

TEST_CASE("LAS: hostile headers are refused with a message, nothing sized to them", "[las][io][limits]")
{
  Las_file las;
  las.format = 1;
  las.points = sample_points(1, 2);
  const std::string good = las.bytes(); // 227 + 2 * 28 = 283 bytes
  REQUIRE(good.size() == 283);
  CHECK(input_error(write_bytes("good.las", good)) == "read");
  const auto spoiled = [&](const std::string& name, const std::function<void(std::string&)>& spoil) {
    std::string bytes = good;
    spoil(bytes);
    return input_error(write_bytes(name, bytes));
  };
  const auto has = [](const std::string& message, const std::string& piece) {
    INFO(message);
    CHECK(message.find(piece) != std::string::npos);
  };

  has(input_error(write_bytes("truncated_header.las", good.substr(0, 100))),
      "cannot parse the file as las (a file of 100 bytes ends in the header, which takes 227 bytes at least)");
  has(input_error(write_bytes("signature_only.las", "LASF")), "a file of 4 bytes ends in the header");
  has(input_error(write_bytes("short_garbage.las", "LA")), "no LAS signature 'LASF' at the start");
  has(spoiled("bad_signature.las", [](std::string& b) { b[3] = 'X'; }), "no LAS signature 'LASF' at the start");
  has(spoiled("count_beyond.las", [](std::string& b) { put<std::uint32_t>(b, 107, 1000000); }),
      "the header announces 1000000 points of 28 bytes from byte 227, more than a file of 283 bytes can hold: "
      "56 bytes left, at least 28 bytes each");
  has(spoiled("count_one_beyond.las", [](std::string& b) { put<std::uint32_t>(b, 107, 3); }),
      "the header announces 3 points of 28 bytes");
  has(spoiled("count_max.las", [](std::string& b) { put<std::uint32_t>(b, 107, 0xFFFFFFFFu); }),
      "the header announces 4294967295 points");
  has(spoiled("record_too_short.las", [](std::string& b) { put<std::uint16_t>(b, 105, 20); }),
      "point records of 20 bytes, less than the 28 of point data format 1");
  has(spoiled("record_zero.las", [](std::string& b) { put<std::uint16_t>(b, 105, 0); }),
      "point records of 0 bytes");
  has(spoiled("format_11.las", [](std::string& b) { b[104] = char(11); }), "point data format 11 is not read");
  has(spoiled("format_63.las", [](std::string& b) { b[104] = char(63); }), "point data format 63 is not read");
  has(spoiled("laz_bit7.las", [](std::string& b) { b[104] = char(0x81); }),
      "cannot decode the file as laz (compressed points without the LASzip record");
  has(spoiled("laz_bit6.las", [](std::string& b) { b[104] = char(0x41); }), "without the LASzip record");
  has(spoiled("version_2.las", [](std::string& b) { b[24] = char(2); }),
      "version 2.2 is not read: expected 1.0 to 1.4");
  has(spoiled("version_1_5.las", [](std::string& b) { b[25] = char(5); }), "version 1.5 is not read");
  has(spoiled("header_too_small.las", [](std::string& b) { put<std::uint16_t>(b, 94, 200); }),
      "a header size of 200 bytes, less than the 227 of every version");
  has(spoiled("header_too_big.las", [](std::string& b) { put<std::uint16_t>(b, 94, 60000); }),
      "a header size of 60000 bytes, more than the file's 283");
  has(spoiled("zero_scale.las", [](std::string& b) { put<double>(b, 139, 0.); }), "a zero scale factor of y");
  has(spoiled("nan_scale.las", [](std::string& b) { put<double>(b, 147, std::nan("")); }),
      "a non-finite scale factor of z");
  has(spoiled("inf_scale.las",
              [](std::string& b) { put<double>(b, 131, std::numeric_limits<double>::infinity()); }),
      "a non-finite scale factor of x");
  has(spoiled("nan_offset.las", [](std::string& b) { put<double>(b, 163, std::nan("")); }),
      "a non-finite offset of y");
  has(spoiled("offset_beyond.las", [](std::string& b) { put<std::uint32_t>(b, 96, 5000); }),
      "point data at byte 5000, beyond the end of a file of 283 bytes");
  has(spoiled("offset_in_header.las", [](std::string& b) { put<std::uint32_t>(b, 96, 100); }),
      "point data at byte 100, inside the header of 227 bytes");
  has(spoiled("overflow.las", [](std::string& b) { put<double>(b, 131, 1e308); }),
      "point 0 has a non-finite coordinate after scale and offset");
  has(spoiled("no_points.las", [](std::string& b) { put<std::uint32_t>(b, 107, 0); }), "no points in the file");

  // LAS 1.4: a 64-bit count of 2^64 - 1 is refused, not allocated
  Las_file v14;
  v14.minor = 4;
  v14.format = 6;
  v14.points = sample_points(6, 2);
  std::string bytes = v14.bytes();
  put<std::uint64_t>(bytes, 247, ~std::uint64_t(0));
  has(input_error(write_bytes("count64_max.las", bytes)),
      "the header announces 18446744073709551615 points of 30 bytes from byte 375, more than a file of 435 bytes");

  // The header, not the extension, says whether the points are compressed: uncompressed points in a
  // `.laz` file are read; a compressed format byte without LASzip's record is refused.
  CHECK(input_error(write_bytes("uncompressed_content.laz", good)) == "read");
  has(input_error(write_bytes("UPPER.LAZ", "garbage")), "no LAS signature 'LASF' at the start");
  CHECK(Lidar_io::read_las_header(write_bytes("header.laz", good)).point_count == 2);
  CHECK_THROWS_AS(Lidar_io::read_las_header(las_scratch() + "/missing.las"), SN::Input_error);
}

// [shared-data]: a ctest entry of its own, skipped where ../shared/data is missing (test/CMakeLists.txt)
TEST_CASE("LAS: the IGN LiDAR HD tile of the shared data", "[las][io][shared-data]")
{
  const std::string path = SN_SHARED_DATA_DIR "/labeled/ign_lidarhd_77050_627755.las";
  REQUIRE(std::filesystem::exists(path));
  const Lidar_io::Las_header h = Lidar_io::read_las_header(path);
  CHECK(h.version_major == 1);
  CHECK(h.version_minor == 4);
  CHECK(h.point_format == 8);
  CHECK(h.header_size == 375);
  CHECK(h.offset_to_point_data == 1847);
  CHECK(h.record_length == 38);
  CHECK(h.point_count == 73355u);
  CHECK(h.scale[0] == 0.01);
  CHECK(h.offset[0] == 0.);
  CHECK(h.min[0] == Approx(770500.00).margin(1e-6));
  CHECK(h.max[0] == Approx(770541.68).margin(1e-6));

  const SN::Oriented_point_set raw = read_las_points(path);
  REQUIRE(raw.points.size() == 73355);
  std::map<int, std::size_t> classes;
  for(int label : raw.labels)
    ++classes[label];
  const std::map<int, std::size_t> expected = {{1, 1344}, {2, 13881}, {3, 187}, {4, 1190}, {5, 29514}, {6, 27239}};
  CHECK(classes == expected); // and no 64
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const auto& p : raw.points)
    for(int c = 0; c < 3; ++c)
    {
      lo[c] = (std::min)(lo[c], p[c]);
      hi[c] = (std::max)(hi[c], p[c]);
    }
  CHECK(lo[0] == Approx(770500.00).margin(1e-6));
  CHECK(hi[0] == Approx(770541.68).margin(1e-6));
  CHECK(lo[0] == h.min[0]);
  CHECK(hi[0] == h.max[0]);
  CHECK(lo[1] == Approx(6277500).margin(0.5));
  CHECK(hi[1] == Approx(6277550).margin(0.5));
  CHECK(lo[2] == Approx(20.25).margin(1e-6));
  CHECK(hi[2] == Approx(43.49).margin(1e-6));
  CHECK(raw.gps_times.size() == 73355);
  CHECK(*std::min_element(raw.gps_times.begin(), raw.gps_times.end()) > 3e8);
  for(std::size_t i = 0; i < raw.points.size(); ++i)
  {
    CHECK(raw.return_numbers[i] >= 1);
    CHECK(raw.return_numbers[i] <= raw.numbers_of_returns[i]);
    if(raw.return_numbers[i] < 1 || raw.return_numbers[i] > raw.numbers_of_returns[i])
      break;
  }

  // through the library reader: 3 duplicates merged, labels one per point
  const SN::Oriented_point_set model = SN::read_oriented_point_set(path, 0);
  CHECK(model.input_vertices == 73355);
  CHECK(model.merged_duplicates == 3);
  CHECK(model.points.size() == 73352);
  CHECK(model.labels.size() == 73352);
  CHECK(model.intensities.size() == 73352);
  CHECK(model.gps_times.size() == 73352);
  // each record's point: the merged records point at their first's position, every point has its record
  REQUIRE(model.point_of_input.size() == 73355);
  std::vector<std::size_t> records_of_point(model.points.size(), 0);
  for(std::size_t r = 0; r < raw.points.size(); ++r)
  {
    REQUIRE(model.point_of_input[r] < model.points.size());
    CHECK(model.points[model.point_of_input[r]] == raw.points[r]);
    ++records_of_point[model.point_of_input[r]];
  }
  CHECK(std::count(records_of_point.begin(), records_of_point.end(), 2) == 3);
  CHECK(std::count(records_of_point.begin(), records_of_point.end(), 0) == 0);
}

TEST_CASE("PLY point sets: a label, class or classification property becomes the labels", "[las][io][ply]")
{
  const auto ply = [](const std::string& property, const std::vector<std::string>& values, bool normals) {
    std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(values.size()) +
                       "\nproperty double x\nproperty double y\nproperty double z\n";
    if(normals)
      text += "property double nx\nproperty double ny\nproperty double nz\n";
    text += "property " + property + "\nend_header\n";
    for(std::size_t i = 0; i < values.size(); ++i)
    {
      const std::size_t at = i == values.size() - 1 ? 1 : i; // the last point duplicates point 1
      text += std::to_string(at % 4) + " " + std::to_string(at / 4) + " " + std::to_string(at % 3) +
              (normals ? " 0 0 1 " : " ") + values[i] + "\n";
    }
    return text;
  };
  const std::vector<std::string> values = {"0", "1", "2", "6", "64", "200", "3", "9"};
  const std::vector<int> expected = {0, 1, 2, 6, 64, 200, 3}; // the duplicate merged into point 1

  for(const std::string& type : {"uchar", "char", "short", "ushort", "int", "uint", "float", "double"})
    for(const std::string& name : {"label", "class", "classification"})
    {
      INFO(type << " " << name);
      std::vector<std::string> v = values;
      if(type == "char")
        v[5] = "-56";
      const std::string path = write_bytes("labels_" + type + "_" + name + ".ply", ply(type + " " + name, v, true));
      const SN::Oriented_point_set model = SN::read_oriented_point_set(path, 0);
      REQUIRE(model.points.size() == 7);
      CHECK(model.merged_duplicates == 1);
      std::vector<int> e = expected;
      if(type == "char")
        e[5] = -56;
      CHECK(model.labels == e);
      CHECK(model.intensities.empty());
    }

  // without normals: estimated, labels kept
  std::vector<std::string> many;
  for(int i = 0; i < 40; ++i)
    many.push_back(std::to_string(i % 5));
  many.back() = "4"; // the duplicate of point 1
  const std::string plain_path = [&] {
    std::string text = "ply\nformat ascii 1.0\nelement vertex 40\n"
                       "property float x\nproperty float y\nproperty float z\nproperty int label\nend_header\n";
    for(int i = 0; i < 40; ++i)
    {
      const int at = i == 39 ? 1 : i;
      text += std::to_string(at % 7) + " " + std::to_string(at / 7) + " " + std::to_string((at * 3) % 2) + " " +
              many[std::size_t(i)] + "\n";
    }
    return write_bytes("labels_no_normals.ply", text);
  }();
  const SN::Oriented_point_set estimated = SN::read_oriented_point_set(plain_path, 6);
  REQUIRE(estimated.points.size() == 39);
  CHECK(estimated.normals_estimated);
  REQUIRE(estimated.labels.size() == 39);
  for(std::size_t i = 0; i < 39; ++i)
    CHECK(estimated.labels[i] == int(i % 5));

  // no such property, or values that are no integers: no labels
  CHECK(SN::read_oriented_point_set(write_bytes("labels_other.ply", ply("int intensity", values, true)), 0)
          .labels.empty());
  std::vector<std::string> fractional = values;
  fractional[2] = "2.5";
  CHECK(SN::read_oriented_point_set(write_bytes("labels_fractional.ply", ply("float label", fractional, true)), 0)
          .labels.empty());
  std::vector<std::string> huge = values;
  huge[2] = "4294967295";
  CHECK(SN::read_oriented_point_set(write_bytes("labels_huge.ply", ply("uint label", huge, true)), 0).labels.empty());
  // other formats have no labels
  CHECK(SN::read_oriented_point_set(write_bytes("no_labels.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 1\n"), 0).labels.empty());
}

// ---- zero normals in point-set files (read_oriented_point_set with Normal_source::AUTO) ----

namespace {

// A noisy-free sphere of `n` points, `x y z nx ny nz` with outward normals but at the indices of
// `zero` (all when `all_zero`), written to a scratch file.
std::string sphere_file(const std::string& name, int n, const std::set<int>& zero, bool all_zero = false)
{
  const std::string file = scratch_folder("zero_normals") + "/" + name;
  std::ofstream out(file);
  out.precision(17);
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = 2.399963229728653 * i;
    const double x = r * std::cos(phi), y = r * std::sin(phi);
    out << x << ' ' << y << ' ' << z << ' ';
    if(all_zero || zero.count(i))
      out << "0 0 0\n";
    else
      out << x << ' ' << y << ' ' << z << '\n';
  }
  return file;
}

SN::Normal_options options(SN::Normal_source source)
{
  SN::Normal_options o;
  o.source = source;
  return o;
}

} // namespace

TEST_CASE("zero normals: a point set whose normals are all zero is a file without normals", "[io][normals]")
{
  const std::string file = sphere_file("all_zero.xyz", 300, {}, true);
  const SN::Oriented_point_set m = SN::read_oriented_point_set(file, options(SN::Normal_source::AUTO));
  CHECK(m.normals_estimated);
  CHECK(m.zero_normals == 300);
  REQUIRE(m.normals.size() == 300);
  for(std::size_t i = 0; i < m.points.size(); ++i)
  {
    CHECK(std::abs(m.normals[i].squared_length() - 1.) < 1e-12);
    // a sphere's estimated normals, oriented by the spanning forest, are outward or inward as one
    CHECK(std::abs(m.normals[i] * (m.points[i] - CGAL::ORIGIN)) > 0.99);
  }
  // without estimation (0 neighbors), as a file without normals: no normals
  CHECK(SN::read_oriented_point_set(file, 0).normals.empty());
  // with --normals file, an error as before
  CHECK_THROWS_WITH(SN::read_oriented_point_set(file, options(SN::Normal_source::FROM_FILE)),
                    Catch::Contains("point 0 has a zero normal"));
}

TEST_CASE("zero normals: a few zero normals are estimated and agree in sign with their neighbors", "[io][normals]")
{
  const std::set<int> zero = {17, 150, 151};
  const std::string file = sphere_file("three_zero.xyz", 400, zero);
  const SN::Oriented_point_set m = SN::read_oriented_point_set(file, options(SN::Normal_source::AUTO));
  CHECK_FALSE(m.normals_estimated);
  CHECK(m.zero_normals == 3);
  REQUIRE(m.normals.size() == 400);
  for(std::size_t i = 0; i < m.points.size(); ++i)
  {
    INFO("point " << i);
    const SN::Oriented_point_set::Vector_3 outward = m.points[i] - CGAL::ORIGIN;
    CHECK(std::abs(m.normals[i].squared_length() - 1.) < 1e-12);
    if(zero.count(int(i)))
      CHECK(m.normals[i] * outward > 0.99); // estimated, with the outward sign of the neighbors' file normals
    else
      CHECK(m.normals[i] * outward == Approx(1.).epsilon(1e-12)); // the file's, untouched
  }
  // the same with the file's normals inward: the estimated ones turn inward too
  {
    const std::string inward_file = sphere_file("three_zero_inward.xyz", 400, zero);
    std::ifstream in(inward_file);
    std::string text, line;
    while(std::getline(in, line))
    {
      double v[6];
      std::sscanf(line.c_str(), "%lf %lf %lf %lf %lf %lf", v, v + 1, v + 2, v + 3, v + 4, v + 5);
      char buffer[256];
      std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g %.17g %.17g %.17g\n", v[0], v[1], v[2], -v[3], -v[4], -v[5]);
      text += buffer;
    }
    in.close();
    std::ofstream(inward_file) << text;
    const SN::Oriented_point_set inward = SN::read_oriented_point_set(inward_file, options(SN::Normal_source::AUTO));
    CHECK(inward.zero_normals == 3);
    for(int i : zero)
      CHECK(inward.normals[std::size_t(i)] * (inward.points[std::size_t(i)] - CGAL::ORIGIN) < -0.99);
  }
  // with --normals file, an error as before
  CHECK_THROWS_WITH(SN::read_oriented_point_set(file, options(SN::Normal_source::FROM_FILE)),
                    Catch::Contains("point 17 has a zero normal"));
  // without estimation (0 neighbors), a zero normal cannot be replaced: an error as before
  CHECK_THROWS_WITH(SN::read_oriented_point_set(file, 0), Catch::Contains("point 17 has a zero normal"));
  // a file with normals and none zero counts none
  CHECK(SN::read_oriented_point_set(sphere_file("no_zero.xyz", 100, {})).zero_normals == 0);
}

namespace {

// The bytes of the file `path`.
std::string file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

template <typename T>
T get(const std::string& bytes, std::size_t at)
{
  REQUIRE(at + sizeof(T) <= bytes.size());
  return Lidar_io::load_little_endian<T>(reinterpret_cast<const unsigned char*>(bytes.data()) + at);
}

// `input`'s records with `added` values (record i: 0.5 i, i, 100 + 0.01 i) through a Las_writer.
std::string write_with_values(const std::string& input, const std::string& output,
                              const std::vector<Lidar_io::Las_extra_dimension>& added)
{
  std::ofstream out(output, std::ios::binary | std::ios::trunc);
  Lidar_io::Las_writer writer(out, Lidar_io::las_output_layout_like(input, added));
  const Lidar_io::Las_output_layout& l = writer.layout();
  std::vector<unsigned char> block;
  Lidar_io::read_las_records(input, [&](std::size_t first, const unsigned char* records, std::size_t count) {
    block.assign(count * l.record_length, 0);
    for(std::size_t i = 0; i < count; ++i)
    {
      unsigned char* r = block.data() + i * l.record_length;
      std::memcpy(r, records + i * l.copied_record_length, l.copied_record_length);
      const double values[] = {0.5 * double(first + i), double(first + i), 100. + 0.01 * double(first + i)};
      for(std::size_t j = 0; j < l.added.size(); ++j)
        Lidar_io::store_las_extra(r, l, j, values[j]);
    }
    writer.write(block.data(), count);
  });
  writer.close();
  out.close();
  return file_bytes(output);
}

// The descriptors of the Extra Bytes record of a LAS 1.4 file: type, options, name.
std::vector<std::tuple<int, int, std::string>> extra_bytes_descriptors(const std::string& bytes)
{
  std::vector<std::tuple<int, int, std::string>> out;
  std::size_t at = get<std::uint16_t>(bytes, 94);
  for(std::uint32_t v = 0; v < get<std::uint32_t>(bytes, 100); ++v)
  {
    const std::size_t length = get<std::uint16_t>(bytes, at + 20);
    if(bytes.compare(at + 2, 9, "LASF_Spec") == 0 && get<std::uint16_t>(bytes, at + 18) == 4)
      for(std::size_t d = at + 54; d + 192 <= at + 54 + length; d += 192)
        out.emplace_back(int(std::uint8_t(bytes[d + 2])), int(std::uint8_t(bytes[d + 3])),
                         std::string(bytes.c_str() + d + 4));
    at += 54 + length;
  }
  return out;
}

const std::vector<Lidar_io::Las_extra_dimension> ADDED = {
  {"value", "half the index", Lidar_io::Las_extra_bytes_type::FLOAT},
  {"count", "the index", Lidar_io::Las_extra_bytes_type::UNSIGNED_CHAR},
  {"scaled", "100 + index / 100", Lidar_io::Las_extra_bytes_type::SHORT, 0.01, 100.}};

} // namespace

TEST_CASE("LAS out: a LAS 1.2 file's records as they were, undocumented extra bytes, values added", "[las][io][las-out]")
{
  Las_file f;
  f.minor = 2;
  f.format = 1;
  f.extra_bytes = 3;
  f.offset[0] = 1000.;
  f.points = sample_points(f.format, 50);
  const std::string input = write_bytes("out_1_2.las", f.bytes());
  const Lidar_io::Las_output_layout l = Lidar_io::las_output_layout_like(input, ADDED);
  CHECK(l.copied_record_length == 31);
  CHECK(l.record_length == 31 + 4 + 1 + 2);
  CHECK(l.added_offsets == std::vector<std::uint16_t>{31, 35, 36});
  const std::string out = write_with_values(input, las_scratch() + "/out_1_2.out.las", ADDED);

  const Lidar_io::Las_header h = Lidar_io::read_las_header(las_scratch() + "/out_1_2.out.las");
  CHECK(h.version_minor == 4);
  CHECK(h.header_size == 375);
  CHECK(h.point_format == 1);
  CHECK(h.record_length == 38);
  CHECK(h.point_count == 50);
  CHECK(get<std::uint32_t>(out, 107) == 50); // the legacy count of a legacy format
  CHECK(out.compare(26, 12, "MODIFICATION") == 0);
  CHECK(out.compare(58, 21, "Sigmoid_neighborhoods") == 0);
  const Lidar_io::Las_header in = Lidar_io::internal::read_las_header(input);
  CHECK(h.min == in.min);
  CHECK(h.max == in.max);
  CHECK(h.scale == in.scale);
  CHECK(h.offset == in.offset);
  std::array<std::uint64_t, 15> by_return{};
  for(const Las_point& p : f.points)
    ++by_return[p.return_number - 1];
  for(std::size_t r = 0; r < 15; ++r)
    CHECK(get<std::uint64_t>(out, 255 + 8 * r) == by_return[r]);
  for(std::size_t r = 0; r < 5; ++r)
    CHECK(get<std::uint32_t>(out, 111 + 4 * r) == by_return[r]);

  const auto descriptors = extra_bytes_descriptors(out);
  REQUIRE(descriptors.size() == 4);
  CHECK(descriptors[0] == std::make_tuple(0, 3, std::string("undocumented")));
  CHECK(descriptors[1] == std::make_tuple(9, 0, std::string("value")));
  CHECK(descriptors[2] == std::make_tuple(1, 0, std::string("count")));
  CHECK(descriptors[3] == std::make_tuple(4, 0x18, std::string("scaled")));

  const std::string records_in = file_bytes(input).substr(in.offset_to_point_data);
  Lidar_io::read_las_records(las_scratch() + "/out_1_2.out.las", [&](std::size_t first, const unsigned char* r, std::size_t n) {
    for(std::size_t i = first; i < first + n; ++i, r += 38)
    {
      CHECK(std::memcmp(r, records_in.data() + 31 * i, 31) == 0);
      CHECK(Lidar_io::load_little_endian<float>(r + 31) == float(0.5 * double(i)));
      CHECK(r[35] == i);
      CHECK(Lidar_io::load_little_endian<std::int16_t>(r + 36) == std::int16_t(std::nearbyint(0.01 * double(i) / 0.01)));
    }
  });
  const SN::Oriented_point_set a = SN::read_oriented_point_set(input, 0), b = SN::read_oriented_point_set(las_scratch() + "/out_1_2.out.las", 0);
  CHECK(a.points == b.points);
  CHECK(a.labels == b.labels);
  CHECK(a.gps_times == b.gps_times);
}

TEST_CASE("LAS out: a LAS 1.4 file's Extra Bytes record, VLRs and EVLRs carried over", "[las][io][las-out]")
{
  Las_file f;
  f.minor = 4;
  f.format = 6;
  f.extra_bytes = 2;
  f.vlr_bytes = 54 + 192 + 54 + 7;
  f.points = sample_points(f.format, 20);
  std::string bytes = f.bytes();
  put<std::uint32_t>(bytes, 100, 2);
  std::size_t at = 375; // an Extra Bytes record of a uint16 "height", then a VLR of 7 bytes
  bytes.replace(at + 2, 9, "LASF_Spec");
  put<std::uint16_t>(bytes, at + 18, 4);
  put<std::uint16_t>(bytes, at + 20, 192);
  put<std::uint8_t>(bytes, at + 54 + 2, 3);
  bytes.replace(at + 54 + 4, 6, "height");
  at += 54 + 192;
  bytes.replace(at + 2, 8, "someone!");
  put<std::uint16_t>(bytes, at + 18, 77);
  put<std::uint16_t>(bytes, at + 20, 7);
  bytes.replace(at + 54, 7, "payload");
  const std::size_t evlr_start = bytes.size();
  std::string evlr(60 + 5, char(0));
  evlr.replace(2, 4, "evlr");
  evlr.replace(60, 5, "tail!");
  bytes += evlr;
  put<std::uint64_t>(bytes, 235, evlr_start);
  put<std::uint32_t>(bytes, 243, 1);
  const std::string input = write_bytes("out_1_4.las", bytes);

  const std::string out = write_with_values(input, las_scratch() + "/out_1_4.out.las", ADDED);
  const auto descriptors = extra_bytes_descriptors(out);
  REQUIRE(descriptors.size() == 4);
  CHECK(descriptors[0] == std::make_tuple(3, 0, std::string("height")));
  CHECK(std::get<2>(descriptors[3]) == "scaled");
  CHECK(get<std::uint32_t>(out, 100) == 2); // the other VLR, then the Extra Bytes record
  CHECK(out.compare(375 + 2, 8, "someone!") == 0);
  CHECK(out.compare(375 + 54, 7, "payload") == 0);
  CHECK(get<std::uint32_t>(out, 107) == 0); // no legacy count in format 6
  CHECK(get<std::uint64_t>(out, 247) == 20);
  const std::uint64_t evlrs = get<std::uint64_t>(out, 235);
  CHECK(evlrs == get<std::uint32_t>(out, 96) + 20 * (30 + 2 + 7));
  CHECK(get<std::uint32_t>(out, 243) == 1);
  CHECK(out.substr(evlrs) == evlr);
}

TEST_CASE("LAS out: new records, the scale rule, the values' conversions, refusals", "[las][io][las-out]")
{
  const Lidar_io::Las_output_layout unit = Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{1., 1., 1.}}, {});
  CHECK(unit.scale[0] == 1e-9);
  CHECK(unit.offset == std::array<double, 3>{{0.5, 0.5, 0.5}});
  CHECK(unit.record_length == 30);
  CHECK(unit.vlr_count == 0);
  const Lidar_io::Las_output_layout survey = Lidar_io::las_output_layout_for({{0., 0., -3.}}, {{2000., 10., 10.}}, ADDED, 7);
  CHECK(survey.scale == std::array<double, 3>{{1e-6, 1e-6, 1e-6}}); // 1000 / 1e-7 > 2^30 >= 1000 / 1e-6
  CHECK(survey.copied_record_length == 36);
  CHECK(survey.record_length == 36 + 7);
  CHECK(survey.vlr_count == 1);
  CHECK(Lidar_io::las_output_layout_for({{5., 5., 5.}}, {{5., 5., 5.}}, {}).scale[2] == 1e-9);

  unsigned char record[43] = {};
  const std::array<double, 3> p = {{1234.5678912345, 0.123456789, -2.999999}};
  Lidar_io::store_las_coordinates(record, survey, p);
  for(int c = 0; c < 3; ++c)
    CHECK(std::abs(double(Lidar_io::load_little_endian<std::int32_t>(record + 4 * c)) * survey.scale[c] + survey.offset[c] - p[c]) <=
          0.5e-6 * (1 + 1e-9));
  CHECK_THROWS_AS(Lidar_io::store_las_coordinates(record, unit, {{3., 0., 0.}}), std::range_error);

  auto stored = [&](std::size_t j, double v) {
    Lidar_io::store_las_extra(record, survey, j, v);
    return record + survey.added_offsets[j];
  };
  CHECK(*stored(1, 300.) == 255);
  CHECK(*stored(1, -5.) == 0);
  CHECK(*stored(1, std::nan("")) == 0);
  CHECK(*stored(1, 41.6) == 42);
  CHECK(std::isnan(Lidar_io::load_little_endian<float>(stored(0, std::nan("")))));
  CHECK(Lidar_io::load_little_endian<std::int16_t>(stored(2, 100.37)) == 37);
  CHECK(Lidar_io::load_little_endian<std::int16_t>(stored(2, -1e9)) == -32768);

  CHECK_THROWS_AS(Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{1., 1., 1.}}, {}, 5), std::invalid_argument);
  CHECK_THROWS_AS(Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{1., std::nan(""), 1.}}, {}), std::invalid_argument);
  CHECK_THROWS_AS(Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{1., 1., 1.}}, {{std::string(33, 'x'), "", Lidar_io::Las_extra_bytes_type::FLOAT}}),
                  std::invalid_argument);
  CHECK_THROWS_AS(Lidar_io::las_output_layout_like(las_scratch() + "/missing.las", {}), SN::Input_error);
}
