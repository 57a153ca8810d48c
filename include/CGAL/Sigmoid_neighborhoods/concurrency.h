// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_CONCURRENCY_H
#define CGAL_SIGMOID_NEIGHBORHOODS_CONCURRENCY_H

#include <CGAL/tags.h>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  `CGAL::Parallel_tag` when the package can run in parallel, otherwise `CGAL::Sequential_tag`.

  `CGAL::Parallel_tag` runs the package's loops with OpenMP in a build with OpenMP (the default
  build), else with TBB where CGAL is linked with it (`CGAL_LINKED_WITH_TBB`); without either, an
  algorithm called with `CGAL::Parallel_tag` fails a static assertion, as CGAL's own do. CGAL's
  `CGAL::Parallel_if_available_tag` only knows TBB. The number of threads of one call is the named
  parameter `number_of_threads` (0, the default: OpenMP's or TBB's default); no global setting is
  read or changed.
*/
#if defined(_OPENMP) || defined(CGAL_LINKED_WITH_TBB)
typedef CGAL::Parallel_tag Parallel_if_available_tag;
#else
typedef CGAL::Sequential_tag Parallel_if_available_tag;
#endif

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_CONCURRENCY_H
