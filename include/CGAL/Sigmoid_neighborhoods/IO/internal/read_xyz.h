// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_XYZ_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_XYZ_H

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/IO/Oriented_point_set.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The numbers of an XYZ/PWN line: a point, or a point and its normal.
constexpr std::size_t XYZ_POINT_COLUMNS = 3;
constexpr std::size_t XYZ_POINT_AND_NORMAL_COLUMNS = 6;

// `x y z` or `x y z nx ny nz` per line; `#` starts a comment. Strict, with line numbers.
inline void read_xyz(const std::string& filename, std::vector<Oriented_point_set::Point_3>& points,
                     std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals)
{
  std::ifstream in(filename);
  std::string line;
  std::size_t line_number = 0, columns = 0;
  while(std::getline(in, line))
  {
    ++line_number;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos)
      line.erase(hash);
    std::istringstream tokens(line);
    std::vector<double> values;
    std::string token;
    while(tokens >> token)
    {
      const char* begin = token.c_str();
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if(end == begin || *end != '\0')
        throw Input_error("line " + std::to_string(line_number) + ": '" + token + "' is not a number");
      if(!std::isfinite(v))
        throw Input_error("line " + std::to_string(line_number) + ": non-finite value '" + token + "'");
      values.push_back(v);
    }
    if(values.empty())
      continue;
    if(values.size() != XYZ_POINT_COLUMNS && values.size() != XYZ_POINT_AND_NORMAL_COLUMNS)
      throw Input_error("line " + std::to_string(line_number) + ": expected 3 (x y z) or 6 (x y z nx ny nz) numbers, got " +
                        std::to_string(values.size()));
    if(columns == 0)
      columns = values.size();
    else if(values.size() != columns)
      throw Input_error("line " + std::to_string(line_number) + ": " + std::to_string(values.size()) +
                        " numbers where earlier lines have " + std::to_string(columns));
    points.emplace_back(values[0], values[1], values[2]);
    if(columns == XYZ_POINT_AND_NORMAL_COLUMNS)
      normals.emplace_back(values[3], values[4], values[5]);
  }
  if(in.bad())
    throw Input_error("read error");
  has_normals = (columns == XYZ_POINT_AND_NORMAL_COLUMNS);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_READ_XYZ_H
