// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What `sigmoid-neighborhoods filter-normals` (filter_command.cpp) shares with denoise and the
// Table 4 experiment: the filter's options, the filter on a point set, the filtered outputs.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_FILTER_COMMAND_H
#define SIGMOID_NEIGHBORHOODS_TOOL_FILTER_COMMAND_H

#include "command_line.h"
#include "las_output.h"
#include "optimal_command.h"
#include "phase_times.h"
#include "ply_output.h"
#include "text_rows.h"

#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>


#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace sigmoid_tool {

struct Filter_options
{
  unsigned int iterations = SN::defaults::FILTER_ITERATIONS;
  double cut_off = SN::defaults::NORMAL_CUT_OFF;
  double eigenvalue_threshold = SN::defaults::EIGENVALUE_THRESHOLD;
  double damping = SN::defaults::DAMPING_FACTOR;
  double radius = 0.; // 0: the default 5 m
  bool adaptive = false;
  unsigned int size_range = SN::defaults::NEIGHBORHOOD_SIZE_RANGE;
  double angle_tolerance = SN::defaults::ANGLE_TOLERANCE;
  unsigned int threads = 0; // 0: OpenMP's default
  bool line_angles = false;
};

// Filters `normals` (one per point of `points`) in place.
template <typename Point, typename Vector>
SN::Normal_filter_summary filter_point_normals(const std::vector<Point>& points, std::vector<Vector>& normals,
                                               const Filter_options& o)
{
  namespace SNP = SN::parameters;
  std::vector<std::uint32_t> indices = point_indices(points.size()); // filter_normals() takes a mutable range
  return SN::filter_normals<SN::Parallel_if_available_tag>(
    indices,
    SNP::line_angles(o.line_angles, SNP::number_of_threads(o.threads, SNP::normal_cut_off(o.cut_off, SNP::eigenvalue_threshold(o.eigenvalue_threshold,
      SNP::damping_factor(o.damping, SNP::adaptive_neighborhood_size(o.adaptive,
        SNP::neighborhood_size_range(o.size_range, SNP::angle_tolerance(o.angle_tolerance,
          CGAL::parameters::number_of_iterations(o.iterations)
            .neighbor_radius(o.radius)
            .point_map(CGAL::make_property_map(points))
            .normal_map(CGAL::make_property_map(normals)))))))))));
}

// The options of filter-normals that denoise shares.
Filter_options read_filter_options(const Arguments& args);

// x y z nx ny nz rows, 17 significant digits, formatted on `threads` threads.
void write_filtered_xyz(std::ostream& out, const SN::Oriented_point_set& model,
                        const std::vector<SN::Oriented_point_set::Vector_3>& normals, unsigned int threads);

// The filtered normals as LAS extra bytes dimensions (las_output.h), after whatever else `complete`
// writes into a record (denoise: the moved coordinates). The result refers to `normals`.
Las_results filtered_normal_results(const std::vector<SN::Oriented_point_set::Vector_3>& normals);

// Positions and the filtered normals only: the filter has no per-point value to show.
void write_filtered_ply(std::ostream& out, const SN::Oriented_point_set& model,
                        const std::vector<SN::Oriented_point_set::Vector_3>& normals);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_FILTER_COMMAND_H
