// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_FEATURE_VALUES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_FEATURE_VALUES_H

#include <CGAL/Classification/Feature_base.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace Classification {

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  a feature of CGAL's Classification package whose values are computed beforehand, one per item,
  as CGAL's own `CGAL::Classification::Feature::Eigenvalue` holds its values: how the package's
  `Point_features` and `Height_features` enter a `CGAL::Classification::Feature_set`
  (see `add_point_features()`).

  Values are stored as `float`, as CGAL's features are. A non-finite value (the entropies of a
  degenerate neighborhood are `+inf`) is stored as `NON_FINITE_VALUE`, below every feature's range:
  CGAL's random forests read past their feature vectors on non-finite values.
*/
class Feature_values : public CGAL::Classification::Feature_base
{
public:
  /// what a non-finite value becomes
  static constexpr float NON_FINITE_VALUE = -1.f;

  /// the value stored for `v`: `float(v)`, or `NON_FINITE_VALUE` if `v` is not finite
  static float stored_value(double v) { return std::isfinite(v) ? float(v) : NON_FINITE_VALUE; }

  /// the feature `name` with `values[i]` at item `i`
  Feature_values(const std::vector<double>& values, const std::string& name)
  {
    m_values.reserve(values.size());
    for(double v : values)
      m_values.push_back(stored_value(v));
    set_name(name);
  }

  /// the value at item `index`
  float value(std::size_t index) override { return m_values[index]; }

private:
  std::vector<float> m_values;
};

} // namespace Classification
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_FEATURE_VALUES_H
