// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `sigmoid-neighborhoods evaluate`: the paper's Section 5 over a repository of models, on one
// machine or in shards (merge_command.cpp joins the shards).

#include "commands.h"
#include "evaluate_command.h"

#include "catalog_input.h"
#include "command_line.h"
#include "evaluation_files.h"
#include "evaluation_json.h"
#include "model_input.h"
#include "optimal_command.h"
#include "phase_times.h"
#include "text_rows.h"

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Sigmoid_neighborhoods/Point_evaluation.h>
#include <CGAL/Sigmoid_neighborhoods/evaluate_sigmoid_neighborhoods.h>
#include "evaluation_statistics.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <iostream>
#include <iterator>
#include <memory>
#include <new>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const EVALUATE_USAGE =
  "usage: sigmoid-neighborhoods evaluate INPUTS...|--catalog SOURCE -o OUTDIR [--repository NAME] [--shard I/N]\n"
  "         [--threads N]"
  "         [--resume] [--per-point] [--only-with-normals] [--barycenter weighted|unweighted]\n"
  "         [--k-min 6] [--k-max 20] [--fixed-k K_MAX] [--a-grid ANGLES] [--b-grid ANGLES]\n"
  "         [--angle-tolerance 1e-6] [normals]\n"
  "  INPUTS: model files or folders (searched recursively for .off .obj .ply .stl .xyz .pwn)\n"
  "  --shard I/N: evaluate the I-th of N shares (1 <= I <= N), balanced by file size\n"
  "  --catalog SOURCE: the tiles of a survey (a folder or a list file, see optimal --help) as the models,\n"
  "      each evaluated on its own points with the halo that makes its per-point rows those of the\n"
  "      union (estimated normals oriented upwards unless --orientation or --viewpoint says otherwise)\n";

struct Model_file
{
  std::string name; // relative to its input root, '/'-separated
  std::string path;
  std::uintmax_t bytes = 0;
};

// Reading a model has steps on one thread (the merge of equal positions, the mesh built from its
// soup, CGAL's readers for files the parallel ones leave to them); on the clean meshes of
// ../shared/data it was a third of a one-thread run when all of it was. So the next models are read
// on threads of their own, one thread each (the same points and normals as on any number), while the
// current one is searched: up to `depth` models ahead, files of at most
// READ_AHEAD_BYTES together, so that memory holds a bounded amount of small models beside the
// searched one (a larger file is read when taken, on all threads). A model's exception reaches the
// caller when it takes the model, as if it were read then.
constexpr std::uintmax_t READ_AHEAD_BYTES = std::uintmax_t(128) << 20;

class Read_ahead
{
public:
  typedef std::function<SN::Oriented_point_set(const Model_file&, unsigned int threads)> Reader;

  // `wanted(i)`: model i will be taken (not resumed); `threads`: those of a model read when taken
  Read_ahead(const std::vector<Model_file>& models, std::size_t depth, unsigned int threads,
             std::function<bool(std::size_t)> wanted, Reader read)
    : m_models(models), m_depth(depth), m_threads(threads), m_wanted(std::move(wanted)), m_read(std::move(read)),
      m_pending(models.size())
  {
  }

  SN::Oriented_point_set take(std::size_t i)
  {
    for(m_next = (std::max)(m_next, i + 1); m_next < m_models.size() && m_next <= i + m_depth; ++m_next)
    {
      const Model_file& file = m_models[m_next];
      if(m_bytes_ahead + file.bytes > READ_AHEAD_BYTES)
        break; // m_next is tried again at the next model
      if(!m_wanted(m_next))
        continue;
      try
      {
        m_pending[m_next] = std::async(std::launch::async, [this, &file] { return m_read(file, 1); });
        m_bytes_ahead += file.bytes;
      }
      catch(const std::exception&)
      {
        // no thread to spare: the model is read when taken
      }
    }
    if(!m_pending[i].valid())
      return m_read(m_models[i], m_threads);
    m_bytes_ahead -= m_models[i].bytes;
    return m_pending[i].get();
  }

private:
  const std::vector<Model_file>& m_models;
  std::size_t m_depth;
  unsigned int m_threads;
  std::function<bool(std::size_t)> m_wanted;
  Reader m_read;
  std::vector<std::future<SN::Oriented_point_set>> m_pending;
  std::size_t m_next = 0;
  std::uintmax_t m_bytes_ahead = 0; // of the models read ahead and not yet taken
};

bool is_model_extension(const fs::path& p)
{
  const std::string ext = SN::lower_case_extension(p.extension().string());
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl" || ext == "xyz" || ext == "pwn" ||
         ext == "las";
}

std::vector<Model_file> find_models(const std::vector<std::string>& inputs)
{
  std::vector<Model_file> models;
  for(const std::string& input : inputs)
  {
    const fs::path root(input);
    std::error_code ec;
    if(fs::is_directory(root, ec))
    {
      for(auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, ec);
          it != fs::recursive_directory_iterator(); it.increment(ec))
        if(it->is_regular_file(ec) && is_model_extension(it->path()))
          // lexically: a symbolic link is named by its own path, not by its target's
          models.push_back({it->path().lexically_relative(root).generic_string(), it->path().string(), it->file_size(ec)});
    }
    else if(fs::is_regular_file(root, ec))
      models.push_back({root.filename().generic_string(), root.string(), fs::file_size(root, ec)});
    else
      throw Usage_error("no such file or folder: " + input);
  }
  std::sort(models.begin(), models.end(), [](const Model_file& x, const Model_file& y) { return x.name < y.name; });
  for(std::size_t i = 1; i < models.size(); ++i)
    if(models[i].name == models[i - 1].name)
      throw Usage_error("two inputs give the same model name " + models[i].name + ": evaluate them separately");
  return models;
}

// The I-th of N shares: models by decreasing size (then name) go to the lightest share so far.
std::vector<Model_file> shard(const std::vector<Model_file>& models, unsigned int index, unsigned int count)
{
  std::vector<Model_file> order = models;
  std::sort(order.begin(), order.end(), [](const Model_file& x, const Model_file& y) {
    return x.bytes != y.bytes ? x.bytes > y.bytes : x.name < y.name;
  });
  std::vector<std::uintmax_t> load(count, 0);
  std::vector<Model_file> mine;
  for(const Model_file& m : order)
  {
    const std::size_t s = std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
    load[s] += m.bytes + 1;
    if(s + 1 == index)
      mine.push_back(m);
  }
  std::sort(mine.begin(), mine.end(), [](const Model_file& x, const Model_file& y) { return x.name < y.name; });
  return mine;
}

// Models done of total, points per second and time left; a bar on a terminal, lines elsewhere. On
// std::clog: a file read ahead holds std::cerr while CGAL's reader speaks (Read_ahead).
class Progress
{
public:
  Progress(std::size_t models, std::uintmax_t bytes)
    : m_total(models), m_bytes(bytes), m_terminal(::isatty(STDERR_FILENO)),
      m_start(std::chrono::steady_clock::now())
  {
  }

  void done(const std::string& name, std::size_t points, std::uintmax_t bytes, const std::string& outcome)
  {
    ++m_done;
    m_points += points;
    m_done_bytes += bytes;
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const double rate = seconds > 0. ? double(m_points) / seconds : 0.;
    const double left = m_done_bytes > 0 ? seconds * double(m_bytes - m_done_bytes) / double(m_done_bytes) : 0.;
    char line[256];
    if(m_terminal)
    {
      const int width = BAR_WIDTH, filled = m_total ? int(width * m_done / m_total) : width;
      std::snprintf(line, sizeof(line), "\r[%-*s] %zu/%zu models, %.0f points/s, %s left   ",
                    width, std::string(std::size_t(filled), '#').c_str(), m_done, m_total, rate,
                    duration(left).c_str());
      std::clog << line << std::flush;
      if(m_done == m_total)
        std::clog << '\n';
    }
    else
    {
      std::snprintf(line, sizeof(line), "[%zu/%zu] %s: %s (%.0f points/s, %s left)\n", m_done, m_total,
                    name.c_str(), outcome.c_str(), rate, duration(left).c_str());
      std::clog << line << std::flush;
    }
  }

  static std::string duration(double seconds)
  {
    char text[32];
    const long s = long(seconds + 0.5);
    if(s >= 3600)
      std::snprintf(text, sizeof(text), "%ldh%02ldm", s / 3600, (s / 60) % 60);
    else
      std::snprintf(text, sizeof(text), "%ldm%02lds", s / 60, s % 60);
    return text;
  }

private:
  // Characters of the bar: with the counts after it, a line fits an 80-column terminal.
  static constexpr int BAR_WIDTH = 30;

  std::size_t m_total, m_done = 0, m_points = 0;
  std::uintmax_t m_bytes, m_done_bytes = 0;
  bool m_terminal;
  std::chrono::steady_clock::time_point m_start;
};

// The tile's own points of `tile` (its halo left out) as a model, with their evaluations: what the
// union gives those points. Its input is the tile's file; merged, its points of earlier tiles too.
SN::Oriented_point_set own_points(const SN::Tile_with_halo& tile, std::vector<SN::Point_evaluation>& evaluations)
{
  const SN::Oriented_point_set& all = tile.points;
  const auto first = std::ptrdiff_t(tile.first), last = std::ptrdiff_t(tile.last);
  SN::Oriented_point_set own;
  own.points.assign(all.points.begin() + first, all.points.begin() + last);
  own.normals.assign(all.normals.begin() + first, all.normals.begin() + last);
  if(!all.labels.empty())
    own.labels.assign(all.labels.begin() + first, all.labels.begin() + last);
  own.normals_estimated = all.normals_estimated;
  own.estimation_method = all.estimation_method;
  own.estimation_neighbors = all.estimation_neighbors;
  own.orientation = all.orientation;
  own.orientation_components = all.orientation_components;
  own.input_vertices = tile.input_points;
  own.merged_duplicates = tile.input_points - tile.size();
  evaluations = std::vector<SN::Point_evaluation>(evaluations.begin() + first, evaluations.begin() + last);
  return own;
}

Model_result model_result(const Model_file& file, const SN::Oriented_point_set& model,
                          const std::vector<SN::Point_evaluation>& evaluations, const Evaluation_settings& s)
{
  Model_result m;
  m.model = file.name;
  m.input_vertices = model.input_vertices;
  m.merged_duplicates = model.merged_duplicates;
  m.dropped_vertices = model.dropped_vertices;
  m.normals = model.normals_estimated ? "estimated" : (model.is_mesh ? "mesh" : "file");
  if(model.normals_estimated)
  {
    m.normal_method = normal_source_name(model);
    m.normal_neighbors = model.estimation_neighbors;
    m.orientation = SN::normal_orientation_name(model.orientation);
    m.normal_components = model.orientation_components;
  }
  m.zero_normals = model.zero_normals;
  m.statistics = SN::Evaluation_statistics(s.k_min, s.k_max, s.a_grid, s.b_grid);
  for(const SN::Point_evaluation& e : evaluations)
    m.statistics.add(e);
  m.points = m.statistics.points;
  m.k_standard_deviation = m.statistics.k_mean_and_deviation().second;
  return m;
}

// A run killed mid-write (SIGKILL, power loss) leaves write_file_atomically's temporaries behind;
// an OUTDIR is written by one evaluate at a time, so the next run removes them.
void remove_temporary_files(const std::string& outdir)
{
  std::error_code ec;
  std::vector<fs::path> leftovers;
  for(fs::recursive_directory_iterator it(outdir, ec), end; !ec && it != end; it.increment(ec))
    if(it->is_regular_file(ec) && is_temporary_file_name(it->path().filename().string()))
      leftovers.push_back(it->path());
  for(const fs::path& file : leftovers)
    fs::remove(file, ec);
  if(!leftovers.empty())
    std::cerr << outdir << ": removed " << leftovers.size() << " temporary files of an interrupted run\n";
}

std::string iso_date()
{
  char text[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

std::string host_name()
{
  char name[256] = {0};
  ::gethostname(name, sizeof(name) - 1);
  return name;
}

// What the arguments ask for: the search, the statistics' settings, the models of this shard.
struct Evaluate_request
{
  std::string outdir, repository;
  Search_options options;
  Evaluation_settings settings;
  SN::Normal_options normal_options;
  std::unique_ptr<Lidar_io::Tile_catalog> catalog; // --catalog: the models are its tiles
  std::vector<Model_file> models;
  unsigned int shard_index = 1, shard_count = 1;
};

Evaluation_settings read_evaluation_settings(const Arguments& args, const Search_options& options)
{
  Evaluation_settings settings;
  settings.k_min = options.k_min;
  settings.k_max = options.k_max;
  settings.fixed_k = args.get_unsigned("--fixed-k", options.k_max);
  if(settings.fixed_k < options.k_min || settings.fixed_k > options.k_max)
    throw Usage_error("--fixed-k must lie in [--k-min, --k-max]");
  settings.barycenter = SN::barycenter_name(options.barycenter);
  settings.angle_tolerance = options.angle_tolerance;
  settings.cut_off_angle = std::acos(EVALUATION_CUT_OFF_COSINE);
  settings.a_grid = options.a_grid; // sorted and deduplicated, as the statistics keep them
  settings.b_grid = options.b_grid;
  return settings;
}

// The models of the inputs or of --catalog, then those of --shard.
void read_models(const Arguments& args, Evaluate_request& r)
{
  if(args.has("--catalog"))
  {
    r.catalog.reset(new Lidar_io::Tile_catalog(read_catalog_argument(args.get("--catalog"))));
    if(!args.has("--orientation") && !args.has("--viewpoint"))
      r.normal_options.orientation = SN::Normal_orientation::UPWARD; // exact per tile
    for(const Lidar_io::Catalog_tile& t : r.catalog->tiles)
    {
      std::error_code ec;
      const std::uintmax_t bytes = fs::file_size(t.path, ec);
      r.models.push_back({t.name, t.path, ec ? 0 : bytes});
    }
  }
  else
    r.models = find_models(args.positional());
  set_normal_settings(r.settings, r.normal_options, r.options.line_angles);

  if(args.has("--shard"))
  {
    const std::string text = args.get("--shard");
    if(std::sscanf(text.c_str(), "%u/%u", &r.shard_index, &r.shard_count) != 2 || r.shard_count == 0 ||
       r.shard_index == 0 || r.shard_index > r.shard_count)
      throw Usage_error("--shard needs I/N with 1 <= I <= N, got '" + text + "'");
    r.models = shard(r.models, r.shard_index, r.shard_count);
  }
}

void read_evaluate_request(const Arguments& args, Evaluate_request& r)
{
  r.outdir = args.output();
  if(r.outdir.empty())
    throw Usage_error("evaluate needs -o OUTDIR");
  if(args.positional().empty() == !args.has("--catalog"))
    throw Usage_error("evaluate needs input files or folders, or --catalog SOURCE (not both)");
  r.options = read_search_options(args);
  r.settings = read_evaluation_settings(args, r.options);
  r.normal_options = read_normal_options(args);
  read_models(args, r);
  r.repository = args.get("--repository");
  const std::string first_input = r.catalog ? args.get("--catalog") : args.positional().front();
  if(r.repository.empty())
    r.repository = fs::path(first_input).lexically_normal().filename().string();
  if(r.repository.empty())
    r.repository = fs::absolute(first_input).lexically_normal().parent_path().filename().string();
}

// What became of the models, for run.json and the last line.
struct Evaluate_tally
{
  std::vector<Model_failure> failures;
  std::vector<Small_model> too_small;
  std::vector<std::string> skipped_without_normals;
  std::size_t evaluated = 0, resumed = 0, points = 0, estimated_models = 0, estimated_points = 0, normal_trees = 0;
};

// The tile `file` of the catalog with its halo, evaluated; `model` and `evaluations` are its own points'.
void evaluate_tile(const Evaluate_request& r, const Model_file& file, Phase_times& times,
                   SN::Oriented_point_set& model, std::vector<SN::Point_evaluation>& evaluations)
{
  const unsigned int k_max = r.options.k_max;
  SN::Normal_options o = r.normal_options;
  o.kept_neighbors = k_max;
  SN::Tile_with_halo tile = SN::read_tile_with_halo(*r.catalog, r.catalog->index_of(file.name), k_max, o);
  if(tile.points.points.size() < std::size_t(k_max) + 1)
    throw Too_small_for_the_grid("too few points", std::size_t(k_max) + 1, tile.points.points.size());
  times.end_reading(tile.points);
  evaluations = evaluate_model(tile.points, r.options, r.settings);
  times.end("search");
  model = own_points(tile, evaluations);
}

// Evaluates the model `index` and writes its files, or records it as skipped for want of normals.
void evaluate_and_write(const Arguments& args, const Evaluate_request& r, std::size_t index, Read_ahead& ahead,
                        Phase_times& times, Progress& progress, Evaluate_tally& tally)
{
  const Model_file& file = r.models[index];
  SN::Oriented_point_set model;
  std::vector<SN::Point_evaluation> evaluations;
  if(r.catalog)
    evaluate_tile(r, file, times, model, evaluations);
  else
  {
    model = ahead.take(index);
    if(model.normals.empty())
    {
      tally.skipped_without_normals.push_back(file.name);
      progress.done(file.name, 0, file.bytes, "skipped: no normals in the file");
      return;
    }
    times.end_reading(model);
    evaluations = evaluate_model(model, r.options, r.settings);
    times.end("search");
  }
  const Model_result result = model_result(file, model, evaluations, r.settings);
  const fs::path json_path = fs::path(r.outdir) / "models" / (file.name + ".json");
  fs::create_directories(json_path.parent_path());
  if(args.has("--per-point"))
    write_file_atomically((fs::path(r.outdir) / "models" / (file.name + ".csv")).string(), [&](std::ofstream& out) {
      write_evaluation_csv(out, model, evaluations, r.options.threads);
    });
  // The model file last: its presence means the model is complete (--resume relies on it).
  write_file_atomically(json_path.string(), [&](std::ofstream& out) { write_model_json(out, result, r.settings); });
  times.end("writing");
  ++tally.evaluated;
  tally.points += result.points;
  if(model.normals_estimated)
  {
    ++tally.estimated_models;
    tally.estimated_points += model.normals.size();
    tally.normal_trees += model.orientation_components;
  }
  else
    tally.estimated_points += model.zero_normals;
  progress.done(file.name, result.points, file.bytes,
                std::to_string(result.points) + " points, " + std::to_string(result.statistics.optimal.failures) +
                  " failures");
}

// Every model of the shard in turn, the next ones read ahead; a model that fails is recorded and
// the run goes on, but for an unusable output folder.
void evaluate_models(const Arguments& args, const Evaluate_request& r, Phase_times& times, Evaluate_tally& tally)
{
  std::uintmax_t total_bytes = 0;
  for(const auto& m : r.models)
    total_bytes += m.bytes;
  Progress progress(r.models.size(), total_bytes);
  auto resumed_model = [&](const Model_file& file) {
    return args.has("--resume") && fs::exists(fs::path(r.outdir) / "models" / (file.name + ".json"));
  };
  // with --threads 1, one thread; a catalog's tiles are read with their halos, on all threads
  const unsigned int threads = resolved_threads(r.options.threads);
  Read_ahead ahead(r.models, r.catalog || threads == 1 ? 0 : threads, r.options.threads,
                   [&](std::size_t i) { return !resumed_model(r.models[i]); },
                   [&](const Model_file& file, unsigned int reader_threads) {
                     SN::Normal_options o = r.normal_options;
                     o.threads = reader_threads;
                     return read_model(file.path, r.options.k_max, o, !args.has("--only-with-normals"));
                   });
  for(std::size_t index = 0; index < r.models.size(); ++index)
  {
    const Model_file& file = r.models[index];
    times.end("reading"); // what a skipped or failed model took
    if(resumed_model(file))
    {
      ++tally.resumed;
      progress.done(file.name, 0, file.bytes, "already done");
      continue;
    }
    try
    {
      evaluate_and_write(args, r, index, ahead, times, progress, tally);
    }
    catch(const Usage_error&)
    {
      throw; // the output folder is unusable: stop
    }
    catch(const Too_small_for_the_grid& e)
    {
      tally.too_small.push_back({file.name, e.needed, e.points});
      progress.done(file.name, 0, file.bytes,
                    "too small for the grid: " + std::to_string(e.points) + " distinct points, needs " +
                      std::to_string(e.needed));
    }
    catch(const std::bad_alloc&)
    {
      // what std::bad_alloc says is no message; the memory is back once the model is dropped
      tally.failures.push_back({file.name, "out of memory while evaluating the model"});
      progress.done(file.name, 0, file.bytes, "FAILED: out of memory while evaluating the model");
    }
    catch(const std::exception& e)
    {
      tally.failures.push_back({file.name, e.what()});
      progress.done(file.name, 0, file.bytes, std::string("FAILED: ") + e.what());
    }
  }
}

// run.json: when, where, how long and with what the shard was evaluated, and what became of its models.
void write_run_json(const Arguments& args, const Evaluate_request& r, const Evaluate_tally& tally,
                    const Phase_times& times, double seconds)
{
  Json run;
  run["command"] = "evaluate";
  run["date"] = iso_date();
  run["host"] = host_name();
  run["seconds"] = seconds;
  run["phases"] = times.json();
  run["threads"] = unsigned(r.options.threads);
  run["shard"] = std::to_string(r.shard_index) + "/" + std::to_string(r.shard_count);
  run["models_in_shard"] = r.models.size();
  run["models_evaluated"] = tally.evaluated;
  run["models_resumed"] = tally.resumed;
  run["models_failed"] = tally.failures.size();
  run["models_too_small"] = tally.too_small.size();
  run["points_evaluated"] = tally.points;
  run["models_with_estimated_normals"] = tally.estimated_models;
  run["points_with_estimated_normals"] = tally.estimated_points;
  run["spanning_forest_trees"] = tally.normal_trees;
  run["settings"] = settings_json(r.settings);
  Json& inputs = run["inputs"] = Json::array();
  for(const auto& input : args.positional())
    inputs.push_back(fs::absolute(input).lexically_normal().string());
  run["skipped_without_normals"] = tally.skipped_without_normals;
  write_file_atomically((fs::path(r.outdir) / "run.json").string(), [&](std::ofstream& out) { write_json(out, run); });
}

int run_evaluate(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT,
                       with_normal_options({"-o", "--output", "--repository", "--shard", "--threads", "--barycenter",
                                            "--k-min", "--k-max", "--fixed-k", "--a-grid", "--b-grid",
                                            "--angle-tolerance", "--catalog"}),
                       with_normal_flags({"-h", "--help", "--resume", "--per-point", "--only-with-normals"}),
                       NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, EVALUATE_USAGE))
  {
    std::cout << GRID_USAGE << NORMAL_USAGE;
    return EXIT_OK;
  }
  Evaluate_request r;
  read_evaluate_request(args, r);
  create_output_folder(r.outdir, "models");
  remove_temporary_files(r.outdir);

  CGAL::Real_timer timer;
  timer.start();
  Evaluate_tally tally;
  Phase_times times;
  evaluate_models(args, r, times, tally);
  timer.stop();

  write_file_atomically((fs::path(r.outdir) / "failures.json").string(),
                        [&](std::ofstream& out) { write_failures_json(out, tally.failures, tally.too_small); });
  write_summary({r.outdir}, r.repository, (fs::path(r.outdir) / "summary.json").string());
  write_run_json(args, r, tally, times, timer.time());
  std::cerr << r.outdir << ": " << tally.evaluated << " models evaluated, " << tally.resumed << " resumed, "
            << tally.too_small.size() << " too small for the grid, " << tally.failures.size() << " failed, "
            << tally.skipped_without_normals.size() << " skipped, " << tally.points << " points, "
            << Progress::duration(timer.time()) << " (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace

std::vector<SN::Point_evaluation> evaluate_model(const SN::Oriented_point_set& model, const Search_options& o,
                                                 const Evaluation_settings& s)
{
  namespace SNP = SN::parameters;
  std::vector<SN::Point_evaluation> result;
  result.reserve(model.points.size());
  with_model_neighborhoods(model, o, [&](const auto& np) {
    SN::evaluate_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(
      point_indices(model.points.size()), std::back_inserter(result),
      SNP::cut_off_angle(s.cut_off_angle, SNP::fixed_k(s.fixed_k, np)));
  });
  return result;
}

// The optimal CSV's columns, then the other weightings of the evaluation.
void write_evaluation_csv(std::ostream& out, const SN::Oriented_point_set& model,
                          const std::vector<SN::Point_evaluation>& evaluations, unsigned int threads)
{
  out << OPTIMAL_CSV_HEADER << ",label_equal,error_cut_off,k_cut_off,label_cut_off,error_fixed_k,label_fixed_k\n";
  write_text_rows(out, 0, evaluations.size(), threads, [&](Text_rows& rows, std::size_t i) {
    const SN::Point_evaluation& e = evaluations[i];
    write_optimal_row(rows, model.points[i], model.normals[i], e.optimal);
    rows.put(',').text(SN::dimensionality_name(e.equal_label)).put(',').number(e.error_cut_off).put(',');
    if(e.k_cut_off != 0)
      rows.integer(e.k_cut_off);
    rows.put(',').text(SN::dimensionality_name(e.cut_off_label)).put(',').number(e.error_fixed_k).put(',');
    rows.text(SN::dimensionality_name(e.fixed_k_label)).put('\n');
  });
}

int run_evaluate_command(int argc, char** argv) { return run_evaluate(argc, argv); }

} // namespace sigmoid_tool
