// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_INSTRUCTIONS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_INSTRUCTIONS_H

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  The vector instructions that the optimal search's batched closed-form eigenvalues run on.

  `PORTABLE` is the code as compiled (SSE2 on x86-64 by default: 2 doubles per instruction).
  `AVX2` (4 doubles) and `AVX512` (8 doubles) are compiled in besides it, with GCC on x86-64, and
  chosen at run time where the processor and the system support them. Every path performs the same
  operations in the same order (no multiply-add is contracted, `sqrt` is the correctly rounded
  instruction on every path), so the records are the same bits whichever runs.
*/
enum class Vector_instructions
{
  PORTABLE,
  AVX2,
  AVX512
};

/// \cond SKIP_IN_MANUAL
namespace internal {
// for the messages of the named parameter `vector_instructions`
inline const char* vector_instructions_name(Vector_instructions v)
{
  return v == Vector_instructions::AVX512 ? "avx512" : v == Vector_instructions::AVX2 ? "avx2" : "portable";
}
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  Whether this build and this processor can run `v`.
*/
inline bool has_vector_instructions(Vector_instructions v)
{
  if(v == Vector_instructions::PORTABLE)
    return true;
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  // libgcc's check covers the system too: the registers' state must be saved by the kernel (XCR0)
  return v == Vector_instructions::AVX2 ? __builtin_cpu_supports("avx2") != 0 : __builtin_cpu_supports("avx512f") != 0;
#else
  return false;
#endif
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  The widest path that has_vector_instructions() allows: the search's default. The named parameter
  `vector_instructions` chooses another, for tests and measurements: the records do not depend on it.
*/
inline Vector_instructions widest_vector_instructions()
{
  return has_vector_instructions(Vector_instructions::AVX512) ? Vector_instructions::AVX512
         : has_vector_instructions(Vector_instructions::AVX2) ? Vector_instructions::AVX2
                                                              : Vector_instructions::PORTABLE;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_INSTRUCTIONS_H
