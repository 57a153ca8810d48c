// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_LAYERED_ITEMS_H
#define LIDAR_IO_INTERNAL_LAZ_LAYERED_ITEMS_H

#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/point14_items.h>
#include <Lidar_io/internal/laz/predictors.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// A finished layer's bytes, or none when it codes no change.
inline void store_layer(const Arithmetic_encoder& encoder, bool changed, std::vector<unsigned char>& layer)
{
  if(changed)
    layer.assign(encoder.bytes().begin(), encoder.bytes().end());
  else
    layer.clear();
}

// The RGB14 item (one layer) and the RGBNIR14 item (two: RGB, then NIR), one model set and last
// colour per scanner channel. In item version 3 (the one read), a switch back to a channel met before
// in the chunk predicts that point from the previous channel's last colour and stores it there
// (LASzip's v3 encoder and decoder both do).
class Rgb14_coder
{
public:
  explicit Rgb14_coder(bool nir) : m_nir(nir) {}

  std::size_t layer_count() const { return m_nir ? 2 : 1; }

  void start(const unsigned char* first, const Layer_bytes* layers, unsigned channel)
  {
    m_has_rgb = !layers[0].empty();
    if(m_has_rgb)
      m_rgb.init(layers[0].begin, layers[0].end);
    m_has_nir = m_nir && !layers[1].empty();
    if(m_has_nir)
      m_nir_decoder.init(layers[1].begin, layers[1].end);
    m_active = {false, false, false, false};
    m_current = channel;
    activate(channel, load(first));
  }

  void decode(unsigned char* out, unsigned channel)
  {
    const unsigned from = switch_to(channel);
    Channel& ch = m_channels[m_current];
    std::array<std::uint16_t, 4>& last = m_channels[from].last;

    if(m_has_rgb)
    {
      const unsigned mask = m_rgb.decode_symbol(ch.used[0]);
      const std::array<std::uint16_t, 3> rgb =
        predict_rgb(mask, {{last[0], last[1], last[2]}}, [&](std::size_t b, unsigned predicted) {
          return (m_rgb.decode_symbol(ch.diff[b]) + predicted) & 0xFFu;
        });
      std::copy(rgb.begin(), rgb.end(), last.begin());
    }
    for(std::size_t i = 0; i < 3; ++i)
      store_little_endian<std::uint16_t>(out + 2 * i, last[i]);

    if(m_nir)
    {
      if(m_has_nir)
      {
        const unsigned sym = m_nir_decoder.decode_symbol(ch.nir_used[0]); // bit 0: low byte changed, bit 1: high
        const unsigned lo = (sym & 1u) ? (m_nir_decoder.decode_symbol(ch.nir_diff[0]) + (last[3] & 0xFFu)) & 0xFFu
                                       : last[3] & 0xFFu;
        const unsigned hi = (sym & 2u) ? (m_nir_decoder.decode_symbol(ch.nir_diff[1]) + (last[3] >> 8)) & 0xFFu
                                       : last[3] >> 8;
        last[3] = std::uint16_t(lo | (hi << 8));
      }
      store_little_endian<std::uint16_t>(out + 6, last[3]);
    }
  }

  // Encoding a chunk: start_encoding() with its first record's item, encode() with each next one,
  // then finish_encoding() stores the layers' bytes in layers[0, layer_count()) (none for a layer
  // that codes no change: LASzip writes it as 0 bytes, and a decoder keeps the first values).
  void start_encoding(const unsigned char* first, unsigned channel)
  {
    m_rgb_encoder.init();
    m_nir_encoder.init();
    m_rgb_changed = m_nir_changed = false;
    m_active = {false, false, false, false};
    m_current = channel;
    activate(channel, load(first));
  }

  void encode(const unsigned char* in, unsigned channel)
  {
    const unsigned from = switch_to(channel);
    Channel& ch = m_channels[m_current];
    std::array<std::uint16_t, 4>& last = m_channels[from].last;
    const std::array<std::uint16_t, 4> value = load(in);
    const std::array<std::uint16_t, 3> rgb{{value[0], value[1], value[2]}};
    const unsigned mask = rgb_change_mask({{last[0], last[1], last[2]}}, rgb);
    m_rgb_encoder.encode_symbol(ch.used[0], mask);
    predict_rgb(mask, {{last[0], last[1], last[2]}}, [&](std::size_t b, unsigned predicted) {
      const unsigned actual = rgb_byte(rgb, b);
      m_rgb_encoder.encode_symbol(ch.diff[b], (actual - predicted) & 0xFFu);
      return actual;
    });
    m_rgb_changed = m_rgb_changed || mask != 0;
    if(m_nir)
    {
      const unsigned changed = ((value[3] ^ last[3]) & 0xFFu ? 1u : 0u) | ((value[3] ^ last[3]) >> 8 ? 2u : 0u);
      m_nir_encoder.encode_symbol(ch.nir_used[0], changed);
      if(changed & 1u)
        m_nir_encoder.encode_symbol(ch.nir_diff[0], unsigned(value[3] - last[3]) & 0xFFu);
      if(changed & 2u)
        m_nir_encoder.encode_symbol(ch.nir_diff[1], unsigned((value[3] >> 8) - (last[3] >> 8)) & 0xFFu);
      m_nir_changed = m_nir_changed || changed != 0;
    }
    last = value;
  }

  void finish_encoding(std::vector<unsigned char>* layers)
  {
    m_rgb_encoder.done();
    store_layer(m_rgb_encoder, m_rgb_changed, layers[0]);
    if(m_nir)
    {
      m_nir_encoder.done();
      store_layer(m_nir_encoder, m_nir_changed, layers[1]);
    }
  }

private:
  std::array<std::uint16_t, 4> load(const unsigned char* item) const
  {
    std::array<std::uint16_t, 4> values{};
    for(std::size_t i = 0; i < (m_nir ? 4u : 3u); ++i)
      values[i] = load_little_endian<std::uint16_t>(item + 2 * i);
    return values;
  }

  // Makes `channel` current; returns the channel whose last colour predicts the next one.
  unsigned switch_to(unsigned channel)
  {
    unsigned from = m_current;
    if(channel != m_current)
    {
      m_current = channel;
      if(!m_active[channel])
      {
        activate(channel, m_channels[from].last);
        from = channel;
      }
    }
    return from;
  }

  struct Channel
  {
    std::array<std::uint16_t, 4> last{};
    Lazy_models<1, 128> used;
    Lazy_models<6, 256> diff;
    Lazy_models<1, 4> nir_used;
    Lazy_models<2, 256> nir_diff;
  };

  void activate(unsigned c, const std::array<std::uint16_t, 4>& from)
  {
    Channel& ch = m_channels[c];
    ch.last = from;
    ch.used.reset();
    ch.diff.reset();
    ch.nir_used.reset();
    ch.nir_diff.reset();
    m_active[c] = true;
  }

  bool m_nir;
  Arithmetic_decoder m_rgb, m_nir_decoder;
  bool m_has_rgb = false, m_has_nir = false;
  Arithmetic_encoder m_rgb_encoder, m_nir_encoder;
  bool m_rgb_changed = false, m_nir_changed = false;
  std::array<Channel, 4> m_channels;
  std::array<bool, 4> m_active{};
  unsigned m_current = 0;
};

// The BYTE14 item: `n` extra bytes, each its own layer, each coded as a byte difference. Channel
// switches as for Rgb14_coder.
class Byte14_coder
{
public:
  explicit Byte14_coder(std::size_t n) : m_n(n), m_decoders(n), m_has(n, 0)
  {
    for(Channel& ch : m_channels)
      ch.last.assign(n, 0);
  }

  std::size_t layer_count() const { return m_n; }

  void start(const unsigned char* first, const Layer_bytes* layers, unsigned channel)
  {
    for(std::size_t i = 0; i < m_n; ++i)
    {
      m_has[i] = !layers[i].empty();
      if(m_has[i])
        m_decoders[i].init(layers[i].begin, layers[i].end);
    }
    m_active = {false, false, false, false};
    m_current = channel;
    activate(channel, first);
  }

  void decode(unsigned char* out, unsigned channel)
  {
    const unsigned from = switch_to(channel);
    Channel& ch = m_channels[m_current];
    unsigned char* last = m_channels[from].last.data();
    for(std::size_t i = 0; i < m_n; ++i)
    {
      if(m_has[i])
        last[i] = static_cast<unsigned char>(last[i] + m_decoders[i].decode_symbol(ch.models[i]));
      out[i] = last[i];
    }
  }

  // Encoding a chunk, as Rgb14_coder's, of the bytes [begin, end) alone: each is a layer of its own,
  // so that groups of them can be encoded apart.
  void start_encoding(const unsigned char* first, unsigned channel, std::size_t begin, std::size_t end)
  {
    CGAL_precondition(begin < end && end <= m_n);
    m_begin = begin;
    m_end = end;
    m_encoders.resize(m_n);
    for(std::size_t i = begin; i < end; ++i)
      m_encoders[i].init();
    m_changed.assign(m_n, 0);
    m_has.assign(m_n, 0);
    std::fill(m_has.begin() + std::ptrdiff_t(begin), m_has.begin() + std::ptrdiff_t(end), 1); // fresh models
    m_active = {false, false, false, false};
    m_current = channel;
    activate(channel, first);
  }

  void encode(const unsigned char* in, unsigned channel)
  {
    const unsigned from = switch_to(channel);
    Channel& ch = m_channels[m_current];
    unsigned char* last = m_channels[from].last.data();
    for(std::size_t i = m_begin; i < m_end; ++i)
    {
      m_encoders[i].encode_symbol(ch.models[i], static_cast<unsigned char>(in[i] - last[i]));
      if(in[i] != last[i])
      {
        m_changed[i] = 1;
        last[i] = in[i];
      }
    }
  }

  // The layers of bytes [begin, end) to layers[0, end - begin).
  void finish_encoding(std::vector<unsigned char>* layers)
  {
    for(std::size_t i = m_begin; i < m_end; ++i)
    {
      m_encoders[i].done();
      store_layer(m_encoders[i], m_changed[i] != 0, layers[i - m_begin]);
    }
  }

private:
  unsigned switch_to(unsigned channel)
  {
    unsigned from = m_current;
    if(channel != m_current)
    {
      m_current = channel;
      if(!m_active[channel])
      {
        activate(channel, m_channels[from].last.data());
        from = channel;
      }
    }
    return from;
  }

  struct Channel
  {
    std::vector<unsigned char> last;
    std::vector<Arithmetic_model> models; // 256 symbols each, made on the channel's first use
  };

  void activate(unsigned c, const unsigned char* from)
  {
    Channel& ch = m_channels[c];
    std::copy(from, from + m_n, ch.last.begin()); // `from` may be another channel's: distinct storage
    if(ch.models.empty())
      ch.models.assign(m_n, Arithmetic_model(256));
    for(std::size_t i = 0; i < m_n; ++i)
      if(m_has[i])
        ch.models[i].init();
    m_active[c] = true;
  }

  std::size_t m_n;
  std::vector<Arithmetic_decoder> m_decoders;
  std::vector<unsigned char> m_has;
  std::vector<Arithmetic_encoder> m_encoders;
  std::vector<unsigned char> m_changed;
  std::size_t m_begin = 0, m_end = 0; // the bytes encoded
  std::array<Channel, 4> m_channels;
  std::array<bool, 4> m_active{};
  unsigned m_current = 0;
};

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_LAYERED_ITEMS_H
