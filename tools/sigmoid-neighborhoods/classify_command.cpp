// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify: semantic classification of labeled point sets (LAS classification
// codes, PLY labels) with CGAL's ETHZ random forest on CGAL's and the package's features: train,
// predict, evaluate, and the experiment that compares feature sets. Here the dispatcher and the usage;
// each step in its own translation unit (classify_*_command.cpp, what they share in
// classification/classify_common.cpp): CGAL's Classification headers compile slowly.

#include "commands.h"

#include "classification/classify_common.h"
#include "classification/feature_options.h"
#include "command_line.h"
#include "model_input.h"

#include <iostream>
#include <string>

namespace sigmoid_tool {

namespace classification {

const char* const CLASSIFY_USAGE =
  "usage: sigmoid-neighborhoods classify train FILE... -o MODEL [--labels MAP] [--features GROUPS]\n"
  "                                [--trees 25] [--depth 20] [--feature-order-seed N] [--max-per-class N]\n"
  "                                [--pyramid-cell 0.5] [--pyramid-levels 5] [--sigmoid 30deg,60deg] [normals]\n"
  "                                [--threads N]\n"
  "       sigmoid-neighborhoods classify predict MODEL INPUT|--catalog SOURCE [--tile NAME] -o OUT.ply\n"
  "                                [--graphcut STRENGTH] [--threads N]\n"
  "       sigmoid-neighborhoods classify evaluate MODEL FILE... -o DIR [--graphcut STRENGTH] [--threads N]\n"
  "       sigmoid-neighborhoods classify experiment --train FILE,... --test FILE,... -o DIR [--sets SETS]\n"
  "                                [--orders 10] [--cv-orders 1] [--graphcut 0.2] [--labels MAP] [--trees 25]\n"
  "                                [--depth 20] [--max-per-class N] [normals]\n"
  "  FILE: a labeled point set: LAS or LAZ (classification codes) or PLY with a label/class/classification property\n"
  "  --labels MAP: the classes and their codes, other codes ignored (default ground=2,low_vegetation=3+4,\n"
  "      high_vegetation=5,building=6)\n"
  "  --feature-order-seed N: the features in a shuffled order (CGAL's forest depends on it; 0: as listed)\n"
  "  --max-per-class N: train on at most N points of each class, evenly spaced in the files' order (0: all)\n"
  "  training runs its trees in parallel on TBB when the build has it: the same forest for any --threads\n"
  "  --graphcut STRENGTH: CGAL's graph-cut regularisation of the labels on 12 neighbors (e.g. 0.2)\n"
  "  normals are estimated (pca on 18 neighbors) and oriented upwards unless --orientation says otherwise\n"
  "  predict writes a binary PLY: scalar_label (class index), scalar_confidence_<class>, red green blue\n"
  "  predict --catalog SOURCE: the union of the tiles in one run; with --tile NAME, the tile's points alone,\n"
  "      featured with a halo of the other tiles' points that holds the k nearest neighbors of the model's\n"
  "      groups, the neighbors of their normals and, for the group height, every cell of the tile (for the\n"
  "      pyramid groups, one checked to hold each level's representatives and rows near the tile): their labels\n"
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

} // namespace classification

int run_classify(int argc, char** argv)
{
  const std::string sub = argc > FIRST_COMMAND_ARGUMENT ? argv[FIRST_COMMAND_ARGUMENT] : "";
  if(sub == "train")
    return run_classify_train(argc, argv);
  if(sub == "predict")
    return run_classify_predict(argc, argv);
  if(sub == "evaluate")
    return run_classify_evaluate(argc, argv);
  if(sub == "experiment")
    return run_classify_experiment(argc, argv);
  if(sub == "-h" || sub == "--help")
  {
    std::cout << classification::CLASSIFY_USAGE << FEATURE_GROUPS_USAGE << NORMAL_USAGE;
    return EXIT_OK;
  }
  throw Usage_error(sub.empty() ? "classify needs train, predict, evaluate or experiment"
                                : "classify: unknown step '" + sub + "': expected train, predict, evaluate or experiment");
}

} // namespace sigmoid_tool

