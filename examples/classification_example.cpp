// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Semantic classification with CGAL's ETHZ random forest, in the manner of CGAL's
// example_ethz_random_forest.cpp: CGAL's own multi-scale features, then the same with the package's
// features at each point's optimal sigmoid neighborhood added. Trained on half of a labeled scan (a
// PLY with an int property `label`, such as CGAL's data/points_3/b9_training.ply), evaluated on the
// other half.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Classification.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <CGAL/Sigmoid_neighborhoods/Point_set_3/estimate_and_orient_normals.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/add_point_features.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Point_set_3<Point, Vector> Point_set;
typedef CGAL::Classification::Point_set_feature_generator<Kernel, Point_set, Point_set::Point_map> Feature_generator;

namespace Classification = CGAL::Classification;
namespace SN = CGAL::Sigmoid_neighborhoods;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: classification_example LABELED.ply\n";
    return EXIT_FAILURE;
  }
  Point_set points;
  std::ifstream in(argv[1], std::ios::binary);
  if(!(in >> points))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  Point_set::Property_map<int> label_map;
  bool has_labels = false;
  std::tie(label_map, has_labels) = points.property_map<int>("label");
  if(!has_labels)
  {
    std::cerr << "no int property 'label' in " << argv[1] << "\n";
    return EXIT_FAILURE;
  }

  Classification::Label_set labels;
  labels.add("ground");
  labels.add("vegetation");
  labels.add("roof");

  // Train on the dark squares of a 10 m checkerboard, test on the light ones: no point is in both,
  // and the scan's labeled patches give every class to both.
  const double cell = 10.;
  std::vector<int> train(points.size(), -1), test(points.size(), -1);
  for(Point_set::Index i : points)
  {
    const Point& p = points.point(i);
    const bool dark = (static_cast<long>(std::floor(p.x() / cell)) + static_cast<long>(std::floor(p.y() / cell))) % 2 == 0;
    (dark ? train : test)[std::size_t(i)] = label_map[i];
  }

  // The package's features need oriented normals: estimated, then turned upwards (an airborne scan).
  SN::estimate_and_orient_normals<SN::Parallel_if_available_tag>(points, 18);
  for(Point_set::Index i : points)
    if(points.normal(i).z() < 0.)
      points.normal(i) = -points.normal(i);
  std::vector<SN::Point_features> optimal;
  SN::compute_optimal_point_features<SN::Parallel_if_available_tag>(
    points, std::back_inserter(optimal),
    CGAL::parameters::point_map(points.point_map()).normal_map(points.normal_map()));

  Feature_generator generator(points, points.point_map(), 5); // CGAL's 5 scales
  for(bool with_package_features : {false, true})
  {
    Classification::Feature_set features;
    features.begin_parallel_additions();
    generator.generate_point_based_features(features);
    features.end_parallel_additions();
    if(with_package_features)
      SN::Classification::add_point_features(features, optimal, SN::Classification::default_point_features(),
                                             "_optimal");

    Classification::ETHZ::Random_forest_classifier classifier(labels, features);
    classifier.train(train);
    std::vector<int> predicted(points.size(), -1);
    Classification::classify<CGAL::Parallel_if_available_tag>(points, labels, classifier, predicted);
    const Classification::Evaluation evaluation(labels, test, predicted);
    std::cout << std::fixed << std::setprecision(3)
              << (with_package_features ? "CGAL's and the package's features" : "CGAL's features")
              << " (" << features.size() << "): accuracy " << evaluation.accuracy() << ", mean IoU "
              << evaluation.mean_intersection_over_union() << "\n";
  }
  return EXIT_SUCCESS;
}
