// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_OFF_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_OFF_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/Byte_budget.h>
#include <Sigmoid_neighborhoods_readers/internal/Polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>

#include <CGAL/IO/OFF/File_scanner_OFF.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// What CGAL's scanner leaves in a face's corner count when it cannot read one.
constexpr std::size_t UNREAD_CORNER_COUNT = std::size_t(-1);

// The bytes an OFF item takes at least, to bound the counts by the bytes left (Byte_budget). The
// header's counts are bounded at one byte a vertex or face, so that a file merely cut short is one
// that cannot be parsed, as CGAL says. Once read, a vertex has taken a line of 3 numbers in ASCII,
// 3 floats in binary; a face's corner count and each corner, a number of one character in ASCII,
// a 32-bit integer in binary.
constexpr std::uintmax_t OFF_ITEM_BYTES = 1;
constexpr std::uintmax_t OFF_ASCII_VERTEX_BYTES = 4, OFF_BINARY_VERTEX_BYTES = 12;
constexpr std::uintmax_t OFF_ASCII_NUMBER_BYTES = 1, OFF_BINARY_NUMBER_BYTES = 4;

// The polygon soup of an OFF file: the loop of CGAL 5.5's `IO::read_OFF()` over CGAL's scanner,
// less what it does unchecked (found by fuzzing): it resizes to the counts of the header and of each
// face as they come (bounded here by the bytes left), and in ASCII it takes colors and texture
// coordinates at positions of the line that a short line does not have (a heap read out of bounds;
// they are not used here, so not read: the scanner has read the whole line already).
// Returns false where CGAL's reader does.
inline bool read_off_soup(const Input_file& file, Polygon_soup& soup)
{
  std::vector<Oriented_point_set::Point_3>& points = soup.points;
  std::ifstream is(file.name);
  CGAL::File_scanner_OFF scanner(is);
  if(is.fail())
    return false;
  const std::size_t vertices = scanner.size_of_vertices(), faces = scanner.size_of_facets();
  const bool binary = scanner.binary();
  const std::uintmax_t number_bytes = binary ? OFF_BINARY_NUMBER_BYTES : OFF_ASCII_NUMBER_BYTES;
  const std::streamoff header_end = is.tellg();
  const std::uintmax_t read = header_end > 0 ? std::uintmax_t(header_end) : 0;
  Byte_budget budget(file.size, read < file.size ? file.size - read : 0);
  {
    Byte_budget header = budget;
    header.check(vertices, OFF_ITEM_BYTES, [&](const std::string& excess) {
      return "the header announces " + std::to_string(vertices) + " vertices" + excess;
    });
    header.take(vertices, OFF_ITEM_BYTES);
    header.check(faces, OFF_ITEM_BYTES, [&](const std::string& excess) {
      return "the header announces " + std::to_string(faces) + " faces after " + std::to_string(vertices) +
             " vertices" + excess;
    });
  }
  points.resize(vertices);
  soup.polygons.resize(faces);
  for(std::size_t i = 0; i < vertices; ++i)
  {
    double x = 0., y = 0., z = 0., w = 1.;
    scanner.scan_vertex(x, y, z, w);
    points[i] = Oriented_point_set::Point_3(x / w, y / w, z / w); // w = 0: non-finite, refused later
    if(binary && scanner.has_normals())
    {
      double nx, ny, nz;
      scanner.scan_normal(nx, ny, nz);
    }
    if(binary && scanner.has_textures())
    {
      double u, v, t;
      scanner.scan_texture(u, v, t);
    }
    if(!is.good())
      return false;
  }
  budget.take(vertices, binary ? OFF_BINARY_VERTEX_BYTES : OFF_ASCII_VERTEX_BYTES);
  for(std::size_t i = 0; i < faces; ++i)
  {
    std::size_t corners = UNREAD_CORNER_COUNT;
    scanner.scan_facet(corners, i);
    if((!is.eof() && !is.good()) || corners == UNREAD_CORNER_COUNT)
      return false;
    budget.take(1, number_bytes);
    budget.check(corners, number_bytes, [&](const std::string& excess) {
      return "face " + std::to_string(i) + " announces " + std::to_string(corners) + " corners" + excess;
    });
    budget.take(corners, number_bytes);
    std::vector<std::size_t>& polygon = soup.polygons[i];
    polygon.resize(corners);
    for(std::size_t j = 0; j < corners; ++j)
    {
      std::size_t id = 0;
      scanner.scan_facet_vertex_index(id, j + 1, i);
      if(!is || id >= vertices)
        return false;
      polygon[j] = id;
    }
  }
  return !is.fail();
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_OFF_H
