// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_ESTIMATE_ORIENTED_NORMALS_H
#define SIGMOID_NEIGHBORHOODS_READERS_ESTIMATE_ORIENTED_NORMALS_H

#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/config.h>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \brief estimates and orients the normals of `points` as `read_oriented_point_set()` estimates those
  of a file without normals: `estimate_normals()` (PCA, or jet fitting with `Normal_source::JET`) on
  the `options.neighbors` nearest points, oriented as `options.orientation` says, both steps on one
  k-nearest-neighbor structure (kept when `options.kept_neighbors` asks for it). For a point set made in
  memory, such as a thinned copy of one read: `normals` and the other fields of the estimation
  (`normals_estimated`, `estimation_neighbors`, the rows, the `seconds` of its steps) are replaced.

  \throws Input_error on points that give no normal (too few, on a line, coincident)
  \throws std::invalid_argument when `options.neighbors` is below what the method needs (2 for PCA,
  5 for jet fitting) or `options.source` is `Normal_source::FROM_FILE`
*/
SIGMOID_NEIGHBORHOODS_READERS_FUNCTION void estimate_oriented_normals(Oriented_point_set& points,
                                                                     const Normal_options& options);

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef SIGMOID_NEIGHBORHOODS_READERS_COMPILED
#include <Sigmoid_neighborhoods_readers/internal/estimate_oriented_normals_impl.h>
#endif

#endif // SIGMOID_NEIGHBORHOODS_READERS_ESTIMATE_ORIENTED_NORMALS_H
