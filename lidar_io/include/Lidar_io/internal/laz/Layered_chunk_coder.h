// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_LAYERED_CHUNK_CODER_H
#define LIDAR_IO_INTERNAL_LAZ_LAYERED_CHUNK_CODER_H

#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/laz_items.h>
#include <Lidar_io/internal/laz/layered_items.h>
#include <Lidar_io/internal/laz/point14_items.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// A chunk of LASzip's layered compressor (compressor 3: LAS 1.4 point formats 6 to 10), decoded into
// LAS records. A chunk is, in this order:
//   - its first point, raw: a whole record as the LAS file stores it;
//   - its point count (uint32);
//   - the byte count (uint32) of every layer of every item, items in record order;
//   - the layers' bytes, in the same order.
// Every layer is an arithmetic-coded stream of its own; a layer of 0 bytes is a field that keeps its
// first value through the chunk. Nothing carries over from one chunk to the next.
class Layered_chunk_coder
{
public:
  explicit Layered_chunk_coder(const std::vector<Item>& items)
  {
    if(items.empty() || items[0].type != POINT14)
      throw Decode_error("the layered compression starts its records with a POINT14 item" +
                         (items.empty() ? std::string(", and no item is listed") : ", not " + item_name(items[0].type)));
    for(std::size_t i = 0; i < items.size(); ++i)
    {
      const Item& item = items[i];
      const std::string name = item_name(item.type) + " version " + std::to_string(item.version);
      if(item.type == WAVEPACKET14)
        throw Decode_error("the wave packets of point formats 9 and 10 (item " + name + ") are not read");
      if(item.type != POINT14 && item.type != RGB14 && item.type != RGBNIR14 && item.type != BYTE14)
        throw Decode_error("item " + name + " is not an item of LASzip's layered compression");
      // Version 4 differs from 3 only after a switch between scanner channels; no file here has it to
      // test a decoder against, so it is refused rather than guessed.
      if(item.version != 3)
        throw Decode_error("item " + name + " is not read (version 3 is)");
      if(item.type == POINT14 && i != 0)
        throw Decode_error("a second POINT14 item");
      const std::size_t expected = item.type == POINT14 ? Point14_record::size
                                   : item.type == RGB14  ? 6
                                   : item.type == RGBNIR14 ? 8
                                                           : item.size;
      if(item.size != expected || item.size == 0)
        throw Decode_error("item " + name + " of " + std::to_string(item.size) + " bytes" +
                           (item.size == 0 ? "" : ", not " + std::to_string(expected)));

      Part part;
      part.type = item.type;
      part.offset = m_record_length;
      part.first_layer = m_layer_names.size();
      if(item.type == POINT14)
      {
        m_point.emplace();
        for(std::size_t l = 0; l < Point14_coder::LAYER_COUNT; ++l)
          m_layer_names.push_back("POINT14 " + std::string(Point14_coder::layer_name(l)));
      }
      else if(item.type == BYTE14)
      {
        part.index = m_bytes.size();
        m_bytes.emplace_back(item.size);
        for(std::size_t l = 0; l < item.size; ++l)
          m_layer_names.push_back("BYTE14 byte " + std::to_string(l));
      }
      else
      {
        const bool nir = item.type == RGBNIR14;
        part.index = m_colors.size();
        m_colors.emplace_back(nir);
        m_layer_names.push_back(item_name(item.type) + " RGB");
        if(nir)
          m_layer_names.push_back("RGBNIR14 NIR");
      }
      if(i != 0)
      {
        if(item.type == BYTE14)
          for(std::size_t b = 0; b < item.size; b += BYTES_PER_TASK)
            m_tasks.push_back({m_parts.size(), b, (std::min)(std::size_t(item.size), b + BYTES_PER_TASK)});
        else
          m_tasks.push_back({m_parts.size(), 0, 0});
        m_parts.push_back(part);
      }
      else
        m_tasks.push_back({NO_PART, 0, 0});
      m_record_length += item.size;
    }
    m_layers.resize(m_layer_names.size());
  }

  std::size_t record_length() const { return m_record_length; }

  // Decodes the chunk [begin, end) of `count` points into out[0, count * record_length()).
  void decode(const unsigned char* begin, const unsigned char* end, std::size_t count, unsigned char* out)
  {
    if(count == 0)
      throw Decode_error("a chunk of no points");
    const std::size_t bytes = std::size_t(end - begin);
    if(bytes < m_record_length + 4)
      throw Decode_error("a chunk of " + std::to_string(bytes) + " bytes, too few for its first point (" +
                         std::to_string(m_record_length) + " bytes) and its point count");
    std::memcpy(out, begin, m_record_length);
    const unsigned char* at = begin + m_record_length;
    const std::uint32_t stored = load_little_endian<std::uint32_t>(at);
    at += 4;
    if(stored != count)
      throw Decode_error("the chunk says it holds " + std::to_string(stored) + " points, the chunk table " +
                         std::to_string(count));

    const std::size_t layer_count = m_layers.size();
    if(std::size_t(end - at) / 4 < layer_count)
      throw Decode_error("the chunk ends inside its " + std::to_string(layer_count) + " layer sizes");
    const unsigned char* data = at + 4 * layer_count;
    for(std::size_t l = 0; l < layer_count; ++l)
    {
      const std::uint32_t size = load_little_endian<std::uint32_t>(at + 4 * l);
      const std::size_t left = std::size_t(end - data);
      if(size > left)
        throw Decode_error("a layer size that overruns the chunk: the " + m_layer_names[l] + " layer of " +
                           std::to_string(size) + " bytes, " + std::to_string(left) + " left");
      m_layers[l].begin = data;
      m_layers[l].end = data + size;
      data += size;
    }
    if(count == 1)
      return; // the raw first point is all; its layers (empty coders) hold nothing to decode

    const unsigned first_channel = m_point->start(out, m_layers.data());
    for(const Part& p : m_parts)
    {
      if(p.type == BYTE14)
        m_bytes[p.index].start(out + p.offset, m_layers.data() + p.first_layer, first_channel);
      else
        m_colors[p.index].start(out + p.offset, m_layers.data() + p.first_layer, first_channel);
    }

    unsigned char* record = out;
    for(std::size_t i = 1; i < count; ++i)
    {
      record += m_record_length;
      const unsigned channel = m_point->decode(record);
      for(const Part& p : m_parts)
      {
        if(p.type == BYTE14)
          m_bytes[p.index].decode(record + p.offset, channel);
        else
          m_colors[p.index].decode(record + p.offset, channel);
      }
    }
  }

  // Encoding what decode() reads back splits into tasks that share nothing, to run in parallel:
  // POINT14's nine layers, each colour item, and the extra bytes by groups of layers (an item after
  // POINT14 follows the scanner channel of each record, which the record holds); assemble() joins them.
  std::size_t encode_task_count() const { return m_tasks.size(); }

  // Encodes task `t` of the chunk of `count` (>= 1) records: its layers' bytes to `layers` (one per
  // layer of the chunk, empty for a layer that codes no change).
  void encode_task(std::size_t t, const unsigned char* records, std::size_t count,
                   std::vector<std::vector<unsigned char>>& layers)
  {
    CGAL_precondition(count >= 1 && layers.size() == m_layers.size());
    const Task& task = m_tasks[t];
    if(task.part == NO_PART)
    {
      m_point->start_encoding(records);
      for(std::size_t i = 1; i < count; ++i)
        m_point->encode(records + i * m_record_length);
      m_point->finish_encoding(layers.data());
      return;
    }
    const Part& p = m_parts[task.part];
    const unsigned char* record = records;
    auto channel = [](const unsigned char* r) { return (unsigned(r[15]) >> 4) & 3u; };
    if(p.type == BYTE14)
    {
      Byte14_coder& bytes = m_bytes[p.index];
      bytes.start_encoding(record + p.offset, channel(record), task.begin, task.end);
      for(std::size_t i = 1; i < count; ++i)
      {
        record += m_record_length;
        bytes.encode(record + p.offset, channel(record));
      }
      bytes.finish_encoding(layers.data() + p.first_layer + task.begin);
      return;
    }
    Rgb14_coder& colors = m_colors[p.index];
    colors.start_encoding(record + p.offset, channel(record));
    for(std::size_t i = 1; i < count; ++i)
    {
      record += m_record_length;
      colors.encode(record + p.offset, channel(record));
    }
    colors.finish_encoding(layers.data() + p.first_layer);
  }

  // Appends the chunk whose tasks gave `layers`: its first record, its count, the layers' sizes, their bytes.
  void assemble(const unsigned char* records, std::size_t count, const std::vector<std::vector<unsigned char>>& layers,
                std::vector<unsigned char>& out) const
  {
    CGAL_precondition(count >= 1 && count <= 0xFFFFFFFFu && layers.size() == m_layers.size());
    out.insert(out.end(), records, records + m_record_length);
    unsigned char number[4];
    store_little_endian<std::uint32_t>(number, std::uint32_t(count));
    out.insert(out.end(), number, number + 4);
    for(const std::vector<unsigned char>& layer : layers)
    {
      store_little_endian<std::uint32_t>(number, std::uint32_t(layer.size()));
      out.insert(out.end(), number, number + 4);
    }
    for(const std::vector<unsigned char>& layer : layers)
      out.insert(out.end(), layer.begin(), layer.end());
  }

  std::size_t layer_count() const { return m_layers.size(); }

private:
  // An item after POINT14, and where its bytes and layers lie.
  struct Part
  {
    std::uint16_t type = 0;
    std::size_t offset = 0, index = 0, first_layer = 0;
  };

  std::optional<Point14_coder> m_point;
  std::vector<Rgb14_coder> m_colors;
  std::vector<Byte14_coder> m_bytes;
  std::vector<Part> m_parts;
  std::vector<std::string> m_layer_names; // for the messages
  std::vector<Layer_bytes> m_layers;      // this chunk's, one per layer name
  // An encoding task: POINT14 (part NO_PART) or an item after it, for BYTE14 its bytes [begin, end).
  struct Task
  {
    std::size_t part = 0, begin = 0, end = 0;
  };
  static constexpr std::size_t NO_PART = std::size_t(-1);
  static constexpr std::size_t BYTES_PER_TASK = 8;
  std::vector<Task> m_tasks;
  std::size_t m_record_length = 0;
};

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_LAYERED_CHUNK_CODER_H
