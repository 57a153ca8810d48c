// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_ARITHMETIC_CODER_H
#define LIDAR_IO_INTERNAL_LAZ_ARITHMETIC_CODER_H

#include <Lidar_io/internal/laz/laz_items.h>

#include <CGAL/assertions.h>

#include <cstdint>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// The range coder of LASzip (an adaptation of Amir Said's FastAC: 32-bit interval, adaptive models
// that rebuild their cumulative counts only now and then), both directions: the models are shared,
// Arithmetic_decoder reads and Arithmetic_encoder writes. Compressed LAZ data is defined by this
// coder bit for bit, so every constant and rounding below is the format's, not a tuning choice.
namespace coder {
constexpr std::uint32_t MIN_LENGTH = 0x01000000u; // below it the interval takes a byte more
constexpr std::uint32_t MAX_LENGTH = 0xFFFFFFFFu; // the interval when a stream starts
constexpr std::uint32_t BIT_LENGTH_SHIFT = 13;    // bit models: probabilities in 1/8192
constexpr std::uint32_t BIT_MAX_COUNT = 1u << 13; // halve the counts past it
constexpr std::uint32_t SYMBOL_LENGTH_SHIFT = 15; // symbol models: cumulative counts in 1/32768
constexpr std::uint32_t SYMBOL_MAX_COUNT = 1u << 15;
constexpr std::uint32_t MAX_SYMBOLS = 1u << 11;
} // namespace coder

// An adaptive model of one binary decision.
class Arithmetic_bit_model
{
public:
  Arithmetic_bit_model() { init(); }

  // Both outcomes equally likely, and frequent updates at first so that the model learns quickly.
  void init()
  {
    m_zeros = 1;
    m_total = 2;
    m_zero_probability = 1u << (coder::BIT_LENGTH_SHIFT - 1);
    m_cycle = m_until_update = 4;
  }

private:
  friend class Arithmetic_decoder;
  friend class Arithmetic_encoder;

  void update()
  {
    if((m_total += m_cycle) > coder::BIT_MAX_COUNT)
    {
      m_total = (m_total + 1) >> 1;
      m_zeros = (m_zeros + 1) >> 1;
      if(m_zeros == m_total) // a probability of 1 would leave no room for the other outcome
        ++m_total;
    }
    const std::uint32_t scale = 0x80000000u / m_total;
    m_zero_probability = (m_zeros * scale) >> (31 - coder::BIT_LENGTH_SHIFT);
    m_cycle = (5 * m_cycle) >> 2;
    if(m_cycle > 64)
      m_cycle = 64;
    m_until_update = m_cycle;
  }

  std::uint32_t m_zeros, m_total, m_zero_probability, m_cycle, m_until_update;
};

// An adaptive model of `symbols` outcomes (2 to 2048). Past 16 symbols a lookup table narrows the
// search for a decoded symbol to a few entries, as LASzip's decoder does; both searches find the same
// symbol, the table only saves time.
class Arithmetic_model
{
public:
  explicit Arithmetic_model(std::uint32_t symbols) : m_symbols(symbols)
  {
    CGAL_precondition(symbols >= 2 && symbols <= coder::MAX_SYMBOLS);
    m_table_size = m_table_shift = 0;
    if(symbols > 16)
    {
      std::uint32_t table_bits = 3;
      while(symbols > (1u << (table_bits + 2)))
        ++table_bits;
      m_table_size = 1u << table_bits;
      m_table_shift = coder::SYMBOL_LENGTH_SHIFT - table_bits;
    }
    // One block: cumulative counts, counts, then the table and its two sentinels.
    m_storage.assign(2 * std::size_t(symbols) + (m_table_size ? m_table_size + 2 : 0), 0);
    init();
  }

  std::uint32_t symbols() const { return m_symbols; }

  // Every symbol seen once: equiprobable.
  void init()
  {
    std::uint32_t* counts = m_storage.data() + m_symbols;
    for(std::uint32_t s = 0; s < m_symbols; ++s)
      counts[s] = 1;
    m_total = 0;
    m_cycle = m_symbols;
    update(true);
    m_until_update = m_cycle = (m_symbols + 6) >> 1;
  }

private:
  friend class Arithmetic_decoder;
  friend class Arithmetic_encoder;

  // Rebuilds the cumulative distribution from the counts, then sets how many symbols pass before the
  // next rebuild: a little more each time, up to a ceiling. Only a decoder searches the table: it is
  // rebuilt with the distribution when `with_table`, else marked stale and rebuilt at the next decode.
  void update(bool with_table)
  {
    std::uint32_t* cumulative = m_storage.data();
    std::uint32_t* counts = cumulative + m_symbols;
    if((m_total += m_cycle) > coder::SYMBOL_MAX_COUNT)
    {
      m_total = 0;
      for(std::uint32_t s = 0; s < m_symbols; ++s)
        m_total += (counts[s] = (counts[s] + 1) >> 1);
    }
    const std::uint32_t scale = 0x80000000u / m_total;
    std::uint32_t sum = 0;
    for(std::uint32_t s = 0; s < m_symbols; ++s)
    {
      cumulative[s] = (scale * sum) >> (31 - coder::SYMBOL_LENGTH_SHIFT);
      sum += counts[s];
    }
    m_table_stale = m_table_size != 0;
    if(with_table)
      rebuild_table();
    m_cycle = (5 * m_cycle) >> 2;
    const std::uint32_t most = (m_symbols + 6) << 3;
    if(m_cycle > most)
      m_cycle = most;
    m_until_update = m_cycle;
  }

  // table[i]: the last symbol whose cumulative count lies below i << shift (a decoder's search starts there).
  void rebuild_table()
  {
    if(!m_table_stale)
      return;
    const std::uint32_t* cumulative = m_storage.data();
    std::uint32_t* table = m_storage.data() + 2 * std::size_t(m_symbols);
    std::uint32_t filled = 0;
    for(std::uint32_t s = 1; s < m_symbols; ++s) // the first cumulative count is 0
    {
      const std::uint32_t slot = cumulative[s] >> m_table_shift;
      while(filled < slot)
        table[++filled] = s - 1;
    }
    table[0] = 0;
    while(filled <= m_table_size)
      table[++filled] = m_symbols - 1;
    m_table_stale = false;
  }

  std::vector<std::uint32_t> m_storage;
  std::uint32_t m_symbols;
  std::uint32_t m_total = 0, m_cycle = 0, m_until_update = 0;
  std::uint32_t m_table_size, m_table_shift;
  bool m_table_stale = false;
};

// Decodes LASzip's arithmetic-coded bytes [begin, end). The decoder keeps `value`, the code's offset
// in the current interval of `length`; each decision narrows the interval, and a byte is shifted in
// whenever it falls below MIN_LENGTH. A damaged stream decodes to garbage, never out of the bytes:
// a read past `end` throws Decode_error.
class Arithmetic_decoder
{
public:
  Arithmetic_decoder() = default;

  void init(const unsigned char* begin, const unsigned char* end)
  {
    m_next = begin;
    m_end = end;
    m_length = coder::MAX_LENGTH;
    m_value = 0;
    for(int i = 0; i < 4; ++i)
      m_value = (m_value << 8) | next_byte();
  }

  // The bytes read so far (the position of the next one).
  const unsigned char* position() const { return m_next; }

  std::uint32_t decode_bit(Arithmetic_bit_model& m)
  {
    const std::uint32_t split = m.m_zero_probability * (m_length >> coder::BIT_LENGTH_SHIFT);
    std::uint32_t bit;
    if(m_value < split)
    {
      bit = 0;
      m_length = split;
      ++m.m_zeros;
    }
    else
    {
      bit = 1;
      m_value -= split;
      m_length -= split;
    }
    if(m_length < coder::MIN_LENGTH)
      renormalize();
    if(--m.m_until_update == 0)
      m.update();
    return bit;
  }

  // A symbol in [0, m.symbols()), whatever the bytes.
  std::uint32_t decode_symbol(Arithmetic_model& m)
  {
    const std::uint32_t* cumulative = m.m_storage.data();
    std::uint32_t symbol, low, high = m_length;
    if(m.m_table_size != 0)
    {
      if(m.m_table_stale) // last updated by an encoder
        m.rebuild_table();
      m_length >>= coder::SYMBOL_LENGTH_SHIFT;
      const std::uint32_t scaled = m_value / m_length;
      std::uint32_t slot = scaled >> m.m_table_shift;
      // Beyond the table the code lies in the last symbol's interval (or the bytes are damaged):
      // the last slot says so without reading past the table.
      if(slot > m.m_table_size)
        slot = m.m_table_size;
      const std::uint32_t* table = cumulative + 2 * std::size_t(m.m_symbols);
      symbol = table[slot];
      std::uint32_t above = table[slot + 1] + 1;
      while(above > symbol + 1)
      {
        const std::uint32_t middle = (symbol + above) >> 1;
        if(cumulative[middle] > scaled)
          above = middle;
        else
          symbol = middle;
      }
      low = cumulative[symbol] * m_length;
      if(symbol != m.m_symbols - 1)
        high = cumulative[symbol + 1] * m_length;
    }
    else
    {
      // Few symbols: bisection on the products themselves.
      low = symbol = 0;
      m_length >>= coder::SYMBOL_LENGTH_SHIFT;
      std::uint32_t above = m.m_symbols;
      std::uint32_t middle = above >> 1;
      do
      {
        const std::uint32_t bound = m_length * cumulative[middle];
        if(bound > m_value)
        {
          above = middle;
          high = bound;
        }
        else
        {
          symbol = middle;
          low = bound;
        }
      } while((middle = (symbol + above) >> 1) != symbol);
    }
    m_value -= low;
    m_length = high - low;
    if(m_length < coder::MIN_LENGTH)
      renormalize();
    ++m.m_storage[m.m_symbols + symbol];
    if(--m.m_until_update == 0)
      m.update(true);
    return symbol;
  }

  // `bits` (1 to 32) equiprobable bits, the lowest first when more than 19 (as LASzip splits them).
  std::uint32_t read_bits(std::uint32_t bits)
  {
    CGAL_precondition(bits >= 1 && bits <= 32);
    if(bits > 19)
    {
      const std::uint32_t low = read_short();
      return (read_bits(bits - 16) << 16) | low;
    }
    return read_uniform(bits);
  }

  std::uint8_t read_byte() { return std::uint8_t(read_uniform(8)); }
  std::uint16_t read_short() { return std::uint16_t(read_uniform(16)); }
  std::uint32_t read_int()
  {
    const std::uint32_t low = read_short();
    return (std::uint32_t(read_short()) << 16) | low;
  }
  std::uint64_t read_int64()
  {
    const std::uint64_t low = read_int();
    return (std::uint64_t(read_int()) << 32) | low;
  }

private:
  // A number of `bits` (at most 19, so that the interval keeps a nonzero length) coded uniformly.
  std::uint32_t read_uniform(std::uint32_t bits)
  {
    m_length >>= bits;
    const std::uint32_t n = m_value / m_length;
    m_value -= m_length * n;
    if(m_length < coder::MIN_LENGTH)
      renormalize();
    // An encoder never codes past 2^bits; only a damaged stream decodes there.
    if(n >> bits)
      throw Decode_error("the arithmetic decoder decodes a raw number out of its range");
    return n;
  }

  std::uint32_t next_byte()
  {
    if(m_next == m_end)
      throw_past_end();
    return *m_next++;
  }

  void renormalize()
  {
    do
    {
      m_value = (m_value << 8) | next_byte();
    } while((m_length <<= 8) < coder::MIN_LENGTH);
  }

  [[noreturn]] static void throw_past_end()
  {
    throw Decode_error("the arithmetic decoder reads past the end of its bytes");
  }

  const unsigned char* m_next = nullptr;
  const unsigned char* m_end = nullptr;
  std::uint32_t m_value = 0, m_length = coder::MAX_LENGTH;
};

// Encodes what Arithmetic_decoder decodes, byte for byte as LASzip's encoder writes it: `base` is the
// low end of the current interval of `length`; each decision narrows it, a byte leaves at the top
// whenever the length falls below MIN_LENGTH, and a sum that overflows `base` carries into the bytes
// already written. The bytes grow in a vector (`bytes()`), ready after `done()`.
class Arithmetic_encoder
{
public:
  // Starts a new stream (the bytes of the last one are dropped; their storage is kept).
  void init()
  {
    m_bytes.clear();
    m_base = 0;
    m_length = coder::MAX_LENGTH;
  }

  const std::vector<unsigned char>& bytes() const { return m_bytes; }

  void encode_bit(Arithmetic_bit_model& m, std::uint32_t bit)
  {
    const std::uint32_t split = m.m_zero_probability * (m_length >> coder::BIT_LENGTH_SHIFT);
    if(bit == 0)
    {
      m_length = split;
      ++m.m_zeros;
    }
    else
    {
      add_to_base(split);
      m_length -= split;
    }
    if(m_length < coder::MIN_LENGTH)
      renormalize();
    if(--m.m_until_update == 0)
      m.update();
  }

  void encode_symbol(Arithmetic_model& m, std::uint32_t symbol)
  {
    CGAL_precondition(symbol < m.m_symbols);
    const std::uint32_t* cumulative = m.m_storage.data();
    if(symbol == m.m_symbols - 1) // the last symbol's interval ends where the current one does
    {
      const std::uint32_t low = cumulative[symbol] * (m_length >> coder::SYMBOL_LENGTH_SHIFT);
      add_to_base(low);
      m_length -= low;
    }
    else
    {
      m_length >>= coder::SYMBOL_LENGTH_SHIFT;
      const std::uint32_t low = cumulative[symbol] * m_length;
      add_to_base(low);
      m_length = cumulative[symbol + 1] * m_length - low;
    }
    if(m_length < coder::MIN_LENGTH)
      renormalize();
    ++m.m_storage[m.m_symbols + symbol];
    if(--m.m_until_update == 0)
      m.update(false);
  }

  // `bits` (1 to 32) equiprobable bits of `value`, as read_bits() reads them.
  void write_bits(std::uint32_t bits, std::uint32_t value)
  {
    CGAL_precondition(bits >= 1 && bits <= 32 && (bits == 32 || (value >> bits) == 0));
    if(bits > 19)
    {
      write_short(std::uint16_t(value & 0xFFFFu));
      value >>= 16;
      bits -= 16;
    }
    write_uniform(bits, value);
  }

  void write_byte(std::uint8_t value) { write_uniform(8, value); }
  void write_short(std::uint16_t value) { write_uniform(16, value); }
  void write_int(std::uint32_t value)
  {
    write_short(std::uint16_t(value & 0xFFFFu));
    write_short(std::uint16_t(value >> 16));
  }
  void write_int64(std::uint64_t value)
  {
    write_int(std::uint32_t(value));
    write_int(std::uint32_t(value >> 32));
  }

  // Ends the stream: the bytes that place the code inside the final interval, then the two or three
  // zero bytes that LASzip's decoder reads ahead (a decoder fetches four bytes at its start).
  void done()
  {
    bool another_byte = true;
    if(m_length > 2 * coder::MIN_LENGTH)
    {
      add_to_base(coder::MIN_LENGTH);
      m_length = coder::MIN_LENGTH >> 1; // one more byte settles it
    }
    else
    {
      add_to_base(coder::MIN_LENGTH >> 1);
      m_length = coder::MIN_LENGTH >> 9; // two more bytes
      another_byte = false;
    }
    renormalize();
    m_bytes.push_back(0);
    m_bytes.push_back(0);
    if(another_byte)
      m_bytes.push_back(0);
  }

private:
  void write_uniform(std::uint32_t bits, std::uint32_t value)
  {
    m_length >>= bits;
    add_to_base(value * m_length);
    if(m_length < coder::MIN_LENGTH)
      renormalize();
  }

  // base += x, the carry of a wrap added to the bytes written (a run of 0xFF turns to zeros).
  void add_to_base(std::uint32_t x)
  {
    const std::uint32_t before = m_base;
    m_base += x;
    if(m_base < before)
    {
      std::size_t i = m_bytes.size();
      while(i > 0 && m_bytes[i - 1] == 0xFFu)
        m_bytes[--i] = 0;
      CGAL_assertion(i > 0); // the first byte never carries out: the interval starts below 2^32
      if(i > 0)
        ++m_bytes[i - 1];
    }
  }

  void renormalize()
  {
    do
    {
      m_bytes.push_back(static_cast<unsigned char>(m_base >> 24));
      m_base <<= 8;
    } while((m_length <<= 8) < coder::MIN_LENGTH);
  }

  std::vector<unsigned char> m_bytes;
  std::uint32_t m_base = 0, m_length = coder::MAX_LENGTH;
};

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_ARITHMETIC_CODER_H
