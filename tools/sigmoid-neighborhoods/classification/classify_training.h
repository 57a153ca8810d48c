// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The training of classify (classify_common.cpp), for the steps that train: train and experiment.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_TRAINING_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_TRAINING_H

#include "classifier_model.h"
#include "classify_common.h"
#include "../phase_times.h"

#include <CGAL/Sigmoid_neighborhoods/Classification/Ethz_forest.h>

#include <optional>
#include <string>
#include <vector>

namespace sigmoid_tool {
namespace classification {

// A forest trained, and the settings with the feature names in the forest's order.
struct Trained
{
  Classifier_settings settings;
  std::optional<SN::Classification::Ethz_forest> forest;
  double seconds = 0.;
  std::size_t training_points = 0; // after --max-per-class
};

// Trains the forest of `t.settings` on `files`, whose features are computed.
void train(const std::vector<Featured_file>& files, Trained& t);

// Trains it on the files `paths`, reading and featuring one at a time, so that memory holds one
// file's features and the training points' rows (as float, CGAL's forest's type) rather than every
// file's columns: the same forest as train(). The files are read twice: first for the labels of
// their points, which size the rows and choose the points of --max-per-class. The phases go to
// `times`; returns the number of points read.
std::size_t train_file_by_file(const std::vector<std::string>& paths, Trained& t, Phase_times& times);

} // namespace classification
} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_TRAINING_H
