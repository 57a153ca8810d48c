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

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
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

// The middle of the last five values, kept sorted. Each new value pushes out the largest or the
// smallest, alternately unless it lands on the side just pushed from: the median follows a drifting
// sequence while skipping single outliers.
class Median5
{
public:
  void init()
  {
    m_v.fill(0);
    m_drop_largest = true;
  }
  std::int32_t get() const { return m_v[2]; }
  void add(std::int32_t v)
  {
    if(m_drop_largest)
    {
      if(!(v < m_v[2]))
        m_drop_largest = false;
      std::size_t i = 4;
      for(; i > 0 && v < m_v[i - 1]; --i)
        m_v[i] = m_v[i - 1];
      m_v[i] = v;
    }
    else
    {
      if(!(m_v[2] < v))
        m_drop_largest = true;
      std::size_t i = 0;
      for(; i < 4 && m_v[i + 1] < v; ++i)
        m_v[i] = m_v[i + 1];
      m_v[i] = v;
    }
  }

private:
  std::array<std::int32_t, 5> m_v{};
  bool m_drop_largest = true;
};

// The context of a return (number of returns n, return number r, each 0 to 7): which series of
// coordinate differences and intensities the point continues. Consistent pairs 1 <= r <= n <= 5 get
// contexts 0 to 14 in order; the others (files that count from 0, swap r and n, ...) share them.
constexpr unsigned char RETURN_CONTEXT[8][8] = {
  {15, 14, 13, 12, 11, 10, 9, 8},   {14, 0, 1, 3, 6, 10, 10, 9},     {13, 1, 2, 4, 7, 11, 11, 10},
  {12, 3, 4, 5, 8, 12, 12, 11},     {11, 6, 7, 8, 9, 13, 13, 12},    {10, 10, 11, 12, 13, 14, 14, 13},
  {9, 10, 11, 12, 13, 14, 15, 14},  {8, 9, 10, 11, 12, 13, 14, 15}};

// A model per previous value of a byte, made the first time that value comes: most of the 256 are
// never needed. Made models restart with each chunk.
class Byte_models
{
public:
  Arithmetic_model& operator[](unsigned char previous)
  {
    std::unique_ptr<Arithmetic_model>& m = m_models[previous];
    if(!m)
      m.reset(new Arithmetic_model(256));
    return *m;
  }
  void init()
  {
    for(std::unique_ptr<Arithmetic_model>& m : m_models)
      if(m)
        m->init();
  }

private:
  std::array<std::unique_ptr<Arithmetic_model>, 256> m_models;
};

// POINT10 (20 bytes): X, Y, Z (int32), intensity (uint16), return bits, classification, scan angle
// rank, user data (bytes), point source ID (uint16).
class Point10_decoder
{
public:
  static constexpr std::size_t SIZE = 20;

  explicit Point10_decoder(Arithmetic_decoder& d)
    : m_decoder(d), m_changed(64), m_intensity_ic(16, 4), m_source_ic(16), m_scan_angle{{Arithmetic_model(256), Arithmetic_model(256)}},
      m_dx(32, 2), m_dy(32, 22), m_dz(32, 20)
  {}

  void init(const unsigned char* raw)
  {
    for(int i = 0; i < 16; ++i)
    {
      m_x_median[i].init();
      m_y_median[i].init();
      m_last_intensity[i] = 0;
    }
    for(int i = 0; i < 8; ++i)
      m_last_z[i] = 0;
    m_changed.init();
    m_intensity_ic.init();
    m_scan_angle[0].init();
    m_scan_angle[1].init();
    m_source_ic.init();
    m_return_models.init();
    m_class_models.init();
    m_user_models.init();
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

  void decode(unsigned char* out)
  {
    // One bit per field that changed: 32 return bits, 16 intensity, 8 classification, 4 scan angle,
    // 2 user data, 1 point source.
    const std::uint32_t changed = m_decoder.decode_symbol(m_changed);
    if(changed & 32)
      m_returns = std::uint8_t(m_decoder.decode_symbol(m_return_models[m_returns]));
    const unsigned r = m_returns & 7u, n = (m_returns >> 3) & 7u;
    const unsigned m = RETURN_CONTEXT[n][r];
    const unsigned level = n > r ? n - r : r - n; // which of the returns' last Z predicts this one
    if(changed != 0)
    {
      if(changed & 16)
        m_last_intensity[m] = std::uint16_t(m_intensity_ic.decompress(m_decoder, m_last_intensity[m], m < 3 ? m : 3));
      m_intensity = m_last_intensity[m];
      if(changed & 8)
        m_class = std::uint8_t(m_decoder.decode_symbol(m_class_models[m_class]));
      if(changed & 4)
        m_scan = std::uint8_t(m_scan + m_decoder.decode_symbol(m_scan_angle[(m_returns >> 6) & 1u]));
      if(changed & 2)
        m_user = std::uint8_t(m_decoder.decode_symbol(m_user_models[m_user]));
      if(changed & 1)
        m_source = std::uint16_t(m_source_ic.decompress(m_decoder, m_source));
    }

    const std::uint32_t single = n == 1 ? 1 : 0;
    std::int32_t diff = m_dx.decompress(m_decoder, m_x_median[m].get(), single);
    m_x = std::int32_t(std::uint32_t(m_x) + std::uint32_t(diff));
    m_x_median[m].add(diff);

    std::uint32_t k = m_dx.k();
    diff = m_dy.decompress(m_decoder, m_y_median[m].get(), single + (k < 20 ? k & ~1u : 20));
    m_y = std::int32_t(std::uint32_t(m_y) + std::uint32_t(diff));
    m_y_median[m].add(diff);

    k = (m_dx.k() + m_dy.k()) / 2;
    m_z = m_last_z[level] = m_dz.decompress(m_decoder, m_last_z[level], single + (k < 18 ? k & ~1u : 18));

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
  Arithmetic_decoder& m_decoder;
  Arithmetic_model m_changed;
  Integer_decompressor m_intensity_ic, m_source_ic;
  std::array<Arithmetic_model, 2> m_scan_angle; // by scan direction
  Byte_models m_return_models, m_class_models, m_user_models;
  Integer_decompressor m_dx, m_dy, m_dz;
  Median5 m_x_median[16], m_y_median[16];
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

  explicit Gps_time11_decoder(Arithmetic_decoder& d)
    : m_decoder(d), m_multiple(MULTIPLE_SYMBOLS), m_after_zero(6), m_ic(32, 9)
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

  void decode(unsigned char* out)
  {
    // A switch to another series codes the time again in that series: a loop, not a recursion
    // (a damaged chunk could chain switches without end).
    for(;;)
    {
      if(m_step[m_current] == 0)
      {
        // 0 same time, 1 a 32-bit difference, 2 a new series, 3-5 another series (1-3 on).
        const std::uint32_t s = m_decoder.decode_symbol(m_after_zero);
        if(s == 1)
        {
          m_step[m_current] = m_ic.decompress(m_decoder, 0, 0);
          m_time[m_current] += std::uint64_t(std::int64_t(m_step[m_current]));
          m_off_step[m_current] = 0;
        }
        else if(s == 2)
          start_series();
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
        const std::uint32_t s = m_decoder.decode_symbol(m_multiple);
        const std::uint32_t step = std::uint32_t(m_step[m_current]);
        if(s == 1)
        {
          m_time[m_current] += std::uint64_t(std::int64_t(m_ic.decompress(m_decoder, std::int32_t(step), 1)));
          m_off_step[m_current] = 0;
        }
        else if(s < UNCHANGED)
        {
          std::int32_t diff;
          if(s == 0)
          {
            diff = m_ic.decompress(m_decoder, 0, 7);
            count_off_step(diff);
          }
          else if(s < MULTIPLE)
            diff = m_ic.decompress(m_decoder, std::int32_t(s * step), s < 10 ? 2 : 3);
          else if(s == MULTIPLE)
          {
            diff = m_ic.decompress(m_decoder, std::int32_t(MULTIPLE * step), 4);
            count_off_step(diff);
          }
          else
          {
            const std::int32_t back = std::int32_t(MULTIPLE) - std::int32_t(s); // -1 to -10
            if(back > MULTIPLE_MINUS)
              diff = m_ic.decompress(m_decoder, std::int32_t(std::uint32_t(back) * step), 5);
            else
            {
              diff = m_ic.decompress(m_decoder, std::int32_t(std::uint32_t(MULTIPLE_MINUS) * step), 6);
              count_off_step(diff);
            }
          }
          m_time[m_current] += std::uint64_t(std::int64_t(diff));
        }
        else if(s == NEW_SERIES)
          start_series();
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
  void start_series()
  {
    m_newest = (m_newest + 1) & 3u;
    const std::uint32_t high = std::uint32_t(m_ic.decompress(m_decoder, std::int32_t(m_time[m_current] >> 32), 8));
    m_time[m_newest] = (std::uint64_t(high) << 32) | m_decoder.read_int();
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

  Arithmetic_decoder& m_decoder;
  Arithmetic_model m_multiple, m_after_zero;
  Integer_decompressor m_ic;
  std::uint64_t m_time[4];
  std::int32_t m_step[4];
  std::int32_t m_off_step[4];
  std::uint32_t m_current = 0, m_newest = 0;
};

// RGB12 (three uint16). Each of the six bytes is coded only when it changed (a mask says which);
// green and blue are predicted from red's change, as colours mostly change in brightness.
class Rgb12_decoder
{
public:
  static constexpr std::size_t SIZE = 6;

  explicit Rgb12_decoder(Arithmetic_decoder& d)
    : m_decoder(d), m_mask(128),
      m_byte{{Arithmetic_model(256), Arithmetic_model(256), Arithmetic_model(256), Arithmetic_model(256),
              Arithmetic_model(256), Arithmetic_model(256)}}
  {}

  void init(const unsigned char* raw)
  {
    m_mask.init();
    for(Arithmetic_model& m : m_byte)
      m.init();
    for(int i = 0; i < 6; ++i)
      m_last[i] = raw[i];
  }

  void decode(unsigned char* out)
  {
    // Bytes: 0 red low, 1 red high, 2 green low, 3 green high, 4 blue low, 5 blue high. Mask bits:
    // 0 red low, 1 red high, 2 green low, 3 green high, 4 blue low, 5 blue high changed; 6 green and
    // blue differ from red.
    const std::uint32_t mask = m_decoder.decode_symbol(m_mask);
    unsigned char c[6];
    c[0] = (mask & 1) ? next(0, m_last[0]) : m_last[0];
    c[1] = (mask & 2) ? next(1, m_last[1]) : m_last[1];
    if(mask & 64)
    {
      for(std::size_t half = 0; half < 2; ++half) // the low bytes, then the high ones
      {
        int diff = int(c[half]) - int(m_last[half]);
        c[2 + half] = (mask & (4u << half)) ? next(2 + half, clamp(diff + m_last[2 + half])) : m_last[2 + half];
        if(mask & (16u << half))
        {
          diff = (diff + (int(c[2 + half]) - int(m_last[2 + half]))) / 2; // C division, towards 0
          c[4 + half] = next(4 + half, clamp(diff + m_last[4 + half]));
        }
        else
          c[4 + half] = m_last[4 + half];
      }
    }
    else
    {
      c[2] = c[4] = c[0];
      c[3] = c[5] = c[1];
    }
    for(int i = 0; i < 6; ++i)
      out[i] = m_last[i] = c[i];
  }

private:
  static unsigned char clamp(int v) { return static_cast<unsigned char>(v <= 0 ? 0 : v >= 255 ? 255 : v); }

  unsigned char next(std::size_t byte, unsigned char predicted)
  {
    return static_cast<unsigned char>(predicted + m_decoder.decode_symbol(m_byte[byte]));
  }

  Arithmetic_decoder& m_decoder;
  Arithmetic_model m_mask;
  std::array<Arithmetic_model, 6> m_byte;
  unsigned char m_last[6];
};

// BYTE (extra bytes, any number): each byte coded as its difference from the record before.
class Byte_decoder
{
public:
  Byte_decoder(Arithmetic_decoder& d, std::size_t size)
    : m_decoder(d), m_models(size, Arithmetic_model(256)), m_last(size, 0)
  {}

  void init(const unsigned char* raw)
  {
    for(Arithmetic_model& m : m_models)
      m.init();
    std::memcpy(m_last.data(), raw, m_last.size());
  }

  void decode(unsigned char* out)
  {
    for(std::size_t i = 0; i < m_last.size(); ++i)
      out[i] = m_last[i] = static_cast<unsigned char>(m_last[i] + m_decoder.decode_symbol(m_models[i]));
  }

private:
  Arithmetic_decoder& m_decoder;
  std::vector<Arithmetic_model> m_models;
  std::vector<unsigned char> m_last;
};

} // namespace pointwise

class Pointwise_chunk_decoder
{
public:
  // Refuses, with Decode_error, any item but POINT10, GPSTIME11, RGB12 and BYTE of version 2, and
  // those of another size than their type's.
  explicit Pointwise_chunk_decoder(const std::vector<Item>& items) : m_decoder(new Arithmetic_decoder)
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
        m_points.emplace_back(new pointwise::Point10_decoder(*m_decoder));
        break;
      case GPSTIME11:
        expected = pointwise::Gps_time11_decoder::SIZE;
        step.index = m_times.size();
        m_times.emplace_back(new pointwise::Gps_time11_decoder(*m_decoder));
        break;
      case RGB12:
        expected = pointwise::Rgb12_decoder::SIZE;
        step.index = m_colours.size();
        m_colours.emplace_back(new pointwise::Rgb12_decoder(*m_decoder));
        break;
      default: // BYTE
        if(item.size == 0)
          throw Decode_error(name + " has 0 bytes");
        step.index = m_bytes.size();
        m_bytes.emplace_back(new pointwise::Byte_decoder(*m_decoder, item.size));
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
      case POINT10: m_points[s.index]->init(raw); break;
      case GPSTIME11: m_times[s.index]->init(raw); break;
      case RGB12: m_colours[s.index]->init(raw); break;
      default: m_bytes[s.index]->init(raw); break;
      }
    }
    if(count == 1)
      return; // the coder's bytes are not needed
    m_decoder->init(begin + m_record_length, end);

    // The common records (a POINT10 item first, then at most one of each other) take a loop of
    // their own, without the dispatch on item types.
    if(is_simple())
    {
      pointwise::Point10_decoder& point = *m_points[0];
      pointwise::Gps_time11_decoder* time = m_times.empty() ? nullptr : m_times[0].get();
      pointwise::Rgb12_decoder* colour = m_colours.empty() ? nullptr : m_colours[0].get();
      pointwise::Byte_decoder* bytes = m_bytes.empty() ? nullptr : m_bytes[0].get();
      const std::size_t time_at = time ? offset_of(GPSTIME11) : 0;
      const std::size_t colour_at = colour ? offset_of(RGB12) : 0;
      const std::size_t bytes_at = bytes ? offset_of(BYTE) : 0;
      for(std::size_t p = 1; p < count; ++p)
      {
        unsigned char* record = out + p * m_record_length;
        point.decode(record);
        if(time)
          time->decode(record + time_at);
        if(colour)
          colour->decode(record + colour_at);
        if(bytes)
          bytes->decode(record + bytes_at);
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
        case POINT10: m_points[s.index]->decode(item); break;
        case GPSTIME11: m_times[s.index]->decode(item); break;
        case RGB12: m_colours[s.index]->decode(item); break;
        default: m_bytes[s.index]->decode(item); break;
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

  // Behind pointers, so that the decoders' references to the coder survive a move of this object.
  std::unique_ptr<Arithmetic_decoder> m_decoder;
  std::vector<std::unique_ptr<pointwise::Point10_decoder>> m_points;
  std::vector<std::unique_ptr<pointwise::Gps_time11_decoder>> m_times;
  std::vector<std::unique_ptr<pointwise::Rgb12_decoder>> m_colours;
  std::vector<std::unique_ptr<pointwise::Byte_decoder>> m_bytes;
  std::vector<Step> m_steps;
  std::size_t m_record_length = 0;
};

} // namespace laz
} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_POINTWISE_CHUNK_DECODER_H
