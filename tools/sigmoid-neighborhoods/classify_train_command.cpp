// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify train: CGAL's ETHZ random forest trained on labeled point sets, saved
// as a model file (classification/classifier_model.h).

#include "classification/classify_common.h"
#include "classification/classify_training.h"
#include "classification/feature_options.h"
#include "classification/label_mapping.h"
#include "command_line.h"
#include "model_input.h"
#include "phase_times.h"

#include <cmath>
#include <cstddef>
#include <iostream>
#include <string>
#include <vector>

namespace sigmoid_tool {

using namespace classification; // what the steps share: classification/classify_common.h

int run_classify_train(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_feature_options(with_normal_options({"-o", "--output", "--labels", "--features",
                                                                 "--trees", "--depth", "--feature-order-seed",
                                                                 "--max-per-class"})),
                       with_normal_flags({"-h", "--help"}), NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, CLASSIFY_USAGE))
  {
    std::cout << feature_groups_usage() << NORMAL_USAGE;
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
  t.settings.features.groups = parse_feature_groups(args.get("--features", DEFAULT_FEATURE_GROUPS));
  t.settings.normals = classify_normal_options(args);
  t.settings.trees = args.get_unsigned("--trees", 25);
  t.settings.depth = args.get_unsigned("--depth", 20);
  t.settings.feature_order_seed = args.get_unsigned("--feature-order-seed", 0);
  t.settings.max_per_class = args.get_unsigned("--max-per-class", 0);
  if(t.settings.trees < 1 || t.settings.depth < 1)
    throw Usage_error("--trees and --depth must be at least 1");
  Phase_times times;
  const std::size_t points = train_file_by_file(args.positional(), t, times);
  write_classifier_model(output, t.settings, *t.forest);
  times.end("writing");
  end_progress();
  std::cerr << output << ": " << t.settings.feature_names.size() << " features, " << t.settings.labels.names.size()
            << " classes, " << points << " points from " << args.positional().size() << " file(s)"
            << (t.training_points != points ? " (" + std::to_string(t.training_points) + " trained on)" : std::string())
            << "; " << number_fixed(times.total(), 2) << " s (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace sigmoid_tool
