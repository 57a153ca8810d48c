// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The module's functions, in three files (CGAL's templates compile slowly), compiled as two units:
// denoising.cpp, and points.cpp with features.cpp and module.cpp (points_features_module.cpp).

#ifndef SIGMOID_NEIGHBORHOODS_PYTHON_BINDINGS_H
#define SIGMOID_NEIGHBORHOODS_PYTHON_BINDINGS_H

#include <pybind11/pybind11.h>

namespace sigmoid_neighborhoods_python {

// read, knn, estimate_normals, height_features
void bind_points(pybind11::module_& m);
// features, optimal
void bind_features(pybind11::module_& m);
// filter_normals, denoise
void bind_denoising(pybind11::module_& m);

} // namespace sigmoid_neighborhoods_python

#endif // SIGMOID_NEIGHBORHOODS_PYTHON_BINDINGS_H
