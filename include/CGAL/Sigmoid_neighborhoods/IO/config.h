// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// How the readers are built. Header-only by default: every translation unit that calls a reader
// compiles it (CGAL's file readers, the mesh repair, the normal estimation: about a minute with -O3).
// With CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO defined, the headers declare the readers only and the
// library CGAL::Sigmoid_neighborhoods_IO (src/Sigmoid_neighborhoods/IO.cpp) defines them, compiled
// once; linking that CMake target defines the macro for its users. The results are the same.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_CONFIG_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_CONFIG_H

/// \cond SKIP_IN_MANUAL
#if defined(CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO)
#  define CGAL_SIGMOID_NEIGHBORHOODS_IO_FUNCTION
#else
#  define CGAL_SIGMOID_NEIGHBORHOODS_IO_FUNCTION inline
#endif
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_CONFIG_H
