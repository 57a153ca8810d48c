// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What `sigmoid-neighborhoods optimal` (optimal_command.cpp) shares with evaluate, report, filter-normals,
// the classification's features and the fuzz target: the search options and the optimal CSV's row.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_OPTIMAL_COMMAND_H
#define SIGMOID_NEIGHBORHOODS_TOOL_OPTIMAL_COMMAND_H

#include "catalog_input.h"
#include "command_line.h"
#include "model_input.h"
#include "phase_times.h"
#include "las_output.h"
#include "ply_output.h"
#include "text_rows.h"

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;

inline const char* GRID_USAGE =
  "  --a-grid, --b-grid: the search grids of a and b (default 0,30deg,60deg,...,180deg), comma-separated\n"
  "      angles in [0, pi], radians (1.5, pi) or degrees (30deg); --a-grid pi --b-grid pi is the\n"
  "      equal-weights search alone (the optimal k of Weinmann et al.)\n";

struct Search_options
{
  unsigned int k_min = SN::defaults::K_MIN, k_max = SN::defaults::K_MAX;
  SN::Barycenter barycenter = SN::Barycenter::WEIGHTED;
  double angle_tolerance = SN::defaults::ANGLE_TOLERANCE;
  unsigned int threads = 0; // 0: OpenMP's default
  bool line_angles = false;
  SN::Neighborhood_criterion criterion = SN::Neighborhood_criterion::DIMENSIONALITY; // --criterion: optimal only
  std::vector<double> a_grid = SN::defaults::angle_grid(), b_grid = SN::defaults::angle_grid();
};

// The search options of --k-min, --k-max, --barycenter, --angle-tolerance, --threads, the line angles
// and the grids (not --criterion: optimal's alone).
Search_options read_search_options(const Arguments& args);

// CGAL's point and normal maps over the points of `model`, indexed by point_indices().
inline auto model_maps(const SN::Oriented_point_set& model)
{
  return CGAL::parameters::point_map(CGAL::make_property_map(model.points))
    .normal_map(CGAL::make_property_map(model.normals));
}

// The named parameters of `o` on top of the pack `np` (ours first, CGAL's after).
template <typename NamedParameters>
auto with_search_options(const Search_options& o, const NamedParameters& np)
{
  namespace SNP = SN::parameters;
  return SNP::criterion(o.criterion, SNP::line_angles(o.line_angles, SNP::number_of_threads(o.threads, SNP::k_min(o.k_min, SNP::k_max(o.k_max,
    SNP::a_grid(o.a_grid, SNP::b_grid(o.b_grid,
      SNP::barycenter(o.barycenter, SNP::angle_tolerance(o.angle_tolerance, np)))))))));
}

// Runs `search(np)` with the model's maps and the search options, and with the model's neighbor
// rows when its normal estimation kept them (one neighbor structure for both steps).
template <typename Search>
void with_model_neighborhoods(const SN::Oriented_point_set& model, const Search_options& o, const Search& search)
{
  namespace SNP = SN::parameters;
  if(model.neighbor_offsets.empty())
    search(with_search_options(o, model_maps(model)));
  else
    search(with_search_options(o, SNP::neighbor_indices(std::cref(model.neighbor_indices),
                                                        SNP::neighbor_offsets(std::cref(model.neighbor_offsets),
                                                                              model_maps(model)))));
}

const char* const OPTIMAL_CSV_HEADER =
  "x,y,z,nx,ny,nz,a,b,k,error,linearity,planarity,scattering,label,error_equal,k_equal";

// One row of the optimal CSV, without the line end (inline: the fuzz target compiles it without the
// commands' library).
inline void write_optimal_row(Text_rows& out, const SN::Oriented_point_set::Point_3& p,
                              const SN::Oriented_point_set::Vector_3& n, const SN::Optimal_sigmoid_neighborhood& r)
{
  for(double v : {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()})
    out.number(v).put(',');
  if(r.is_failure())
    out.text(",,,");
  else
    out.number(r.a).put(',').number(r.b).put(',').integer(r.k).put(',');
  out.number(r.error()).put(',');
  if(!r.is_failure())
    for(double v : {r.features.linearity, r.features.planarity, r.features.scattering})
      out.number(v).put(',');
  else
    out.text(",,,");
  out.text(SN::dimensionality_name(r.features.label)).put(',').number(r.error_equal).put(',');
  if(r.k_equal != 0)
    out.integer(r.k_equal);
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_OPTIMAL_COMMAND_H
