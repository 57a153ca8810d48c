// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A few costly items (scales, columns, cell sizes) side by side on the tool's threads.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FOR_EACH_ITEM_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FOR_EACH_ITEM_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace sigmoid_tool {

// Runs body(s) for s in [first, last) on up to `threads` threads (0: the hardware's), each item
// taken by the next free thread; the exception of the first item that threw is rethrown after all
// have run (out of memory included: none leaves a thread).
template <typename Body>
void for_each_item(std::size_t first, std::size_t last, unsigned int threads, const Body& body)
{
  if(last <= first)
    return;
  const std::size_t count = last - first;
  std::size_t workers = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  workers = std::min(workers, count);
  std::atomic<std::size_t> next(first);
  std::vector<std::exception_ptr> errors(count);
  auto work = [&] {
    for(std::size_t s = next++; s < last; s = next++)
      try
      {
        body(s);
      }
      catch(...)
      {
        errors[s - first] = std::current_exception();
      }
  };
  std::vector<std::thread> pool;
  for(std::size_t w = 1; w < workers; ++w)
    pool.emplace_back(work);
  work();
  for(std::thread& t : pool)
    t.join();
  for(const std::exception_ptr& e : errors)
    if(e)
      std::rethrow_exception(e);
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_FOR_EACH_ITEM_H
