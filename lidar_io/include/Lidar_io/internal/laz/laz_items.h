// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_LAZ_ITEMS_H
#define LIDAR_IO_INTERNAL_LAZ_LAZ_ITEMS_H

#include <cstdint>
#include <stdexcept>
#include <string>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// The parts of a point record that LASzip compresses one by one, as its VLR lists them (LAZ
// specification 1.4: "item" types); a record is its items' bytes one after the other.
enum Item_type : std::uint16_t
{
  BYTE = 0, SHORT = 1, INT = 2, LONG = 3, FLOAT = 4, DOUBLE = 5,
  POINT10 = 6, GPSTIME11 = 7, RGB12 = 8, WAVEPACKET13 = 9,
  POINT14 = 10, RGB14 = 11, RGBNIR14 = 12, WAVEPACKET14 = 13, BYTE14 = 14
};

struct Item
{
  std::uint16_t type = 0, size = 0, version = 0;
};

// A chunk that does not decode; the message says why, without the file or the chunk (the caller
// adds them).
struct Decode_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

inline std::string item_name(std::uint16_t type)
{
  static const char* const names[] = {"BYTE",   "SHORT",     "INT",   "LONG",         "FLOAT",
                                      "DOUBLE", "POINT10",   "GPSTIME11", "RGB12",  "WAVEPACKET13",
                                      "POINT14", "RGB14",    "RGBNIR14", "WAVEPACKET14", "BYTE14"};
  return type < sizeof(names) / sizeof(names[0]) ? names[type] : "unknown item " + std::to_string(type);
}

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_LAZ_ITEMS_H
