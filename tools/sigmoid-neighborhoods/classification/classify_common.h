// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the steps of sigmoid-neighborhoods classify share (classify_*_command.cpp): the files read and
// featured, CGAL's ETHZ random forest trained and applied, the outputs and the line of progress. Their
// definitions are in classify_common.cpp, the one translation unit that instantiates CGAL's training,
// classify(), graph-cut, the PLY writer and the feature computation of add_features(). This header is
// light (no CGAL classification, no feature computation): the training, which holds the forest, is
// declared in classify_training.h.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_COMMON_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_COMMON_H

#include "classifier_settings.h"
#include "confusion.h"
#include "feature_options.h"
#include "label_mapping.h"
#include "../command_line.h"
#include "../model_input.h"

#include <CGAL/Bbox_2.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace Classification {
class Ethz_forest;
} // namespace Classification
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

namespace sigmoid_tool {

// The steps of classify, one translation unit each, that run_classify (classify_command.cpp) dispatches to.
int run_classify_train(int argc, char** argv);      // classify_train_command.cpp
int run_classify_predict(int argc, char** argv);    // classify_predict_command.cpp
int run_classify_evaluate(int argc, char** argv);   // classify_evaluate_command.cpp
int run_classify_experiment(int argc, char** argv); // classify_experiment_command.cpp

namespace classification {

extern const char* const CLASSIFY_USAGE; // classify_command.cpp

std::string number_fixed(double v, int digits);
std::string percent(double v); // "n/a" for NaN
std::string fixed3(double v);  // "n/a" for NaN

// One line of progress on a terminal, nothing in a log.
void progress(const std::string& what);
void end_progress();

// A labeled (or unlabeled) file read and featured.
struct Featured_file
{
  std::string path;
  SN::Oriented_point_set model;
  std::vector<int> truth; // class index per point, -1: not in any class (or no labels)
  std::vector<Feature_column> columns;
  double seconds_features = 0.;
};

SN::Normal_options classify_normal_options(const Arguments& args);

// The options of the feature groups that train and experiment share (--threads, --sigmoid, --pyramid-*,
// --cgal-*; classify_command.cpp), added to `valued`; the groups are left empty: each caller's.
std::vector<std::string> with_feature_options(std::vector<std::string> valued);
Feature_options read_feature_options(const Arguments& args);

// --graphcut STRENGTH (0: none).
double read_graphcut(const Arguments& args);

// The truth and, when `compute_features`, the feature columns of `f.model`.
void add_features(Featured_file& f, const Label_mapping& labels, bool need_labels, const Feature_options& features,
                  bool compute_features = true);

Featured_file read_and_feature(const std::string& path, const Label_mapping& labels, bool need_labels,
                               const SN::Normal_options& normals, const Feature_options& features,
                               bool compute_features = true);

// The points of `path` with their labels and truth alone: no normals estimated, no features (the
// same points as read_and_feature() reads).
Featured_file read_labels(const std::string& path, const Classifier_settings& settings);

// Throws where `f`, read again, has other than the `labeled_points` that read_labels() found.
void check_same_points(const Featured_file& f, std::size_t labeled_points);

// The classes of one file under a trained forest, and each class's probability per point.
struct Prediction
{
  std::vector<int> classes;
  std::vector<std::vector<float>> confidence; // per class, per point
  double seconds = 0.;
  double seconds_loading = 0.; // of `seconds`: the forest read from its bytes
};

Prediction predict(const Featured_file& file, const Classifier_settings& settings, const std::string& forest_bytes,
                   const SN::Classification::Ethz_forest* trained, double graphcut);

// The points `first` ... `last - 1` of `file` (a tile without its halo), all by default.
void write_prediction_ply(const std::string& path, const Featured_file& file, const Prediction& p,
                          const Label_mapping& m, std::size_t first = 0, std::size_t last = std::size_t(-1));

void write_evaluation(const std::string& dir, const Confusion& c, const Label_mapping& m, const std::string& title);

} // namespace classification

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_COMMON_H
