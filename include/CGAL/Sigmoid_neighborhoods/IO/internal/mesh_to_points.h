// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_MESH_TO_POINTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_MESH_TO_POINTS_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/check_points.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/is_polygon_mesh.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/merge_equal_positions.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_polygon_soup.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The faces need three distinct corners to have a normal.
constexpr std::size_t FEWEST_FACE_CORNERS = 3;

// Every vertex finite and within LARGEST_COORDINATE, every corner a vertex of the soup.
inline void check_soup(const Polygon_soup& soup)
{
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    check_coordinates(soup.points[v], "vertex", v);
  for(const auto& polygon : soup.polygons)
    for(std::size_t v : polygon)
      if(v >= soup.points.size())
        throw Input_error("a face refers to vertex " + std::to_string(v) + " of " + std::to_string(soup.points.size()));
}

// A mesh to points (SPEC §1): one point per vertex with a face, vertices at one position merged
// into the first of them, normals from CGAL's vertex normals of the faces that keep three corners.
// The check of the faces runs on `threads` threads (0: the default).
inline void mesh_to_points(const Polygon_soup& soup, Oriented_point_set& out, unsigned int threads = 0)
{
  typedef Oriented_point_set::Point_3 Point_3;
  namespace PMP = CGAL::Polygon_mesh_processing;
  out.is_mesh = true;
  out.input_vertices = soup.points.size();
  check_soup(soup);

  std::vector<bool> referenced(soup.points.size(), false);
  for(const auto& polygon : soup.polygons)
    for(std::size_t v : polygon)
      referenced[v] = true;
  const Merged_positions merged = merge_equal_positions(soup.points, referenced);
  const std::size_t referenced_count = merged.first.size() + merged.merged;
  out.dropped_vertices = soup.points.size() - referenced_count;
  out.merged_duplicates = merged.merged;
  std::vector<Point_3> distinct;
  distinct.reserve(merged.first.size());
  for(std::size_t v : merged.first)
    distinct.push_back(soup.points[v]);

  // Faces that collapse to fewer than three corners have no normal: left out.
  std::vector<std::vector<std::size_t>> faces;
  for(const auto& polygon : soup.polygons)
  {
    std::vector<std::size_t> face;
    for(std::size_t v : polygon)
    {
      const std::size_t c = merged.position_of[v];
      if(std::find(face.begin(), face.end(), c) == face.end())
        face.push_back(c);
    }
    if(face.size() >= FEWEST_FACE_CORNERS)
      faces.push_back(std::move(face));
  }
  if(faces.empty())
    throw Input_error("no face with three distinct corners");
  // Non-manifold or inconsistently oriented faces: CGAL orients them, splitting vertices where needed;
  // the split copies share a position and are merged again below.
  if(!is_polygon_mesh(faces, threads))
    PMP::orient_polygon_soup(distinct, faces);
  if(!is_polygon_mesh(faces, threads))
    throw Input_error("the faces do not form a polygon mesh, even after orientation");
  CGAL::Surface_mesh<Point_3> mesh;
  PMP::polygon_soup_to_polygon_mesh(distinct, faces, mesh);

  const auto mesh_points = internal::mesh_points(mesh, CGAL::parameters::default_values());
  // Vertices of `distinct` used by no kept face are isolated in `mesh`.
  out.dropped_vertices += mesh_points.summary.dropped_vertices();
  for(std::size_t i = 0; i < mesh_points.input.size(); ++i)
  {
    const auto& p = mesh_points.input.points[i];
    const auto& n = mesh_points.input.normals[i];
    out.points.emplace_back(p.x(), p.y(), p.z());
    out.normals.emplace_back(n[0], n[1], n[2]);
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_MESH_TO_POINTS_H
