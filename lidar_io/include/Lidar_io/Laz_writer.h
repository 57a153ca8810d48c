// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LAZ_WRITER_H
#define LIDAR_IO_LAZ_WRITER_H

#include <Lidar_io/Las_writer.h>
#include <Lidar_io/internal/laz/decode_chunks.h>
#include <Lidar_io/internal/laz/encode_chunks.h>
#include <Lidar_io/concurrency.h>
#include <Lidar_io/internal/parallel.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ios>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  writes a LAZ file: a LAS 1.4 file laid out by a `Las_output_layout` whose point records are
  compressed as LASzip 3.4 compresses them, so that LASzip, PDAL, laz-perf, laz-rs and this library's
  own reader decode them. Point formats 0 to 3 take LASzip's point-wise chunked items (version 2),
  6 to 8 its layered chunked items (version 3), and the bytes after a format's fields (the extra
  bytes dimensions) are compressed too; the wave packets of formats 4, 5, 9 and 10 are refused.

  The records given to `write()` are cut into chunks of `chunk_size` (LASzip's 50,000 by default),
  compressed `threads` chunks at a time in parallel (0: the OpenMP or TBB default; the items of a
  layered chunk and groups of its extra bytes are compressed apart, in parallel too) and written in
  order; the bytes of the file are the same for any thread count, and a chunk's bytes those LASzip
  writes for the same records. `close()` writes the chunk table, the EVLRs and the header again
  (counts, counts by return and bounding box as `Las_writer` writes them; the point format with bit
  7 set, the LASzip record added to the VLRs). The stream must be seekable (a file). Memory: the
  records of one batch of chunks and their compressed bytes, about `threads` x `chunk_size` records.
  A failed write throws `std::ios_base::failure`.
  \tparam ConcurrencyTag `Parallel_if_available_tag` (default) or `Sequential_tag`
*/
template <typename ConcurrencyTag = Parallel_if_available_tag>
class Laz_writer
{
public:
  /// writes the header and the VLRs of `layout` (with the LASzip record) to `out`
  /// \throws std::invalid_argument for a point format with wave packets, or a chunk size of 0
  Laz_writer(std::ostream& out, Las_output_layout layout, unsigned int threads = 0, std::uint32_t chunk_size = 50000)
    : m_out(out), m_layout(std::move(layout)), m_threads(threads), m_chunk_size(chunk_size)
  {
    if(chunk_size == 0)
      throw std::invalid_argument("LAZ: chunks of 0 points");
    m_items = internal::laz::laz_items_for(m_layout.point_format, m_layout.record_length);
    m_compressor = m_items[0].type == internal::laz::POINT14 ? internal::laz::LAYERED_CHUNKED
                                                             : internal::laz::POINTWISE_CHUNKED;
    add_las_vlr(m_layout, "laszip encoded", internal::laz::LASZIP_RECORD_ID, "LASzip 3.4 r3 compressed points",
                internal::laz::laszip_record_payload(m_items, m_chunk_size));
    write_header(0);
    m_out.write(reinterpret_cast<const char*>(m_layout.vlrs.data()), std::streamsize(m_layout.vlrs.size()));
    const unsigned char no_table_yet[8] = {};
    m_out.write(reinterpret_cast<const char*>(no_table_yet), 8);
    check("the header");
    m_batch = internal::thread_count<ConcurrencyTag>(threads);
  }

  /// the layout written (with the LASzip record among its VLRs)
  const Las_output_layout& layout() const { return m_layout; }

  /// adds `count` records of `layout().record_length` bytes each, in order; whole batches of chunks
  /// are compressed and written
  void write(const unsigned char* records, std::size_t count)
  {
    const std::size_t length = m_layout.record_length;
    for(std::size_t i = 0; i < count; ++i)
      m_summary.add(records + i * length, m_layout.has_extended_format());
    m_pending.insert(m_pending.end(), records, records + count * length);
    const std::size_t batch_records = m_batch * std::size_t(m_chunk_size);
    if(m_pending.size() >= batch_records * length)
    {
      const std::size_t whole = m_pending.size() / (batch_records * length) * batch_records;
      compress(whole);
    }
  }

  /// what the records written so far sum up to
  const Las_point_summary& summary() const { return m_summary; }

  /// compresses the last records, writes the chunk table, the EVLRs and the header; the file is complete
  void close()
  {
    compress(m_pending.size() / m_layout.record_length);
    const std::uint64_t table = std::uint64_t(m_out.tellp());
    const std::vector<unsigned char> coded = internal::laz::encode_chunk_table(m_chunk_bytes);
    m_out.write(reinterpret_cast<const char*>(coded.data()), std::streamsize(coded.size()));
    m_out.write(reinterpret_cast<const char*>(m_layout.evlrs.data()), std::streamsize(m_layout.evlrs.size()));
    const std::streampos end = m_out.tellp();
    m_out.seekp(0);
    const std::uint64_t point_data = Las_output_layout::HEADER_BYTES + m_layout.vlrs.size();
    write_header(table + coded.size() - point_data);
    m_out.seekp(std::streamoff(point_data));
    unsigned char at[8];
    store_little_endian<std::uint64_t>(at, table);
    m_out.write(reinterpret_cast<const char*>(at), 8);
    m_out.seekp(end);
    check("the header and the chunk table");
  }

private:
  // Compresses the first `count` pending records, in chunks, `m_batch` chunks at a time, each chunk in
  // its coder's tasks (layered chunks: POINT14, the colours, groups of extra bytes), all of a batch's
  // tasks in parallel; then writes them.
  void compress(std::size_t count)
  {
    const std::size_t length = m_layout.record_length;
    const std::size_t chunks = (count + m_chunk_size - 1) / m_chunk_size;
    internal::laz::Chunk_coder& shape = m_single ? *m_single : m_single.emplace(m_compressor, m_items);
    const std::size_t tasks = shape.encode_task_count();
    for(std::size_t first = 0; first < chunks; first += m_batch)
    {
      const std::size_t n = (std::min)(m_batch, chunks - first);
      m_layers.resize((std::max)(m_layers.size(), n));
      for(std::size_t i = 0; i < n; ++i)
        m_layers[i].resize(shape.encode_layer_count());
      auto records_of = [&](std::size_t i) { return (std::min)(std::size_t(m_chunk_size), count - (first + i) * m_chunk_size); };
      const auto encode = [&](std::size_t task, internal::laz::Chunk_coder& coder) {
        const std::size_t i = task / tasks;
        coder.encode_task(task % tasks, m_pending.data() + (first + i) * m_chunk_size * length, records_of(i), m_layers[i]);
      };
      if(n * tasks == 1)
        encode(0, shape);
      else
        internal::for_each_index<ConcurrencyTag>(
          n * tasks, m_threads, [&] { return internal::laz::Chunk_coder(m_compressor, m_items); }, encode, 1);
      for(std::size_t i = 0; i < n; ++i)
      {
        m_chunk.clear();
        shape.assemble(m_pending.data() + (first + i) * m_chunk_size * length, records_of(i), m_layers[i], m_chunk);
        m_out.write(reinterpret_cast<const char*>(m_chunk.data()), std::streamsize(m_chunk.size()));
        m_chunk_bytes.push_back(m_chunk.size());
      }
      check("the compressed point records");
    }
    m_pending.erase(m_pending.begin(), m_pending.begin() + std::ptrdiff_t(count * length));
  }

  void check(const char* what)
  {
    if(!m_out)
      throw std::ios_base::failure(std::string("cannot write ") + what + " of the LAZ file");
  }

  void write_header(std::uint64_t point_bytes)
  {
    const auto h = internal::las_header_bytes(m_layout, m_summary, point_bytes, m_layout.point_format | 0x80u);
    m_out.write(reinterpret_cast<const char*>(h.data()), std::streamsize(h.size()));
  }

  std::ostream& m_out;
  Las_output_layout m_layout;
  unsigned int m_threads;
  std::uint32_t m_chunk_size;
  std::size_t m_batch = 1;
  std::vector<internal::laz::Item> m_items;
  internal::laz::Compressor m_compressor = internal::laz::POINTWISE_CHUNKED;
  Las_point_summary m_summary;
  std::vector<unsigned char> m_pending;           // records not compressed yet
  std::vector<std::vector<std::vector<unsigned char>>> m_layers; // a batch's chunks' layers
  std::vector<unsigned char> m_chunk; // one chunk assembled
  std::optional<internal::laz::Chunk_coder> m_single; // the tasks' shape, and the coder of a lone task
  std::vector<std::uint64_t> m_chunk_bytes;
};

} // namespace Lidar_io

#endif // LIDAR_IO_LAZ_WRITER_H
