// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INPUT_ERROR_H
#define LIDAR_IO_INPUT_ERROR_H

#include <stdexcept>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  the error thrown by `read_oriented_point_set()` and `read_polygon_mesh()`: its `what()` is one
  line for a person.
*/
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace Lidar_io

#endif // LIDAR_IO_INPUT_ERROR_H
