// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_LAS_POINT_SUMMARY_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_LAS_POINT_SUMMARY_H

#include <CGAL/Sigmoid_neighborhoods/IO/little_endian.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
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

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_LAS_POINT_SUMMARY_H
