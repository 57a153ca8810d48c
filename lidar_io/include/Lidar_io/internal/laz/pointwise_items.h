// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_POINTWISE_ITEMS_H
#define LIDAR_IO_INTERNAL_LAZ_POINTWISE_ITEMS_H

#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/integer_coder.h>
#include <Lidar_io/internal/laz/predictors.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// The items of LASzip's point-wise chunked compression (compressor 2, LAS point formats 0 to 5),
// version 2, in both directions: each holds what it predicts from (the record before, its models),
// init() starts a chunk from its raw first record, decode() and encode() code the next one.

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
class Point10_coder
{
public:
  static constexpr std::size_t SIZE = 20;

  Point10_coder()
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

  void encode(Arithmetic_encoder& e, const unsigned char* in)
  {
    const std::int32_t x = load_little_endian<std::int32_t>(in), y = load_little_endian<std::int32_t>(in + 4),
                       z = load_little_endian<std::int32_t>(in + 8);
    const std::uint16_t intensity = load_little_endian<std::uint16_t>(in + 12);
    const std::uint8_t returns = in[14], classification = in[15], scan = in[16], user = in[17];
    const std::uint16_t source = load_little_endian<std::uint16_t>(in + 18);
    const unsigned r = returns & 7u, n = (returns >> 3) & 7u;
    const unsigned m = RETURN_CONTEXT[n][r];
    const unsigned level = n > r ? n - r : r - n;

    // the intensity against the last of its return context, the rest against the record before
    const std::uint32_t changed = (returns != m_returns ? 32u : 0u) | (intensity != m_last_intensity[m] ? 16u : 0u) |
                                  (classification != m_class ? 8u : 0u) | (scan != m_scan ? 4u : 0u) |
                                  (user != m_user ? 2u : 0u) | (source != m_source ? 1u : 0u);
    e.encode_symbol(m_changed, changed);
    if(changed & 32)
      e.encode_symbol(m_return_models[m_returns], returns);
    if(changed & 16)
    {
      m_intensity_ic.compress(e, m_last_intensity[m], intensity, m < 3 ? m : 3);
      m_last_intensity[m] = intensity;
    }
    if(changed & 8)
      e.encode_symbol(m_class_models[m_class], classification);
    if(changed & 4)
      e.encode_symbol(m_scan_angle[(returns >> 6) & 1u], std::uint8_t(scan - m_scan));
    if(changed & 2)
      e.encode_symbol(m_user_models[m_user], user);
    if(changed & 1)
      m_source_ic.compress(e, m_source, source);

    const std::uint32_t single = n == 1 ? 1 : 0;
    std::int32_t diff = std::int32_t(std::uint32_t(x) - std::uint32_t(m_x));
    m_dx.compress(e, m_x_median[m].get(), diff, single);
    m_x_median[m].add(diff);

    std::uint32_t k = m_dx.k();
    diff = std::int32_t(std::uint32_t(y) - std::uint32_t(m_y));
    m_dy.compress(e, m_y_median[m].get(), diff, single + (k < 20 ? k & ~1u : 20));
    m_y_median[m].add(diff);

    k = (m_dx.k() + m_dy.k()) / 2;
    m_dz.compress(e, m_last_z[level], z, single + (k < 18 ? k & ~1u : 18));
    m_last_z[level] = z;

    m_x = x;
    m_y = y;
    m_z = z;
    m_intensity = intensity;
    m_returns = returns;
    m_class = classification;
    m_scan = scan;
    m_user = user;
    m_source = source;
  }

private:
  Arithmetic_model m_changed;
  Integer_coder m_intensity_ic, m_source_ic;
  std::array<Arithmetic_model, 2> m_scan_angle; // by scan direction
  Lazy_models<256, 256> m_return_models, m_class_models, m_user_models; // by the previous byte
  Integer_coder m_dx, m_dy, m_dz;
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
class Gps_time11_coder
{
public:
  static constexpr std::size_t SIZE = 8;

  Gps_time11_coder()
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

  void encode(Arithmetic_encoder& e, const unsigned char* in)
  {
    const std::uint64_t time = load_little_endian<std::uint64_t>(in);
    // A switch to another series codes the time again in that one (at most three switches: the
    // series switched to holds a time within 32 bits).
    for(;;)
    {
      const bool after_zero = m_step[m_current] == 0;
      if(time == m_time[m_current])
      {
        e.encode_symbol(after_zero ? m_after_zero : m_multiple, after_zero ? 0u : UNCHANGED);
        return;
      }
      std::int32_t diff;
      if(gps_time_difference(time, m_time[m_current], diff))
      {
        if(after_zero)
        {
          e.encode_symbol(m_after_zero, 1);
          m_ic.compress(e, 0, diff, 0);
          m_step[m_current] = diff;
          m_off_step[m_current] = 0;
        }
        else
          encode_multiple(e, diff);
        m_time[m_current] = time;
        return;
      }
      std::uint32_t other = 1;
      std::int32_t unused;
      while(other < 4 && !gps_time_difference(time, m_time[(m_current + other) & 3u], unused))
        ++other;
      if(other == 4)
      {
        e.encode_symbol(after_zero ? m_after_zero : m_multiple, after_zero ? 2u : NEW_SERIES);
        m_ic.compress(e, std::int32_t(std::uint32_t(m_time[m_current] >> 32)), std::int32_t(std::uint32_t(time >> 32)), 8);
        e.write_int(std::uint32_t(time));
        m_newest = (m_newest + 1) & 3u;
        m_current = m_newest;
        m_step[m_current] = 0;
        m_off_step[m_current] = 0;
        m_time[m_current] = time;
        return;
      }
      e.encode_symbol(after_zero ? m_after_zero : m_multiple, after_zero ? other + 2 : NEW_SERIES + other);
      m_current = (m_current + other) & 3u;
    }
  }

private:
  // A difference within 32 bits in a series with a step: as a multiple of the step, mirroring decode().
  void encode_multiple(Arithmetic_encoder& e, std::int32_t diff)
  {
    const Gps_step_code c = gps_step_code(diff, m_step[m_current]);
    e.encode_symbol(m_multiple, c.symbol);
    m_ic.compress(e, c.prediction, diff, c.context);
    if(c.on_step)
      m_off_step[m_current] = 0;
    else if(c.off_step)
      count_off_step(diff);
  }

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
  Integer_coder m_ic;
  std::uint64_t m_time[4];
  std::int32_t m_step[4];
  std::int32_t m_off_step[4];
  std::uint32_t m_current = 0, m_newest = 0;
};

// RGB12 (three uint16). A mask says which bytes changed; each changed byte is coded as its
// difference from a prediction, green and blue predicted from red's change (predict_rgb()).
class Rgb12_coder
{
public:
  static constexpr std::size_t SIZE = 6;

  Rgb12_coder()
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
    m_last = predict_rgb(mask, m_last, [&](std::size_t b, unsigned predicted) {
      return (d.decode_symbol(m_byte[b]) + predicted) & 0xFFu;
    });
    for(std::size_t i = 0; i < 3; ++i)
      store_little_endian<std::uint16_t>(out + 2 * i, m_last[i]);
  }

  void encode(Arithmetic_encoder& e, const unsigned char* in)
  {
    std::array<std::uint16_t, 3> rgb;
    for(std::size_t i = 0; i < 3; ++i)
      rgb[i] = load_little_endian<std::uint16_t>(in + 2 * i);
    const unsigned mask = rgb_change_mask(m_last, rgb);
    e.encode_symbol(m_mask, mask);
    predict_rgb(mask, m_last, [&](std::size_t b, unsigned predicted) {
      const unsigned actual = rgb_byte(rgb, b);
      e.encode_symbol(m_byte[b], (actual - predicted) & 0xFFu);
      return actual;
    });
    m_last = rgb;
  }

private:
  Arithmetic_model m_mask;
  std::array<Arithmetic_model, 6> m_byte; // the bytes' corrections, as the mask numbers them
  std::array<std::uint16_t, 3> m_last{};
};

// BYTE (extra bytes, any number): each byte coded as its difference from the record before.
class Byte_coder
{
public:
  explicit Byte_coder(std::size_t size)
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

  void encode(Arithmetic_encoder& e, const unsigned char* in)
  {
    for(std::size_t i = 0; i < m_last.size(); ++i)
    {
      e.encode_symbol(m_models[i], static_cast<unsigned char>(in[i] - m_last[i]));
      m_last[i] = in[i];
    }
  }

private:
  std::vector<Arithmetic_model> m_models;
  std::vector<unsigned char> m_last;
};

} // namespace pointwise

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_POINTWISE_ITEMS_H
