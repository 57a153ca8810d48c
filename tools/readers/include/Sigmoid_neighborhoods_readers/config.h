// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// How the readers are built. Header-only by default: every translation unit that calls a reader
// compiles it (CGAL's file readers, the mesh repair, the normal estimation: about a minute with -O3).
// With SIGMOID_NEIGHBORHOODS_READERS_COMPILED defined, the headers declare the readers only and the
// library Sigmoid_neighborhoods_readers (tools/readers/src/readers.cpp) defines them, compiled
// once; linking that CMake target defines the macro for its users. The results are the same.

#ifndef SIGMOID_NEIGHBORHOODS_READERS_CONFIG_H
#define SIGMOID_NEIGHBORHOODS_READERS_CONFIG_H

/// \cond SKIP_IN_MANUAL
#if defined(SIGMOID_NEIGHBORHOODS_READERS_COMPILED)
#  define SIGMOID_NEIGHBORHOODS_READERS_FUNCTION
#else
#  define SIGMOID_NEIGHBORHOODS_READERS_FUNCTION inline
#endif
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_CONFIG_H
