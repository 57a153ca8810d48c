// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The files of an evaluation folder (evaluation_json.h) and the normal options they record.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_FILES_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_FILES_H

#include "evaluation_json.h"
#include "model_input.h"

#include <string>

namespace sigmoid_tool {

inline void set_normal_settings(Evaluation_settings& s, const SN::Normal_options& o, bool line_angles)
{
  s.normals = SN::normal_source_name(o.source);
  s.normal_neighbors = o.neighbors;
  s.orientation = SN::normal_orientation_name(o.orientation);
  s.viewpoint.clear();
  if(o.orientation == SN::Normal_orientation::VIEWPOINT)
    s.viewpoint = {o.viewpoint.x(), o.viewpoint.y(), o.viewpoint.z()};
  s.line_angles = line_angles;
}

// The normal options an evaluation was run with, for recomputing one of its models.
inline SN::Normal_options normal_options(const Evaluation_settings& s, unsigned int threads)
{
  SN::Normal_options o;
  o.source = s.normals.empty() ? SN::Normal_source::AUTO : read_normal_source(s.normals);
  o.neighbors = s.normal_neighbors == 0 ? SN::DEFAULT_ESTIMATION_NEIGHBORS : s.normal_neighbors;
  // read_settings() gave one of the names, or none for the default
  o.orientation = s.orientation.empty() ? SN::Normal_orientation::SPANNING_FOREST
                                        : SN::normal_orientation_from_name(s.orientation);
  if(s.viewpoint.size() == 3)
    o.viewpoint = SN::Oriented_point_set::Point_3(s.viewpoint[0], s.viewpoint[1], s.viewpoint[2]);
  o.threads = threads;
  return o;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_FILES_H
