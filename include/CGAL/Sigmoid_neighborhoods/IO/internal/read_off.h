// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_OFF_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_OFF_H

#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/Polygon_soup.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/cgal_5_5_workarounds.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/input_file.h>

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

// The polygon soup of an OFF file: the loop of CGAL 5.5's `IO::read_OFF()` over CGAL's scanner,
// less what it does unchecked (found by fuzzing): it resizes to the counts of the header and of each
// face as they come (bounded here by the file size), and in ASCII it takes colors and texture
// coordinates at positions of the line that a short line does not have (a heap read out of bounds;
// they are not used here, so not read: the scanner has read the whole line already).
// Returns false where CGAL's reader does.
inline bool read_off_soup(const Input_file& file, Polygon_soup& soup)
{
  const std::uintmax_t file_size = file.size;
  std::vector<Oriented_point_set::Point_3>& points = soup.points;
  std::vector<std::vector<std::size_t>>& polygons = soup.polygons;
  std::ifstream is(file.name);
  CGAL::File_scanner_OFF scanner(is);
  if(is.fail())
    return false;
  const std::size_t vertices = scanner.size_of_vertices(), faces = scanner.size_of_facets();
  check_header_count(vertices, file_size, "vertices");
  check_header_count(faces, file_size - vertices, "faces after the vertices");
  points.resize(vertices);
  polygons.resize(faces);
  for(std::size_t i = 0; i < vertices; ++i)
  {
    double x = 0., y = 0., z = 0., w = 1.;
    scanner.scan_vertex(x, y, z, w);
    points[i] = Oriented_point_set::Point_3(x / w, y / w, z / w); // w = 0: non-finite, refused later
    if(scanner.binary() && scanner.has_normals())
    {
      double nx, ny, nz;
      scanner.scan_normal(nx, ny, nz);
    }
    if(scanner.binary() && scanner.has_textures())
    {
      double u, v, t;
      scanner.scan_texture(u, v, t);
    }
    if(!is.good())
      return false;
  }
  for(std::size_t i = 0; i < faces; ++i)
  {
    std::size_t corners = UNREAD_CORNER_COUNT;
    scanner.scan_facet(corners, i);
    if((!is.eof() && !is.good()) || corners == UNREAD_CORNER_COUNT)
      return false;
    check_header_count(corners, file_size, "corners of face " + std::to_string(i));
    polygons[i].resize(corners);
    for(std::size_t j = 0; j < corners; ++j)
    {
      std::size_t id = 0;
      scanner.scan_facet_vertex_index(id, j + 1, i);
      if(!is || id >= vertices)
        return false;
      polygons[i][j] = id;
    }
  }
  return !is.fail();
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_OFF_H
