// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// read, knn, estimate_normals, height_features.

#include "bindings.h"
#include "numpy_arrays.h"

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <Lidar_io/Las_writer.h>
#include <Lidar_io/Laz_writer.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>

namespace sigmoid_neighborhoods_python {

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;
typedef SN::Parallel_if_available_tag Tag;

namespace {

SN::Oriented_point_set::Point_3 viewpoint_of(const py::object& viewpoint, SN::Normal_orientation orientation)
{
  if(viewpoint.is_none())
  {
    if(orientation == SN::Normal_orientation::VIEWPOINT)
      throw std::invalid_argument("orientation 'viewpoint' needs a viewpoint (x, y, z)");
    return CGAL::ORIGIN;
  }
  const std::vector<double> v = viewpoint.cast<std::vector<double>>();
  if(v.size() != 3)
    throw std::invalid_argument("the viewpoint must have 3 coordinates, got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

template <typename T>
py::object array_or_none(std::vector<T>& values)
{
  if(values.empty())
    return py::none();
  return to_numpy(std::move(values));
}

py::dict read(const py::object& path, const std::string& normals, unsigned int k, const std::string& orientation,
              const py::object& viewpoint, const std::optional<int>& threads)
{
  const std::string filename = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  SN::Normal_options options;
  options.source = SN::normal_source_from_name(normals);
  options.neighbors = k;
  options.orientation = SN::normal_orientation_from_name(orientation);
  options.viewpoint = viewpoint_of(viewpoint, options.orientation);
  options.threads = threads_of(threads);
  SN::Oriented_point_set set;
  {
    py::gil_scoped_release release;
    set = SN::read_oriented_point_set(filename, options);
  }
  const std::size_t n = set.points.size();
  py::array_t<double> points({py::ssize_t(n), py::ssize_t(3)});
  double* p = points.mutable_data();
  for(std::size_t i = 0; i < n; ++i)
    for(int c = 0; c < 3; ++c)
      p[3 * i + c] = set.points[i][c];
  py::object normal_array = py::none();
  if(!set.normals.empty())
  {
    py::array_t<double> a({py::ssize_t(n), py::ssize_t(3)});
    double* q = a.mutable_data();
    for(std::size_t i = 0; i < n; ++i)
      for(int c = 0; c < 3; ++c)
        q[3 * i + c] = set.normals[i][c];
    normal_array = a;
  }
  py::dict result;
  result["points"] = points;
  result["normals"] = normal_array;
  std::vector<std::int32_t> labels(set.labels.begin(), set.labels.end());
  result["labels"] = array_or_none(labels);
  result["intensity"] = array_or_none(set.intensities);
  result["return_number"] = array_or_none(set.return_numbers);
  result["number_of_returns"] = array_or_none(set.numbers_of_returns);
  result["gps_time"] = array_or_none(set.gps_times);
  result["is_mesh"] = set.is_mesh;
  result["normals_estimated"] = set.normals_estimated;
  result["orientation_components"] = set.orientation_components;
  result["input_vertices"] = set.input_vertices;
  result["merged_duplicates"] = set.merged_duplicates;
  result["zero_normals"] = set.zero_normals;
  result["dropped_vertices"] = set.dropped_vertices;
  return result;
}

// A one-dimensional array of n values as doubles (a copy when converted), or none.
std::optional<py::array_t<double, py::array::forcecast>> column_of(const py::object& object, std::size_t n,
                                                                   const std::string& name)
{
  if(object.is_none())
    return std::nullopt;
  py::array array = py::array::ensure(object);
  if(!array || (array.dtype().kind() != 'f' && array.dtype().kind() != 'i' && array.dtype().kind() != 'u' &&
                array.dtype().kind() != 'b'))
    throw py::type_error(name + " must be an array of numbers");
  if(array.ndim() != 1 || std::size_t(array.shape(0)) != n)
    throw py::value_error(name + " must have shape (" + std::to_string(n) + ",), got " + Rows_3::shape_text(array));
  return py::array_t<double, py::array::forcecast>::ensure(array);
}

// The smallest extra bytes type that holds the dtype's values exactly.
Lidar_io::Las_extra_bytes_type extra_bytes_type(const py::dtype& dtype)
{
  typedef Lidar_io::Las_extra_bytes_type T;
  const char kind = dtype.kind();
  const py::ssize_t size = dtype.itemsize();
  if(kind == 'f')
    return size <= 4 ? T::FLOAT : T::DOUBLE;
  if(kind == 'b')
    return T::UNSIGNED_CHAR;
  const bool is_unsigned = kind == 'u';
  if(size == 1)
    return is_unsigned ? T::UNSIGNED_CHAR : T::CHAR;
  if(size == 2)
    return is_unsigned ? T::UNSIGNED_SHORT : T::SHORT;
  if(size == 4)
    return is_unsigned ? T::UNSIGNED_LONG : T::LONG;
  return is_unsigned ? T::UNSIGNED_LONG_LONG : T::LONG_LONG;
}

void write(const py::object& path, const py::object& points_object, const py::object& fields_object,
           const py::object& labels, const py::object& intensity, const py::object& return_number,
           const py::object& number_of_returns, const py::object& gps_time)
{
  const std::string filename = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  const std::string extension = SN::lower_case_extension(filename);
  if(extension != "las" && extension != "laz")
    throw py::value_error(filename + ": write() writes LAS (.las) or LAZ (.laz)");
  const Rows_3 points(points_object, "points");
  const std::size_t n = points.size();
  const auto classification = column_of(labels, n, "labels");
  const auto intensities = column_of(intensity, n, "intensity");
  const auto returns = column_of(return_number, n, "return_number");
  const auto numbers = column_of(number_of_returns, n, "number_of_returns");
  const auto times = column_of(gps_time, n, "gps_time");
  std::vector<Lidar_io::Las_extra_dimension> dimensions;
  std::vector<py::array_t<double, py::array::forcecast>> columns;
  if(!fields_object.is_none())
    for(const auto& item : fields_object.cast<py::dict>())
    {
      const std::string name = py::str(item.first);
      py::array array = py::array::ensure(item.second);
      if(!array)
        throw py::type_error("field " + name + " must be an array of numbers");
      columns.push_back(*column_of(py::reinterpret_borrow<py::object>(item.second), n, "field " + name));
      dimensions.push_back({name, "", extra_bytes_type(array.dtype())});
    }
  std::array<double, 3> min{{0., 0., 0.}}, max{{0., 0., 0.}};
  for(std::size_t i = 0; i < n; ++i)
    for(int c = 0; c < 3; ++c)
    {
      const double v = points(i, c);
      if(!std::isfinite(v))
        throw py::value_error("points[" + std::to_string(i) + "] is not finite");
      min[c] = i == 0 ? v : (std::min)(min[c], v);
      max[c] = i == 0 ? v : (std::max)(max[c], v);
    }
  Lidar_io::Las_output_layout layout = Lidar_io::las_output_layout_for(min, max, dimensions); // ValueError: a bad name
  const std::string temporary = filename + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if(!out)
      throw py::value_error("cannot write " + filename + ": " + std::strerror(errno));
    try
    {
      // a field's value clamped to what it holds (NaN as 0): no conversion out of range
      auto at = [](const std::optional<py::array_t<double, py::array::forcecast>>& a, std::size_t i, double otherwise,
                   double largest) {
        const double v = a ? a->data()[i] : otherwise;
        return std::isnan(v) ? 0. : std::clamp(std::nearbyint(v), 0., largest);
      };
      auto write_records = [&](auto& writer) {
        const Lidar_io::Las_output_layout& l = writer.layout();
        std::vector<unsigned char> record(l.record_length);
        for(std::size_t i = 0; i < n; ++i)
        {
          std::fill(record.begin(), record.end(), 0);
          Lidar_io::store_las_coordinates(record.data(), l, {{points(i, 0), points(i, 1), points(i, 2)}});
          Lidar_io::store_little_endian<std::uint16_t>(record.data() + 12, std::uint16_t(at(intensities, i, 0., 65535.)));
          record[14] = std::uint8_t(unsigned(at(returns, i, 1., 15.)) | unsigned(at(numbers, i, 1., 15.)) << 4);
          record[16] = std::uint8_t(at(classification, i, 0., 255.));
          Lidar_io::store_little_endian<double>(record.data() + 22, times ? times->data()[i] : 0.);
          for(std::size_t j = 0; j < columns.size(); ++j)
            Lidar_io::store_las_extra(record.data(), l, j, columns[j].data()[i]);
          writer.write(record.data(), 1);
        }
        writer.close();
      };
      if(extension == "laz")
      {
        Lidar_io::Laz_writer<> writer(out, layout);
        write_records(writer);
      }
      else
      {
        Lidar_io::Las_writer writer(out, layout);
        write_records(writer);
      }
      out.close();
      if(!out)
        throw std::ios_base::failure("cannot write " + filename);
    }
    catch(...)
    {
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
  }
  if(std::rename(temporary.c_str(), filename.c_str()) != 0)
    throw py::value_error("cannot write " + filename + ": " + std::strerror(errno));
}

py::tuple knn(const py::object& points_object, unsigned int k, const std::optional<int>& threads)
{
  const Rows_3 points(points_object, "points");
  const unsigned int thread_count = threads_of(threads);
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  {
    py::gil_scoped_release release;
    SN::compute_k_nearest_neighbors<Tag>(
      point_range(points.size()), k, indices, offsets,
      SNP::number_of_threads(thread_count, CGAL::parameters::point_map(Point_rows_map{&points})));
  }
  return py::make_tuple(to_numpy(std::move(indices)), to_numpy(std::move(offsets)));
}

py::array_t<double> estimate_normals(const py::object& points_object, unsigned int k, const std::string& method_name,
                                     const std::string& orientation_name, const py::object& viewpoint_object,
                                     const py::object& neighbors, const std::optional<int>& threads)
{
  const Rows_3 points(points_object, "points");
  const SN::Normal_estimation_method method = SN::normal_estimation_method_from_name(method_name);
  const SN::Normal_orientation orientation = SN::normal_orientation_from_name(orientation_name);
  const SN::Oriented_point_set::Point_3 viewpoint = viewpoint_of(viewpoint_object, orientation);
  const unsigned int thread_count = threads_of(threads);
  const std::size_t n = points.size();
  std::optional<Neighbor_rows> rows = neighbor_rows(neighbors, points, unsigned((std::min)(std::size_t(k), n ? n - 1 : 0)));
  py::array_t<double> normals({py::ssize_t(n), py::ssize_t(3)});
  Output_rows_map<Vector_3> normal_map{normals.mutable_data()};
  py::gil_scoped_release release;
  const auto maps = SNP::number_of_threads(
    thread_count, CGAL::parameters::point_map(Point_rows_map{&points}).normal_map(normal_map));
  if(!rows)
  {
    // one neighbor structure for the estimation and the orientation, as read() does
    rows.emplace();
    if(n > std::size_t(k))
      SN::compute_k_nearest_neighbors<Tag>(point_range(n), k, rows->indices, rows->offsets, maps);
  }
  const auto np = SNP::neighbor_indices(std::cref(rows->indices), SNP::neighbor_offsets(std::cref(rows->offsets), maps));
  auto range = point_range(n); // written through the maps
  SN::estimate_normals<Tag>(range, k, SNP::normal_estimation_method(method, np));
  if(orientation == SN::Normal_orientation::SPANNING_FOREST)
    SN::orient_normals_by_spanning_forest<Tag>(range, k, np);
  else if(orientation == SN::Normal_orientation::VIEWPOINT)
    SN::orient_normals_towards_viewpoint(range, viewpoint, maps);
  else if(orientation == SN::Normal_orientation::UPWARD)
    for(std::size_t i = 0; i < n; ++i)
      if(normal_map.data[3 * i + 2] < 0.)
        put(normal_map, i, -get(normal_map, i));
  return normals;
}

py::dict height_features(const py::object& points_object, double cell_size)
{
  const Rows_3 points(points_object, "points");
  const std::size_t n = points.size();
  py::array_t<double> above = new_array<double>(n), below = new_array<double>(n), range = new_array<double>(n);
  double *a = above.mutable_data(), *b = below.mutable_data(), *r = range.mutable_data();
  {
    py::gil_scoped_release release;
    std::size_t i = 0;
    SN::compute_height_features(point_range(n), cell_size, boost::make_function_output_iterator([&](const SN::Height_features& h) {
                                  a[i] = h.height_above_lowest;
                                  b[i] = h.height_below_highest;
                                  r[i++] = h.vertical_range;
                                }),
                                CGAL::parameters::point_map(Point_rows_map{&points}));
  }
  py::dict result;
  result["height_above_lowest"] = above;
  result["height_below_highest"] = below;
  result["vertical_range"] = range;
  return result;
}

} // namespace

void bind_points(py::module_& m)
{
  using namespace pybind11::literals;
  m.def("read", &read, "path"_a, py::kw_only(), "normals"_a = "auto", "k"_a = SN::DEFAULT_ESTIMATION_NEIGHBORS,
        "orientation"_a = "mst", "viewpoint"_a = py::none(), "threads"_a = py::none(),
        R"doc(read(path, *, normals="auto", k=18, orientation="mst", viewpoint=None, threads=None) -> dict

Reads a mesh (OFF, PLY, OBJ, STL) or a point set (XYZ/PWN, PLY, OFF without faces, uncompressed LAS)
into distinct points with oriented unit normals, as read_oriented_point_set() (SPEC section 1) and the
command line do: a mesh gives one point per vertex with a face and its vertex normal; a point set's
duplicates are merged, the first kept with its label and LAS fields.

Parameters
----------
path : str or os.PathLike
    the file; its extension (any case) selects the format: .off .obj .ply .stl .xyz .pwn .las .laz
normals : {"auto", "file", "pca", "jet"}
    "auto": the file's, estimated when it has none (k = 0: not estimated, normals is None);
    "file": the file's, an error without; "pca", "jet": estimated, the file's ignored
k : int
    the neighbors of the estimation and of the spanning-forest orientation (default 18)
orientation : {"mst", "viewpoint", "up", "none"}
    of estimated normals: a minimum spanning forest from each component's highest point, towards
    `viewpoint`, towards +z (airborne scans), or as estimated
viewpoint : (x, y, z), optional
    for orientation="viewpoint"
threads : int, optional
    threads of the LAZ decoding and the estimation (None: OpenMP's default)

Returns
-------
dict with "points" (n, 3) float64; "normals" (n, 3) float64 or None; "labels" int32 (LAS classification,
PLY label/class/classification) or None; "intensity" uint16, "return_number" and "number_of_returns"
uint8, "gps_time" float64 (LAS) or None; "is_mesh", "normals_estimated" (bool);
"orientation_components", "input_vertices", "merged_duplicates", "dropped_vertices", "zero_normals" (int).

Raises
------
OSError
    a missing, unreadable, empty or malformed file, damaged LAZ or wave packets, non-finite coordinates, zero normals, no points,
    no normals with normals="file", too few points to estimate normals; the message is the reader's
ValueError
    unknown option values, k below what the estimation needs
)doc");

  m.def("write", &write, "path"_a, "points"_a, "fields"_a = py::none(), py::kw_only(), "labels"_a = py::none(),
        "intensity"_a = py::none(), "return_number"_a = py::none(), "number_of_returns"_a = py::none(),
        "gps_time"_a = py::none(),
        R"doc(write(path, points, fields=None, *, labels=None, intensity=None, return_number=None, number_of_returns=None, gps_time=None)

Writes the points as a LAS 1.4 file (point data format 6), or a LAZ file (.laz: the same compressed as
LASzip compresses it, on all cores), which read() reads back: the coordinates
rounded to one scale for the three axes, the smallest power of ten for which the points' largest half
extent takes at most 2^30 units (a coordinate moves by at most half a unit, below 5e-9 times the
largest extent, and the rounding of a double); labels (0 to 255) as the classification, intensity, return numbers (default 1 of 1)
and GPS time as LAS stores them; each entry of `fields` as an extra bytes dimension of that name and
of the array's type (float32, float64, int8 to uint64; bool as uint8), described in the Extra Bytes
record that PDAL, LAStools, lidR and CloudCompare read. Written to a temporary file and renamed.

Parameters
----------
path : str or os.PathLike
    a .las or .laz file
points : (n, 3) array of numbers
fields : dict of str to (n,) arrays, optional
    names of at most 32 characters
labels, intensity, return_number, number_of_returns, gps_time : (n,) arrays, optional

Raises
------
ValueError
    another extension, non-finite points, a field's name or shape, a file that cannot be created
RuntimeError
    a write that fails (a full disk); no file is left
TypeError
    arrays that do not hold numbers
)doc");

  m.def("knn", &knn, "points"_a, "k"_a, py::kw_only(), "threads"_a = py::none(),
        R"doc(knn(points, k, *, threads=None) -> (indices, offsets)

The k nearest other points of every point in compressed rows (pgeof's nn / nn_ptr), SPEC section 2:
row i is indices[offsets[i]:offsets[i + 1]], the min(k, n - 1) nearest points other than i, ordered
by distance and then by index (the package's own kd-tree order: an algorithm given these rows through
neighbors= computes what it computes without them, bit for bit). The same for any number of threads.

Parameters
----------
points : (n, 3) array
k : int
    at least 1
threads : int, optional

Returns
-------
indices : uint32 array of n * min(k, n - 1) entries
offsets : uint64 array of n + 1 entries

Raises
------
ValueError
    k < 1, non-finite coordinates, 2^32 points or more
)doc");

  m.def("estimate_normals", &estimate_normals, "points"_a, "k"_a = SN::DEFAULT_ESTIMATION_NEIGHBORS, py::kw_only(),
        "method"_a = "pca", "orientation"_a = "mst", "viewpoint"_a = py::none(), "neighbors"_a = py::none(),
        "threads"_a = py::none(),
        R"doc(estimate_normals(points, k=18, *, method="pca", orientation="mst", viewpoint=None, neighbors=None, threads=None) -> normals

Estimates a unit normal at every point from the point and its k nearest other points
(estimate_normals()), then orients them (orient_normals_by_spanning_forest(),
orient_normals_towards_viewpoint()), both steps on one neighbor structure: what read() does for a
file without normals, bit for bit.

Parameters
----------
points : (n, 3) array
k : int
    neighbors per fit: at least 2 (pca) or 5 (jet of degree 2); at least k + 1 points
method : {"pca", "jet"}
    the eigenvector of the least eigenvalue of the covariance (as CGAL::pca_estimate_normals()), or the
    normal of a fitted jet of degree 2 (as CGAL::jet_estimate_normals())
orientation : {"mst", "viewpoint", "up", "none"}
    a minimum spanning forest of the k-nearest-neighbor graph, every component from its highest point
    turned towards +z; towards `viewpoint`; towards +z; or none (signs arbitrary)
viewpoint : (x, y, z), optional
neighbors : (indices, offsets), optional
    caller rows of at least min(k, n - 1) neighbors (see knn()), checked
threads : int, optional

Returns
-------
(n, 3) float64 array of unit normals

Raises
------
ValueError
    too few points or neighbors, points whose neighbors coincide or lie on a line, bad neighbor rows
)doc");

  m.def("height_features", &height_features, "points"_a, "cell_size"_a,
        R"doc(height_features(points, cell_size) -> dict

The height features of every point in square horizontal cells of side cell_size
(compute_height_features()), as CGAL's Point_set_feature_generator computes them: cells
[i c, (i + 1) c) x [j c, (j + 1) c) anchored at the origin, so that adjacent tiles get the cells of
their union; z is up.

Returns
-------
dict of float64 arrays: "height_above_lowest" (z - min z), "height_below_highest" (max z - z),
"vertical_range" (max z - min z), over the point's cell

Raises
------
ValueError
    cell_size not positive and finite, non-finite coordinates
)doc");
}

} // namespace sigmoid_neighborhoods_python
