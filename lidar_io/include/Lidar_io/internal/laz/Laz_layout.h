// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_LAZ_LAYOUT_H
#define LIDAR_IO_INTERNAL_LAZ_LAZ_LAYOUT_H

#include <Lidar_io/little_endian.h>
#include <Lidar_io/Input_error.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/integer_coder.h>
#include <Lidar_io/internal/laz/laz_items.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// Where the compressed points of a LAZ file lie, checked against the file before anything is sized
// to it. LAZ specification 1.4 (LASzip): a variable-length record (user "laszip encoded", record 22204)
// names the compressor, the chunk size and the items of a point record; the point data starts with
// the 64-bit offset of the chunk table, then the chunks one after the other; the chunk table holds,
// arithmetic-coded, each chunk's byte count and, with variable chunks (COPC), its point count.
enum Compressor : std::uint16_t
{
  NO_COMPRESSION = 0,
  POINTWISE = 1,         // one stream for all points (LASzip 1.x): refused
  POINTWISE_CHUNKED = 2, // point formats 0 to 5
  LAYERED_CHUNKED = 3    // point formats 6 to 10
};

constexpr std::uint16_t LASZIP_RECORD_ID = 22204;
constexpr std::uint32_t VARIABLE_CHUNK_SIZE = 0xFFFFFFFFu;
constexpr std::size_t VLR_HEADER_BYTES = 54;
// A chunk's points per compressed byte, at most. Every point costs at least one symbol of an adaptive
// model whose counts never let a symbol's probability pass 1 - 63/32768 (LASzip's models halve their
// counts at 2^15 and keep each at 1 or more), about 0.003 bit: below 2,900 points per byte. A chunk
// that claims more is a lie, refused before its records are allocated.
constexpr std::uint64_t MAX_POINTS_PER_CHUNK_BYTE = 4096;

struct Layout
{
  Compressor compressor = NO_COMPRESSION;
  std::vector<Item> items;
  std::uint32_t chunk_size = 0;             // points per chunk, or VARIABLE_CHUNK_SIZE
  std::vector<std::uint64_t> chunk_starts;  // chunks + 1 file offsets: chunk c is [starts[c], starts[c + 1])
  std::vector<std::uint64_t> chunk_firsts;  // chunks + 1 point indices: chunk c holds [firsts[c], firsts[c + 1])

  std::size_t chunk_count() const { return chunk_starts.empty() ? 0 : chunk_starts.size() - 1; }
};

inline std::string laz_error(const std::string& reason) { return "cannot decode the file as laz (" + reason + ")"; }

inline void read_exactly(std::istream& in, std::uint64_t offset, unsigned char* out, std::size_t n, const char* what)
{
  in.clear();
  in.seekg(std::streamoff(offset));
  if(!in.read(reinterpret_cast<char*>(out), std::streamsize(n)))
    throw Input_error(laz_error(std::string("read error in ") + what));
}

// The items, compressor and chunk size of the LASzip record among the `vlr_count` records that
// follow the header, all within [header_size, offset_to_point_data).
inline Layout read_laszip_record(std::istream& in, std::uint32_t header_size, std::uint32_t vlr_count,
                                 std::uint32_t offset_to_point_data, std::size_t record_length)
{
  std::uint64_t at = header_size;
  for(std::uint32_t v = 0; v < vlr_count; ++v)
  {
    unsigned char h[VLR_HEADER_BYTES];
    if(at + VLR_HEADER_BYTES > offset_to_point_data)
      break; // records that overrun the point data are not records; the LASzip one is then missing
    read_exactly(in, at, h, VLR_HEADER_BYTES, "a variable-length record");
    const std::uint16_t record_id = std::uint16_t(load_little_endian(h + 18, 2));
    const std::uint16_t length = std::uint16_t(load_little_endian(h + 20, 2));
    const bool laszip = record_id == LASZIP_RECORD_ID && std::strncmp(reinterpret_cast<const char*>(h + 2),
                                                                     "laszip encoded", 16) == 0;
    if(laszip)
    {
      if(at + VLR_HEADER_BYTES + length > offset_to_point_data || length < 34)
        throw Input_error(laz_error("its LASzip record of " + std::to_string(length) +
                                    " bytes overruns the point data or is shorter than 34 bytes"));
      std::vector<unsigned char> d(length);
      read_exactly(in, at + VLR_HEADER_BYTES, d.data(), length, "the LASzip record");
      Layout layout;
      const std::uint16_t compressor = std::uint16_t(load_little_endian(d.data(), 2));
      layout.chunk_size = std::uint32_t(load_little_endian(d.data() + 12, 4));
      const std::size_t item_count = std::size_t(load_little_endian(d.data() + 32, 2));
      if(34 + 6 * item_count > length)
        throw Input_error(laz_error("its LASzip record lists " + std::to_string(item_count) +
                                    " items in " + std::to_string(length) + " bytes"));
      std::size_t sum = 0;
      for(std::size_t i = 0; i < item_count; ++i)
      {
        Item item;
        item.type = std::uint16_t(load_little_endian(d.data() + 34 + 6 * i, 2));
        item.size = std::uint16_t(load_little_endian(d.data() + 36 + 6 * i, 2));
        item.version = std::uint16_t(load_little_endian(d.data() + 38 + 6 * i, 2));
        sum += item.size;
        layout.items.push_back(item);
      }
      if(sum != record_length)
        throw Input_error(laz_error("its LASzip items make records of " + std::to_string(sum) +
                                    " bytes, the header says " + std::to_string(record_length)));
      if(compressor != POINTWISE_CHUNKED && compressor != LAYERED_CHUNKED)
        throw Input_error(laz_error(compressor == POINTWISE
                                      ? "LASzip's unchunked compressor of its first versions is not read: "
                                        "recompress the file with a current LASzip"
                                      : "compressor " + std::to_string(compressor) + " is not a LASzip compressor"));
      layout.compressor = Compressor(compressor);
      if(layout.chunk_size == 0)
        throw Input_error(laz_error("chunks of 0 points"));
      return layout;
    }
    at += VLR_HEADER_BYTES + length;
  }
  throw Input_error(laz_error("compressed points without the LASzip record (user 'laszip encoded', record 22204) "
                              "that says how"));
}

// The chunk table of `layout` read and checked: every chunk within [offset_to_point_data + 8, the
// table), none empty, its points within the bound above, and `point_count` points in all.
inline void read_chunk_table(std::istream& in, std::uint64_t file_size, std::uint32_t offset_to_point_data,
                             std::uint64_t point_count, std::size_t record_length, Layout& layout)
{
  const std::uint64_t first_chunk = std::uint64_t(offset_to_point_data) + 8;
  if(first_chunk > file_size)
    throw Input_error(laz_error("the file ends before the offset of its chunk table"));
  unsigned char b[8];
  read_exactly(in, offset_to_point_data, b, 8, "the offset of the chunk table");
  std::uint64_t table = load_little_endian(b, 8);
  if(table == (std::numeric_limits<std::uint64_t>::max)()) // written last, by a writer that could not seek back
  {
    if(file_size < first_chunk + 8)
      throw Input_error(laz_error("the file ends before the offset of its chunk table"));
    read_exactly(in, file_size - 8, b, 8, "the offset of the chunk table at the end of the file");
    table = load_little_endian(b, 8);
  }
  if(table == offset_to_point_data)
    throw Input_error(laz_error("no chunk table: its writer stopped before writing it"));
  if(table < first_chunk)
    throw Input_error(laz_error("a chunk table at byte " + std::to_string(table) + ", before the first chunk at byte " +
                                std::to_string(first_chunk)));
  if(table > file_size || file_size - table < 8)
    throw Input_error(laz_error("a chunk table at byte " + std::to_string(table) + ", past the end of a file of " +
                                std::to_string(file_size) + " bytes"));
  read_exactly(in, table, b, 8, "the chunk table");
  const std::uint32_t version = std::uint32_t(load_little_endian(b, 4));
  const std::uint64_t chunks = load_little_endian(b + 4, 4);
  if(version != 0)
    throw Input_error(laz_error("chunk table version " + std::to_string(version) + ", expected 0"));
  const bool variable = layout.chunk_size == VARIABLE_CHUNK_SIZE;
  // Each chunk holds its first point raw: a record (a chunk of one point holds nothing else).
  const std::uint64_t most_chunks = (table - first_chunk) / record_length;
  if(chunks > most_chunks)
    throw Input_error(laz_error("a chunk table of " + std::to_string(chunks) + " chunks, more than the " +
                                std::to_string(table - first_chunk) + " bytes before it can hold"));
  if(!variable && chunks != (point_count + layout.chunk_size - 1) / layout.chunk_size)
    throw Input_error(laz_error("a chunk table of " + std::to_string(chunks) + " chunks for " +
                                std::to_string(point_count) + " points in chunks of " +
                                std::to_string(layout.chunk_size)));

  layout.chunk_starts.assign(1, first_chunk);
  layout.chunk_firsts.assign(1, 0);
  if(chunks == 0)
  {
    if(point_count != 0)
      throw Input_error(laz_error("an empty chunk table for " + std::to_string(point_count) + " points"));
    return;
  }
  // Two 32-bit numbers a chunk take at most 10 coded bytes; what follows the table (EVLRs) is not read.
  const std::uint64_t table_bytes = file_size - table - 8;
  std::vector<unsigned char> coded(std::size_t((std::min<std::uint64_t>)(table_bytes, 40 * chunks + 64)));
  read_exactly(in, table + 8, coded.data(), coded.size(), "the chunk table");

  layout.chunk_starts.reserve(std::size_t(chunks) + 1);
  layout.chunk_firsts.reserve(std::size_t(chunks) + 1);
  try
  {
    Arithmetic_decoder decoder;
    decoder.init(coded.data(), coded.data() + coded.size());
    Integer_coder sizes(32, 2);
    sizes.init();
    std::uint32_t last_points = 0, last_bytes = 0;
    for(std::uint64_t c = 0; c < chunks; ++c)
    {
      std::uint64_t points = 0;
      if(variable)
        points = last_points = std::uint32_t(sizes.decompress(decoder, std::int32_t(last_points), 0));
      else
        points = (std::min<std::uint64_t>)(layout.chunk_size, point_count - c * layout.chunk_size);
      const std::uint64_t bytes = last_bytes = std::uint32_t(sizes.decompress(decoder, std::int32_t(last_bytes), 1));
      const std::uint64_t start = layout.chunk_starts.back();
      const std::string chunk = "chunk " + std::to_string(c) + " of " + std::to_string(chunks);
      if(bytes < record_length || bytes > table - start)
        throw Input_error(laz_error("the chunk table gives " + chunk + " " + std::to_string(bytes) +
                                    " bytes from byte " + std::to_string(start) + ": " +
                                    (bytes < record_length ? "fewer than a point takes"
                                                               : "beyond the chunk table at byte " + std::to_string(table))));
      if(points == 0 || points > MAX_POINTS_PER_CHUNK_BYTE * bytes ||
         points > point_count - layout.chunk_firsts.back())
        throw Input_error(laz_error("the chunk table gives " + chunk + " " + std::to_string(points) + " points in " +
                                    std::to_string(bytes) + " bytes, " +
                                    (points == 0 ? "none"
                                     : points > point_count - layout.chunk_firsts.back()
                                       ? "more than the header's " + std::to_string(point_count) + " in all"
                                       : "more than " + std::to_string(MAX_POINTS_PER_CHUNK_BYTE) +
                                           " per byte, which no LASzip chunk holds")));
      layout.chunk_starts.push_back(start + bytes);
      layout.chunk_firsts.push_back(layout.chunk_firsts.back() + points);
    }
  }
  catch(const Decode_error& e)
  {
    throw Input_error(laz_error(std::string("its chunk table does not decode: ") + e.what()));
  }
  if(layout.chunk_firsts.back() != point_count)
    throw Input_error(laz_error("its chunks hold " + std::to_string(layout.chunk_firsts.back()) +
                                " points, the header says " + std::to_string(point_count)));
}

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_LAZ_LAYOUT_H
