// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_READ_LAS_RECORDS_H
#define LIDAR_IO_READ_LAS_RECORDS_H

#include <Lidar_io/Las_header.h>
#include <Lidar_io/internal/las_record_blocks.h>
#include <Lidar_io/internal/read_las_header.h>

#include <fstream>
#include <string>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  the public header block of the LAS or LAZ file `filename`, checked (`Las_header`). Whether the
  points are compressed is the header's to say, whatever the extension.
  \throws Input_error when the file cannot be opened or its header is not one the library reads
*/
inline Las_header read_las_header(const std::string& filename) { return internal::read_las_header(filename); }

/*!
  \ingroup PkgLidarIo
  calls `sink(first, records, count)` on the point records of the LAS or LAZ file `filename` in
  their order, `count` at a time from record `first`, laid out as an uncompressed file stores them
  (`Las_header::record_length` bytes each, extra bytes included): read a few megabytes at a time, or
  decoded from LASzip's chunks (point-wise and layered, every item version LASzip writes), `threads`
  chunks at a time in parallel (0: OpenMP's default), each record decoded exactly. The blocks come in
  order and `records` is valid during the call only. Returns the file's header.
  \throws Input_error when the file is unreadable, its header or chunk table is not one the library
  reads, or a chunk cannot be decoded (the records given before stay valid)
*/
template <typename Sink>
Las_header read_las_records(const std::string& filename, const Sink& sink, unsigned int threads = 0)
{
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Input_error("cannot open the file");
  const Las_header h = internal::read_las_header(in, internal::las_file_size(filename));
  internal::for_each_las_record_block(in, h, threads, sink);
  return h;
}

} // namespace Lidar_io

#endif // LIDAR_IO_READ_LAS_RECORDS_H
