// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_PLY_POINT_LAYOUT_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_PLY_POINT_LAYOUT_H

#include <Sigmoid_neighborhoods_readers/internal/cgal_5_5_workarounds.h>
#include <Sigmoid_neighborhoods_readers/internal/input_file.h>

#include <CGAL/IO/PLY/PLY_reader.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The PLY vertex properties taken as per-point labels, the first present in this order.
inline const std::vector<std::string>& ply_label_names()
{
  static const std::vector<std::string> names = {"label", "class", "classification"};
  return names;
}

// One scalar vertex property of a PLY file: where it lies in a record and how to read it.
struct Ply_field
{
  std::size_t offset = 0; // in a binary record
  std::size_t column = 0; // among the properties: the token of an ASCII record
  enum Type { INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT, DOUBLE } type = DOUBLE;

  double read(const unsigned char* record) const
  {
    const unsigned char* at = record + offset;
    switch(type)
    {
    case INT8: return double(load<std::int8_t>(at));
    case UINT8: return double(load<std::uint8_t>(at));
    case INT16: return double(load<std::int16_t>(at));
    case UINT16: return double(load<std::uint16_t>(at));
    case INT32: return double(load<std::int32_t>(at));
    case UINT32: return double(load<std::uint32_t>(at));
    case FLOAT: return double(load<float>(at));
    default: return load<double>(at);
    }
  }

  template <typename T>
  static T load(const unsigned char* at)
  {
    T value;
    std::memcpy(&value, at, sizeof(T)); // little-endian files on little-endian machines only
    return value;
  }
};

// The type and size of one of CGAL's scalar PLY readers; false for a list.
inline bool ply_field_type(const CGAL::IO::internal::PLY_read_number* property, Ply_field::Type& type,
                           std::size_t& bytes)
{
  using CGAL::IO::internal::PLY_read_typed_number;
  auto is = [property](auto value) {
    return dynamic_cast<const PLY_read_typed_number<decltype(value)>*>(property) != nullptr;
  };
  if(is(std::int8_t())) { type = Ply_field::INT8; bytes = 1; }
  else if(is(std::uint8_t())) { type = Ply_field::UINT8; bytes = 1; }
  else if(is(std::int16_t())) { type = Ply_field::INT16; bytes = 2; }
  else if(is(std::uint16_t())) { type = Ply_field::UINT16; bytes = 2; }
  else if(is(std::int32_t())) { type = Ply_field::INT32; bytes = 4; }
  else if(is(std::uint32_t())) { type = Ply_field::UINT32; bytes = 4; }
  else if(is(float())) { type = Ply_field::FLOAT; bytes = 4; }
  else if(is(double())) { type = Ply_field::DOUBLE; bytes = 8; }
  else
    return false;
  return true;
}

// What the fast PLY readers take from a point set's header: the vertex element's properties, those
// CGAL's point set reader takes from them, and where the records start.
struct Ply_point_layout
{
  enum { X, Y, Z, NX, NY, NZ, FIELDS };
  Ply_field fields[FIELDS];
  bool has_normals = false;
  bool has_label = false;
  Ply_field label;
  std::vector<Ply_field::Type> types; // of every property, in order
  std::size_t stride = 0;             // the bytes of a binary record
  std::size_t count = 0;              // the vertices
  std::streamoff header_end = 0;
};

// The layout of a PLY point set in `format` (`binary_little_endian` or `ascii`): a vertex element
// of scalars, x y z both float or both double, normals of their type or double, and no other
// element with items, after the header check CGAL's readers get (check_ply_header()). False for any
// other file: those go to CGAL's readers.
inline bool ply_point_layout(const Input_file& file, const std::string& wanted_format, Ply_point_layout& layout)
{
  std::ifstream in(file.name, std::ios::binary);
  {
    std::string line, format_tag, format;
    if(!std::getline(in, line) || !std::getline(in, line))
      return false;
    std::istringstream(line) >> format_tag >> format;
    if(format != wanted_format)
      return false;
    in.seekg(0);
  }
  check_ply_header(file.name);
  CGAL::IO::internal::PLY_reader reader(false);
  std::istream& stream = in;
  if(!reader.init(stream) || in.fail())
    return false;
  layout.header_end = in.tellg();

  const CGAL::IO::internal::PLY_element* vertices = nullptr;
  for(std::size_t e = 0; e < reader.number_of_elements(); ++e)
  {
    const CGAL::IO::internal::PLY_element& element = reader.element(e);
    if(element.name() == "vertex" || element.name() == "vertices")
    {
      if(vertices != nullptr || e != 0)
        return false;
      vertices = &element;
    }
    else if(element.number_of_items() != 0)
      return false;
  }
  if(vertices == nullptr)
    return false;

  // The record's layout, and the fields CGAL's point set reader takes from it.
  enum { X = Ply_point_layout::X, Y, Z, NX, NY, NZ, FIELDS };
  const char* const field_names[FIELDS] = {"x", "y", "z", "nx", "ny", "nz"};
  Ply_field* fields = layout.fields;
  bool found[FIELDS] = {false, false, false, false, false, false};
  int label_rank = int(ply_label_names().size()); // the first of ply_label_names() present wins
  auto& element = const_cast<CGAL::IO::internal::PLY_element&>(*vertices);
  for(std::size_t p = 0; p < element.number_of_properties(); ++p)
  {
    const CGAL::IO::internal::PLY_read_number* property = element.property(p);
    Ply_field field;
    field.offset = layout.stride;
    field.column = p;
    std::size_t bytes = 0;
    if(!ply_field_type(property, field.type, bytes))
      return false; // a list
    layout.stride += bytes;
    layout.types.push_back(field.type);
    for(int f = 0; f < FIELDS; ++f)
      if(property->name() == field_names[f])
      {
        fields[f] = field;
        found[f] = true;
      }
    for(int rank = 0; rank < label_rank; ++rank)
      if(property->name() == ply_label_names()[std::size_t(rank)])
      {
        layout.label = field;
        label_rank = rank;
      }
  }
  layout.has_label = label_rank < int(ply_label_names().size());
  // CGAL reads x y z as floats when one is a float, as doubles otherwise: both ways alike only
  auto real = [&](int f) { return fields[f].type == Ply_field::FLOAT || fields[f].type == Ply_field::DOUBLE; };
  if(!found[X] || !found[Y] || !found[Z] || !real(X) || fields[X].type != fields[Y].type ||
     fields[X].type != fields[Z].type)
    return false;
  layout.has_normals = found[NX] && found[NY] && found[NZ];
  if(layout.has_normals)
    for(int f = NX; f <= NZ; ++f)
      if(!real(f) || (fields[X].type == Ply_field::FLOAT && fields[f].type != Ply_field::FLOAT))
        return false;

  layout.count = element.number_of_items();
  return true;
}

// The labels of the values of a label property: ply_labels_of_type()'s rule, integers of `int`,
// else no labels.
inline void ply_labels_of_values(const std::vector<double>& values, std::vector<int>& labels)
{
  for(double value : values)
  {
    if(!(value >= double((std::numeric_limits<int>::min)()) && value <= double((std::numeric_limits<int>::max)())) ||
       std::trunc(value) != value)
    {
      labels.clear();
      return;
    }
    labels.push_back(int(value));
  }
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_PLY_POINT_LAYOUT_H
