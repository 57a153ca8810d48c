// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_BINARY_PLY_POINTS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_BINARY_PLY_POINTS_H

#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/internal/check_ply_counts.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>
#include <Sigmoid_neighborhoods_readers/internal/ply_point_layout.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

inline bool is_little_endian_machine()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// The points of a binary little-endian PLY point set (ply_point_layout()), read straight from its
// records on `threads` threads: the same points, normals and labels as CGAL's point set reader gives
// in read_points_without_faces(), which reads such a file three times over, through streams. False,
// with nothing read, for any other file: those go to CGAL's readers.
inline bool read_binary_ply_points(const Input_file& file, std::vector<Oriented_point_set::Point_3>& points,
                                   std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals,
                                   std::vector<int>& labels, unsigned int threads)
{
  Ply_point_layout layout;
  if(!is_little_endian_machine() || !ply_point_layout(file, "binary_little_endian", layout))
    return false;
  check_ply_counts(file); // the records' bytes are there before they are allocated
  const std::size_t n = layout.count, stride = layout.stride;
  std::vector<unsigned char> records(n * stride);
  std::ifstream in(file.name, std::ios::binary);
  in.seekg(layout.header_end);
  in.read(reinterpret_cast<char*>(records.data()), std::streamsize(records.size()));
  if(std::size_t(in.gcount()) != records.size())
    return false; // check_ply_counts() has seen these bytes: CGAL's reader says what happened

  enum { X = Ply_point_layout::X, Y, Z, NX, NY, NZ };
  const Ply_field* fields = layout.fields;
  has_normals = layout.has_normals;
  points.resize(n);
  if(has_normals)
    normals.resize(n);
  std::vector<double> label_values(layout.has_label ? n : 0);
  const std::ptrdiff_t count = std::ptrdiff_t(n);
  auto convert = [&](std::ptrdiff_t i) {
    const unsigned char* record = records.data() + std::size_t(i) * stride;
    points[std::size_t(i)] = Oriented_point_set::Point_3(fields[X].read(record), fields[Y].read(record),
                                                         fields[Z].read(record));
    if(has_normals)
      normals[std::size_t(i)] = Oriented_point_set::Vector_3(fields[NX].read(record), fields[NY].read(record),
                                                             fields[NZ].read(record));
    if(!label_values.empty())
      label_values[std::size_t(i)] = layout.label.read(record);
  };
#ifdef _OPENMP
  // no OpenMP region for a small file: a forked child (the readers' limit tests) cannot start one
  const int team = threads == 0 ? omp_get_max_threads() : int(threads);
  if(team > 1 && count >= std::ptrdiff_t(1) << 16)
  {
#pragma omp parallel for schedule(static) num_threads(team)
    for(std::ptrdiff_t i = 0; i < count; ++i)
      convert(i);
  }
  else
#else
  (void)threads;
#endif
    for(std::ptrdiff_t i = 0; i < count; ++i)
      convert(i);
  ply_labels_of_values(label_values, labels);
  return true;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_READ_BINARY_PLY_POINTS_H
