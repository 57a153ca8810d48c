// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's kernels, compiled once (see include/CGAL/Sigmoid_neighborhoods/config.h): the
// kd-tree, the optimal search, the normal fitting and the spanning forest, on the package's own types.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE
#  error "compile with CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE defined (CMake target Sigmoid_neighborhoods_core)"
#endif

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query_impl.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists_impl.h>
#include <CGAL/Sigmoid_neighborhoods/internal/estimate_normals_impl.h>
#include <CGAL/Sigmoid_neighborhoods/internal/orient_normals_impl.h>
#include <CGAL/Sigmoid_neighborhoods/internal/optimal_search_all_impl.h>
