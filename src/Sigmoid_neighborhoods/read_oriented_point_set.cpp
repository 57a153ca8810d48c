// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one reader the module calls, compiled once (CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO): pip builds
// this unit instead of the library's src/Sigmoid_neighborhoods/IO.cpp, whose mesh, catalog and halo
// readers the module does not use (with -O3, 32 s of CPU against IO.cpp's 48). The CMake build links
// the library.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO
#  error "compile with CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO defined (python/setup.py)"
#endif

#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_oriented_point_set_impl.h>
