// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A trained classifier as one file (classifier_settings.h): CGAL's ETHZ random forest written and
// loaded, and the label and feature sets it is trained on.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_MODEL_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_MODEL_H

#include "classifier_settings.h"
#include "feature_options.h"
#include "label_mapping.h"

#include <CGAL/Sigmoid_neighborhoods/Classification/Ethz_forest.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/Feature_values.h>

#include <CGAL/Classification/ETHZ/Random_forest_classifier.h>
#include <CGAL/Classification/Feature_set.h>
#include <CGAL/Classification/Label_set.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace sigmoid_tool {

// The forest's labels, in class order.
inline CGAL::Classification::Label_set label_set(const Label_mapping& m)
{
  CGAL::Classification::Label_set labels;
  for(const std::string& name : m.names)
    labels.add(name.c_str());
  return labels;
}

// The columns as a CGAL feature set, in the order of `names` (each must be one of the columns).
// The values of the features `names`, in that order, among `columns`.
inline std::vector<const std::vector<double>*> ordered_columns(const std::vector<Feature_column>& columns,
                                                             const std::vector<std::string>& names)
{
  std::vector<const std::vector<double>*> ordered;
  for(const std::string& name : names)
  {
    const auto it = std::find_if(columns.begin(), columns.end(), [&](const Feature_column& c) { return c.name == name; });
    if(it == columns.end())
      throw Usage_error("the model reads a feature '" + name + "' that its feature groups do not give");
    ordered.push_back(&it->values);
  }
  return ordered;
}

inline void fill_feature_set(const std::vector<Feature_column>& columns, const std::vector<std::string>& names,
                             CGAL::Classification::Feature_set& set)
{
  const std::vector<const std::vector<double>*> ordered = ordered_columns(columns, names);
  for(std::size_t f = 0; f < names.size(); ++f)
    set.add<SN::Classification::Feature_values>(*ordered[f], names[f]);
}

inline void write_classifier_model(const std::string& path, const Classifier_settings& s,
                                   const SN::Classification::Ethz_forest& forest)
{
  write_file_atomically(path, [&](std::ofstream& out) {
    out << CLASSIFIER_MODEL_MAGIC << '\n' << settings_json(s).dump() << '\n';
    forest.save_configuration(out);
  }, true);
}

// The forest of `forest_bytes` for `classes` classes and `features` features; a damaged forest is a
// Usage_error.
inline SN::Classification::Ethz_forest load_forest(const std::string& path, const std::string& forest_bytes,
                                                   std::size_t classes, std::size_t features)
{
  try
  {
    return SN::Classification::Ethz_forest(forest_bytes, classes, features);
  }
  catch(const std::exception& e)
  {
    throw Usage_error(path + ": not a usable classifier model: its forest cannot be read (" + e.what() + ")");
  }
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CLASSIFIER_MODEL_H
