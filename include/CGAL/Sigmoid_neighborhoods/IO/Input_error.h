// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INPUT_ERROR_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INPUT_ERROR_H

#include <stdexcept>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  the error thrown by `read_oriented_point_set()` and `read_polygon_mesh()`: its `what()` is one
  line for a person.
*/
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INPUT_ERROR_H
