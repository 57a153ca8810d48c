// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The package's public entry header: shape-aware sigmoid neighborhoods for point sets and meshes.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/vector_instructions.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>
#include <CGAL/Sigmoid_neighborhoods/Mesh_points_summary.h>
#include <CGAL/Sigmoid_neighborhoods/Point_evaluation.h>
#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/Neighborhood_criterion.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/search_tree.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3.h>
#include <CGAL/Sigmoid_neighborhoods/compute_sigmoid_features.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/thin_on_voxel_grid.h>
#include <CGAL/Sigmoid_neighborhoods/compute_pyramid_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/evaluate_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>
#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/compute_mean_neighbor_distance.h>

#endif // CGAL_SIGMOID_NEIGHBORHOODS_H
