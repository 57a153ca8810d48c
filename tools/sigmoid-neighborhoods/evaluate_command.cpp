// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods evaluate and merge (evaluate_command.h).

#include "commands.h"
#include "evaluate_command.h"

#include <CGAL/Sigmoid_neighborhoods/evaluate_sigmoid_neighborhoods.h>

namespace sigmoid_tool {

std::vector<SN::Point_evaluation> evaluate_model(const SN::Oriented_point_set& model, const Search_options& o,
                                                 const Evaluation_settings& s)
{
  namespace SNP = SN::parameters;
  std::vector<SN::Point_evaluation> result;
  result.reserve(model.points.size());
  with_model_neighborhoods(model, o, [&](const auto& np) {
    SN::evaluate_sigmoid_neighborhoods<SN::Parallel_if_available_tag>(
      point_indices(model.points.size()), std::back_inserter(result),
      SNP::cut_off_angle(s.cut_off_angle, SNP::fixed_k(s.fixed_k, np)));
  });
  return result;
}

int run_evaluate_command(int argc, char** argv) { return run_evaluate(argc, argv); }

int run_merge_command(int argc, char** argv) { return run_merge(argc, argv); }
} // namespace sigmoid_tool
