// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LAS_WRITER_H
#define LIDAR_IO_LAS_WRITER_H

#include <Lidar_io/Las_output_layout.h>
#include <Lidar_io/Las_point_summary.h>
#include <Lidar_io/little_endian.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <ios>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace Lidar_io {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The public header block of a LAS 1.4 file laid out by `layout`, whose records, summed up by
// `summary`, take `point_bytes` (compressed or not) and are followed by the layout's EVLRs;
// `format_byte` is the point format as stored (LAZ sets bit 7).
inline std::array<unsigned char, Las_output_layout::HEADER_BYTES>
las_header_bytes(const Las_output_layout& layout, const Las_point_summary& summary, std::uint64_t point_bytes,
                 unsigned int format_byte)
{
  std::array<unsigned char, Las_output_layout::HEADER_BYTES> h = layout.header;
  unsigned char* b = h.data();
  b[24] = 1;
  b[25] = 4;
  store_little_endian<std::uint16_t>(b + 94, std::uint16_t(h.size()));
  const std::uint64_t point_data = h.size() + layout.vlrs.size();
  if(point_data > (std::numeric_limits<std::uint32_t>::max)())
    throw std::length_error("variable length records of " + std::to_string(layout.vlrs.size()) +
                            " bytes: a LAS header points past them with 32 bits");
  store_little_endian<std::uint32_t>(b + 96, std::uint32_t(point_data));
  store_little_endian<std::uint32_t>(b + 100, layout.vlr_count);
  b[104] = std::uint8_t(format_byte);
  store_little_endian<std::uint16_t>(b + 105, layout.record_length);
  for(int c = 0; c < 3; ++c)
  {
    store_little_endian<double>(b + 131 + 8 * c, layout.scale[c]);
    store_little_endian<double>(b + 155 + 8 * c, layout.offset[c]);
  }
  store_las_point_summary(b, h.size(), summary);
  const std::uint64_t evlrs = point_data + point_bytes;
  const bool has_waveforms = layout.waveforms_in_evlrs != Las_output_layout::NO_WAVEFORMS;
  store_little_endian<std::uint64_t>(b + 227, has_waveforms ? evlrs + layout.waveforms_in_evlrs : 0u);
  store_little_endian<std::uint64_t>(b + 235, layout.evlr_count != 0 ? evlrs : 0u);
  store_little_endian<std::uint32_t>(b + 243, layout.evlr_count);
  return h;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgLidarIo
  writes a LAS 1.4 file laid out by a `Las_output_layout`: its header and VLRs when made, the
  point records given to `write()` in order, and on `close()` the EVLRs and the header again with the
  records' counts, counts by return and bounding box (LAS 1.4 rules: the 64-bit counts always; the
  legacy 32-bit ones equal to them in point formats 0 to 5 while they fit, else 0) and the layout's
  `scale` and `offset`. The file starts at the stream's start and the stream must be seekable (a
  file): `close()` rewrites the header. Memory: the layout only; the records stay the caller's.
  A failed write throws `std::ios_base::failure`.
*/
class Las_writer
{
public:
  /// writes the header and the VLRs of `layout` to `out`
  Las_writer(std::ostream& out, Las_output_layout layout) : m_out(out), m_layout(std::move(layout))
  {
    write_header();
    m_out.write(reinterpret_cast<const char*>(m_layout.vlrs.data()), std::streamsize(m_layout.vlrs.size()));
    check("the header");
  }

  /// the layout written
  const Las_output_layout& layout() const { return m_layout; }

  /// writes `count` records of `layout().record_length` bytes each, in order
  void write(const unsigned char* records, std::size_t count)
  {
    for(std::size_t i = 0; i < count; ++i)
      m_summary.add(records + i * m_layout.record_length, m_layout.has_extended_format());
    m_out.write(reinterpret_cast<const char*>(records), std::streamsize(count * m_layout.record_length));
    check("the point records");
  }

  /// what the records written so far sum up to
  const Las_point_summary& summary() const { return m_summary; }

  /// writes the EVLRs and the header's summary of the records; the file is complete
  void close()
  {
    m_out.write(reinterpret_cast<const char*>(m_layout.evlrs.data()), std::streamsize(m_layout.evlrs.size()));
    const std::streampos end = m_out.tellp();
    m_out.seekp(0);
    write_header();
    m_out.seekp(end);
    check("the header's point counts");
  }

private:
  void check(const char* what)
  {
    if(!m_out)
      throw std::ios_base::failure(std::string("cannot write ") + what + " of the LAS file");
  }

  void write_header()
  {
    const auto h =
      internal::las_header_bytes(m_layout, m_summary, m_summary.count * m_layout.record_length, m_layout.point_format);
    m_out.write(reinterpret_cast<const char*>(h.data()), std::streamsize(h.size()));
  }

  std::ostream& m_out;
  Las_output_layout m_layout;
  Las_point_summary m_summary;
};

} // namespace Lidar_io

#endif // LIDAR_IO_LAS_WRITER_H
