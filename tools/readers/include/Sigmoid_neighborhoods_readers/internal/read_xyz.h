// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_XYZ_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_XYZ_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/text_blocks.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <system_error>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The numbers of an XYZ/PWN line: a point, or a point and its normal.
constexpr std::size_t XYZ_POINT_COLUMNS = 3;
constexpr std::size_t XYZ_POINT_AND_NORMAL_COLUMNS = 6;

// What one block of whole lines holds, with line numbers counted from the block's start. Parsing
// stops at the block's first error; whether it is the file's first error, and whether the block's
// first line with numbers agrees with the earlier blocks, only the blocks before it can say.
struct Xyz_block
{
  std::vector<Oriented_point_set::Point_3> points;
  std::vector<Oriented_point_set::Vector_3> normals;
  std::size_t lines = 0;
  std::size_t first_columns = 0; // the count of numbers on its first line with numbers, 0: none
  std::size_t first_columns_line = 0;
  std::string error; // the message of its first error, after "line N: "
  std::size_t error_line = 0;
};

// Parses the token [first, last): false with `error` set when it is not a finite number. The same
// double as std::strtod, the same errors: std::from_chars is the fast path, and whatever it does
// not take whole (a leading '+', hex floats, out-of-range values, junk) goes to std::strtod.
inline bool parse_xyz_number(const char* first, const char* last, double& v, std::string& error)
{
  const std::from_chars_result r = std::from_chars(first, last, v);
  if(r.ec != std::errc() || r.ptr != last)
  {
    const std::string token(first, last); // null-terminated for strtod
    char* end = nullptr;
    v = std::strtod(token.c_str(), &end);
    if(end == token.c_str() || *end != '\0')
    {
      error = "'" + token + "' is not a number";
      return false;
    }
  }
  if(!std::isfinite(v))
  {
    error = "non-finite value '" + std::string(first, last) + "'";
    return false;
  }
  return true;
}

// Parses the lines of [first, last) into `b`, as the sequential reader did, until the first error.
inline void parse_xyz_block(const char* first, const char* last, Xyz_block& b)
{
  std::size_t columns = 0;
  for(const char* line = first; line < last;)
  {
    const char* line_end = static_cast<const char*>(std::memchr(line, '\n', std::size_t(last - line)));
    if(line_end == nullptr)
      line_end = last; // a last line without '\n'
    ++b.lines;
    const char* hash = static_cast<const char*>(std::memchr(line, '#', std::size_t(line_end - line)));
    const char* stop = hash ? hash : line_end;
    double values[XYZ_POINT_AND_NORMAL_COLUMNS];
    std::size_t count = 0;
    for(const char* p = line;;)
    {
      p = skip_text_spaces(p, stop);
      if(p == stop)
        break;
      const char* token = p;
      p = text_token_end(p, stop);
      double v;
      if(!parse_xyz_number(token, p, v, b.error))
      {
        b.error_line = b.lines;
        return;
      }
      if(count < XYZ_POINT_AND_NORMAL_COLUMNS)
        values[count] = v;
      ++count;
    }
    line = line_end == last ? last : line_end + 1;
    if(count == 0)
      continue;
    if(count != XYZ_POINT_COLUMNS && count != XYZ_POINT_AND_NORMAL_COLUMNS)
    {
      b.error = "expected 3 (x y z) or 6 (x y z nx ny nz) numbers, got " + std::to_string(count);
      b.error_line = b.lines;
      return;
    }
    if(columns == 0)
    {
      columns = b.first_columns = count;
      b.first_columns_line = b.lines;
    }
    else if(count != columns)
    {
      b.error = std::to_string(count) + " numbers where earlier lines have " + std::to_string(columns);
      b.error_line = b.lines;
      return;
    }
    b.points.emplace_back(values[0], values[1], values[2]);
    if(count == XYZ_POINT_AND_NORMAL_COLUMNS)
      b.normals.emplace_back(values[3], values[4], values[5]);
  }
}

// `x y z` or `x y z nx ny nz` per line; `#` starts a comment. Strict, with line numbers. Parsed on
// `threads` threads (0: OpenMP's default) a block of lines each; the points, and the error when
// there is one, are those of a sequential reading, whatever the number of threads.
inline void read_xyz(const std::string& filename, std::vector<Oriented_point_set::Point_3>& points,
                     std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals,
                     unsigned int threads = 0)
{
  Text_file text = read_text_file(filename);
  const char* const data = text.bytes.get();
  const std::vector<std::size_t> starts = line_block_starts(data, 0, text.size, text_reader_threads(threads));
  std::vector<Xyz_block> blocks(starts.size() - 1);
  std::vector<std::exception_ptr> exceptions; // out of memory
  parse_blocks(blocks.size(), text_reader_threads(threads), exceptions,
               [&](std::size_t i) { parse_xyz_block(data + starts[i], data + starts[i + 1], blocks[i]); });
  text.bytes.reset(); // the text is no longer needed: freed before the points are gathered

  // The blocks in file order: the first error a sequential reading meets is the one thrown. The
  // file's column count is that of its first line with numbers. A block's first line with numbers
  // comes before any error of the block and is checked against it; if they agree, the block's own
  // checks, made against that line, hold for the file.
  std::size_t columns = 0, lines_before = 0, total = 0;
  for(std::size_t i = 0; i < blocks.size(); ++i)
  {
    const Xyz_block& b = blocks[i];
    if(exceptions[i])
      std::rethrow_exception(exceptions[i]);
    if(b.first_columns != 0)
    {
      if(columns == 0)
        columns = b.first_columns;
      else if(b.first_columns != columns)
        throw Input_error("line " + std::to_string(lines_before + b.first_columns_line) + ": " +
                          std::to_string(b.first_columns) + " numbers where earlier lines have " +
                          std::to_string(columns));
    }
    if(!b.error.empty())
      throw Input_error("line " + std::to_string(lines_before + b.error_line) + ": " + b.error);
    lines_before += b.lines;
    total += b.points.size();
  }
  points.reserve(points.size() + total);
  if(columns == XYZ_POINT_AND_NORMAL_COLUMNS)
    normals.reserve(normals.size() + total);
  for(Xyz_block& b : blocks)
  {
    points.insert(points.end(), b.points.begin(), b.points.end());
    normals.insert(normals.end(), b.normals.begin(), b.normals.end());
    b = Xyz_block(); // freed as it goes
  }
  has_normals = (columns == XYZ_POINT_AND_NORMAL_COLUMNS);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_XYZ_H
