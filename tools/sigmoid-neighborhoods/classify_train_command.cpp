// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify train: CGAL's ETHZ random forest trained on labeled point sets, saved
// as a model file (classification/classifier_model.h).

#include "classification/classify_common.h"
#include "classification/classify_training.h"
#include "classification/feature_options.h"
#include "classification/label_mapping.h"
#include "classification/scale_choice.h"
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

namespace {

// "; scales in metres chosen: 0.5 m (mean IoU 0.842, trained 4x thinner 0.835; 0.0625 m: ...)"
std::string scale_choice_text(const Classifier_settings& s)
{
  if(!s.scale_choice)
    return std::string();
  const Scale_choice_report& c = *s.scale_choice;
  std::string text = "; first scale in metres chosen: " + number17(c.chosen) + " m (mean IoU, at the density and "
                     "trained 4x thinner:";
  for(std::size_t i = 0; i < c.ladder.size(); ++i)
    text += std::string(i == 0 ? " " : ", ") + number17(c.ladder[i]) + " m " + number_fixed(c.same_density[i], 3) +
            " " + number_fixed(c.thinned[i], 3);
  return text + "; " + number_fixed(c.seconds, 1) + " s)";
}

} // namespace

int run_classify_train(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_feature_options(with_normal_options({"-o", "--output", "--labels", "--features",
                                                                 "--trees", "--depth", "--feature-order-seed",
                                                                 "--max-per-class"})),
                       with_normal_flags({"-h", "--help", "--choose-scales"}), NORMAL_TRIPLE_OPTIONS);
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
  // The scales in metres are chosen on the training files unless given: explicitly with
  // --choose-scales (refused where it cannot be made), else wherever a group has them (where the files
  // cannot tell the scales apart, the fixed ones, said on the summary line).
  const bool scales_given = args.has("--cgal-voxel") || args.has("--pyramid-cell");
  if(args.has("--choose-scales"))
  {
    if(scales_given)
      throw Usage_error("--choose-scales chooses --cgal-voxel and --pyramid-cell: give them or it");
    if(!has_metric_scales(t.settings.features))
      throw Usage_error("--choose-scales: no group of --features has scales in metres (cgal-metric, cgal-grid, "
                        "pyramid, pyramid-sigmoid)");
  }
  std::string unchosen;
  if(!scales_given && has_metric_scales(t.settings.features))
  {
    try
    {
      t.settings.scale_choice = choose_first_scale(args.positional(), t.settings);
      t.settings.features = with_first_scale(t.settings.features, t.settings.scale_choice->chosen);
    }
    catch(const Scale_choice_impossible& e)
    {
      if(args.has("--choose-scales"))
        throw;
      unchosen = std::string("; first scale in metres not chosen (") + e.what() + "): " +
                 number17(t.settings.features.cgal_voxel) + " m";
    }
    times.end("choice of scales");
  }
  const std::size_t points = train_file_by_file(args.positional(), t, times);
  write_classifier_model(output, t.settings, *t.forest);
  times.end("writing");
  end_progress();
  std::cerr << output << ": " << t.settings.feature_names.size() << " features, " << t.settings.labels.names.size()
            << " classes, " << points << " points from " << args.positional().size() << " file(s)"
            << (t.training_points != points ? " (" + std::to_string(t.training_points) + " trained on)" : std::string())
            << scale_choice_text(t.settings) << unchosen
            << "; " << number_fixed(times.total(), 2) << " s (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace sigmoid_tool
