// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_NORMAL_OPTIONS_H
#define SIGMOID_NEIGHBORHOODS_READERS_NORMAL_OPTIONS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Origin.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  the number of neighbors of the normal estimation and orientation of `read_oriented_point_set()`
  for point sets without normals (the value of CGAL's normal estimation examples).
*/
constexpr unsigned int DEFAULT_ESTIMATION_NEIGHBORS = 18;

/*!
  where the normals of `read_oriented_point_set()` come from.
*/
enum class Normal_source
{
  AUTO,      ///< the file's (a mesh's vertex normals, a point set's `nx ny nz`), estimated when it has none
  FROM_FILE, ///< the file's; a file without normals is an error
  PCA,       ///< estimated by `estimate_normals()` with `Normal_estimation_method::PCA`, the file's ignored
  JET        ///< estimated by `estimate_normals()` with `Normal_estimation_method::JET`, the file's ignored
};

/*!
  how `read_oriented_point_set()` orients the normals it estimates.
*/
enum class Normal_orientation
{
  SPANNING_FOREST, ///< `orient_normals_by_spanning_forest()`: every connected component from its highest point
  VIEWPOINT,       ///< `orient_normals_towards_viewpoint()`: every normal towards `Normal_options::viewpoint`
  UPWARD,          ///< every normal towards `+z` (`n_z >= 0`), as an airborne scanner sees the surfaces
  NONE             ///< as estimated: signs arbitrary (for the named parameter `line_angles`)
};

/*!
  the name of a source on the command line and in Python: `auto`, `file`, `pca` or `jet`.
*/
inline const char* normal_source_name(Normal_source s)
{
  return s == Normal_source::FROM_FILE ? "file"
         : s == Normal_source::PCA     ? "pca"
         : s == Normal_source::JET     ? "jet"
                                       : "auto";
}

/*!
  the source named `name` (`auto`, `file`, `pca` or `jet`).
  \throws std::invalid_argument for any other name
*/
inline Normal_source normal_source_from_name(const std::string& name)
{
  for(Normal_source s : {Normal_source::AUTO, Normal_source::FROM_FILE, Normal_source::PCA, Normal_source::JET})
    if(name == normal_source_name(s))
      return s;
  throw std::invalid_argument("unknown normals '" + name + "': expected auto, file, pca or jet");
}

/*!
  the name of an orientation on the command line and in Python: `mst`, `viewpoint`, `up` or `none`.
*/
inline const char* normal_orientation_name(Normal_orientation o)
{
  return o == Normal_orientation::SPANNING_FOREST ? "mst"
         : o == Normal_orientation::VIEWPOINT     ? "viewpoint"
         : o == Normal_orientation::UPWARD        ? "up"
                                                   : "none";
}

/*!
  the orientation named `name` (`mst`, `viewpoint`, `up` or `none`).
  \throws std::invalid_argument for any other name
*/
inline Normal_orientation normal_orientation_from_name(const std::string& name)
{
  for(Normal_orientation o : {Normal_orientation::SPANNING_FOREST, Normal_orientation::VIEWPOINT,
                              Normal_orientation::UPWARD, Normal_orientation::NONE})
    if(name == normal_orientation_name(o))
      return o;
  throw std::invalid_argument("unknown orientation '" + name + "': expected mst, viewpoint, up or none");
}

/*!
  the normals of `read_oriented_point_set()`: their source, the estimation and the orientation.
*/
struct Normal_options
{
  Normal_source source = Normal_source::AUTO; ///< where the normals come from
  /// the `k` of the estimation and of the spanning forest; 0 with `Normal_source::AUTO`: a file without
  /// normals comes back without normals
  unsigned int neighbors = DEFAULT_ESTIMATION_NEIGHBORS;
  Normal_orientation orientation = Normal_orientation::SPANNING_FOREST; ///< of estimated normals
  Exact_predicates_inexact_constructions_kernel::Point_3 viewpoint = ORIGIN; ///< for `Normal_orientation::VIEWPOINT`
  /// when normals are estimated, the k-nearest-neighbor rows of `max(neighbors, kept_neighbors)` are
  /// kept in `Oriented_point_set::neighbor_indices` for the steps after (0: none kept)
  unsigned int kept_neighbors = 0;
  /// the threads of the readers (LAZ chunks, PLY point sets, XYZ, OFF, OBJ), of a mesh's check and
  /// normals, and of the estimation (0: the OpenMP or TBB default)
  unsigned int threads = 0;  /// the search structure of the estimation's neighbor rows (the same rows with either)
  Neighbor_search neighbor_search = Neighbor_search::CGAL_KD_TREE;
};

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_NORMAL_OPTIONS_H
