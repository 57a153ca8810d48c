// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ASCII_PLY_POINTS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ASCII_PLY_POINTS_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/ply_point_layout.h>
#include <Sigmoid_neighborhoods_readers/internal/text_blocks.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Reads the token [first, last) as CGAL's ASCII PLY reader reads a property of `type`, into `v`;
// false for a token it might read otherwise (those files go to CGAL's reader). Integers: digits,
// with a '-' for a signed type, within the type's range (CGAL reads a char through a short and
// casts it, and `>>` reads "-1" into an unsigned type). Floats: a plain number
// (parse_plain_double()) that std::from_chars reads whole as a float, correctly rounded as CGAL's
// `IO::iformat()` (sscanf("%f")) does. Doubles: parse_plain_double().
inline bool parse_ply_ascii_value(const char* first, const char* last, Ply_field::Type type, double& v)
{
  switch(type)
  {
  case Ply_field::FLOAT:
  {
    double check = 0.;
    float f = 0.f;
    if(!parse_plain_double(first, last, check)) // the characters, whole, and a finite double
      return false;
    const std::from_chars_result r = std::from_chars(first, last, f);
    if(r.ec != std::errc() || r.ptr != last || !std::isfinite(f))
      return false;
    v = double(f);
    return true;
  }
  case Ply_field::DOUBLE: return parse_plain_double(first, last, v);
  default: break;
  }
  const bool is_signed = type == Ply_field::INT8 || type == Ply_field::INT16 || type == Ply_field::INT32;
  if(first == last || (*first == '-' && !is_signed) || !(*first == '-' || (*first >= '0' && *first <= '9')))
    return false;
  std::int64_t value = 0;
  const std::from_chars_result r = std::from_chars(first, last, value);
  if(r.ec != std::errc() || r.ptr != last)
    return false;
  std::int64_t lowest = 0, highest = 0;
  switch(type)
  {
  case Ply_field::INT8: lowest = -128; highest = 127; break;
  case Ply_field::UINT8: highest = 255; break;
  case Ply_field::INT16: lowest = -32768; highest = 32767; break;
  case Ply_field::UINT16: highest = 65535; break;
  case Ply_field::INT32:
    lowest = (std::numeric_limits<std::int32_t>::min)();
    highest = (std::numeric_limits<std::int32_t>::max)();
    break;
  default: highest = (std::numeric_limits<std::uint32_t>::max)(); break;
  }
  if(value < lowest || value > highest)
    return false;
  v = double(value);
  return true;
}

// The points of an ASCII PLY point set (ply_point_layout()), parsed on `threads` threads (0:
// OpenMP's default), a block of lines each: the same points, normals and labels as CGAL's point
// set reader gives in read_points_without_faces(). The blocks first count their lines with tokens,
// so that each knows which vertex its lines hold. Taken only when each of the first `count` lines
// with tokens holds one vertex, every property read as CGAL reads it (parse_ply_ascii_value()):
// then CGAL's reader, which reads tokens without regard to lines, reads the same values. False, with
// nothing read, for any other file: those go to CGAL's readers, after check_ply_counts(). That check
// reads every value on one thread; it is not needed here: the room taken is bounded by the lines
// counted, and a file taken here passes it.
inline bool read_ascii_ply_points(const Input_file& file, std::vector<Oriented_point_set::Point_3>& points,
                                  std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals,
                                  std::vector<int>& labels, unsigned int threads)
{
  Ply_point_layout layout;
  if(!ply_point_layout(file, "ascii", layout))
    return false;
  Text_file text = read_text_file(file.name);
  if(std::uintmax_t(layout.header_end) > text.size)
    return false;
  const char* const data = text.bytes.get();
  const std::size_t thread_number = text_reader_threads(threads);
  const std::vector<std::size_t> starts =
    line_block_starts(data, std::size_t(layout.header_end), text.size, thread_number);
  const std::size_t block_count = starts.size() - 1, n = layout.count;
  std::vector<std::exception_ptr> exceptions;

  const std::vector<std::size_t> first_record = first_item_of_blocks(block_count, thread_number, [&](std::size_t b) {
    std::size_t lines = 0;
    for_each_line_with_tokens(data + starts[b], data + starts[b + 1], [&](const char*, const char*, bool) {
      ++lines;
      return true;
    });
    return lines;
  });
  if(first_record[block_count] < n)
    return false; // cut short: CGAL's reader says so

  enum { X = Ply_point_layout::X, Y, Z, NX, NY, NZ };
  const Ply_field* fields = layout.fields;
  const std::size_t columns = layout.types.size();
  points.resize(n);
  if(layout.has_normals)
    normals.resize(n);
  std::vector<double> label_values(layout.has_label ? n : 0);
  std::vector<char> failed(block_count, 0);
  parse_blocks(block_count, thread_number, exceptions, [&](std::size_t b) {
    std::size_t record = first_record[b];
    if(record >= n)
      return;
    std::vector<double> values(columns);
    for_each_line_with_tokens(data + starts[b], data + starts[b + 1], [&](const char* p, const char* end, bool) {
      for(std::size_t c = 0; c < columns; ++c)
      {
        p = skip_text_spaces(p, end);
        const char* token_end = text_token_end(p, end);
        if(!parse_ply_ascii_value(p, token_end, layout.types[c], values[c]))
        {
          failed[b] = 1;
          return false;
        }
        p = token_end;
      }
      if(skip_text_spaces(p, end) != end) // a token more: CGAL's reader reads it as the next vertex's
      {
        failed[b] = 1;
        return false;
      }
      points[record] = Oriented_point_set::Point_3(values[fields[X].column], values[fields[Y].column],
                                                   values[fields[Z].column]);
      if(layout.has_normals)
        normals[record] = Oriented_point_set::Vector_3(values[fields[NX].column], values[fields[NY].column],
                                                       values[fields[NZ].column]);
      if(layout.has_label)
        label_values[record] = values[layout.label.column];
      return ++record < n;
    });
  });
  text.bytes.reset();
  for(std::size_t b = 0; b < block_count; ++b)
    if(exceptions[b] || failed[b])
    {
      points.clear();
      normals.clear();
      for(const std::exception_ptr& e : exceptions)
        if(e)
          std::rethrow_exception(e); // out of memory
      return false;
    }
  has_normals = layout.has_normals;
  ply_labels_of_values(label_values, labels);
  return true;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ASCII_PLY_POINTS_H
