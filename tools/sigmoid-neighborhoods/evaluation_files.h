// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The files of an evaluation folder: models/<path>.json per model, summary.json, failures.json,
// run.json. The summary is always rebuilt from the model files in the order of their paths, so
// equal inputs give equal summaries however the models were sharded, resumed or merged.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_FILES_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_FILES_H

#include "command_line.h"
#include "json.h"
#include "model_input.h"

#include <CGAL/Sigmoid_neighborhoods/evaluation_statistics.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace fs = std::filesystem;

// The sharp cut-off of the evaluation, `a = b = arccos(0.9)`: the cut-off the paper compares with
// (and Yadav et al.'s normal filter uses).
constexpr double EVALUATION_CUT_OFF_COSINE = 0.9;

// What must be equal for two evaluations to merge.
struct Evaluation_settings
{
  unsigned int k_min = SN::DEFAULT_K_MIN, k_max = SN::DEFAULT_K_MAX, fixed_k = SN::DEFAULT_K_MAX;
  std::string barycenter = "weighted";
  double angle_tolerance = SN::DEFAULT_ANGLE_TOLERANCE;
  double cut_off_angle = 0.;
  std::vector<double> a_grid, b_grid;
  // the normals of files without them, and the angle of the weights (model_input.h)
  std::string normals = "auto";
  unsigned int normal_neighbors = SN::DEFAULT_ESTIMATION_NEIGHBORS;
  std::string orientation = "mst";
  std::vector<double> viewpoint; // x, y, z with orientation "viewpoint"
  bool line_angles = false;

  bool operator==(const Evaluation_settings& o) const
  {
    return k_min == o.k_min && k_max == o.k_max && fixed_k == o.fixed_k && barycenter == o.barycenter &&
           angle_tolerance == o.angle_tolerance && cut_off_angle == o.cut_off_angle && a_grid == o.a_grid &&
           b_grid == o.b_grid && normals == o.normals && normal_neighbors == o.normal_neighbors &&
           orientation == o.orientation && viewpoint == o.viewpoint && line_angles == o.line_angles;
  }
};

inline void set_normal_settings(Evaluation_settings& s, const SN::Normal_options& o, bool line_angles)
{
  s.normals = o.source == SN::Normal_source::AUTO        ? "auto"
              : o.source == SN::Normal_source::FROM_FILE ? "file"
              : o.source == SN::Normal_source::JET       ? "jet"
                                                         : "pca";
  s.normal_neighbors = o.neighbors;
  s.orientation = orientation_name(o.orientation);
  s.viewpoint.clear();
  if(o.orientation == SN::Normal_orientation::VIEWPOINT)
    s.viewpoint = {o.viewpoint.x(), o.viewpoint.y(), o.viewpoint.z()};
  s.line_angles = line_angles;
}

// The normal options an evaluation was run with, for recomputing one of its models.
inline SN::Normal_options normal_options(const Evaluation_settings& s, unsigned int threads)
{
  SN::Normal_options o;
  o.source = s.normals.empty() ? SN::Normal_source::AUTO : read_normal_source(s.normals);
  o.neighbors = s.normal_neighbors == 0 ? SN::DEFAULT_ESTIMATION_NEIGHBORS : s.normal_neighbors;
  o.orientation = s.orientation == "viewpoint" ? SN::Normal_orientation::VIEWPOINT
                  : s.orientation == "none"    ? SN::Normal_orientation::NONE
                  : s.orientation == "up"      ? SN::Normal_orientation::UPWARD
                                               : SN::Normal_orientation::SPANNING_FOREST;
  if(s.viewpoint.size() == 3)
    o.viewpoint = SN::Oriented_point_set::Point_3(s.viewpoint[0], s.viewpoint[1], s.viewpoint[2]);
  o.threads = threads;
  return o;
}

struct Model_result
{
  std::string model; // path relative to its input root, '/'-separated
  std::size_t points = 0, input_vertices = 0, merged_duplicates = 0, dropped_vertices = 0;
  std::string normals; // mesh, file or estimated
  // estimated normals: pca or jet, their k, their orientation (mst, viewpoint, none) and its trees
  std::string normal_method, orientation;
  unsigned int normal_neighbors = 0;
  std::size_t normal_components = 0;
  double k_standard_deviation = std::numeric_limits<double>::quiet_NaN();
  SN::Evaluation_statistics statistics;
};

// ------------------------------------------------------------------------------------------------
// writing

inline void write_error_statistics(Json_writer& w, const char* key, const SN::Error_statistics& s)
{
  w.begin_object(key).value("count", s.count).value("failures", s.failures);
  w.value("sum", s.sum).value("sum_of_squares", s.sum_of_squares).value("min", s.min).value("max", s.max);
  w.value("mean", s.mean()).value("standard_deviation", s.standard_deviation());
  w.begin_object("labels").value("linear", s.labels[0]).value("planar", s.labels[1]).value("scattered", s.labels[2]).end_object();
  if(!s.k_histogram.empty())
    w.array("k_histogram", s.k_histogram);
  w.end_object();
}

inline void write_settings(Json_writer& w, const Evaluation_settings& s)
{
  w.begin_object("settings").value("k_min", s.k_min).value("k_max", s.k_max).value("fixed_k", s.fixed_k);
  w.value("barycenter", s.barycenter).value("angle_tolerance", s.angle_tolerance);
  w.value("cut_off_angle", s.cut_off_angle).array("a_grid", s.a_grid).array("b_grid", s.b_grid);
  w.value("normals", s.normals).value("normal_neighbors", s.normal_neighbors).value("orientation", s.orientation);
  if(!s.viewpoint.empty())
    w.array("viewpoint", s.viewpoint);
  w.value("line_angles", s.line_angles).end_object();
}

inline void write_statistics(Json_writer& w, const SN::Evaluation_statistics& s)
{
  w.begin_object("statistics").value("points", s.points);
  write_error_statistics(w, "equal", s.equal);
  write_error_statistics(w, "cut_off", s.cut_off);
  write_error_statistics(w, "optimal", s.optimal);
  write_error_statistics(w, "fixed_k", s.fixed_k);
  const auto km = s.k_mean_and_deviation();
  w.value("k_mean", km.first).value("k_standard_deviation", km.second);
  w.begin_object("table3");
  w.value("a_zero", s.a_lowering[0]).value("a_lower_valid", s.a_lowering[1]);
  w.value("a_lower_fails", s.a_lowering[2]).value("b_equals_a", s.b_lowering[0]);
  w.value("b_lower_valid", s.b_lowering[1]).value("b_lower_fails", s.b_lowering[2]);
  w.end_object();
  w.array("pair_k_histogram", s.pair_k_histogram);
  w.end_object();
}

inline void write_model_json(std::ostream& out, const Model_result& m, const Evaluation_settings& settings)
{
  Json_writer w(out);
  w.begin_object().value("model", m.model).value("points", m.statistics.points);
  w.value("input_vertices", m.input_vertices).value("merged_duplicates", m.merged_duplicates);
  w.value("dropped_vertices", m.dropped_vertices).value("normals", m.normals);
  if(m.normals == "estimated")
  {
    w.value("normal_method", m.normal_method).value("normal_neighbors", m.normal_neighbors);
    w.value("orientation", m.orientation).value("normal_components", m.normal_components);
  }
  w.value("failures", m.statistics.optimal.failures);
  w.value("k_standard_deviation", m.k_standard_deviation);
  write_settings(w, settings);
  write_statistics(w, m.statistics);
  w.end_object().finish();
}

// ------------------------------------------------------------------------------------------------
// reading

inline Evaluation_settings read_settings(const Json& tree)
{
  Evaluation_settings s;
  const Json& t = tree.get_child("settings");
  s.k_min = t.get<unsigned int>("k_min");
  s.k_max = t.get<unsigned int>("k_max");
  s.fixed_k = t.get<unsigned int>("fixed_k");
  s.barycenter = t.get<std::string>("barycenter");
  s.angle_tolerance = json_double(t, "angle_tolerance", 0.);
  s.cut_off_angle = json_double(t, "cut_off_angle", 0.);
  s.a_grid = json_double_array(t, "a_grid");
  s.b_grid = json_double_array(t, "b_grid");
  // absent from the files of earlier versions, which estimated normals otherwise: "" never merges with them
  s.normals = t.get<std::string>("normals", "");
  s.normal_neighbors = t.get<unsigned int>("normal_neighbors", 0);
  s.orientation = t.get<std::string>("orientation", "");
  if(t.get_child_optional("viewpoint"))
    s.viewpoint = json_double_array(t, "viewpoint");
  s.line_angles = t.get<bool>("line_angles", false);
  return s;
}

inline void read_error_statistics(const Json& t, SN::Error_statistics& s)
{
  s.count = json_size(t, "count");
  s.failures = json_size(t, "failures");
  s.sum = json_double(t, "sum", 0.);
  s.sum_of_squares = json_double(t, "sum_of_squares", 0.);
  s.min = json_double(t, "min", std::numeric_limits<double>::infinity());
  s.max = json_double(t, "max", -std::numeric_limits<double>::infinity());
  s.labels = {{json_size(t, "labels.linear"), json_size(t, "labels.planar"), json_size(t, "labels.scattered")}};
  if(t.get_child_optional("k_histogram"))
    s.k_histogram = json_array<std::size_t>(t, "k_histogram");
}

inline Model_result read_model_json(const std::string& path, Evaluation_settings& settings)
{
  const Json tree = read_json(path);
  settings = read_settings(tree);
  Model_result m;
  m.model = tree.get<std::string>("model");
  m.input_vertices = json_size(tree, "input_vertices");
  m.merged_duplicates = json_size(tree, "merged_duplicates");
  m.dropped_vertices = json_size(tree, "dropped_vertices");
  m.normals = tree.get<std::string>("normals");
  m.normal_method = tree.get<std::string>("normal_method", "");
  m.normal_neighbors = tree.get<unsigned int>("normal_neighbors", 0);
  m.orientation = tree.get<std::string>("orientation", "");
  m.normal_components = tree.get<std::size_t>("normal_components", 0);
  m.k_standard_deviation = json_double(tree, "k_standard_deviation", std::numeric_limits<double>::quiet_NaN());
  SN::Evaluation_statistics& s = m.statistics;
  s = SN::Evaluation_statistics(settings.k_min, settings.k_max, settings.a_grid, settings.b_grid);
  const Json& t = tree.get_child("statistics");
  s.points = json_size(t, "points");
  m.points = s.points;
  read_error_statistics(t.get_child("equal"), s.equal);
  read_error_statistics(t.get_child("cut_off"), s.cut_off);
  read_error_statistics(t.get_child("optimal"), s.optimal);
  read_error_statistics(t.get_child("fixed_k"), s.fixed_k);
  s.a_lowering = {{json_size(t, "table3.a_zero"), json_size(t, "table3.a_lower_valid"), json_size(t, "table3.a_lower_fails")}};
  s.b_lowering = {{json_size(t, "table3.b_equals_a"), json_size(t, "table3.b_lower_valid"), json_size(t, "table3.b_lower_fails")}};
  s.pair_k_histogram = json_array<std::size_t>(t, "pair_k_histogram");
  if(s.pair_k_histogram.size() != s.pairs().size() * (s.k_max - s.k_min + 1))
    throw std::runtime_error(path + ": pair_k_histogram has the wrong size");
  return m;
}

struct Model_failure
{
  std::string model, message;
};

inline void write_failures_json(std::ostream& out, std::vector<Model_failure> failures)
{
  std::sort(failures.begin(), failures.end(),
            [](const Model_failure& x, const Model_failure& y) { return x.model < y.model; });
  Json_writer w(out);
  w.begin_object().begin_array("failures");
  for(const auto& f : failures)
    w.begin_object().value("model", f.model).value("message", f.message).end_object();
  w.end_array().end_object().finish();
}

inline std::vector<Model_failure> read_failures_json(const std::string& path)
{
  std::vector<Model_failure> result;
  if(!fs::exists(path))
    return result;
  const Json tree = read_json(path);
  for(const auto& child : tree.get_child("failures"))
    result.push_back({child.second.get<std::string>("model"), child.second.get<std::string>("message")});
  return result;
}

// Every model file under `folder`/models, as (model path, file path).
inline std::vector<std::pair<std::string, std::string>> model_files(const std::string& folder)
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

// summary.json of the models of `folders` (one folder, or the shards of one repository).
inline void write_summary(const std::vector<std::string>& folders, const std::string& repository,
                          const std::string& summary_path)
{
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<Model_failure> failures;
  for(const auto& folder : folders)
  {
    const auto f = model_files(folder);
    files.insert(files.end(), f.begin(), f.end());
    const auto m = read_failures_json((fs::path(folder) / "failures.json").string());
    failures.insert(failures.end(), m.begin(), m.end());
  }
  std::sort(files.begin(), files.end());
  for(std::size_t i = 1; i < files.size(); ++i)
    if(files[i].first == files[i - 1].first)
      throw Usage_error("model " + files[i].first + " is in two of the folders to merge");

  bool first = true;
  Evaluation_settings settings;
  SN::Evaluation_statistics total;
  std::size_t merged = 0, dropped = 0, estimated = 0;
  std::vector<Model_result> models;
  for(const auto& f : files)
  {
    Evaluation_settings s;
    Model_result m = read_model_json(f.second, s);
    if(first)
    {
      settings = s;
      total = SN::Evaluation_statistics(s.k_min, s.k_max, s.a_grid, s.b_grid);
      first = false;
    }
    else if(!(s == settings))
      throw Usage_error(f.second + " was computed with other settings than the other models");
    total.merge(m.statistics);
    merged += m.merged_duplicates;
    dropped += m.dropped_vertices;
    estimated += (m.normals == "estimated");
    m.statistics = SN::Evaluation_statistics();
    models.push_back(std::move(m));
  }
  std::sort(failures.begin(), failures.end(),
            [](const Model_failure& x, const Model_failure& y) { return x.model < y.model; });

  write_file_atomically(summary_path, [&](std::ofstream& out) {
    Json_writer w(out);
    w.begin_object()
      .value("repository", repository)
      .value("models", models.size())
      .value("failed_models", failures.size())
      .value("points", total.points)
      .value("merged_duplicates", merged)
      .value("dropped_vertices", dropped)
      .value("models_with_estimated_normals", estimated);
    if(!first)
    {
      write_settings(w, settings);
      write_statistics(w, total);
    }
    w.begin_array("per_model");
    for(const auto& m : models)
      w.begin_object()
        .value("model", m.model)
        .value("points", m.points)
        .value("k_standard_deviation", m.k_standard_deviation)
        .end_object();
    w.end_array();
    w.begin_array("failed");
    for(const auto& f : failures)
      w.value(nullptr, f.model);
    w.end_array();
    w.end_object().finish();
  });
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_FILES_H
