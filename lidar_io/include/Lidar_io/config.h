// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the library is built. Header-only by default, as CGAL is: every translation unit that calls a
// reader compiles it. With LIDAR_IO_COMPILED defined, the headers declare the functions that are not
// templates and the library Lidar_io::compiled (lidar_io/src/Lidar_io.cpp) defines them, compiled
// once; linking that CMake target defines the macro for its users. The results are the same.

#ifndef LIDAR_IO_CONFIG_H
#define LIDAR_IO_CONFIG_H

/// \cond SKIP_IN_MANUAL
#if defined(LIDAR_IO_COMPILED)
#  define LIDAR_IO_FUNCTION
#else
#  define LIDAR_IO_FUNCTION inline
#endif
/// \endcond

#endif // LIDAR_IO_CONFIG_H
