// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LITTLE_ENDIAN_H
#define LIDAR_IO_LITTLE_ENDIAN_H

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace Lidar_io {

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename T>
using Unsigned_of_size =
  typename std::conditional<sizeof(T) == 8, std::uint64_t,
    typename std::conditional<sizeof(T) == 4, std::uint32_t,
      typename std::conditional<sizeof(T) == 2, std::uint16_t, std::uint8_t>::type>::type>::type;

} // namespace internal
/// \endcond

/*!
  \ingroup PkgLidarIo
  the number of type `T` stored little-endian at `bytes` (any address), as LAS and LAZ files store
  their numbers: the bytes assembled into an unsigned integer of the size of `T`, copied into `T`
  (two's complement integers, IEEE floating point), whatever the machine's byte order.
  \tparam T an integer or floating-point type of 1, 2, 4 or 8 bytes
*/
template <typename T>
T load_little_endian(const unsigned char* bytes)
{
  typedef internal::Unsigned_of_size<T> Unsigned;
  static_assert(sizeof(Unsigned) == sizeof(T) && std::is_trivially_copyable<T>::value, "a plain number");
  Unsigned u = 0;
  for(std::size_t i = sizeof(T); i-- > 0;)
    u = Unsigned(Unsigned(u << 8) | Unsigned(bytes[i]));
  T value;
  std::memcpy(&value, &u, sizeof(T));
  return value;
}

/*!
  \ingroup PkgLidarIo
  stores `value` little-endian at `bytes` (any address): the inverse of `load_little_endian()`.
  \tparam T an integer or floating-point type of 1, 2, 4 or 8 bytes
*/
template <typename T>
void store_little_endian(unsigned char* bytes, T value)
{
  typedef internal::Unsigned_of_size<T> Unsigned;
  static_assert(sizeof(Unsigned) == sizeof(T) && std::is_trivially_copyable<T>::value, "a plain number");
  Unsigned u;
  std::memcpy(&u, &value, sizeof(T));
  for(std::size_t i = 0; i < sizeof(T); ++i, u = Unsigned(u >> 8))
    bytes[i] = static_cast<unsigned char>(u & 0xFF);
}

/*!
  \ingroup PkgLidarIo
  the unsigned integer of the `count` bytes stored little-endian at `bytes`, `count` at most 8: the
  fields of LAS and LAZ records of other widths (LASzip's variable-length integers, 3-byte fields).
*/
inline std::uint64_t load_little_endian(const unsigned char* bytes, std::size_t count)
{
  std::uint64_t v = 0;
  for(std::size_t i = count; i-- > 0;)
    v = (v << 8) | bytes[i];
  return v;
}

/*!
  \ingroup PkgLidarIo
  stores the `count` low bytes of `value` little-endian at `bytes`, `count` at most 8.
*/
inline void store_little_endian(unsigned char* bytes, std::uint64_t value, std::size_t count)
{
  for(std::size_t i = 0; i < count; ++i, value >>= 8)
    bytes[i] = static_cast<unsigned char>(value);
}

} // namespace Lidar_io

#endif // LIDAR_IO_LITTLE_ENDIAN_H
