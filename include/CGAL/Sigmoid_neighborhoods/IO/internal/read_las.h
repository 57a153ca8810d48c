// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_LAS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_LAS_H

#include <CGAL/Sigmoid_neighborhoods/IO/little_endian.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Las_header.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/Byte_budget.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/input_file.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/Laz_layout.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/decode_chunks.h>
#include <CGAL/Sigmoid_neighborhoods/IO/lower_case_extension.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
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
  const Byte_budget budget(file_size, file_size - h.offset_to_point_data);
  budget.check(h.point_count, h.record_length, [&](const std::string& excess) {
    return las_error("the header announces " + std::to_string(h.point_count) + " points of " +
                     std::to_string(h.record_length) + " bytes from byte " + std::to_string(h.offset_to_point_data) +
                     excess);
  });
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

inline void reserve_las_points(Oriented_point_set& out, std::size_t n, bool gps_times)
{
  out.points.reserve(out.points.size() + n);
  out.labels.reserve(out.labels.size() + n);
  out.intensities.reserve(out.intensities.size() + n);
  out.return_numbers.reserve(out.return_numbers.size() + n);
  out.numbers_of_returns.reserve(out.numbers_of_returns.size() + n);
  if(gps_times)
    out.gps_times.reserve(out.gps_times.size() + n);
}

// Where the LASzip chunks of a compressed file lie, checked against the file.
inline laz::Layout read_laz_layout(std::istream& in, const Las_header& h)
{
  laz::Layout layout =
    laz::read_laszip_record(in, h.header_size, h.vlr_count, h.offset_to_point_data, h.record_length);
  if((layout.compressor == laz::LAYERED_CHUNKED) != h.has_extended_format())
    throw Input_error(laz::laz_error("compressor " + std::to_string(layout.compressor) + " for point data format " +
                                     std::to_string(h.point_format) + ": LASzip compresses formats 0 to 5 point "
                                     "by point (2) and formats 6 to 10 in layers (3)"));
  laz::read_chunk_table(in, h.file_size, h.offset_to_point_data, h.point_count, h.record_length, layout);
  return layout;
}

// Calls `sink(first, records, count)` on the file's point records in order, `count` at a time, as
// an uncompressed file stores them: read from an uncompressed file a few megabytes at a time, or
// decoded from a LAZ file chunk by chunk, `threads` chunks in parallel.
template <typename Sink>
void for_each_las_record_block(std::istream& in, const Las_header& h, unsigned int threads, const Sink& sink)
{
  const std::size_t n = std::size_t(h.point_count);
  if(h.compressed)
  {
    const laz::Layout layout = read_laz_layout(in, h);
    laz::for_each_decoded_chunk(in, layout, h.record_length, threads, sink);
    return;
  }
  in.seekg(std::streamoff(h.offset_to_point_data));
  const std::size_t chunk_points = (std::max)(std::size_t(1), LAS_CHUNK_BYTES / h.record_length);
  std::vector<unsigned char> chunk;
  for(std::size_t first = 0; first < n;)
  {
    const std::size_t count = (std::min)(chunk_points, n - first);
    chunk.resize(count * h.record_length);
    if(!in.read(reinterpret_cast<char*>(chunk.data()), std::streamsize(chunk.size())))
      throw Input_error(las_error("the file ends in point " + std::to_string(first + std::size_t(in.gcount()) /
                                                                                     h.record_length)));
    sink(first, chunk.data(), count);
    first += count;
  }
}

// Every record of a LAS file.
struct Keep_every_las_point
{
  bool operator()(std::size_t, const double*) const { return true; }
};

// The points of a LAS or LAZ file with their classification (`labels`), intensity, return number,
// number of returns and, in the formats that have it, GPS time, appended to `out`; the file's records
// in its order, read (or decoded, on `threads` threads) a chunk at a time, those for which
// `keep(record, xyz)` is true (a tile's halo reads a neighbor tile without holding it whole). Whether
// the points are compressed is the header's to say, whatever the extension.
template <typename Keep = Keep_every_las_point>
void read_las(const Input_file& file, Oriented_point_set& out, Keep keep = Keep(), unsigned int threads = 0)
{
  std::ifstream in(file.name, std::ios::binary);
  if(!in)
    throw Input_error("cannot open the file");
  const Las_header h =
    read_las_header(in, file.size == Byte_budget::UNKNOWN_SIZE ? las_file_size(file.name) : file.size);

  // At most one point per record of the file (read_las_header() checked it): sized to the file,
  // unless a filter keeps a part of it. A LAZ file's count is checked against its chunk table, not
  // bounded by its size: its vectors grow as its chunks are decoded.
  if(std::is_same<Keep, Keep_every_las_point>::value && !h.compressed)
    reserve_las_points(out, std::size_t(h.point_count), h.has_gps_time());

  for_each_las_record_block(in, h, threads, [&](std::size_t first, const unsigned char* records, std::size_t count) {
    for(std::size_t i = 0; i < count; ++i)
    {
      const unsigned char* r = records + i * h.record_length;
      double xyz[3];
      for(int c = 0; c < 3; ++c)
      {
        xyz[c] = double(load_little_endian<std::int32_t>(r + 4 * c)) * h.scale[c] + h.offset[c];
        if(!std::isfinite(xyz[c]))
          throw Input_error(las_error("point " + std::to_string(first + i) +
                                      " has a non-finite coordinate after scale and offset"));
      }
      if(!keep(first + i, xyz))
        continue;
      out.points.emplace_back(xyz[0], xyz[1], xyz[2]);
      out.intensities.push_back(load_little_endian<std::uint16_t>(r + 12));
      const unsigned int returns = r[14];
      if(h.has_extended_format())
      {
        out.return_numbers.push_back(std::uint8_t(returns & 0x0F));
        out.numbers_of_returns.push_back(std::uint8_t(returns >> 4));
        out.labels.push_back(int(r[16]));
      }
      else
      {
        out.return_numbers.push_back(std::uint8_t(returns & 0x07));
        out.numbers_of_returns.push_back(std::uint8_t((returns >> 3) & 0x07));
        out.labels.push_back(int(r[15] & 0x1F));
      }
      if(h.has_gps_time())
        out.gps_times.push_back(load_little_endian<double>(r + h.gps_time_offset()));
    }
  });
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_LAS_H
