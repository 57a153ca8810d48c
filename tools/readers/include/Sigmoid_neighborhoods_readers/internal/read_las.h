// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_LAS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_LAS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Lidar_io/Las_header.h>
#include <Lidar_io/little_endian.h>
#include <Lidar_io/read_las_records.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Room for n more points.
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
  // the header first, to size the vectors; read_las_records() reads it again with the records
  const Lidar_io::Las_header h = Lidar_io::read_las_header(file.name);

  // At most one point per record of the file (read_las_header() checked it): sized to the file,
  // unless a filter keeps a part of it. A LAZ file's count is checked against its chunk table, not
  // bounded by its size: its vectors grow as its chunks are decoded.
  if(std::is_same<Keep, Keep_every_las_point>::value && !h.compressed)
    reserve_las_points(out, std::size_t(h.point_count), h.has_gps_time());

  auto append = [&](std::size_t first, const unsigned char* records, std::size_t count) {
    for(std::size_t i = 0; i < count; ++i)
    {
      const unsigned char* r = records + i * h.record_length;
      double xyz[3];
      for(int c = 0; c < 3; ++c)
      {
        xyz[c] = double(Lidar_io::load_little_endian<std::int32_t>(r + 4 * c)) * h.scale[c] + h.offset[c];
        if(!std::isfinite(xyz[c]))
          throw Input_error("cannot parse the file as las (point " + std::to_string(first + i) +
                            " has a non-finite coordinate after scale and offset)");
      }
      if(!keep(first + i, xyz))
        continue;
      out.points.emplace_back(xyz[0], xyz[1], xyz[2]);
      out.intensities.push_back(Lidar_io::load_little_endian<std::uint16_t>(r + 12));
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
        out.gps_times.push_back(Lidar_io::load_little_endian<double>(r + h.gps_time_offset()));
    }
  };
  Lidar_io::read_las_records(file.name, append, threads);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_LAS_H
