// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_POINTWISE_CHUNK_CODER_H
#define LIDAR_IO_INTERNAL_LAZ_POINTWISE_CHUNK_CODER_H

#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/laz_items.h>
#include <Lidar_io/internal/laz/pointwise_items.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// LASzip's point-wise chunked compression (compressor 2, LAS point formats 0 to 5), items of version 2.
// In a chunk the first record is stored raw; every item then predicts its next value from the record
// before and codes what differs, all items sharing one arithmetic coder, record after record, and
// the coder's closing bytes end the chunk (even a chunk of one record has them).
class Pointwise_chunk_coder
{
public:
  // Refuses, with Decode_error, any item but POINT10, GPSTIME11, RGB12 and BYTE of version 2, and
  // those of another size than their type's.
  explicit Pointwise_chunk_coder(const std::vector<Item>& items)
  {
    for(const Item& item : items)
    {
      const std::string name = "item " + item_name(item.type) + " version " + std::to_string(item.version);
      const bool known = item.type == POINT10 || item.type == GPSTIME11 || item.type == RGB12 || item.type == BYTE;
      if(item.type == WAVEPACKET13)
        throw Decode_error("the wave packets of point formats 4 and 5 (" + name + ") are not read");
      if(!known || item.version != 2)
        throw Decode_error(name + " is not read" + (known ? " (version 2 is)" : ""));
      std::size_t expected = item.size;
      Step step{Item_type(item.type), 0, m_record_length, item.size};
      switch(item.type)
      {
      case POINT10:
        expected = pointwise::Point10_coder::SIZE;
        step.index = m_points.size();
        m_points.emplace_back();
        break;
      case GPSTIME11:
        expected = pointwise::Gps_time11_coder::SIZE;
        step.index = m_times.size();
        m_times.emplace_back();
        break;
      case RGB12:
        expected = pointwise::Rgb12_coder::SIZE;
        step.index = m_colours.size();
        m_colours.emplace_back();
        break;
      default: // BYTE
        if(item.size == 0)
          throw Decode_error(name + " has 0 bytes");
        step.index = m_bytes.size();
        m_bytes.emplace_back(item.size);
        break;
      }
      if(item.size != expected)
        throw Decode_error(name + " has " + std::to_string(item.size) + " bytes, not " + std::to_string(expected));
      m_steps.push_back(step);
      m_record_length += item.size;
    }
  }

  std::size_t record_length() const { return m_record_length; }

  // Decodes the `count` (>= 1) records of the chunk [begin, end) into out[0, count * record_length()).
  void decode(const unsigned char* begin, const unsigned char* end, std::size_t count, unsigned char* out)
  {
    CGAL_precondition(count >= 1);
    if(std::size_t(end - begin) < m_record_length)
      throw Decode_error("the chunk of " + std::to_string(end - begin) + " bytes is shorter than its first record of " +
                         std::to_string(m_record_length) + " bytes");
    std::memcpy(out, begin, m_record_length);
    init_items(out);
    if(count == 1)
      return; // the coder's bytes are not needed
    m_coder.init(begin + m_record_length, end);

    // The common records (a POINT10 item first, then at most one of each other) take a loop of
    // their own, without the dispatch on item types.
    if(is_simple())
    {
      pointwise::Point10_coder& point = m_points[0];
      pointwise::Gps_time11_coder* time = m_times.empty() ? nullptr : &m_times[0];
      pointwise::Rgb12_coder* colour = m_colours.empty() ? nullptr : &m_colours[0];
      pointwise::Byte_coder* bytes = m_bytes.empty() ? nullptr : &m_bytes[0];
      const std::size_t time_at = time ? offset_of(GPSTIME11) : 0;
      const std::size_t colour_at = colour ? offset_of(RGB12) : 0;
      const std::size_t bytes_at = bytes ? offset_of(BYTE) : 0;
      for(std::size_t p = 1; p < count; ++p)
      {
        unsigned char* record = out + p * m_record_length;
        point.decode(m_coder, record);
        if(time)
          time->decode(m_coder, record + time_at);
        if(colour)
          colour->decode(m_coder, record + colour_at);
        if(bytes)
          bytes->decode(m_coder, record + bytes_at);
      }
      return;
    }
    for(std::size_t p = 1; p < count; ++p)
    {
      unsigned char* record = out + p * m_record_length;
      for(const Step& s : m_steps)
      {
        unsigned char* item = record + s.offset;
        switch(s.type)
        {
        case POINT10: m_points[s.index].decode(m_coder, item); break;
        case GPSTIME11: m_times[s.index].decode(m_coder, item); break;
        case RGB12: m_colours[s.index].decode(m_coder, item); break;
        default: m_bytes[s.index].decode(m_coder, item); break;
        }
      }
    }
  }

  // Appends to `out` the chunk of the `count` (>= 1) records at `records`: what decode() reads back.
  void encode(const unsigned char* records, std::size_t count, std::vector<unsigned char>& out)
  {
    CGAL_precondition(count >= 1);
    out.insert(out.end(), records, records + m_record_length);
    init_items(records);
    m_encoder.init();
    for(std::size_t p = 1; p < count; ++p)
    {
      const unsigned char* record = records + p * m_record_length;
      for(const Step& s : m_steps)
      {
        const unsigned char* item = record + s.offset;
        switch(s.type)
        {
        case POINT10: m_points[s.index].encode(m_encoder, item); break;
        case GPSTIME11: m_times[s.index].encode(m_encoder, item); break;
        case RGB12: m_colours[s.index].encode(m_encoder, item); break;
        default: m_bytes[s.index].encode(m_encoder, item); break;
        }
      }
    }
    m_encoder.done();
    out.insert(out.end(), m_encoder.bytes().begin(), m_encoder.bytes().end());
  }

private:
  // Every item starts the chunk from its part of the chunk's first record (stored raw).
  void init_items(const unsigned char* first)
  {
    for(const Step& s : m_steps)
    {
      const unsigned char* raw = first + s.offset;
      switch(s.type)
      {
      case POINT10: m_points[s.index].init(raw); break;
      case GPSTIME11: m_times[s.index].init(raw); break;
      case RGB12: m_colours[s.index].init(raw); break;
      default: m_bytes[s.index].init(raw); break;
      }
    }
  }

  struct Step
  {
    Item_type type;
    std::size_t index;  // among the decoders of its type
    std::size_t offset; // in the record
    std::size_t size;
  };

  // POINT10 first, at most one item of each type, the others in LAS order: their decoding order is
  // then the one of the general loop.
  bool is_simple() const
  {
    if(m_steps.empty() || m_steps[0].type != POINT10 || m_points.size() != 1 || m_times.size() > 1 ||
       m_colours.size() > 1 || m_bytes.size() > 1)
      return false;
    int rank = 0;
    for(const Step& s : m_steps)
    {
      const int r = s.type == POINT10 ? 0 : s.type == GPSTIME11 ? 1 : s.type == RGB12 ? 2 : 3;
      if(r < rank)
        return false;
      rank = r;
    }
    return true;
  }

  std::size_t offset_of(Item_type type) const
  {
    for(const Step& s : m_steps)
      if(s.type == type)
        return s.offset;
    return 0;
  }

  Arithmetic_decoder m_coder; // the chunk's one coder, handed to every item
  Arithmetic_encoder m_encoder;
  std::vector<pointwise::Point10_coder> m_points;
  std::vector<pointwise::Gps_time11_coder> m_times;
  std::vector<pointwise::Rgb12_coder> m_colours;
  std::vector<pointwise::Byte_coder> m_bytes;
  std::vector<Step> m_steps;
  std::size_t m_record_length = 0;
};

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_POINTWISE_CHUNK_CODER_H
