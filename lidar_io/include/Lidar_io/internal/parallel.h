// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_PARALLEL_H
#define LIDAR_IO_INTERNAL_PARALLEL_H

#include <Lidar_io/concurrency.h>

#if defined(_OPENMP)
#include <omp.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <type_traits>

namespace Lidar_io {
namespace internal {

// The threads one call runs on: `requested`, or OpenMP's default when it is 0; 1 when sequential.
template <typename ConcurrencyTag>
std::size_t thread_count(unsigned int requested)
{
#if defined(_OPENMP)
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    return requested != 0 ? requested : static_cast<std::size_t>((std::max)(omp_get_max_threads(), 1));
#endif
  (void)requested;
  return 1;
}

// Runs `body(i, scratch)` for i in [0, n) on `threads` threads (0: OpenMP's default) with one
// `Scratch` per thread built by `make_scratch()`, `grain` indices handed out at a time. Each index's
// result depends on `i` only, so the outcome is the same bits on any number of threads. An exception
// stops the loop (the indices not begun are skipped) and the one of the smallest index is rethrown:
// an exception must not leave an OpenMP region.
template <typename ConcurrencyTag, typename MakeScratch, typename Body>
void for_each_index(std::size_t n, unsigned int threads, const MakeScratch& make_scratch, const Body& body,
                    std::size_t grain = 16)
{
#if defined(_OPENMP)
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && n > 0)
  {
    const int thread_number = static_cast<int>(thread_count<ConcurrencyTag>(threads));
    constexpr std::int64_t NONE = (std::numeric_limits<std::int64_t>::max)();
    std::atomic<std::int64_t> first_failed{NONE}; // -1 for a thread's scratch
    std::exception_ptr error;
    auto record = [&](std::int64_t i) {
#pragma omp critical(lidar_io_exception)
      if(i < first_failed.load())
      {
        first_failed.store(i);
        error = std::current_exception();
      }
    };
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel num_threads(thread_number)
    {
      typedef decltype(make_scratch()) Scratch;
      std::optional<Scratch> scratch;
      try
      {
        scratch.emplace(make_scratch());
      }
      catch(...)
      {
        record(-1);
      }
      // every thread reaches the worksharing loop, even one whose scratch failed
#pragma omp for schedule(dynamic, static_cast<int>(grain))
      for(std::int64_t i = 0; i < count; ++i)
      {
        if(first_failed.load(std::memory_order_relaxed) != NONE)
          continue;
        try
        {
          body(static_cast<std::size_t>(i), *scratch);
        }
        catch(...)
        {
          record(i);
        }
      }
    }
    if(error)
      std::rethrow_exception(error);
    return;
  }
#endif
  (void)threads;
  (void)grain;
  auto scratch = make_scratch();
  for(std::size_t i = 0; i < n; ++i)
    body(i, scratch);
}

} // namespace internal
} // namespace Lidar_io

#endif // LIDAR_IO_INTERNAL_PARALLEL_H
