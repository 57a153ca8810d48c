// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_READ_POLYGON_MESH_H
#define SIGMOID_NEIGHBORHOODS_READERS_READ_POLYGON_MESH_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/config.h>

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \brief reads a mesh file (OFF, PLY, OBJ, STL) into `mesh`, through the readers of
  `read_oriented_point_set()`, and makes it a polygon mesh as
  `CGAL::Polygon_mesh_processing::IO::read_polygon_mesh()` does: the soup repaired by
  `repair_polygon_soup()` and oriented by `orient_polygon_soup()` (unless it is a polygon mesh
  already, when that would change nothing); vertices without a face are removed. Plain ASCII OFF
  and OBJ files are parsed on OpenMP's default number of threads, with the result of CGAL's readers.

  \param filename the file; its extension (any case) selects the format: `.off`, `.obj`, `.ply` or `.stl`
  \param mesh the mesh read; it should be empty

  \throws Input_error with a one-line message on anything unusable: a missing, unreadable or empty
  file, an unknown extension, a syntax error, non-finite coordinates, no faces, faces that do not
  form a polygon mesh.
*/
SIGMOID_NEIGHBORHOODS_READERS_FUNCTION void
read_polygon_mesh(const std::string& filename, CGAL::Surface_mesh<Oriented_point_set::Point_3>& mesh);

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef SIGMOID_NEIGHBORHOODS_READERS_COMPILED
#include <Sigmoid_neighborhoods_readers/internal/read_polygon_mesh_impl.h>
#endif

#endif // SIGMOID_NEIGHBORHOODS_READERS_READ_POLYGON_MESH_H
