// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_ENCODE_CHUNKS_H
#define LIDAR_IO_INTERNAL_LAZ_ENCODE_CHUNKS_H

#include <Lidar_io/Las_header.h>
#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/laz/Laz_layout.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/integer_coder.h>
#include <Lidar_io/internal/laz/laz_items.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// The items LASzip's current versions list for records of `point_format` and `record_length` bytes:
// point-wise version 2 items for formats 0 to 3, layered version 3 ones for formats 6 to 8, the bytes
// past the format's own as extra bytes. Wave packets (formats 4, 5, 9, 10) are refused, as the reader
// refuses them.
inline std::vector<Item> laz_items_for(unsigned int point_format, std::size_t record_length)
{
  if(point_format > 10)
    throw std::invalid_argument("LAZ: point format " + std::to_string(point_format) + ", not one of LAS 1.4's 0 to 10");
  if(las_format_has_wave_packets(point_format))
    throw std::invalid_argument("LAZ: the wave packets of point format " + std::to_string(point_format) +
                                " are not compressed (write the file as LAS)");
  if(record_length < LAS_POINT_RECORD_BYTES[point_format] || record_length > 0xFFFF)
    throw std::invalid_argument("LAZ: records of " + std::to_string(record_length) + " bytes in point format " +
                                std::to_string(point_format));
  const std::uint16_t extra = std::uint16_t(record_length - LAS_POINT_RECORD_BYTES[point_format]);
  std::vector<Item> items;
  if(point_format <= 3)
  {
    items.push_back({POINT10, 20, 2});
    if(point_format == 1 || point_format == 3)
      items.push_back({GPSTIME11, 8, 2});
    if(point_format >= 2)
      items.push_back({RGB12, 6, 2});
    if(extra != 0)
      items.push_back({BYTE, extra, 2});
  }
  else
  {
    items.push_back({POINT14, 30, 3});
    if(point_format == 7)
      items.push_back({RGB14, 6, 3});
    if(point_format == 8)
      items.push_back({RGBNIR14, 8, 3});
    if(extra != 0)
      items.push_back({BYTE14, extra, 3});
  }
  return items;
}

// The payload of the LASzip record (user "laszip encoded", record 22204) for `items` in chunks of
// `chunk_size` points, as LASzip 3.4 revision 3 writes it (no special EVLRs, no options).
inline std::vector<unsigned char> laszip_record_payload(const std::vector<Item>& items, std::uint32_t chunk_size)
{
  std::vector<unsigned char> d(34 + 6 * items.size(), 0);
  const bool layered = !items.empty() && items[0].type == POINT14;
  store_little_endian<std::uint16_t>(d.data(), layered ? LAYERED_CHUNKED : POINTWISE_CHUNKED);
  d[4] = 3; // LASzip version 3.4 r3: the one whose items these are
  d[5] = 4;
  store_little_endian<std::uint16_t>(d.data() + 6, 3);
  store_little_endian<std::uint32_t>(d.data() + 12, chunk_size);
  store_little_endian<std::int64_t>(d.data() + 16, -1);
  store_little_endian<std::int64_t>(d.data() + 24, -1);
  store_little_endian<std::uint16_t>(d.data() + 32, std::uint16_t(items.size()));
  for(std::size_t i = 0; i < items.size(); ++i)
  {
    store_little_endian<std::uint16_t>(d.data() + 34 + 6 * i, items[i].type);
    store_little_endian<std::uint16_t>(d.data() + 36 + 6 * i, items[i].size);
    store_little_endian<std::uint16_t>(d.data() + 38 + 6 * i, items[i].version);
  }
  return d;
}

// The chunk table that read_chunk_table() reads, for chunks of these byte counts (fixed-size chunks):
// version 0, the count, then each byte count coded against the one before.
inline std::vector<unsigned char> encode_chunk_table(const std::vector<std::uint64_t>& chunk_bytes)
{
  std::vector<unsigned char> table(8);
  store_little_endian<std::uint32_t>(table.data(), 0);
  store_little_endian<std::uint32_t>(table.data() + 4, std::uint32_t(chunk_bytes.size()));
  if(chunk_bytes.empty())
    return table;
  Arithmetic_encoder encoder;
  encoder.init();
  Integer_coder sizes(32, 2);
  sizes.init();
  std::uint32_t last = 0;
  for(const std::uint64_t bytes : chunk_bytes)
  {
    if(bytes > 0xFFFFFFFFu)
      throw std::length_error("LAZ: a chunk of " + std::to_string(bytes) + " bytes, more than its table's 32 bits");
    sizes.compress(encoder, std::int32_t(last), std::int32_t(std::uint32_t(bytes)), 1);
    last = std::uint32_t(bytes);
  }
  encoder.done();
  table.insert(table.end(), encoder.bytes().begin(), encoder.bytes().end());
  return table;
}

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_ENCODE_CHUNKS_H
