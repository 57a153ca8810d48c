// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_POLYGON_SOUP_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_POLYGON_SOUP_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/Polygon_soup.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/cgal_5_5_workarounds.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/input_file.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_off.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_ply.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_stl.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Reads the soup of an OFF, OBJ, PLY or STL file with the reader of its format; a file that
// cannot be parsed throws, with CGAL's explanation when it gave one. No faces is not an error here.
inline void read_polygon_soup(const Input_file& file, Polygon_soup& soup)
{
  const std::string& ext = file.extension;
  bool read = false;
  std::string reason;
  {
    Captured_cerr captured;
    if(ext == "off")
      read = read_off_soup(file, soup);
    else if(ext == "ply")
      read = read_ply_soup(file, soup);
    else if(ext == "obj")
      read = CGAL::IO::read_OBJ(file.name, soup.points, soup.polygons);
    else if(ext == "stl")
      read = read_stl_soup(file, soup);
    reason = captured.first_line();
  }
  if(!read)
    throw Input_error("cannot parse the file as " + ext + (ext == "obj" ? ", or it has no faces" : "") +
                      (reason.empty() ? std::string() : " (" + reason + ")"));
}

// The points, and normals when it has them, of an OFF or PLY file without faces, read by CGAL's
// point set reader (after read_polygon_soup(), which has checked the header).
inline void read_points_without_faces(const Input_file& file, std::vector<Oriented_point_set::Point_3>& points,
                                      std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals)
{
  CGAL::Point_set_3<Oriented_point_set::Point_3, Oriented_point_set::Vector_3> point_set;
  {
    Captured_cerr captured;
    if(!CGAL::IO::read_point_set(file.name, point_set))
    {
      const std::string why = captured.first_line();
      throw Input_error("cannot parse the file as " + file.extension + (why.empty() ? "" : " (" + why + ")"));
    }
  }
  has_normals = point_set.has_normal_map();
  for(auto it = point_set.begin(); it != point_set.end(); ++it)
  {
    points.push_back(point_set.point(*it));
    if(has_normals)
      normals.push_back(point_set.normal(*it));
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_POLYGON_SOUP_H
