// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CHECK_PLY_COUNTS_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CHECK_PLY_COUNTS_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/internal/Byte_budget.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>

#include <CGAL/IO/PLY/PLY_reader.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// How CGAL 5.5's PLY reader reads one property of an element: a scalar with its own reader, or a
// list, whose length it reads and resizes its buffer to before it reads a single entry: 2e9 in a
// file of 220 bytes took 7.8 GB, and a length that the end of the file cuts short is undefined.
struct Ply_property_layout
{
  typedef CGAL::IO::internal::PLY_read_number Reader;

  const Reader* reader = nullptr; // CGAL's, made by its header parser
  std::uintmax_t bytes = 0;       // binary bytes of a scalar, or of a list's length
  std::uintmax_t entry_bytes = 0; // binary bytes of a list's entry; 0 for a scalar
  std::size_t (*read_length)(const Reader&, std::istream&) = nullptr;
  void (*read_entry)(const Reader&, std::istream&) = nullptr;

  bool is_list() const { return read_length != nullptr; }
};

template <typename Scalar>
bool ply_scalar_layout(const Ply_property_layout::Reader* reader, Ply_property_layout& layout)
{
  if(dynamic_cast<const CGAL::IO::internal::PLY_read_typed_number<Scalar>*>(reader) == nullptr)
    return false;
  layout.bytes = sizeof(Scalar);
  return true;
}

// A list's length and entries are read exactly as CGAL reads them (its own read<T>()).
template <typename Length, typename Entry>
bool ply_list_layout(const Ply_property_layout::Reader* reader, Ply_property_layout& layout)
{
  typedef Ply_property_layout::Reader Reader;
  if(dynamic_cast<const CGAL::IO::internal::PLY_read_typed_list_with_typed_size<Length, Entry>*>(reader) == nullptr)
    return false;
  layout.bytes = sizeof(Length);
  layout.entry_bytes = sizeof(Entry);
  layout.read_length = [](const Reader& r, std::istream& in) {
    return static_cast<std::size_t>(r.template read<Length>(in));
  };
  layout.read_entry = [](const Reader& r, std::istream& in) { r.template read<Entry>(in); };
  return true;
}

template <typename Length, typename... Entries>
bool ply_list_layout_of_length(const Ply_property_layout::Reader* reader, Ply_property_layout& layout)
{
  return (ply_list_layout<Length, Entries>(reader, layout) || ...);
}

// The layout of a property of one of `Types`, whose lists have a length of one of `Lengths`.
template <typename... Types>
struct Ply_types
{
  static bool scalar(const Ply_property_layout::Reader* reader, Ply_property_layout& layout)
  {
    return (ply_scalar_layout<Types>(reader, layout) || ...);
  }
  template <typename... Lengths>
  static bool list(const Ply_property_layout::Reader* reader, Ply_property_layout& layout)
  {
    return (ply_list_layout_of_length<Lengths, Types...>(reader, layout) || ...);
  }
};

// The layout of a property that CGAL's PLY_reader::init() made, with the types it makes: scalars
// and list entries of any PLY type, list lengths of an integer type.
inline Ply_property_layout ply_property_layout(const Ply_property_layout::Reader* reader)
{
  typedef Ply_types<std::int8_t, std::uint8_t, std::int16_t, std::uint16_t, std::int32_t, std::uint32_t, float, double>
    Types;
  Ply_property_layout layout;
  layout.reader = reader;
  if(!Types::scalar(reader, layout) &&
     !Types::list<std::uint8_t, std::int8_t, std::uint16_t, std::int16_t, std::uint32_t, std::int32_t>(reader, layout))
    throw std::logic_error("a PLY property of a type that CGAL's reader does not make");
  return layout;
}

// The message of a PLY file refused here, as CGAL's refusals read (read_polygon_soup()).
inline std::string ply_error(const std::string& reason) { return "cannot parse the file as ply (" + reason + ")"; }

// Skips `bytes` bytes of a binary body; a file that ends first fails the stream.
inline void skip_ply_bytes(std::istream& in, std::uintmax_t bytes)
{
  in.ignore(std::streamsize(bytes));
  if(std::uintmax_t(in.gcount()) != bytes)
    in.setstate(std::ios::failbit);
}

// After a failed read: whether only white space was left, a file cut short, rather than a malformed
// value (CGAL's ASCII reader clears the end-of-file bit when a read fails).
inline bool ply_file_ends(std::istream& in)
{
  in.clear();
  return (in >> std::ws).peek() == std::char_traits<char>::eof();
}

// Reads one property of an item as CGAL's reader does, but a list's length is checked against the
// bytes left before its entries are read (and none is stored). False when the file ends or a value
// is malformed. `describe_list(length)` starts the reason of a refused length.
template <typename Describe>
bool read_ply_property(std::istream& in, const Ply_property_layout& property, bool ascii, Byte_budget& budget,
                       const Describe& describe_list)
{
  if(!property.is_list())
  {
    if(ascii)
      property.reader->get(in);
    else
      skip_ply_bytes(in, property.bytes);
    budget.take(1, ascii ? 1 : property.bytes);
    return !in.fail();
  }
  const std::uintmax_t length = property.read_length(*property.reader, in);
  if(in.fail())
    return false;
  budget.take(1, ascii ? 1 : property.bytes);
  const std::uintmax_t entry_bytes = ascii ? 1 : property.entry_bytes;
  budget.check(length, entry_bytes,
               [&](const std::string& excess) { return ply_error(describe_list(length) + excess); });
  if(ascii)
    for(std::uintmax_t i = 0; i < length && !in.fail(); ++i)
      property.read_entry(*property.reader, in);
  else
    skip_ply_bytes(in, length * entry_bytes);
  budget.take(length, entry_bytes);
  return !in.fail();
}

// Every PLY count checked against the bytes left before CGAL 5.5's reader sees the file: the items of
// every element, from the header, and the length of every list of every item, from the body. The
// body is read through here with CGAL's own header parser and value readers, so that both see the
// same numbers; a number takes at least one byte in ASCII, its type's size in binary. A file that
// ends early or has a malformed value is refused here too: CGAL's reader would size a list to the
// length it failed to read. Headers that CGAL refuses are left to it, and its message.
inline void check_ply_counts(const Input_file& file)
{
  std::ifstream in(file.name, std::ios::binary); // as CGAL::IO::read_PLY() opens it
  bool ascii = true;
  {
    std::string line, format_tag, format;
    if(std::getline(in, line) && std::getline(in, line))
      std::istringstream(line) >> format_tag >> format;
    ascii = format != "binary_little_endian" && format != "binary_big_endian"; // CGAL refuses other names
    in.clear();
    in.seekg(0);
  }
  CGAL::IO::internal::PLY_reader reader(false);
  // through std::istream&, as CGAL's readers call it: one instance of init(), 20 kB of code, not two
  std::istream& stream = in;
  if(!in || !reader.init(stream))
    return;
  if(in.fail())
    throw Input_error(ply_error("no end_header line"));
  const std::streamoff header_end = in.tellg();
  const std::uintmax_t read = header_end > 0 ? std::uintmax_t(header_end) : file.size;
  const Byte_budget after_header(file.size, read < file.size ? file.size - read : 0);

  // The header's counts, each item at least its properties' numbers.
  std::vector<std::vector<Ply_property_layout>> layouts(reader.number_of_elements());
  std::vector<std::uintmax_t> item_bytes(reader.number_of_elements(), 0);
  Byte_budget header = after_header;
  for(std::size_t e = 0; e < reader.number_of_elements(); ++e)
  {
    CGAL::IO::internal::PLY_element& element = reader.element(e);
    for(std::size_t p = 0; p < element.number_of_properties(); ++p)
    {
      layouts[e].push_back(ply_property_layout(element.property(p)));
      item_bytes[e] += ascii ? 1 : layouts[e].back().bytes;
    }
    header.check(element.number_of_items(), item_bytes[e], [&](const std::string& excess) {
      return ply_error("the header announces " + std::to_string(element.number_of_items()) + " items of element '" +
                       element.name() + "'" + excess);
    });
    header.take(element.number_of_items(), item_bytes[e]);
  }

  // The body: binary elements without lists are skipped whole.
  Byte_budget body = after_header;
  for(std::size_t e = 0; e < reader.number_of_elements(); ++e)
  {
    CGAL::IO::internal::PLY_element& element = reader.element(e);
    bool has_list = false;
    for(const Ply_property_layout& property : layouts[e])
      has_list = has_list || property.is_list();
    if(!ascii && !has_list)
    {
      body.check(element.number_of_items(), item_bytes[e], [&](const std::string& excess) {
        return ply_error("the header announces " + std::to_string(element.number_of_items()) + " items of element '" +
                         element.name() + "'" + excess);
      });
      skip_ply_bytes(in, element.number_of_items() * item_bytes[e]);
      body.take(element.number_of_items(), item_bytes[e]);
      if(in.fail())
        throw Input_error(ply_error("a file of " + std::to_string(file.size) + " bytes ends in element '" +
                                    element.name() + "'"));
      continue;
    }
    for(std::size_t item = 0; item < element.number_of_items(); ++item)
      for(const Ply_property_layout& property : layouts[e])
        if(!read_ply_property(in, property, ascii, body, [&](std::uintmax_t length) {
             return "item " + std::to_string(item) + " of element '" + element.name() + "' announces a list '" +
                    property.reader->name() + "' of " + std::to_string(length) + " entries";
           }))
          throw Input_error(ply_error((ply_file_ends(in) ? "a file of " + std::to_string(file.size) + " bytes ends in"
                                                         : std::string("a malformed value in")) +
                                      " item " + std::to_string(item) + " of element '" + element.name() +
                                      "', property '" + property.reader->name() + "'"));
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_CHECK_PLY_COUNTS_H
