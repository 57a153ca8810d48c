// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_POINTWISE_CHUNK_DECODER_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_POINTWISE_CHUNK_DECODER_H

#include <CGAL/Sigmoid_neighborhoods/IO/little_endian.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/arithmetic_decoder.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/integer_decompressor.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/laz_items.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/predictors.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {
namespace laz {

// LASzip's point-wise chunked compression (compressor 2, LAS point formats 0 to 5), items of version 2.
// In a chunk the first record is stored raw; every item then predicts its next value from the record
// before and codes what differs, all items sharing one arithmetic coder, record after record.

namespace pointwise {

// The context of a return (number of returns n, return number r, each 0 to 7): which series of
// coordinate differences and intensities the point continues. Consistent pairs 1 <= r <= n <= 5 get
// contexts 0 to 14 in order; the others (files that count from 0, swap r and n, ...) share them.
constexpr unsigned char RETURN_CONTEXT[8][8] = {
  {15, 14, 13, 12, 11, 10, 9, 8},   {14, 0, 1, 3, 6, 10, 10, 9},     {13, 1, 2, 4, 7, 11, 11, 10},
  {12, 3, 4, 5, 8, 12, 12, 11},     {11, 6, 7, 8, 9, 13, 13, 12},    {10, 10, 11, 12, 13, 14, 14, 13},
  {9, 10, 11, 12, 13, 14, 15, 14},  {8, 9, 10, 11, 12, 13, 14, 15}};

// POINT10 (20 bytes): X, Y, Z (int32), intensity (uint16), return bits, classification, scan angle
// rank, user data (bytes), point source ID (uint16).
class Point10_decoder
{
public:
  static constexpr std::size_t SIZE = 20;

  Point10_decoder()
    : m_changed(64), m_intensity_ic(16, 4), m_source_ic(16), m_scan_angle{{Arithmetic_model(256), Arithmetic_model(256)}},
      m_dx(32, 2), m_dy(32, 22), m_dz(32, 20)
  {}

  void init(const unsigned char* raw)
  {
    for(int i = 0; i < 16; ++i)
    {
      m_x_median[i].reset();
      m_y_median[i].reset();
      m_last_intensity[i] = 0;
    }
    for(int i = 0; i < 8; ++i)
      m_last_z[i] = 0;
    m_changed.init();
    m_intensity_ic.init();
    m_scan_angle[0].init();
    m_scan_angle[1].init();
    m_source_ic.init();
    m_return_models.reset();
    m_class_models.reset();
    m_user_models.reset();
    m_dx.init();
    m_dy.init();
    m_dz.init();
    m_x = load_little_endian<std::int32_t>(raw);
    m_y = load_little_endian<std::int32_t>(raw + 4);
    m_z = load_little_endian<std::int32_t>(raw + 8);
    m_intensity = 0; // the encoder's reference record has it cleared
    m_returns = raw[14];
    m_class = raw[15];
    m_scan = raw[16];
    m_user = raw[17];
    m_source = load_little_endian<std::uint16_t>(raw + 18);
  }

  void decode(Arithmetic_decoder& d, unsigned char* out)
  {
    // One bit per field that changed: 32 return bits, 16 intensity, 8 classification, 4 scan angle,
    // 2 user data, 1 point source.
    const std::uint32_t changed = d.decode_symbol(m_changed);
    if(changed & 32)
      m_returns = std::uint8_t(d.decode_symbol(m_return_models[m_returns]));
    const unsigned r = m_returns & 7u, n = (m_returns >> 3) & 7u;
    const unsigned m = RETURN_CONTEXT[n][r];
    const unsigned level = n > r ? n - r : r - n; // which of the returns' last Z predicts this one
    if(changed != 0)
    {
      if(changed & 16)
        m_last_intensity[m] = std::uint16_t(m_intensity_ic.decompress(d, m_last_intensity[m], m < 3 ? m : 3));
      m_intensity = m_last_intensity[m];
      if(changed & 8)
        m_class = std::uint8_t(d.decode_symbol(m_class_models[m_class]));
      if(changed & 4)
        m_scan = std::uint8_t(m_scan + d.decode_symbol(m_scan_angle[(m_returns >> 6) & 1u]));
      if(changed & 2)
        m_user = std::uint8_t(d.decode_symbol(m_user_models[m_user]));
      if(changed & 1)
        m_source = std::uint16_t(m_source_ic.decompress(d, m_source));
    }

    const std::uint32_t single = n == 1 ? 1 : 0;
    std::int32_t diff = m_dx.decompress(d, m_x_median[m].get(), single);
    m_x = std::int32_t(std::uint32_t(m_x) + std::uint32_t(diff));
    m_x_median[m].add(diff);

    std::uint32_t k = m_dx.k();
    diff = m_dy.decompress(d, m_y_median[m].get(), single + (k < 20 ? k & ~1u : 20));
    m_y = std::int32_t(std::uint32_t(m_y) + std::uint32_t(diff));
    m_y_median[m].add(diff);

    k = (m_dx.k() + m_dy.k()) / 2;
    m_z = m_last_z[level] = m_dz.decompress(d, m_last_z[level], single + (k < 18 ? k & ~1u : 18));

    store_little_endian<std::int32_t>(out, m_x);
    store_little_endian<std::int32_t>(out + 4, m_y);
    store_little_endian<std::int32_t>(out + 8, m_z);
    store_little_endian<std::uint16_t>(out + 12, m_intensity);
    out[14] = m_returns;
    out[15] = m_class;
    out[16] = m_scan;
    out[17] = m_user;
    store_little_endian<std::uint16_t>(out + 18, m_source);
  }

private:
  Arithmetic_model m_changed;
  Integer_decompressor m_intensity_ic, m_source_ic;
  std::array<Arithmetic_model, 2> m_scan_angle; // by scan direction
  Lazy_models<256, 256> m_return_models, m_class_models, m_user_models; // by the previous byte
  Integer_decompressor m_dx, m_dy, m_dz;
  Streaming_median5 m_x_median[16], m_y_median[16];
  std::uint16_t m_last_intensity[16];
  std::int32_t m_last_z[8];
  std::int32_t m_x = 0, m_y = 0, m_z = 0;
  std::uint16_t m_intensity = 0, m_source = 0;
  std::uint8_t m_returns = 0, m_class = 0, m_scan = 0, m_user = 0;
};

// GPSTIME11 (8 bytes, a double coded as its 64-bit pattern). Up to four time series are followed at
// once (scanners interleave them); within one, the difference from the last time is predicted as a
// multiple of the series' usual step.
class Gps_time11_decoder
{
public:
  static constexpr std::size_t SIZE = 8;

  Gps_time11_decoder()
    : m_multiple(MULTIPLE_SYMBOLS), m_after_zero(6), m_ic(32, 9)
  {}

  void init(const unsigned char* raw)
  {
    m_current = m_newest = 0;
    for(int i = 0; i < 4; ++i)
    {
      m_time[i] = 0;
      m_step[i] = 0;
      m_off_step[i] = 0;
    }
    m_time[0] = load_little_endian<std::uint64_t>(raw);
    m_multiple.init();
    m_after_zero.init();
    m_ic.init();
  }

  void decode(Arithmetic_decoder& d, unsigned char* out)
  {
    // A switch to another series codes the time again in that series: a loop, not a recursion
    // (a damaged chunk could chain switches without end).
    for(;;)
    {
      if(m_step[m_current] == 0)
      {
        // 0 same time, 1 a 32-bit difference, 2 a new series, 3-5 another series (1-3 on).
        const std::uint32_t s = d.decode_symbol(m_after_zero);
        if(s == 1)
        {
          m_step[m_current] = m_ic.decompress(d, 0, 0);
          m_time[m_current] += std::uint64_t(std::int64_t(m_step[m_current]));
          m_off_step[m_current] = 0;
        }
        else if(s == 2)
          start_series(d);
        else if(s > 2)
        {
          m_current = (m_current + s - 2) & 3u;
          continue;
        }
      }
      else
      {
        // 1 one step, 2-499 that many steps, 500 (or more) 500, 501-509 -1 to -9 steps, 510 -10 (or
        // fewer), 0 a difference not near a multiple; 511 same time, 512 a new series, 513-515 another.
        const std::uint32_t s = d.decode_symbol(m_multiple);
        const std::uint32_t step = std::uint32_t(m_step[m_current]);
        if(s == 1)
        {
          m_time[m_current] += std::uint64_t(std::int64_t(m_ic.decompress(d, std::int32_t(step), 1)));
          m_off_step[m_current] = 0;
        }
        else if(s < UNCHANGED)
        {
          std::int32_t diff;
          if(s == 0)
          {
            diff = m_ic.decompress(d, 0, 7);
            count_off_step(diff);
          }
          else if(s < MULTIPLE)
            diff = m_ic.decompress(d, std::int32_t(s * step), s < 10 ? 2 : 3);
          else if(s == MULTIPLE)
          {
            diff = m_ic.decompress(d, std::int32_t(MULTIPLE * step), 4);
            count_off_step(diff);
          }
          else
          {
            const std::int32_t back = std::int32_t(MULTIPLE) - std::int32_t(s); // -1 to -10
            if(back > MULTIPLE_MINUS)
              diff = m_ic.decompress(d, std::int32_t(std::uint32_t(back) * step), 5);
            else
            {
              diff = m_ic.decompress(d, std::int32_t(std::uint32_t(MULTIPLE_MINUS) * step), 6);
              count_off_step(diff);
            }
          }
          m_time[m_current] += std::uint64_t(std::int64_t(diff));
        }
        else if(s == NEW_SERIES)
          start_series(d);
        else if(s > NEW_SERIES)
        {
          m_current = (m_current + s - NEW_SERIES) & 3u;
          continue;
        }
      }
      break;
    }
    store_little_endian<std::uint64_t>(out, m_time[m_current]);
  }

private:
  static constexpr std::uint32_t MULTIPLE = 500;
  static constexpr std::int32_t MULTIPLE_MINUS = -10;
  static constexpr std::uint32_t UNCHANGED = MULTIPLE + 10 + 1;   // 511
  static constexpr std::uint32_t NEW_SERIES = MULTIPLE + 10 + 2;  // 512
  static constexpr std::uint32_t MULTIPLE_SYMBOLS = MULTIPLE + 10 + 6;

  // A time far from the current series: the upper 32 bits predicted from the current series', the
  // lower 32 raw. It replaces the oldest of the four series.
  void start_series(Arithmetic_decoder& d)
  {
    m_newest = (m_newest + 1) & 3u;
    const std::uint32_t high = std::uint32_t(m_ic.decompress(d, std::int32_t(m_time[m_current] >> 32), 8));
    m_time[m_newest] = (std::uint64_t(high) << 32) | d.read_int();
    m_current = m_newest;
    m_step[m_current] = 0;
    m_off_step[m_current] = 0;
  }

  // After four differences in a row that no multiple of the step predicts, the last becomes the step.
  void count_off_step(std::int32_t diff)
  {
    if(++m_off_step[m_current] > 3)
    {
      m_step[m_current] = diff;
      m_off_step[m_current] = 0;
    }
  }

  Arithmetic_model m_multiple, m_after_zero;
  Integer_decompressor m_ic;
  std::uint64_t m_time[4];
  std::int32_t m_step[4];
  std::int32_t m_off_step[4];
  std::uint32_t m_current = 0, m_newest = 0;
};

// RGB12 (three uint16). A mask says which bytes changed; each changed byte is coded as its
// difference from a prediction, green and blue predicted from red's change (predict_rgb()).
class Rgb12_decoder
{
public:
  static constexpr std::size_t SIZE = 6;

  Rgb12_decoder()
    : m_mask(128),
      m_byte{{Arithmetic_model(256), Arithmetic_model(256), Arithmetic_model(256), Arithmetic_model(256),
              Arithmetic_model(256), Arithmetic_model(256)}}
  {}

  void init(const unsigned char* raw)
  {
    m_mask.init();
    for(Arithmetic_model& m : m_byte)
      m.init();
    for(std::size_t i = 0; i < 3; ++i)
      m_last[i] = load_little_endian<std::uint16_t>(raw + 2 * i);
  }

  void decode(Arithmetic_decoder& d, unsigned char* out)
  {
    const unsigned mask = d.decode_symbol(m_mask);
    m_last = predict_rgb(mask, m_last, [&](std::size_t byte) { return d.decode_symbol(m_byte[byte]); });
    for(std::size_t i = 0; i < 3; ++i)
      store_little_endian<std::uint16_t>(out + 2 * i, m_last[i]);
  }

private:
  Arithmetic_model m_mask;
  std::array<Arithmetic_model, 6> m_byte; // the bytes' corrections, as the mask numbers them
  std::array<std::uint16_t, 3> m_last{};
};

// BYTE (extra bytes, any number): each byte coded as its difference from the record before.
class Byte_decoder
{
public:
  explicit Byte_decoder(std::size_t size)
    : m_models(size, Arithmetic_model(256)), m_last(size, 0)
  {}

  void init(const unsigned char* raw)
  {
    for(Arithmetic_model& m : m_models)
      m.init();
    std::memcpy(m_last.data(), raw, m_last.size());
  }

  void decode(Arithmetic_decoder& d, unsigned char* out)
  {
    for(std::size_t i = 0; i < m_last.size(); ++i)
      out[i] = m_last[i] = static_cast<unsigned char>(m_last[i] + d.decode_symbol(m_models[i]));
  }

private:
  std::vector<Arithmetic_model> m_models;
  std::vector<unsigned char> m_last;
};

} // namespace pointwise

class Pointwise_chunk_decoder
{
public:
  // Refuses, with Decode_error, any item but POINT10, GPSTIME11, RGB12 and BYTE of version 2, and
  // those of another size than their type's.
  explicit Pointwise_chunk_decoder(const std::vector<Item>& items)
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
        expected = pointwise::Point10_decoder::SIZE;
        step.index = m_points.size();
        m_points.emplace_back();
        break;
      case GPSTIME11:
        expected = pointwise::Gps_time11_decoder::SIZE;
        step.index = m_times.size();
        m_times.emplace_back();
        break;
      case RGB12:
        expected = pointwise::Rgb12_decoder::SIZE;
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
    for(const Step& s : m_steps)
    {
      const unsigned char* raw = out + s.offset;
      switch(s.type)
      {
      case POINT10: m_points[s.index].init(raw); break;
      case GPSTIME11: m_times[s.index].init(raw); break;
      case RGB12: m_colours[s.index].init(raw); break;
      default: m_bytes[s.index].init(raw); break;
      }
    }
    if(count == 1)
      return; // the coder's bytes are not needed
    m_decoder.init(begin + m_record_length, end);

    // The common records (a POINT10 item first, then at most one of each other) take a loop of
    // their own, without the dispatch on item types.
    if(is_simple())
    {
      pointwise::Point10_decoder& point = m_points[0];
      pointwise::Gps_time11_decoder* time = m_times.empty() ? nullptr : &m_times[0];
      pointwise::Rgb12_decoder* colour = m_colours.empty() ? nullptr : &m_colours[0];
      pointwise::Byte_decoder* bytes = m_bytes.empty() ? nullptr : &m_bytes[0];
      const std::size_t time_at = time ? offset_of(GPSTIME11) : 0;
      const std::size_t colour_at = colour ? offset_of(RGB12) : 0;
      const std::size_t bytes_at = bytes ? offset_of(BYTE) : 0;
      for(std::size_t p = 1; p < count; ++p)
      {
        unsigned char* record = out + p * m_record_length;
        point.decode(m_decoder, record);
        if(time)
          time->decode(m_decoder, record + time_at);
        if(colour)
          colour->decode(m_decoder, record + colour_at);
        if(bytes)
          bytes->decode(m_decoder, record + bytes_at);
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
        case POINT10: m_points[s.index].decode(m_decoder, item); break;
        case GPSTIME11: m_times[s.index].decode(m_decoder, item); break;
        case RGB12: m_colours[s.index].decode(m_decoder, item); break;
        default: m_bytes[s.index].decode(m_decoder, item); break;
        }
      }
    }
  }

private:
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

  Arithmetic_decoder m_decoder; // the chunk's one coder, handed to every item
  std::vector<pointwise::Point10_decoder> m_points;
  std::vector<pointwise::Gps_time11_decoder> m_times;
  std::vector<pointwise::Rgb12_decoder> m_colours;
  std::vector<pointwise::Byte_decoder> m_bytes;
  std::vector<Step> m_steps;
  std::size_t m_record_length = 0;
};

} // namespace laz
} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_POINTWISE_CHUNK_DECODER_H
