// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// numpy arrays as the package's inputs and outputs: coordinates read where they are through property
// maps, caller neighbor rows checked, results written into arrays numpy owns.

#ifndef SIGMOID_NEIGHBORHOODS_PYTHON_NUMPY_ARRAYS_H
#define SIGMOID_NEIGHBORHOODS_PYTHON_NUMPY_ARRAYS_H

#include <CGAL/Simple_cartesian.h>

#include <boost/property_map/property_map.hpp>
#include <boost/range/counting_range.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sigmoid_neighborhoods_python {

namespace py = pybind11;

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;

// An (n, 3) array of float32 or float64 in any layout, read in place; any other real or integer type
// is converted to float64 first (a copy). Coordinates are converted to double one by one, exactly.
class Rows_3
{
public:
  Rows_3() = default;
  Rows_3(const py::handle& object, const char* name)
  {
    if(object.is_none())
      throw py::type_error(std::string(name) + " is None" +
                           (std::string(name) == "normals"
                              ? ": read() gives None for a file without normals and k = 0; estimate_normals() gives them"
                              : ""));
    py::array array = py::array::ensure(object);
    if(!array)
      throw py::type_error(std::string(name) + " must be an array of shape (n, 3)");
    const char kind = array.dtype().kind();
    if(kind != 'f' && kind != 'i' && kind != 'u')
      throw py::type_error(std::string(name) + " must hold real numbers (dtype kind 'f', 'i' or 'u'), got dtype " +
                           std::string(py::str(array.dtype())));
    if(array.ndim() != 2 || array.shape(1) != 3)
      throw py::value_error(std::string(name) + " must have shape (n, 3), got " + shape_text(array));
    if(array.dtype().is(py::dtype::of<float>()))
      m_single = true;
    else if(!array.dtype().is(py::dtype::of<double>()))
      array = py::array_t<double, py::array::forcecast>::ensure(array);
    m_array = array;
    m_data = static_cast<const char*>(array.data());
    m_size = std::size_t(array.shape(0));
    m_row_stride = array.strides(0);
    m_column_stride = array.strides(1);
  }

  std::size_t size() const { return m_size; }
  bool is_single() const { return m_single; }

  double operator()(std::size_t i, int c) const
  {
    const char* p = m_data + py::ssize_t(i) * m_row_stride + c * m_column_stride;
    return m_single ? double(*reinterpret_cast<const float*>(p)) : *reinterpret_cast<const double*>(p);
  }

  static std::string shape_text(const py::array& a)
  {
    std::string s = "(";
    for(py::ssize_t d = 0; d < a.ndim(); ++d)
      s += (d ? ", " : "") + std::to_string(a.shape(d));
    return s + (a.ndim() == 1 ? ",)" : ")");
  }

private:
  py::array m_array; // keeps a converted copy alive
  const char* m_data = nullptr;
  std::size_t m_size = 0;
  py::ssize_t m_row_stride = 0, m_column_stride = 0;
  bool m_single = false;
};

// Rows_3 as CGAL property maps over the indices 0, ..., n - 1.
struct Point_rows_map
{
  typedef std::size_t key_type;
  typedef Point_3 value_type;
  typedef Point_3 reference;
  typedef boost::readable_property_map_tag category;
  const Rows_3* rows;
  friend Point_3 get(const Point_rows_map& m, std::size_t i) { return Point_3((*m.rows)(i, 0), (*m.rows)(i, 1), (*m.rows)(i, 2)); }
};

struct Vector_rows_map
{
  typedef std::size_t key_type;
  typedef Vector_3 value_type;
  typedef Vector_3 reference;
  typedef boost::readable_property_map_tag category;
  const Rows_3* rows;
  friend Vector_3 get(const Vector_rows_map& m, std::size_t i)
  {
    return Vector_3((*m.rows)(i, 0), (*m.rows)(i, 1), (*m.rows)(i, 2));
  }
};

// A C-contiguous float64 (n, 3) output array as a read-write map of points or vectors.
template <typename Value>
struct Output_rows_map
{
  typedef std::size_t key_type;
  typedef Value value_type;
  typedef Value reference;
  typedef boost::read_write_property_map_tag category;
  double* data;
  friend Value get(const Output_rows_map& m, std::size_t i) { return Value(m.data[3 * i], m.data[3 * i + 1], m.data[3 * i + 2]); }
  friend void put(const Output_rows_map& m, std::size_t i, const Value& v)
  {
    m.data[3 * i] = v[0];
    m.data[3 * i + 1] = v[1];
    m.data[3 * i + 2] = v[2];
  }
};

// The keys of the maps: the indices 0, ..., n - 1.
inline boost::iterator_range<boost::counting_iterator<std::size_t>> point_range(std::size_t n)
{
  return boost::counting_range(std::size_t(0), n);
}

// A new one-dimensional array of n values.
template <typename T>
py::array_t<T> new_array(std::size_t n)
{
  return py::array_t<T>(std::vector<py::ssize_t>{py::ssize_t(n)});
}

// A new C-contiguous float64 (n, 3) array holding `rows`' values.
inline py::array_t<double> copy_rows(const Rows_3& rows)
{
  py::array_t<double> result({py::ssize_t(rows.size()), py::ssize_t(3)});
  double* out = result.mutable_data();
  for(std::size_t i = 0; i < rows.size(); ++i)
    for(int c = 0; c < 3; ++c)
      out[3 * i + c] = rows(i, c);
  return result;
}

// A std::vector moved into a numpy array that owns it (through a capsule), without a copy.
template <typename T>
py::array_t<T> to_numpy(std::vector<T>&& values, std::vector<py::ssize_t> shape = {})
{
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  if(shape.empty())
    shape.push_back(py::ssize_t(owned->size()));
  return py::array_t<T>(shape, owned->data(), free_when_done);
}

inline unsigned int threads_of(const std::optional<int>& threads)
{
  if(!threads)
    return 0;
  if(*threads < 1)
    throw py::value_error("threads must be at least 1 (or None: OpenMP's default), got " + std::to_string(*threads));
  return unsigned(*threads);
}

// Caller neighborhoods in compressed rows (pgeof's `nn`, `nn_ptr`), any integer types, checked against
// the points: every index in [0, n) and not the point itself, at least `fewest` entries per row and,
// where the first k of a row are taken as the k nearest (`ordered`), rows ordered by distance (ties in
// any order). Held in the package's own types.
struct Neighbor_rows
{
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
};

namespace detail {

template <typename T>
std::vector<T> integer_vector(const py::handle& object, const char* name)
{
  py::array array = py::array::ensure(object);
  if(!array || (array.dtype().kind() != 'i' && array.dtype().kind() != 'u'))
    throw py::type_error(std::string("neighbors: ") + name + " must be an array of integers");
  if(array.ndim() != 1)
    throw py::value_error(std::string("neighbors: ") + name + " must be one-dimensional, got shape " +
                          Rows_3::shape_text(array));
  const py::array_t<std::int64_t, py::array::forcecast> values = py::array_t<std::int64_t, py::array::forcecast>::ensure(array);
  const std::int64_t* v = values.data();
  std::vector<T> result(std::size_t(values.size()));
  for(std::size_t e = 0; e < result.size(); ++e)
  {
    if(v[e] < 0)
      throw py::value_error(std::string("neighbors: ") + name + "[" + std::to_string(e) + "] is " +
                            std::to_string(v[e]) + ": negative (a missing neighbor?)");
    if(sizeof(T) < 8 && std::uint64_t(v[e]) > std::uint64_t(UINT32_MAX))
      throw py::value_error(std::string("neighbors: ") + name + "[" + std::to_string(e) + "] is " +
                            std::to_string(v[e]) + ": beyond 2^32 - 1");
    result[e] = T(v[e]);
  }
  return result;
}

} // namespace detail

inline std::optional<Neighbor_rows> neighbor_rows(const py::object& neighbors, const Rows_3& points, unsigned int fewest,
                                                 bool ordered = true)
{
  if(neighbors.is_none())
    return std::nullopt;
  py::sequence pair;
  if(!py::isinstance<py::sequence>(neighbors) || py::len(neighbors) != 2)
    throw py::type_error("neighbors must be a pair (indices, offsets), as knn() returns it");
  pair = neighbors.cast<py::sequence>();
  Neighbor_rows rows;
  rows.indices = detail::integer_vector<std::uint32_t>(pair[0], "indices");
  rows.offsets = detail::integer_vector<std::size_t>(pair[1], "offsets");
  const std::size_t n = points.size();
  if(rows.offsets.size() != n + 1)
    throw py::value_error("neighbors: offsets must hold n + 1 = " + std::to_string(n + 1) + " entries, got " +
                          std::to_string(rows.offsets.size()));
  if(rows.offsets[0] != 0 || rows.offsets[n] != rows.indices.size())
    throw py::value_error("neighbors: offsets must start at 0 and end at len(indices) = " +
                          std::to_string(rows.indices.size()));
  py::gil_scoped_release release;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t begin = rows.offsets[i], end = rows.offsets[i + 1];
    if(end < begin)
      throw py::value_error("neighbors: row " + std::to_string(i) + ": offsets decrease");
    if(end - begin < fewest)
      throw py::value_error("neighbors: row " + std::to_string(i) + " has " + std::to_string(end - begin) +
                            " neighbors, at least " + std::to_string(fewest) + " are needed");
    double previous = 0.;
    for(std::size_t e = begin; e < end; ++e)
    {
      const std::size_t j = rows.indices[e];
      if(j >= n)
        throw py::value_error("neighbors: row " + std::to_string(i) + ": index " + std::to_string(j) +
                              " is out of range (" + std::to_string(n) + " points)");
      if(j == i)
        throw py::value_error("neighbors: row " + std::to_string(i) + " contains the point itself");
      double d2 = 0.;
      for(int c = 0; c < 3; ++c)
        d2 += (points(j, c) - points(i, c)) * (points(j, c) - points(i, c));
      if(ordered && d2 < previous)
        throw py::value_error("neighbors: row " + std::to_string(i) + " is not ordered by distance (entry " +
                              std::to_string(e - begin) + " is nearer than the one before)");
      previous = d2;
    }
  }
  return rows;
}

} // namespace sigmoid_neighborhoods_python

#endif // SIGMOID_NEIGHBORHOODS_PYTHON_NUMPY_ARRAYS_H
