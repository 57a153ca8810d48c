// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// How the package's kernels are built. The public functions are templates on the caller's ranges,
// maps and concurrency tag; each copies its input into the package's own types (`Double_point`,
// `Eigen::Vector3d`) and runs a kernel on those types only: the kd-tree, the optimal search, the
// normal fitting, the spanning forest. Header-only by default: every translation unit that calls one
// compiles it. With CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE defined, the headers declare the
// kernels only and the library CGAL::Sigmoid_neighborhoods_core (src/Sigmoid_neighborhoods/core.cpp)
// defines them, compiled once; linking that CMake target defines the macro for its users. Every
// translation unit of a program must agree; the results are the same, bit for bit.

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_CONFIG_H
#define CGAL_SIGMOID_NEIGHBORHOODS_CONFIG_H

/// \cond SKIP_IN_MANUAL
#if defined(CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE)
#  define CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION
#else
#  define CGAL_SIGMOID_NEIGHBORHOODS_CORE_FUNCTION inline
#endif
// for a small template whose callers pass lambdas it calls in a loop: inlined, their captures stay
// in registers (the kd-tree's walk: 4 % of a query)
#if defined(__GNUC__)
#  define CGAL_SIGMOID_NEIGHBORHOODS_ALWAYS_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#  define CGAL_SIGMOID_NEIGHBORHOODS_ALWAYS_INLINE __forceinline
#else
#  define CGAL_SIGMOID_NEIGHBORHOODS_ALWAYS_INLINE inline
#endif
// for a loop of comparisons and selects that GCC vectorizes only when comparisons may not trap
// (under the default -ftrapping-math a signalling comparison is "control flow"); the values are the
// same, only floating-point exception flags may differ, and nothing reads them
#if defined(__GNUC__) && !defined(__clang__)
#  define CGAL_SIGMOID_NEIGHBORHOODS_VECTORIZED_SELECTS __attribute__((optimize("no-trapping-math")))
#else
#  define CGAL_SIGMOID_NEIGHBORHOODS_VECTORIZED_SELECTS
#endif
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_CONFIG_H
