// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods filter-normals`: the normal voting tensor filter of Yadav et al. (2018) on
// one model, with the default ball neighborhoods or adaptive sizes (SPEC §7), as a point set.

#include "commands.h"
#include "filter_command.h"

#include "command_line.h"
#include "las_output.h"
#include "model_input.h"
#include "phase_times.h"
#include "ply_output.h"
#include "text_rows.h"

#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const FILTER_USAGE =
  "usage: sigmoid-neighborhoods filter-normals INPUT -o OUTPUT [--adaptive] [--iterations 50] [--cut-off 0.9]\n"
  "         [--eigenvalue-threshold 0.25] [--damping 3] [--radius R] [--size-range 10]\n"
  "         [--angle-tolerance 1e-6] [--threads N] [normals]\n"
  "  INPUT: a mesh (.off .obj .ply .stl) or a point set (.xyz .pwn .ply .las .laz; normals estimated when\n"
  "      absent)\n"
  "  OUTPUT: .xyz or .pwn (x y z nx ny nz, 17 significant digits), .ply (binary point cloud with normals),\n"
  "      .las (LAS 1.4: a LAS/LAZ input's records untouched, format 6 for other inputs, with the filtered\n"
  "      normal as extra bytes dimensions normal_x/y/z, float) or .laz (the same compressed)\n"
  "  --radius: the ball radius of the neighborhoods (default 5 times the mean distance to 12 neighbors)\n"
  "  --adaptive: every point picks its k in {k_i - R, ..., k_i + R} (R = --size-range) of least E_dim\n"
  "              with the cut-off weights, in every sweep (SPEC §7)\n";

int run_filter_normals(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT,
                       with_normal_options({"-o", "--output", "--iterations", "--cut-off", "--eigenvalue-threshold",
                                            "--damping", "--radius", "--size-range", "--angle-tolerance", "--threads"}),
                       with_normal_flags({"-h", "--help", "--adaptive"}), NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, FILTER_USAGE))
  {
    std::cout << NORMAL_USAGE;
    return EXIT_OK;
  }
  const auto input_and_output =
    one_input_and_output(args, "filter-normals", "OUTPUT (.xyz, .pwn, .ply, .las or .laz)");
  const std::string& input = input_and_output.first;
  const std::string& output = input_and_output.second;
  const std::string ext = SN::lower_case_extension(output);
  if(ext != "xyz" && ext != "pwn" && ext != "ply" && !is_las_output(output))
    throw Usage_error("unknown output format '" + (ext.empty() ? std::string("(no extension)") : "." + ext) +
                      "': expected .xyz, .pwn, .ply, .las or .laz");
  const Filter_options options = read_filter_options(args);
  const SN::Normal_options normal_options = read_normal_options(args);
  check_las_output(output, Las_output_points{input});

  Phase_times times;
  const SN::Oriented_point_set model =
    read_input(input, [&] { return SN::read_oriented_point_set(input, normal_options); });
  times.end_reading(model);
  std::vector<SN::Oriented_point_set::Vector_3> normals = model.normals;
  SN::Normal_filter_summary summary;
  try
  {
    summary = filter_point_normals(model.points, normals, options);
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(input + ": " + e.what());
  }
  times.end("filter");

  if(is_las_output(output))
    write_las_results(output, Las_output_points{input}, model, filtered_normal_results(normals), options.threads);
  else if(ext == "ply")
    write_file_atomically(output, [&](std::ofstream& out) { write_filtered_ply(out, model, normals); }, true);
  else
    write_file_atomically(output, [&](std::ofstream& out) { write_filtered_xyz(out, model, normals, options.threads); });
  times.end("writing");
  char line[256];
  std::snprintf(line, sizeof(line), "%u sweeps, radius %.6g, mean neighborhood %.1f points, %zu empty cones",
                summary.iterations, summary.radius, summary.mean_neighbors, summary.empty_cones);
  std::string text = line;
  if(options.adaptive)
  {
    std::snprintf(line, sizeof(line), ", adaptive: mean k %.1f, %zu fallbacks", summary.mean_selected_size,
                  summary.fallbacks);
    text += line;
  }
  std::snprintf(line, sizeof(line), ", %.2f s", times.total());
  std::cerr << input << ": " << model_description(model) << (options.line_angles ? ", line angles" : "") << ", "
            << text << line << " (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace

Filter_options read_filter_options(const Arguments& args)
{
  Filter_options o;
  o.iterations = args.get_unsigned("--iterations", o.iterations);
  o.cut_off = args.get_double("--cut-off", o.cut_off);
  if(!(o.cut_off >= -1. && o.cut_off <= 1.))
    throw Usage_error("--cut-off must lie in [-1, 1]");
  o.eigenvalue_threshold = args.get_double("--eigenvalue-threshold", o.eigenvalue_threshold);
  if(!std::isfinite(o.eigenvalue_threshold))
    throw Usage_error("--eigenvalue-threshold must be a finite number");
  o.damping = args.get_double("--damping", o.damping);
  if(!(o.damping >= 0. && std::isfinite(o.damping)))
    throw Usage_error("--damping must be finite and >= 0");
  o.radius = args.get_double("--radius", 0.);
  if(args.has("--radius") && !(o.radius > 0. && std::isfinite(o.radius)))
    throw Usage_error("--radius must be finite and > 0");
  o.adaptive = args.has("--adaptive");
  o.size_range = args.get_unsigned("--size-range", o.size_range);
  o.angle_tolerance = read_angle_tolerance(args, o.angle_tolerance);
  o.threads = read_threads(args);
  o.line_angles = read_line_angles(args);
  return o;
}

void write_filtered_xyz(std::ostream& out, const SN::Oriented_point_set& model,
                        const std::vector<SN::Oriented_point_set::Vector_3>& normals, unsigned int threads)
{
  write_text_rows(out, 0, normals.size(), threads, [&](Text_rows& rows, std::size_t i) {
    const auto& p = model.points[i];
    const auto& n = normals[i];
    rows.number(p.x()).put(' ').number(p.y()).put(' ').number(p.z()).put(' ');
    rows.number(n.x()).put(' ').number(n.y()).put(' ').number(n.z()).put('\n');
  });
}

Las_results filtered_normal_results(const std::vector<SN::Oriented_point_set::Vector_3>& normals)
{
  typedef Lidar_io::Las_extra_bytes_type Type;
  Las_results r;
  r.dimensions = {{"normal_x", "filtered unit normal, x", Type::FLOAT},
                  {"normal_y", "filtered unit normal, y", Type::FLOAT},
                  {"normal_z", "filtered unit normal, z", Type::FLOAT}};
  r.complete = [&normals](unsigned char* record, const Lidar_io::Las_output_layout& l, std::size_t i) {
    for(int c = 0; c < 3; ++c)
      Lidar_io::store_las_extra(record, l, std::size_t(c), normals[i][c]);
  };
  return r;
}

void write_filtered_ply(std::ostream& out, const SN::Oriented_point_set& model,
                        const std::vector<SN::Oriented_point_set::Vector_3>& normals)
{
  Ply_point_set ps(true);
  ps.reserve(normals.size());
  for(std::size_t i = 0; i < normals.size(); ++i)
    ps.insert(model.points[i], normals[i]);
  write_binary_ply(out, ps);
}

int run_filter_normals_command(int argc, char** argv) { return run_filter_normals(argc, argv); }

} // namespace sigmoid_tool
