// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_TEXT_BLOCKS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_TEXT_BLOCKS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A block holds this much at least: smaller ones cost more to hand out than to parse.
constexpr std::size_t TEXT_SMALLEST_BLOCK_BYTES = std::size_t(1) << 18;

// The bytes of a whole file.
struct Text_file
{
  std::unique_ptr<char[]> bytes;
  std::size_t size = 0;
};

// The whole file in one read when its size is known; a pipe's is not: twice the room at a time
// then. Not zeroed first: memory is slow to touch the first time.
inline Text_file read_text_file(const std::string& filename)
{
  Text_file text;
  std::ifstream in(filename, std::ios::binary);
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(filename, ec);
  std::size_t capacity = ec ? TEXT_SMALLEST_BLOCK_BYTES : std::size_t(file_size) + 1; // + 1: the read meets the end
  text.bytes.reset(new char[capacity]);
  while(in)
  {
    if(text.size == capacity)
    {
      std::unique_ptr<char[]> larger(new char[capacity *= 2]);
      std::memcpy(larger.get(), text.bytes.get(), text.size);
      text.bytes = std::move(larger);
    }
    in.read(text.bytes.get() + text.size, std::streamsize(capacity - text.size));
    text.size += std::size_t(in.gcount());
  }
  if(in.bad())
    throw Input_error("read error");
  return text;
}

// The threads a text reader runs on: `threads`, or OpenMP's default when 0.
inline std::size_t text_reader_threads(unsigned int threads)
{
#ifdef _OPENMP
  return threads != 0 ? threads : std::size_t((std::max)(omp_get_max_threads(), 1));
#else
  (void)threads;
  return 1;
#endif
}

// The starts of blocks of whole lines that cover [first, size) of `data`, about 4 a thread for
// balance and each of TEXT_SMALLEST_BLOCK_BYTES at least; the last entry is `size`. Every block
// but the first starts just after a '\n'.
inline std::vector<std::size_t> line_block_starts(const char* data, std::size_t first, std::size_t size,
                                                  std::size_t thread_number)
{
  const std::size_t bytes = size - first;
  const std::size_t wanted =
    (std::max)(std::size_t(1), (std::min)(4 * thread_number, bytes / TEXT_SMALLEST_BLOCK_BYTES));
  std::vector<std::size_t> starts{first};
  for(std::size_t i = 1; i < wanted; ++i)
  {
    const std::size_t from = (std::max)(starts.back(), first + i * (bytes / wanted));
    const void* line_end = std::memchr(data + from, '\n', size - from);
    if(line_end == nullptr)
      break;
    const std::size_t start = std::size_t(static_cast<const char*>(line_end) - data) + 1;
    if(start == size)
      break;
    starts.push_back(start);
  }
  starts.push_back(size);
  return starts;
}

// Runs `parse(i)` for each block i in [0, blocks) on `thread_number` threads. An exception must not
// leave an OpenMP region: the first one of each block is kept in `exceptions[i]`.
template <typename Parse>
void parse_blocks(std::size_t blocks, std::size_t thread_number, std::vector<std::exception_ptr>& exceptions,
                  const Parse& parse)
{
  exceptions.assign(blocks, nullptr);
  auto guarded = [&](std::int64_t i) {
    try
    {
      parse(std::size_t(i));
    }
    catch(...)
    {
      exceptions[std::size_t(i)] = std::current_exception();
    }
  };
  const std::int64_t count = std::int64_t(blocks);
#ifdef _OPENMP
  // No OpenMP region for one block: a forked child (the memory-limit tests) cannot start one.
  if(count > 1 && thread_number > 1)
  {
#pragma omp parallel for schedule(dynamic, 1) num_threads(static_cast<int>(thread_number))
    for(std::int64_t i = 0; i < count; ++i)
      guarded(i);
    return;
  }
#else
  (void)thread_number;
#endif
  for(std::int64_t i = 0; i < count; ++i)
    guarded(i);
}

// The index of each block's first item, and the total at the end: `count(b)` items in block b,
// counted on the threads (a count must not throw).
template <typename Count>
std::vector<std::size_t> first_item_of_blocks(std::size_t blocks, std::size_t thread_number, const Count& count)
{
  std::vector<std::size_t> first(blocks + 1, 0);
  std::vector<std::exception_ptr> exceptions;
  parse_blocks(blocks, thread_number, exceptions, [&](std::size_t b) { first[b + 1] = count(b); });
  for(std::size_t b = 0; b < blocks; ++b)
    first[b + 1] += first[b];
  return first;
}

// The spaces of std::isspace in the C locale, those `>>` skips between the tokens of a line.
inline bool is_text_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

// The first character at or after `p` that is not a space, or `last`.
inline const char* skip_text_spaces(const char* p, const char* last)
{
  while(p < last && is_text_space(*p))
    ++p;
  return p;
}

// The end of the token that starts at `p`: its first space, or `last`.
inline const char* text_token_end(const char* p, const char* last)
{
  while(p < last && !is_text_space(*p))
    ++p;
  return p;
}

// Calls `line(start, end, newline)` for each line of [first, last) with a character other than a
// space: `start` is that first character, `end` the line's end (its '\n' left out), `newline`
// whether a '\n' ends it. `line` returns false to stop.
template <typename Line>
void for_each_line_with_tokens(const char* first, const char* last, const Line& line)
{
  for(const char* p = first; p < last;)
  {
    const char* end = static_cast<const char*>(std::memchr(p, '\n', std::size_t(last - p)));
    const bool newline = end != nullptr;
    if(!newline)
      end = last;
    const char* start = skip_text_spaces(p, end);
    p = newline ? end + 1 : last;
    if(start != end && !line(start, end, newline))
      return;
  }
}

// Whether the token [first, last) is a plain decimal number, read into `v`: digits, '.', 'e', 'E',
// and signs, without a leading '+', taken whole by std::from_chars, finite. Such a token is read to
// the same double by CGAL's `IO::iformat()` (the same characters, then sscanf("%lf")) and by
// `std::strtod`, all correctly rounded; the fast readers leave every other token to CGAL's readers.
inline bool parse_plain_double(const char* first, const char* last, double& v)
{
  if(first == last || *first == '+')
    return false;
  for(const char* p = first; p < last; ++p)
    if(!((*p >= '0' && *p <= '9') || *p == '.' || *p == 'e' || *p == 'E' || *p == '+' || *p == '-'))
      return false;
  const std::from_chars_result r = std::from_chars(first, last, v);
  return r.ec == std::errc() && r.ptr == last && std::isfinite(v);
}

// Reads the `count` tokens after `p` on [p, last) as plain numbers (parse_plain_double()) into
// `values`; returns the end of the last, or nullptr when one is missing or not plain.
inline const char* parse_plain_doubles(const char* p, const char* last, double* values, std::size_t count)
{
  for(std::size_t i = 0; i < count; ++i)
  {
    p = skip_text_spaces(p, last);
    const char* token_end = text_token_end(p, last);
    if(!parse_plain_double(p, token_end, values[i]))
      return nullptr;
    p = token_end;
  }
  return p;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_TEXT_BLOCKS_H
