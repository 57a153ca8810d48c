// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PARALLEL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PARALLEL_H

#include <CGAL/tags.h>

#if defined(_OPENMP)
#include <omp.h>
#endif

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  `CGAL::Parallel_tag` when the package can run in parallel (OpenMP or TBB), otherwise
  `CGAL::Sequential_tag`. CGAL's own alias only knows TBB.
*/
#if defined(_OPENMP) || defined(CGAL_LINKED_WITH_TBB)
typedef CGAL::Parallel_tag Parallel_if_available_tag;
#else
typedef CGAL::Sequential_tag Parallel_if_available_tag;
#endif

namespace internal {

// Runs `body(i, scratch)` for i in [0, n), with one `Scratch` per thread built by
// `make_scratch()`. Every index is processed by one call whose result depends on `i` only,
// so the outcome is the same, bit for bit, for any number of threads. `body` must not throw.
template <typename ConcurrencyTag, typename MakeScratch, typename Body>
void for_each_index(std::size_t n, const MakeScratch& make_scratch, const Body& body)
{
#if defined(_OPENMP)
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel
    {
      auto scratch = make_scratch();
#pragma omp for schedule(dynamic, 16)
      for(std::int64_t i = 0; i < count; ++i)
        body(static_cast<std::size_t>(i), scratch);
    }
    return;
  }
#endif
  auto scratch = make_scratch();
  for(std::size_t i = 0; i < n; ++i)
    body(i, scratch);
}

// The same over blocks of indices: `compute(i, scratch)` returns the result of index i, and
// `sink(i, result)` receives the results in index order, one block at a time, so that memory
// holds one block of results rather than all of them.
template <typename ConcurrencyTag, typename Result, typename MakeScratch, typename Compute, typename Sink>
void for_each_index_in_blocks(std::size_t n, const MakeScratch& make_scratch, const Compute& compute,
                              const Sink& sink)
{
  // 1024 points per thread: enough that the last chunks of a block keep few threads waiting, few
  // enough that a block of results stays small next to the input, even at 1e5 points.
  std::size_t threads = 1;
#if defined(_OPENMP)
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    threads = static_cast<std::size_t>((std::max)(omp_get_max_threads(), 1));
#endif
  const std::size_t BLOCK = 1024 * threads;
  std::vector<Result> results;
  for(std::size_t start = 0; start < n; start += BLOCK)
  {
    const std::size_t count = (std::min)(BLOCK, n - start);
    results.resize(count);
    for_each_index<ConcurrencyTag>(count, make_scratch, [&](std::size_t i, auto& scratch) {
      results[i] = compute(start + i, scratch);
    });
    for(std::size_t i = 0; i < count; ++i)
      sink(start + i, results[i]);
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PARALLEL_H
