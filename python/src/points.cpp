// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// read, knn, estimate_normals, height_features.

#include "bindings.h"
#include "numpy_arrays.h"

#include <CGAL/Sigmoid_neighborhoods/IO/read_oriented_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <pybind11/stl.h>

#include <functional>
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
