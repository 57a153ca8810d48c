// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The generated models of the paper's Table 4: a cube and an octahedron cut into small triangles.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_SUBDIVIDED_POLYHEDRA_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_SUBDIVIDED_POLYHEDRA_H

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

namespace subdivision {

// Points of shared edges are computed from the same integers on every face, so equal points are
// bitwise equal (up to the sign of zero) and CGAL's soup repair merges them.
template <typename PolygonMesh, typename Point>
void soup_to_mesh(std::vector<Point>& points, std::vector<std::vector<std::size_t>>& faces, PolygonMesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::merge_duplicate_points_in_polygon_soup(points, faces);
  PMP::polygon_soup_to_polygon_mesh(points, faces, mesh);
}

template <typename PolygonMesh>
using Mesh_point_t = typename boost::property_traits<
  typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;

} // namespace subdivision

/*
  adds to `mesh` the surface of the cube `[-1, 1]^3`, each face cut into `m x m` squares
  and each square into two triangles (the same diagonal everywhere), outward oriented:
  `6 m^2 + 2` vertices and `12 m^2` triangles. `m = 18` gives 1,946 vertices, the nearest to the
  1,906 of the cube of Yadav et al. (2018).
  \tparam PolygonMesh a model of `MutableFaceGraph` with an internal point property map
  \pre `m >= 1`; otherwise `std::invalid_argument`
*/
template <typename PolygonMesh>
void make_subdivided_cube(unsigned int m, PolygonMesh& mesh)
{
  typedef subdivision::Mesh_point_t<PolygonMesh> Point;
  if(m < 1)
    throw std::invalid_argument("make_subdivided_cube(): needs m >= 1");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  auto coordinate = [m](unsigned int i) { return double(2 * int(i) - int(m)) / double(m); };
  for(int axis = 0; axis < 3; ++axis)
    for(int sign = -1; sign <= 1; sign += 2)
    {
      // (u, v, axis) is a right-handed frame for sign = +1; swapped for sign = -1: outward faces.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if(sign < 0)
        std::swap(u, v);
      const std::size_t first = points.size();
      for(unsigned int j = 0; j <= m; ++j)
        for(unsigned int i = 0; i <= m; ++i)
        {
          std::array<double, 3> c;
          c[axis] = double(sign);
          c[u] = coordinate(i);
          c[v] = coordinate(j);
          points.emplace_back(c[0], c[1], c[2]);
        }
      auto index = [first, m](unsigned int i, unsigned int j) { return first + std::size_t(j) * (m + 1) + i; };
      for(unsigned int j = 0; j < m; ++j)
        for(unsigned int i = 0; i < m; ++i)
        {
          faces.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
          faces.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    }
  subdivision::soup_to_mesh(points, faces, mesh);
}

/*
  adds to `mesh` the surface of the octahedron `|x| + |y| + |z| = 1`, each face cut into
  `m^2` equal triangles, outward oriented: `4 m^2 + 2` vertices and `8 m^2` triangles. `m = 64`
  gives 16,386 vertices, the nearest to the 16,395 of the octahedron of Yadav et al. (2018).
  \tparam PolygonMesh a model of `MutableFaceGraph` with an internal point property map
  \pre `m >= 1`; otherwise `std::invalid_argument`
*/
template <typename PolygonMesh>
void make_subdivided_octahedron(unsigned int m, PolygonMesh& mesh)
{
  typedef subdivision::Mesh_point_t<PolygonMesh> Point;
  if(m < 1)
    throw std::invalid_argument("make_subdivided_octahedron(): needs m >= 1");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  for(int sx = -1; sx <= 1; sx += 2)
    for(int sy = -1; sy <= 1; sy += 2)
      for(int sz = -1; sz <= 1; sz += 2)
      {
        // Barycentric lattice (i, j, m - i - j) / m on the face with corners sx e_x, sy e_y, sz e_z.
        std::vector<std::vector<std::size_t>> index(m + 1);
        for(unsigned int i = 0; i <= m; ++i)
          for(unsigned int j = 0; i + j <= m; ++j)
          {
            index[i].push_back(points.size());
            points.emplace_back(sx * (double(i) / m), sy * (double(j) / m), sz * (double(m - i - j) / m));
          }
        // (i, j) -> (i + 1, j) -> (i, j + 1) is outward on the face (+, +, +); a face whose
        // signs multiply to -1 is its mirror image, with reversed triangles.
        const bool reversed = sx * sy * sz < 0;
        auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
          faces.push_back(reversed ? std::vector<std::size_t>{a, c, b} : std::vector<std::size_t>{a, b, c});
        };
        for(unsigned int i = 0; i < m; ++i)
          for(unsigned int j = 0; i + j < m; ++j)
          {
            add(index[i][j], index[i + 1][j], index[i][j + 1]);
            if(i + j + 1 < m)
              add(index[i + 1][j], index[i + 1][j + 1], index[i][j + 1]);
          }
      }
  subdivision::soup_to_mesh(points, faces, mesh);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_SUBDIVIDED_POLYHEDRA_H
