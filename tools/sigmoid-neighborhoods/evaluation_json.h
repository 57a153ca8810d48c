// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The JSON files of an evaluation folder: models/<path>.json per model, summary.json, failures.json.
// The summary is always rebuilt from the model files in the order of their paths, so equal inputs
// give equal summaries however the models were sharded, resumed or merged. Every file is read as
// untrusted input (shards come back from other machines, files are edited by hand): its types,
// ranges and sizes are checked, and its counts against each other; a summary must be the one its
// model files give. Anything wrong is a Usage_error `FILE: what is wrong` (exit code 2).

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_JSON_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_JSON_H

#include "command_line.h"
#include "json.h"

#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include "evaluation_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace fs = std::filesystem;

// The sharp cut-off of the evaluation, `a = b = arccos(0.9)`: the cut-off the paper compares with
// (and Yadav et al.'s normal filter uses).
constexpr double EVALUATION_CUT_OFF_COSINE = 0.9;

// The largest k_max, normal_neighbors and the like read: the largest integer option of the tool.
constexpr std::uint64_t LARGEST_EVALUATION_K = Arguments::LARGEST_UNSIGNED_OPTION;

// What must be equal for two evaluations to merge.
struct Evaluation_settings
{
  unsigned int k_min = SN::defaults::K_MIN, k_max = SN::defaults::K_MAX, fixed_k = SN::defaults::K_MAX;
  std::string barycenter = "weighted";
  double angle_tolerance = SN::defaults::ANGLE_TOLERANCE;
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

struct Model_result
{
  std::string model; // path relative to its input root, '/'-separated
  std::size_t points = 0, input_vertices = 0, merged_duplicates = 0, dropped_vertices = 0;
  std::string normals; // mesh, file or estimated
  // estimated normals: pca or jet, their k, their orientation (mst, viewpoint, none) and its trees
  std::string normal_method, orientation;
  unsigned int normal_neighbors = 0;
  std::size_t normal_components = 0;
  std::size_t zero_normals = 0; // zero in the file: all (then estimated) or those estimated from their neighbors
  double k_standard_deviation = std::numeric_limits<double>::quiet_NaN();
  SN::Evaluation_statistics statistics;
};

struct Model_failure
{
  std::string model, message;
};

// A model with fewer distinct points than the grid's k_max + 1: `points` of the `needed`.
struct Small_model
{
  std::string model;
  std::size_t needed = 0, points = 0;
};

// ------------------------------------------------------------------------------------------------
// writing

Json error_statistics_json(const SN::Error_statistics& s);

Json settings_json(const Evaluation_settings& s);

Json statistics_json(const SN::Evaluation_statistics& s);

Json model_json(const Model_result& m, const Evaluation_settings& settings);

void write_model_json(std::ostream& out, const Model_result& m, const Evaluation_settings& settings);

template <typename Record>
void sort_by_model(std::vector<Record>& records)
{
  std::sort(records.begin(), records.end(), [](const Record& x, const Record& y) { return x.model < y.model; });
}

Json small_models_json(const std::vector<Small_model>& small);

// failures.json: the models that failed, with their messages, and those too small for the grid.
void write_failures_json(std::ostream& out, std::vector<Model_failure> failures, std::vector<Small_model> small);

// ------------------------------------------------------------------------------------------------
// reading

// The number of pairs a <= b of two sorted grids, without listing them.
std::uint64_t number_of_pairs(const std::vector<double>& a, const std::vector<double>& b);

std::vector<double> read_grid(const Json_object& t, const char* key);

Evaluation_settings read_settings(const Json_object& file);

// One weighting's statistics of `points` points; `k_sizes` the length of its k histogram (0: none).
void read_error_statistics(const Json_object& t, std::size_t k_sizes, std::uint64_t points,
                                  SN::Error_statistics& s);

// The statistics of a model file or a summary, with its (checked) settings.
SN::Evaluation_statistics read_statistics(const Json_object& file, const Evaluation_settings& settings);

// models/NAME.json, checked; `name` is the model's path, which the file must name.
Model_result read_model_json(const std::string& path, const std::string& name, Evaluation_settings& settings);

// failures.json, when the folder has one; "too_small" is absent from the files of earlier versions.
void read_failures_json(const std::string& path, std::vector<Model_failure>& failures,
                               std::vector<Small_model>& small);

// Every model file under `folder`/models, as (model path, file path).
std::vector<std::pair<std::string, std::string>> model_files(const std::string& folder);

// What the model files and failures.json of evaluation folders hold, checked, with their settings
// and the statistics of all models.
struct Evaluation_contents
{
  bool any_model = false;
  Evaluation_settings settings;
  SN::Evaluation_statistics total;
  std::size_t merged = 0, dropped = 0, estimated = 0;
  // points with estimated normals, models with zero normals in the file and those points
  std::size_t estimated_points = 0, with_zero_normals = 0, zero_normals = 0;
  std::vector<Model_result> models; // without their statistics
  std::vector<Model_failure> failures;
  std::vector<Small_model> small;
};

// Reads `folders` (one folder, or the shards of one repository); a model in two places is refused.
Evaluation_contents read_evaluation_folders(const std::vector<std::string>& folders);

Json summary_json(const Evaluation_contents& c, const std::string& repository);

// summary.json of the models of `folders` (one folder, or the shards of one repository).
void write_summary(const std::vector<std::string>& folders, const std::string& repository,
                          const std::string& summary_path);

// The repository named by `folder`/summary.json, checked on its own only: for `merge FOLDER -o FOLDER`,
// which rewrites a summary (of an earlier version, or edited) from the folder's model files.
std::string read_summary_repository(const std::string& folder);

// `folder`/summary.json, checked: exactly what its model files and failures.json give (`contents`).
Json_value read_summary(const std::string& folder, Evaluation_contents& contents);

Json_value read_summary(const std::string& folder);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_JSON_H
