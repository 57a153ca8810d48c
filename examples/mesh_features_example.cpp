// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Per-vertex optimal neighborhoods of a Surface_mesh, and the features of one fixed sigmoid,
// stored as vertex property maps.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/compute_sigmoid_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SN = CGAL::Sigmoid_neighborhoods;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "usage: " << argv[0] << " MESH (OFF, PLY, OBJ, STL)" << std::endl;
    return EXIT_FAILURE;
  }

  // The optimal (a*, b*, k*) per vertex; vertex normals are computed by CGAL.
  auto optimal = mesh.add_property_map<Mesh::Vertex_index, SN::Optimal_sigmoid_neighborhood>("v:optimal").first;
  const SN::Mesh_points_summary summary =
    SN::compute_optimal_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(mesh, optimal);

  // The sharp cut-off of a dot-product threshold 0.9, with k = 12.
  auto cut_off = mesh.add_property_map<Mesh::Vertex_index, SN::Dimensionality_features>("v:cut_off").first;
  const double threshold = std::acos(0.9);
  SN::compute_sigmoid_features<SN::Parallel_if_available_tag>(mesh, SN::Cosine_sigmoid(threshold, threshold), 12,
                                                               cut_off);

  const char* const names[] = {"linear", "planar", "scattered", "degenerate"}; // the order of SN::Dimensionality
  std::map<std::string, std::size_t> labels;
  std::size_t cut_off_failures = 0;
  for(Mesh::Vertex_index v : mesh.vertices())
  {
    ++labels[names[int(optimal[v].features.label)]];
    cut_off_failures += cut_off[v].is_degenerate();
  }
  std::cout << summary.points << " points from " << summary.vertices << " vertices ("
            << summary.merged_duplicates << " merged, " << summary.dropped_vertices() << " dropped)\n";
  for(const auto& l : labels)
    std::cout << l.first << ": " << l.second << "\n";
  std::cout << "degenerate with the cut-off a = b = arccos(0.9), k = 12: " << cut_off_failures << std::endl;
  return EXIT_SUCCESS;
}
