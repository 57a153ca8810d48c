// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods denoise-experiment`: the paper's Table 4 (Section 5.5, SPEC §7). Noise along
// the normals of clean meshes, then the normal filter of Yadav et al. (2018) with its default
// neighborhoods and with adaptive sizes; the MSE of the normals against the noise-free ones.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_DENOISE_COMMAND_H
#define SIGMOID_NEIGHBORHOODS_TOOL_DENOISE_COMMAND_H

#include "command_line.h"
#include "filter_command.h"
#include "report_command.h"

#include <CGAL/Sigmoid_neighborhoods/denoising_utilities.h>
#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>
#include <CGAL/Sigmoid_neighborhoods/subdivided_polyhedra.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/pca_estimate_normals.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#ifndef SIGMOID_NEIGHBORHOODS_SCRIPT_DIR
#define SIGMOID_NEIGHBORHOODS_SCRIPT_DIR "."
#endif

namespace sigmoid_tool {

inline const char* DENOISE_USAGE =
  "usage: sigmoid-neighborhoods denoise-experiment [MODELS...] -o DIR [--noise 0.3,0.6] [--seed 1]\n"
  "         [--data DIR] [--fandisk FILE] [--figure-model NAME] [--noisy-normals mesh|pca] [--threads N]\n"
  "  MODELS: cube bearing fandisk sharp_sphere fertility octahedron rockerarm (default: all seven), or mesh\n"
  "          files (filtered with p = 50, cut-off 0.9, eigenvalue threshold 0.25)\n"
  "  cube, octahedron: generated (1,946 and 16,386 vertices); fandisk: --fandisk FILE, else libcgal-demo's;\n"
  "  the others: NAME.off/.obj/.ply/.stl in --data DIR (default ../shared/data/application), skipped if absent\n"
  "  --noise: noise levels, sd in units of l (mean distance to the 6 nearest neighbors)\n"
  "  --noisy-normals: the filter's input normals, vertex normals of the noisy mesh (default) or PCA over\n"
  "                   12 neighbors oriented like the noise-free normals\n"
  "  writes DIR/table4.md, DIR/table4.csv, DIR/normal_error_MODEL.csv and .png, DIR/timings.csv\n";

typedef SN::Oriented_point_set::Kernel Denoise_kernel;
typedef Denoise_kernel::Point_3 Denoise_point;
typedef Denoise_kernel::Vector_3 Denoise_vector;
typedef CGAL::Surface_mesh<Denoise_point> Denoise_mesh;

// A model of Table 4 with the paper's (p, cut-off, eigenvalue threshold) and its published MSEs.
struct Denoise_model
{
  std::string name;    // command-line name, file stem
  std::string title;   // as in the paper
  unsigned int iterations;
  double cut_off, eigenvalue_threshold;
  std::size_t paper_vertices;
  // MSE(Noise), MSE(Yadav et al.), MSE(ours) at 0.3 l, then at 0.6 l
  double paper[6];
};

// SPEC §7: the larger number of each pair is the cut-off, the smaller the eigenvalue threshold.
inline const std::vector<Denoise_model>& table4_models()
{
  static const std::vector<Denoise_model> models = {
    {"cube", "Cube", 150, 0.95, 0.3, 1906,
     {0.018171157, 0.004720763, 0.003817538, 0.067785183, 0.041014649, 0.017185731}},
    {"bearing", "Bearing", 100, 0.9, 0.25, 3475,
     {0.019149792, 0.092202990, 0.06311642, 0.087963467, 0.105885719, 0.099716185}},
    {"fandisk", "Fandisk", 150, 0.9, 0.3, 6475,
     {0.015985698, 0.047105692, 0.033043562, 0.059076477, 0.067027229, 0.052858261}},
    {"sharp_sphere", "Sharp Sphere", 100, 0.9, 0.25, 8354,
     {0.033954089, 0.152198571, 0.124993406, 0.091947551, 0.162334741, 0.143099697}},
    {"fertility", "Fertility", 100, 0.9, 0.25, 9239,
     {0.134043694, 0.220368116, 0.197418828, 0.232151395, 0.25364564, 0.25100736}},
    {"octahedron", "Octahedron", 80, 0.9, 0.25, 16395,
     {0.287851891, 0.282346769, 0.275334065, 0.304714745, 0.277547626, 0.271626537}},
    {"rockerarm", "Rockerarm", 80, 0.9, 0.25, 24106,
     {0.017150895, 0.081370198, 0.067150116, 0.063687905, 0.084070141, 0.078171864}}};
  return models;
}

constexpr unsigned int GENERATED_CUBE_SUBDIVISIONS = 18;       // 1,946 vertices
constexpr unsigned int GENERATED_OCTAHEDRON_SUBDIVISIONS = 64; // 16,386 vertices
constexpr unsigned int SPACING_NEIGHBORS = 6;                  // l of SPEC §7
constexpr unsigned int PCA_NEIGHBORS = 12;                     // the authors' initial normals

struct Denoise_options
{
  std::vector<double> noise{0.3, 0.6};
  std::uint64_t seed = 1;
  std::string data_dir, fandisk, figure_model, output;
  bool pca_normals = false;
  int threads = 0;
};

// One (model, noise level) of the table.
struct Denoise_result
{
  std::string model, title;
  std::size_t points = 0;
  double level = 0., spacing = 0., sigma = 0.;
  unsigned int iterations = 0;
  double cut_off = 0., eigenvalue_threshold = 0.;
  double mse_noise = 0., mse_default = 0., mse_adaptive = 0.;
  SN::Normal_filter_summary default_summary, adaptive_summary;
  const Denoise_model* paper = nullptr; // for the paper's figures, when this level is 0.3 or 0.6
  int paper_level = -1;                 // 0 for 0.3 l, 1 for 0.6 l
  double seconds_default = 0., seconds_adaptive = 0.;
  std::vector<double> error_noise, error_default, error_adaptive; // per point
};

inline std::vector<double> parse_noise_levels(const std::string& text)
{
  std::vector<double> levels;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if(item.empty() || *end != '\0' || !(v > 0.) || !std::isfinite(v))
      throw Usage_error("--noise needs positive numbers separated by commas, got '" + text + "'");
    levels.push_back(v);
  }
  if(levels.empty())
    throw Usage_error("--noise needs at least one level");
  return levels;
}

inline std::string find_tool_script(const std::string& name)
{
  std::vector<fs::path> candidates;
  if(const char* env = std::getenv("SIGMOID_NEIGHBORHOODS_SCRIPTS"))
    candidates.push_back(fs::path(env) / name);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if(!ec)
    candidates.push_back(exe.parent_path().parent_path() / "share" / "sigmoid-neighborhoods" / name);
  candidates.push_back(fs::path(SIGMOID_NEIGHBORHOODS_SCRIPT_DIR) / name);
  for(const auto& c : candidates)
    if(fs::exists(c, ec))
      return c.string();
  throw Usage_error("cannot find " + name + " (set SIGMOID_NEIGHBORHOODS_SCRIPTS)");
}

inline std::string default_application_data()
{
  if(const char* env = std::getenv("SIGMOID_NEIGHBORHOODS_APPLICATION_DATA"))
    return env;
  return (fs::path(SIGMOID_NEIGHBORHOODS_SCRIPT_DIR) / ".." / ".." / ".." / "shared" / "data" / "application")
    .lexically_normal()
    .string();
}

// Reads a mesh; isolated vertices are removed, every vertex must have a defined normal.
inline void read_denoise_mesh(const std::string& path, Denoise_mesh& mesh)
{
  std::error_code ec;
  if(!fs::is_regular_file(path, ec))
    throw SN::Input_error("no such file");
  bool read;
  {
    SN::internal::Captured_cerr captured;
    read = CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path, mesh);
  }
  if(!read || mesh.is_empty() || mesh.number_of_faces() == 0)
    throw SN::Input_error("cannot read a polygon mesh with faces from the file");
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
}

// The mesh of a model name, or the reason it is absent. Models given as files have the file's name.
inline bool load_denoise_mesh(const std::string& name, const Denoise_options& o, Denoise_mesh& mesh, std::string& source,
                              std::string& absent)
{
  if(name == "cube")
  {
    SN::make_subdivided_cube(GENERATED_CUBE_SUBDIVISIONS, mesh);
    source = "generated: make_subdivided_cube(" + std::to_string(GENERATED_CUBE_SUBDIVISIONS) + ")";
    return true;
  }
  if(name == "octahedron")
  {
    SN::make_subdivided_octahedron(GENERATED_OCTAHEDRON_SUBDIVISIONS, mesh);
    source = "generated: make_subdivided_octahedron(" + std::to_string(GENERATED_OCTAHEDRON_SUBDIVISIONS) + ")";
    return true;
  }
  std::error_code ec;
  if(name == "fandisk")
  {
    if(!o.fandisk.empty())
    {
      read_denoise_mesh(o.fandisk, mesh);
      source = o.fandisk;
      return true;
    }
    // Debian's libcgal-demo ships it in CGAL's data archive.
    const std::string archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
    if(!fs::exists(archive, ec))
    {
      absent = "not found: give --fandisk FILE or install libcgal-demo (" + archive + ")";
      return false;
    }
    const fs::path tmp = fs::temp_directory_path() / ("sigmoid-neighborhoods-fandisk-" + std::to_string(::getpid()));
    fs::create_directories(tmp, ec);
    const std::string command = "tar -xzf " + shell_quote(archive) + " -C " + shell_quote(tmp.string()) +
                                " data/meshes/fandisk.off 2>/dev/null";
    const bool extracted = std::system(command.c_str()) == 0;
    const std::string file = (tmp / "data" / "meshes" / "fandisk.off").string();
    if(extracted)
      read_denoise_mesh(file, mesh);
    fs::remove_all(tmp, ec);
    if(!extracted)
    {
      absent = "data/meshes/fandisk.off could not be extracted from " + archive;
      return false;
    }
    source = "libcgal-demo: " + archive + "!data/meshes/fandisk.off";
    return true;
  }
  for(const auto& m : table4_models())
    if(m.name == name)
    {
      for(const char* ext : {".off", ".obj", ".ply", ".stl"})
      {
        const fs::path file = fs::path(o.data_dir) / (name + ext);
        if(fs::exists(file, ec))
        {
          read_denoise_mesh(file.string(), mesh);
          source = file.string();
          return true;
        }
      }
      absent = "absent: no " + name + ".off/.obj/.ply/.stl in " + o.data_dir;
      return false;
    }
  read_denoise_mesh(name, mesh); // a file given by the user
  source = name;
  return true;
}

// One noise level of one model: noise, noisy normals, both filters, MSEs.
inline Denoise_result run_denoise_level(const Denoise_mesh& clean, const std::vector<Denoise_vector>& truth,
                                        double spacing, double level, const Denoise_model& settings,
                                        const Denoise_options& o)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Denoise_result r;
  r.points = clean.number_of_vertices();
  r.level = level;
  r.spacing = spacing;
  r.sigma = level * spacing;
  r.iterations = settings.iterations;
  r.cut_off = settings.cut_off;
  r.eigenvalue_threshold = settings.eigenvalue_threshold;

  // Noise along the noise-free normals, in vertex order.
  Denoise_mesh noisy = clean;
  auto truth_map = noisy.add_property_map<Denoise_mesh::Vertex_index, Denoise_vector>("v:truth").first;
  std::size_t i = 0;
  for(auto v : noisy.vertices())
    truth_map[v] = truth[i++];
  auto vertices = noisy.vertices();
  SN::add_normal_noise(vertices, r.sigma, o.seed, CGAL::parameters::point_map(noisy.points()).normal_map(truth_map));

  std::vector<Denoise_point> points;
  for(auto v : noisy.vertices())
    points.push_back(noisy.point(v));
  std::vector<Denoise_vector> normals;
  if(!o.pca_normals)
  {
    auto noisy_normals = noisy.add_property_map<Denoise_mesh::Vertex_index, Denoise_vector>("v:noisy").first;
    PMP::compute_vertex_normals(noisy, noisy_normals);
    for(auto v : noisy.vertices())
      normals.push_back(noisy_normals[v]);
  }
  else
  {
    typedef std::pair<Denoise_point, Denoise_vector> Item;
    std::vector<Item> items;
    for(const auto& p : points)
      items.emplace_back(p, CGAL::NULL_VECTOR);
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      items, PCA_NEIGHBORS,
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Item>())
        .normal_map(CGAL::Second_of_pair_property_map<Item>()));
    for(std::size_t j = 0; j < items.size(); ++j)
      normals.push_back(items[j].second * truth[j] < 0 ? -items[j].second : items[j].second);
  }
  for(std::size_t j = 0; j < normals.size(); ++j)
    if(!(normals[j].squared_length() > 0.))
      throw std::invalid_argument("noisy vertex " + std::to_string(j) + " has no defined normal");

  auto errors = [&truth](const std::vector<Denoise_vector>& n) {
    std::vector<double> e(n.size());
    for(std::size_t j = 0; j < n.size(); ++j)
      e[j] = SN::normal_squared_error(truth[j], n[j]);
    return e;
  };
  r.mse_noise = SN::normal_mse(truth, normals);
  r.error_noise = errors(normals);

  Filter_options f;
  f.iterations = settings.iterations;
  f.cut_off = settings.cut_off;
  f.eigenvalue_threshold = settings.eigenvalue_threshold;
  for(bool adaptive : {false, true})
  {
    f.adaptive = adaptive;
    std::vector<Denoise_vector> filtered = normals;
    CGAL::Real_timer timer;
    timer.start();
    const SN::Normal_filter_summary summary = filter_point_normals(points, filtered, f);
    timer.stop();
    (adaptive ? r.adaptive_summary : r.default_summary) = summary;
    (adaptive ? r.seconds_adaptive : r.seconds_default) = timer.time();
    (adaptive ? r.mse_adaptive : r.mse_default) = SN::normal_mse(truth, filtered);
    (adaptive ? r.error_adaptive : r.error_default) = errors(filtered);
  }
  return r;
}

inline std::string number17(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

inline std::string number9(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.9f", v);
  return buffer;
}

inline std::string level_name(double level)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%g", level);
  return buffer;
}

inline void write_table4_csv(std::ostream& out, const std::vector<Denoise_result>& results)
{
  out << "model,points,noise,spacing,sigma,iterations,cut_off,eigenvalue_threshold,mse_noise,mse_default,"
         "mse_adaptive,adaptive_below_default,radius,mean_k_default,mean_k_adaptive,fallbacks,empty_cones_default,"
         "paper_mse_noise,paper_mse_default,paper_mse_adaptive\n";
  for(const auto& r : results)
  {
    out << r.model << ',' << r.points << ',' << level_name(r.level) << ',' << number17(r.spacing) << ','
        << number17(r.sigma) << ',' << r.iterations << ',' << number17(r.cut_off) << ','
        << number17(r.eigenvalue_threshold) << ',' << number17(r.mse_noise) << ',' << number17(r.mse_default) << ','
        << number17(r.mse_adaptive) << ',' << (r.mse_adaptive < r.mse_default ? "yes" : "no") << ','
        << number17(r.default_summary.radius) << ',' << number17(r.default_summary.mean_neighbors) << ','
        << number17(r.adaptive_summary.mean_selected_size) << ',' << r.adaptive_summary.fallbacks << ','
        << r.default_summary.empty_cones << ',';
    if(r.paper_level >= 0)
      out << number17(r.paper->paper[3 * r.paper_level]) << ',' << number17(r.paper->paper[3 * r.paper_level + 1])
          << ',' << number17(r.paper->paper[3 * r.paper_level + 2]);
    else
      out << ",,";
    out << '\n';
  }
}

inline void write_table4_markdown(std::ostream& out, const std::vector<Denoise_result>& results,
                                  const std::vector<std::pair<std::string, std::string>>& sources,
                                  const std::vector<std::pair<std::string, std::string>>& skipped,
                                  const Denoise_options& o)
{
  out << "# Table 4: normal filtering with default and adaptive neighborhood sizes\n\n";
  out << "Noise: Gaussian offsets along the noise-free vertex normals, sd = level x l, l = mean distance of the "
         "points to their 6 nearest neighbors (noise-free), `std::mt19937_64` seed "
      << o.seed << " for every model and level, drawn in vertex order. ";
  out << "Filter input normals: "
      << (o.pca_normals ? "PCA over the 12 nearest neighbors (CGAL `pca_estimate_normals`), oriented like the "
                          "noise-free normals"
                        : "vertex normals of the noisy mesh (CGAL `compute_vertex_normals`, as the noise-free ones)")
      << ". Filter: Yadav et al. (2018) stage 1, `(p, cut-off, eigenvalue threshold)` per model (SPEC §7), damping "
         "3, balls of radius 5 m (m = mean 12-NN distance of the noisy points); adaptive: every point takes the "
         "`k` of least `E_dim` in `{k_i - 10, ..., k_i + 10}` with `a = b = arccos(cut-off)` before each sweep. "
         "MSE = mean `|n - n~|^2` against the noise-free vertex normals.\n\n";

  // The paper's layout: one row per model, the noise levels side by side.
  std::vector<std::string> models;
  for(const auto& r : results)
    if(std::find(models.begin(), models.end(), r.model) == models.end())
      models.push_back(r.model);
  out << "| model | points |";
  for(double level : o.noise)
    out << ' ' << level_name(level) << " l: MSE(Noise) | MSE(default) | MSE(adaptive) |";
  out << "\n|---|---:|";
  for(std::size_t l = 0; l < o.noise.size(); ++l)
    out << "---:|---:|---:|";
  out << '\n';
  for(const auto& name : models)
  {
    bool first = true;
    for(const auto& r : results)
      if(r.model == name)
      {
        if(first)
          out << "| " << r.title << " | " << r.points << " |";
        first = false;
        const double best = (std::min)({r.mse_noise, r.mse_default, r.mse_adaptive});
        for(double v : {r.mse_noise, r.mse_default, r.mse_adaptive})
          out << ' ' << (v == best ? "**" + number9(v) + "**" : number9(v)) << " |";
      }
    out << '\n';
  }
  out << "\nBold: the smallest of the three.\n\n";

  out << "## Does adaptive < default hold (the paper: on every model)?\n\n";
  out << "| model | noise | MSE(default) | MSE(adaptive) | adaptive - default | adaptive < default | "
         "paper: MSE(Noise) | paper: default | paper: adaptive |\n|---|---:|---:|---:|---:|:---:|---:|---:|---:|\n";
  std::size_t holds = 0;
  for(const auto& r : results)
  {
    holds += r.mse_adaptive < r.mse_default;
    char difference[40];
    std::snprintf(difference, sizeof(difference), "%+.9f", r.mse_adaptive - r.mse_default);
    out << "| " << r.title << " | " << level_name(r.level) << " l | " << number9(r.mse_default) << " | "
        << number9(r.mse_adaptive) << " | " << difference << " | " << (r.mse_adaptive < r.mse_default ? "yes" : "no")
        << " |";
    if(r.paper_level >= 0)
      for(int c = 0; c < 3; ++c)
        out << ' ' << number9(r.paper->paper[3 * r.paper_level + c]) << " |";
    else
      out << " – | – | – |";
    out << '\n';
  }
  out << "\nAdaptive < default holds for " << holds << " of " << results.size() << " model/noise pairs here.\n\n";

  out << "## Neighborhoods\n\n";
  out << "| model | noise | p | cut-off | threshold | l | radius 5 m | mean k_i | mean adaptive k | "
         "fallbacks | empty cones (default) | empty cones (adaptive) |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const auto& r : results)
  {
    char line[512];
    std::snprintf(line, sizeof(line), "| %s | %s l | %u | %g | %g | %.6g | %.6g | %.2f | %.2f | %zu | %zu | %zu |\n",
                  r.title.c_str(), level_name(r.level).c_str(), r.iterations, r.cut_off, r.eigenvalue_threshold,
                  r.spacing, r.default_summary.radius, r.default_summary.mean_neighbors,
                  r.adaptive_summary.mean_selected_size, r.adaptive_summary.fallbacks,
                  r.default_summary.empty_cones, r.adaptive_summary.empty_cones);
    out << line;
  }
  out << "\nFallbacks and empty cones count point-sweeps. A fallback is a point whose every size is degenerate "
         "with the cut-off weights: it votes with its default neighborhood and equal weights.\n\n";

  out << "## Models\n\n";
  for(const auto& s : sources)
    out << "- " << s.first << ": " << s.second << '\n';
  for(const auto& s : skipped)
    out << "- " << s.first << ": skipped, " << s.second << '\n';
}

inline void write_error_csv(std::ostream& out, const Denoise_mesh& clean, const std::vector<const Denoise_result*>& levels)
{
  out << "x,y,z";
  for(const auto* r : levels)
  {
    const std::string l = level_name(r->level);
    out << ",noise_" << l << ",default_" << l << ",adaptive_" << l;
  }
  out << '\n';
  std::size_t i = 0;
  for(auto v : clean.vertices())
  {
    const auto& p = clean.point(v);
    out << number17(p.x()) << ',' << number17(p.y()) << ',' << number17(p.z());
    for(const auto* r : levels)
      out << ',' << number17(r->error_noise[i]) << ',' << number17(r->error_default[i]) << ','
          << number17(r->error_adaptive[i]);
    out << '\n';
    ++i;
  }
}

inline int run_denoise_experiment(int argc, char** argv)
{
  const Arguments args(argc, argv, 2,
                       {"-o", "--output", "--noise", "--seed", "--data", "--fandisk", "--figure-model",
                        "--noisy-normals", "--threads"},
                       {"-h", "--help"});
  if(args.has("-h") || args.has("--help"))
  {
    std::cout << DENOISE_USAGE;
    return EXIT_OK;
  }
  Denoise_options o;
  o.output = args.get("-o", args.get("--output"));
  if(o.output.empty())
    throw Usage_error("denoise-experiment needs -o DIR");
  if(args.has("--noise"))
    o.noise = parse_noise_levels(args.get("--noise"));
  if(args.has("--seed"))
  {
    const std::string text = args.get("--seed");
    char* end = nullptr;
    errno = 0;
    const unsigned long long seed = std::strtoull(text.c_str(), &end, 10);
    if(text.empty() || *end != '\0' || errno != 0 || text[0] == '-')
      throw Usage_error("--seed needs a non-negative integer, got '" + text + "'");
    o.seed = seed;
  }
  o.data_dir = args.get("--data", default_application_data());
  o.fandisk = args.get("--fandisk");
  const std::string normals = args.get("--noisy-normals", "mesh");
  if(normals != "mesh" && normals != "pca")
    throw Usage_error("--noisy-normals must be mesh or pca, got '" + normals + "'");
  o.pca_normals = normals == "pca";
  o.threads = static_cast<int>(args.get_unsigned("--threads", 0));
#ifdef _OPENMP
  if(o.threads > 0)
    omp_set_num_threads(o.threads);
#endif
  std::vector<std::string> names = args.positional();
  if(names.empty())
    for(const auto& m : table4_models())
      names.push_back(m.name);
  std::error_code ec;
  for(const auto& name : names)
  {
    bool known = false;
    for(const auto& m : table4_models())
      known = known || m.name == name;
    if(!known && !fs::is_regular_file(name, ec))
      throw Usage_error("unknown model '" + name +
                        "': expected cube, bearing, fandisk, sharp_sphere, fertility, octahedron, rockerarm or a mesh file");
  }
  o.figure_model = args.get("--figure-model");
  if(!o.figure_model.empty() && std::find(names.begin(), names.end(), o.figure_model) == names.end())
    throw Usage_error("--figure-model " + o.figure_model + " is not among the models run");
  if(!o.fandisk.empty() && !fs::is_regular_file(o.fandisk, ec))
    throw Usage_error("--fandisk " + o.fandisk + ": no such file");

  // Models first (a bad file stops the run before anything is written), then the experiment.
  struct Loaded
  {
    std::string name;
    Denoise_model settings;
    Denoise_mesh mesh;
  };
  std::vector<Loaded> loaded;
  std::vector<std::pair<std::string, std::string>> sources, skipped;
  for(const auto& name : names)
  {
    Loaded l;
    l.name = name;
    l.settings = {fs::path(name).stem().string(), fs::path(name).filename().string(), SN::DEFAULT_FILTER_ITERATIONS, SN::DEFAULT_NORMAL_CUT_OFF,
                  SN::DEFAULT_EIGENVALUE_THRESHOLD, 0, {0, 0, 0, 0, 0, 0}};
    for(const auto& m : table4_models())
      if(m.name == name)
        l.settings = m;
    std::string source, absent;
    try
    {
      if(!load_denoise_mesh(name, o, l.mesh, source, absent))
      {
        skipped.emplace_back(l.settings.title, absent);
        std::cerr << "denoise-experiment: " << l.settings.title << " skipped: " << absent << '\n';
        continue;
      }
    }
    catch(const SN::Input_error& e)
    {
      throw Usage_error(name + ": " + e.what());
    }
    sources.emplace_back(l.settings.title, source + " (" + std::to_string(l.mesh.number_of_vertices()) +
                                             " vertices; the paper's: " +
                                             (l.settings.paper_vertices ? std::to_string(l.settings.paper_vertices)
                                                                        : std::string("–")) + ")");
    loaded.push_back(std::move(l));
  }
  if(loaded.empty())
    throw Usage_error("no model could be loaded");
  if(o.figure_model.empty())
  {
    o.figure_model = loaded.front().name;
    for(const auto& l : loaded)
      if(l.name == "fandisk")
        o.figure_model = "fandisk";
  }
  fs::create_directories(o.output, ec);
  if(!fs::is_directory(o.output, ec))
    throw Usage_error("cannot create the folder " + o.output);

  std::vector<Denoise_result> results;
  std::vector<std::string> timings;
  for(const auto& l : loaded)
  {
    auto truth_map = get(CGAL::dynamic_vertex_property_t<Denoise_vector>(), l.mesh);
    CGAL::Polygon_mesh_processing::compute_vertex_normals(l.mesh, truth_map);
    std::vector<Denoise_vector> truth;
    for(auto v : l.mesh.vertices())
    {
      truth.push_back(get(truth_map, v));
      if(!(truth.back().squared_length() > 0.))
        throw Usage_error(l.name + ": vertex " + std::to_string(std::size_t(v)) + " has no defined normal");
    }
    auto vertices = l.mesh.vertices();
    double spacing;
    try
    {
      spacing = SN::compute_mean_neighbor_distance<SN::Parallel_if_available_tag>(
        vertices, SPACING_NEIGHBORS, CGAL::parameters::point_map(l.mesh.points()));
    }
    catch(const std::invalid_argument& e)
    {
      throw Usage_error(l.name + ": " + e.what());
    }
    std::vector<const Denoise_result*> figure;
    const std::size_t first = results.size();
    for(double level : o.noise)
    {
      Denoise_result r;
      try
      {
        r = run_denoise_level(l.mesh, truth, spacing, level, l.settings, o);
      }
      catch(const std::invalid_argument& e)
      {
        throw Usage_error(l.name + ": " + e.what());
      }
      r.model = l.settings.name;
      r.title = l.settings.title;
      for(const auto& m : table4_models())
        if(m.name == l.name)
        {
          r.paper = &m;
          r.paper_level = level == 0.3 ? 0 : level == 0.6 ? 1 : -1;
        }
      char line[256];
      std::snprintf(line, sizeof(line), "%s,%s,%zu,%u,%.3f,%.3f", r.model.c_str(), level_name(level).c_str(), r.points,
                    r.iterations, r.seconds_default, r.seconds_adaptive);
      timings.push_back(line);
      std::cerr << "denoise-experiment: " << r.title << " at " << level_name(level) << " l: MSE noise "
                << number9(r.mse_noise) << ", default " << number9(r.mse_default) << " (" << r.seconds_default
                << " s), adaptive " << number9(r.mse_adaptive) << " (" << r.seconds_adaptive << " s)\n";
      results.push_back(std::move(r));
    }
    if(l.name == o.figure_model)
    {
      for(std::size_t i = first; i < results.size(); ++i)
        figure.push_back(&results[i]);
      const std::string csv = (fs::path(o.output) / ("normal_error_" + l.settings.name + ".csv")).string();
      write_file_atomically(csv, [&](std::ofstream& out) { write_error_csv(out, l.mesh, figure); });
    }
    for(std::size_t i = first; i < results.size(); ++i) // per-point errors are no longer needed
    {
      results[i].error_noise.clear();
      results[i].error_default.clear();
      results[i].error_adaptive.clear();
    }
  }

  write_file_atomically((fs::path(o.output) / "table4.csv").string(),
                        [&](std::ofstream& out) { write_table4_csv(out, results); });
  write_file_atomically((fs::path(o.output) / "table4.md").string(), [&](std::ofstream& out) {
    write_table4_markdown(out, results, sources, skipped, o);
  });
  write_file_atomically((fs::path(o.output) / "timings.csv").string(), [&](std::ofstream& out) {
    out << "model,noise,points,iterations,seconds_default,seconds_adaptive\n";
    for(const auto& t : timings)
      out << t << '\n';
  });

  std::string figure_name;
  for(const auto& l : loaded)
    if(l.name == o.figure_model)
      figure_name = l.settings.name;
  const std::string csv = (fs::path(o.output) / ("normal_error_" + figure_name + ".csv")).string();
  const std::string png = (fs::path(o.output) / ("normal_error_" + figure_name + ".png")).string();
  const std::string command = shell_quote(python_interpreter()) + " " +
                              shell_quote(find_tool_script("plot_normal_error.py")) + " " + shell_quote(csv) + " " +
                              shell_quote(png) + " --title " + shell_quote(figure_name);
  if(std::system(command.c_str()) != 0)
  {
    std::cerr << "sigmoid-neighborhoods denoise-experiment: the figure could not be drawn (needs python3 with "
                 "matplotlib); the tables are written in "
              << o.output << '\n';
    return EXIT_FAILED;
  }
  std::cerr << "denoise-experiment: " << (fs::path(o.output) / "table4.md").string() << ", table4.csv and " << png
            << '\n';
  return EXIT_OK;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_DENOISE_COMMAND_H
