// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_ORIENTED_POINT_SET_H
#define SIGMOID_NEIGHBORHOODS_READERS_ORIENTED_POINT_SET_H

#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  a point set with oriented unit normals read from a file, and how it was obtained (SPEC §1).
  Returned by `read_oriented_point_set()`; its `points` and `normals` go to
  `compute_optimal_sigmoid_neighborhoods()` with `CGAL::make_property_map()` maps over the indices
  `0, ..., points.size() - 1`, as the command-line tool does.
*/
struct Oriented_point_set
{
  /// the kernel of the points and normals
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  /// the point type
  typedef Kernel::Point_3 Point_3;
  /// the normal type
  typedef Kernel::Vector_3 Vector_3;

  std::vector<Point_3> points;   ///< distinct points, in input order
  std::vector<Vector_3> normals; ///< unit normals, one per point
  /// per-point labels, one per point when the file has them (LAS classification, PLY `label`/`class`/
  /// `classification` property), else empty
  std::vector<int> labels;
  std::vector<std::uint16_t> intensities;       ///< LAS intensities, one per point; empty unless LAS
  std::vector<std::uint8_t> return_numbers;     ///< LAS return numbers, one per point; empty unless LAS
  std::vector<std::uint8_t> numbers_of_returns; ///< LAS numbers of returns, one per point; empty unless LAS
  /// LAS GPS times, one per point in the point data formats that have them (all but 0 and 2), else empty
  std::vector<double> gps_times;
  bool is_mesh = false;                 ///< read from faces; normals are vertex normals unless estimated
  bool normals_estimated = false;       ///< estimated by `estimate_normals()` (`Normal_options`)
  Normal_estimation_method estimation_method = defaults::NORMAL_ESTIMATION_METHOD; ///< when estimated
  unsigned int estimation_neighbors = 0;  ///< the `k` of the estimation and orientation, when estimated
  Normal_orientation orientation = Normal_orientation::NONE; ///< of estimated normals
  std::size_t orientation_components = 0; ///< the trees of `Normal_orientation::SPANNING_FOREST`
  /// points whose normal in the file is zero, with `Normal_source::AUTO`: all of them when every normal
  /// is zero (a file without normals: `normals_estimated`), else those estimated and oriented to agree
  /// with their neighbors' normals (SPEC §1)
  std::size_t zero_normals = 0;
  std::size_t input_vertices = 0;       ///< vertices or points in the file
  std::size_t merged_duplicates = 0;    ///< merged into an earlier point at the same position
  /// per point of the file, the index in `points` of its position, when `merged_duplicates` is not 0
  /// (a point set read from a file); else empty: the file's point `i` is `points[i]` (a LAS writer
  /// gives each record of the file the results of its point)
  std::vector<std::size_t> point_of_input;
  std::size_t dropped_vertices = 0;     ///< mesh vertices without a face or with an undefined normal
  /// the k-nearest-neighbor rows of the estimation (`Normal_options::kept_neighbors`), for the named
  /// parameters `neighbor_indices` and `neighbor_offsets` of the steps after; empty when none kept
  std::vector<std::uint32_t> neighbor_indices;
  std::vector<std::size_t> neighbor_offsets; ///< see `neighbor_indices`

  /// the wall-clock seconds of the steps of the normal estimation, zero where a step did not run
  /// (the rest of a reader's time is the reading itself: parsing, checks, merging)
  struct Step_seconds
  {
    double neighbor_rows = 0.;     ///< the k-nearest-neighbor rows (the kd-tree and its queries)
    double normal_estimation = 0.; ///< the fitting of the normals (PCA or jet)
    double orientation = 0.;       ///< their orientation (`Normal_orientation`)
  };
  Step_seconds seconds; ///< see `Step_seconds`
};

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_ORIENTED_POINT_SET_H
