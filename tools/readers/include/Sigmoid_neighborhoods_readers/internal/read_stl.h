// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_STL_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_STL_H

#include <Sigmoid_neighborhoods_readers/internal/Byte_budget.h>
#include <Sigmoid_neighborhoods_readers/internal/Polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>

#include <CGAL/IO/STL.h>

#include <cctype>
#include <cstdint>
#include <fstream>
#include <string>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A binary STL file: an 80-byte header, a 32-bit little-endian triangle count, 50 bytes a triangle.
constexpr std::uintmax_t STL_HEADER_BYTES = 80, STL_COUNT_BYTES = 4, STL_TRIANGLE_BYTES = 50;

// The polygon soup of an STL file: CGAL's reader, after the triangle count of a binary file is
// checked against the bytes left. CGAL reads as binary a file whose first word is not `solid`,
// followed by a space or a line end (else as ASCII first), and stops at the end of the file
// anyway; the count is checked for the message.
inline bool read_stl_soup(const Input_file& file, Polygon_soup& soup)
{
  {
    std::ifstream in(file.name, std::ios::binary);
    std::string start;
    char c = 0;
    while(in.get(c) && std::isspace(static_cast<unsigned char>(c)))
      continue;
    for(start += c; start.size() < 6 && in.get(c);)
      start += c;
    const bool ascii = start.size() == 6 && start.compare(0, 5, "solid") == 0 &&
                       (start[5] == '\n' || start[5] == '\r' || start[5] == ' ');
    unsigned char count[STL_COUNT_BYTES];
    in.clear();
    in.seekg(std::streamoff(STL_HEADER_BYTES));
    if(!ascii && in.read(reinterpret_cast<char*>(count), STL_COUNT_BYTES))
    {
      const std::uint32_t triangles = std::uint32_t(count[0]) | std::uint32_t(count[1]) << 8 |
                                      std::uint32_t(count[2]) << 16 | std::uint32_t(count[3]) << 24;
      const Byte_budget budget(file.size, file.size - (STL_HEADER_BYTES + STL_COUNT_BYTES));
      budget.check(triangles, STL_TRIANGLE_BYTES, [&](const std::string& excess) {
        return "cannot parse the file as stl (the header announces " + std::to_string(triangles) + " triangles" +
               excess + ")";
      });
    }
  }
  return CGAL::IO::read_STL(file.name, soup.points, soup.polygons);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_STL_H
