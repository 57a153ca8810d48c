// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_INTERNAL_LAZ_INTEGER_CODER_H
#define LIDAR_IO_INTERNAL_LAZ_INTEGER_CODER_H

#include <Lidar_io/internal/laz/arithmetic_coder.h>

#include <CGAL/assertions.h>

#include <cstdint>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace Lidar_io {
namespace internal {
namespace laz {

// LASzip's integer coding: a number is coded as its difference (the corrector) from a prediction.
// The corrector's magnitude class k (it lies in [-(2^k - 1), 2^k], k = 0 meaning 0 or 1) is a symbol
// of a per-context model; its position within the class is a symbol of a per-k model, or for
// k > bits_high the top bits_high bits a symbol and the rest raw bits. Numbers wrap modulo the
// range (2^bits, or `range` when given), as the encoder folded them. It holds models alone: the
// arithmetic coder of its stream comes with each call, so that one object compresses and decompresses.
class Integer_coder
{
public:
  explicit Integer_coder(std::uint32_t bits = 16, std::uint32_t contexts = 1, std::uint32_t bits_high = 8,
                                std::uint32_t range = 0)
    : m_bits_high(bits_high)
  {
    CGAL_precondition(contexts >= 1 && bits_high >= 1 && bits_high <= 11);
    if(range != 0)
    {
      // As many bits as the range needs (one less when it is a power of two).
      m_corrector_bits = 0;
      for(std::uint32_t r = range; r != 0; r >>= 1)
        ++m_corrector_bits;
      if(range == (1u << (m_corrector_bits - 1)))
        --m_corrector_bits;
      m_range = range;
      m_min_corrector = -std::int32_t(range / 2);
    }
    else if(bits != 0 && bits < 32)
    {
      m_corrector_bits = bits;
      m_range = 1u << bits;
      m_min_corrector = -std::int32_t(m_range / 2);
    }
    else
    {
      m_corrector_bits = 32;
      m_range = 0; // the whole 32-bit circle: wrapping does it
      m_min_corrector = std::int32_t(-2147483647 - 1);
    }
    m_k_models.assign(contexts, Arithmetic_model(m_corrector_bits + 1));
    // Classes k = 1 .. min(corrector bits, 31); k = 32 codes nothing more (the corrector is then the
    // range's minimum), so it has no model.
    const std::uint32_t modeled = m_corrector_bits < 32 ? m_corrector_bits : 31;
    m_position_models.reserve(modeled);
    for(std::uint32_t k = 1; k <= modeled; ++k)
      m_position_models.emplace_back(1u << (k <= bits_high ? k : bits_high));
  }

  // Fresh models, as at the start of every chunk.
  void init()
  {
    for(Arithmetic_model& m : m_k_models)
      m.init();
    m_low_bit.init();
    for(Arithmetic_model& m : m_position_models)
      m.init();
  }

  // The number coded against `prediction`. With 2^bits (bits < 32) as the range and a prediction in
  // [0, 2^bits), it lies in [0, 2^bits) whatever the bytes; with a `range` given, only valid bytes
  // keep it in [0, range) (LASzip folds once).
  std::int32_t decompress(Arithmetic_decoder& decoder, std::int32_t prediction, std::uint32_t context = 0)
  {
    CGAL_precondition(context < m_k_models.size());
    std::uint32_t real = std::uint32_t(prediction) + std::uint32_t(read_corrector(decoder, m_k_models[context]));
    // Back into [0, range): the encoder folded the corrector so that this wraps at most once.
    if(std::int32_t(real) < 0)
      real += m_range;
    else if(real >= m_range)
      real -= m_range;
    return std::int32_t(real);
  }

  // Codes `real` against `prediction`: what decompress() with the same prediction and context gives back.
  void compress(Arithmetic_encoder& encoder, std::int32_t prediction, std::int32_t real, std::uint32_t context = 0)
  {
    CGAL_precondition(context < m_k_models.size());
    // The corrector folded into [min, min + range): 32-bit wrapping arithmetic, as LASzip's (its
    // signed overflow wraps on every platform it runs on).
    std::uint32_t corrector = std::uint32_t(real) - std::uint32_t(prediction);
    if(m_range != 0)
    {
      const std::int32_t c = std::int32_t(corrector);
      const std::int32_t max_corrector = std::int32_t(std::uint32_t(m_min_corrector) + m_range - 1u);
      if(c < m_min_corrector)
        corrector += m_range;
      else if(c > max_corrector)
        corrector -= m_range;
    }
    write_corrector(encoder, std::int32_t(corrector), m_k_models[context]);
  }

  // The magnitude class of the last corrector: later predictions use it as a context.
  std::uint32_t k() const { return m_k; }

private:
  void write_corrector(Arithmetic_encoder& encoder, std::int32_t c, Arithmetic_model& k_model)
  {
    // k: the smallest with c in [-(2^k - 1), 2^k]
    std::uint32_t magnitude = c <= 0 ? 0u - std::uint32_t(c) : std::uint32_t(c) - 1u;
    std::uint32_t k = 0;
    for(; magnitude != 0; magnitude >>= 1)
      ++k;
    m_k = k;
    encoder.encode_symbol(k_model, k);
    if(k == 0)
    {
      encoder.encode_bit(m_low_bit, std::uint32_t(c));
      return;
    }
    if(k >= 32)
      return; // the range's minimum: the class says it all
    // c moved into [0, 2^k): the negative half below 2^(k-1), the positive one above
    const std::uint32_t position =
      c < 0 ? std::uint32_t(c) + ((std::uint32_t(1) << k) - 1u) : std::uint32_t(c) - 1u;
    Arithmetic_model& model = m_position_models[k - 1];
    if(k <= m_bits_high)
      encoder.encode_symbol(model, position);
    else
    {
      const std::uint32_t raw = k - m_bits_high;
      encoder.encode_symbol(model, position >> raw);
      encoder.write_bits(raw, position & ((std::uint32_t(1) << raw) - 1u));
    }
  }

  std::int32_t read_corrector(Arithmetic_decoder& decoder, Arithmetic_model& k_model)
  {
    const std::uint32_t k = m_k = decoder.decode_symbol(k_model); // <= corrector bits
    if(k == 0)
      return std::int32_t(decoder.decode_bit(m_low_bit));
    if(k >= 32)
      return m_min_corrector;
    Arithmetic_model& position = m_position_models[k - 1];
    std::uint32_t c;
    if(k <= m_bits_high)
      c = decoder.decode_symbol(position);
    else
    {
      const std::uint32_t raw = k - m_bits_high;
      c = decoder.decode_symbol(position) << raw;
      c |= decoder.read_bits(raw);
    }
    // c in [0, 2^k): the upper half stands for [2^(k-1) + 1, 2^k], the lower for [-(2^k - 1), -2^(k-1)].
    if(c >= (1u << (k - 1)))
      return std::int32_t(c + 1);
    return std::int32_t(c - ((1u << k) - 1));
  }

  std::uint32_t m_bits_high;
  std::uint32_t m_corrector_bits = 0, m_range = 0;
  std::int32_t m_min_corrector = 0;
  std::uint32_t m_k = 0;
  std::vector<Arithmetic_model> m_k_models;       // per context: the corrector's class k
  Arithmetic_bit_model m_low_bit;                  // k = 0: the corrector is 0 or 1
  std::vector<Arithmetic_model> m_position_models; // k = 1, 2, ...: the corrector within its class
};

} // namespace laz
} // namespace internal
} // namespace Lidar_io
/// \endcond

#endif // LIDAR_IO_INTERNAL_LAZ_INTEGER_CODER_H
