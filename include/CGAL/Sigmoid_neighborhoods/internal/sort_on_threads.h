// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SORT_ON_THREADS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SORT_ON_THREADS_H

#include <algorithm>
#include <cstddef>
#include <iterator>

#if defined(_OPENMP) && defined(__GLIBCXX__)
#include <omp.h>
#include <parallel/algorithm>
#endif

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Sorts [first, last) by `less` on `threads` threads (0: OpenMP's default), with libstdc++'s
// parallel mode where OpenMP is there, else std::sort. `less` must be a strict total order (ties
// broken by index): then the result does not depend on the threads or on the algorithm.
template <typename RandomAccessIterator, typename Less>
void sort_on_threads(RandomAccessIterator first, RandomAccessIterator last, const Less& less, unsigned int threads)
{
#if defined(_OPENMP) && defined(__GLIBCXX__)
  // no OpenMP region for a small range: it would cost more than it saves, and a forked child (the
  // readers' limit tests) cannot start one
  const int team = threads == 0 ? omp_get_max_threads() : int(threads);
  if(team > 1 && std::size_t(std::distance(first, last)) >= (std::size_t(1) << 16))
  {
    __gnu_parallel::sort(first, last, less,
                         __gnu_parallel::default_parallel_tag(static_cast<__gnu_parallel::_ThreadIndex>(team)));
    return;
  }
#else
  (void)threads;
#endif
  std::sort(first, last, less);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_SORT_ON_THREADS_H
