// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// The definitions of read_oriented_point_set.h: inline in the header-only build, compiled once into the
// library Sigmoid_neighborhoods_readers otherwise (config.h).

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ORIENTED_POINT_SET_IMPL_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ORIENTED_POINT_SET_IMPL_H

#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/internal/check_points.h>
#include <Sigmoid_neighborhoods_readers/internal/estimate_normals.h>
#include <Sigmoid_neighborhoods_readers/internal/estimate_zero_normals.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/merge_equal_positions.h>
#include <Sigmoid_neighborhoods_readers/internal/mesh_to_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_ascii_ply_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_binary_ply_points.h>
#include <Sigmoid_neighborhoods_readers/internal/read_las.h>
#include <Sigmoid_neighborhoods_readers/internal/read_polygon_soup.h>
#include <Sigmoid_neighborhoods_readers/internal/read_xyz.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

SIGMOID_NEIGHBORHOODS_READERS_FUNCTION Oriented_point_set
read_oriented_point_set(const std::string& filename, const Normal_options& options)
{
  const bool may_skip_estimation = options.source == Normal_source::AUTO && options.neighbors == 0;
  const unsigned int fewest = internal::fewest_estimation_neighbors(internal::estimation_method(options.source));
  if(!may_skip_estimation && options.source != Normal_source::FROM_FILE && options.neighbors < fewest)
    throw std::invalid_argument("read_oriented_point_set: the estimation needs at least " + std::to_string(fewest) +
                                " neighbors" + (options.source == Normal_source::AUTO ? " (or 0: no estimation)" : "") +
                                ", got " + std::to_string(options.neighbors));
  const bool estimate_anyway = options.source == Normal_source::PCA || options.source == Normal_source::JET;
  const internal::Input_file file = internal::open_input_file(
    filename, {"off", "obj", "ply", "stl", "xyz", "pwn", "las", "laz"}, ".off, .obj, .ply, .stl, .xyz, .pwn, .las or .laz");

  // Each format to points, and normals when the file has them; a mesh is done there.
  Oriented_point_set out;
  bool has_normals = false;
  if(file.extension == "xyz" || file.extension == "pwn")
    internal::read_xyz(file.name, out.points, out.normals, has_normals, options.threads);
  else if(file.extension == "las" || file.extension == "laz")
    internal::read_las(file, out, internal::Keep_every_las_point(), options.threads); // no normals in LAS
  else if(file.extension == "ply" &&
          (internal::read_binary_ply_points(file, out.points, out.normals, has_normals, out.labels, options.threads) ||
           internal::read_ascii_ply_points(file, out.points, out.normals, has_normals, out.labels, options.threads)))
    ; // a point set, read on every thread
  else
  {
    internal::Polygon_soup soup;
    internal::read_polygon_soup(file, soup, options.threads);
    if(!soup.polygons.empty())
    {
      internal::mesh_to_points(soup, out, options.threads);
      if(estimate_anyway)
        internal::estimate_normals(out, options);
      return out;
    }
    if(file.extension == "obj" || file.extension == "stl")
      throw Input_error("no faces in the file");
    internal::read_points_without_faces(file, out.points, out.normals, has_normals, &out.labels); // OFF or PLY
  }

  // A point set: checked, merged, normals estimated when asked or when it has none.
  out.input_vertices = out.points.size();
  if(out.points.empty())
    throw Input_error("no points in the file");
  // zero normals: replaced anyway (PCA, JET), estimated (AUTO), refused (FROM_FILE)
  std::size_t first_zero = 0;
  const std::size_t zeros = internal::check_points_and_normals(
    out.points, out.normals, has_normals, options.source != Normal_source::FROM_FILE, &first_zero);
  const bool all_zero = zeros > 0 && zeros == out.normals.size();
  if(all_zero)
  {
    has_normals = false; // normal columns of zeros: no normals
    out.normals.clear();
  }
  else if(zeros > 0 && may_skip_estimation)
    throw Input_error("point " + std::to_string(first_zero) + " has a zero normal");
  internal::merge_duplicate_points(out, has_normals, options.threads);
  if(!has_normals && options.source == Normal_source::FROM_FILE)
    throw Input_error("the file has no normals");
  if(!has_normals && may_skip_estimation)
  {
    out.normals.clear();
    return out;
  }
  if(!has_normals || estimate_anyway)
  {
    internal::estimate_normals(out, options);
    if(all_zero && options.source == Normal_source::AUTO)
      out.zero_normals = out.points.size();
  }
  else if(zeros > 0)
    internal::estimate_zero_normals(out, options);
  return out;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_ORIENTED_POINT_SET_IMPL_H
