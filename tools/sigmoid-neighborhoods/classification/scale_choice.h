// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first scale of the groups with scales in metres (cgal-metric's voxel and the pyramid's cell),
// chosen by classify train on its own training files (scale_choice.cpp).

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_SCALE_CHOICE_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_SCALE_CHOICE_H

#include "classifier_settings.h"
#include "feature_options.h"

#include <cstddef>
#include <string>
#include <vector>

namespace sigmoid_tool {
namespace classification {

// The candidates, in metres: octaves around the 0.5 m that the IGN tiles chose before, from 6.25 cm
// (the centimetres of a street scene: poles, wires, kerbs) to 1 m (a sparse airborne survey).
const std::vector<double>& scale_ladder();

// Whether a group of `o` has scales in metres.
bool has_metric_scales(const Feature_options& o);

// `o` with its first scale in metres `first` for every such group: cgal-metric's voxel, the pyramid's
// cell, and the pyramid's sigmoid cells by the same factor.
Feature_options with_first_scale(Feature_options o, double first);

// Training points per class and fold of the choice's forests by default: enough for a forest of 25
// trees to rank the candidates, few enough that the choice costs a few plain trainings.
constexpr std::size_t SCALE_CHOICE_CAP = 4000;

// The training files cannot tell the scales apart: a fold of the checkerboard has no labeled point.
struct Scale_choice_impossible : Usage_error
{
  using Usage_error::Usage_error;
};

// Chooses the first scale among scale_ladder() on the files `paths`, read with the settings `s`:
// the points split in space into two folds (a checkerboard of 4 x 4 blocks over the files' extent),
// a forest trained on the points of one fold (at most `cap` per class) predicts the other, at the
// files' density and trained on a copy thinned 4x at random (its normals estimated again); a
// candidate's score is the worse of the two pooled mean IoUs (a scale must hold at both densities),
// the best score wins and ties go to the coarser scale (fewer cells to compute). A class missing from
// a fold counts against every candidate alike. Throws Scale_choice_impossible when a fold has no training point.
Scale_choice_report choose_first_scale(const std::vector<std::string>& paths, const Classifier_settings& s,
                                       std::size_t cap = SCALE_CHOICE_CAP);

} // namespace classification
} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_SCALE_CHOICE_H
