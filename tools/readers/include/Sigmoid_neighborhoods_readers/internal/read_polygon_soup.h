// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_POLYGON_SOUP_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_POLYGON_SOUP_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/Polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/cgal_5_5_workarounds.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/ply_point_layout.h>
#include <Sigmoid_neighborhoods_readers/internal/read_ascii_off.h>
#include <Sigmoid_neighborhoods_readers/internal/read_obj.h>
#include <Sigmoid_neighborhoods_readers/internal/read_off.h>
#include <Sigmoid_neighborhoods_readers/internal/read_ply.h>
#include <Sigmoid_neighborhoods_readers/internal/read_stl.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Reads the soup of an OFF, OBJ, PLY or STL file with the reader of its format; a file that
// cannot be parsed throws, with CGAL's explanation when it gave one. No faces is not an error here.
// Plain ASCII OFF and OBJ files are parsed on `threads` threads (0: the default), the others by
// CGAL's readers, with the same result.
inline void read_polygon_soup(const Input_file& file, Polygon_soup& soup, unsigned int threads = 0)
{
  const std::string& ext = file.extension;
  bool read = false;
  std::string reason;
  {
    Captured_cerr captured;
    if(ext == "off")
      read = read_ascii_off_soup(file, soup, threads) || read_off_soup(file, soup);
    else if(ext == "ply")
      read = read_ply_soup(file, soup);
    else if(ext == "obj")
      read = read_obj_soup(file, soup, threads) || CGAL::IO::read_OBJ(file.name, soup.points, soup.polygons);
    else if(ext == "stl")
      read = read_stl_soup(file, soup);
    reason = captured.first_line();
  }
  if(!read)
    throw Input_error("cannot parse the file as " + ext + (ext == "obj" ? ", or it has no faces" : "") +
                      (reason.empty() ? std::string() : " (" + reason + ")"));
}

// The values of the property `name` of type `T` of `point_set` as labels, when it has one: true then,
// with `labels` empty when a value is no integer of `int` (a non-integral or non-finite float, an
// unsigned beyond INT_MAX): such a property is not a label.
template <typename T, typename Point_set>
bool ply_labels_of_type(const Point_set& point_set, const std::string& name, std::vector<int>& labels)
{
  const auto found = point_set.template property_map<T>(name);
  if(!found.second)
    return false;
  labels.reserve(point_set.size());
  for(auto it = point_set.begin(); it != point_set.end(); ++it)
  {
    const double value = double(get(found.first, *it)); // exact for every PLY type but 64-bit ones
    if(!(value >= double((std::numeric_limits<int>::min)()) && value <= double((std::numeric_limits<int>::max)())) ||
       std::trunc(value) != value)
    {
      labels.clear();
      return true;
    }
    labels.push_back(int(value));
  }
  return true;
}

// The labels of a point set read from a PLY file: its first property of ply_label_names(), of any
// numeric type of CGAL's PLY reader; none (empty) otherwise.
template <typename Point_set>
void ply_labels(const Point_set& point_set, std::vector<int>& labels)
{
  for(const std::string& name : ply_label_names())
    if(ply_labels_of_type<std::int8_t>(point_set, name, labels) ||
       ply_labels_of_type<std::uint8_t>(point_set, name, labels) ||
       ply_labels_of_type<std::int16_t>(point_set, name, labels) ||
       ply_labels_of_type<std::uint16_t>(point_set, name, labels) ||
       ply_labels_of_type<std::int32_t>(point_set, name, labels) ||
       ply_labels_of_type<std::uint32_t>(point_set, name, labels) ||
       ply_labels_of_type<float>(point_set, name, labels) || ply_labels_of_type<double>(point_set, name, labels))
      return;
}

// The points, and normals when it has them, of an OFF or PLY file without faces, read by CGAL's
// point set reader (after read_polygon_soup(), which has checked the header); with `labels`, the
// labels of a PLY file that has them (ply_labels()).
inline void read_points_without_faces(const Input_file& file, std::vector<Oriented_point_set::Point_3>& points,
                                      std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals,
                                      std::vector<int>* labels = nullptr)
{
  CGAL::Point_set_3<Oriented_point_set::Point_3, Oriented_point_set::Vector_3> point_set;
  {
    Captured_cerr captured;
    if(!CGAL::IO::read_point_set(file.name, point_set))
    {
      const std::string why = captured.first_line();
      throw Input_error("cannot parse the file as " + file.extension + (why.empty() ? "" : " (" + why + ")"));
    }
  }
  has_normals = point_set.has_normal_map();
  for(auto it = point_set.begin(); it != point_set.end(); ++it)
  {
    points.push_back(point_set.point(*it));
    if(has_normals)
      normals.push_back(point_set.normal(*it));
  }
  if(labels != nullptr && file.extension == "ply")
    ply_labels(point_set, *labels);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_POLYGON_SOUP_H
