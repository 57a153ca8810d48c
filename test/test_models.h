// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small synthetic models for the tests.

#ifndef SN_TEST_MODELS_H
#define SN_TEST_MODELS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/property_map.h>

#include <array>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;

// Oriented points as (point, normal) pairs, with their property maps.
typedef std::pair<Point_3, Vector_3> Point_with_normal;
typedef std::vector<Point_with_normal> Point_list;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

inline auto maps() { return CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); }

// Equal to the last bit (and 0 and -0 told apart): what "bit for bit" tests compare.
inline bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof(double)) == 0; }

// The surface of [0, n]^3 (scaled by `scale`), each face an n x n grid of squares cut in two
// triangles, oriented outwards: flat faces, sharp edges and corners.
inline Mesh make_grid_cube(int n, double scale = 1.)
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::map<std::array<int, 3>, std::size_t> index;
  auto vertex = [&](std::array<int, 3> c) {
    auto it = index.find(c);
    if(it != index.end())
      return it->second;
    index.emplace(c, points.size());
    points.emplace_back(scale * c[0], scale * c[1], scale * c[2]);
    return points.size() - 1;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      // (u, v, axis) is right-handed; on the low side swap u and v to point outwards
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if(side == 0)
        std::swap(u, v);
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          auto at = [&](int di, int dj) {
            std::array<int, 3> c;
            c[axis] = side * n;
            c[u] = i + di;
            c[v] = j + dj;
            return vertex(c);
          };
          triangles.push_back({at(0, 0), at(1, 0), at(1, 1)});
          triangles.push_back({at(0, 0), at(1, 1), at(0, 1)});
        }
    }
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

#endif // SN_TEST_MODELS_H
