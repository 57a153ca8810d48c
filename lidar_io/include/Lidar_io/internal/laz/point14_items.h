// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_POINT14_ITEMS_H
#define LIDAR_IO_INTERNAL_LAZ_POINT14_ITEMS_H

#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/laz/arithmetic_coder.h>
#include <Lidar_io/internal/laz/integer_coder.h>
#include <Lidar_io/internal/laz/laz_items.h>
#include <Lidar_io/internal/laz/predictors.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// The POINT14 item of LASzip's layered compression (LAZ 1.4, point formats 6 to 10; item version
// 3) and what the other layered items share (RGB14, RGBNIR14 and BYTE14 are in
// layered_items.h). Every field of a chunk is coded in its own layer, each layer by its own
// arithmetic coder, and all models are kept once per scanner channel (4): a point is predicted from
// the last point of its own channel. POINT14 decodes first and tells the other items the channel.

// One layer's bytes within a chunk; empty when the field never changes in the chunk.
struct Layer_bytes
{
  const unsigned char* begin = nullptr;
  const unsigned char* end = nullptr;
  bool empty() const { return begin == end; }
};

// The 30 bytes of a LAS 1.4 point (formats 6 to 10), kept as the record stores them.
struct Point14_record
{
  std::uint32_t x = 0, y = 0, z = 0; // unsigned: coordinates change by wrapping 32-bit additions
  std::uint16_t intensity = 0;
  std::uint8_t returns = 0; // return number in bits 0-3, number of returns in bits 4-7
  std::uint8_t flags = 0;   // classification flags 0-3, scanner channel 4-5, scan direction 6, edge of flight line 7
  std::uint8_t classification = 0, user_data = 0;
  std::uint16_t scan_angle = 0, point_source = 0;
  std::uint64_t gps_time = 0; // the double's bits: LASzip codes GPS times as 64-bit integers
  bool gps_time_changed = false; // not in the record: the next point's context

  static constexpr std::size_t size = 30;

  void read(const unsigned char* b)
  {
    x = load_little_endian<std::uint32_t>(b);
    y = load_little_endian<std::uint32_t>(b + 4);
    z = load_little_endian<std::uint32_t>(b + 8);
    intensity = load_little_endian<std::uint16_t>(b + 12);
    returns = b[14];
    flags = b[15];
    classification = b[16];
    user_data = b[17];
    scan_angle = load_little_endian<std::uint16_t>(b + 18);
    point_source = load_little_endian<std::uint16_t>(b + 20);
    gps_time = load_little_endian<std::uint64_t>(b + 22);
    gps_time_changed = false;
  }

  void write(unsigned char* b) const
  {
    store_little_endian<std::uint32_t>(b, x);
    store_little_endian<std::uint32_t>(b + 4, y);
    store_little_endian<std::uint32_t>(b + 8, z);
    store_little_endian<std::uint16_t>(b + 12, intensity);
    b[14] = returns;
    b[15] = flags;
    b[16] = classification;
    b[17] = user_data;
    store_little_endian<std::uint16_t>(b + 18, scan_angle);
    store_little_endian<std::uint16_t>(b + 20, point_source);
    store_little_endian<std::uint64_t>(b + 22, gps_time);
  }

  unsigned return_number() const { return returns & 15u; }
  unsigned number_of_returns() const { return unsigned(returns) >> 4; }
  unsigned scanner_channel() const { return (flags >> 4) & 3u; }
};

// LASzip's 6 classes of (number of returns n, return number r), rows n, columns r: single, first of
// two, last of two, first of more, intermediate, last of more; the pairs that cannot be are spread
// over the same classes. A property of the format: the encoder's table, as it uses it.
inline const std::uint8_t (&return_map_6ctx())[16][16]
{
  static const std::uint8_t map[16][16] = {
    {0, 1, 2, 3, 4, 5, 3, 4, 4, 5, 5, 5, 5, 5, 5, 5}, {1, 0, 1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3},
    {2, 1, 2, 4, 4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3}, {3, 3, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4}, {5, 3, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {3, 3, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4}, {4, 3, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4}, {5, 3, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4}, {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 4, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4, 4}, {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5}, {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5}};
  return map;
}

// How deep a return lies in its pulse, |n - r| capped at 7: LASzip's 8 contexts of the Z prediction.
inline unsigned return_level_8ctx(unsigned n, unsigned r)
{
  const unsigned d = n > r ? n - r : r - n;
  return d < 7 ? d : 7;
}

// The POINT14 item, version 3: nine layers.
class Point14_coder
{
public:
  enum Layer_index
  {
    XY_LAYER, // changed-values bits, scanner channel, returns, X and Y
    Z_LAYER,
    CLASSIFICATION_LAYER,
    FLAGS_LAYER,
    INTENSITY_LAYER,
    SCAN_ANGLE_LAYER,
    USER_DATA_LAYER,
    POINT_SOURCE_LAYER,
    GPS_TIME_LAYER,
    LAYER_COUNT
  };

  static const char* layer_name(std::size_t i)
  {
    static const char* const names[LAYER_COUNT] = {"channel, returns and X/Y", "Z",         "classification",
                                                   "flags",                    "intensity", "scan angle",
                                                   "user data",                "point source ID", "GPS time"};
    return names[i];
  }

  Point14_coder() = default;

  // Starts a chunk from its first point (raw) and its nine layers; returns the first point's channel.
  unsigned start(const unsigned char* first, const Layer_bytes* layers)
  {
    if(layers[XY_LAYER].empty())
      throw Decode_error("the POINT14 " + std::string(layer_name(XY_LAYER)) + " layer of a chunk of several points is empty");
    for(std::size_t i = 0; i < LAYER_COUNT; ++i)
    {
      m_has[i] = !layers[i].empty();
      if(m_has[i])
        m_decoders[i].init(layers[i].begin, layers[i].end);
    }
    return start_from(first);
  }

  // Decodes the next point into out[0, 30); returns its scanner channel.
  unsigned decode(unsigned char* out)
  {
    Channel* ch = &*m_channels[m_current];
    Point14_record* last = &ch->last;
    Arithmetic_decoder& xy = m_decoders[XY_LAYER];

    // What changed is coded in the context of how the channel's last point returned.
    const unsigned lpr = (last->return_number() == 1 ? 1u : 0u) |
                         (last->return_number() >= last->number_of_returns() ? 2u : 0u) |
                         (last->gps_time_changed ? 4u : 0u);
    const unsigned changed = xy.decode_symbol(ch->changed_values[lpr]);

    if(changed & (1u << 6)) // another scanner channel: continue from that channel's last point
    {
      const unsigned step = xy.decode_symbol(ch->scanner_channel[0]); // 0..2: the channel moves by 1 to 3
      const unsigned next = (m_current + step + 1) & 3u;
      if(!m_active[next])
        activate(next, *last);
      m_current = next;
      ch = &*m_channels[next];
      last = &ch->last;
      last->flags = std::uint8_t((last->flags & ~0x30u) | (next << 4));
    }
    const bool point_source_changed = (changed & (1u << 5)) != 0;
    const bool gps_changed = (changed & (1u << 4)) != 0;
    const bool scan_angle_changed = (changed & (1u << 3)) != 0;

    const unsigned last_n = last->number_of_returns(), last_r = last->return_number();
    unsigned n = last_n;
    if(changed & (1u << 2))
      n = xy.decode_symbol(ch->number_of_returns[last_n]); // 16 symbols
    unsigned r = last_r;
    switch(changed & 3u)
    {
    case 0: break;
    case 1: r = (last_r + 1) & 15u; break;
    case 2: r = (last_r + 15) & 15u; break;
    default:
      if(gps_changed)
        r = xy.decode_symbol(ch->return_number[last_r]); // 16 symbols
      else
        r = (last_r + xy.decode_symbol(ch->return_number_gps_same[0]) + 2) & 15u;
    }
    last->returns = std::uint8_t(r | (n << 4));

    const unsigned m = return_map_6ctx()[n][r];
    const unsigned level = return_level_8ctx(n, r);
    const unsigned cpr = (r == 1 ? 1u : 0u) | (r >= n ? 2u : 0u); // first, last, single or in between
    const unsigned single = n == 1 ? 1u : 0u;

    const unsigned xy_slot = (m << 1) | (gps_changed ? 1u : 0u);
    std::int32_t diff = ch->dx.decompress(m_decoders[XY_LAYER], ch->x_median[xy_slot].get(), single);
    last->x += std::uint32_t(diff);
    ch->x_median[xy_slot].add(diff);
    unsigned k = ch->dx.k();
    diff = ch->dy.decompress(m_decoders[XY_LAYER], ch->y_median[xy_slot].get(), single + (k < 20 ? (k & ~1u) : 20u));
    last->y += std::uint32_t(diff);
    ch->y_median[xy_slot].add(diff);

    if(m_has[Z_LAYER])
    {
      k = (ch->dx.k() + ch->dy.k()) / 2;
      const std::int32_t z = ch->z.decompress(m_decoders[Z_LAYER], ch->last_z[level], single + (k < 18 ? (k & ~1u) : 18u));
      last->z = std::uint32_t(z);
      ch->last_z[level] = z;
    }
    if(m_has[CLASSIFICATION_LAYER])
    {
      const unsigned context = ((last->classification & 0x1Fu) << 1) | (cpr == 3 ? 1u : 0u);
      last->classification =
        std::uint8_t(m_decoders[CLASSIFICATION_LAYER].decode_symbol(ch->classification[context]));
    }
    if(m_has[FLAGS_LAYER])
    {
      // The coded 6 bits: edge of flight line, scan direction, then the 4 classification flags.
      const unsigned context = ((last->flags >> 2) & 0x30u) | (last->flags & 0x0Fu);
      const unsigned f = m_decoders[FLAGS_LAYER].decode_symbol(ch->flags[context]);
      last->flags = std::uint8_t(((f & 0x30u) << 2) | (last->flags & 0x30u) | (f & 0x0Fu));
    }
    if(m_has[INTENSITY_LAYER])
    {
      const unsigned slot = (cpr << 1) | (gps_changed ? 1u : 0u);
      const std::uint16_t v = std::uint16_t(ch->intensity.decompress(m_decoders[INTENSITY_LAYER], ch->last_intensity[slot], cpr));
      ch->last_intensity[slot] = v;
      last->intensity = v;
    }
    if(m_has[SCAN_ANGLE_LAYER] && scan_angle_changed)
      last->scan_angle = std::uint16_t(
        ch->scan_angle.decompress(m_decoders[SCAN_ANGLE_LAYER], std::int16_t(last->scan_angle), gps_changed ? 1u : 0u)); // signed, as coded
    if(m_has[USER_DATA_LAYER])
      last->user_data = std::uint8_t(m_decoders[USER_DATA_LAYER].decode_symbol(ch->user_data[last->user_data >> 2]));
    if(m_has[POINT_SOURCE_LAYER] && point_source_changed)
      last->point_source = std::uint16_t(ch->point_source.decompress(m_decoders[POINT_SOURCE_LAYER], last->point_source));
    if(m_has[GPS_TIME_LAYER] && gps_changed)
    {
      decode_gps_time(*ch);
      last->gps_time = ch->gps_last[ch->gps_current];
    }
    last->write(out);
    last->gps_time_changed = gps_changed;
    return m_current;
  }

  // Encoding a chunk: start_encoding() with its first record, encode() with each next one (it returns
  // the point's scanner channel: the record's), then finish_encoding() stores the nine layers' bytes
  // in layers[0, 9) (none for a layer that codes no change, written as 0 bytes; the XY and Z layers
  // are always written).
  unsigned start_encoding(const unsigned char* first)
  {
    for(Arithmetic_encoder& e : m_encoders)
      e.init();
    m_changed.fill(false);
    m_has.fill(true); // every model fresh
    return start_from(first);
  }

  unsigned encode(const unsigned char* in)
  {
    Point14_record item;
    item.read(in);
    Channel* ch = &*m_channels[m_current];
    Arithmetic_encoder& xy = m_encoders[XY_LAYER];
    const Point14_record& before = ch->last;
    const unsigned lpr = (before.return_number() == 1 ? 1u : 0u) |
                         (before.return_number() >= before.number_of_returns() ? 2u : 0u) |
                         (before.gps_time_changed ? 4u : 0u);
    // The changes are those from the last point of the point's own channel, when it was met before.
    const unsigned channel = item.scanner_channel();
    const Point14_record& last = channel != m_current && m_active[channel] ? m_channels[channel]->last : before;
    // GPS times compared as their bits (LASzip compares doubles: the same but for -0 after +0, which
    // it would not record)
    const bool gps_changed = item.gps_time != last.gps_time;
    const unsigned last_n = last.number_of_returns(), last_r = last.return_number();
    const unsigned n = item.number_of_returns(), r = item.return_number();
    unsigned changed = (channel != m_current ? 64u : 0u) | (item.point_source != last.point_source ? 32u : 0u) |
                       (gps_changed ? 16u : 0u) | (item.scan_angle != last.scan_angle ? 8u : 0u) |
                       (n != last_n ? 4u : 0u);
    if(r != last_r)
      changed |= r == ((last_r + 1) & 15u) ? 1u : r == ((last_r + 15) & 15u) ? 2u : 3u;
    xy.encode_symbol(ch->changed_values[lpr], changed);
    if(changed & 64u)
    {
      xy.encode_symbol(ch->scanner_channel[0], ((channel - m_current) & 3u) - 1u);
      if(!m_active[channel])
        activate(channel, before);
      m_current = channel;
      ch = &*m_channels[channel];
    }
    Point14_record& reference = ch->last; // `last`, or its copy in a channel just met
    if(changed & 4u)
      xy.encode_symbol(ch->number_of_returns[last_n], n);
    if((changed & 3u) == 3u)
    {
      if(gps_changed)
        xy.encode_symbol(ch->return_number[last_r], r);
      else
        xy.encode_symbol(ch->return_number_gps_same[0], (r - last_r - 2) & 15u);
    }

    const unsigned m = return_map_6ctx()[n][r];
    const unsigned level = return_level_8ctx(n, r);
    const unsigned cpr = (r == 1 ? 1u : 0u) | (r >= n ? 2u : 0u);
    const unsigned single = n == 1 ? 1u : 0u;

    const unsigned xy_slot = (m << 1) | (gps_changed ? 1u : 0u);
    std::int32_t diff = std::int32_t(item.x - reference.x);
    ch->dx.compress(xy, ch->x_median[xy_slot].get(), diff, single);
    ch->x_median[xy_slot].add(diff);
    unsigned k = ch->dx.k();
    diff = std::int32_t(item.y - reference.y);
    ch->dy.compress(xy, ch->y_median[xy_slot].get(), diff, single + (k < 20 ? (k & ~1u) : 20u));
    ch->y_median[xy_slot].add(diff);

    k = (ch->dx.k() + ch->dy.k()) / 2;
    ch->z.compress(m_encoders[Z_LAYER], ch->last_z[level], std::int32_t(item.z), single + (k < 18 ? (k & ~1u) : 18u));
    ch->last_z[level] = std::int32_t(item.z);

    m_changed[CLASSIFICATION_LAYER] = m_changed[CLASSIFICATION_LAYER] || item.classification != reference.classification;
    m_encoders[CLASSIFICATION_LAYER].encode_symbol(
      ch->classification[((reference.classification & 0x1Fu) << 1) | (cpr == 3 ? 1u : 0u)], item.classification);

    const unsigned last_flags = ((reference.flags >> 2) & 0x30u) | (reference.flags & 0x0Fu);
    const unsigned flags = ((item.flags >> 2) & 0x30u) | (item.flags & 0x0Fu);
    m_changed[FLAGS_LAYER] = m_changed[FLAGS_LAYER] || flags != last_flags;
    m_encoders[FLAGS_LAYER].encode_symbol(ch->flags[last_flags], flags);

    m_changed[INTENSITY_LAYER] = m_changed[INTENSITY_LAYER] || item.intensity != reference.intensity;
    const unsigned intensity_slot = (cpr << 1) | (gps_changed ? 1u : 0u);
    ch->intensity.compress(m_encoders[INTENSITY_LAYER], ch->last_intensity[intensity_slot], item.intensity, cpr);
    ch->last_intensity[intensity_slot] = item.intensity;

    if(changed & 8u)
    {
      m_changed[SCAN_ANGLE_LAYER] = true;
      ch->scan_angle.compress(m_encoders[SCAN_ANGLE_LAYER], std::int16_t(reference.scan_angle),
                              std::int16_t(item.scan_angle), gps_changed ? 1u : 0u);
    }

    m_changed[USER_DATA_LAYER] = m_changed[USER_DATA_LAYER] || item.user_data != reference.user_data;
    m_encoders[USER_DATA_LAYER].encode_symbol(ch->user_data[reference.user_data >> 2], item.user_data);

    if(changed & 32u)
    {
      m_changed[POINT_SOURCE_LAYER] = true;
      ch->point_source.compress(m_encoders[POINT_SOURCE_LAYER], reference.point_source, item.point_source);
    }
    if(gps_changed)
    {
      m_changed[GPS_TIME_LAYER] = true;
      encode_gps_time(*ch, item.gps_time);
    }
    reference = item;
    reference.gps_time_changed = gps_changed;
    return m_current;
  }

  void finish_encoding(std::vector<unsigned char>* layers)
  {
    m_changed[XY_LAYER] = m_changed[Z_LAYER] = true;
    for(std::size_t i = 0; i < LAYER_COUNT; ++i)
    {
      m_encoders[i].done();
      if(m_changed[i])
        layers[i].assign(m_encoders[i].bytes().begin(), m_encoders[i].bytes().end());
      else
        layers[i].clear();
    }
  }

private:
  // Every channel unused but the first record's, which starts from it; returns that channel.
  unsigned start_from(const unsigned char* first)
  {
    m_active = {false, false, false, false};
    Point14_record record;
    record.read(first);
    m_current = record.scanner_channel();
    activate(m_current, record);
    return m_current;
  }

  // The GPS time coder: a change is coded as a multiple of the last difference, as a new
  // difference, as a jump to one of four remembered time sequences, or in full.
  static constexpr int GPS_MULTI = 500;         // codes 2 .. 499: that many times the last difference
  static constexpr int GPS_MULTI_MINUS = -10;   // codes 501 .. 510: -1 .. -10 times it
  static constexpr unsigned GPS_FULL = unsigned(GPS_MULTI - GPS_MULTI_MINUS + 1);    // 511: the time in full
  static constexpr unsigned GPS_SYMBOLS = unsigned(GPS_MULTI - GPS_MULTI_MINUS + 5); // 515: then 3 jumps

  struct Channel
  {
    Channel() : dx(32, 2), dy(32, 22), z(32, 20), intensity(16, 4), scan_angle(16, 2), point_source(16), gps(32, 9) {}

    Point14_record last;
    std::array<std::uint16_t, 8> last_intensity{};
    std::array<std::int32_t, 8> last_z{};
    std::array<Streaming_median5, 12> x_median, y_median;

    std::array<std::uint64_t, 4> gps_last{};
    std::array<std::int32_t, 4> gps_diff{};
    std::array<std::int32_t, 4> gps_extremes{}; // how often in a row the difference was far from the last one
    unsigned gps_current = 0, gps_next = 0;

    Lazy_models<8, 128> changed_values;
    Lazy_models<1, 3> scanner_channel;
    Lazy_models<16, 16> number_of_returns;
    Lazy_models<16, 16> return_number;
    Lazy_models<1, 13> return_number_gps_same;
    Lazy_models<64, 256> classification;
    Lazy_models<64, 64> flags;
    Lazy_models<64, 256> user_data;
    Lazy_models<1, GPS_SYMBOLS> gps_multi;
    Lazy_models<1, 5> gps_0diff;

    Integer_coder dx, dy, z, intensity, scan_angle, point_source, gps;
  };

  // A channel's first use in a chunk: every model fresh, every prediction from `from`.
  void activate(unsigned c, const Point14_record& from)
  {
    if(!m_channels[c])
      m_channels[c].emplace();
    Channel& ch = *m_channels[c];
    ch.last = from;
    ch.last.gps_time_changed = false;
    ch.last_intensity.fill(from.intensity);
    ch.last_z.fill(std::int32_t(from.z));
    for(Streaming_median5& s : ch.x_median)
      s.reset();
    for(Streaming_median5& s : ch.y_median)
      s.reset();
    ch.gps_last = {from.gps_time, 0, 0, 0};
    ch.gps_diff = {0, 0, 0, 0};
    ch.gps_extremes = {0, 0, 0, 0};
    ch.gps_current = ch.gps_next = 0;
    ch.changed_values.reset();
    ch.scanner_channel.reset();
    ch.number_of_returns.reset();
    ch.return_number.reset();
    ch.return_number_gps_same.reset();
    ch.classification.reset();
    ch.flags.reset();
    ch.user_data.reset();
    ch.gps_multi.reset();
    ch.gps_0diff.reset();
    ch.dx.init();
    ch.dy.init();
    // The other decompressors only ever decode from their own layers.
    if(m_has[Z_LAYER])
      ch.z.init();
    if(m_has[INTENSITY_LAYER])
      ch.intensity.init();
    if(m_has[SCAN_ANGLE_LAYER])
      ch.scan_angle.init();
    if(m_has[POINT_SOURCE_LAYER])
      ch.point_source.init();
    if(m_has[GPS_TIME_LAYER])
      ch.gps.init();
    m_active[c] = true;
  }

  // 32-bit products of the predictions wrap, as the encoder's do.
  static std::int32_t times(std::int32_t a, std::int32_t b) { return std::int32_t(std::uint32_t(a) * std::uint32_t(b)); }

  static void count_extreme(Channel& ch, unsigned s, std::int32_t diff)
  {
    // A difference far from the last one several times in a row becomes the new reference.
    if(++ch.gps_extremes[s] > 3)
    {
      ch.gps_diff[s] = diff;
      ch.gps_extremes[s] = 0;
    }
  }

  void decode_full_gps_time(Channel& ch)
  {
    const unsigned s = ch.gps_current;
    ch.gps_next = (ch.gps_next + 1) & 3u;
    const std::int32_t high = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], std::int32_t(std::uint32_t(ch.gps_last[s] >> 32)), 8);
    ch.gps_last[ch.gps_next] = (std::uint64_t(std::uint32_t(high)) << 32) | m_decoders[GPS_TIME_LAYER].read_int();
    ch.gps_current = ch.gps_next;
    ch.gps_diff[ch.gps_current] = 0;
    ch.gps_extremes[ch.gps_current] = 0;
  }

  // A new time in sequence `ch.gps_current`: as decode_gps_time() reads it (LASzip's choices).
  void encode_gps_time(Channel& ch, std::uint64_t time)
  {
    Arithmetic_encoder& e = m_encoders[GPS_TIME_LAYER];
    for(;;) // at most one jump: the sequence jumped to holds a time within 32 bits
    {
      const unsigned s = ch.gps_current;
      std::int32_t diff;
      if(gps_time_difference(time, ch.gps_last[s], diff))
      {
        if(ch.gps_diff[s] == 0)
        {
          e.encode_symbol(ch.gps_0diff[0], 0);
          ch.gps.compress(e, 0, diff, 0);
          ch.gps_diff[s] = diff;
          ch.gps_extremes[s] = 0;
        }
        else
        {
          const Gps_step_code c = gps_step_code(diff, ch.gps_diff[s]);
          e.encode_symbol(ch.gps_multi[0], c.symbol);
          ch.gps.compress(e, c.prediction, diff, c.context);
          if(c.on_step)
            ch.gps_extremes[s] = 0;
          else if(c.off_step)
            count_extreme(ch, s, diff);
        }
        ch.gps_last[s] = time;
        return;
      }
      unsigned other = 1;
      std::int32_t unused;
      while(other < 4 && !gps_time_difference(time, ch.gps_last[(s + other) & 3u], unused))
        ++other;
      const bool after_zero = ch.gps_diff[s] == 0;
      if(other < 4)
      {
        if(after_zero)
          e.encode_symbol(ch.gps_0diff[0], other + 1);
        else
          e.encode_symbol(ch.gps_multi[0], GPS_FULL + other);
        ch.gps_current = (s + other) & 3u;
        continue;
      }
      if(after_zero)
        e.encode_symbol(ch.gps_0diff[0], 1);
      else
        e.encode_symbol(ch.gps_multi[0], GPS_FULL);
      ch.gps.compress(e, std::int32_t(std::uint32_t(ch.gps_last[s] >> 32)), std::int32_t(std::uint32_t(time >> 32)), 8);
      e.write_int(std::uint32_t(time));
      ch.gps_next = (ch.gps_next + 1) & 3u;
      ch.gps_current = ch.gps_next;
      ch.gps_diff[ch.gps_current] = 0;
      ch.gps_extremes[ch.gps_current] = 0;
      ch.gps_last[ch.gps_current] = time;
      return;
    }
  }

  void decode_gps_time(Channel& ch)
  {
    Arithmetic_decoder& d = m_decoders[GPS_TIME_LAYER];
    // An encoder jumps to another sequence only to one where the time then fits; more than one jump
    // for a point is damage (and bounding the loop keeps such damage cheap).
    for(int jumps = 0; jumps < 4; ++jumps)
    {
      const unsigned s = ch.gps_current;
      if(ch.gps_diff[s] == 0)
      {
        const unsigned code = d.decode_symbol(ch.gps_0diff[0]); // 0..4
        if(code == 0)
        {
          ch.gps_diff[s] = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], 0, 0);
          ch.gps_last[s] += std::uint64_t(std::int64_t(ch.gps_diff[s]));
          ch.gps_extremes[s] = 0;
          return;
        }
        if(code == 1)
        {
          decode_full_gps_time(ch);
          return;
        }
        ch.gps_current = (s + code - 1) & 3u;
        continue;
      }
      const unsigned code = d.decode_symbol(ch.gps_multi[0]); // 0..514
      if(code == 1)
      {
        ch.gps_last[s] += std::uint64_t(std::int64_t(ch.gps.decompress(m_decoders[GPS_TIME_LAYER], ch.gps_diff[s], 1)));
        ch.gps_extremes[s] = 0;
        return;
      }
      if(code < GPS_FULL)
      {
        std::int32_t diff;
        if(code == 0)
        {
          diff = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], 0, 7);
          count_extreme(ch, s, diff);
        }
        else if(code < unsigned(GPS_MULTI))
          diff = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], times(std::int32_t(code), ch.gps_diff[s]), code < 10 ? 2 : 3);
        else if(code == unsigned(GPS_MULTI))
        {
          diff = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], times(GPS_MULTI, ch.gps_diff[s]), 4);
          count_extreme(ch, s, diff);
        }
        else
        {
          const std::int32_t multi = GPS_MULTI - std::int32_t(code); // -1 .. -10
          if(multi > GPS_MULTI_MINUS)
            diff = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], times(multi, ch.gps_diff[s]), 5);
          else
          {
            diff = ch.gps.decompress(m_decoders[GPS_TIME_LAYER], times(GPS_MULTI_MINUS, ch.gps_diff[s]), 6);
            count_extreme(ch, s, diff);
          }
        }
        ch.gps_last[s] += std::uint64_t(std::int64_t(diff));
        return;
      }
      if(code == GPS_FULL)
      {
        decode_full_gps_time(ch);
        return;
      }
      ch.gps_current = (s + code - GPS_FULL) & 3u;
    }
    throw Decode_error("a GPS time that jumps between time sequences again and again");
  }

  std::array<Arithmetic_decoder, LAYER_COUNT> m_decoders;
  std::array<bool, LAYER_COUNT> m_has{};
  std::array<Arithmetic_encoder, LAYER_COUNT> m_encoders;
  std::array<bool, LAYER_COUNT> m_changed{};
  std::array<std::optional<Channel>, 4> m_channels;
  std::array<bool, 4> m_active{};
  unsigned m_current = 0;
};

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_POINT14_ITEMS_H
