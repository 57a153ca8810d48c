// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_DECODE_CHUNKS_H
#define LIDAR_IO_INTERNAL_LAZ_DECODE_CHUNKS_H

#include <Lidar_io/Input_error.h>
#include <Lidar_io/internal/laz/Laz_layout.h>
#include <Lidar_io/internal/laz/Layered_chunk_coder.h>
#include <Lidar_io/internal/laz/Pointwise_chunk_coder.h>
#include <Lidar_io/concurrency.h>
#include <Lidar_io/internal/parallel.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// The coder of a file's compressor, both directions; one per thread, reused chunk after chunk.
class Chunk_coder
{
public:
  // Decode_error for items the compressor does not read (wave packets, unknown versions).
  Chunk_coder(Compressor compressor, const std::vector<Item>& items)
  {
    if(compressor == POINTWISE_CHUNKED)
      m_pointwise.emplace(items);
    else
      m_layered.emplace(items);
  }
  explicit Chunk_coder(const Layout& layout) : Chunk_coder(layout.compressor, layout.items) {}

  // Encoding a chunk of records, in tasks that run in parallel (one for a point-wise chunk, its single
  // coder), each giving some of the chunk's `encode_layer_count()` layers, then assembled.
  std::size_t encode_task_count() const { return m_pointwise ? 1 : m_layered->encode_task_count(); }
  std::size_t encode_layer_count() const { return m_pointwise ? 1 : m_layered->layer_count(); }
  void encode_task(std::size_t t, const unsigned char* records, std::size_t count,
                   std::vector<std::vector<unsigned char>>& layers)
  {
    if(m_pointwise)
    {
      layers[0].clear();
      m_pointwise->encode(records, count, layers[0]);
    }
    else
      m_layered->encode_task(t, records, count, layers);
  }
  void assemble(const unsigned char* records, std::size_t count, const std::vector<std::vector<unsigned char>>& layers,
                std::vector<unsigned char>& out) const
  {
    if(m_pointwise)
      out.insert(out.end(), layers[0].begin(), layers[0].end());
    else
      m_layered->assemble(records, count, layers, out);
  }

  void decode(const unsigned char* begin, const unsigned char* end, std::size_t count, unsigned char* out)
  {
    if(m_pointwise)
      m_pointwise->decode(begin, end, count, out);
    else
      m_layered->decode(begin, end, count, out);
  }

private:
  std::optional<Pointwise_chunk_coder> m_pointwise;
  std::optional<Layered_chunk_coder> m_layered;
};

// Calls `sink(first_point, records, count)` for every chunk of `layout`, in the file's order, with its
// `count` records as an uncompressed LAS file stores them. The chunks are decoded `threads` at a time
// (0: the OpenMP or TBB default) in parallel, each on its own bytes, so memory holds one chunk per
// thread beyond what `sink` keeps, and the records are the same for any thread count. A chunk that
// does not decode is an Input_error naming it.
template <typename ConcurrencyTag = Parallel_if_available_tag, typename Sink>
void for_each_decoded_chunk(std::istream& in, const Layout& layout, std::size_t record_length, unsigned int threads,
                            const Sink& sink)
{
  try
  {
    Chunk_coder check(layout); // refuses unread items here, once, before any chunk
  }
  catch(const Decode_error& e)
  {
    throw Input_error(laz_error(e.what()));
  }
  const std::size_t chunks = layout.chunk_count();
  const std::size_t batch = thread_count<ConcurrencyTag>(threads);
  std::vector<unsigned char> coded;
  std::vector<std::vector<unsigned char>> records(batch);
  std::optional<Chunk_coder> single;
  std::vector<std::string> errors;
  for(std::size_t first = 0; first < chunks; first += batch)
  {
    const std::size_t n = (std::min)(batch, chunks - first);
    const std::uint64_t from = layout.chunk_starts[first], to = layout.chunk_starts[first + n];
    coded.resize(std::size_t(to - from));
    read_exactly(in, from, coded.data(), coded.size(), "a chunk");
    for(std::size_t i = 0; i < n; ++i)
      records[i].resize(std::size_t(layout.chunk_firsts[first + i + 1] - layout.chunk_firsts[first + i]) *
                        record_length);
    const auto decode = [&](std::size_t i, Chunk_coder& decoder) {
      const std::size_t c = first + i;
      const std::uint64_t begin = layout.chunk_starts[c], end = layout.chunk_starts[c + 1];
      try
      {
        decoder.decode(coded.data() + (begin - from), coded.data() + (end - from),
                       std::size_t(layout.chunk_firsts[c + 1] - layout.chunk_firsts[c]), records[i].data());
      }
      catch(const Decode_error& e)
      {
        // kept, not thrown: a parallel loop skips the indices it has not begun once one throws, so
        // the first damaged chunk of a batch is reported whatever the threads do
        errors[i] = "chunk " + std::to_string(c) + " of " + std::to_string(chunks) + ", bytes " +
                    std::to_string(begin) + " to " + std::to_string(end) + ": " + e.what();
      }
    };
    errors.assign(n, std::string());
    if(n == 1) // the last chunk, or a file of one: no threads to wake
      decode(0, single ? *single : single.emplace(layout));
    else
      for_each_index<ConcurrencyTag>(n, threads, [&] { return Chunk_coder(layout); }, decode, 1);
    for(const std::string& error : errors)
      if(!error.empty())
        throw Input_error(laz_error(error));
    for(std::size_t i = 0; i < n; ++i)
      sink(std::size_t(layout.chunk_firsts[first + i]), records[i].data(),
           std::size_t(layout.chunk_firsts[first + i + 1] - layout.chunk_firsts[first + i]));
  }
}

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_DECODE_CHUNKS_H
