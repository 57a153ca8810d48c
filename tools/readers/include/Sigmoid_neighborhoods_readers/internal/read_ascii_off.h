// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ASCII_OFF_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ASCII_OFF_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/Polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/text_blocks.h>

#include <CGAL/IO/OFF/File_scanner_OFF.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The largest index or corner count the fast OFF reader takes: CGAL's scanner reads them as
// doubles, exact below 2^53.
constexpr std::uint64_t OFF_LARGEST_PLAIN_INTEGER = std::uint64_t(1) << 53;

// Whether the token [first, last) is a plain unsigned decimal integer below 2^53, read into `v`.
inline bool parse_plain_index(const char* first, const char* last, std::uint64_t& v)
{
  if(first == last || *first < '0' || *first > '9')
    return false;
  const std::from_chars_result r = std::from_chars(first, last, v);
  return r.ec == std::errc() && r.ptr == last && v < OFF_LARGEST_PLAIN_INTEGER;
}

// Calls `line(first, last, ends_with_newline)` for each line of [first, last) that CGAL's OFF
// scanner reads as an item: it skips spaces, empty lines and lines whose first character after
// spaces is '#', then takes the rest of the line. `line` returns false to stop.
template <typename Line>
void for_each_off_item_line(const char* first, const char* last, const Line& line)
{
  for_each_line_with_tokens(first, last, [&](const char* start, const char* end, bool newline) {
    return *start == '#' || line(start, end, newline);
  });
}

// The soup of an ASCII OFF file, parsed on `threads` threads (0: OpenMP's default): a block of
// lines each, counted first, so that each block knows which of its lines are vertices and which
// faces. Takes the plain files only: the header `OFF` or `COFF`, `NOFF`, ... read by CGAL's scanner,
// not binary nor homogeneous; each vertex line with three plain numbers first (parse_plain_double())
// and a line end; each face line with its corner count and that many plain indices of vertices
// first; every other token after these ignored, as CGAL's reader does. Returns false, with `soup`
// empty, for any other file: read_off_soup() reads it then, or says why it cannot. What it returns
// is what read_off_soup() returns, bit for bit.
inline bool read_ascii_off_soup(const Input_file& file, Polygon_soup& soup, unsigned int threads = 0)
{
  std::size_t vertices = 0, faces = 0;
  std::streamoff header_end = 0;
  {
    std::ifstream is(file.name);
    CGAL::File_scanner_OFF scanner(is);
    if(is.fail() || scanner.binary() || scanner.skel() || scanner.is_homogeneous() || scanner.n_dimensional() ||
       scanner.index_offset() != 0)
      return false;
    vertices = scanner.size_of_vertices();
    faces = scanner.size_of_facets();
    header_end = is.tellg();
    if(header_end <= 0)
      return false;
  }
  Text_file text = read_text_file(file.name);
  if(std::size_t(header_end) > text.size)
    return false;
  const char* const data = text.bytes.get();
  const std::size_t thread_number = text_reader_threads(threads);
  const std::vector<std::size_t> starts = line_block_starts(data, std::size_t(header_end), text.size, thread_number);
  const std::size_t block_count = starts.size() - 1;
  std::vector<std::exception_ptr> exceptions;

  // The item lines of each block, then the index of each block's first one.
  const std::vector<std::size_t> first_item = first_item_of_blocks(block_count, thread_number, [&](std::size_t b) {
    std::size_t items = 0;
    for_each_off_item_line(data + starts[b], data + starts[b + 1], [&](const char*, const char*, bool) {
      ++items;
      return true;
    });
    return items;
  });
  // Fewer lines than the header announces: read_off_soup() says so. The room taken below is
  // bounded by the lines there are.
  if(first_item[block_count] < vertices || first_item[block_count] - vertices < faces)
    return false;

  soup.points.resize(vertices);
  soup.polygons.resize(faces);
  std::vector<char> failed(block_count, 0);
  parse_blocks(block_count, thread_number, exceptions, [&](std::size_t b) {
    std::size_t item = first_item[b];
    if(item >= vertices + faces)
      return;
    auto fail = [&] {
      failed[b] = 1;
      return false;
    };
    for_each_off_item_line(data + starts[b], data + starts[b + 1], [&](const char* p, const char* end, bool newline) {
      if(const char* hash = static_cast<const char*>(std::memchr(p, '#', std::size_t(end - p))))
        end = hash;
      if(item < vertices)
      {
        // CGAL's scanner fails on a vertex line that meets the end of the file
        double xyz[3];
        if(!newline || parse_plain_doubles(p, end, xyz, 3) == nullptr)
          return fail();
        soup.points[item] = Oriented_point_set::Point_3(xyz[0], xyz[1], xyz[2]);
      }
      else
      {
        std::uint64_t corners = 0;
        p = skip_text_spaces(p, end);
        const char* token_end = text_token_end(p, end);
        if(!parse_plain_index(p, token_end, corners))
          return fail();
        std::vector<std::size_t>& polygon = soup.polygons[item - vertices];
        for(std::uint64_t j = 0; j < corners; ++j)
        {
          std::uint64_t index = 0;
          p = skip_text_spaces(token_end, end);
          token_end = text_token_end(p, end);
          if(!parse_plain_index(p, token_end, index) || index >= vertices)
            return fail();
          polygon.push_back(std::size_t(index));
        }
      }
      return ++item < vertices + faces;
    });
  });
  for(std::size_t b = 0; b < block_count; ++b)
    if(exceptions[b] || failed[b])
    {
      soup = Polygon_soup();
      for(const std::exception_ptr& e : exceptions)
        if(e)
          std::rethrow_exception(e); // out of memory
      return false;
    }
  return true;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ASCII_OFF_H
