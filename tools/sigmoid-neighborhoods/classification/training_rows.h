// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rows a forest trains on: the training points' features as float, row-major, as CGAL's ETHZ
// forest reads them (classify_common.cpp), for the training and the choice of scales.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_TRAINING_ROWS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_TRAINING_ROWS_H

#include "feature_options.h"

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {
namespace classification {

// An allocator whose resize() leaves the values uninitialised: the rows are written once, on every
// thread, so that their pages are first touched by the threads that fill them, not zeroed by one.
template <typename T>
struct Uninitialized_allocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    typedef Uninitialized_allocator<U> other;
  };
  Uninitialized_allocator() = default;
  template <typename U>
  Uninitialized_allocator(const Uninitialized_allocator<U>&) noexcept
  {
  }
  template <typename U>
  void construct(U* p) noexcept
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// The training points' features, row-major in the forest's order, as CGAL's forest reads them
// (Feature_values::stored_value()), after one float of 0 (Ethz_forest::train()), and their classes.
struct Training_rows
{
  std::vector<float, Uninitialized_allocator<float>> values{0.f}; // values[1 + i * width + f]
  std::vector<int> labels;
};

// The names of `columns`, in their order.
std::vector<std::string> column_names(const std::vector<Feature_column>& columns);

// At most `cap` points per class of `truth` kept (0: all), evenly spaced, the others marked -1.
void cap_points_per_class(std::vector<int>& truth, std::size_t classes, std::size_t cap);

// Appends the rows of the points of `columns` whose `truth` is a class, with the features `names`
// (Feature_values::stored_value()), on `threads` threads (0: all).
void append_training_rows(const std::vector<Feature_column>& columns, const std::vector<int>& truth,
                          const std::vector<std::string>& names, unsigned int threads, Training_rows& rows);

} // namespace classification
} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_TRAINING_ROWS_H
