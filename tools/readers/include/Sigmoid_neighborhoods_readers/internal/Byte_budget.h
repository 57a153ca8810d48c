// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_BYTE_BUDGET_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_BYTE_BUDGET_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// What is left of a file being read, to bound every count the file announces (items of an element,
// entries of a list, corners of a face, triangles) before anything is sized to it: CGAL's readers
// resize their vectors to such counts before they read a single item, so a file of a few hundred
// bytes could ask for gigabytes (found by fuzzing and with hostile files). The bytes left are an
// upper bound on those not read yet: the bytes after a known position, less a lower bound on what
// each item read took.
class Byte_budget
{
public:
  static constexpr std::uintmax_t UNKNOWN_SIZE = (std::numeric_limits<std::uintmax_t>::max)();

  // `left` bytes of a file of `file_size` bytes are still to be read; an unknown size bounds nothing.
  Byte_budget(std::uintmax_t file_size, std::uintmax_t left) : m_file_size(file_size), m_left(left) {}

  // Refuses `count` items of at least `bytes_each` bytes each (at least 1: even an empty item is
  // a step of the reader) unless the bytes left can hold them. The message is `message(excess)`,
  // called only on a refusal, where `excess` says by how much: ", more than a file of 20 bytes can
  // hold: 8 bytes left, at least 1 byte each" after "the header announces 10 vertices".
  template <typename Message>
  void check(std::uintmax_t count, std::uintmax_t bytes_each, const Message& message) const
  {
    bytes_each = (std::max)(bytes_each, std::uintmax_t(1));
    if(m_file_size == UNKNOWN_SIZE || count <= m_left / bytes_each)
      return;
    throw Input_error(message(", more than a file of " + bytes(m_file_size) + " can hold: " + bytes(m_left) +
                              " left, at least " + bytes(bytes_each) + " each"));
  }

  // `count` items of at least `bytes_each` bytes each have been read (or are set aside).
  void take(std::uintmax_t count, std::uintmax_t bytes_each)
  {
    const std::uintmax_t most = bytes_each == 0 ? UNKNOWN_SIZE : m_left / bytes_each;
    m_left = count > most ? 0 : m_left - count * bytes_each;
  }

private:
  static std::string bytes(std::uintmax_t n) { return std::to_string(n) + (n == 1 ? " byte" : " bytes"); }

  std::uintmax_t m_file_size, m_left;
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_BYTE_BUDGET_H
