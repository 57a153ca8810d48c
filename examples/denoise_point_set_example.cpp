// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point-set denoising (Yadav et al. 2018, the three stages) of a noisy cube mesh: its vertices move in
// place, its faces stay; measured by the distance of the vertices to the noise-free cube.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_masks_3.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/compute_mean_neighbor_distance.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SN = CGAL::Sigmoid_neighborhoods;
namespace PMP = CGAL::Polygon_mesh_processing;

// The cube [-1, 1]^3, each face cut into 16 x 16 squares by CGAL's linear subdivision and each
// square into two triangles: 1,538 vertices.
void make_cube(Mesh& mesh)
{
  CGAL::make_hexahedron(Point(-1, -1, -1), Point(1, -1, -1), Point(1, 1, -1), Point(-1, 1, -1), Point(-1, 1, 1),
                        Point(-1, -1, 1), Point(1, -1, 1), Point(1, 1, 1), mesh);
  if(!PMP::is_outward_oriented(mesh))
    PMP::reverse_face_orientations(mesh);
  CGAL::Subdivision_method_3::PQQ(mesh, CGAL::Linear_mask_3<Mesh>(&mesh, get(CGAL::vertex_point, mesh)),
                                  CGAL::parameters::number_of_iterations(4));
  PMP::triangulate_faces(mesh);
}

// Gaussian noise along the unit normals: p <- p + e n, e ~ N(0, sd^2), one draw per vertex in order.
template <typename NormalMap>
void add_normal_noise(Mesh& mesh, const NormalMap& normals, double sd)
{
  std::mt19937_64 engine(1);
  std::normal_distribution<double> offset(0., sd);
  for(Mesh::Vertex_index v : mesh.vertices())
    mesh.point(v) = mesh.point(v) + offset(engine) * normals[v];
}

// The distance of p to the surface of the cube [-1, 1]^3.
double cube_distance(const Point& p)
{
  const double x = std::abs(p.x()), y = std::abs(p.y()), z = std::abs(p.z());
  const double largest = (std::max)({x, y, z});
  if(largest <= 1.)
    return 1. - largest;
  const double dx = (std::max)(x - 1., 0.), dy = (std::max)(y - 1., 0.), dz = (std::max)(z - 1., 0.);
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double mean_distance(const Mesh& mesh)
{
  double sum = 0.;
  for(auto v : mesh.vertices())
    sum += cube_distance(mesh.point(v));
  return sum / double(mesh.number_of_vertices());
}

int main(int argc, char** argv)
{
  Mesh mesh;
  make_cube(mesh);
  auto normals = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:normal").first;
  PMP::compute_vertex_normals(mesh, normals);

  // Gaussian noise along the normals, sd = 0.3 l (l: mean distance to the 6 nearest neighbors).
  const double l = SN::compute_mean_neighbor_distance<SN::Parallel_if_available_tag>(
    mesh.vertices(), 6, CGAL::parameters::point_map(mesh.points()));
  add_normal_noise(mesh, normals, 0.3 * l);
  const double before = mean_distance(mesh);
  const std::size_t faces = mesh.number_of_faces();

  // The authors' defaults; the input normals are the noisy mesh's vertex normals.
  const SN::Point_set_denoising_summary s = SN::denoise_point_set<SN::Parallel_if_available_tag>(mesh);
  const double after = mean_distance(mesh);
  std::cout << s.points << " points, " << s.iterations << " iterations (noise level " << s.noise_estimate / l
            << " l), " << s.planar << " planar, " << s.edges << " edges, " << s.corners << " corners\n"
            << "mean distance to the cube: noisy " << before / l << " l, denoised " << after / l << " l" << std::endl;
  if(argc > 1)
  {
    std::ofstream out(argv[1]);
    out.precision(17);
    CGAL::IO::write_OFF(out, mesh);
  }
  const bool ok = after < 0.6 * before && mesh.number_of_faces() == faces;
  std::cout << (ok ? "denoising brings the points closer to the cube" : "denoising did not help") << std::endl;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
