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
  the error thrown for a file that cannot be read (missing, truncated, damaged, a header or a chunk
  table the library does not read): its `what()` is one line for a person.
*/
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace Lidar_io

#endif // LIDAR_IO_INPUT_ERROR_H
