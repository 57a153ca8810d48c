// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify: semantic classification of labeled point sets (LAS classification
// codes, PLY labels) with CGAL's ETHZ random forest on CGAL's and the package's features: train,
// predict, evaluate, and the experiment that compares feature sets. In its own translation unit:
// CGAL's Classification headers compile slowly.

#include "classify_command.h"

#include "classification/classifier_model.h"
#include "classification/confusion.h"
#include "classification/feature_groups.h"
#include "classification/label_mapping.h"
#include "catalog_input.h"
#include "command_line.h"
#include "model_input.h"
#include "ply_output.h"

#include <CGAL/Classification/ETHZ/Random_forest_classifier.h>
#include <CGAL/Classification/Point_set_neighborhood.h>
#include <CGAL/Classification/classify.h>
#include <CGAL/Real_timer.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

const char* const CLASSIFY_USAGE =
  "usage: sigmoid-neighborhoods classify train FILE... -o MODEL [--labels MAP] [--features GROUPS]\n"
  "                                [--trees 25] [--depth 20] [--feature-order-seed N] [normals] [--threads N]\n"
  "       sigmoid-neighborhoods classify predict MODEL INPUT|--catalog SOURCE [--tile NAME] -o OUT.ply\n"
  "                                [--graphcut STRENGTH] [--threads N]\n"
  "       sigmoid-neighborhoods classify evaluate MODEL FILE... -o DIR [--graphcut STRENGTH] [--threads N]\n"
  "       sigmoid-neighborhoods classify experiment --train FILE,... --test FILE,... -o DIR [--sets SETS]\n"
  "                                [--orders 10] [--cv-orders 1] [--graphcut 0.2] [--labels MAP] [--trees 25]\n"
  "                                [--depth 20] [normals]\n"
  "  FILE: a labeled point set: LAS (classification codes) or PLY with a label/class/classification property\n"
  "  --labels MAP: the classes and their codes, other codes ignored (default ground=2,low_vegetation=3+4,\n"
  "      high_vegetation=5,building=6)\n"
  "  --feature-order-seed N: the features in a shuffled order (CGAL's forest depends on it; 0: as listed)\n"
  "  --graphcut STRENGTH: CGAL's graph-cut regularisation of the labels on 12 neighbors (e.g. 0.2)\n"
  "  normals are estimated (pca on 18 neighbors) and oriented upwards unless --orientation says otherwise\n"
  "  predict writes a binary PLY: scalar_label (class index), scalar_confidence_<class>, red green blue\n"
  "  predict --catalog SOURCE: the union of the tiles in one run; with --tile NAME, the tile's points alone,\n"
  "      featured with a halo of the other tiles' points that holds the k nearest neighbors of the model's\n"
  "      groups, the neighbors of their normals and, for the group height, every cell of the tile: their labels\n"
  "      and confidences are those of the union, bit for bit (orientation mst excepted); refused with --tile:\n"
  "      the group cgal (CGAL's generator takes its scales from the average spacing and anchors its grids at\n"
  "      the bounding box of the whole point set) and --graphcut (a minimisation over the whole point set):\n"
  "      predict the union for those\n"
  "  evaluate writes DIR/evaluation.md, .csv, .json: confusion matrix, precision, recall, F1, IoU per\n"
  "      class, overall accuracy, mean F1, mean IoU\n"
  "  experiment trains and tests every feature set of --sets (NAME=GROUP,GROUP;NAME=...; default: the sets\n"
  "      A to G of the manual) in --orders feature orders, with and without graph-cut, and writes\n"
  "      DIR/experiment.md, experiment.csv, experiment.json and runs.csv; each set is also cross-validated on\n"
  "      the training files (each left out in turn, --cv-orders orders), and the set and graph-cut of the\n"
  "      best cross-validated mean IoU are reported as the choice\n";

std::string number_fixed(double v, int digits)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, v);
  return buffer;
}

// One line of progress on a terminal, nothing in a log.
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

// A labeled (or unlabeled) file read and featured.
struct Featured_file
{
  std::string path;
  SN::Oriented_point_set model;
  std::vector<int> truth; // class index per point, -1: not in any class (or no labels)
  std::vector<Feature_column> columns;
  double seconds_features = 0.;
};

SN::Normal_options classify_normal_options(const Arguments& args)
{
  SN::Normal_options o = read_normal_options(args);
  if(!args.has("--orientation") && !args.has("--viewpoint"))
    o.orientation = SN::Normal_orientation::UPWARD;
  if(o.source == SN::Normal_source::AUTO || o.source == SN::Normal_source::FROM_FILE)
    o.source = SN::Normal_source::PCA; // the same normals for every file, whatever it holds
  return o;
}

// The truth and, when `compute_features`, the feature columns of `f.model`.
void add_features(Featured_file& f, const Label_mapping& labels, bool need_labels, const Feature_options& features,
                  bool compute_features = true)
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
                               bool compute_features = true)
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

// The columns of several files, one after the other.
std::vector<Feature_column> concatenated(const std::vector<Featured_file>& files)
{
  std::vector<Feature_column> result = files.front().columns;
  for(std::size_t f = 1; f < files.size(); ++f)
  {
    if(column_names(files[f].columns) != column_names(result))
      throw std::logic_error("files with different feature columns");
    for(std::size_t c = 0; c < result.size(); ++c)
      result[c].values.insert(result[c].values.end(), files[f].columns[c].values.begin(),
                              files[f].columns[c].values.end());
  }
  return result;
}

typedef CGAL::Classification::ETHZ::Random_forest_classifier Forest;

// Trains a forest on `files`; returns the settings with the feature names in the forest's order.
struct Trained
{
  Classifier_settings settings;
  CGAL::Classification::Label_set labels;
  CGAL::Classification::Feature_set features;
  std::unique_ptr<Forest> forest;
  double seconds = 0.;
};

void train(const std::vector<Featured_file>& files, Trained& t)
{
  const std::vector<Feature_column> columns = concatenated(files);
  t.settings.feature_names = ordered_names(column_names(columns), t.settings.feature_order_seed);
  t.labels = label_set(t.settings.labels);
  fill_feature_set(columns, t.settings.feature_names, t.features);
  std::vector<int> truth;
  for(const Featured_file& f : files)
    truth.insert(truth.end(), f.truth.begin(), f.truth.end());
  std::vector<std::size_t> per_class(t.settings.labels.names.size(), 0);
  for(int c : truth)
    if(c >= 0)
      ++per_class[std::size_t(c)];
  for(std::size_t c = 0; c < per_class.size(); ++c)
    if(per_class[c] == 0)
      throw Usage_error("no training point of class '" + t.settings.labels.names[c] + "' (codes " +
                        t.settings.labels.text() + ")");
  progress("training " + std::to_string(t.settings.trees) + " trees on " + std::to_string(truth.size()) + " points");
  CGAL::Real_timer timer;
  timer.start();
  t.forest = std::make_unique<Forest>(t.labels, t.features);
  t.forest->train<CGAL::Parallel_if_available_tag>(truth, true, t.settings.trees, t.settings.depth);
  t.seconds = timer.time();
}

// The classes of one file under a trained forest, and each class's probability per point.
struct Prediction
{
  std::vector<int> classes;
  std::vector<std::vector<float>> confidence; // per class, per point
  double seconds = 0.;
};

Prediction predict(const Featured_file& file, const Classifier_settings& settings, const std::string& forest_bytes,
                   const Forest* trained, double graphcut)
{
  CGAL::Real_timer timer;
  timer.start();
  CGAL::Classification::Label_set labels = label_set(settings.labels);
  CGAL::Classification::Feature_set features;
  fill_feature_set(file.columns, settings.feature_names, features);
  Forest forest(labels, features);
  if(trained != nullptr)
  {
    std::stringstream bytes;
    trained->save_configuration(bytes);
    forest.load_configuration(bytes);
  }
  else
    load_forest(file.path, forest_bytes, forest);
  const std::size_t n = file.model.points.size();
  Prediction p;
  p.confidence.assign(labels.size(), std::vector<float>(n, 0.f));
  std::vector<float> probabilities(labels.size());
  for(std::size_t i = 0; i < n; ++i)
  {
    forest(i, probabilities);
    for(std::size_t c = 0; c < labels.size(); ++c)
      p.confidence[c][i] = probabilities[c];
  }
  p.classes.assign(n, -1);
  if(graphcut > 0.)
  {
    typedef SN::Oriented_point_set::Kernel Kernel;
    typedef CGAL::Identity_property_map<Kernel::Point_3> Point_map;
    CGAL::Classification::Point_set_neighborhood<Kernel, std::vector<Kernel::Point_3>, Point_map> neighborhood(
      file.model.points, Point_map());
    CGAL::Classification::classify_with_graphcut<CGAL::Parallel_if_available_tag>(
      file.model.points, Point_map(), labels, forest, neighborhood.k_neighbor_query(12), float(graphcut), 1, p.classes);
  }
  else
    CGAL::Classification::classify<CGAL::Parallel_if_available_tag>(file.model.points, labels, forest, p.classes);
  p.seconds = timer.time();
  return p;
}

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

// The points `first` ... `last - 1` of `file` (a tile without its halo), all by default.
void write_prediction_ply(const std::string& path, const Featured_file& file, const Prediction& p,
                          const Label_mapping& m, std::size_t first = 0, std::size_t last = std::size_t(-1))
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

Feature_options read_feature_options(const Arguments& args)
{
  Feature_options o;
  o.groups = parse_feature_groups(args.get("--features", "cgal"));
  o.threads = read_threads(args);
  return o;
}

int run_train(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_normal_options({"-o", "--output", "--labels", "--features", "--trees", "--depth",
                                            "--feature-order-seed", "--threads"}),
                       with_normal_flags({"-h", "--help"}), NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, CLASSIFY_USAGE))
  {
    std::cout << FEATURE_GROUPS_USAGE << NORMAL_USAGE;
    return EXIT_OK;
  }
  if(args.positional().empty())
    throw Usage_error("classify train needs at least one labeled FILE");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error("classify train needs -o MODEL");
  Trained t;
  t.settings.labels = parse_label_mapping(args.get("--labels", DEFAULT_LABELS));
  t.settings.features = read_feature_options(args);
  t.settings.normals = classify_normal_options(args);
  t.settings.trees = args.get_unsigned("--trees", 25);
  t.settings.depth = args.get_unsigned("--depth", 20);
  t.settings.feature_order_seed = args.get_unsigned("--feature-order-seed", 0);
  if(t.settings.trees < 1 || t.settings.depth < 1)
    throw Usage_error("--trees and --depth must be at least 1");
  std::vector<Featured_file> files;
  for(const std::string& path : args.positional())
    files.push_back(read_and_feature(path, t.settings.labels, true, t.settings.normals, t.settings.features));
  train(files, t);
  write_classifier_model(output, t.settings, *t.forest);
  end_progress();
  std::size_t points = 0;
  double feature_seconds = 0.;
  for(const Featured_file& f : files)
  {
    points += f.model.points.size();
    feature_seconds += f.seconds_features;
  }
  std::cerr << output << ": " << t.settings.feature_names.size() << " features, " << t.settings.labels.names.size()
            << " classes, " << points << " points from " << files.size() << " file(s); features "
            << number_fixed(feature_seconds, 1) << " s, training " << number_fixed(t.seconds, 1) << " s\n";
  return EXIT_OK;
}

double read_graphcut(const Arguments& args)
{
  const double strength = args.get_double("--graphcut", 0.);
  if(!(strength >= 0.) || !std::isfinite(strength))
    throw Usage_error("--graphcut needs a strength >= 0 (0: none)");
  return strength;
}

// What a tile's features or labels cannot share with the union: a refusal naming it, before any reading.
void refuse_inexact_tile(const Classifier_settings& settings, double graphcut)
{
  const std::string groups = whole_set_groups(settings.features);
  if(!groups.empty())
    throw Usage_error("classify predict --tile: the model's feature group " + groups +
                      " depends on the whole point set (CGAL's generator: scales from the average spacing, grids "
                      "anchored at the bounding box), so a tile would not get the union's features; predict the "
                      "union (--catalog without --tile) or use a model without it");
  if(graphcut > 0.)
    throw Usage_error("classify predict --tile: --graphcut minimises over the whole point set, so a tile would not "
                      "get the union's labels; predict the union (--catalog without --tile) or leave --graphcut out");
}

// Which model a tile was predicted with, for the tile description: its settings and its trees.
std::string model_fingerprint(const Classifier_settings& settings, const std::string& forest_bytes)
{
  return "model:" + std::to_string(std::hash<std::string>()(settings_json(settings).dump() + forest_bytes));
}

int run_predict(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_catalog_options({"-o", "--output", "--graphcut", "--threads"}), {"-h", "--help"});
  if(print_help(args, CLASSIFY_USAGE))
  {
    std::cout << CATALOG_USAGE;
    return EXIT_OK;
  }
  if(args.positional().empty())
    throw Usage_error("classify predict needs MODEL INPUT, or MODEL --catalog SOURCE");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error("classify predict needs -o OUT.ply");
  const std::string& model_path = args.positional()[0];
  std::string forest_bytes;
  Classifier_settings settings = read_classifier_settings(model_path, forest_bytes);
  const std::string model = model_fingerprint(settings, forest_bytes);
  settings.features.threads = settings.normals.threads = read_threads(args);
  const double graphcut = read_graphcut(args);
  if(args.has("--tile"))
    refuse_inexact_tile(settings, graphcut);
  CGAL::Real_timer timer;
  timer.start();
  progress("reading");
  // the normals' neighbor rows kept for the features; a tile's halo holds them and the height cells
  Input_points in = read_input_points(args, "classify predict", largest_neighborhood(settings.features),
                                      settings.normals, cell_halo(settings.features), 1);
  if(in.is_tile && in.first == in.last)
    throw Usage_error(in.source + ": tile " + in.tile_name + " has no point of its own (empty, or all on an earlier "
                      "tile's seam): nothing to predict");
  Featured_file file;
  file.path = in.source;
  file.model = std::move(in.model);
  add_features(file, settings.labels, false, settings.features);
  const Prediction p = predict(file, settings, forest_bytes, nullptr, graphcut);
  write_prediction_ply(output, file, p, settings.labels, in.first, in.last);
  timer.stop();
  write_tile_description(output, "classify predict", args, in, timer.time(), model);
  end_progress();
  std::vector<std::size_t> counts(settings.labels.names.size(), 0);
  for(std::size_t i = in.first; i < in.last; ++i)
    if(p.classes[i] >= 0)
      ++counts[std::size_t(p.classes[i])];
  std::cerr << output << ": " << in.last - in.first << " points" << halo_description(in) << ":";
  for(std::size_t c = 0; c < counts.size(); ++c)
    std::cerr << (c ? ", " : " ") << settings.labels.names[c] << ' ' << counts[c];
  std::cerr << "; features " << number_fixed(file.seconds_features, 1) << " s, classification "
            << number_fixed(p.seconds, 1) << " s\n";
  return EXIT_OK;
}

int run_evaluate(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       {"-o", "--output", "--graphcut", "--threads", "--labels"}, {"-h", "--help"});
  if(print_help(args, CLASSIFY_USAGE))
    return EXIT_OK;
  if(args.positional().size() < 2)
    throw Usage_error("classify evaluate needs MODEL FILE...");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error("classify evaluate needs -o DIR");
  const std::string& model_path = args.positional()[0];
  std::string forest_bytes;
  Classifier_settings settings = read_classifier_settings(model_path, forest_bytes);
  if(args.has("--labels") && parse_label_mapping(args.get("--labels")).text() != settings.labels.text())
    throw Usage_error("--labels " + args.get("--labels") + " differ from the model's " + settings.labels.text());
  settings.features.threads = settings.normals.threads = read_threads(args);
  const double graphcut = read_graphcut(args);
  Confusion confusion(settings.labels.names.size());
  for(std::size_t f = 1; f < args.positional().size(); ++f)
  {
    const Featured_file file =
      read_and_feature(args.positional()[f], settings.labels, true, settings.normals, settings.features);
    const Prediction p = predict(file, settings, forest_bytes, nullptr, graphcut);
    for(std::size_t i = 0; i < p.classes.size(); ++i)
      confusion.add(file.truth[i], p.classes[i]);
  }
  end_progress();
  write_evaluation(output, confusion, settings.labels, "Classification of " + std::to_string(args.positional().size() - 1) +
                                                         " file(s) by " + model_path);
  std::cerr << output << ": overall accuracy " << percent(confusion.overall_accuracy()) << ", mean F1 "
            << fixed3(confusion.mean_f1()) << ", mean IoU " << fixed3(confusion.mean_iou()) << " on "
            << confusion.total() << " points\n";
  return EXIT_OK;
}


// The feature sets of the experiment: what a CGAL user has (A), the fixed scale of pgeof and
// jakteristics (B), the classical optimal neighborhoods (C, D), the package's (E), several scales
// without and with sigmoid weights (F, F_sigmoid), and CGAL's with the package's added (G_*), the
// last two of them the same ablation on top of CGAL's.
const char* const DEFAULT_EXPERIMENT_SETS =
  "A=cgal;B=k20,height;C=eigenentropy,height;D=dimensionality,height;E=optimal,height;F=multiscale,height;"
  "F_sigmoid=multiscale-sigmoid,height;G_optimal=cgal,optimal;G_multiscale=cgal,multiscale;"
  "G_multiscale_sigmoid=cgal,multiscale-sigmoid";

struct Feature_set_spec
{
  std::string name;
  std::vector<std::string> groups;
};

std::vector<Feature_set_spec> parse_sets(const std::string& text)
{
  std::vector<Feature_set_spec> sets;
  for(const std::string& item : split(text, ';'))
  {
    const std::size_t equals = item.find('=');
    if(equals == std::string::npos || equals == 0)
      throw Usage_error("--sets: expected NAME=GROUP[,GROUP...], got '" + item + "'");
    sets.push_back({item.substr(0, equals), parse_feature_groups(item.substr(equals + 1))});
  }
  return sets;
}

std::vector<std::string> split_list(const std::string& text, const std::string& option)
{
  std::vector<std::string> items;
  for(const std::string& item : split(text, ','))
    if(!item.empty())
      items.push_back(item);
  if(items.empty())
    throw Usage_error(option + " needs at least one file");
  return items;
}

// One file of the experiment: read once, each feature group computed once (and timed), the sets'
// columns assembled from the groups.
struct Experiment_file
{
  Featured_file file; // columns empty: see groups
  std::map<std::string, std::vector<Feature_column>> groups;
  std::map<std::string, double> seconds;
};

Experiment_file read_experiment_file(const std::string& path, const Label_mapping& labels,
                                     const SN::Normal_options& normals, const Feature_options& base,
                                     const std::vector<std::string>& groups)
{
  Experiment_file e;
  Feature_options all = base;
  all.groups = groups;
  // read with the rows of every group kept, then no group: each is computed and timed below, on those rows
  e.file = read_and_feature(path, labels, true, normals, all, false);
  for(const std::string& group : groups)
  {
    Feature_options one = base;
    one.groups = {group};
    CGAL::Real_timer timer;
    timer.start();
    e.groups[group] = compute_feature_columns(e.file.model, one, [&](const std::string& step) {
      progress(path + ": " + step);
    });
    e.seconds[group] = timer.time();
  }
  return e;
}

Featured_file with_set(const Experiment_file& e, const Feature_set_spec& set)
{
  Featured_file f;
  f.path = e.file.path;
  f.model.points = e.file.model.points; // for graph-cut's neighborhoods
  f.model.labels = e.file.model.labels;
  f.truth = e.file.truth;
  for(const std::string& group : set.groups)
  {
    const auto& columns = e.groups.at(group);
    f.columns.insert(f.columns.end(), columns.begin(), columns.end());
    f.seconds_features += e.seconds.at(group);
  }
  return f;
}

struct Run_result
{
  std::string set;
  unsigned int order = 0;
  bool graphcut = false;
  Confusion confusion{0};
  double train_seconds = 0., classify_seconds = 0.;
  std::vector<int> first_test_file; // its classes, kept for the figure (order 1 without graph-cut)
};


struct Set_summary
{
  std::string set;
  bool graphcut = false;
  std::size_t features = 0;
  double miou_mean = 0., miou_min = 0., miou_max = 0., oa_mean = 0., mf1_mean = 0.;
  std::vector<double> class_iou_mean;
  double feature_seconds = 0., train_seconds = 0., classify_seconds = 0.;
  double cross_validated_miou = std::numeric_limits<double>::quiet_NaN(); // on the training files
};

// Mean IoU of leaving each training file out in turn, per (set, graph-cut): the choice of a set is
// made on these, never on the test files.
typedef std::map<std::pair<std::string, bool>, double> Cross_validation;

std::vector<Set_summary> summarize(const std::vector<Feature_set_spec>& sets, const std::vector<Run_result>& runs,
                                   const std::vector<Experiment_file>& train_files,
                                   const std::vector<Experiment_file>& test_files, std::size_t classes)
{
  std::vector<Set_summary> result;
  for(const Feature_set_spec& set : sets)
    for(bool graphcut : {false, true})
    {
      Set_summary s;
      s.set = set.name;
      s.graphcut = graphcut;
      s.class_iou_mean.assign(classes, 0.);
      s.miou_min = std::numeric_limits<double>::infinity();
      s.miou_max = -s.miou_min;
      std::size_t n = 0;
      for(const Run_result& r : runs)
        if(r.set == set.name && r.graphcut == graphcut)
        {
          const double miou = r.confusion.mean_iou();
          s.miou_mean += miou;
          s.miou_min = std::min(s.miou_min, miou);
          s.miou_max = std::max(s.miou_max, miou);
          s.oa_mean += r.confusion.overall_accuracy();
          s.mf1_mean += r.confusion.mean_f1();
          for(std::size_t c = 0; c < classes; ++c)
            s.class_iou_mean[c] += r.confusion.iou(c);
          s.train_seconds += r.train_seconds;
          s.classify_seconds += r.classify_seconds;
          ++n;
        }
      if(n == 0)
        continue;
      s.miou_mean /= double(n);
      s.oa_mean /= double(n);
      s.mf1_mean /= double(n);
      for(double& v : s.class_iou_mean)
        v /= double(n);
      s.train_seconds /= double(n);
      s.classify_seconds /= double(n);
      for(const auto* files : {&train_files, &test_files})
        for(const Experiment_file& e : *files)
          for(const std::string& g : set.groups)
            s.feature_seconds += e.seconds.at(g);
      if(!train_files.empty())
        for(const std::string& g : set.groups)
          s.features += train_files.front().groups.at(g).size();
      result.push_back(std::move(s));
    }
  return result;
}

void write_experiment(const std::string& dir, const std::vector<Feature_set_spec>& sets,
                      const std::vector<Experiment_file>& train_files, const std::vector<Experiment_file>& test_files,
                      const std::vector<Run_result>& runs, const Classifier_settings& base, unsigned int orders,
                      double graphcut, const Cross_validation& cross_validation, unsigned int cv_orders)
{
  const Label_mapping& m = base.labels;
  const std::size_t classes = m.names.size();
  std::vector<Set_summary> summaries = summarize(sets, runs, train_files, test_files, classes);
  const Set_summary* chosen = nullptr;
  for(Set_summary& s : summaries)
  {
    const auto it = cross_validation.find({s.set, s.graphcut});
    if(it != cross_validation.end())
      s.cross_validated_miou = it->second;
  }
  for(const Set_summary& s : summaries)
    if(!std::isnan(s.cross_validated_miou) && (chosen == nullptr || s.cross_validated_miou > chosen->cross_validated_miou))
      chosen = &s;
  auto count_points = [](const std::vector<Experiment_file>& files) {
    std::size_t labeled = 0;
    for(const Experiment_file& e : files)
      for(int t : e.file.truth)
        labeled += t >= 0;
    return labeled;
  };
  auto paths = [](const std::vector<Experiment_file>& files) {
    std::string s;
    for(const Experiment_file& e : files)
      s += (s.empty() ? "" : ", ") + std::string("`") + std::filesystem::path(e.file.path).filename().string() + "`";
    return s;
  };

  write_file_atomically(dir + "/runs.csv", [&](std::ofstream& out) {
    out << "set,order,graphcut,overall_accuracy,mean_f1,mean_iou";
    for(const std::string& name : m.names)
      out << ",iou_" << name;
    out << ",train_seconds,classify_seconds\n";
    for(const Run_result& r : runs)
    {
      out << r.set << ',' << r.order << ',' << (r.graphcut ? 1 : 0) << ',' << number17(r.confusion.overall_accuracy())
          << ',' << number17(r.confusion.mean_f1()) << ',' << number17(r.confusion.mean_iou());
      for(std::size_t c = 0; c < classes; ++c)
        out << ',' << number17(r.confusion.iou(c));
      out << ',' << number_fixed(r.train_seconds, 3) << ',' << number_fixed(r.classify_seconds, 3) << '\n';
    }
  });

  write_file_atomically(dir + "/experiment.csv", [&](std::ofstream& out) {
    out << "set,groups,graphcut,features,mean_iou_mean,mean_iou_min,mean_iou_max,overall_accuracy_mean,mean_f1_mean";
    for(const std::string& name : m.names)
      out << ",iou_" << name << "_mean";
    out << ",feature_seconds,train_seconds_mean,classify_seconds_mean,cross_validated_mean_iou\n";
    for(const Set_summary& s : summaries)
    {
      std::string groups;
      for(const Feature_set_spec& set : sets)
        if(set.name == s.set)
          for(const std::string& g : set.groups)
            groups += (groups.empty() ? "" : "+") + g;
      out << s.set << ',' << groups << ',' << (s.graphcut ? 1 : 0) << ',' << s.features << ','
          << number17(s.miou_mean) << ',' << number17(s.miou_min) << ',' << number17(s.miou_max) << ','
          << number17(s.oa_mean) << ',' << number17(s.mf1_mean);
      for(double v : s.class_iou_mean)
        out << ',' << number17(v);
      out << ',' << number_fixed(s.feature_seconds, 2) << ',' << number_fixed(s.train_seconds, 2) << ','
          << number_fixed(s.classify_seconds, 2) << ','
          << (std::isnan(s.cross_validated_miou) ? std::string() : number17(s.cross_validated_miou)) << '\n';
    }
  });

  nlohmann::json j;
  j["labels"] = m.text();
  j["train"] = nlohmann::json::array();
  for(const Experiment_file& e : train_files)
    j["train"].push_back(e.file.path);
  for(const Experiment_file& e : test_files)
    j["test"].push_back(e.file.path);
  j["orders"] = orders;
  j["graphcut_strength"] = graphcut;
  j["trees"] = base.trees;
  j["depth"] = base.depth;
  j["normals"] = settings_json(base)["normals"];
  j["cross_validation_orders"] = cv_orders;
  if(chosen != nullptr)
    j["chosen"] = {{"set", chosen->set}, {"graphcut", chosen->graphcut}};
  for(const Set_summary& s : summaries)
  {
    nlohmann::json row = {{"set", s.set},          {"graphcut", s.graphcut},     {"features", s.features},
                          {"mean_iou", {{"mean", s.miou_mean}, {"min", s.miou_min}, {"max", s.miou_max}}},
                          {"overall_accuracy_mean", s.oa_mean}, {"mean_f1_mean", s.mf1_mean},
                          {"feature_seconds", s.feature_seconds}, {"train_seconds_mean", s.train_seconds},
                          {"classify_seconds_mean", s.classify_seconds}};
    if(!std::isnan(s.cross_validated_miou))
      row["cross_validated_mean_iou"] = s.cross_validated_miou;
    for(std::size_t c = 0; c < classes; ++c)
      row["iou_mean"][m.names[c]] = s.class_iou_mean[c];
    j["sets"].push_back(row);
  }
  write_file_atomically(dir + "/experiment.json", [&](std::ofstream& out) { out << j.dump(2) << '\n'; });

  write_file_atomically(dir + "/experiment.md", [&](std::ofstream& out) {
    out << "# Classification experiment\n\n"
        << "CGAL's ETHZ random forest (" << base.trees << " trees, depth " << base.depth << "), trained on "
        << paths(train_files) << " (" << count_points(train_files) << " labeled points), tested on "
        << paths(test_files) << " (" << count_points(test_files) << "); classes " << m.text()
        << ", other codes ignored. Every set in " << orders
        << " feature orders (the forest depends on the order): mean IoU as mean [min, max]; the other scores are "
           "means. Graph-cut: CGAL's classify_with_graphcut, strength "
        << number_fixed(graphcut, 2) << ", 12 neighbors. Times: features of all files, training and "
           "classification (one order).\n\n"
        << "| set | groups | graph-cut | features | mean IoU | OA | mean F1 |";
    for(const std::string& name : m.names)
      out << " IoU " << name << " |";
    out << " features + train + classify | cross-validated mean IoU |\n|---|---|---|---:|---|---:|---:|";
    for(std::size_t c = 0; c < classes; ++c)
      out << "---:|";
    out << "---:|---:|\n";
    for(const Set_summary& s : summaries)
    {
      std::string groups;
      for(const Feature_set_spec& set : sets)
        if(set.name == s.set)
          for(const std::string& g : set.groups)
            groups += (groups.empty() ? "" : " + ") + g;
      out << "| " << s.set << " | " << groups << " | " << (s.graphcut ? "yes" : "no") << " | " << s.features << " | "
          << fixed3(s.miou_mean) << " [" << fixed3(s.miou_min) << ", " << fixed3(s.miou_max) << "] | "
          << percent(s.oa_mean) << " | " << fixed3(s.mf1_mean) << " |";
      for(double v : s.class_iou_mean)
        out << ' ' << fixed3(v) << " |";
      out << ' ' << number_fixed(s.feature_seconds, 1) << " + " << number_fixed(s.train_seconds, 1) << " + "
          << number_fixed(s.classify_seconds, 1) << " s | " << fixed3(s.cross_validated_miou) << " |\n";
    }
    if(chosen != nullptr)
      out << "\nChosen on the training files alone (the best cross-validated mean IoU: each training file left out "
             "in turn, the forest trained on the others, "
          << cv_orders << " order" << (cv_orders == 1 ? "" : "s") << "): **" << chosen->set << "**, "
          << (chosen->graphcut ? "with" : "without") << " graph-cut, which scores " << fixed3(chosen->miou_mean)
          << " [" << fixed3(chosen->miou_min) << ", " << fixed3(chosen->miou_max) << "] on the test files.\n";
  });
  std::cerr << dir << "/experiment.md: " << sets.size() << " feature sets, " << orders << " orders, "
            << runs.size() << " runs\n";
}

// The first test file seen from above, by the truth, by the first set and by the set of best mean
// IoU without graph-cut (order 1), and their errors: DIR/figure_tile.csv and DIR/figure_tile.png.
bool write_experiment_figure(const std::string& dir, const std::vector<Feature_set_spec>& sets,
                             const Experiment_file& tile, const std::vector<Run_result>& runs, const Label_mapping& m)
{
  const std::vector<Set_summary> summaries =
    summarize(sets, runs, std::vector<Experiment_file>{}, std::vector<Experiment_file>{}, m.names.size());
  std::string best;
  double best_iou = -1.;
  for(const Set_summary& s : summaries)
    if(!s.graphcut && s.set != sets.front().name && s.miou_mean > best_iou)
    {
      best_iou = s.miou_mean;
      best = s.set;
    }
  std::vector<std::string> shown{sets.front().name};
  if(!best.empty())
    shown.push_back(best);
  std::vector<const std::vector<int>*> predictions;
  for(const std::string& name : shown)
    for(const Run_result& r : runs)
      if(r.set == name && r.order == 1 && !r.graphcut)
        predictions.push_back(&r.first_test_file);
  const std::string csv = dir + "/figure_tile.csv";
  write_file_atomically(csv, [&](std::ofstream& out) {
    out << "x,y,z,truth";
    for(const std::string& name : shown)
      out << ',' << name;
    out << '\n';
    for(std::size_t i = 0; i < tile.file.model.points.size(); ++i)
    {
      const auto& p = tile.file.model.points[i];
      out << number17(p.x()) << ',' << number17(p.y()) << ',' << number17(p.z()) << ',' << tile.file.truth[i];
      for(const auto* prediction : predictions)
        out << ',' << (*prediction)[i];
      out << '\n';
    }
  });
  std::string classes;
  for(const std::string& name : m.names)
    classes += (classes.empty() ? "" : ",") + name;
  const std::string title = std::filesystem::path(tile.file.path).filename().string() + ": truth, " +
                            shown.front() + (best.empty() ? "" : " and " + best) + " (order 1, no graph-cut)";
  if(!run_python_script("plot_classification.py", {csv, dir + "/figure_tile.png", "--classes", classes, "--title", title}))
  {
    std::cerr << "sigmoid-neighborhoods classify: the figure failed (plot_classification.py, matplotlib); "
              << csv << " holds its data\n";
    return false;
  }
  return true;
}

int run_experiment(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_normal_options({"-o", "--output", "--train", "--test", "--sets", "--orders", "--graphcut",
                                            "--labels", "--trees", "--depth", "--threads", "--cv-orders"}),
                       with_normal_flags({"-h", "--help"}), NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, CLASSIFY_USAGE))
    return EXIT_OK;
  const std::string output = args.output();
  if(output.empty() || !args.has("--train") || !args.has("--test") || !args.positional().empty())
    throw Usage_error("classify experiment needs --train FILE,... --test FILE,... -o DIR");
  const std::vector<std::string> train_paths = split_list(args.get("--train"), "--train");
  const std::vector<std::string> test_paths = split_list(args.get("--test"), "--test");
  const std::vector<Feature_set_spec> sets = parse_sets(args.get("--sets", DEFAULT_EXPERIMENT_SETS));
  const unsigned int orders = args.get_unsigned("--orders", 10);
  const unsigned int cv_orders = args.get_unsigned("--cv-orders", 1);
  const double graphcut = args.has("--graphcut") ? read_graphcut(args) : 0.2;
  if(orders < 1)
    throw Usage_error("--orders must be at least 1");
  Classifier_settings base;
  base.labels = parse_label_mapping(args.get("--labels", DEFAULT_LABELS));
  base.normals = classify_normal_options(args);
  base.features.threads = read_threads(args);
  base.trees = args.get_unsigned("--trees", 25);
  base.depth = args.get_unsigned("--depth", 20);
  std::vector<std::string> groups;
  for(const Feature_set_spec& set : sets)
    for(const std::string& g : set.groups)
      if(std::find(groups.begin(), groups.end(), g) == groups.end())
        groups.push_back(g);
  create_output_folder(output);

  std::vector<Experiment_file> train_files, test_files;
  for(const std::string& path : train_paths)
    train_files.push_back(read_experiment_file(path, base.labels, base.normals, base.features, groups));
  for(const std::string& path : test_paths)
    test_files.push_back(read_experiment_file(path, base.labels, base.normals, base.features, groups));

  std::vector<Run_result> runs;
  for(const Feature_set_spec& set : sets)
  {
    std::vector<Featured_file> train_set, test_set;
    for(const Experiment_file& e : train_files)
      train_set.push_back(with_set(e, set));
    for(const Experiment_file& e : test_files)
      test_set.push_back(with_set(e, set));
    for(unsigned int order = 1; order <= orders; ++order)
    {
      progress(set.name + ": order " + std::to_string(order) + " of " + std::to_string(orders));
      Trained t;
      t.settings = base;
      t.settings.features.groups = set.groups;
      t.settings.feature_order_seed = order;
      train(train_set, t);
      for(bool with_graphcut : {false, true})
      {
        Run_result r;
        r.set = set.name;
        r.order = order;
        r.graphcut = with_graphcut;
        r.confusion = Confusion(base.labels.names.size());
        r.train_seconds = t.seconds;
        for(const Featured_file& f : test_set)
        {
          const Prediction p = predict(f, t.settings, std::string(), t.forest.get(), with_graphcut ? graphcut : 0.);
          r.classify_seconds += p.seconds;
          for(std::size_t i = 0; i < p.classes.size(); ++i)
            r.confusion.add(f.truth[i], p.classes[i]);
          if(order == 1 && !with_graphcut && &f == &test_set.front())
            r.first_test_file = p.classes;
        }
        runs.push_back(std::move(r));
      }
    }
  }
  // Leave one training file out: what the choice of a set and of the graph-cut is made on.
  Cross_validation cross_validation;
  if(train_files.size() >= 2)
    for(const Feature_set_spec& set : sets)
    {
      std::array<double, 2> sum{{0., 0.}};
      for(unsigned int order = 1; order <= cv_orders; ++order)
      {
        std::array<Confusion, 2> pooled{{Confusion(base.labels.names.size()), Confusion(base.labels.names.size())}};
        for(std::size_t left_out = 0; left_out < train_files.size(); ++left_out)
        {
          progress(set.name + ": cross-validation, order " + std::to_string(order) + ", fold " +
                   std::to_string(left_out + 1));
          std::vector<Featured_file> others;
          for(std::size_t f = 0; f < train_files.size(); ++f)
            if(f != left_out)
              others.push_back(with_set(train_files[f], set));
          Trained t;
          t.settings = base;
          t.settings.features.groups = set.groups;
          t.settings.feature_order_seed = order;
          train(others, t);
          const Featured_file held_out = with_set(train_files[left_out], set);
          for(int with_graphcut = 0; with_graphcut < 2; ++with_graphcut)
          {
            const Prediction p = predict(held_out, t.settings, std::string(), t.forest.get(),
                                         with_graphcut ? graphcut : 0.);
            for(std::size_t i = 0; i < p.classes.size(); ++i)
              pooled[std::size_t(with_graphcut)].add(held_out.truth[i], p.classes[i]);
          }
        }
        for(std::size_t g = 0; g < 2; ++g)
          sum[g] += pooled[g].mean_iou();
      }
      for(std::size_t g = 0; g < 2; ++g)
        if(cv_orders > 0)
          cross_validation[{set.name, g == 1}] = sum[g] / double(cv_orders);
    }
  end_progress();
  write_experiment(output, sets, train_files, test_files, runs, base, orders, graphcut, cross_validation, cv_orders);
  return write_experiment_figure(output, sets, test_files.front(), runs, base.labels) ? EXIT_OK : EXIT_FAILED;
}

} // namespace

int run_classify(int argc, char** argv)
{
  const std::string sub = argc > FIRST_COMMAND_ARGUMENT ? argv[FIRST_COMMAND_ARGUMENT] : "";
  if(sub == "train")
    return run_train(argc, argv);
  if(sub == "predict")
    return run_predict(argc, argv);
  if(sub == "evaluate")
    return run_evaluate(argc, argv);
  if(sub == "experiment")
    return run_experiment(argc, argv);
  if(sub == "-h" || sub == "--help")
  {
    std::cout << CLASSIFY_USAGE << FEATURE_GROUPS_USAGE << NORMAL_USAGE;
    return EXIT_OK;
  }
  throw Usage_error(sub.empty() ? "classify needs train, predict, evaluate or experiment"
                                : "classify: unknown step '" + sub + "': expected train, predict, evaluate or experiment");
}

} // namespace sigmoid_tool
