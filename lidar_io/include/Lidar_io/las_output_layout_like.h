// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LAS_OUTPUT_LAYOUT_LIKE_H
#define LIDAR_IO_LAS_OUTPUT_LAYOUT_LIKE_H

#include <Lidar_io/Input_error.h>
#include <Lidar_io/Las_header.h>
#include <Lidar_io/Las_output_layout.h>
#include <Lidar_io/little_endian.h>
#include <Lidar_io/internal/read_las_header.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  the layout of a LAS 1.4 file that holds the point records of the LAS or LAZ file `filename` as
  they are, each followed by the dimensions `added`: the input's point data format, scales,
  offsets, GUID, file source ID, global encoding, creation date and every VLR (CRS included) but
  LASzip's, and its EVLRs and waveform data after the points. The input's Extra Bytes record keeps
  its descriptors, extra bytes it does not describe are described as undocumented (data type 0),
  and `added` is described after them. The system identifier becomes `MODIFICATION` and the
  generating software `Sigmoid_neighborhoods`; a LAS 1.0 to 1.3 header is made a LAS 1.4 one.
  \throws Input_error when the file cannot be read or its header, VLRs or Extra Bytes record do not
  hold together
  \throws std::invalid_argument for a dimension without a name or with one of more than 32
  characters, and std::length_error for records of more than 65535 bytes
*/
inline Las_output_layout las_output_layout_like(const std::string& filename,
                                                const std::vector<Las_extra_dimension>& added)
{
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Input_error("cannot open the file");
  const std::uintmax_t file_size = internal::las_file_size(filename);
  const Las_header h = internal::read_las_header(in, file_size);
  std::vector<unsigned char> prefix(h.offset_to_point_data);
  in.seekg(0);
  if(!in.read(reinterpret_cast<char*>(prefix.data()), std::streamsize(prefix.size())))
    throw Input_error(internal::las_error("read error in the header or its variable length records"));

  Las_output_layout l;
  std::copy_n(prefix.begin(), (std::min)(std::size_t(h.header_size), l.header.size()), l.header.begin());
  std::fill(l.header.begin() + (std::min)(std::size_t(h.header_size), l.header.size()), l.header.end(), 0);
  if(h.header_size < internal::LAS_HEADER_BYTES_1_4)
    std::fill(l.header.begin() + 227, l.header.end(), 0); // LAS 1.3's waveform field is read below
  l.point_format = h.point_format;
  l.copied_record_length = h.record_length;
  l.scale = h.scale;
  l.offset = h.offset;
  internal::store_las_software_fields(l, "MODIFICATION");

  // The VLRs but LASzip's and the Extra Bytes record, which is made again with the added dimensions.
  std::vector<unsigned char> described;
  std::size_t at = h.header_size;
  for(std::uint32_t v = 0; v < h.vlr_count; ++v)
  {
    if(at + internal::LAS_VLR_HEADER_BYTES > prefix.size())
      throw Input_error(internal::las_error("variable length record " + std::to_string(v) + " of " +
                                            std::to_string(h.vlr_count) + " runs into the point data"));
    const unsigned char* vlr = prefix.data() + at;
    const std::size_t length = load_little_endian<std::uint16_t>(vlr + 20);
    const std::size_t end = at + internal::LAS_VLR_HEADER_BYTES + length;
    if(end > prefix.size())
      throw Input_error(internal::las_error("variable length record " + std::to_string(v) + " of " +
                                            std::to_string(h.vlr_count) + " runs into the point data"));
    if(internal::las_vlr_is(vlr, "LASF_Spec", 4))
      described.assign(vlr + internal::LAS_VLR_HEADER_BYTES, vlr + internal::LAS_VLR_HEADER_BYTES + length -
                                                                 length % internal::LAS_EXTRA_BYTES_DESCRIPTOR_BYTES);
    else if(!internal::las_vlr_is(vlr, "laszip encoded", 22204))
    {
      l.vlrs.insert(l.vlrs.end(), vlr, static_cast<const unsigned char*>(prefix.data() + end));
      ++l.vlr_count;
    }
    at = end;
  }
  const std::size_t extra = h.record_length - internal::LAS_POINT_RECORD_BYTES[h.point_format];
  std::size_t documented = 0;
  for(std::size_t d = 0; d < described.size(); d += internal::LAS_EXTRA_BYTES_DESCRIPTOR_BYTES)
    documented += internal::las_descriptor_bytes(described.data() + d);
  if(documented > extra)
    throw Input_error(internal::las_error("its Extra Bytes record describes " + std::to_string(documented) +
                                          " bytes per point, more than the " + std::to_string(extra) +
                                          " extra bytes of its records"));
  for(std::size_t rest = extra - documented; rest > 0;)
  {
    const std::size_t bytes = (std::min)(rest, std::size_t(255));
    std::array<unsigned char, internal::LAS_EXTRA_BYTES_DESCRIPTOR_BYTES> d{};
    d[3] = std::uint8_t(bytes); // data type 0: `options` bytes without a meaning given
    internal::store_las_text(d.data() + 4, 32, "undocumented");
    described.insert(described.end(), d.begin(), d.end());
    rest -= bytes;
  }
  internal::add_las_extra_dimensions(l, std::move(described), added);

  // What follows the point records and is copied after them: the EVLRs (LAS 1.4) and the waveform
  // data packets stored in the file (LAS 1.3 and 1.4); bytes before them (a LAZ chunk table) are not.
  const bool is_1_4 = h.version_minor == 4 && h.header_size >= internal::LAS_HEADER_BYTES_1_4;
  std::uint64_t trailer = file_size;
  if(is_1_4 && load_little_endian<std::uint32_t>(prefix.data() + 243) != 0)
  {
    l.evlr_count = load_little_endian<std::uint32_t>(prefix.data() + 243);
    trailer = load_little_endian<std::uint64_t>(prefix.data() + 235);
  }
  std::uint64_t waveforms = 0;
  if(h.version_minor >= 3 && h.header_size >= 235 && (load_little_endian<std::uint16_t>(prefix.data() + 6) & 0x2) != 0)
    waveforms = load_little_endian<std::uint64_t>(prefix.data() + 227);
  if(waveforms != 0)
  {
    if(!is_1_4)
      l.evlr_count = 1; // LAS 1.3 stores its waveform data packets in an EVLR
    trailer = (std::min)(trailer, waveforms);
  }
  if(trailer < h.offset_to_point_data || trailer > file_size || (waveforms != 0 && waveforms > file_size))
    throw Input_error(internal::las_error("EVLRs or waveform data at byte " + std::to_string(trailer) +
                                          ", not after the point records"));
  if(waveforms != 0)
    l.waveforms_in_evlrs = waveforms - trailer;
  l.evlrs.resize(std::size_t(file_size - trailer));
  in.clear();
  in.seekg(std::streamoff(trailer));
  if(!l.evlrs.empty() && !in.read(reinterpret_cast<char*>(l.evlrs.data()), std::streamsize(l.evlrs.size())))
    throw Input_error(internal::las_error("read error in the EVLRs"));
  return l;
}

} // namespace Lidar_io

#endif // LIDAR_IO_LAS_OUTPUT_LAYOUT_LIKE_H
