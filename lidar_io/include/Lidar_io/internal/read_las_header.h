// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_READ_LAS_HEADER_H
#define LIDAR_IO_INTERNAL_READ_LAS_HEADER_H

// The header of a LAS or LAZ file, apart from its points: what a writer copying a file's layout
// needs, without the decoder or the point set.

#include <Lidar_io/Input_error.h>
#include <Lidar_io/Las_header.h>
#include <Lidar_io/little_endian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <string>
#include <system_error>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {

// Uncompressed LAS 1.0 to 1.4, point data record formats 0 to 10, as the ASPRS LAS 1.4 R15
// specification lays them out; every number little-endian.
//
// The public header block (offsets in bytes; LAS 1.0 to 1.2 end at 227, 1.3 at 235, 1.4 at 375):
//     0 "LASF"   24 version major, 25 minor   94 header size (uint16)   96 offset to point data (uint32)
//   100 number of variable-length records (uint32)
//   104 point data record format (uint8; LASzip sets bit 7, some writers bit 6: compressed, LAZ)
//   105 point data record length (uint16)   107 legacy number of point records (uint32)
//   131 scale x y z, 155 offset x y z, 179 max x, min x, max y, min y, max z, min z (doubles)
//   247 number of point records (uint64, LAS 1.4)
// A point record (formats 0-5 | formats 6-10):
//     0 X, 4 Y, 8 Z (int32): coordinate = X * scale + offset, in double   12 intensity (uint16)
//    14 return number bits 0-2, number of returns bits 3-5 | bits 0-3, bits 4-7
//    15 classification in bits 0-4 (5-7: synthetic, key-point, withheld flags) | flags, channel
//    16 scan angle rank | classification (8 bits)
//    GPS time (double): at 20 in formats 1, 3, 4, 5 | at 22; none in formats 0 and 2
// then, by format, RGB, NIR and wave packets, and any extra bytes up to the record length.
constexpr std::size_t LAS_SIGNATURE_BYTES = 4;
constexpr std::size_t LAS_HEADER_BYTES_1_0 = 227; // LAS 1.0 to 1.2; the least any version takes
constexpr std::size_t LAS_HEADER_BYTES_1_4 = 375; // with the 64-bit point count
constexpr unsigned int LAS_LAST_MINOR_VERSION = 4;
constexpr unsigned int LAS_LAST_POINT_FORMAT = 10; // LAS_POINT_RECORD_BYTES: Las_header.h
constexpr unsigned int LAS_FIRST_EXTENDED_FORMAT = 6; // formats 6-10: 8-bit classification, 4-bit returns
constexpr unsigned int LAS_COMPRESSION_BITS = 0xC0;   // of the format byte: LAZ
constexpr unsigned int LAS_FORMAT_BITS = 0x3F;
constexpr std::size_t LAS_CHUNK_BYTES = std::size_t(1) << 22; // records read at a time

inline std::string las_error(const std::string& reason) { return "cannot parse the file as las (" + reason + ")"; }

// The header of a LAS file of `file_size` bytes read from `in`, at its start, or Input_error.
inline Las_header read_las_header(std::istream& in, std::uintmax_t file_size)
{
  unsigned char b[LAS_HEADER_BYTES_1_4] = {};
  const std::size_t available = std::size_t((std::min)(file_size, std::uintmax_t(LAS_HEADER_BYTES_1_4)));
  if(!in.read(reinterpret_cast<char*>(b), std::streamsize(available)))
    throw Input_error(las_error("read error in the header"));
  if(available < LAS_SIGNATURE_BYTES || std::memcmp(b, "LASF", LAS_SIGNATURE_BYTES) != 0)
    throw Input_error(las_error("no LAS signature 'LASF' at the start"));
  if(available < LAS_HEADER_BYTES_1_0)
    throw Input_error(las_error("a file of " + std::to_string(file_size) + " bytes ends in the header, which takes " +
                                std::to_string(LAS_HEADER_BYTES_1_0) + " bytes at least"));

  Las_header h;
  h.file_size = file_size;
  h.version_major = b[24];
  h.version_minor = b[25];
  if(h.version_major != 1 || h.version_minor > LAS_LAST_MINOR_VERSION)
    throw Input_error(las_error("version " + std::to_string(h.version_major) + "." + std::to_string(h.version_minor) +
                                " is not read: expected 1.0 to 1.4"));
  h.header_size = load_little_endian<std::uint16_t>(b + 94);
  if(h.header_size < LAS_HEADER_BYTES_1_0)
    throw Input_error(las_error("a header size of " + std::to_string(h.header_size) + " bytes, less than the " +
                                std::to_string(LAS_HEADER_BYTES_1_0) + " of every version"));
  if(h.header_size > file_size)
    throw Input_error(las_error("a header size of " + std::to_string(h.header_size) + " bytes, more than the file's " +
                                std::to_string(file_size)));

  const unsigned int format_byte = b[104];
  h.compressed = (format_byte & LAS_COMPRESSION_BITS) != 0;
  h.vlr_count = load_little_endian<std::uint32_t>(b + 100);
  h.point_format = format_byte & LAS_FORMAT_BITS;
  if(h.point_format > LAS_LAST_POINT_FORMAT)
    throw Input_error(las_error("point data format " + std::to_string(h.point_format) +
                                " is not read: expected 0 to 10"));
  h.record_length = load_little_endian<std::uint16_t>(b + 105);
  if(h.record_length < LAS_POINT_RECORD_BYTES[h.point_format])
    throw Input_error(las_error("point records of " + std::to_string(h.record_length) + " bytes, less than the " +
                                std::to_string(LAS_POINT_RECORD_BYTES[h.point_format]) + " of point data format " +
                                std::to_string(h.point_format)));

  h.point_count = load_little_endian<std::uint32_t>(b + 107);
  if(h.version_minor == 4 && h.header_size >= LAS_HEADER_BYTES_1_4 && available >= LAS_HEADER_BYTES_1_4)
  {
    const std::uint64_t count = load_little_endian<std::uint64_t>(b + 247);
    if(count != 0)
      h.point_count = count;
  }

  const char* const axes[] = {"x", "y", "z"};
  for(int i = 0; i < 3; ++i)
  {
    h.scale[i] = load_little_endian<double>(b + 131 + 8 * i);
    h.offset[i] = load_little_endian<double>(b + 155 + 8 * i);
    h.max[i] = load_little_endian<double>(b + 179 + 16 * i);
    h.min[i] = load_little_endian<double>(b + 187 + 16 * i);
    if(!std::isfinite(h.scale[i]) || h.scale[i] == 0.)
      throw Input_error(las_error(std::string(h.scale[i] == 0. ? "a zero" : "a non-finite") + " scale factor of " +
                                  axes[i] + ": expected a finite number other than 0"));
    if(!std::isfinite(h.offset[i]))
      throw Input_error(las_error("a non-finite offset of " + std::string(axes[i])));
  }

  h.offset_to_point_data = load_little_endian<std::uint32_t>(b + 96);
  if(h.offset_to_point_data < h.header_size)
    throw Input_error(las_error("point data at byte " + std::to_string(h.offset_to_point_data) +
                                ", inside the header of " + std::to_string(h.header_size) + " bytes"));
  if(h.offset_to_point_data > file_size)
    throw Input_error(las_error("point data at byte " + std::to_string(h.offset_to_point_data) +
                                ", beyond the end of a file of " + std::to_string(file_size) + " bytes"));
  if(h.compressed)
    return h; // LAZ: the points are checked against the chunk table (read_laz_layout())
  // The count bounded by the bytes after the header before anything is sized to it: a file of a few
  // hundred bytes could otherwise ask for gigabytes.
  const std::uintmax_t left = file_size - h.offset_to_point_data;
  const std::uintmax_t each = (std::max)(std::uintmax_t(h.record_length), std::uintmax_t(1));
  if(h.point_count > left / each)
  {
    auto bytes = [](std::uintmax_t n) { return std::to_string(n) + (n == 1 ? " byte" : " bytes"); };
    throw Input_error(las_error("the header announces " + std::to_string(h.point_count) + " points of " +
                                std::to_string(h.record_length) + " bytes from byte " +
                                std::to_string(h.offset_to_point_data) + ", more than a file of " + bytes(file_size) +
                                " can hold: " + bytes(left) + " left, at least " + bytes(each) + " each"));
  }
  return h;
}

// The size of a file, or Input_error.
inline std::uintmax_t las_file_size(const std::string& filename)
{
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(filename, ec);
  if(ec)
    throw Input_error("cannot tell the size of the file (" + ec.message() + ")");
  return size;
}

// The header of the LAS or LAZ file `filename`, checked (a later reader of many tiles indexes them
// by their bounding boxes).
inline Las_header read_las_header(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Input_error("cannot open the file");
  return read_las_header(in, las_file_size(filename));
}

} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_READ_LAS_HEADER_H
