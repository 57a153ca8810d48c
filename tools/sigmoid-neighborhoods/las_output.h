// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The commands' LAS 1.4 and LAZ outputs: a LAS or LAZ input's records as they are, the results added as
// extra bytes dimensions (a record merged into an earlier one at its position gets that point's
// results), or new records (point format 6) for the other formats.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_LAS_OUTPUT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_LAS_OUTPUT_H

#include <Lidar_io/Las_output_layout.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace sigmoid_tool {

class Arguments;
struct Input_points;

// Whether `path` names a LAS output: .las, or .laz for the same compressed as LASzip does.
bool is_las_output(const std::string& path);

// Refuses a LAS output of a catalog's union (its records would come from several files); a tile's
// (--tile) is its file's records.
void refuse_las_output_of_catalog(const Arguments& args, const std::string& command);

// The records of a LAS output: those of `source` when it is a LAS or LAZ file, each with the results
// of its point (`point_of_record`, else the model's point_of_input when something was merged, else the
// record's own index), else new records of the model's points `first` ... `last - 1`.
struct Las_output_points
{
  std::string source;
  std::size_t first = 0, last = std::size_t(-1);
  const std::vector<std::size_t>* point_of_record = nullptr;
};

// The records of a LAS output of `in`: its file's, or a tile's file's with the results of their points
// in the tile with its halo (a seam duplicate: the earlier tile's point it was merged into).
Las_output_points las_output_points(const Input_points& in);

// What a command adds to each record: its dimensions, and the values of one point.
struct Las_results
{
  std::vector<Lidar_io::Las_extra_dimension> dimensions;
  // writes the values of `point` (an index into the model's points) into `record`, laid out by
  // `layout`: its added dimensions, and any field it changes (the classification)
  std::function<void(unsigned char* record, const Lidar_io::Las_output_layout& layout,
                     std::size_t point)>
    complete;
};

// Refuses, before the work, what write_las_results() would refuse of these records: a LAZ output of a
// LAS or LAZ file whose records hold wave packets (point formats 4, 5, 9, 10).
void check_las_output(const std::string& path, const Las_output_points& points);

// Writes `path` atomically: the records of `points` (a LAS or LAZ source decoded on `threads`) with
// `results`; compressed on `threads` when `path` ends in .laz. Any failure is a Usage_error.
void write_las_results(const std::string& path, const Las_output_points& points,
                       const CGAL::Sigmoid_neighborhoods::Oriented_point_set& model, const Las_results& results,
                       unsigned int threads);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_LAS_OUTPUT_H
