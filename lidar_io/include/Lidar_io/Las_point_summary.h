// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LAS_POINT_SUMMARY_H
#define LIDAR_IO_LAS_POINT_SUMMARY_H

#include <Lidar_io/little_endian.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  what the public header block of a LAS 1.4 file says of the point records after it, summed up
  as they are written: their count, their count by return number and their bounding box.
*/
struct Las_point_summary
{
  std::uint64_t count = 0; ///< records
  std::array<std::uint64_t, 15> by_return{}; ///< records of return numbers 1 to 15 (0 counts nowhere)
  /// the smallest integer coordinates
  std::array<std::int32_t, 3> min{{(std::numeric_limits<std::int32_t>::max)(), (std::numeric_limits<std::int32_t>::max)(),
                                   (std::numeric_limits<std::int32_t>::max)()}};
  /// the largest integer coordinates
  std::array<std::int32_t, 3> max{{(std::numeric_limits<std::int32_t>::min)(), (std::numeric_limits<std::int32_t>::min)(),
                                   (std::numeric_limits<std::int32_t>::min)()}};

  /// adds the record `record`, of a point format 6 to 10 when `extended_format`
  void add(const unsigned char* record, bool extended_format)
  {
    ++count;
    for(int c = 0; c < 3; ++c)
    {
      const std::int32_t v = load_little_endian<std::int32_t>(record + 4 * c);
      min[c] = (std::min)(min[c], v);
      max[c] = (std::max)(max[c], v);
    }
    const unsigned int return_number = extended_format ? (record[14] & 0x0F) : (record[14] & 0x07);
    if(return_number >= 1)
      ++by_return[return_number - 1];
  }
};

/*!
  \ingroup PkgLidarIo
  writes into `header`, a public header block of `header_size` bytes that holds its version, point
  format, scales and offsets, the counts and the bounding box of `points` (bounds as a reader
  computes them, integer * scale + offset). LAS 1.4 rules: the 64-bit counts always; the legacy
  32-bit counts 0 in point formats 6 to 10 and when the count exceeds 32 bits, else equal to the
  64-bit ones (returns 1 to 5). Before LAS 1.4 the legacy counts are the only ones.
  \throws std::length_error for a count beyond 32 bits in a header before LAS 1.4
*/
inline void store_las_point_summary(unsigned char* header, std::size_t header_size, const Las_point_summary& points)
{
  const unsigned int minor = header[25];
  const unsigned int format = header[104] & 0x3F; // LASzip's compression bits aside
  const bool has_64_bit_counts = minor >= 4 && header_size >= 375;
  const bool fits_legacy = points.count <= (std::numeric_limits<std::uint32_t>::max)();
  if(!has_64_bit_counts && !fits_legacy)
    throw std::length_error(std::to_string(points.count) + " points: more than a LAS 1." + std::to_string(minor) +
                            " header can count (32 bits)");
  const bool legacy = !has_64_bit_counts || (format < 6 && fits_legacy);
  store_little_endian<std::uint32_t>(header + 107, legacy ? std::uint32_t(points.count) : 0u);
  for(std::size_t r = 0; r < 5; ++r)
    store_little_endian<std::uint32_t>(header + 111 + 4 * r, legacy ? std::uint32_t(points.by_return[r]) : 0u);
  if(has_64_bit_counts)
  {
    store_little_endian<std::uint64_t>(header + 247, points.count);
    for(std::size_t r = 0; r < 15; ++r)
      store_little_endian<std::uint64_t>(header + 255 + 8 * r, points.by_return[r]);
  }
  for(int c = 0; c < 3; ++c)
  {
    double low = 0., high = 0.;
    if(points.count != 0)
    {
      // a negative scale swaps the ends
      const double scale = load_little_endian<double>(header + 131 + 8 * c);
      const double offset = load_little_endian<double>(header + 155 + 8 * c);
      const double a = double(points.min[c]) * scale + offset, b = double(points.max[c]) * scale + offset;
      low = (std::min)(a, b);
      high = (std::max)(a, b);
    }
    store_little_endian<double>(header + 179 + 16 * c, high);
    store_little_endian<double>(header + 187 + 16 * c, low);
  }
}

} // namespace Lidar_io

#endif // LIDAR_IO_LAS_POINT_SUMMARY_H
