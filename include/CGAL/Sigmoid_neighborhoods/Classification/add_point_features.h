// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_ADD_POINT_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_ADD_POINT_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/Classification/Feature_values.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>

#include <CGAL/Classification/Feature_set.h>

#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace Classification {

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  the features of `Point_feature` that describe the shape of the neighborhood, the default set of
  `add_point_features()`: linearity, planarity, scattering, omnivariance, anisotropy, eigenentropy,
  sum of eigenvalues, change of curvature, verticality and the normal's `z`.
*/
inline std::vector<Point_feature> default_point_features()
{
  return {Point_feature::LINEARITY,    Point_feature::PLANARITY,          Point_feature::SCATTERING,
          Point_feature::OMNIVARIANCE, Point_feature::ANISOTROPY,         Point_feature::EIGENENTROPY,
          Point_feature::SUM_OF_EIGENVALUES, Point_feature::CHANGE_OF_CURVATURE, Point_feature::VERTICALITY,
          Point_feature::NORMAL_Z};
}

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  \brief adds the features `which` of `features` (one record per item of the classified range) to
  `feature_set`, each a `Feature_values` named `point_feature_name(f) + suffix`, next to whatever
  `CGAL::Classification::Point_set_feature_generator` or the caller added.

  \tparam PointFeaturesRange a range of `Point_features`, such as what `compute_point_features()`
          or `compute_optimal_point_features()` write
  \param feature_set the feature set of the classifier
  \param features one record per item, in the items' order
  \param which the features to add (`default_point_features()` by default)
  \param suffix appended to each name, to tell scales or neighborhood choices apart (`"_k20"`, `"_optimal"`)
*/
template <typename PointFeaturesRange>
void add_point_features(CGAL::Classification::Feature_set& feature_set, const PointFeaturesRange& features,
                        const std::vector<Point_feature>& which = default_point_features(),
                        const std::string& suffix = std::string())
{
  for(Point_feature f : which)
  {
    std::vector<double> values;
    for(const Point_features& p : features)
      values.push_back(p.value(f));
    // moved: with parallel additions (TBB), the Feature_set keeps its arguments until end_parallel_additions()
    feature_set.add<Feature_values>(std::move(values), point_feature_name(f) + suffix);
  }
}

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  \brief adds the three `Height_features` to `feature_set`, named `height_above_lowest`,
  `height_below_highest` and `vertical_range` followed by `suffix`.
*/
template <typename HeightFeaturesRange>
void add_height_features(CGAL::Classification::Feature_set& feature_set, const HeightFeaturesRange& features,
                         const std::string& suffix = std::string())
{
  std::vector<double> above, below, range;
  for(const Height_features& h : features)
  {
    above.push_back(h.height_above_lowest);
    below.push_back(h.height_below_highest);
    range.push_back(h.vertical_range);
  }
  feature_set.add<Feature_values>(std::move(above), "height_above_lowest" + suffix);
  feature_set.add<Feature_values>(std::move(below), "height_below_highest" + suffix);
  feature_set.add<Feature_values>(std::move(range), "vertical_range" + suffix);
}

} // namespace Classification
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_ADD_POINT_FEATURES_H
