// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_LAYERED_CHUNK_DECODER_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_LAYERED_CHUNK_DECODER_H

#include <CGAL/Sigmoid_neighborhoods/IO/little_endian.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/arithmetic_decoder.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/laz_items.h>
#include <CGAL/Sigmoid_neighborhoods/IO/internal/laz/point14_items.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {
namespace laz {

// The RGB14 item (one layer) and the RGBNIR14 item (two: RGB, then NIR), one model set and last
// colour per scanner channel. In item version 3 (the one read), a switch back to a channel met before
// in the chunk predicts that point from the previous channel's last colour and stores it there
// (LASzip's v3 encoder and decoder both do).
class Rgb14_decoder
{
public:
  explicit Rgb14_decoder(bool nir) : m_nir(nir) {}

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
    std::array<std::uint16_t, 4> values{};
    for(std::size_t i = 0; i < (m_nir ? 4u : 3u); ++i)
      values[i] = load_little_endian<std::uint16_t>(first + 2 * i);
    m_current = channel;
    activate(channel, values);
  }

  void decode(unsigned char* out, unsigned channel)
  {
    unsigned from = m_current; // whose last colour predicts this one
    if(channel != m_current)
    {
      m_current = channel;
      if(!m_active[channel])
      {
        activate(channel, m_channels[from].last);
        from = channel;
      }
    }
    Channel& ch = m_channels[m_current];
    std::array<std::uint16_t, 4>& last = m_channels[from].last;

    if(m_has_rgb)
    {
      const unsigned mask = m_rgb.decode_symbol(ch.used[0]);
      const std::array<std::uint16_t, 3> rgb = predict_rgb(mask, {{last[0], last[1], last[2]}}, [&](std::size_t byte) {
        return m_rgb.decode_symbol(ch.diff[byte]);
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

private:
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
  std::array<Channel, 4> m_channels;
  std::array<bool, 4> m_active{};
  unsigned m_current = 0;
};

// The BYTE14 item: `n` extra bytes, each its own layer, each coded as a byte difference. Channel
// switches as for Rgb14_decoder.
class Byte14_decoder
{
public:
  explicit Byte14_decoder(std::size_t n) : m_n(n), m_decoders(n), m_has(n, 0)
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
    Channel& ch = m_channels[m_current];
    unsigned char* last = m_channels[from].last.data();
    for(std::size_t i = 0; i < m_n; ++i)
    {
      if(m_has[i])
        last[i] = static_cast<unsigned char>(last[i] + m_decoders[i].decode_symbol(ch.models[i]));
      out[i] = last[i];
    }
  }

private:
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
  std::array<Channel, 4> m_channels;
  std::array<bool, 4> m_active{};
  unsigned m_current = 0;
};

// A chunk of LASzip's layered compressor (compressor 3: LAS 1.4 point formats 6 to 10), decoded into
// LAS records. A chunk is, in this order:
//   - its first point, raw: a whole record as the LAS file stores it;
//   - its point count (uint32);
//   - the byte count (uint32) of every layer of every item, items in record order;
//   - the layers' bytes, in the same order.
// Every layer is an arithmetic-coded stream of its own; a layer of 0 bytes is a field that keeps its
// first value through the chunk. Nothing carries over from one chunk to the next.
class Layered_chunk_decoder
{
public:
  explicit Layered_chunk_decoder(const std::vector<Item>& items)
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
        for(std::size_t l = 0; l < Point14_decoder::LAYER_COUNT; ++l)
          m_layer_names.push_back("POINT14 " + std::string(Point14_decoder::layer_name(l)));
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
        m_parts.push_back(part);
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

private:
  // An item after POINT14, and where its bytes and layers lie.
  struct Part
  {
    std::uint16_t type = 0;
    std::size_t offset = 0, index = 0, first_layer = 0;
  };

  std::optional<Point14_decoder> m_point;
  std::vector<Rgb14_decoder> m_colors;
  std::vector<Byte14_decoder> m_bytes;
  std::vector<Part> m_parts;
  std::vector<std::string> m_layer_names; // for the messages
  std::vector<Layer_bytes> m_layers;      // this chunk's, one per layer name
  std::size_t m_record_length = 0;
};

} // namespace laz
} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_INTERNAL_LAZ_LAYERED_CHUNK_DECODER_H
