// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods denoise`: Yadav et al.'s three-stage denoising of a point set or of a
// mesh's vertices (denoise_point_set()).

#include "command_line.h"
#include "commands.h"
#include "filter_command.h"
#include "las_output.h"
#include "model_input.h"
#include "phase_times.h"
#include "ply_output.h"

#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <Sigmoid_neighborhoods_readers/read_polygon_mesh.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/IO/STL.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {


const char* const DENOISE_POINT_SET_USAGE =
  "usage: sigmoid-neighborhoods denoise INPUT -o OUTPUT [--adaptive] [--iterations 50] [--cut-off 0.9]\n"
  "         [--eigenvalue-threshold 0.25] [--damping 3] [--radius R] [--size-range 10] [--step 0.1]\n"
  "         [--max-deviation E] [--weight-radius R] [--rank-threshold 0.1] [--authors-update] [--no-stop]\n"
  "         [--in-place] [--optimal-vote] [--threads N] [normals]\n"
  "  Yadav et al. 2018: per iteration, normal filtering, corner/edge/planar classification, vertex update\n"
  "  INPUT: a mesh (.off .obj .ply .stl) or a point set (.xyz .pwn .ply; normals estimated when absent)\n"
  "  OUTPUT: .xyz or .pwn (x y z nx ny nz), .ply (binary point cloud with normals); for a mesh INPUT\n"
  "          also .off, .obj or .stl, and .ply is then the mesh: vertices moved, faces kept (the input\n"
  "          normals are then the mesh's vertex normals, whatever --normals says); .las: LAS 1.4, a LAS/LAZ\n"
  "          input's records with their coordinates moved (rounded to its scale) and the normals as extra\n"
  "          bytes normal_x/y/z (format 6 records for other inputs); .laz: the same compressed\n"
  "  --iterations: at most this many (default 50); they stop when the points have moved by the noise\n"
  "                level estimated from the input (--no-stop: all of them)\n"
  "  --step: the step alpha towards each rule's target; --max-deviation: a move farther than E from the\n"
  "          input position is refused (default 2 m, m the mean distance to 12 neighbors)\n"
  "  --weight-radius: r of the planar weights exp(-4 |p_j - p_i|^2 / r^2) (default 2 m)\n"
  "  --rank-threshold: edge and corner solves drop directions of relative eigenvalue below it (0: none)\n"
  "  --authors-update: stage 3 as the authors' code (unweighted metrics, full steps, normal term in r)\n"
  "  --in-place: stages 2 and 3 update in place in input order (the authors' Gauss-Seidel), one thread\n"
  "  --adaptive: every point picks its k in {k_i - R, ..., k_i + R} of least E_dim (SPEC §7)\n"
  "  --optimal-vote: stage 1's votes weighted by each point's optimal sigmoid (a*, b*) (beyond the paper)\n"
  "  --plane-update: smooth patches too move towards their neighbors' tangent planes (by default they move\n"
  "                  onto a quadric fitted to their neighbors, beyond the paper)\n";

typedef CGAL::Surface_mesh<SN::Oriented_point_set::Point_3> Denoise_tool_mesh;

bool is_mesh_format(const std::string& ext) { return ext == "off" || ext == "obj" || ext == "stl"; }

// Prints "denoise: iteration i/p" over itself on a terminal; nothing otherwise.
class Iteration_progress
{
public:
  explicit Iteration_progress(std::string input) : m_input(std::move(input)), m_terminal(::isatty(STDERR_FILENO)) {}
  bool operator()(double fraction) const
  {
    if(m_terminal)
      std::cerr << '\r' << m_input << ": denoising, " << int(100. * fraction + 0.5) << " %" << std::flush;
    return true;
  }
  void clear() const
  {
    if(m_terminal)
      std::cerr << '\r' << std::string(m_input.size() + 24, ' ') << '\r';
  }

private:
  std::string m_input;
  bool m_terminal;
};

template <typename NamedParameters>
auto denoising_parameters(const Filter_options& f, const Arguments& args, const NamedParameters& np)
{
  namespace SNP = SN::parameters;
  return SNP::jet_vertex_update(!args.has("--plane-update"),
    SNP::step_size(args.get_double("--step", SN::defaults::PLANAR_STEP_SIZE),
    SNP::maximum_deviation(args.get_double("--max-deviation", 0.),
    SNP::rank_threshold(args.get_double("--rank-threshold", SN::defaults::RANK_THRESHOLD),
    SNP::planar_weight_radius(args.get_double("--weight-radius", 0.),
    SNP::authors_vertex_update(args.has("--authors-update"),
    SNP::stop_at_noise_level(!args.has("--no-stop"),
    SNP::in_place_updates(args.has("--in-place"),
    SNP::optimal_vote_weights(args.has("--optimal-vote"),
    SNP::line_angles(f.line_angles, SNP::number_of_threads(f.threads, SNP::normal_cut_off(f.cut_off,
    SNP::eigenvalue_threshold(f.eigenvalue_threshold, SNP::damping_factor(f.damping,
    SNP::adaptive_neighborhood_size(f.adaptive, SNP::neighborhood_size_range(f.size_range,
    SNP::angle_tolerance(f.angle_tolerance,
      np.number_of_iterations(f.iterations).neighbor_radius(f.radius))))))))))))))))));
}

std::string denoising_summary_text(const SN::Point_set_denoising_summary& s)
{
  char line[512];
  std::snprintf(line, sizeof(line),
                "%u iterations%s, noise level %.3g, classes %zu planar %zu edges %zu corners, %zu moves refused, "
                "%zu rank-deficient solves, mean displacement %.3g (largest %.3g)",
                s.iterations,
                s.stopped_at_noise_level ? " (stopped at the noise level)" : (s.interrupted ? " (interrupted)" : ""),
                s.noise_estimate, s.planar, s.edges, s.corners, s.refused, s.rank_deficient, s.mean_displacement,
                s.largest_displacement);
  return line;
}

void check_denoising_arguments(const Arguments& args)
{
  const double step = args.get_double("--step", SN::defaults::PLANAR_STEP_SIZE);
  if(!(step >= 0. && std::isfinite(step)))
    throw Usage_error("--step must be finite and >= 0");
  const double deviation = args.get_double("--max-deviation", 0.);
  if(args.has("--max-deviation") && !(deviation > 0. && std::isfinite(deviation)))
    throw Usage_error("--max-deviation must be finite and > 0");
  const double weight_radius = args.get_double("--weight-radius", 0.);
  if(args.has("--weight-radius") && !(weight_radius > 0. && std::isfinite(weight_radius)))
    throw Usage_error("--weight-radius must be finite and > 0");
  const double rank = args.get_double("--rank-threshold", SN::defaults::RANK_THRESHOLD);
  if(!(rank >= 0. && rank <= 1.))
    throw Usage_error("--rank-threshold must lie in [0, 1]");
}

// The denoised points as LAS (las_output.h): a LAS/LAZ input's records, their coordinates moved to
// their point's denoised position at the file's scale, its filtered normal as extra bytes.
void write_denoised_las(const std::string& path, const std::string& input, const SN::Oriented_point_set& denoised,
                               const std::vector<SN::Oriented_point_set::Vector_3>& normals, unsigned int threads)
{
  Las_results r = filtered_normal_results(normals);
  r.complete = [&denoised, store_normals = r.complete](unsigned char* record, const Lidar_io::Las_output_layout& l,
                                                       std::size_t i) {
    const auto& p = denoised.points[i];
    Lidar_io::store_las_coordinates(record, l, {{p.x(), p.y(), p.z()}});
    store_normals(record, l, i);
  };
  write_las_results(path, Las_output_points{input}, denoised, r, threads);
}

// Writes `mesh` as OFF, OBJ, STL or binary PLY (by `ext`), atomically.
void write_denoised_mesh(const std::string& output, const std::string& ext, const Denoise_tool_mesh& mesh)
{
  write_file_atomically(output, [&](std::ofstream& out) {
    const auto precision = CGAL::parameters::stream_precision(17);
    bool written = false;
    if(ext == "ply")
    {
      CGAL::IO::set_binary_mode(out);
      written = CGAL::IO::write_PLY(out, mesh, precision);
    }
    else if(ext == "obj")
      written = CGAL::IO::write_OBJ(out, mesh, precision);
    else if(ext == "stl")
      written = CGAL::IO::write_STL(out, mesh, precision);
    else
      written = CGAL::IO::write_OFF(out, mesh, precision);
    if(!written)
      throw Usage_error("cannot write " + output);
  }, ext == "ply");
}

// What one denoising run reads and writes.
struct Denoise_files
{
  std::string input, output, ext;
};

// A mesh written as a mesh: its vertices move, its faces stay. Returns the input's description.
std::string denoise_mesh_file(const Denoise_files& files, const Filter_options& options, const Arguments& args,
                              const Iteration_progress& progress, Phase_times& times,
                              SN::Point_set_denoising_summary& summary)
{
  Denoise_tool_mesh mesh;
  read_input(files.input, [&] {
    SN::read_polygon_mesh(files.input, mesh);
    return true;
  });
  try
  {
    summary = SN::denoise_point_set<SN::Parallel_if_available_tag>(
      mesh, denoising_parameters(options, args, CGAL::parameters::callback(std::cref(progress))));
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(files.input + ": " + e.what());
  }
  progress.clear();
  times.end("denoising");
  write_denoised_mesh(files.output, files.ext, mesh);
  return std::to_string(mesh.number_of_vertices()) + " vertices (mesh vertex normals, " +
         std::to_string(summary.mesh.merged_duplicates) + " merged duplicates)";
}

// The points of `model` denoised and written as XYZ, PLY or LAS. Returns the input's description.
std::string denoise_point_file(const SN::Oriented_point_set& model, const Denoise_files& files,
                               const Filter_options& options, const Arguments& args,
                               const Iteration_progress& progress, Phase_times& times,
                               SN::Point_set_denoising_summary& summary)
{
  std::vector<SN::Oriented_point_set::Point_3> points = model.points;
  std::vector<SN::Oriented_point_set::Vector_3> normals = model.normals;
  std::vector<std::uint32_t> indices = point_indices(points.size());
  try
  {
    summary = SN::denoise_point_set<SN::Parallel_if_available_tag>(
      indices, denoising_parameters(options, args, CGAL::parameters::callback(std::cref(progress))
                                                     .point_map(CGAL::make_property_map(points))
                                                     .normal_map(CGAL::make_property_map(normals))));
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(files.input + ": " + e.what());
  }
  progress.clear();
  times.end("denoising");
  SN::Oriented_point_set denoised = model;
  denoised.points = points;
  const std::string& output = files.output;
  if(is_las_output(output))
    write_denoised_las(output, files.input, denoised, normals, options.threads);
  else if(files.ext == "ply")
    write_file_atomically(output, [&](std::ofstream& out) { write_filtered_ply(out, denoised, normals); }, true);
  else
    write_file_atomically(output, [&](std::ofstream& out) { write_filtered_xyz(out, denoised, normals, options.threads); });
  return model_description(model);
}

} // namespace

int run_denoise_command(int argc, char** argv)
{
  const Arguments args(
    argc, argv, FIRST_COMMAND_ARGUMENT,
    with_normal_options({"-o", "--output", "--iterations", "--cut-off", "--eigenvalue-threshold", "--damping", "--radius",
                         "--size-range", "--angle-tolerance", "--threads", "--step", "--max-deviation",
                         "--rank-threshold", "--weight-radius"}),
    with_normal_flags({"-h", "--help", "--adaptive", "--authors-update", "--no-stop", "--in-place", "--optimal-vote",
                       "--plane-update"}),
    NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, DENOISE_POINT_SET_USAGE))
  {
    std::cout << NORMAL_USAGE;
    return EXIT_OK;
  }
  const auto input_and_output =
    one_input_and_output(args, "denoise", "OUTPUT (.xyz, .pwn, .ply, .las, .laz, or for a mesh .off, .obj, .stl)");
  const Denoise_files files{input_and_output.first, input_and_output.second,
                            SN::lower_case_extension(input_and_output.second)};
  const std::string& ext = files.ext;
  if(ext != "xyz" && ext != "pwn" && ext != "ply" && !is_las_output(files.output) && !is_mesh_format(ext))
    throw Usage_error("unknown output format '" + (ext.empty() ? std::string("(no extension)") : "." + ext) +
                      "': expected .xyz, .pwn, .ply, .las, .laz, .off, .obj or .stl");
  const Filter_options options = read_filter_options(args);
  check_denoising_arguments(args);
  const SN::Normal_options normal_options = read_normal_options(args);
  check_las_output(files.output, Las_output_points{files.input});
  const Iteration_progress progress(files.input);

  Phase_times times;
  SN::Point_set_denoising_summary summary;
  const SN::Oriented_point_set model =
    read_input(files.input, [&] { return SN::read_oriented_point_set(files.input, normal_options); });
  times.end_reading(model);
  if(is_mesh_format(ext) && !model.is_mesh)
    throw Usage_error(files.input + ": a point set cannot be written as a mesh (." + ext + "): use .xyz, .pwn or .ply");
  const std::string description =
    model.is_mesh && ext != "xyz" && ext != "pwn" && !is_las_output(files.output)
      ? denoise_mesh_file(files, options, args, progress, times, summary)
      : denoise_point_file(model, files, options, args, progress, times, summary);
  times.end("writing");
  char seconds[64];
  std::snprintf(seconds, sizeof(seconds), ", %.2f s", times.total());
  std::cerr << files.input << ": " << description << (options.adaptive ? ", adaptive" : "") << ", "
            << denoising_summary_text(summary) << seconds << " (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace sigmoid_tool
