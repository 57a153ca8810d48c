// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// points.cpp, features.cpp and module.cpp compiled as one translation unit: apart, each parsed CGAL's
// kernels, pybind11 and numpy's headers and compiled pybind11's and the package's common templates
// again (with -O3, 35 s of CPU apart, 17 s together). denoising.cpp, the longest, stays a unit of its
// own, so that the two compilers of `pip install` finish together (python/setup.py).

#include "points.cpp"
#include "features.cpp"
#include "module.cpp"
