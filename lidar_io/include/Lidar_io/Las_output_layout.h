// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LAS_OUTPUT_LAYOUT_H
#define LIDAR_IO_LAS_OUTPUT_LAYOUT_H

#include <Lidar_io/Input_error.h>
#include <Lidar_io/Las_header.h>
#include <Lidar_io/little_endian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  the data type of an extra bytes dimension of a LAS 1.4 point record (LAS 1.4 R15, Table 24).
*/
enum class Las_extra_bytes_type : std::uint8_t
{
  UNSIGNED_CHAR = 1, ///< uint8
  CHAR,              ///< int8
  UNSIGNED_SHORT,    ///< uint16
  SHORT,             ///< int16
  UNSIGNED_LONG,     ///< uint32
  LONG,              ///< int32
  UNSIGNED_LONG_LONG,///< uint64
  LONG_LONG,         ///< int64
  FLOAT,             ///< 32-bit IEEE
  DOUBLE             ///< 64-bit IEEE
};

/*!
  \ingroup PkgLidarIo
  the bytes a value of type `type` takes in a record.
*/
inline std::size_t las_extra_bytes_size(Las_extra_bytes_type type)
{
  static const std::size_t bytes[] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
  return bytes[std::size_t(type)];
}

/*!
  \ingroup PkgLidarIo
  a value added to every point record of a LAS file, described in its Extra Bytes record (record 4
  of `LASF_Spec`), which PDAL, LAStools, lidR and CloudCompare read by `name`.
*/
struct Las_extra_dimension
{
  std::string name;        ///< at most 32 characters
  std::string description; ///< at most 32 characters
  Las_extra_bytes_type type = Las_extra_bytes_type::FLOAT; ///< how the value is stored
  /// 0: the value stored as it is (rounded to the nearest integer for an integer type); else stored
  /// as the integer nearest to `(value - offset) / scale`, which readers turn back into
  /// `integer * scale + offset`
  double scale = 0.;
  double offset = 0.; ///< see `scale`
};

/*!
  \ingroup PkgLidarIo
  what a LAS 1.4 file written by `Las_writer` holds besides its point records: its public header
  block (the counts and the bounding box are the writer's), its variable length records with the
  Extra Bytes record last, its extended variable length records after the points, and where each
  record's fields lie. Made by `las_output_layout_like()` (its own header: it reads a file) for the records of a LAS or LAZ file with
  values added, or by `las_output_layout_for()` for new records.
*/
struct Las_output_layout
{
  static constexpr std::size_t HEADER_BYTES = 375; ///< a LAS 1.4 public header block

  std::array<unsigned char, HEADER_BYTES> header{}; ///< the public header block
  std::vector<unsigned char> vlrs;    ///< the variable length records, each with its 54-byte header
  std::uint32_t vlr_count = 0;        ///< records in `vlrs`
  std::vector<unsigned char> evlrs;   ///< the extended variable length records, written after the points
  std::uint32_t evlr_count = 0;       ///< records in `evlrs`
  /// where the waveform data packets start in `evlrs` (a point's waveform offset counts from there),
  /// or `NO_WAVEFORMS`
  std::uint64_t waveforms_in_evlrs = NO_WAVEFORMS;
  static constexpr std::uint64_t NO_WAVEFORMS = std::uint64_t(-1); ///< see `waveforms_in_evlrs`

  unsigned int point_format = 6;      ///< 0 to 10
  std::uint16_t copied_record_length = 0; ///< the bytes of a record before the added dimensions
  std::uint16_t record_length = 0;    ///< with the added dimensions
  std::vector<Las_extra_dimension> added; ///< the dimensions added after the copied bytes
  std::vector<std::uint16_t> added_offsets; ///< the byte of a record where each of `added` starts
  std::array<double, 3> scale{{0., 0., 0.}};  ///< coordinate = integer * scale + offset (the header's)
  std::array<double, 3> offset{{0., 0., 0.}}; ///< see `scale`

  /// formats 6 to 10: 4-bit return numbers, 8-bit classification at byte 16
  bool has_extended_format() const { return point_format >= 6; }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

constexpr std::size_t LAS_VLR_HEADER_BYTES = 54;
constexpr std::size_t LAS_EXTRA_BYTES_DESCRIPTOR_BYTES = 192;

// A fixed-width text field: the characters of `text` that fit, the rest zero.
inline void store_las_text(unsigned char* field, std::size_t width, const std::string& text)
{
  std::memset(field, 0, width);
  std::memcpy(field, text.data(), (std::min)(width, text.size()));
}

inline bool las_vlr_is(const unsigned char* vlr, const char* user_id, std::uint16_t record_id)
{
  char user[17] = {};
  std::memcpy(user, vlr + 2, 16);
  return std::string(user) == user_id && load_little_endian<std::uint16_t>(vlr + 18) == record_id;
}

// The bytes a descriptor of the Extra Bytes record gives each record: data types 1 to 10, the
// deprecated arrays of two and three of them (11 to 30), or `options` bytes for type 0.
inline std::size_t las_descriptor_bytes(const unsigned char* descriptor)
{
  const unsigned int type = descriptor[2];
  if(type == 0)
    return descriptor[3];
  if(type > 30)
    throw Input_error("cannot parse the file as las (an extra bytes dimension of data type " + std::to_string(type) +
                      ", not one of LAS 1.4's)");
  const unsigned int base = (type - 1) % 10 + 1;
  return las_extra_bytes_size(Las_extra_bytes_type(base)) * ((type - 1) / 10 + 1);
}

inline std::array<unsigned char, LAS_EXTRA_BYTES_DESCRIPTOR_BYTES> las_descriptor(const Las_extra_dimension& d)
{
  std::array<unsigned char, LAS_EXTRA_BYTES_DESCRIPTOR_BYTES> b{};
  b[2] = std::uint8_t(d.type);
  store_las_text(b.data() + 4, 32, d.name);
  store_las_text(b.data() + 160, 32, d.description);
  if(d.scale != 0.)
  {
    b[3] = 0x08 | 0x10; // scale and offset given
    store_little_endian<double>(b.data() + 112, d.scale);
    store_little_endian<double>(b.data() + 136, d.offset);
  }
  return b;
}

inline void append_las_vlr(Las_output_layout& l, const char* user_id, std::uint16_t record_id,
                           const char* description, const std::vector<unsigned char>& payload)
{
  if(payload.size() > 0xFFFF)
    throw std::length_error("a variable length record of " + std::to_string(payload.size()) + " bytes: at most 65535");
  unsigned char h[LAS_VLR_HEADER_BYTES] = {};
  store_las_text(h + 2, 16, user_id);
  store_little_endian<std::uint16_t>(h + 18, record_id);
  store_little_endian<std::uint16_t>(h + 20, std::uint16_t(payload.size()));
  store_las_text(h + 22, 32, description);
  l.vlrs.insert(l.vlrs.end(), h, h + LAS_VLR_HEADER_BYTES);
  l.vlrs.insert(l.vlrs.end(), payload.begin(), payload.end());
  ++l.vlr_count;
}

// Places `added` after the first `l.copied_record_length` bytes of each record and describes them,
// after the descriptors `described` of the bytes before them, in one Extra Bytes record, the last VLR.
inline void add_las_extra_dimensions(Las_output_layout& l, std::vector<unsigned char> described,
                                     const std::vector<Las_extra_dimension>& added)
{
  std::size_t length = l.copied_record_length;
  for(const Las_extra_dimension& d : added)
  {
    if(d.name.empty() || d.name.size() > 32 || d.description.size() > 32)
      throw std::invalid_argument("the extra bytes dimension '" + d.name + "': a name of 1 to 32 characters and a "
                                  "description of at most 32");
    if(std::uint8_t(d.type) < 1 || std::uint8_t(d.type) > 10 || !std::isfinite(d.scale) || !std::isfinite(d.offset))
      throw std::invalid_argument("the extra bytes dimension '" + d.name + "': a type of 1 to 10, a finite scale and offset");
    l.added_offsets.push_back(std::uint16_t((std::min)(length, std::size_t(0xFFFF))));
    length += las_extra_bytes_size(d.type);
    const auto descriptor = las_descriptor(d);
    described.insert(described.end(), descriptor.begin(), descriptor.end());
  }
  if(length > 0xFFFF)
    throw std::length_error("point records of " + std::to_string(length) + " bytes: LAS allows at most 65535");
  l.record_length = std::uint16_t(length);
  l.added = added;
  if(!described.empty())
    append_las_vlr(l, "LASF_Spec", 4, "Extra Bytes", described);
}

inline void store_las_software_fields(Las_output_layout& l, const char* system_identifier)
{
  store_las_text(l.header.data() + 26, 32, system_identifier);
  store_las_text(l.header.data() + 58, 32, "Sigmoid_neighborhoods");
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgLidarIo
  appends to the VLRs of `layout` a variable length record of user `user_id` (at most 16 characters),
  number `record_id` and `description` (at most 32 characters) holding `payload`, e.g. a CRS as OGC
  WKT (`LASF_Projection`, 2112).
  \throws std::length_error for a payload of more than 65535 bytes
*/
inline void add_las_vlr(Las_output_layout& layout, const std::string& user_id, std::uint16_t record_id,
                        const std::string& description, const std::vector<unsigned char>& payload)
{
  internal::append_las_vlr(layout, user_id.c_str(), record_id, description.c_str(), payload);
}

/*!
  \ingroup PkgLidarIo
  the layout of a LAS 1.4 file of new point records in `point_format` (6, or 7 and 8 with colors)
  followed by the dimensions `added`, for points within the box `min`, `max`. Each axis is stored
  about the box's centre (`offset`) in units of one `scale` for all three axes: the smallest power
  of ten for which the box's largest half extent takes at most 2^30 units, so a coordinate is
  rounded by at most half a unit, less than 5e-9 times the box's largest extent (1e-9 for a box of
  one point), and the rounding of a double in `integer * scale + offset`. No CRS is written (global encoding: WKT bit set, as LAS 1.4 requires of these formats);
  the system identifier is `OTHER`, the creation date that of `creation_time` (now by default; a
  fixed time makes files that repeat bit for bit).
  \throws std::invalid_argument for a point format other than 6, 7 or 8, or a box not finite
*/
inline Las_output_layout las_output_layout_for(const std::array<double, 3>& min, const std::array<double, 3>& max,
                                               const std::vector<Las_extra_dimension>& added,
                                               unsigned int point_format = 6,
                                               std::time_t creation_time = std::time(nullptr))
{
  if(point_format < 6 || point_format > 8)
    throw std::invalid_argument("las_output_layout_for: point format 6, 7 or 8, not " + std::to_string(point_format));
  Las_output_layout l;
  l.point_format = point_format;
  l.copied_record_length = internal::LAS_POINT_RECORD_BYTES[point_format];
  double half_extent = 0.;
  for(int c = 0; c < 3; ++c)
  {
    if(!std::isfinite(min[c]) || !std::isfinite(max[c]) || min[c] > max[c])
      throw std::invalid_argument("las_output_layout_for: a box of finite coordinates, min <= max");
    l.offset[c] = min[c] + (max[c] - min[c]) / 2.;
    half_extent = (std::max)({half_extent, max[c] - l.offset[c], l.offset[c] - min[c]});
  }
  double scale = 1e-9;
  while(half_extent / scale > double(1 << 30))
    scale *= 10.;
  l.scale = {{scale, scale, scale}};

  unsigned char* h = l.header.data();
  std::memcpy(h, "LASF", 4);
  store_little_endian<std::uint16_t>(h + 6, 0x10); // WKT (none given); GPS week time
  h[24] = 1;
  h[25] = 4;
  internal::store_las_software_fields(l, "OTHER");
  std::tm date{};
  gmtime_r(&creation_time, &date);
  store_little_endian<std::uint16_t>(h + 90, std::uint16_t(date.tm_yday + 1));
  store_little_endian<std::uint16_t>(h + 92, std::uint16_t(date.tm_year + 1900));
  internal::add_las_extra_dimensions(l, {}, added);
  return l;
}

/*!
  \ingroup PkgLidarIo
  stores the coordinates `xyz` in `record` as `layout` scales them: the nearest integers.
  \throws std::range_error for a coordinate that does not fit a 32-bit integer at the layout's scale
*/
inline void store_las_coordinates(unsigned char* record, const Las_output_layout& layout, const std::array<double, 3>& xyz)
{
  for(int c = 0; c < 3; ++c)
  {
    const double units = std::nearbyint((xyz[c] - layout.offset[c]) / layout.scale[c]);
    if(!(units >= double((std::numeric_limits<std::int32_t>::min)()) &&
         units <= double((std::numeric_limits<std::int32_t>::max)())))
      throw std::range_error("a coordinate " + std::to_string(xyz[c]) + " outside what a LAS file of scale " +
                             std::to_string(layout.scale[c]) + " and offset " + std::to_string(layout.offset[c]) +
                             " holds");
    store_little_endian<std::int32_t>(record + 4 * c, std::int32_t(units));
  }
}

/*!
  \ingroup PkgLidarIo
  stores `value` as the added dimension `j` of `layout` in `record`: as a float or double (a NaN
  stays one), or, for an integer type, the nearest integer of the value (scaled when the dimension
  has a scale), clamped to the type's range (NaN as 0).
*/
inline void store_las_extra(unsigned char* record, const Las_output_layout& layout, std::size_t j, double value)
{
  const Las_extra_dimension& d = layout.added[j];
  unsigned char* at = record + layout.added_offsets[j];
  if(d.scale != 0.)
    value = (value - d.offset) / d.scale;
  auto integer = [&](auto zero) {
    typedef decltype(zero) T;
    const double v = std::isnan(value) ? 0. : std::nearbyint(value);
    const double low = double((std::numeric_limits<T>::min)()), high = double((std::numeric_limits<T>::max)());
    store_little_endian<T>(at, v <= low ? (std::numeric_limits<T>::min)()
                                        : v >= high ? (std::numeric_limits<T>::max)() : T(v));
  };
  switch(d.type)
  {
  case Las_extra_bytes_type::UNSIGNED_CHAR: integer(std::uint8_t()); break;
  case Las_extra_bytes_type::CHAR: integer(std::int8_t()); break;
  case Las_extra_bytes_type::UNSIGNED_SHORT: integer(std::uint16_t()); break;
  case Las_extra_bytes_type::SHORT: integer(std::int16_t()); break;
  case Las_extra_bytes_type::UNSIGNED_LONG: integer(std::uint32_t()); break;
  case Las_extra_bytes_type::LONG: integer(std::int32_t()); break;
  case Las_extra_bytes_type::UNSIGNED_LONG_LONG: integer(std::uint64_t()); break;
  case Las_extra_bytes_type::LONG_LONG: integer(std::int64_t()); break;
  case Las_extra_bytes_type::FLOAT: store_little_endian<float>(at, float(value)); break;
  case Las_extra_bytes_type::DOUBLE: store_little_endian<double>(at, value); break;
  }
}

} // namespace Lidar_io

#endif // LIDAR_IO_LAS_OUTPUT_LAYOUT_H
