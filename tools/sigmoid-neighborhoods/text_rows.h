// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Large text outputs (the CSV of `optimal`, of `filter-normals`) written on every thread: blocks of
// rows formatted in parallel, each with the shortest text that reads back to the same double
// (std::to_chars), and written in order, so that the file is the same for any number of threads.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_TEXT_ROWS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_TEXT_ROWS_H

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <ostream>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sigmoid_tool {

// The text of a block of rows.
class Text_rows
{
public:
  // the shortest text that reads back to `v` ("inf", "-inf", "nan" for the others)
  Text_rows& number(double v)
  {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof(buffer), v).ptr;
    m_text.append(buffer, end);
    return *this;
  }

  Text_rows& integer(std::int64_t v)
  {
    char buffer[24];
    const auto end = std::to_chars(buffer, buffer + sizeof(buffer), v).ptr;
    m_text.append(buffer, end);
    return *this;
  }

  Text_rows& text(const char* s)
  {
    m_text.append(s);
    return *this;
  }

  Text_rows& put(char c)
  {
    m_text.push_back(c);
    return *this;
  }

  const std::string& str() const { return m_text; }
  void clear() { m_text.clear(); }

private:
  std::string m_text;
};

// Rows of a block written by a thread, the threads' blocks in turn.
constexpr std::size_t TEXT_ROWS_PER_BLOCK = 4096;

// Writes `row(rows, i)` for i = first, ..., last - 1 to `out`, in that order, formatted on `threads`
// threads (0: OpenMP's default). `row` appends one row, line end included.
template <typename Row>
void write_text_rows(std::ostream& out, std::size_t first, std::size_t last, unsigned int threads, const Row& row)
{
  if(last <= first)
    return;
  const std::ptrdiff_t blocks = std::ptrdiff_t((last - first + TEXT_ROWS_PER_BLOCK - 1) / TEXT_ROWS_PER_BLOCK);
  auto format = [&](std::ptrdiff_t b, Text_rows& rows) {
    rows.clear();
    const std::size_t begin = first + std::size_t(b) * TEXT_ROWS_PER_BLOCK;
    const std::size_t end = std::min(last, begin + TEXT_ROWS_PER_BLOCK);
    for(std::size_t i = begin; i < end; ++i)
      row(rows, i);
  };
#ifdef _OPENMP
  const int team = threads == 0 ? omp_get_max_threads() : int(threads);
  if(team > 1 && blocks > 1)
  {
    // each thread formats its block, then waits for its turn to write it: formatting and writing overlap
    // an exception (out of memory) must not leave the parallel region: the first is kept, the rows
    // after it are not written, and it is thrown after the region
    std::exception_ptr error;
    std::atomic<bool> failed(false);
#pragma omp parallel num_threads(team)
    {
      Text_rows rows;
#pragma omp for ordered schedule(static, 1)
      for(std::ptrdiff_t b = 0; b < blocks; ++b)
      {
        bool formatted = true;
        try
        {
          format(b, rows);
        }
        catch(...)
        {
          formatted = false;
#pragma omp critical(sigmoid_neighborhoods_text_rows)
          if(!error)
            error = std::current_exception();
          failed.store(true);
        }
#pragma omp ordered
        if(formatted && !failed.load())
          out.write(rows.str().data(), std::streamsize(rows.str().size()));
      }
    }
    if(error)
      std::rethrow_exception(error);
    return;
  }
#endif
  (void)threads;
  Text_rows rows;
  for(std::ptrdiff_t b = 0; b < blocks; ++b)
  {
    format(b, rows);
    out.write(rows.str().data(), std::streamsize(rows.str().size()));
  }
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_TEXT_ROWS_H
