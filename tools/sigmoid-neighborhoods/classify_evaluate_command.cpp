// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify evaluate: a model's classes against the labels of point sets, as a
// confusion matrix and its scores.

#include "classification/classify_common.h"
#include "classification/confusion.h"
#include "classification/label_mapping.h"
#include "command_line.h"
#include "phase_times.h"

#include <cstddef>
#include <iostream>
#include <string>

namespace sigmoid_tool {

using namespace classification; // what the steps share: classification/classify_common.h

int run_classify_evaluate(int argc, char** argv)
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
  Phase_times times;
  for(std::size_t f = 1; f < args.positional().size(); ++f)
  {
    const Featured_file file =
      read_and_feature(args.positional()[f], settings.labels, true, settings.normals, settings.features);
    times.end_reading(file.model);
    times.move("reading", "features", file.seconds_features);
    const Prediction p = predict(file, settings, forest_bytes, nullptr, graphcut);
    times.end("forest");
    for(std::size_t i = 0; i < p.classes.size(); ++i)
      confusion.add(file.truth[i], p.classes[i]);
  }
  end_progress();
  write_evaluation(output, confusion, settings.labels, "Classification of " + std::to_string(args.positional().size() - 1) +
                                                         " file(s) by " + model_path);
  times.end("writing");
  std::cerr << output << ": overall accuracy " << percent(confusion.overall_accuracy()) << ", mean F1 "
            << fixed3(confusion.mean_f1()) << ", mean IoU " << fixed3(confusion.mean_iou()) << " on "
            << confusion.total() << " points, " << number_fixed(times.total(), 2) << " s (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace sigmoid_tool
