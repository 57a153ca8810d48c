// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one reader the module calls, compiled once (SIGMOID_NEIGHBORHOODS_READERS_COMPILED): pip builds
// this unit instead of the library's src/Sigmoid_neighborhoods/IO.cpp, whose mesh, catalog and halo
// readers the module does not use (with -O3, 32 s of CPU against IO.cpp's 48). The CMake build links
// the library.

#ifndef SIGMOID_NEIGHBORHOODS_READERS_COMPILED
#  error "compile with SIGMOID_NEIGHBORHOODS_READERS_COMPILED defined (python/setup.py)"
#endif

#include <Sigmoid_neighborhoods_readers/internal/read_oriented_point_set_impl.h>
