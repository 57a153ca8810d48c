// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods denoise-comparison`: the package's denoiser against CGAL's smoothing on
// noisy CAD models (experiments/denoising_comparison.h), as a Markdown table, a CSV and a figure.

#include "command_line.h"
#include "commands.h"
#include "denoise_options.h"
#include "experiments/denoising_comparison.h"
#include "experiments/table4_data.h"
#include "experiments/table4_experiment.h"
#include "tool_paths.h"
#include <CGAL/Sigmoid_neighborhoods/compute_mean_neighbor_distance.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const DENOISE_COMPARISON_USAGE =
  "usage: sigmoid-neighborhoods denoise-comparison [MODELS...] -o DIR [--noise 0.3,0.6] [--seed 1]\n"
  "         [--data DIR] [--fandisk FILE] [--figure-model NAME] [--fixed-iterations N,...] [--threads N]\n"
  "  MODELS: names (cube octahedron fandisk sharp_sphere rockerarm fertility bearing: as denoise-experiment;\n"
  "          yadav_fandisk: Yadav et al.'s noisy fandisk against the clean one, both in --data DIR) or mesh\n"
  "          files; default: cube octahedron fandisk sharp_sphere rockerarm fertility yadav_fandisk and the CAD\n"
  "          models of CGAL's data and ../shared/data/clean that exist (see the manual)\n"
  "  every model gets noise of each level (sd in units of l, the mean distance to 6 neighbors) along its\n"
  "  normals and isotropically, PCA normals on 12 neighbors oriented like the clean ones, then: the\n"
  "  package's denoise_point_set (defaults; the plane update; adaptive; (a*, b*) vote; in place; the authors' stage 3), CGAL's jet_smooth_point_set (k 18) and\n"
  "  bilateral_smooth_point_set (k 18, sharpness 25 degrees, 3 iterations)\n"
  "  --fixed-iterations: references, the package's defaults without the stopping rule after each of these\n"
  "          iteration counts (not ranked, not drawn: what the best stopping rule could give)\n"
  "  writes DIR/denoising.md, DIR/denoising.csv, DIR/denoising_points.csv and DIR/denoising.png\n";

// The CAD models of the default run beyond the named ones: files that exist are used.
std::vector<std::string> default_cad_models(const std::string& fandisk_folder)
{
  std::vector<std::string> files;
  namespace fs = std::filesystem;
  std::error_code ec;
  for(const char* name : {"anchor.off", "joint.off", "couplingdown.off"})
  {
    const fs::path file = fs::path(fandisk_folder) / name;
    if(!fandisk_folder.empty() && fs::exists(file, ec))
      files.push_back(file.string());
  }
  const std::string shared = tool_paths::shared_data();
  for(const char* name : {"clean/gd_block.obj", "clean/trimesh_ADIS16480.STL", "clean/trimesh_featuretype.STL"})
  {
    const fs::path file = fs::path(shared) / name;
    if(!shared.empty() && fs::exists(file, ec))
      files.push_back(file.string());
  }
  return files;
}

struct Comparison_row
{
  std::string model, noise;
  double level = 0., spacing = 0.;
  std::size_t points = 0;
  std::vector<Method_result> methods;
};

const char* noise_name(Noise_direction d) { return d == Noise_direction::NORMAL ? "normal" : "isotropic"; }

// The clean positions and normals of a mesh's vertices; a vertex without a defined normal is an error.
void clean_vertices(const Denoise_mesh& mesh, std::vector<Denoise_point>& points,
                           std::vector<Denoise_vector>& normals, const std::string& name)
{
  auto normal_map = get(CGAL::dynamic_vertex_property_t<Denoise_vector>(), mesh);
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normal_map);
  for(auto v : mesh.vertices())
  {
    points.push_back(mesh.point(v));
    normals.push_back(get(normal_map, v));
    if(!(normals.back().squared_length() > 0.))
      throw Usage_error(name + ": vertex " + std::to_string(std::size_t(v)) + " has no defined normal");
  }
}

void write_comparison_table(std::ostream& out, const std::vector<Comparison_row>& rows,
                                   const std::vector<std::pair<std::string, std::string>>& sources)
{
  out << "# Point-set denoising: the package against CGAL's smoothing\n\n"
      << "Distances of the points to the clean surface (CGAL's `AABB_tree`), mean / RMS, in units of `l` "
         "(the model's mean distance to 6 neighbors); the normal MSE `(1/n) sum |n_i - m_i|^2` against the clean "
         "vertex normals (– where a method gives no normals); the time in seconds. The best mean distance of a row "
         "is in bold.\n\n"
      << "Settings: noise of standard deviation `level * l`, along the clean normals or isotropic (that deviation "
         "on each axis); initial normals by PCA on 12 neighbors, each turned to agree with the clean normal. "
         "*package*: `denoise_point_set()` with its defaults (at most 50 iterations, cut-off 0.9, tau 0.25, "
         "alpha 0.1, smooth points onto their jets, stopped at the estimated noise level); *plane update*: the same "
         "with `jet_vertex_update(false)`, every planar point towards the weighted mean plane; *adaptive*: the same with "
         "`adaptive_neighborhood_size(true)`; *(a\\*, b\\*) vote*: the same with `optimal_vote_weights(true)`, "
         "stage 1's votes weighted by each point's optimal sigmoid; *in place*: the same with `in_place_updates(true)` (the authors' "
         "Gauss-Seidel order); *authors' stage 3*: `authors_vertex_update(true)` and `rank_threshold(0)`, the "
         "authors' vertex update; *jet*: `jet_smooth_point_set()`, k = 18; *bilateral*: "
         "`bilateral_smooth_point_set()`, k = 18, sharpness angle 25 degrees, 3 iterations.";
  for(const auto& m : rows.front().methods)
    if(m.reference)
    {
      out << " *package, N iterations*: the defaults without the stopping rule, N iterations: references "
             "(what the best stopping rule could give), not ranked.";
      break;
    }
  out << "\n\n";
  const std::vector<Method_result>& first = rows.front().methods;
  out << "| model | noise | points |";
  for(const auto& m : first)
    out << ' ' << m.method << " |";
  out << " normal MSE (";
  bool first_name = true;
  for(const auto& m : first)
    if(m.normal_mse >= 0.)
    {
      out << (first_name ? "" : "; ") << m.method;
      first_name = false;
    }
  out << ") | seconds (";
  for(std::size_t i = 1; i < first.size(); ++i)
    out << (i == 1 ? "" : "; ") << first[i].method;
  out << ") |\n|---|---|---:|";
  for(std::size_t i = 0; i < first.size(); ++i)
    out << "---:|";
  out << "---|---|\n";
  auto fixed = [](double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
  };
  for(const auto& r : rows)
  {
    std::size_t best = 1;
    for(std::size_t i = 1; i < r.methods.size(); ++i)
      if(!r.methods[i].reference && r.methods[i].mean_distance < r.methods[best].mean_distance)
        best = i;
    out << "| " << r.model << " | " << r.noise << " | " << r.points << " |";
    for(std::size_t i = 0; i < r.methods.size(); ++i)
    {
      const std::string text = fixed(r.methods[i].mean_distance / r.spacing, 4) + " / " +
                               fixed(r.methods[i].rms_distance / r.spacing, 4);
      out << ' ' << (i == best ? "**" + text + "**" : text) << " |";
    }
    out << ' ';
    bool first_value = true;
    for(const auto& m : r.methods)
      if(m.normal_mse >= 0.)
      {
        out << (first_value ? "" : "; ") << fixed(m.normal_mse, 4);
        first_value = false;
      }
    out << " | ";
    for(std::size_t i = 1; i < r.methods.size(); ++i)
      out << (i == 1 ? "" : "; ") << fixed(r.methods[i].seconds, 2);
    out << " |\n";
  }
  out << "\n## Models\n\n";
  for(const auto& s : sources)
    out << "- " << s.first << ": " << s.second << '\n';
}

void write_comparison_csv(std::ostream& out, const std::vector<Comparison_row>& rows)
{
  out << "model,noise,level,spacing,points,method,mean_distance,rms_distance,normal_mse,seconds,note,max_distance\n";
  for(const auto& r : rows)
    for(const auto& m : r.methods)
    {
      out << '"' << r.model << "\",\"" << r.noise << "\"," << number17(r.level) << ',' << number17(r.spacing) << ','
          << r.points << ",\"" << m.method << "\"," << number17(m.mean_distance) << ',' << number17(m.rms_distance) << ',';
      if(m.normal_mse >= 0.)
        out << number17(m.normal_mse);
      out << ',' << number17(m.seconds) << ",\"" << m.note << "\"," << number17(m.max_distance) << '\n';
    }
}

struct Comparison_options
{
  std::string output, data_dir, fandisk, figure_model;
  std::vector<double> levels;
  std::uint64_t seed = 1;
  unsigned int threads = 0;
  std::vector<unsigned int> fixed_iterations;
  std::vector<std::string> names;
};

Comparison_options comparison_options(const Arguments& args)
{
  Comparison_options o;
  o.output = args.get("-o", args.get("--output", ""));
  if(o.output.empty())
    throw Usage_error("needs -o DIR\n" + std::string(DENOISE_COMPARISON_USAGE));
  o.levels = parse_noise_levels(args.get("--noise", "0.3,0.6"));
  o.seed = parse_seed(args.get("--seed", "1"));
  o.data_dir = args.get("--data", default_application_data());
  o.fandisk = args.get("--fandisk", "");
  o.threads = read_threads(args);
  if(args.has("--fixed-iterations"))
    o.fixed_iterations = parse_iteration_counts(args.get("--fixed-iterations"));
  o.names = args.positional();
  if(o.names.empty())
  {
    o.names = {"cube", "octahedron", "fandisk", "sharp_sphere", "rockerarm", "fertility", "yadav_fandisk"};
    const std::string cgal_fandisk = o.fandisk.empty() ? std::string(tool_paths::default_fandisk()) : o.fandisk;
    for(const auto& f : default_cad_models(std::filesystem::path(cgal_fandisk).parent_path().string()))
      o.names.push_back(f);
  }
  o.figure_model = args.get("--figure-model", o.names.front());
  return o;
}

struct Comparison_model
{
  std::string name, title;
  Denoise_mesh mesh;
  std::vector<Denoise_point> noisy_reference; // yadav_fandisk: the authors' noisy vertices
};

// Yadav et al.'s noisy fandisk and the clean one, vertex for vertex, from `data_dir`; false (with
// `absent` saying why) when either file is missing.
bool load_yadav_fandisk(const std::string& data_dir, Comparison_model& l, std::string& source, std::string& absent)
{
  namespace fs = std::filesystem;
  const fs::path clean = fs::path(data_dir) / "fandisk.obj";
  const fs::path noisy = fs::path(data_dir) / "noisy_reference" / "fandisk_lowNoise.obj";
  std::error_code ec;
  if(!fs::exists(clean, ec) || !fs::exists(noisy, ec))
  {
    absent = "absent: no fandisk.obj and noisy_reference/fandisk_lowNoise.obj in " + data_dir;
    return false;
  }
  Denoise_mesh noisy_mesh;
  read_input(clean.string(), [&] { SN::read_polygon_mesh(clean.string(), l.mesh); return true; });
  read_input(noisy.string(), [&] { SN::read_polygon_mesh(noisy.string(), noisy_mesh); return true; });
  if(noisy_mesh.number_of_vertices() != l.mesh.number_of_vertices())
    throw Usage_error(noisy.string() + ": not vertex for vertex with " + clean.string());
  for(auto v : noisy_mesh.vertices())
    l.noisy_reference.push_back(noisy_mesh.point(v));
  source = noisy.string() + " against " + clean.string();
  return true;
}

// Every model read before anything runs: a bad file stops the run before anything is written.
std::vector<Comparison_model> load_comparison_models(const Comparison_options& o,
                                                     std::vector<std::pair<std::string, std::string>>& sources)
{
  std::vector<Comparison_model> models;
  for(const auto& name : o.names)
  {
    Comparison_model l;
    l.name = name;
    std::string source, absent;
    bool loaded = false;
    if(name == "yadav_fandisk")
    {
      loaded = load_yadav_fandisk(o.data_dir, l, source, absent);
      l.title = "Fandisk (Yadav et al.'s noise)";
    }
    else
    {
      loaded = read_input(name, [&] { return load_denoise_mesh(name, o.data_dir, o.fandisk, l.mesh, source, absent); });
      l.title = find_table4_model(name) ? find_table4_model(name)->title : std::filesystem::path(name).stem().string();
    }
    if(!loaded)
    {
      std::cerr << "denoise-comparison: " << name << " skipped: " << absent << '\n';
      continue;
    }
    sources.emplace_back(l.title, source + " (" + std::to_string(l.mesh.number_of_vertices()) + " vertices)");
    models.push_back(std::move(l));
  }
  if(models.empty())
    throw Usage_error("no model to run");
  return models;
}

// The noisy copies of a model: the authors' own, or each level along the normals and isotropically.
struct Noise_case
{
  std::string name;
  double level;
  std::vector<Denoise_point> points;
};

std::vector<Noise_case> noise_cases(const Comparison_model& l, const std::vector<Denoise_point>& clean,
                                    const std::vector<Denoise_vector>& truth, double spacing,
                                    const Comparison_options& o)
{
  std::vector<Noise_case> cases;
  if(!l.noisy_reference.empty())
  {
    cases.push_back({"Yadav et al.'s", 0., l.noisy_reference});
    return cases;
  }
  for(Noise_direction direction : {Noise_direction::NORMAL, Noise_direction::ISOTROPIC})
    for(double level : o.levels)
    {
      std::ostringstream noise;
      noise << level << " l " << noise_name(direction);
      cases.push_back({noise.str(), level, noisy_points(clean, truth, level * spacing, direction, o.seed)});
    }
  return cases;
}

// The figure's points: every method's output points with their distances (units of l).
std::string figure_points_text(const Comparison_row& row)
{
  std::ostringstream text;
  text << "method,x,y,z,distance\n";
  for(const auto& m : row.methods)
    for(std::size_t i = 0; i < (m.reference ? 0 : m.points.size()); ++i)
      text << '"' << m.method << "\"," << number17(m.points[i].x()) << ',' << number17(m.points[i].y()) << ','
           << number17(m.points[i].z()) << ',' << number17(m.distances[i] / row.spacing) << '\n';
  return text.str();
}

// One model's rows: every noisy copy denoised by every method; the figure's points of its first
// copy when it is the figure's model.
void compare_model(const Comparison_model& l, const Comparison_options& o, std::vector<Comparison_row>& rows,
                   std::string& figure_text, std::string& figure_title)
{
  std::vector<Denoise_point> clean;
  std::vector<Denoise_vector> truth;
  clean_vertices(l.mesh, clean, truth, l.name);
  const Surface_distance surface(l.mesh);
  double spacing = 0.;
  try
  {
    spacing = SN::compute_mean_neighbor_distance<SN::Parallel_if_available_tag>(
      clean, SPACING_NEIGHBORS, SN::parameters::number_of_threads(o.threads));
  }
  catch(const std::invalid_argument& e)
  {
    throw Usage_error(l.name + ": " + e.what());
  }
  const std::vector<Noise_case> cases = noise_cases(l, clean, truth, spacing, o);
  for(std::size_t c = 0; c < cases.size(); ++c)
  {
    Comparison_row row;
    row.model = l.title;
    row.noise = cases[c].name;
    row.level = cases[c].level;
    row.spacing = spacing;
    row.points = clean.size();
    try
    {
      row.methods = compare_denoisers(with_pca_normals(cases[c].points, truth, o.threads), truth, surface, o.threads,
                                      o.fixed_iterations);
    }
    catch(const std::invalid_argument& e)
    {
      throw Usage_error(l.name + ": " + e.what());
    }
    std::cerr << "denoise-comparison: " << row.model << ", " << row.noise << ": mean distance / l";
    for(const auto& m : row.methods)
      std::cerr << ", " << m.method << ' ' << std::setprecision(3) << m.mean_distance / spacing;
    std::cerr << '\n';
    if(l.name == o.figure_model && c == 0)
    {
      figure_text = figure_points_text(row);
      figure_title = row.model + ", noise " + row.noise;
    }
    rows.push_back(std::move(row));
  }
}

} // namespace

int run_denoise_comparison_command(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT,
                       {"-o", "--output", "--noise", "--seed", "--data", "--fandisk", "--figure-model",
                        "--fixed-iterations", "--threads"},
                       {"-h", "--help"});
  if(print_help(args, DENOISE_COMPARISON_USAGE))
    return EXIT_OK;
  const Comparison_options o = comparison_options(args);
  std::vector<std::pair<std::string, std::string>> sources;
  const std::vector<Comparison_model> models = load_comparison_models(o, sources);

  std::vector<Comparison_row> rows;
  std::string figure_text, figure_title;
  for(const auto& l : models)
    compare_model(l, o, rows, figure_text, figure_title);

  create_output_folder(o.output);
  const std::filesystem::path dir(o.output);
  write_file_atomically((dir / "denoising.md").string(),
                        [&](std::ofstream& out) { write_comparison_table(out, rows, sources); });
  write_file_atomically((dir / "denoising.csv").string(), [&](std::ofstream& out) { write_comparison_csv(out, rows); });
  if(!figure_text.empty())
  {
    const std::string points_file = (dir / "denoising_points.csv").string();
    write_file_atomically(points_file, [&](std::ofstream& out) { out << figure_text; });
    if(!run_python_script("plot_denoising.py", {points_file, (dir / "denoising.png").string(), "--title", figure_title}))
      std::cerr << "denoise-comparison: no figure (python3 with matplotlib is needed)\n";
  }
  std::cerr << "denoise-comparison: " << rows.size() << " rows in " << (dir / "denoising.md").string() << '\n';
  return EXIT_OK;
}

} // namespace sigmoid_tool
