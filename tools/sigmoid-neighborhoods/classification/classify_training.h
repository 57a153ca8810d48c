// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The training of classify (classify_common.cpp), for the steps that train: train and experiment.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_TRAINING_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_TRAINING_H

#include "classifier_model.h"
#include "classify_common.h"

#include <CGAL/Classification/ETHZ/Random_forest_classifier.h>
#include <CGAL/Classification/Feature_set.h>
#include <CGAL/Classification/Label_set.h>

#include <memory>
#include <vector>

namespace sigmoid_tool {
namespace classification {

// Trains a forest on `files`; returns the settings with the feature names in the forest's order.
struct Trained
{
  Classifier_settings settings;
  CGAL::Classification::Label_set labels;
  CGAL::Classification::Feature_set features;
  std::unique_ptr<Forest> forest;
  double seconds = 0.;
  std::size_t training_points = 0; // after --max-per-class
};

void train(const std::vector<Featured_file>& files, Trained& t);

} // namespace classification
} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFY_TRAINING_H
