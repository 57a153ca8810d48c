// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library Lidar_io::compiled: the functions of the lidar IO that are not templates, compiled once
// (config.h).

#ifndef LIDAR_IO_COMPILED
#  error "compile with LIDAR_IO_COMPILED defined (CMake target Lidar_io::compiled)"
#endif

#include <Lidar_io/internal/read_tile_catalog_impl.h>
