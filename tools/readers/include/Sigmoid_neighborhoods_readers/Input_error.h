// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INPUT_ERROR_H
#define SIGMOID_NEIGHBORHOODS_READERS_INPUT_ERROR_H

#include <Lidar_io/Input_error.h>
#include <Lidar_io/lower_case_extension.h>

namespace CGAL {
namespace Sigmoid_neighborhoods {

// One error for every unreadable input, LAS or not: the readers read LAS files through the lidar
// library and callers catch one type.
using Lidar_io::Input_error;
using Lidar_io::lower_case_extension;

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_INPUT_ERROR_H
