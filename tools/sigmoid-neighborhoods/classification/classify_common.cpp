// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify: what its steps share (classify_common.h). The one translation unit
// that instantiates CGAL's training, classify() and graph-cut, the PLY writer and, the experiment's
// aside, the feature computation: CGAL's Classification headers compile slowly.

#include "classify_common.h"
#include "classify_training.h"
#include "training_rows.h"
#include "feature_groups.h"

#include "../ply_output.h"

#include <CGAL/Classification/Point_set_neighborhood.h>
#include <CGAL/Classification/classify.h>
#include <CGAL/Real_timer.h>

#include <nlohmann/json.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {
namespace classification {

std::string number_fixed(double v, int digits)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, v);
  return buffer;
}

void progress(const std::string& what)
{
  static const bool terminal = ::isatty(2) != 0;
  if(terminal)
    std::cerr << "\r\033[K" << what << std::flush;
}
void end_progress()
{
  static const bool terminal = ::isatty(2) != 0;
  if(terminal)
    std::cerr << "\r\033[K" << std::flush;
}

SN::Normal_options classify_normal_options(const Arguments& args)
{
  SN::Normal_options o = read_normal_options(args);
  if(!args.has("--orientation") && !args.has("--viewpoint"))
    o.orientation = SN::Normal_orientation::UPWARD;
  if(o.source == SN::Normal_source::AUTO || o.source == SN::Normal_source::FROM_FILE)
    o.source = SN::Normal_source::PCA; // the same normals for every file, whatever it holds
  o.neighbor_search = CLASSIFICATION_NEIGHBOR_SEARCH;
  return o;
}

void add_features(Featured_file& f, const Label_mapping& labels, bool need_labels, const Feature_options& features,
                  bool compute_features)
{
  const std::string& path = f.path;
  if(need_labels && f.model.labels.empty())
    throw Usage_error(path + ": the file has no labels (LAS classification, PLY label/class/classification)");
  f.truth.assign(f.model.points.size(), -1);
  for(std::size_t i = 0; i < f.model.labels.size(); ++i)
    f.truth[i] = labels.class_of(f.model.labels[i]);
  if(!compute_features)
    return;
  CGAL::Real_timer timer;
  timer.start();
  f.columns = read_input(path, [&] {
    return compute_feature_columns(f.model, features, [&](const std::string& step) { progress(path + ": " + step); });
  });
  f.seconds_features = timer.time();
}

Featured_file read_and_feature(const std::string& path, const Label_mapping& labels, bool need_labels,
                               const SN::Normal_options& normals, const Feature_options& features,
                               bool compute_features)
{
  Featured_file f;
  f.path = path;
  progress(path + ": reading");
  // the normals' neighbor rows kept for the features: one neighbor structure per file
  f.model = read_input(path, [&] { return read_model(path, largest_neighborhood(features), normals); });
  add_features(f, labels, need_labels, features, compute_features);
  return f;
}

std::vector<std::string> column_names(const std::vector<Feature_column>& columns)
{
  std::vector<std::string> names;
  for(const Feature_column& c : columns)
    names.push_back(c.name);
  return names;
}

namespace {

// The names in the forest's order: as computed, or shuffled by a seed.
std::vector<std::string> ordered_names(std::vector<std::string> names, unsigned int seed)
{
  if(seed != 0)
  {
    std::mt19937 rng(seed);
    std::shuffle(names.begin(), names.end(), rng);
  }
  return names;
}

} // namespace

// At most `cap` training points per class (0: all), evenly spaced in the files' order (a scan's order
// sweeps the ground: the kept points cover the survey), the others marked -1, which CGAL's training
// skips. Deterministic: the same points for any thread count and run.
void cap_points_per_class(std::vector<int>& truth, std::size_t classes, std::size_t cap)
{
  if(cap == 0)
    return;
  std::vector<std::size_t> count(classes, 0), seen(classes, 0), kept(classes, 0);
  for(int c : truth)
    if(c >= 0)
      ++count[std::size_t(c)];
  for(int& c : truth)
  {
    if(c < 0 || count[std::size_t(c)] <= cap)
      continue;
    const std::size_t k = std::size_t(c);
    // the point of rank r is kept when floor((r + 1) cap / n) passes a new integer: cap points in all
    const std::size_t wanted = (seen[k] + 1) * cap / count[k];
    ++seen[k];
    if(wanted > kept[k])
      ++kept[k];
    else
      c = -1;
  }
}

namespace {

// Marks -1 in `truth` (one vector per file) the points that do not train (--max-per-class, over the
// files one after the other), after checking that every class has a point; returns how many train.
std::size_t choose_training_points(std::vector<std::vector<int>>& truth, const Classifier_settings& s)
{
  std::vector<int> all;
  for(const std::vector<int>& t : truth)
    all.insert(all.end(), t.begin(), t.end());
  std::vector<std::size_t> per_class(s.labels.names.size(), 0);
  for(int c : all)
    if(c >= 0)
      ++per_class[std::size_t(c)];
  for(std::size_t c = 0; c < per_class.size(); ++c)
    if(per_class[c] == 0)
      throw Usage_error("no training point of class '" + s.labels.names[c] + "' (codes " + s.labels.text() + ")");
  cap_points_per_class(all, per_class.size(), s.max_per_class);
  auto from = all.begin();
  for(std::vector<int>& t : truth)
  {
    std::copy(from, from + std::ptrdiff_t(t.size()), t.begin());
    from += std::ptrdiff_t(t.size());
  }
  return std::size_t(std::count_if(all.begin(), all.end(), [](int c) { return c >= 0; }));
}

} // namespace

void append_training_rows(const std::vector<Feature_column>& columns, const std::vector<int>& truth,
                          const std::vector<std::string>& names, unsigned int threads, Training_rows& rows)
{
  const std::vector<const std::vector<double>*> ordered = ordered_columns(columns, names);
  std::vector<std::size_t> points;
  for(std::size_t i = 0; i < truth.size(); ++i)
    if(truth[i] >= 0)
      points.push_back(i);
  const std::size_t first = rows.labels.size(), width = names.size();
  rows.labels.resize(first + points.size());
  rows.values.resize(1 + (first + points.size()) * width);
  // in blocks of rows, a column at a time: each column read in order, the block's rows in the cache
  const std::size_t block = 256;
  const std::ptrdiff_t blocks = std::ptrdiff_t((points.size() + block - 1) / block);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads == 0 ? omp_get_max_threads() : int(threads))
#endif
  for(std::ptrdiff_t b = 0; b < blocks; ++b)
  {
    const std::size_t begin = std::size_t(b) * block, end = std::min(points.size(), begin + block);
    for(std::size_t f = 0; f < width; ++f)
    {
      const std::vector<double>& column = *ordered[f];
      float* value = rows.values.data() + 1 + (first + begin) * width + f;
      for(std::size_t r = begin; r < end; ++r, value += width)
        *value = SN::Classification::Feature_values::stored_value(column[points[r]]);
    }
    for(std::size_t r = begin; r < end; ++r)
      rows.labels[first + r] = truth[points[r]];
  }
  (void)threads;
}

namespace {

void train_forest(Training_rows& rows, Trained& t)
{
  progress("training " + std::to_string(t.settings.trees) + " trees on " + std::to_string(rows.labels.size()) +
           " points");
  CGAL::Real_timer timer;
  timer.start();
  // --threads bounds the trees trained at once; the forest does not depend on it
  t.forest.emplace(SN::Classification::Ethz_forest::train<SN::Parallel_if_available_tag>(
    rows.values, rows.labels, t.settings.labels.names.size(), t.settings.trees, t.settings.depth,
    SN::parameters::number_of_threads(t.settings.features.threads)));
  t.seconds = timer.time();
  t.training_points = rows.labels.size();
}

} // namespace

void train(const std::vector<Featured_file>& files, Trained& t)
{
  std::vector<std::vector<int>> truth;
  for(const Featured_file& f : files)
    truth.push_back(f.truth);
  const std::size_t used = choose_training_points(truth, t.settings);
  const std::vector<std::string> names = column_names(files.front().columns);
  t.settings.feature_names = ordered_names(names, t.settings.feature_order_seed);
  Training_rows rows;
  rows.values.reserve(1 + used * names.size());
  rows.labels.reserve(used);
  for(std::size_t f = 0; f < files.size(); ++f)
  {
    if(column_names(files[f].columns) != names)
      throw std::logic_error("files with different feature columns");
    append_training_rows(files[f].columns, truth[f], t.settings.feature_names, t.settings.features.threads, rows);
  }
  train_forest(rows, t);
}

Featured_file read_labels(const std::string& path, const Classifier_settings& settings)
{
  // Read without normals (the same points: duplicates merge on their positions), unless the file's
  // own normals refuse that (a few zero normals need estimating): then as the features read it.
  SN::Normal_options without_normals;
  without_normals.neighbors = 0;
  without_normals.threads = settings.normals.threads;
  progress(path + ": reading the labels");
  Featured_file f;
  f.path = path;
  try
  {
    f.model = SN::read_oriented_point_set(path, without_normals);
  }
  catch(const SN::Input_error&)
  {
    f.model = read_input(path, [&] { return read_model(path, 0, settings.normals); });
  }
  add_features(f, settings.labels, true, settings.features, false);
  return f;
}

void check_same_points(const Featured_file& f, std::size_t labeled_points)
{
  if(f.truth.size() != labeled_points)
    throw Usage_error(f.path + ": the file changed while it was read (" + std::to_string(labeled_points) +
                      " points, then " + std::to_string(f.truth.size()) + ")");
}

std::size_t train_file_by_file(const std::vector<std::string>& paths, Trained& t, Phase_times& times)
{
  // the labels first: they size the rows and choose the training points
  std::vector<std::vector<int>> truth;
  for(const std::string& path : paths)
    truth.push_back(read_labels(path, t.settings).truth);
  times.end("labels");
  const std::size_t used = choose_training_points(truth, t.settings);
  Training_rows rows;
  rows.labels.reserve(used);
  std::vector<std::string> names;
  std::size_t points = 0;
  for(std::size_t p = 0; p < paths.size(); ++p)
  {
    const Featured_file f = read_and_feature(paths[p], t.settings.labels, true, t.settings.normals, t.settings.features);
    times.end_reading(f.model);
    times.move("reading", "features", f.seconds_features);
    check_same_points(f, truth[p].size());
    if(p == 0)
    {
      names = column_names(f.columns);
      t.settings.feature_names = ordered_names(names, t.settings.feature_order_seed);
      rows.values.reserve(1 + used * names.size()); // the rows' one allocation
    }
    else if(column_names(f.columns) != names)
      throw std::logic_error("files with different feature columns");
    append_training_rows(f.columns, truth[p], t.settings.feature_names, t.settings.features.threads, rows);
    times.end("training rows");
    points += f.model.points.size();
  }
  train_forest(rows, t);
  times.end("training");
  return points;
}

Prediction predict(const Featured_file& file, const Classifier_settings& settings, const std::string& forest_bytes,
                   const SN::Classification::Ethz_forest* trained, double graphcut)
{
  CGAL::Real_timer timer;
  timer.start();
  const std::size_t n = file.model.points.size(), classes = settings.labels.names.size();
  std::optional<SN::Classification::Ethz_forest> loaded;
  if(trained == nullptr)
    loaded.emplace(load_forest(file.path, forest_bytes, classes, settings.feature_names.size()));
  const SN::Classification::Ethz_forest* trees = trained != nullptr ? trained : &*loaded;
  const double seconds_loading = timer.time();
  Prediction p;
  p.confidence.assign(classes, std::vector<float>(n, 0.f));
  p.classes.assign(n, -1);
  if(graphcut > 0.)
  {
    CGAL::Classification::Label_set labels = label_set(settings.labels);
    CGAL::Classification::Feature_set features;
    fill_feature_set(file.columns, settings.feature_names, features);
    CGAL::Classification::ETHZ::Random_forest_classifier forest(labels, features);
    {
      std::stringstream bytes;
      trees->save_configuration(bytes);
      forest.load_configuration(bytes);
    }
#ifdef CGAL_LINKED_WITH_TBB
    // --threads bounds CGAL's loops over the points
    std::unique_ptr<tbb::global_control> limit;
    if(settings.features.threads != 0)
      limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    settings.features.threads);
#endif
    std::vector<float> probabilities(labels.size());
    for(std::size_t i = 0; i < n; ++i)
    {
      forest(i, probabilities);
      for(std::size_t c = 0; c < labels.size(); ++c)
        p.confidence[c][i] = probabilities[c];
    }
    typedef SN::Oriented_point_set::Kernel Kernel;
    typedef CGAL::Identity_property_map<Kernel::Point_3> Point_map;
    CGAL::Classification::Point_set_neighborhood<Kernel, std::vector<Kernel::Point_3>, Point_map> neighborhood(
      file.model.points, Point_map());
    CGAL::Classification::classify_with_graphcut<CGAL::Parallel_if_available_tag>(
      file.model.points, Point_map(), labels, forest, neighborhood.k_neighbor_query(12), float(graphcut), 1, p.classes);
  }
  else
  {
    // CGAL's classify() with the confidences, on the package's own loop (see Ethz_forest)
    const std::vector<const std::vector<double>*> ordered = ordered_columns(file.columns, settings.feature_names);
    trees->classify<CGAL::Parallel_if_available_tag>(
      n, [&](std::size_t i, std::size_t f) { return (*ordered[f])[i]; }, p.classes, p.confidence,
      SN::parameters::number_of_threads(settings.features.threads));
  }
  p.seconds = timer.time();
  p.seconds_loading = seconds_loading;
  return p;
}

namespace {

Rgb class_color(std::size_t c, const std::string& name)
{
  if(name == "ground")
    return {160, 110, 60};
  if(name == "low_vegetation")
    return {150, 220, 90};
  if(name == "high_vegetation" || name == "vegetation")
    return {20, 130, 40};
  if(name == "building" || name == "roof")
    return {210, 50, 40};
  static const Rgb palette[] = {{0, 114, 178}, {230, 159, 0}, {86, 180, 233}, {204, 121, 167},
                                {240, 228, 66}, {0, 158, 115}, {213, 94, 0}, {128, 128, 128}};
  return palette[c % 8];
}

} // namespace

void write_prediction_ply(const std::string& path, const Featured_file& file, const Prediction& p,
                          const Label_mapping& m, std::size_t first, std::size_t last)
{
  last = std::min(last, file.model.points.size());
  Ply_point_set ps(false);
  ps.reserve(last - first);
  for(std::size_t i = first; i < last; ++i)
    ps.insert(file.model.points[i]);
  auto label = add_ply_scalar<int>(ps, "label");
  std::vector<Ply_point_set::Property_map<float>> confidence;
  for(const std::string& name : m.names)
    confidence.push_back(add_ply_scalar<float>(ps, "confidence_" + name));
  Ply_point_set::Property_map<int> truth;
  const bool has_truth = !file.model.labels.empty();
  if(has_truth)
    truth = add_ply_scalar<int>(ps, "truth");
  auto red = ps.add_property_map<std::uint8_t>("red", 0).first;
  auto green = ps.add_property_map<std::uint8_t>("green", 0).first;
  auto blue = ps.add_property_map<std::uint8_t>("blue", 0).first;
  std::size_t i = first;
  for(auto it = ps.begin(); it != ps.end(); ++it, ++i)
  {
    const int c = p.classes[i];
    label[*it] = c;
    for(std::size_t k = 0; k < confidence.size(); ++k)
      confidence[k][*it] = p.confidence[k][i];
    if(has_truth)
      truth[*it] = file.truth[i];
    const Rgb rgb = c < 0 ? FAILURE_GRAY : class_color(std::size_t(c), m.names[std::size_t(c)]);
    red[*it] = rgb[0];
    green[*it] = rgb[1];
    blue[*it] = rgb[2];
  }
  write_file_atomically(path, [&](std::ofstream& out) { write_binary_ply(out, ps); }, true);
}

std::string percent(double v) { return std::isnan(v) ? "n/a" : number_fixed(100. * v, 1) + " %"; }
std::string fixed3(double v) { return std::isnan(v) ? "n/a" : number_fixed(v, 3); }

namespace {

nlohmann::json confusion_json(const Confusion& c, const Label_mapping& m)
{
  nlohmann::json j;
  j["classes"] = m.names;
  nlohmann::json matrix = nlohmann::json::array();
  for(std::size_t t = 0; t < c.classes(); ++t)
  {
    nlohmann::json row = nlohmann::json::array();
    for(std::size_t p = 0; p < c.classes(); ++p)
      row.push_back(c.count(t, p));
    matrix.push_back(row);
  }
  j["confusion"] = matrix; // rows: truth, columns: prediction
  auto number = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
  for(std::size_t k = 0; k < c.classes(); ++k)
    j["per_class"][m.names[k]] = {{"precision", number(c.precision(k))}, {"recall", number(c.recall(k))},
                                  {"f1", number(c.f1(k))},               {"iou", number(c.iou(k))},
                                  {"points", c.true_count(k)}};
  j["overall_accuracy"] = number(c.overall_accuracy());
  j["mean_f1"] = number(c.mean_f1());
  j["mean_iou"] = number(c.mean_iou());
  j["points"] = c.total();
  return j;
}

} // namespace

void write_evaluation(const std::string& dir, const Confusion& c, const Label_mapping& m, const std::string& title)
{
  create_output_folder(dir);
  write_file_atomically(dir + "/evaluation.json",
                        [&](std::ofstream& out) { out << confusion_json(c, m).dump(2) << '\n'; });
  write_file_atomically(dir + "/evaluation.csv", [&](std::ofstream& out) {
    out << "class,points,precision,recall,f1,iou";
    for(const std::string& name : m.names)
      out << ",predicted_" << name;
    out << '\n';
    for(std::size_t k = 0; k < c.classes(); ++k)
    {
      out << m.names[k] << ',' << c.true_count(k);
      for(double v : {c.precision(k), c.recall(k), c.f1(k), c.iou(k)})
        out << ',' << (std::isnan(v) ? std::string() : number17(v));
      for(std::size_t p = 0; p < c.classes(); ++p)
        out << ',' << c.count(k, p);
      out << '\n';
    }
    out << "all," << c.total() << ",,," << number17(c.mean_f1()) << ',' << number17(c.mean_iou()) << '\n';
  });
  write_file_atomically(dir + "/evaluation.md", [&](std::ofstream& out) {
    out << "# " << title << "\n\n"
        << "Overall accuracy " << percent(c.overall_accuracy()) << ", mean F1 " << fixed3(c.mean_f1())
        << ", mean IoU " << fixed3(c.mean_iou()) << " on " << c.total() << " points.\n\n"
        << "| class | points | precision | recall | F1 | IoU |\n|---|---:|---:|---:|---:|---:|\n";
    for(std::size_t k = 0; k < c.classes(); ++k)
      out << "| " << m.names[k] << " | " << c.true_count(k) << " | " << fixed3(c.precision(k)) << " | "
          << fixed3(c.recall(k)) << " | " << fixed3(c.f1(k)) << " | " << fixed3(c.iou(k)) << " |\n";
    out << "\nConfusion matrix (rows: truth, columns: prediction):\n\n| truth \\ predicted |";
    for(const std::string& name : m.names)
      out << ' ' << name << " |";
    out << "\n|---|" << std::string(3 * 0, ' ');
    for(std::size_t k = 0; k < c.classes(); ++k)
      out << "---:|";
    out << '\n';
    for(std::size_t t = 0; t < c.classes(); ++t)
    {
      out << "| " << m.names[t] << " |";
      for(std::size_t p = 0; p < c.classes(); ++p)
        out << ' ' << c.count(t, p) << " |";
      out << '\n';
    }
  });
}

double read_graphcut(const Arguments& args)
{
  const double strength = args.get_double("--graphcut", 0.);
  if(!(strength >= 0.) || !std::isfinite(strength))
    throw Usage_error("--graphcut needs a strength >= 0 (0: none)");
  return strength;
}

} // namespace classification
} // namespace sigmoid_tool
