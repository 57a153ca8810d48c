// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library CGAL::Sigmoid_neighborhoods_IO: the readers of IO/, compiled once (IO/config.h).

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO
#  error "compile with CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_IO defined (CMake target Sigmoid_neighborhoods_IO)"
#endif

#include <CGAL/Sigmoid_neighborhoods/IO/internal/estimate_oriented_normals_impl.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_oriented_point_set_impl.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_polygon_mesh_impl.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_tile_catalog_impl.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/read_tile_with_halo_impl.h>
