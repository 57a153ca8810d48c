// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAS_RECORD_BLOCKS_H
#define LIDAR_IO_INTERNAL_LAS_RECORD_BLOCKS_H

// The point records of a LAS or LAZ file, block by block, as an uncompressed file stores them.

#include <Lidar_io/Input_error.h>
#include <Lidar_io/Las_header.h>
#include <Lidar_io/internal/laz/Laz_layout.h>
#include <Lidar_io/internal/laz/decode_chunks.h>
#include <Lidar_io/internal/read_las_header.h>

#include <algorithm>
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {

// Where the LASzip chunks of a compressed file lie, checked against the file.
inline laz::Layout read_laz_layout(std::istream& in, const Las_header& h)
{
  laz::Layout layout =
    laz::read_laszip_record(in, h.header_size, h.vlr_count, h.offset_to_point_data, h.record_length);
  if((layout.compressor == laz::LAYERED_CHUNKED) != h.has_extended_format())
    throw Input_error(laz::laz_error("compressor " + std::to_string(layout.compressor) + " for point data format " +
                                     std::to_string(h.point_format) + ": LASzip compresses formats 0 to 5 point "
                                     "by point (2) and formats 6 to 10 in layers (3)"));
  laz::read_chunk_table(in, h.file_size, h.offset_to_point_data, h.point_count, h.record_length, layout);
  return layout;
}

// Calls `sink(first, records, count)` on the file's point records in order, `count` at a time, as
// an uncompressed file stores them: read from an uncompressed file a few megabytes at a time, or
// decoded from a LAZ file chunk by chunk, `threads` chunks in parallel.
template <typename Sink>
void for_each_las_record_block(std::istream& in, const Las_header& h, unsigned int threads, const Sink& sink)
{
  const std::size_t n = std::size_t(h.point_count);
  if(h.compressed)
  {
    const laz::Layout layout = read_laz_layout(in, h);
    laz::for_each_decoded_chunk(in, layout, h.record_length, threads, sink);
    return;
  }
  in.seekg(std::streamoff(h.offset_to_point_data));
  const std::size_t chunk_points = (std::max)(std::size_t(1), LAS_CHUNK_BYTES / h.record_length);
  std::vector<unsigned char> chunk;
  for(std::size_t first = 0; first < n;)
  {
    const std::size_t count = (std::min)(chunk_points, n - first);
    chunk.resize(count * h.record_length);
    if(!in.read(reinterpret_cast<char*>(chunk.data()), std::streamsize(chunk.size())))
      throw Input_error(las_error("the file ends in point " + std::to_string(first + std::size_t(in.gcount()) /
                                                                                     h.record_length)));
    sink(first, chunk.data(), count);
    first += count;
  }
}

} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAS_RECORD_BLOCKS_H
