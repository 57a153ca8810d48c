// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What `sigmoid-neighborhoods evaluate` (evaluate_command.cpp) shares with report: a model's
// evaluation and its per-point CSV.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EVALUATE_COMMAND_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EVALUATE_COMMAND_H

#include "evaluation_json.h"
#include "optimal_command.h"

#include <CGAL/Sigmoid_neighborhoods/Point_evaluation.h>

#include <ostream>
#include <vector>

namespace sigmoid_tool {

// The evaluation of every point of `model` (instantiated once, for evaluate and report's figure model).
std::vector<SN::Point_evaluation> evaluate_model(const SN::Oriented_point_set& model, const Search_options& o,
                                                 const Evaluation_settings& s);

// The optimal CSV's columns, then the other weightings of the evaluation (evaluate --per-point and
// report's figure model).
void write_evaluation_csv(std::ostream& out, const SN::Oriented_point_set& model,
                          const std::vector<SN::Point_evaluation>& evaluations, unsigned int threads);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EVALUATE_COMMAND_H
