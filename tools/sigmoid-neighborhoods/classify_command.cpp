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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace classification {

const char* const CLASSIFY_USAGE =
  "usage: sigmoid-neighborhoods classify train FILE... -o MODEL [--labels MAP] [--features GROUPS]\n"
  "                                [--trees 25] [--depth 20] [--feature-order-seed N] [--max-per-class N]\n"
  "                                [--pyramid-cell S] [--pyramid-levels 5] [--pyramid-sigmoid-cells C,...]\n"
  "                                [--sigmoid 30deg,60deg] [--scales 10,25,50,100] [--cgal-voxel S]\n"
  "                                [--cgal-scales 5] [--choose-scales] [normals] [--threads N]\n"
  "       sigmoid-neighborhoods classify predict MODEL INPUT|--catalog SOURCE [--tile NAME] -o OUT.ply|OUT.las|OUT.laz\n"
  "                                [--graphcut STRENGTH] [--threads N]\n"
  "       sigmoid-neighborhoods classify evaluate MODEL FILE... -o DIR [--graphcut STRENGTH] [--threads N]\n"
  "       sigmoid-neighborhoods classify experiment --train FILE,... --test FILE,... -o DIR [--sets SETS]\n"
  "                                [--orders 10] [--cv-orders 1] [--graphcut 0.2] [--labels MAP] [--trees 25]\n"
  "                                [--depth 20] [--max-per-class N] [--choose-scales] [the feature options of train]\n"
  "                                [normals]\n"
  "  FILE: a labeled point set: LAS or LAZ (classification codes) or PLY with a label/class/classification property\n"
  "  --labels MAP: the classes and their codes, other codes ignored (default ground=2,low_vegetation=3+4,\n"
  "      high_vegetation=5,building=6)\n"
  "  --feature-order-seed N: the features in a shuffled order (CGAL's forest depends on it; 0: as listed)\n"
  "  --cgal-voxel S: the voxel of the groups cgal-metric and cgal-grid's first scale in metres, doubled per\n"
  "      scale, stored in the model (default: chosen, see --choose-scales); --cgal-scales N: the number of\n"
  "      scales of cgal, cgal-metric and cgal-grid (5)\n"
  "  --choose-scales: --cgal-voxel and --pyramid-cell (one value) chosen among 0.0625, 0.125, 0.25, 0.5\n"
  "      and 1 m on the training files: two folds of a 4 x 4 checkerboard, each predicted by a forest\n"
  "      trained on the other (at most 4000 points a class), at the files' density and trained on a copy\n"
  "      thinned 4x; the best of the worse of the two mean IoUs, stored in the model with the scores.\n"
  "      train chooses so by default wherever a group has scales in metres and neither option is given\n"
  "      (0.5 m where a fold of the files has no labeled point; with --choose-scales, refused there);\n"
  "      experiment only with --choose-scales (else both are 0.5 m)\n"
  "  --scales K,...: the neighbor counts of the groups multiscale and multiscale-sigmoid (10,25,50,100),\n"
  "      stored in the model\n"
  "  --max-per-class N: train on at most N points of each class, evenly spaced in the files' order (0: all)\n"
  "  training grows its trees on --threads threads: the same trees for any number\n"
  "  --graphcut STRENGTH: CGAL's graph-cut regularisation of the labels on 12 neighbors (e.g. 0.2)\n"
  "  normals are estimated (pca on 18 neighbors) and oriented upwards unless --orientation says otherwise\n"
  "  predict writes a binary PLY: scalar_label (class index), scalar_confidence_<class>, red green blue;\n"
  "      or, to OUT.las, LAS 1.4: the input's LAS/LAZ records untouched but their classification, the\n"
  "      predicted class's first code in the model (--class-codes NAME=CODE,... to choose others), with\n"
  "      extra bytes dimensions confidence (float) and original_class; to OUT.laz, the same compressed;\n"
  "      with --tile NAME, the tile's file's records (not of a catalog's union)\n"
  "  predict --catalog SOURCE: the union of the tiles in one run; with --tile NAME, the tile's points alone,\n"
  "      featured with a halo of the other tiles' points that holds the k nearest neighbors of the model's\n"
  "      groups, the neighbors of their normals and, for the group height, every cell of the tile (for the\n"
  "      pyramid groups and cgal-metric, one checked to hold each level's representatives and rows, and the\n"
  "      12 nearest points and voxels, near the tile; for cgal-metric and cgal-grid, their grids' windows):\n"
  "      their labels and confidences are those of the union, bit for bit (orientation mst excepted); refused\n"
  "      with --tile: the group cgal (CGAL takes its scales from the average spacing), cgal-metric and\n"
  "      cgal-grid in models trained before their grids were anchored at the origin, and --graphcut (a\n"
  "      minimisation over the whole point set): predict the union for those\n"
  "  evaluate writes DIR/evaluation.md, .csv, .json: confusion matrix, precision, recall, F1, IoU per\n"
  "      class, overall accuracy, mean F1, mean IoU\n"
  "  experiment trains and tests every feature set of --sets (NAME=GROUP,GROUP;NAME=...; default: the sets\n"
  "      A to Q of benchmark/README.md) in --orders feature orders, with and without graph-cut (--graphcut 0:\n"
  "      without alone), and writes DIR/experiment.md, experiment.csv, experiment.json and runs.csv; each set\n"
  "      is also cross-validated on the training files (each left out in turn, --cv-orders orders), and the\n"
  "      set and graph-cut of the best cross-validated mean IoU are reported as the choice; with\n"
  "      --choose-scales, each set with scales in metres is trained and tested at the first scale that\n"
  "      train would choose for it on the training files, and the ladder's scores are reported\n";

std::vector<std::string> with_feature_options(std::vector<std::string> valued)
{
  for(const char* option : {"--threads", "--sigmoid", "--pyramid-cell", "--pyramid-levels", "--pyramid-sigmoid-cells",
                            "--cgal-voxel", "--cgal-scales", "--scales"})
    valued.push_back(option);
  return valued;
}

Feature_options read_feature_options(const Arguments& args)
{
  Feature_options o;
  o.threads = read_threads(args);
  o.pyramid_cell = args.get_double("--pyramid-cell", o.pyramid_cell);
  o.pyramid_levels = args.get_unsigned("--pyramid-levels", o.pyramid_levels);
  if(args.has("--sigmoid"))
  {
    // the smaller angle is a, the larger b; one angle is a step (a = b)
    const std::vector<double> ab = read_angle_list(args, "--sigmoid", {});
    if(ab.size() > 2)
      throw Usage_error("--sigmoid needs the two angles A,B of the weights (e.g. 30deg,60deg)");
    o.sigmoid_a = ab.front();
    o.sigmoid_b = ab.back();
  }
  if(args.has("--pyramid-sigmoid-cells"))
    for(const std::string& item : split(args.get("--pyramid-sigmoid-cells"), ','))
    {
      char* end = nullptr;
      const double cell = std::strtod(item.c_str(), &end);
      if(item.empty() || *end != '\0')
        throw Usage_error("--pyramid-sigmoid-cells: '" + item + "' is not a cell size in metres");
      std::vector<double>& chosen = o.pyramid_sigmoid_cells;
      if(std::find(chosen.begin(), chosen.end(), cell) == chosen.end())
        chosen.push_back(cell);
    }
  o.cgal_voxel = args.get_double("--cgal-voxel", o.cgal_voxel);
  if(args.has("--scales"))
  {
    // ascending and distinct: the columns are named by k
    o.scales.clear();
    for(const std::string& item : split(args.get("--scales"), ','))
    {
      char* end = nullptr;
      const unsigned long k = std::strtoul(item.c_str(), &end, 10);
      if(item.empty() || item[0] == '-' || *end != '\0' || k < 1 || k > 10000)
        throw Usage_error("--scales: '" + item + "' is not a neighbor count of 1 to 10000");
      o.scales.push_back(static_cast<unsigned int>(k));
    }
    std::sort(o.scales.begin(), o.scales.end());
    o.scales.erase(std::unique(o.scales.begin(), o.scales.end()), o.scales.end());
  }
  o.cgal_scales = args.get_unsigned("--cgal-scales", o.cgal_scales);
  o.check(Feature_options::COMMAND_LINE);
  return o;
}

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
    std::cout << classification::CLASSIFY_USAGE << feature_groups_usage() << NORMAL_USAGE;
    return EXIT_OK;
  }
  throw Usage_error(sub.empty() ? "classify needs train, predict, evaluate or experiment"
                                : "classify: unknown step '" + sub + "': expected train, predict, evaluate or experiment");
}

} // namespace sigmoid_tool

