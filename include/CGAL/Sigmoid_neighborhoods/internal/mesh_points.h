// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H

#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>

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

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  how the vertices of a mesh became the points of the computation (SPEC §1): one point per
  vertex with an incident face and a defined normal, vertices at the same position merged
  (the one of smallest index kept).
*/
struct Mesh_points_summary
{
  std::size_t vertices = 0;          ///< vertices of the mesh
  std::size_t points = 0;            ///< distinct points evaluated
  std::size_t merged_duplicates = 0; ///< vertices merged into an earlier one at the same position
  std::size_t isolated_vertices = 0; ///< vertices without an incident face, not evaluated
  std::size_t undefined_normals = 0; ///< vertices whose faces are all degenerate (zero normal), not evaluated

  std::size_t dropped_vertices() const { return isolated_vertices + undefined_normals; }
};

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
    const Point& p = mesh.point(v);
    if(!(std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()))))
      throw std::invalid_argument("vertex " + std::to_string(std::size_t(v)) + " has a non-finite coordinate");
    const Vector_3 n = get(normals, v);
    const double squared_norm = CGAL::to_double(n.squared_length());
    if(!(squared_norm > 0.) || !std::isfinite(squared_norm))
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
    const Point& p = mesh.point(v);
    const Vector_3 n = get(normals, v);
    Eigen::Vector3d normal(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    const double squared_norm = normal.squaredNorm();
    if(std::abs(squared_norm - 1.) > 1e-12)
      normal /= std::sqrt(squared_norm);
    result.point_of_vertex[std::size_t(v)] = std::uint32_t(result.input.points.size());
    result.input.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
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
