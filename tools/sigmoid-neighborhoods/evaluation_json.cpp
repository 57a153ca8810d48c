// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// evaluation_json.h, compiled once for the tool.

#include "evaluation_json.h"

namespace sigmoid_tool {

Json error_statistics_json(const SN::Error_statistics& s)
{
  Json j;
  j["count"] = s.count;
  j["failures"] = s.failures;
  j["sum"] = s.sum;
  j["sum_of_squares"] = s.sum_of_squares;
  j["min"] = s.min;
  j["max"] = s.max;
  j["mean"] = s.mean();
  j["standard_deviation"] = s.standard_deviation();
  Json& labels = j["labels"];
  labels["linear"] = s.labels[0];
  labels["planar"] = s.labels[1];
  labels["scattered"] = s.labels[2];
  if(!s.k_histogram.empty())
    j["k_histogram"] = s.k_histogram;
  return j;
}

Json settings_json(const Evaluation_settings& s)
{
  Json j;
  j["k_min"] = s.k_min;
  j["k_max"] = s.k_max;
  j["fixed_k"] = s.fixed_k;
  j["barycenter"] = s.barycenter;
  j["angle_tolerance"] = s.angle_tolerance;
  j["cut_off_angle"] = s.cut_off_angle;
  j["a_grid"] = s.a_grid;
  j["b_grid"] = s.b_grid;
  j["normals"] = s.normals;
  j["normal_neighbors"] = s.normal_neighbors;
  j["orientation"] = s.orientation;
  if(!s.viewpoint.empty())
    j["viewpoint"] = s.viewpoint;
  j["line_angles"] = s.line_angles;
  return j;
}

Json statistics_json(const SN::Evaluation_statistics& s)
{
  Json j;
  j["points"] = s.points;
  j["equal"] = error_statistics_json(s.equal);
  j["cut_off"] = error_statistics_json(s.cut_off);
  j["optimal"] = error_statistics_json(s.optimal);
  j["fixed_k"] = error_statistics_json(s.fixed_k);
  const auto km = s.k_mean_and_deviation();
  j["k_mean"] = km.first;
  j["k_standard_deviation"] = km.second;
  Json& t = j["table3"];
  t["a_zero"] = s.a_lowering[0];
  t["a_lower_valid"] = s.a_lowering[1];
  t["a_lower_fails"] = s.a_lowering[2];
  t["b_equals_a"] = s.b_lowering[0];
  t["b_lower_valid"] = s.b_lowering[1];
  t["b_lower_fails"] = s.b_lowering[2];
  j["pair_k_histogram"] = s.pair_k_histogram;
  return j;
}

Json model_json(const Model_result& m, const Evaluation_settings& settings)
{
  Json j;
  j["model"] = m.model;
  j["points"] = m.statistics.points;
  j["input_vertices"] = m.input_vertices;
  j["merged_duplicates"] = m.merged_duplicates;
  j["dropped_vertices"] = m.dropped_vertices;
  j["normals"] = m.normals;
  if(m.normals == "estimated")
  {
    j["normal_method"] = m.normal_method;
    j["normal_neighbors"] = m.normal_neighbors;
    j["orientation"] = m.orientation;
    j["normal_components"] = m.normal_components;
  }
  j["zero_normals"] = m.zero_normals;
  j["failures"] = m.statistics.optimal.failures;
  j["k_standard_deviation"] = m.k_standard_deviation;
  j["settings"] = settings_json(settings);
  j["statistics"] = statistics_json(m.statistics);
  return j;
}

void write_model_json(std::ostream& out, const Model_result& m, const Evaluation_settings& settings)
{
  write_json(out, model_json(m, settings));
}

Json small_models_json(const std::vector<Small_model>& small)
{
  Json list = Json::array();
  for(const auto& m : small)
    list.push_back(Json{{"model", m.model}, {"needed", m.needed}, {"points", m.points}});
  return list;
}

void write_failures_json(std::ostream& out, std::vector<Model_failure> failures, std::vector<Small_model> small)
{
  sort_by_model(failures);
  sort_by_model(small);
  Json j;
  Json& list = j["failures"] = Json::array();
  for(const auto& f : failures)
    list.push_back(Json{{"model", f.model}, {"message", f.message}});
  j["too_small"] = small_models_json(small);
  write_json(out, j);
}

std::uint64_t number_of_pairs(const std::vector<double>& a, const std::vector<double>& b)
{
  std::uint64_t n = 0;
  std::size_t first_b = 0;
  for(double x : a)
  {
    while(first_b < b.size() && b[first_b] < x)
      ++first_b;
    n += b.size() - first_b;
  }
  return n;
}

std::vector<double> read_grid(const Json_object& t, const char* key)
{
  const std::vector<double> grid = t.numbers(key, std::numeric_limits<std::size_t>::max());
  if(grid.empty())
    t.fail(t.name(key), "is empty, expected at least one angle");
  for(std::size_t i = 0; i < grid.size(); ++i)
  {
    if(!(grid[i] >= 0. && grid[i] <= CGAL_PI))
      t.fail(t.name(key) + "[" + std::to_string(i) + "]", "is " + std::to_string(grid[i]) + ", not an angle in [0, pi]");
    if(i > 0 && !(grid[i - 1] < grid[i]))
      t.fail(t.name(key), "is not sorted and without repetitions, as the tool writes its grids");
  }
  return grid;
}

Evaluation_settings read_settings(const Json_object& file)
{
  const Json_object t = file.object("settings");
  t.only({"k_min", "k_max", "fixed_k", "barycenter", "angle_tolerance", "cut_off_angle", "a_grid", "b_grid", "normals",
          "normal_neighbors", "orientation", "viewpoint", "line_angles"});
  Evaluation_settings s;
  s.k_min = unsigned(t.integer("k_min", 1, LARGEST_EVALUATION_K));
  s.k_max = unsigned(t.integer("k_max", s.k_min, LARGEST_EVALUATION_K));
  s.fixed_k = unsigned(t.integer("fixed_k", s.k_min, s.k_max));
  s.barycenter = t.choice("barycenter", {"weighted", "unweighted"});
  s.angle_tolerance = t.number("angle_tolerance", -1.);
  if(!(s.angle_tolerance >= 0. && s.angle_tolerance < CGAL_PI))
    t.fail(t.name("angle_tolerance"), "is not an angle in [0, pi)");
  s.cut_off_angle = t.number("cut_off_angle", -1.);
  if(!(s.cut_off_angle >= 0. && s.cut_off_angle <= CGAL_PI))
    t.fail(t.name("cut_off_angle"), "is not an angle in [0, pi]");
  s.a_grid = read_grid(t, "a_grid");
  s.b_grid = read_grid(t, "b_grid");
  if(s.a_grid.front() > s.b_grid.back())
    t.fail(t.name("a_grid"), "and b_grid have no pair a <= b");
  // absent from the files of earlier versions, which estimated normals otherwise: "" never merges with them
  s.normals = t.has("normals") ? t.choice("normals", {"auto", "file", "pca", "jet"}) : "";
  s.normal_neighbors = unsigned(t.integer_or("normal_neighbors", 0, 0, LARGEST_EVALUATION_K));
  s.orientation = t.has("orientation") ? t.choice("orientation", {"mst", "viewpoint", "up", "none"}) : "";
  if(t.has("viewpoint"))
  {
    s.viewpoint = t.numbers("viewpoint", 3);
    if(s.viewpoint.size() != 3 || s.orientation != "viewpoint")
      t.fail(t.name("viewpoint"), "must be 3 coordinates, with the orientation viewpoint");
  }
  else if(s.orientation == "viewpoint")
    t.fail(t.name("viewpoint"), "is missing, though the orientation is viewpoint");
  s.line_angles = t.has("line_angles") ? t.boolean("line_angles") : false;
  return s;
}

void read_error_statistics(const Json_object& t, std::size_t k_sizes, std::uint64_t points,
                                  SN::Error_statistics& s)
{
  t.only({"count", "failures", "sum", "sum_of_squares", "min", "max", "mean", "standard_deviation", "labels",
          "k_histogram"});
  s.count = t.integer("count");
  s.failures = t.integer("failures");
  if(std::uint64_t(s.count) + s.failures != points)
    t.fail(t.name("count"), "and failures add up to " + std::to_string(s.count + s.failures) + ", not to the " +
                              std::to_string(points) + " points");
  s.sum = t.number("sum", -1.);
  s.sum_of_squares = t.number("sum_of_squares", -1.);
  if(!(s.sum >= 0. && s.sum_of_squares >= 0.))
    t.fail(t.name("sum"), "or sum_of_squares is negative or null");
  const double inf = std::numeric_limits<double>::infinity();
  s.min = t.number("min", inf);
  s.max = t.number("max", -inf);
  if((s.count == 0) != (s.min == inf) || (s.count == 0) != (s.max == -inf))
    t.fail(t.name("min"), "and max must be null exactly when count is 0");
  if(s.count > 0 && !(0. <= s.min && s.min <= s.max))
    t.fail(t.name("min"), "is negative or larger than max");
  // written from the sums: anything else is an edited file
  auto check_equal = [&](const char* key, double expected) {
    const double v = t.number(key, std::numeric_limits<double>::quiet_NaN());
    if(!(v == expected || (std::isnan(v) && std::isnan(expected))))
      t.fail(t.name(key), "is not what count, sum and sum_of_squares give");
  };
  check_equal("mean", s.mean());
  check_equal("standard_deviation", s.standard_deviation());
  const Json_object labels = t.object("labels");
  labels.only({"linear", "planar", "scattered"});
  s.labels = {{labels.integer("linear"), labels.integer("planar"), labels.integer("scattered")}};
  if(s.labels[0] + s.labels[1] + s.labels[2] > s.count)
    t.fail(t.name("labels"), "count more points than count");
  s.k_histogram.clear();
  if(k_sizes > 0)
  {
    const std::vector<std::uint64_t> h = t.integers("k_histogram", k_sizes);
    s.k_histogram.assign(h.begin(), h.end());
    std::uint64_t total = 0;
    for(std::uint64_t c : h)
      total += c;
    if(total > s.count)
      t.fail(t.name("k_histogram"), "counts more points than count");
  }
  else if(t.has("k_histogram"))
    t.fail(t.name("k_histogram"), "is not written for a fixed k");
}

SN::Evaluation_statistics read_statistics(const Json_object& file, const Evaluation_settings& settings)
{
  const Json_object t = file.object("statistics");
  t.only({"points", "equal", "cut_off", "optimal", "fixed_k", "k_mean", "k_standard_deviation", "table3",
          "pair_k_histogram"});
  // the sizes first: the statistics allocate what the grids and k range announce
  const std::uint64_t k_sizes = std::uint64_t(settings.k_max) - settings.k_min + 1;
  const std::uint64_t pairs = number_of_pairs(settings.a_grid, settings.b_grid);
  const std::size_t histogram = t.array("pair_k_histogram").size();
  if(pairs * k_sizes != histogram)
    t.fail(t.name("pair_k_histogram"), "has " + std::to_string(histogram) + " entries, not the " +
                                         std::to_string(pairs) + " pairs (a, b) times " + std::to_string(k_sizes) +
                                         " values of k of the settings");
  const Json_object optimal = t.object("optimal");
  if(optimal.array("k_histogram").size() != k_sizes)
    optimal.fail(optimal.name("k_histogram"), "does not have the " + std::to_string(k_sizes) + " entries of k_min to k_max");
  SN::Evaluation_statistics s(settings.k_min, settings.k_max, settings.a_grid, settings.b_grid);
  s.points = t.integer("points");
  read_error_statistics(t.object("equal"), k_sizes, s.points, s.equal);
  read_error_statistics(t.object("cut_off"), k_sizes, s.points, s.cut_off);
  read_error_statistics(optimal, k_sizes, s.points, s.optimal);
  read_error_statistics(t.object("fixed_k"), 0, s.points, s.fixed_k);
  const std::vector<std::uint64_t> h = t.integers("pair_k_histogram", histogram);
  s.pair_k_histogram.assign(h.begin(), h.end());
  const Json_object table3 = t.object("table3");
  table3.only({"a_zero", "a_lower_valid", "a_lower_fails", "b_equals_a", "b_lower_valid", "b_lower_fails"});
  s.a_lowering = {{table3.integer("a_zero"), table3.integer("a_lower_valid"), table3.integer("a_lower_fails")}};
  s.b_lowering = {{table3.integer("b_equals_a"), table3.integer("b_lower_valid"), table3.integer("b_lower_fails")}};
  // each point with an optimum counts once in both groups of Table 3, at most once in Figure 4
  const std::uint64_t with_optimum = s.a_lowering[0] + s.a_lowering[1] + s.a_lowering[2];
  if(with_optimum > s.points || with_optimum != s.b_lowering[0] + s.b_lowering[1] + s.b_lowering[2])
    t.fail(t.name("table3"), "counts differ between a and b, or exceed the points");
  std::uint64_t in_pairs = 0;
  for(std::uint64_t c : h)
    in_pairs += c;
  if(in_pairs > with_optimum)
    t.fail(t.name("pair_k_histogram"), "counts more points than table3");
  const auto km = s.k_mean_and_deviation();
  for(const auto& key : {std::make_pair("k_mean", km.first), std::make_pair("k_standard_deviation", km.second)})
  {
    const double v = t.number(key.first, std::numeric_limits<double>::quiet_NaN());
    if(!(v == key.second || (std::isnan(v) && std::isnan(key.second))))
      t.fail(t.name(key.first), "is not what optimal.k_histogram gives");
  }
  return s;
}

Model_result read_model_json(const std::string& path, const std::string& name, Evaluation_settings& settings)
{
  const Json_value j = read_json_file(path, LARGEST_MODEL_FILE);
  const Json_object t(j, path);
  t.only({"model", "points", "input_vertices", "merged_duplicates", "dropped_vertices", "normals", "normal_method",
          "normal_neighbors", "orientation", "normal_components", "zero_normals", "failures", "k_standard_deviation",
          "settings", "statistics"});
  settings = read_settings(t);
  Model_result m;
  m.model = t.string("model");
  if(m.model != as_written(name))
    t.fail("model", "is '" + m.model + "', but the file is that of model '" + name + "'");
  m.model = name;
  m.statistics = read_statistics(t, settings);
  m.points = t.integer("points");
  if(m.points != m.statistics.points)
    t.fail("points", "is not statistics.points");
  m.input_vertices = t.integer("input_vertices");
  m.merged_duplicates = t.integer("merged_duplicates");
  m.dropped_vertices = t.integer("dropped_vertices");
  if(std::uint64_t(m.points) + m.merged_duplicates + m.dropped_vertices > m.input_vertices)
    t.fail("input_vertices", "is fewer than the points, merged duplicates and dropped vertices");
  m.normals = t.choice("normals", {"mesh", "file", "estimated"});
  if(m.normals == "estimated")
  {
    m.normal_method = t.choice("normal_method", {"pca", "jet"});
    m.normal_neighbors = unsigned(t.integer("normal_neighbors", 1, LARGEST_EVALUATION_K));
    m.orientation = t.choice("orientation", {"mst", "viewpoint", "up", "none"});
    m.normal_components = t.integer("normal_components", 0, m.points);
  }
  else
    for(const char* key : {"normal_method", "normal_neighbors", "orientation", "normal_components"})
      if(t.has(key))
        t.fail(key, "is written for estimated normals only");
  // absent from the files of earlier versions, which refused zero normals
  m.zero_normals = t.integer_or("zero_normals", 0, 0, m.points);
  if(m.normals == "mesh" && m.zero_normals > 0)
    t.fail("zero_normals", "is not 0 for mesh normals");
  if(t.integer("failures") != m.statistics.optimal.failures)
    t.fail("failures", "is not statistics.optimal.failures");
  m.k_standard_deviation = t.number("k_standard_deviation", std::numeric_limits<double>::quiet_NaN());
  const double sd = m.statistics.k_mean_and_deviation().second;
  if(!(m.k_standard_deviation == sd || (std::isnan(sd) && std::isnan(m.k_standard_deviation))))
    t.fail("k_standard_deviation", "is not statistics.k_standard_deviation");
  return m;
}

void read_failures_json(const std::string& path, std::vector<Model_failure>& failures,
                               std::vector<Small_model>& small)
{
  failures.clear();
  small.clear();
  if(!fs::exists(path))
    return;
  const Json_value j = read_json_file(path, LARGEST_FAILURES_FILE);
  const Json_object t(j, path);
  t.only({"failures", "too_small"});
  const Json_value& list = t.array("failures");
  for(std::size_t i = 0; i < list.size(); ++i)
  {
    const Json_object f(list[i], path, "failures[" + std::to_string(i) + "]");
    f.only({"model", "message"});
    failures.push_back({f.string("model"), f.string("message", 65536)});
  }
  if(!t.has("too_small"))
    return;
  const Json_value& smalls = t.array("too_small");
  for(std::size_t i = 0; i < smalls.size(); ++i)
  {
    const Json_object f(smalls[i], path, "too_small[" + std::to_string(i) + "]");
    f.only({"model", "needed", "points"});
    Small_model m;
    m.model = f.string("model");
    m.needed = f.integer("needed", 2, LARGEST_EVALUATION_K + 1);
    m.points = f.integer("points", 0, m.needed - 1);
    small.push_back(m);
  }
}

std::vector<std::pair<std::string, std::string>> model_files(const std::string& folder)
{
  std::vector<std::pair<std::string, std::string>> result;
  const fs::path root = fs::path(folder) / "models";
  if(!fs::exists(root))
    return result;
  for(const auto& entry : fs::recursive_directory_iterator(root))
  {
    const fs::path p = entry.path();
    if(entry.is_regular_file() && p.extension() == ".json")
    {
      std::string model = fs::relative(p, root).generic_string();
      model.resize(model.size() - 5); // ".json"
      result.emplace_back(model, p.string());
    }
  }
  std::sort(result.begin(), result.end());
  return result;
}

Evaluation_contents read_evaluation_folders(const std::vector<std::string>& folders)
{
  std::vector<std::pair<std::string, std::string>> files;
  Evaluation_contents c;
  // (model, file that names it): a model evaluated or failed in two places is refused
  std::vector<std::pair<std::string, std::string>> names;
  for(const auto& folder : folders)
  {
    const auto f = model_files(folder);
    files.insert(files.end(), f.begin(), f.end());
    for(const auto& m : f)
      names.emplace_back(m.first, m.second);
    const std::string failures_path = (fs::path(folder) / "failures.json").string();
    std::vector<Model_failure> failed;
    std::vector<Small_model> small;
    read_failures_json(failures_path, failed, small);
    c.failures.insert(c.failures.end(), failed.begin(), failed.end());
    c.small.insert(c.small.end(), small.begin(), small.end());
    for(const auto& x : failed)
      names.emplace_back(x.model, failures_path);
    for(const auto& x : small)
      names.emplace_back(x.model, failures_path);
  }
  std::sort(names.begin(), names.end());
  for(std::size_t i = 1; i < names.size(); ++i)
    if(names[i].first == names[i - 1].first)
      throw Usage_error(names[i].second + ": model " + names[i].first + " is also in " + names[i - 1].second +
                        ": a model is evaluated in one folder only");
  std::sort(files.begin(), files.end());
  for(const auto& f : files)
  {
    Evaluation_settings s;
    Model_result m = read_model_json(f.second, f.first, s);
    if(!c.any_model)
    {
      c.settings = s;
      c.total = SN::Evaluation_statistics(s.k_min, s.k_max, s.a_grid, s.b_grid);
      c.any_model = true;
    }
    else if(!(s == c.settings))
      throw Usage_error(f.second + " was computed with other settings than the other models");
    c.total.merge(m.statistics);
    c.merged += m.merged_duplicates;
    c.dropped += m.dropped_vertices;
    c.estimated += (m.normals == "estimated");
    c.estimated_points += m.normals == "estimated" ? m.points : m.zero_normals;
    c.with_zero_normals += (m.zero_normals > 0);
    c.zero_normals += m.zero_normals;
    m.statistics = SN::Evaluation_statistics();
    c.models.push_back(std::move(m));
  }
  sort_by_model(c.failures);
  sort_by_model(c.small);
  return c;
}

Json summary_json(const Evaluation_contents& c, const std::string& repository)
{
  Json j;
  j["repository"] = repository;
  j["models"] = c.models.size();
  j["failed_models"] = c.failures.size();
  j["too_small_models"] = c.small.size();
  j["points"] = c.total.points;
  j["merged_duplicates"] = c.merged;
  j["dropped_vertices"] = c.dropped;
  j["models_with_estimated_normals"] = c.estimated;
  j["points_with_estimated_normals"] = c.estimated_points;
  j["models_with_zero_normals"] = c.with_zero_normals;
  j["zero_normals"] = c.zero_normals;
  if(c.any_model)
  {
    j["settings"] = settings_json(c.settings);
    j["statistics"] = statistics_json(c.total);
  }
  Json& per_model = j["per_model"] = Json::array();
  for(const auto& m : c.models)
    per_model.push_back(Json{{"model", m.model}, {"points", m.points}, {"k_standard_deviation", m.k_standard_deviation}});
  Json& failed = j["failed"] = Json::array();
  for(const auto& f : c.failures)
    failed.push_back(f.model);
  j["too_small"] = small_models_json(c.small);
  return j;
}

void write_summary(const std::vector<std::string>& folders, const std::string& repository,
                          const std::string& summary_path)
{
  const Json j = summary_json(read_evaluation_folders(folders), repository);
  write_file_atomically(summary_path, [&](std::ofstream& out) { write_json(out, j); });
}

std::string read_summary_repository(const std::string& folder)
{
  const std::string path = (fs::path(folder) / "summary.json").string();
  const Json_value j = read_json_file(path, LARGEST_SUMMARY_FILE);
  return Json_object(j, path).string("repository");
}

Json_value read_summary(const std::string& folder, Evaluation_contents& contents)
{
  const std::string path = (fs::path(folder) / "summary.json").string();
  // the model files first: they bound the summary's size before it is parsed
  contents = read_evaluation_folders({folder});
  const std::uintmax_t expected_bytes = summary_json(contents, std::string()).dump(2).size();
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if(!ec && bytes > 2 * expected_bytes + 65536)
    throw json_error(path, "a file of " + std::to_string(bytes) + " bytes, more than twice the " +
                             std::to_string(expected_bytes) + " of the summary its model files give");
  const Json_value j = read_json_file(path, LARGEST_SUMMARY_FILE);
  const std::string repository = Json_object(j, path).string("repository");
  // the summary as written, NaN as null: compared value for value
  const Json_value expected =
    Json_value::parse(summary_json(contents, repository).dump(-1, ' ', false, Json::error_handler_t::replace));
  if(j != expected)
  {
    const Json_value patch = Json_value::diff(expected, j);
    const std::string where = patch.empty() ? std::string("/") : patch[0].value("path", std::string("/"));
    throw json_error(path, "does not match the model files and failures.json of its folder (at " + where +
                             "); 'sigmoid-neighborhoods merge " + folder + " -o " + folder + "' rewrites it");
  }
  return j;
}

Json_value read_summary(const std::string& folder)
{
  Evaluation_contents contents;
  return read_summary(folder, contents);
}
} // namespace sigmoid_tool
