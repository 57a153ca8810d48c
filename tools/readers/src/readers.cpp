// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library Sigmoid_neighborhoods_readers: the readers of tools/readers, compiled once (config.h).

#ifndef SIGMOID_NEIGHBORHOODS_READERS_COMPILED
#  error "compile with SIGMOID_NEIGHBORHOODS_READERS_COMPILED defined (CMake target Sigmoid_neighborhoods_readers)"
#endif

#include <Sigmoid_neighborhoods_readers/internal/estimate_oriented_normals_impl.h>
#include <Sigmoid_neighborhoods_readers/internal/read_oriented_point_set_impl.h>
#include <Sigmoid_neighborhoods_readers/internal/read_polygon_mesh_impl.h>
#include <Sigmoid_neighborhoods_readers/internal/read_tile_with_halo_impl.h>
