// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The package's algorithms on a CGAL::Point_set_3, one header each in Point_set_3/: include the one
// a program calls to compile only what it uses.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_H

#include <CGAL/Sigmoid_neighborhoods/Point_set_3/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3/compute_sigmoid_features.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3/estimate_and_orient_normals.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3/filter_normals.h>

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_H
