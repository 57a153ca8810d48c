// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LAS_HEADER_H
#define LIDAR_IO_LAS_HEADER_H

#include <array>
#include <cstddef>
#include <cstdint>

namespace Lidar_io {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The bytes of a record of each point data format 0 to 10 without extra bytes (LAS 1.4 R15).
constexpr std::uint16_t LAS_POINT_RECORD_BYTES[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

} // namespace internal
/// \endcond

/// \ingroup PkgLidarIo
/// whether records of LAS point data format `point_format` hold wave packets (formats 4, 5, 9 and
/// 10), which LAZ output does not compress
constexpr bool las_format_has_wave_packets(unsigned int point_format)
{
  return point_format == 4 || point_format == 5 || point_format == 9 || point_format == 10;
}

/*!
  \ingroup PkgLidarIo
  what the public header block of a LAS or LAZ file (ASPRS LAS 1.0 to 1.4 R15) says of its point
  records, checked by `read_las_header()`: the version and point data format are ones the library
  reads, the scales and offsets are finite and the scales not zero, and the points an uncompressed
  file announces lie within it (a LAZ file's are checked against its chunk table as they are decoded).
*/
struct Las_header
{
  unsigned int version_major = 0;  ///< 1
  unsigned int version_minor = 0;  ///< 0 to 4
  std::uint16_t header_size = 0;   ///< bytes of the public header block
  std::uint32_t offset_to_point_data = 0; ///< where the point records (or LASzip's chunks) start
  std::uint32_t vlr_count = 0;     ///< variable length records between the header and the points
  bool compressed = false;         ///< LAZ: the points in LASzip's chunks
  unsigned int point_format = 0;   ///< 0 to 10
  std::uint16_t record_length = 0; ///< at least the point format's size; the rest is extra bytes
  std::uint64_t point_count = 0;   ///< the 64-bit count of LAS 1.4 when not 0, else the legacy one
  std::array<double, 3> scale{{0., 0., 0.}};  ///< coordinate = integer * scale + offset
  std::array<double, 3> offset{{0., 0., 0.}}; ///< see `scale`
  std::array<double, 3> min{{0., 0., 0.}};    ///< the bounding box, as written (unchecked)
  std::array<double, 3> max{{0., 0., 0.}};    ///< see `min`
  std::uintmax_t file_size = 0;    ///< bytes of the file

  /// formats 6 to 10: 4-bit return numbers, 8-bit classification, GPS time at byte 22
  bool has_extended_format() const { return point_format >= 6; }
  /// every format but 0 and 2
  bool has_gps_time() const { return point_format != 0 && point_format != 2; }
  /// the byte of a record where its GPS time starts, when it has one
  std::size_t gps_time_offset() const { return has_extended_format() ? 22 : 20; }
};

} // namespace Lidar_io

#endif // LIDAR_IO_LAS_HEADER_H
