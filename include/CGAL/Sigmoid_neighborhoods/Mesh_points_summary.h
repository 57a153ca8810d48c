// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_MESH_POINTS_SUMMARY_H
#define CGAL_SIGMOID_NEIGHBORHOODS_MESH_POINTS_SUMMARY_H

#include <cstddef>

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

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_MESH_POINTS_SUMMARY_H
