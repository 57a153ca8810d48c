// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PARALLEL_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_PARALLEL_H

#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/tags.h>

#if defined(_OPENMP)
#include <omp.h>
#elif defined(CGAL_LINKED_WITH_TBB)
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

template <typename ConcurrencyTag>
constexpr bool is_parallel()
{
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
}

// CGAL's contract (CGAL::for_each): `Parallel_tag` runs in parallel or does not compile.
template <typename ConcurrencyTag>
constexpr void check_concurrency_tag()
{
#if !defined(_OPENMP) && !defined(CGAL_LINKED_WITH_TBB)
  static_assert(!is_parallel<ConcurrencyTag>(),
                "CGAL::Parallel_tag needs OpenMP or TBB (CGAL_LINKED_WITH_TBB): use CGAL::Sequential_tag "
                "or CGAL::Sigmoid_neighborhoods::Parallel_if_available_tag");
#endif
}

// The threads one call runs on: `requested`, or the OpenMP or TBB default when it is 0.
template <typename ConcurrencyTag>
std::size_t thread_count(unsigned int requested)
{
  check_concurrency_tag<ConcurrencyTag>();
  if(!is_parallel<ConcurrencyTag>())
    return 1;
  if(requested != 0)
    return requested;
#if defined(_OPENMP)
  return static_cast<std::size_t>((std::max)(omp_get_max_threads(), 1));
#elif defined(CGAL_LINKED_WITH_TBB)
  return static_cast<std::size_t>((std::max)(tbb::this_task_arena::max_concurrency(), 1));
#else
  return 1;
#endif
}

// The threads a kernel of the package (see config.h) runs a call of `ConcurrencyTag` on: 1 for a
// sequential tag, else `requested` (0: the default). The kernels are not templates on the tag.
template <typename ConcurrencyTag>
unsigned int kernel_threads(unsigned int requested)
{
  check_concurrency_tag<ConcurrencyTag>();
  return is_parallel<ConcurrencyTag>() ? requested : 1u;
}

// The exception of the smallest index among those thrown in an OpenMP region, each caught where it
// is thrown (an exception must not leave the region); -1 for a thread's scratch.
class Smallest_index_exception
{
public:
  void record(std::int64_t i)
  {
#if defined(_OPENMP)
#pragma omp critical(sigmoid_neighborhoods_exception)
#endif
    if(i < m_index.load())
    {
      m_index.store(i);
      m_error = std::current_exception();
    }
  }
  bool any() const { return m_index.load(std::memory_order_relaxed) != NONE; }
  // whether one was recorded below `end`
  bool before(std::int64_t end) const { return m_index.load() < end; }
  void rethrow_if_any() const
  {
    if(m_error)
      std::rethrow_exception(m_error);
  }

private:
  static constexpr std::int64_t NONE = (std::numeric_limits<std::int64_t>::max)();
  std::exception_ptr m_error;
  std::atomic<std::int64_t> m_index{NONE};
};

// Runs `body(i, scratch)` for i in [0, n) on `threads` threads (0: the default), with one
// `Scratch` per thread built by `make_scratch()`. Every index is processed by one call whose
// result depends on `i` only, so the outcome is the same, bit for bit, for any number of threads.
// An exception thrown by `body` (or `make_scratch`) stops the loop and is rethrown to the caller:
// the one of the smallest index among those that threw.
// `grain` indices are handed to a thread at a time: few costly indices (chunks of a file) take 1.
template <typename ConcurrencyTag, typename MakeScratch, typename Body>
void for_each_index(std::size_t n, unsigned int threads, const MakeScratch& make_scratch, const Body& body,
                    std::size_t grain = 16)
{
  const std::size_t thread_number = thread_count<ConcurrencyTag>(threads);
#if defined(_OPENMP)
  if(is_parallel<ConcurrencyTag>() && n > 0)
  {
    typedef decltype(make_scratch()) Scratch;
    const std::int64_t count = static_cast<std::int64_t>(n);
    // after an exception the remaining indices are skipped
    Smallest_index_exception errors;
#pragma omp parallel num_threads(static_cast<int>(thread_number))
    {
      std::optional<Scratch> scratch;
      try
      {
        scratch.emplace(make_scratch());
      }
      catch(...)
      {
        errors.record(-1);
      }
      // every thread reaches the worksharing loop, even one whose scratch failed
#pragma omp for schedule(dynamic, static_cast<int>(grain))
      for(std::int64_t i = 0; i < count; ++i)
      {
        if(errors.any())
          continue;
        try
        {
          body(static_cast<std::size_t>(i), *scratch);
        }
        catch(...)
        {
          errors.record(i);
        }
      }
    }
    errors.rethrow_if_any();
    return;
  }
#elif defined(CGAL_LINKED_WITH_TBB)
  if(is_parallel<ConcurrencyTag>() && n > 0)
  {
    typedef decltype(make_scratch()) Scratch;
    // TBB cancels the loop on the first exception and rethrows it to the caller.
    tbb::enumerable_thread_specific<Scratch> scratches(make_scratch);
    auto run = [&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
        Scratch& scratch = scratches.local();
        for(std::size_t i = r.begin(); i != r.end(); ++i)
          body(i, scratch);
      });
    };
    tbb::task_arena arena(static_cast<int>(thread_number));
    arena.execute(run);
    return;
  }
#endif
  (void)thread_number;
  (void)grain;
  auto scratch = make_scratch();
  for(std::size_t i = 0; i < n; ++i)
    body(i, scratch);
}

// Points per thread in a block of for_each_index_in_blocks(): enough that the last chunks of a
// block keep few threads waiting, few enough that a block of results stays small next to the
// input, even at 1e5 points.
constexpr std::size_t BLOCK_SIZE_PER_THREAD = 1024;

// The same over blocks of indices: `compute(i, scratch)` returns the result of index i, and
// `sink(i, result)` receives the results in index order, one block at a time, so that memory
// holds two blocks of results rather than all of them. Under OpenMP one parallel region serves
// every block: while the threads compute a block, one of them hands the previous block to the
// sink, then joins them, and each thread keeps one scratch for the whole call. An exception is
// rethrown to the caller, the one of the smallest index (a sink's at the index it was given); the
// results before the block where it happened are given to the sink, as in one pass.
template <typename ConcurrencyTag, typename Result, typename MakeScratch, typename Compute, typename Sink>
void for_each_index_in_blocks(std::size_t n, unsigned int threads, const MakeScratch& make_scratch,
                              const Compute& compute, const Sink& sink)
{
  const std::size_t thread_number = thread_count<ConcurrencyTag>(threads);
  const std::size_t block = BLOCK_SIZE_PER_THREAD * thread_number;
#if defined(_OPENMP)
  if(is_parallel<ConcurrencyTag>() && thread_number > 1 && n > block)
  {
    typedef decltype(make_scratch()) Scratch;
    const std::size_t blocks = (n + block - 1) / block;
    std::vector<Result> results[2] = {std::vector<Result>(block), std::vector<Result>(block)};
    Smallest_index_exception errors;
    const std::int64_t grain = 16;
#pragma omp parallel num_threads(static_cast<int>(thread_number))
    {
      std::optional<Scratch> scratch;
      try
      {
        scratch.emplace(make_scratch());
      }
      catch(...)
      {
        errors.record(-1);
      }
      // Iteration b computes block b and sinks block b - 1. Every thread meets the same
      // worksharing constructs in every iteration: after an error the work is skipped, not the
      // constructs.
      for(std::size_t b = 0; b <= blocks; ++b)
      {
#pragma omp single nowait
        if(b > 0)
        {
          const std::size_t start = (b - 1) * block, count = (std::min)(block, n - start);
          // given only when no error came before its end: then its results are whole
          if(!errors.before(std::int64_t(start + count)))
          {
            const std::vector<Result>& done = results[(b - 1) % 2];
            for(std::size_t i = 0; i < count; ++i)
            {
              try
              {
                sink(start + i, done[i]);
              }
              catch(...)
              {
                errors.record(std::int64_t(start + i));
                break;
              }
            }
          }
        }
        const std::size_t start = b * block;
        const std::int64_t count = b < blocks ? std::int64_t((std::min)(block, n - start)) : 0;
        std::vector<Result>& current = results[b % 2];
#pragma omp for schedule(dynamic, grain)
        for(std::int64_t i = 0; i < count; ++i)
        {
          if(errors.any())
            continue;
          try
          {
            current[std::size_t(i)] = compute(start + std::size_t(i), *scratch);
          }
          catch(...)
          {
            errors.record(std::int64_t(start) + i);
          }
        }
      }
    }
    errors.rethrow_if_any();
    return;
  }
#endif
  std::vector<Result> results;
  for(std::size_t start = 0; start < n; start += block)
  {
    const std::size_t count = (std::min)(block, n - start);
    results.resize(count);
    for_each_index<ConcurrencyTag>(count, threads, make_scratch, [&](std::size_t i, auto& scratch) {
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
