// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods optimal`: the optimal (a, b, k) of every point of one model, as CSV, LAS or
// LAZ, and PLY.

#include "commands.h"
#include "optimal_command.h"

#include "catalog_input.h"
#include "command_line.h"
#include "las_output.h"
#include "model_input.h"
#include "phase_times.h"
#include "ply_output.h"
#include "text_rows.h"

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const OPTIMAL_USAGE =
  "usage: sigmoid-neighborhoods optimal INPUT|--catalog SOURCE [--tile NAME] -o OUT.csv|OUT.las|OUT.laz\n"
  "         [--ply OUT.ply] [--color error|label|none]"
  " [--k-min 6] [--k-max 20] [--a-grid ANGLES] [--b-grid ANGLES] [--barycenter weighted|unweighted]\n"
  "         [--angle-tolerance 1e-6] [--criterion dimensionality|eigenentropy] [--threads N] [normals]\n"
  "  INPUT: a mesh (.off .obj .ply .stl) or a point set (.xyz .pwn .ply .las .laz; normals estimated when\n"
  "      absent)\n"
  "  -o OUT.las: LAS 1.4, the input's LAS/LAZ records untouched (format 6 for other inputs) with the CSV's\n"
  "      columns as extra bytes dimensions (normal_x/y/z, a, b, error... float; k, label, k_equal integers);\n"
  "      OUT.laz: the same compressed as LASzip does (point formats 0-3 and 6-8); of a catalog's tile\n"
  "      (--tile NAME), its file's records (a seam duplicate's: the results of the earlier tile's point it\n"
  "      was merged into); of a catalog's union, refused\n"
  "  --ply: a binary PLY point cloud: the CSV's columns as properties scalar_<column> (CloudCompare's\n"
  "      scalar fields), quality = error and red green blue (MeshLab)\n"
  "  --criterion: what the search minimises, E_dim (dimensionality, the default) or the eigenentropy\n"
  "      of Weinmann et al.; the columns error and error_equal hold its values\n";

std::vector<SN::Optimal_sigmoid_neighborhood> optimal_search(const SN::Oriented_point_set& model,
                                                             const Search_options& o)
{
  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  records.reserve(model.points.size());
  with_model_neighborhoods(model, o, [&](const auto& np) {
    SN::compute_optimal_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(point_indices(model.points.size()),
                                                                             std::back_inserter(records), np);
  });
  return records;
}

// The rows of the points `first` ... `last - 1` (a tile without its halo), all by default, formatted
// on `threads` threads.
void write_optimal_csv(std::ostream& out, const SN::Oriented_point_set& model,
                       const std::vector<SN::Optimal_sigmoid_neighborhood>& records, unsigned int threads,
                       std::size_t first = 0, std::size_t last = std::size_t(-1))
{
  out << OPTIMAL_CSV_HEADER << '\n';
  write_text_rows(out, first, (std::min)(last, records.size()), threads, [&](Text_rows& rows, std::size_t i) {
    write_optimal_row(rows, model.points[i], model.normals[i], records[i]);
    rows.put('\n');
  });
}

// A binary PLY point cloud with the CSV's columns as per-vertex properties `scalar_<column>` (a, b
// and the features double, k and k_equal int, label uchar: 0 linear, 1 planar, 2 scattered,
// 3 degenerate; a failure has NaN a, b and features, k = 0 and error = inf), then `quality` and the
// colors of `colors` for the viewers without scalar fields.
void write_optimal_ply(std::ostream& out, const SN::Oriented_point_set& model,
                       const std::vector<SN::Optimal_sigmoid_neighborhood>& records, Ply_colors colors,
                       std::size_t first = 0, std::size_t last = std::size_t(-1))
{
  last = (std::min)(last, records.size());
  Ply_point_set ps(true);
  ps.reserve(last - first);
  auto a = add_ply_scalar<double>(ps, "a"), b = add_ply_scalar<double>(ps, "b");
  auto k = add_ply_scalar<std::int32_t>(ps, "k");
  auto error = add_ply_scalar<double>(ps, "error"), linearity = add_ply_scalar<double>(ps, "linearity"),
       planarity = add_ply_scalar<double>(ps, "planarity"), scattering = add_ply_scalar<double>(ps, "scattering");
  auto label = add_ply_scalar<std::uint8_t>(ps, "label");
  auto error_equal = add_ply_scalar<double>(ps, "error_equal");
  auto k_equal = add_ply_scalar<std::int32_t>(ps, "k_equal");
  Ply_viewer_properties viewer(ps, colors);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(std::size_t i = first; i < last; ++i)
  {
    const auto& r = records[i];
    auto it = ps.insert(model.points[i], model.normals[i]);
    a[*it] = r.a;
    b[*it] = r.b;
    k[*it] = std::int32_t(r.k);
    error[*it] = r.error();
    linearity[*it] = r.is_failure() ? nan : r.features.linearity;
    planarity[*it] = r.is_failure() ? nan : r.features.planarity;
    scattering[*it] = r.is_failure() ? nan : r.features.scattering;
    label[*it] = std::uint8_t(r.features.label);
    error_equal[*it] = r.error_equal;
    k_equal[*it] = std::int32_t(r.k_equal);
    viewer.set(*it, r.error(), r.features.label);
  }
  write_binary_ply(out, ps);
}

// The CSV's columns as extra bytes dimensions of the input's records (las_output.h): normals and
// the values float (single precision, as the viewers read them), k, label and k_equal integers of
// the fewest bytes that hold --k-max.
void write_optimal_las(const std::string& path, const Las_output_points& points, const SN::Oriented_point_set& model,
                       const std::vector<SN::Optimal_sigmoid_neighborhood>& records, const Search_options& o)
{
  typedef Lidar_io::Las_extra_bytes_type Type;
  const Type count = o.k_max <= 255 ? Type::UNSIGNED_CHAR : Type::UNSIGNED_SHORT;
  Las_results r;
  r.dimensions = {{"normal_x", "unit normal, x", Type::FLOAT},
                  {"normal_y", "unit normal, y", Type::FLOAT},
                  {"normal_z", "unit normal, z", Type::FLOAT},
                  {"a", "optimal sigmoid a, radians", Type::FLOAT},
                  {"b", "optimal sigmoid b, radians", Type::FLOAT},
                  {"k", "optimal neighbors (0: failure)", count},
                  {"error", "E_dim at the optimum", Type::FLOAT},
                  {"linearity", "linearity at the optimum", Type::FLOAT},
                  {"planarity", "planarity at the optimum", Type::FLOAT},
                  {"scattering", "scattering at the optimum", Type::FLOAT},
                  {"label", "0 lin. 1 plan. 2 scat. 3 degen.", Type::UNSIGNED_CHAR},
                  {"error_equal", "E_dim, equal weights", Type::FLOAT},
                  {"k_equal", "its neighbors (0: failure)", count}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.complete = [&](unsigned char* record, const Lidar_io::Las_output_layout& l, std::size_t i) {
    const auto& n = model.normals[i];
    const auto& q = records[i];
    const bool failed = q.is_failure();
    const double values[] = {n.x(), n.y(), n.z(), q.a, q.b, double(q.k), q.error(),
                             failed ? nan : q.features.linearity, failed ? nan : q.features.planarity,
                             failed ? nan : q.features.scattering, double(q.features.label), q.error_equal,
                             double(q.k_equal)};
    for(std::size_t j = 0; j < l.added.size(); ++j)
      Lidar_io::store_las_extra(record, l, j, values[j]);
  };
  write_las_results(path, points, model, r, o.threads);
}

int run_optimal(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT,
                       with_catalog_options(with_normal_options(
                         {"-o", "--output", "--ply", "--color", "--k-min", "--k-max", "--a-grid", "--b-grid",
                          "--barycenter", "--angle-tolerance", "--criterion", "--threads"})),
                       with_normal_flags({"-h", "--help"}), NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, OPTIMAL_USAGE))
  {
    std::cout << GRID_USAGE << COLOR_USAGE << NORMAL_USAGE << CATALOG_USAGE;
    return EXIT_OK;
  }
  const std::string csv = args.output();
  if(csv.empty())
    throw Usage_error("optimal needs -o OUT.csv, OUT.las or OUT.laz");
  const std::string ply = args.get("--ply");
  const bool las_output = is_las_output(csv);
  refuse_las_output_of_catalog(args, "optimal");
  Search_options options = read_search_options(args);
  try
  {
    options.criterion = SN::criterion_from_name(args.get("--criterion", "dimensionality"));
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(std::string("--criterion: ") + e.what());
  }
  const Ply_colors colors = read_ply_colors(args);
  const SN::Normal_options normal_options = read_normal_options(args);

  Phase_times times;
  const Input_points in = read_input_points(args, "optimal", options.k_max, normal_options);
  if(las_output)
    check_las_output(csv, las_output_points(in));
  times.end_reading(in.model);
  const SN::Oriented_point_set& model = in.model;
  // a tile without points of its own (empty, or all on an earlier tile's seam) has no rows
  const auto records =
    in.first < in.last ? optimal_search(model, options) : std::vector<SN::Optimal_sigmoid_neighborhood>();
  times.end("search");
  std::size_t failures = 0;
  for(std::size_t i = in.first; i < in.last; ++i)
    failures += records[i].is_failure();

  if(las_output)
    write_optimal_las(csv, las_output_points(in), model, records, options);
  else
    write_file_atomically(csv, [&](std::ofstream& out) {
      write_optimal_csv(out, model, records, options.threads, in.first, in.last);
    });
  if(!ply.empty())
    write_file_atomically(
      ply, [&](std::ofstream& out) { write_optimal_ply(out, model, records, colors, in.first, in.last); }, true);
  times.end("writing");
  write_tile_description(csv, "optimal", args, in, times);
  char seconds[32];
  std::snprintf(seconds, sizeof(seconds), "%.2f", times.total());
  std::cerr << in.source << ": " << model_description(model) << halo_description(in)
            << (options.line_angles ? ", line angles" : "")
            << (options.criterion != SN::Neighborhood_criterion::DIMENSIONALITY
                  ? std::string(", criterion ") + SN::criterion_name(options.criterion) : std::string())
            << ", "
            << failures << " failures, " << seconds << " s (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace

Search_options read_search_options(const Arguments& args)
{
  Search_options o;
  o.k_min = args.get_unsigned("--k-min", o.k_min);
  o.k_max = args.get_unsigned("--k-max", o.k_max);
  if(o.k_min < 1 || o.k_min > o.k_max)
    throw Usage_error("needs 1 <= --k-min <= --k-max");
  const std::string bary = args.get("--barycenter", "weighted");
  try
  {
    o.barycenter = SN::barycenter_from_name(bary);
  }
  catch(const std::invalid_argument&)
  {
    throw Usage_error("--barycenter must be weighted or unweighted, got '" + bary + "'");
  }
  o.angle_tolerance = read_angle_tolerance(args, o.angle_tolerance);
  o.threads = read_threads(args);
  o.line_angles = read_line_angles(args);
  o.a_grid = read_angle_list(args, "--a-grid", o.a_grid);
  o.b_grid = read_angle_list(args, "--b-grid", o.b_grid);
  if(o.a_grid.front() > o.b_grid.back())
    throw Usage_error("--a-grid and --b-grid have no pair with a <= b");
  return o;
}

int run_optimal_command(int argc, char** argv) { return run_optimal(argc, argv); }

} // namespace sigmoid_tool
