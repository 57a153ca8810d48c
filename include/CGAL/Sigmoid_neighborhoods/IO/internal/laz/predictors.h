// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_PREDICTORS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_PREDICTORS_H

#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/arithmetic_decoder.h>

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <optional>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
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

// LASzip's colour prediction (RGB12 version 2, RGB14 version 3) from the `last` colour: `mask` bits
// 0 to 5 say which bytes changed (red low, red high, green low, green high, blue low, blue high), bit
// 6 that green and blue differ from red; green and blue are predicted from red's change, clamped to a
// byte. `correction(b)` gives the coded difference of byte b, called in the coder's order (red low,
// red high, green low, blue low, green high, blue high).
template <typename Correction>
std::array<std::uint16_t, 3> predict_rgb(unsigned mask, const std::array<std::uint16_t, 3>& last,
                                         const Correction& correction)
{
  auto clamp_byte = [](int v) { return unsigned(v <= 0 ? 0 : v >= 255 ? 255 : v); };
  unsigned byte[6]; // as the mask numbers them
  for(std::size_t b = 0; b < 6; ++b)
    byte[b] = (last[b / 2] >> (8 * (b % 2))) & 0xFFu;
  unsigned next[6];
  for(std::size_t half = 0; half < 2; ++half) // red's low byte, then its high one
    next[half] = (mask & (1u << half)) ? (correction(half) + byte[half]) & 0xFFu : byte[half];
  if(mask & (1u << 6))
    for(std::size_t half = 0; half < 2; ++half) // the low bytes of green and blue, then the high ones
    {
      int d = int(next[half]) - int(byte[half]);
      next[2 + half] =
        (mask & (4u << half)) ? (correction(2 + half) + clamp_byte(d + int(byte[2 + half]))) & 0xFFu : byte[2 + half];
      if(mask & (16u << half))
      {
        d = (d + int(next[2 + half]) - int(byte[2 + half])) / 2; // C division, towards 0, as the encoder's
        next[4 + half] = (correction(4 + half) + clamp_byte(d + int(byte[4 + half]))) & 0xFFu;
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

} // namespace laz
} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_PREDICTORS_H
