// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H

#include <CGAL/Sigmoid_neighborhoods/Mesh_points_summary.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

namespace internal {

constexpr std::uint32_t NO_POINT = (std::numeric_limits<std::uint32_t>::max)();

template <typename Point>
struct Mesh_points
{
  Oriented_points input;
  // For every vertex index: the index of its point in `input`, or NO_POINT when dropped.
  std::vector<std::uint32_t> point_of_vertex;
  Mesh_points_summary summary;
};

// Vertex normals come from `vertex_normal_map` when given, else from
// `Polygon_mesh_processing::compute_vertex_normals()`.
template <typename Point, typename NamedParameters>
Mesh_points<Point> mesh_points(const CGAL::Surface_mesh<Point>& mesh, const NamedParameters& np)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector_3;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  Mesh_points<Point> result;
  result.point_of_vertex.assign(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), NO_POINT);
  result.summary.vertices = mesh.number_of_vertices();

  auto normals = get(CGAL::dynamic_vertex_property_t<Vector_3>(), mesh);
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value)
  {
    const auto given = get_parameter(np, CGAL::internal_np::vertex_normal_map);
    for(Vertex_index v : mesh.vertices())
      put(normals, v, get(given, v));
  }
  else
    CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);

  std::vector<Vertex_index> candidates;
  for(Vertex_index v : mesh.vertices())
  {
    if(mesh.is_isolated(v))
    {
      ++result.summary.isolated_vertices;
      continue;
    }
    checked_point(mesh.point(v), "vertex", std::size_t(v));
    Eigen::Vector3d normal;
    if(!unit_normal(get(normals, v), normal))
    {
      ++result.summary.undefined_normals;
      continue;
    }
    candidates.push_back(v);
  }

  // Equal positions become adjacent after a stable sort by coordinates; the first in index
  // order represents them all.
  std::vector<Vertex_index> sorted = candidates;
  auto position_less = [&mesh](Vertex_index x, Vertex_index y) {
    const Point &p = mesh.point(x), &q = mesh.point(y);
    if(p.x() != q.x()) return p.x() < q.x();
    if(p.y() != q.y()) return p.y() < q.y();
    return p.z() < q.z();
  };
  std::stable_sort(sorted.begin(), sorted.end(), position_less);
  std::vector<Vertex_index> representative(result.point_of_vertex.size());
  for(std::size_t s = 0; s < sorted.size();)
  {
    std::size_t e = s + 1;
    while(e < sorted.size() && mesh.point(sorted[e]) == mesh.point(sorted[s]))
      ++e;
    for(std::size_t t = s; t < e; ++t)
      representative[std::size_t(sorted[t])] = sorted[s];
    s = e;
  }

  for(Vertex_index v : candidates)
  {
    const Vertex_index r = representative[std::size_t(v)];
    if(r != v)
    {
      ++result.summary.merged_duplicates;
      continue;
    }
    Eigen::Vector3d normal;
    unit_normal(get(normals, v), normal);
    result.point_of_vertex[std::size_t(v)] = std::uint32_t(result.input.points.size());
    result.input.points.push_back(checked_point(mesh.point(v), "vertex", std::size_t(v)));
    result.input.normals.push_back(normal);
  }
  for(Vertex_index v : candidates)
    result.point_of_vertex[std::size_t(v)] = result.point_of_vertex[std::size_t(representative[std::size_t(v)])];
  result.summary.points = result.input.points.size();
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H
