// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_MESH_TO_POINTS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_MESH_TO_POINTS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/check_points.h>
#include <Sigmoid_neighborhoods_readers/internal/is_polygon_mesh.h>
#include <Sigmoid_neighborhoods_readers/internal/merge_equal_positions.h>
#include <Sigmoid_neighborhoods_readers/internal/read_polygon_soup.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
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

// Meshes with fewer faces have their normals computed on one thread.
constexpr std::size_t PARALLEL_NORMAL_FACES = std::size_t(1) << 13;

// What CGAL's `Polygon_mesh_processing::compute_vertex_normals()` gives, each face's and each
// vertex's normal computed by CGAL's function on `threads` threads (0: the default): the same bits.
template <typename Point_3>
typename CGAL::Surface_mesh<Point_3>::template Property_map<typename CGAL::Surface_mesh<Point_3>::Vertex_index,
                                                            typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3>
vertex_normals_on_threads(CGAL::Surface_mesh<Point_3>& mesh, unsigned int threads)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector_3;
  auto face_normals = mesh.template add_property_map<typename Mesh::Face_index, Vector_3>("f:normal").first;
  auto vertex_normals = mesh.template add_property_map<typename Mesh::Vertex_index, Vector_3>("v:normal").first;
  const std::vector<typename Mesh::Face_index> all_faces(mesh.faces().begin(), mesh.faces().end());
  const std::vector<typename Mesh::Vertex_index> all_vertices(mesh.vertices().begin(), mesh.vertices().end());
  auto on_threads = [&](std::size_t n, const auto& body) {
    auto no_scratch = [] { return 0; };
    auto each = [&](std::size_t i, int) { body(i); };
    // a small mesh on one thread: a forked child (the readers' limit tests) cannot start a region
    if(all_faces.size() < PARALLEL_NORMAL_FACES)
      for_each_index<CGAL::Sequential_tag>(n, 1, no_scratch, each);
    else
      for_each_index<Parallel_if_available_tag>(n, threads, no_scratch, each, 256);
  };
  on_threads(all_faces.size(), [&](std::size_t i) {
    face_normals[all_faces[i]] = PMP::compute_face_normal(all_faces[i], mesh);
  });
  on_threads(all_vertices.size(), [&](std::size_t i) {
    vertex_normals[all_vertices[i]] =
      PMP::compute_vertex_normal(all_vertices[i], mesh, CGAL::parameters::face_normal_map(face_normals));
  });
  return vertex_normals;
}

// A mesh to points (SPEC §1): one point per vertex with a face, vertices at one position merged
// into the first of them, normals from CGAL's vertex normals of the faces that keep three corners.
// The merge, the check of the faces and the normals run on `threads` threads (0: the default).
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
  const Merged_positions merged = merge_equal_positions(soup.points, referenced, threads);
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

  const auto mesh_points = internal::mesh_points(
    mesh, CGAL::parameters::vertex_normal_map(vertex_normals_on_threads(mesh, threads)));
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

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_MESH_TO_POINTS_H
