// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writing uncompressed LAS files (ASPRS LAS 1.4 R15): the fields of the public header block that a
// writer of tiles changes (point counts, bounding box, the offsets of what follows the points),
// computed from the point records written, and the layout of an input whose records are copied,
// header and trailer as they are (catalog retile keeps a tile's LAS version).

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_LAS_WRITER_H
#define SIGMOID_NEIGHBORHOODS_TOOL_LAS_WRITER_H

#include <CGAL/Sigmoid_neighborhoods/IO/Las_point_summary.h>
#include <CGAL/Sigmoid_neighborhoods/IO/little_endian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sigmoid_tool {
namespace las {

// Byte offsets in the public header block (LAS 1.4 R15, Table 3); every number little-endian.
constexpr std::size_t GLOBAL_ENCODING = 6;              // uint16
constexpr std::size_t VERSION_MAJOR = 24, VERSION_MINOR = 25;
constexpr std::size_t HEADER_SIZE = 94;                 // uint16
constexpr std::size_t OFFSET_TO_POINT_DATA = 96;        // uint32
constexpr std::size_t NUMBER_OF_VLRS = 100;             // uint32
constexpr std::size_t POINT_FORMAT = 104;               // uint8; LASzip sets bit 7, some writers bit 6
constexpr std::size_t RECORD_LENGTH = 105;              // uint16
constexpr std::size_t LEGACY_POINT_COUNT = 107;         // uint32
constexpr std::size_t LEGACY_POINTS_BY_RETURN = 111;    // 5 x uint32
constexpr std::size_t SCALE = 131, OFFSET = 155;        // 3 doubles each
constexpr std::size_t BOUNDS = 179;                     // max x, min x, max y, min y, max z, min z
constexpr std::size_t WAVEFORM_DATA_START = 227;        // uint64, LAS 1.3 and 1.4
constexpr std::size_t FIRST_EVLR_START = 235;           // uint64, LAS 1.4
constexpr std::size_t NUMBER_OF_EVLRS = 243;            // uint32, LAS 1.4
constexpr std::size_t POINT_COUNT = 247;                // uint64, LAS 1.4
constexpr std::size_t POINTS_BY_RETURN = 255;           // 15 x uint64, LAS 1.4

constexpr std::size_t HEADER_BYTES_1_0 = 227; // LAS 1.0 to 1.2; the least any version takes
constexpr std::size_t HEADER_BYTES_1_3 = 235;
constexpr std::size_t HEADER_BYTES_1_4 = 375;
constexpr std::size_t VLR_HEADER_BYTES = 54;
constexpr unsigned int LAST_POINT_FORMAT = 10;
constexpr unsigned int FIRST_EXTENDED_FORMAT = 6; // formats 6-10: 4-bit return numbers, no legacy counts
constexpr std::uint16_t POINT_RECORD_BYTES[LAST_POINT_FORMAT + 1] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
constexpr unsigned int COMPRESSION_BITS = 0xC0; // of the format byte
constexpr unsigned int FORMAT_BITS = 0x3F;
constexpr unsigned int WAVEFORM_DATA_INTERNAL = 0x2; // bit 1 of the global encoding
constexpr std::size_t LEGACY_RETURNS = 5, RETURNS = 15;

// A LAS file that cannot be copied or written; the message is one line.
struct Las_format_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

inline std::string laz_refusal()
{
  // The tiles are the input's records copied with its header: a LAZ input would need LASzip's
  // record dropped and its points decoded first, which the other commands do and retile does not.
  return "catalog retile copies the records of an uncompressed LAS file: decompress a LAZ file first, e.g. "
         "'laszip -i FILE.laz -o FILE.las' or 'pdal translate FILE.laz FILE.las'";
}

// Little-endian numbers at any address: the package's, as its LAS reader reads them.
using CGAL::Sigmoid_neighborhoods::load_little_endian;
using CGAL::Sigmoid_neighborhoods::store_little_endian;

// What a header says of the point records after it, gathered as they are written.
using Point_summary = CGAL::Sigmoid_neighborhoods::Las_point_summary;

// The public summary's counts and bounds written into `header` (store_las_point_summary()), a
// count that a header before LAS 1.4 cannot hold refused as the tool refuses a LAS file.
inline void write_point_summary(unsigned char* header, std::size_t header_size, const Point_summary& points)
{
  try
  {
    CGAL::Sigmoid_neighborhoods::store_las_point_summary(header, header_size, points);
  }
  catch(const std::length_error& e)
  {
    throw Las_format_error(e.what());
  }
}

// An uncompressed LAS file as a tile writer copies it: everything before the point records (public
// header block, VLRs and any bytes up to the point data), the records, and a trailer after them
// (the EVLRs of LAS 1.4 and the waveform data packets stored in the file), copied whole.
struct Las_layout
{
  std::vector<unsigned char> prefix; // the bytes before the point records, header first
  unsigned int version_minor = 0;
  unsigned int point_format = 0;
  std::uint16_t header_size = 0;
  std::uint16_t record_length = 0;
  std::uint64_t point_count = 0;
  std::array<double, 3> scale{{0., 0., 0.}}, offset{{0., 0., 0.}};
  std::uint64_t point_data_start = 0, point_data_end = 0;
  std::uint64_t trailer_start = 0, file_size = 0; // no trailer: trailer_start == file_size
  std::uint32_t evlrs = 0;

  bool has_extended_format() const { return point_format >= FIRST_EXTENDED_FORMAT; }
  std::uint64_t trailer_bytes() const { return file_size - trailer_start; }
};

inline Las_format_error las_error(const std::string& reason)
{
  return Las_format_error("cannot parse the file as las (" + reason + ")");
}

// The layout of the LAS file of `file_size` bytes read from `in`, at its start, checked as the
// package's reader checks it (signature, version 1.0 to 1.4, point formats 0 to 10, no compression,
// every announced record within the file); `in` is left after the prefix.
inline Las_layout read_las_layout(std::istream& in, std::uint64_t file_size)
{
  unsigned char b[HEADER_BYTES_1_4] = {};
  const std::size_t available = std::size_t((std::min)(file_size, std::uint64_t(HEADER_BYTES_1_4)));
  if(!in.read(reinterpret_cast<char*>(b), std::streamsize(available)))
    throw las_error("read error in the header");
  if(available < 4 || std::memcmp(b, "LASF", 4) != 0)
    throw las_error("no LAS signature 'LASF' at the start");
  if(available < HEADER_BYTES_1_0)
    throw las_error("a file of " + std::to_string(file_size) + " bytes ends in the header");
  Las_layout l;
  l.file_size = file_size;
  l.version_minor = b[VERSION_MINOR];
  if(b[VERSION_MAJOR] != 1 || l.version_minor > 4)
    throw las_error("version " + std::to_string(b[VERSION_MAJOR]) + "." + std::to_string(l.version_minor) +
                    " is not read: expected 1.0 to 1.4");
  l.header_size = load_little_endian<std::uint16_t>(b + HEADER_SIZE);
  if(l.header_size < HEADER_BYTES_1_0 || l.header_size > file_size)
    throw las_error("a header size of " + std::to_string(l.header_size) + " bytes");
  const unsigned int format_byte = b[POINT_FORMAT];
  if((format_byte & COMPRESSION_BITS) != 0)
    throw Las_format_error(laz_refusal() + " (the point data format byte is " + std::to_string(format_byte) +
                           ": compressed)");
  l.point_format = format_byte & FORMAT_BITS;
  if(l.point_format > LAST_POINT_FORMAT)
    throw las_error("point data format " + std::to_string(l.point_format) + " is not read: expected 0 to 10");
  l.record_length = load_little_endian<std::uint16_t>(b + RECORD_LENGTH);
  if(l.record_length < POINT_RECORD_BYTES[l.point_format])
    throw las_error("point records of " + std::to_string(l.record_length) + " bytes, less than the " +
                    std::to_string(POINT_RECORD_BYTES[l.point_format]) + " of point data format " +
                    std::to_string(l.point_format));
  const bool is_1_4 = l.version_minor == 4 && l.header_size >= HEADER_BYTES_1_4 && available >= HEADER_BYTES_1_4;
  l.point_count = load_little_endian<std::uint32_t>(b + LEGACY_POINT_COUNT);
  if(is_1_4 && load_little_endian<std::uint64_t>(b + POINT_COUNT) != 0)
    l.point_count = load_little_endian<std::uint64_t>(b + POINT_COUNT);
  for(int c = 0; c < 3; ++c)
  {
    l.scale[c] = load_little_endian<double>(b + SCALE + 8 * c);
    l.offset[c] = load_little_endian<double>(b + OFFSET + 8 * c);
    if(!std::isfinite(l.scale[c]) || l.scale[c] == 0. || !std::isfinite(l.offset[c]))
      throw las_error("a zero or non-finite scale factor or offset");
  }
  l.point_data_start = load_little_endian<std::uint32_t>(b + OFFSET_TO_POINT_DATA);
  if(l.point_data_start < l.header_size || l.point_data_start > file_size)
    throw las_error("point data at byte " + std::to_string(l.point_data_start) + ", outside the file's " +
                    std::to_string(file_size) + " bytes after its header");
  if(l.point_count > (file_size - l.point_data_start) / l.record_length)
    throw las_error("the header announces " + std::to_string(l.point_count) + " points of " +
                    std::to_string(l.record_length) + " bytes from byte " + std::to_string(l.point_data_start) +
                    ", more than the file's " + std::to_string(file_size) + " bytes hold");
  l.point_data_end = l.point_data_start + l.point_count * l.record_length;

  // What follows the points and is copied with them; bytes between the two (padding) are dropped.
  l.trailer_start = file_size;
  if(is_1_4 && load_little_endian<std::uint32_t>(b + NUMBER_OF_EVLRS) != 0)
  {
    l.evlrs = load_little_endian<std::uint32_t>(b + NUMBER_OF_EVLRS);
    const std::uint64_t start = load_little_endian<std::uint64_t>(b + FIRST_EVLR_START);
    if(start < l.point_data_end || start > file_size)
      throw las_error("the first EVLR at byte " + std::to_string(start) + ", not after the point records");
    l.trailer_start = start;
  }
  const std::uint64_t waveforms = l.header_size >= HEADER_BYTES_1_3 ? load_little_endian<std::uint64_t>(b + WAVEFORM_DATA_START) : 0;
  if(l.version_minor >= 3 && (load_little_endian<std::uint16_t>(b + GLOBAL_ENCODING) & WAVEFORM_DATA_INTERNAL) != 0 &&
     waveforms != 0)
  {
    if(waveforms < l.point_data_end || waveforms > file_size)
      throw las_error("waveform data at byte " + std::to_string(waveforms) + ", not after the point records");
    l.trailer_start = (std::min)(l.trailer_start, waveforms);
  }

  l.prefix.assign(b, b + available);
  l.prefix.resize(l.point_data_start);
  if(l.point_data_start > available &&
     !in.read(reinterpret_cast<char*>(l.prefix.data() + available), std::streamsize(l.point_data_start - available)))
    throw las_error("read error in the variable length records");
  if(l.point_data_start < available)
    in.seekg(std::streamoff(l.point_data_start));
  return l;
}

// The public header block of a copy of `layout` that holds the records summed up in `points`,
// its trailer (when any) right after them.
inline std::vector<unsigned char> copied_header(const Las_layout& layout, const Point_summary& points)
{
  std::vector<unsigned char> header(layout.prefix.begin(), layout.prefix.begin() + layout.header_size);
  write_point_summary(header.data(), header.size(), points);
  if(layout.trailer_start == layout.file_size)
    return header;
  // The offsets into the trailer move with it; a point's offset to its waveform packet is relative to
  // the start of the waveform data record (field WAVEFORM_DATA_START), so the records stay right.
  const std::uint64_t new_start = layout.point_data_start + points.count * layout.record_length;
  for(std::size_t field : {WAVEFORM_DATA_START, FIRST_EVLR_START})
  {
    if(field + 8 > header.size())
      continue;
    const std::uint64_t at = load_little_endian<std::uint64_t>(header.data() + field);
    if(at >= layout.trailer_start && at < layout.file_size)
      store_little_endian<std::uint64_t>(header.data() + field, at - layout.trailer_start + new_start);
  }
  return header;
}

} // namespace las
} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_LAS_WRITER_H
