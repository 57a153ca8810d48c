// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_ORIENTED_POINT_SET_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_ORIENTED_POINT_SET_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/IO/lower_case_extension.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/check_points.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/input_file.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/merge_equal_positions.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/mesh_to_points.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_polygon_soup.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_xyz.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  the number of neighbors of the normal estimation and orientation of `read_oriented_point_set()`
  for point sets without normals (the value of CGAL's normal estimation examples).
*/
constexpr unsigned int DEFAULT_ESTIMATION_NEIGHBORS = 18;

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  \brief reads a mesh (OFF, PLY, OBJ, STL) or a point set (XYZ/PWN lines `x y z [nx ny nz]`,
  PLY with or without `nx ny nz`, OFF without faces) into distinct points with oriented unit normals,
  as SPEC §1 prescribes.

  Meshes: one point per vertex that has a face, its normal from
  `Polygon_mesh_processing::compute_vertex_normals()` (inconsistent orientations are repaired by
  `orient_polygon_soup()` first); vertices at one position merged, the first kept.
  Point sets: duplicates merged, the first kept; without normals, normals are estimated by jet
  fitting and oriented by a minimum spanning tree over `estimation_neighbors` neighbors; with
  `estimation_neighbors = 0` they are not estimated and `normals` comes back empty.

  \param filename the file; its extension (any case) selects the format: `.off`, `.obj`, `.ply`,
  `.stl`, `.xyz` or `.pwn`
  \param estimation_neighbors the number of neighbors of the normal estimation and orientation of
  point sets without normals, 0 or at least 6 (jet fitting of degree 2 needs 6 points; smaller
  values throw `std::invalid_argument`); 0 leaves them without normals
  \return the points, their normals, and counts of merged, dropped and unoriented points

  \throws Input_error with a one-line message on anything unusable: a missing, unreadable or empty
  file, an unknown extension, a syntax error, non-finite coordinates, zero or non-finite normals,
  no points.
*/
inline Oriented_point_set read_oriented_point_set(const std::string& filename,
                                                  unsigned int estimation_neighbors = DEFAULT_ESTIMATION_NEIGHBORS)
{
  if(estimation_neighbors != 0 && estimation_neighbors < internal::FEWEST_POINTS_TO_ESTIMATE_NORMALS)
    throw std::invalid_argument("read_oriented_point_set: estimation_neighbors must be 0 or at least " +
                                std::to_string(internal::FEWEST_POINTS_TO_ESTIMATE_NORMALS));
  const internal::Input_file file = internal::open_input_file(
    filename, {"off", "obj", "ply", "stl", "xyz", "pwn"}, ".off, .obj, .ply, .stl, .xyz or .pwn");

  // Each format to points, and normals when the file has them; a mesh is done there.
  Oriented_point_set out;
  bool has_normals = false;
  if(file.extension == "xyz" || file.extension == "pwn")
    internal::read_xyz(file.name, out.points, out.normals, has_normals);
  else
  {
    internal::Polygon_soup soup;
    internal::read_polygon_soup(file, soup);
    if(!soup.polygons.empty())
    {
      internal::mesh_to_points(soup, out);
      return out;
    }
    if(file.extension == "obj" || file.extension == "stl")
      throw Input_error("no faces in the file");
    internal::read_points_without_faces(file, out.points, out.normals, has_normals); // OFF or PLY
  }

  // A point set: checked, merged, normals estimated when it has none.
  out.input_vertices = out.points.size();
  if(out.points.empty())
    throw Input_error("no points in the file");
  internal::check_points_and_normals(out.points, out.normals, has_normals);
  internal::merge_duplicate_points(out, has_normals);
  if(!has_normals && estimation_neighbors == 0)
  {
    out.normals.clear();
    return out;
  }
  if(!has_normals)
  {
    if(out.points.size() < internal::FEWEST_POINTS_TO_ESTIMATE_NORMALS)
      throw Input_error("too few distinct points (" + std::to_string(out.points.size()) + ") to estimate normals");
    internal::estimate_normals(out, (std::min)(estimation_neighbors, unsigned(out.points.size() - 1)));
  }
  return out;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_ORIENTED_POINT_SET_H
