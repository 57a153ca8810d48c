// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_PREDICTORS_H
#define LIDAR_IO_INTERNAL_LAZ_PREDICTORS_H

#include <Lidar_io/internal/laz/arithmetic_coder.h>

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <optional>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// What LASzip's point-wise (POINT10, RGB12) and layered (POINT14, RGB14) items predict alike.

// LASzip's running estimate of the middle of the last coordinate differences ("StreamingMedian5"):
// five values kept sorted; each new one pushes out the largest or the smallest, alternately unless it
// lands on the side just pushed from, so that the middle follows a drifting sequence and skips single
// outliers. Not an exact median: what matters is that it predicts as the encoder did.
class Streaming_median5
{
public:
  void reset()
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

// N symbol models of `Symbols` symbols that every chunk starts fresh. LASzip creates many of them
// only when a context first occurs (a model per previous byte value, per scanner channel ...); a model
// is therefore made and initialised on its first use after reset(), which gives the state of
// initialising all of them at the start and costs nothing for the contexts a chunk never meets.
// Allocated once, kept across chunks.
template <std::size_t N, std::uint32_t Symbols>
class Lazy_models
{
public:
  void reset() { m_fresh.reset(); }

  Arithmetic_model& operator[](std::size_t i)
  {
    if(!m_fresh[i])
    {
      if(!m_models[i])
        m_models[i].emplace(Symbols);
      m_models[i]->init();
      m_fresh[i] = true;
    }
    return *m_models[i];
  }

private:
  std::array<std::optional<Arithmetic_model>, N> m_models;
  std::bitset<N> m_fresh;
};

// What LASzip's GPS time encoders (GPSTIME11 version 2, POINT14 version 3) compute alike.

// The difference of two times' 64-bit patterns when it fits 32 bits.
inline bool gps_time_difference(std::uint64_t time, std::uint64_t from, std::int32_t& difference)
{
  const std::int64_t d = std::int64_t(time - from);
  difference = std::int32_t(std::uint32_t(std::uint64_t(d)));
  return d == std::int64_t(difference);
}

// How a time difference `d` within 32 bits is coded in a series whose step is `step` (not 0), the same
// in GPSTIME11 version 2 and POINT14 version 3: the multiple of the step it is near (LASzip's float
// quotient rounded half away from zero) picks the symbol, the prediction and the integer coder's
// context; `off_step` says that the difference counts as off the step (four in a row replace it),
// `on_step` that it resets that count.
struct Gps_step_code
{
  std::uint32_t symbol;
  std::int32_t prediction;
  std::uint32_t context;
  bool off_step, on_step;
};

inline Gps_step_code gps_step_code(std::int32_t d, std::int32_t step)
{
  constexpr std::int32_t MULTI = 500, MULTI_MINUS = -10;
  const float q = float(d) / float(step);
  const float rounded = q >= 0.f ? q + 0.5f : q - 0.5f;
  // LASzip converts with a C cast; a quotient beyond 32 bits (d near 2^31 over +-1) gives what x86
  // gives, the integer minimum
  const std::int32_t multi = rounded > -2147483904.f && rounded < 2147483648.f ? std::int32_t(rounded)
                                                                                 : std::int32_t(std::uint32_t(1) << 31);
  auto times = [step](std::int32_t m) { return std::int32_t(std::uint32_t(m) * std::uint32_t(step)); };
  if(multi == 1)
    return {1, step, 1, false, true};
  if(multi > 0)
    return multi < MULTI ? Gps_step_code{std::uint32_t(multi), times(multi), multi < 10 ? 2u : 3u, false, false}
                         : Gps_step_code{std::uint32_t(MULTI), times(MULTI), 4, true, false};
  if(multi < 0)
    return multi > MULTI_MINUS
             ? Gps_step_code{std::uint32_t(MULTI - multi), times(multi), 5, false, false}
             : Gps_step_code{std::uint32_t(MULTI - MULTI_MINUS), times(MULTI_MINUS), 6, true, false};
  return {0, 0, 7, true, false};
}

// LASzip's colour prediction (RGB12 version 2, RGB14 version 3) from the `last` colour, for both
// directions: `mask` bits 0 to 5 say which bytes changed (red low, red high, green low, green high,
// blue low, blue high), bit 6 that green and blue differ from red; green and blue are predicted from
// red's change, clamped to a byte. `code(b, predicted)` is called for each changed byte b, in the
// coder's order (red low, red high, green low, blue low, green high, blue high), and returns the
// byte: a decoder adds the coded difference to the prediction, an encoder codes the difference of
// its byte from the prediction. Returns the colour.
template <typename Code>
std::array<std::uint16_t, 3> predict_rgb(unsigned mask, const std::array<std::uint16_t, 3>& last, const Code& code)
{
  auto clamp_byte = [](int v) { return unsigned(v <= 0 ? 0 : v >= 255 ? 255 : v); };
  unsigned byte[6]; // as the mask numbers them
  for(std::size_t b = 0; b < 6; ++b)
    byte[b] = (last[b / 2] >> (8 * (b % 2))) & 0xFFu;
  unsigned next[6];
  for(std::size_t half = 0; half < 2; ++half) // red's low byte, then its high one
    next[half] = (mask & (1u << half)) ? code(half, byte[half]) : byte[half];
  if(mask & (1u << 6))
    for(std::size_t half = 0; half < 2; ++half) // the low bytes of green and blue, then the high ones
    {
      int d = int(next[half]) - int(byte[half]);
      next[2 + half] = (mask & (4u << half)) ? code(2 + half, clamp_byte(d + int(byte[2 + half]))) : byte[2 + half];
      if(mask & (16u << half))
      {
        d = (d + int(next[2 + half]) - int(byte[2 + half])) / 2; // C division, towards 0, as the encoder's
        next[4 + half] = code(4 + half, clamp_byte(d + int(byte[4 + half])));
      }
      else
        next[4 + half] = byte[4 + half];
    }
  else
  {
    next[2] = next[4] = next[0];
    next[3] = next[5] = next[1];
  }
  return {{std::uint16_t(next[0] | (next[1] << 8)), std::uint16_t(next[2] | (next[3] << 8)),
           std::uint16_t(next[4] | (next[5] << 8))}};
}

// The mask predict_rgb() reads, for `rgb` after `last`.
inline unsigned rgb_change_mask(const std::array<std::uint16_t, 3>& last, const std::array<std::uint16_t, 3>& rgb)
{
  unsigned mask = 0;
  for(std::size_t b = 0; b < 6; ++b)
    if(((last[b / 2] ^ rgb[b / 2]) >> (8 * (b % 2))) & 0xFFu)
      mask |= 1u << b;
  if(rgb[0] != rgb[1] || rgb[0] != rgb[2])
    mask |= 1u << 6;
  return mask;
}

// One byte of a colour decoded or encoded by predict_rgb(): the byte b of `rgb`.
inline unsigned rgb_byte(const std::array<std::uint16_t, 3>& rgb, std::size_t b)
{
  return (rgb[b / 2] >> (8 * (b % 2))) & 0xFFu;
}

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_PREDICTORS_H
