// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_OBJ_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_OBJ_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/Polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/text_blocks.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <exception>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The keywords CGAL 5.5's `IO::read_OBJ()` accepts and ignores, besides `vt`, `vn` and comments.
inline bool is_ignored_obj_keyword(const char* first, const char* last)
{
  static const char* const keywords[] = {
    "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech", "d_interp", "mtllib", "shadow_obj",
    "trace_obj", "o", "g", "s", "p", "cstype", "deg", "step", "bmat", "con", "curv", "curv2", "surf", "parm",
    "trim", "hole", "scrv", "sp", "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2", "q0_2", "q1_2",
    "curv2d_2", "bsp", "bzp", "cdc", "cdp", "res"};
  const std::size_t length = std::size_t(last - first);
  return std::any_of(std::begin(keywords), std::end(keywords), [&](const char* k) {
    return std::strlen(k) == length && std::memcmp(k, first, length) == 0;
  });
}

// What one block of whole lines of an OBJ file holds.
struct Obj_block
{
  std::vector<Oriented_point_set::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::size_t largest_index = 0; // the largest index of a corner, counted from 1; 0: none
  bool failed = false;           // a line the fast reader leaves to CGAL's
};

// The characters `std::istream::ignore(256, ' ')` skips from `p`: up to and including the first
// space, 256 at most.
inline const char* ignore_to_obj_space(const char* p, const char* last)
{
  for(std::size_t taken = 0; p < last && taken < 256; ++taken)
    if(*p++ == ' ')
      break;
  return p;
}

// Parses the lines of [first, last) as CGAL 5.5's `IO::read_OBJ()` does, until a line it leaves to
// CGAL's reader: a keyword CGAL refuses, a vertex without three plain numbers first
// (parse_plain_double()), a corner index that is signed, 0 (both counted from the vertices read so
// far) or too large for an `int`.
inline void parse_obj_block(const char* first, const char* last, Obj_block& b)
{
  auto fail = [&] {
    b.failed = true;
    return false;
  };
  for_each_line_with_tokens(first, last, [&](const char* keyword, const char* end, bool) {
    const char* p = text_token_end(keyword, end);
    const std::size_t length = std::size_t(p - keyword);
    if(length == 1 && *keyword == 'v')
    {
      // CGAL reads x, y, z; the rest of the line is ignored
      double xyz[3];
      if(parse_plain_doubles(p, end, xyz, 3) == nullptr)
        return fail();
      b.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    else if(length == 1 && *keyword == 'f')
    {
      // `iss >> i` then `iss.ignore(256, ' ')`, until `>>` finds no integer
      std::vector<std::size_t> polygon;
      for(;;)
      {
        p = skip_text_spaces(p, end);
        if(p == end || *p < '0' || *p > '9')
        {
          if(p != end && (*p == '-' || *p == '+'))
            return fail(); // a sign: maybe an index relative to the vertices read so far
          break;
        }
        int index = 0;
        const std::from_chars_result r = std::from_chars(p, end, index);
        if(r.ec != std::errc() || index < 1)
          return fail();
        polygon.push_back(std::size_t(index - 1));
        b.largest_index = (std::max)(b.largest_index, std::size_t(index));
        p = ignore_to_obj_space(r.ptr, end);
      }
      b.polygons.push_back(std::move(polygon));
    }
    else if(!((length == 2 && (std::memcmp(keyword, "vt", 2) == 0 || std::memcmp(keyword, "vn", 2) == 0)) ||
              *keyword == '#' || is_ignored_obj_keyword(keyword, p)))
      return fail();
    return true;
  });
}

// The soup of an OBJ file, parsed on `threads` threads (0: OpenMP's default), a block of lines each.
// Returns false, with `soup` empty, where CGAL's reader fails or where a line is one that
// parse_obj_block() leaves to it: CGAL's `IO::read_OBJ()` reads the file then, or says why it cannot.
// What it returns is what CGAL's reader returns, bit for bit.
inline bool read_obj_soup(const Input_file& file, Polygon_soup& soup, unsigned int threads = 0)
{
  Text_file text = read_text_file(file.name);
  const char* const data = text.bytes.get();
  const std::size_t thread_number = text_reader_threads(threads);
  const std::vector<std::size_t> starts = line_block_starts(data, 0, text.size, thread_number);
  std::vector<Obj_block> blocks(starts.size() - 1);
  std::vector<std::exception_ptr> exceptions;
  parse_blocks(blocks.size(), thread_number, exceptions,
               [&](std::size_t i) { parse_obj_block(data + starts[i], data + starts[i + 1], blocks[i]); });
  text.bytes.reset();
  std::size_t points = 0, polygons = 0, largest_index = 0;
  for(std::size_t i = 0; i < blocks.size(); ++i)
  {
    if(exceptions[i])
      std::rethrow_exception(exceptions[i]); // out of memory
    if(blocks[i].failed)
      return false;
    points += blocks[i].points.size();
    polygons += blocks[i].polygons.size();
    largest_index = (std::max)(largest_index, blocks[i].largest_index);
  }
  // CGAL refuses a file without points or faces, and a corner beyond the vertex after the last
  if(points == 0 || polygons == 0 || largest_index > points + 1)
    return false;
  soup.points.reserve(points);
  soup.polygons.reserve(polygons);
  for(Obj_block& b : blocks)
  {
    soup.points.insert(soup.points.end(), b.points.begin(), b.points.end());
    std::move(b.polygons.begin(), b.polygons.end(), std::back_inserter(soup.polygons));
    b = Obj_block(); // freed as it goes
  }
  return true;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_OBJ_H
