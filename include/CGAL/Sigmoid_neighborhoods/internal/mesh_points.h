// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H

#include <CGAL/Sigmoid_neighborhoods/Mesh_points_summary.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>

#include <CGAL/Sigmoid_neighborhoods/internal/merge_equal_positions.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
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

struct Mesh_points
{
  Oriented_points input;
  // For every vertex index (the mesh's vertex index map): the index of its point in `input`, or
  // NO_POINT when dropped.
  std::vector<std::uint32_t> point_of_vertex;
  // The same for every vertex in the order of vertices(mesh): what the overloads write back.
  std::vector<std::uint32_t> point_in_vertex_order;
  Mesh_points_summary summary;
};

// A vertex without an incident halfedge has no face (CGAL's is_isolated()).
template <typename PolygonMesh>
bool is_isolated_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& mesh)
{
  return halfedge(v, mesh) == boost::graph_traits<PolygonMesh>::null_halfedge();
}

// The vertices of any FaceListGraph as the points of the computation (SPEC §1), positions from
// `vertex_point_map`, normals from `vertex_normal_map` when given, else from
// `Polygon_mesh_processing::compute_vertex_normals()`.
template <typename PolygonMesh, typename NamedParameters>
Mesh_points mesh_points(const PolygonMesh& mesh, const NamedParameters& np)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor Vertex;
  typedef typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type Geom_traits;
  typedef typename Geom_traits::Vector_3 Vector_3;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  const auto point_map =
    choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh));
  const auto index_map = CGAL::get_initialized_vertex_index_map(mesh, np);
  Mesh_points result;
  result.input.line_angles = line_angles(np);
  std::size_t slots = 0;
  for(Vertex v : vertices(mesh))
  {
    slots = (std::max)(slots, std::size_t(get(index_map, v)) + 1);
    ++result.summary.vertices;
  }
  result.point_of_vertex.assign(slots, NO_POINT);

  auto normals = get(CGAL::dynamic_vertex_property_t<Vector_3>(), mesh);
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value)
  {
    const auto given = get_parameter(np, CGAL::internal_np::vertex_normal_map);
    for(Vertex v : vertices(mesh))
      put(normals, v, get(given, v));
  }
  else
    CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals, np);

  // The vertices with a face and a defined normal, their positions and unit normals, in index order.
  struct Candidate
  {
    std::size_t index;
    Double_point position;
    Eigen::Vector3d normal;
  };
  std::vector<Candidate> candidates;
  for(Vertex v : vertices(mesh))
  {
    if(is_isolated_vertex(v, mesh))
    {
      ++result.summary.isolated_vertices;
      continue;
    }
    const std::size_t index = std::size_t(get(index_map, v));
    const Double_point position = checked_point(get(point_map, v), "vertex", index);
    Eigen::Vector3d normal;
    if(!unit_normal(get(normals, v), normal))
    {
      ++result.summary.undefined_normals;
      continue;
    }
    candidates.push_back(Candidate{index, position, normal});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.index < y.index; });
  std::vector<Double_point> positions;
  positions.reserve(candidates.size());
  for(const Candidate& c : candidates)
    positions.push_back(c.position);

  // Vertices at one position become the first of them in index order.
  const Merged_positions merged = merge_equal_positions(positions);
  result.summary.merged_duplicates = merged.merged;
  result.input.points.reserve(merged.first.size());
  result.input.normals.reserve(merged.first.size());
  for(std::size_t first : merged.first)
  {
    result.input.points.push_back(candidates[first].position);
    result.input.normals.push_back(candidates[first].normal);
  }
  for(std::size_t c = 0; c < candidates.size(); ++c)
    result.point_of_vertex[candidates[c].index] = std::uint32_t(merged.position_of[c]);
  result.point_in_vertex_order.reserve(result.summary.vertices);
  for(Vertex v : vertices(mesh))
    result.point_in_vertex_order.push_back(result.point_of_vertex[std::size_t(get(index_map, v))]);
  result.summary.points = result.input.points.size();
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_MESH_POINTS_H
