// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The definitions of read_polygon_mesh.h: inline in the header-only build, compiled once into the
// library Sigmoid_neighborhoods_readers otherwise (config.h).

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_POLYGON_MESH_IMPL_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_POLYGON_MESH_IMPL_H

#include <Sigmoid_neighborhoods_readers/read_polygon_mesh.h>

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/is_polygon_mesh.h>
#include <Sigmoid_neighborhoods_readers/internal/mesh_to_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_polygon_soup.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

SIGMOID_NEIGHBORHOODS_READERS_FUNCTION void
read_polygon_mesh(const std::string& filename, CGAL::Surface_mesh<Oriented_point_set::Point_3>& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const internal::Input_file file =
    internal::open_input_file(filename, {"off", "obj", "ply", "stl"}, ".off, .obj, .ply or .stl");
  internal::Polygon_soup soup;
  internal::read_polygon_soup(file, soup);
  if(soup.polygons.empty())
    throw Input_error("no faces in the file");
  internal::check_soup(soup);
  PMP::repair_polygon_soup(soup.points, soup.polygons);
  // A soup that is a mesh is one consistently oriented fan around each vertex: CGAL's orientation
  // would flip no face and split no vertex, so it is skipped.
  if(!internal::is_polygon_mesh(soup.polygons))
  {
    PMP::orient_polygon_soup(soup.points, soup.polygons);
    if(!internal::is_polygon_mesh(soup.polygons))
      throw Input_error("the faces do not form a polygon mesh, even after orientation");
  }
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  PMP::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  if(mesh.is_empty() || mesh.number_of_faces() == 0)
    throw Input_error("no faces in the file");
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_POLYGON_MESH_IMPL_H
