// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VECTOR_LANES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VECTOR_LANES_H

// Lanes of 4 (AVX2) and 8 (AVX-512) doubles as GCC's vector extensions, for code that is compiled
// for those instruction sets inside functions with a target attribute (see vector_instructions.h)
// while the rest of the build stays portable. Eigen cannot serve there: its packet width is fixed
// by the macros in force when its headers are read.
//
// The operations match Eigen's packets on the portable path bit for bit: arithmetic is IEEE on
// every width; max and min are Eigen's (`(b > a) ? b : a`, `(b < a) ? b : a`, so std::max's and
// std::min's rule on NaNs and on signed zeros); abs clears the sign bit; sqrt is the correctly rounded
// instruction. Broadcasts are exact copies of the scalar.
//
// The lanes pass by value only between functions that are inlined into one compiled for their
// instruction set, so GCC's note that such values change the ABI of functions compiled without it
// (-Wpsabi) does not apply: the CMake target turns it off; a build without it may print it once.

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_DISPATCH 1

#include <immintrin.h>

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

typedef double Lanes4 __attribute__((vector_size(32)));
typedef double Lanes8 __attribute__((vector_size(64)));

template <typename T>
struct Lanes_traits
{
  static constexpr bool is_lanes = false;
};
template <>
struct Lanes_traits<Lanes4>
{
  static constexpr bool is_lanes = true;
  static constexpr int size = 4;
  typedef std::int64_t Bits __attribute__((vector_size(32)));
};
template <>
struct Lanes_traits<Lanes8>
{
  static constexpr bool is_lanes = true;
  static constexpr int size = 8;
  typedef std::int64_t Bits __attribute__((vector_size(64)));
};

template <typename V>
using If_lanes = typename std::enable_if<Lanes_traits<V>::is_lanes, V>::type;

template <typename V>
inline If_lanes<V> broadcast(double x)
{
  V v;
  for(int l = 0; l < Lanes_traits<V>::size; ++l)
    v[l] = x;
  return v;
}

template <typename V>
inline If_lanes<V> elementwise_max(const V& a, const V& b) { return b > a ? b : a; }
template <typename V>
inline If_lanes<V> elementwise_max(const V& a, double b) { return elementwise_max(a, broadcast<V>(b)); }
template <typename V>
inline If_lanes<V> elementwise_min(const V& a, const V& b) { return b < a ? b : a; }
template <typename V>
inline If_lanes<V> elementwise_min(const V& a, double b) { return elementwise_min(a, broadcast<V>(b)); }
template <typename V>
inline If_lanes<V> elementwise_abs(const V& a)
{
  typedef typename Lanes_traits<V>::Bits Bits;
  Bits magnitude; // every bit but the sign
  for(int l = 0; l < Lanes_traits<V>::size; ++l)
    magnitude[l] = INT64_MAX;
  return (V)((Bits)a & magnitude);
}

// Only inside functions compiled for AVX (resp. AVX-512F).
__attribute__((target("avx"))) inline Lanes4 elementwise_sqrt(const Lanes4& a)
{
  return (Lanes4)_mm256_sqrt_pd((__m256d)a);
}
__attribute__((target("avx512f"))) inline Lanes8 elementwise_sqrt(const Lanes8& a)
{
  return (Lanes8)_mm512_sqrt_pd((__m512d)a);
}

template <typename V>
inline If_lanes<V> load_lanes(const double* p)
{
  V v;
  std::memcpy(&v, p, sizeof(V));
  return v;
}
template <typename V>
inline If_lanes<V> store_lanes(double* p, const V& v)
{
  std::memcpy(p, &v, sizeof(V));
  return v;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // GCC on x86-64

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VECTOR_LANES_H
