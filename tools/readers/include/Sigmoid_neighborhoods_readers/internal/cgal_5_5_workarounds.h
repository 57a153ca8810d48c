// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// What CGAL 5.5's readers need around them to read untrusted files: their explanations on
// std::cerr kept for a one-line message, and the PLY header checks that they leave out (found by
// fuzzing). The counts of every format are bounded by the bytes left (Byte_budget.h): the OFF loop
// that replaces `CGAL::IO::read_OFF()` in read_off.h, check_ply_counts.h, read_stl.h.

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CGAL_5_5_WORKAROUNDS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CGAL_5_5_WORKAROUNDS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>

#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// CGAL's readers explain a failure on std::cerr; keep the explanation for our one-line message.
// std::cerr is one for the process: files read on several threads at once take turns here (the
// parsing; what follows it, the repair and the normals, runs side by side).
class Captured_cerr
{
  static std::mutex& turn()
  {
    static std::mutex m;
    return m;
  }

public:
  Captured_cerr() : m_turn(turn()), m_old(std::cerr.rdbuf(m_buffer.rdbuf())) {}
  ~Captured_cerr() { std::cerr.rdbuf(m_old); }
  Captured_cerr(const Captured_cerr&) = delete;
  Captured_cerr& operator=(const Captured_cerr&) = delete;

  // The first line CGAL wrote, without its "Error: " prefix.
  std::string first_line() const
  {
    static const std::string ERROR_PREFIX = "Error: ";
    std::string text = m_buffer.str();
    const std::size_t end = text.find('\n');
    text = text.substr(0, end);
    if(text.rfind(ERROR_PREFIX, 0) == 0)
      text = text.substr(ERROR_PREFIX.size());
    return text;
  }

private:
  std::lock_guard<std::mutex> m_turn;
  std::ostringstream m_buffer;
  std::streambuf* m_old;
};

// The most vertex properties of a PLY point set: CGAL's point set reader looks every property of
// every vertex up by name among all of them, a time quadratic in their number (a header of 20,000
// one-byte properties and 20 vertices, 0.8 MB, took 30 s). Real point sets have a few dozen (a 3D
// Gaussian splat has 62).
constexpr std::size_t MAX_POINT_SET_PROPERTIES = 256;

// Header contents that CGAL 5.5's PLY reader does not check (crashes, found by fuzzing), besides
// the counts (check_ply_counts.h): a `property` line before any `element` line (it takes the back()
// of an empty vector), and vertex properties of another type than it reads them as (it dereferences
// a failed dynamic_cast): `x y z` as float or double, and, in a point set (no faces), which CGAL
// reads all as float when one of `x y z` is float, `nx ny nz` as float then; a point set also looks
// its other properties up by name, cut at a NUL byte, so vertex property names must be distinct and
// without NUL, and at most MAX_POINT_SET_PROPERTIES.
inline void check_ply_header(const std::string& filename)
{
  // The first two lines are the signature and the format, which CGAL checks.
  constexpr std::size_t LINES_CHECKED_BY_CGAL = 2;
  std::ifstream in(filename, std::ios::binary);
  std::string line, element;
  std::vector<std::pair<std::string, std::string>> vertex_properties; // (name, type)
  std::set<std::string> vertex_property_names;
  bool has_faces = false, float_point = false;
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number)
  {
    std::istringstream tokens(line);
    std::string keyword;
    if(line_number <= LINES_CHECKED_BY_CGAL || !(tokens >> keyword))
      continue;
    if(keyword == "end_header")
      break;
    if(keyword == "element")
    {
      std::size_t items = 0; // read as CGAL reads it
      tokens >> element >> items;
      has_faces = has_faces || ((element == "face" || element == "faces") && items > 0);
    }
    else if(keyword == "property")
    {
      if(element.empty())
        throw Input_error("cannot parse the file as ply (a property before any element, line " +
                          std::to_string(line_number) + ")");
      std::string type, name;
      if((element == "vertex" || element == "vertices") && tokens >> type >> name)
      {
        if(type == "list" && !(tokens >> name >> name))
          continue; // `list SIZE_TYPE INDEX_TYPE NAME`; CGAL refuses the line
        if(name.find('\0') != std::string::npos || !vertex_property_names.insert(name).second)
          throw Input_error("cannot parse the file as ply (vertex property '" + name.substr(0, name.find('\0')) +
                            "' given twice or with a NUL byte, line " + std::to_string(line_number) + ")");
        vertex_properties.emplace_back(name, type);
      }
    }
  }
  if(!has_faces && vertex_properties.size() > MAX_POINT_SET_PROPERTIES)
    throw Input_error("cannot parse the file as ply (a point set of " + std::to_string(vertex_properties.size()) +
                      " properties per vertex, more than " + std::to_string(MAX_POINT_SET_PROPERTIES) +
                      ": CGAL's reader takes a time quadratic in their number)");
  auto is_float = [](const std::string& type) { return type == "float" || type == "float32"; };
  for(const auto& property : vertex_properties)
    if(property.first == "x" || property.first == "y" || property.first == "z")
      float_point = float_point || is_float(property.second);
  for(const auto& property : vertex_properties)
  {
    const std::string& name = property.first;
    const bool is_point = (name == "x" || name == "y" || name == "z");
    if(!is_point && (has_faces || (name != "nx" && name != "ny" && name != "nz")))
      continue;
    const bool as_read = float_point && !has_faces ? is_float(property.second)
                                                   : is_float(property.second) || property.second == "double" ||
                                                       property.second == "float64";
    if(!as_read)
      throw Input_error("cannot parse the file as ply (vertex property '" + name + "' of type '" + property.second +
                        "': coordinates and normals must be float or double" +
                        (float_point && !has_faces ? ", all float when a coordinate is" : "") + ")");
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CGAL_5_5_WORKAROUNDS_H
