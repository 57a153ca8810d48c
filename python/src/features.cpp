// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// features (one sigmoid, one or several sizes) and optimal (the search of (a*, b*, k*)).

#include "bindings.h"
#include "numpy_arrays.h"

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <pybind11/stl.h>

#include <functional>
#include <stdexcept>

namespace sigmoid_neighborhoods_python {

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;
typedef SN::Parallel_if_available_tag Tag;

namespace {

// Named result arrays of shape `shape` (+ (3,) for the eigenvalues), allocated before the GIL is
// released and written through raw pointers while it is.
class Columns
{
public:
  explicit Columns(std::vector<py::ssize_t> shape) : m_shape(std::move(shape)) {}

  template <typename T>
  T* add(const char* name, bool vector = false)
  {
    std::vector<py::ssize_t> shape = m_shape;
    if(vector)
      shape.push_back(3);
    py::array_t<T> a(shape);
    m_dict[name] = a;
    return a.mutable_data();
  }

  py::dict dict() const { return m_dict; }

private:
  std::vector<py::ssize_t> m_shape;
  py::dict m_dict;
};

struct Dimensionality_columns
{
  double *eigenvalues, *linearity, *planarity, *scattering, *error, *eigenentropy;
  std::int8_t* label;

  explicit Dimensionality_columns(Columns& c)
    : eigenvalues(c.add<double>("eigenvalues", true)), linearity(c.add<double>("linearity")),
      planarity(c.add<double>("planarity")), scattering(c.add<double>("scattering")),
      error(c.add<double>("error")), eigenentropy(c.add<double>("eigenentropy")), label(c.add<std::int8_t>("label"))
  {}

  void write(std::size_t e, const SN::Dimensionality_features& f, double criterion_value) const
  {
    for(int c = 0; c < 3; ++c)
      eigenvalues[3 * e + c] = f.eigenvalues[c];
    linearity[e] = f.linearity;
    planarity[e] = f.planarity;
    scattering[e] = f.scattering;
    error[e] = criterion_value;
    eigenentropy[e] = f.eigenentropy;
    label[e] = std::int8_t(f.label);
  }
};

// What Point_features adds to the eigenvalue features.
struct Point_feature_columns
{
  double *omnivariance, *anisotropy, *sum_of_eigenvalues, *change_of_curvature, *verticality, *normal_z, *radius;

  explicit Point_feature_columns(Columns& c)
    : omnivariance(c.add<double>("omnivariance")), anisotropy(c.add<double>("anisotropy")),
      sum_of_eigenvalues(c.add<double>("sum_of_eigenvalues")), change_of_curvature(c.add<double>("change_of_curvature")),
      verticality(c.add<double>("verticality")), normal_z(c.add<double>("normal_z")), radius(c.add<double>("radius"))
  {}

  void write(std::size_t e, const SN::Point_features& f) const
  {
    omnivariance[e] = f.omnivariance;
    anisotropy[e] = f.anisotropy;
    sum_of_eigenvalues[e] = f.sum_of_eigenvalues;
    change_of_curvature[e] = f.change_of_curvature;
    verticality[e] = f.verticality;
    normal_z[e] = f.normal_z;
    radius[e] = f.radius;
  }
};

// Calls `run` with the named parameters `np`, followed by the caller's rows when there are any.
template <typename NamedParameters, typename Run>
void with_rows(const std::optional<Neighbor_rows>& rows, const NamedParameters& np, const Run& run)
{
  if(rows)
    run(SNP::neighbor_indices(std::cref(rows->indices), SNP::neighbor_offsets(std::cref(rows->offsets), np)));
  else
    run(np);
}

py::dict features(const py::object& points_object, const py::object& normals_object, double a, double b,
                  const py::object& k_object, const std::string& barycenter, bool line_angles, double angle_tolerance,
                  const py::object& neighbors, const std::optional<int>& threads)
{
  const Rows_3 points(points_object, "points"), normals(normals_object, "normals");
  if(normals.size() != points.size())
    throw std::invalid_argument("points and normals differ in length: " + std::to_string(points.size()) + " and " +
                                std::to_string(normals.size()));
  const bool several = !py::isinstance<py::int_>(k_object);
  const std::vector<unsigned int> sizes =
    several ? k_object.cast<std::vector<unsigned int>>() : std::vector<unsigned int>{k_object.cast<unsigned int>()};
  if(sizes.empty())
    throw std::invalid_argument("no neighborhood size given");
  const unsigned int largest = *std::max_element(sizes.begin(), sizes.end());
  const SN::Cosine_sigmoid sigmoid(a, b, angle_tolerance);
  const auto np = SNP::barycenter(
    SN::barycenter_from_name(barycenter),
    SNP::line_angles(line_angles, SNP::number_of_threads(threads_of(threads), CGAL::parameters::point_map(Point_rows_map{&points})
                                                                                .normal_map(Vector_rows_map{&normals}))));
  const std::optional<Neighbor_rows> rows = neighbor_rows(neighbors, points, largest);
  const std::size_t n = points.size(), m = sizes.size();
  Columns columns(several ? std::vector<py::ssize_t>{py::ssize_t(n), py::ssize_t(m)} : std::vector<py::ssize_t>{py::ssize_t(n)});
  const Dimensionality_columns dimensionality(columns);
  const Point_feature_columns extra(columns);
  std::uint32_t* k_column = columns.add<std::uint32_t>("k");
  double* a_column = columns.add<double>("a");
  double* b_column = columns.add<double>("b");
  {
    py::gil_scoped_release release;
    std::size_t i = 0;
    auto sink = boost::make_function_output_iterator([&](const std::vector<SN::Point_features>& per_size) {
      for(std::size_t s = 0; s < m; ++s)
      {
        const SN::Point_features& f = per_size[s];
        const std::size_t e = i * m + s;
        dimensionality.write(e, f.dimensionality, f.dimensionality.error);
        extra.write(e, f);
        k_column[e] = f.k;
        a_column[e] = f.a;
        b_column[e] = f.b;
      }
      ++i;
    });
    with_rows(rows, np, [&](const auto& p) { SN::compute_point_features<Tag>(point_range(n), sigmoid, sizes, sink, p); });
  }
  return columns.dict();
}

py::dict optimal(const py::object& points_object, const py::object& normals_object, unsigned int k_min,
                 unsigned int k_max, const std::optional<std::vector<double>>& a_grid,
                 const std::optional<std::vector<double>>& b_grid, const std::string& barycenter,
                 const std::string& criterion, bool line_angles, double angle_tolerance, bool all_features,
                 const py::object& neighbors, const std::optional<int>& threads)
{
  const Rows_3 points(points_object, "points"), normals(normals_object, "normals");
  if(normals.size() != points.size())
    throw std::invalid_argument("points and normals differ in length: " + std::to_string(points.size()) + " and " +
                                std::to_string(normals.size()));
  const SN::Neighborhood_criterion minimised = SN::criterion_from_name(criterion);
  const auto maps = SNP::number_of_threads(
    threads_of(threads),
    CGAL::parameters::point_map(Point_rows_map{&points}).normal_map(Vector_rows_map{&normals}));
  const auto weights = SNP::line_angles(line_angles, SNP::angle_tolerance(angle_tolerance, maps));
  const auto grid = SNP::a_grid(a_grid ? *a_grid : SN::defaults::angle_grid(),
                                SNP::b_grid(b_grid ? *b_grid : SN::defaults::angle_grid(), weights));
  const auto np = SNP::k_min(
    k_min, SNP::k_max(k_max, SNP::barycenter(SN::barycenter_from_name(barycenter), SNP::criterion(minimised, grid))));
  const std::optional<Neighbor_rows> rows = neighbor_rows(neighbors, points, k_max);
  const std::size_t n = points.size();
  Columns columns({py::ssize_t(n)});
  double* a_column = columns.add<double>("a");
  double* b_column = columns.add<double>("b");
  std::uint32_t* k_column = columns.add<std::uint32_t>("k");
  const Dimensionality_columns dimensionality(columns);
  double* error_equal = columns.add<double>("error_equal");
  std::uint32_t* k_equal = columns.add<std::uint32_t>("k_equal");
  double* dimensionality_error = columns.add<double>("dimensionality_error");
  std::optional<Point_feature_columns> extra;
  if(all_features)
    extra.emplace(columns);
  {
    py::gil_scoped_release release;
    std::size_t i = 0, j = 0;
    auto records = boost::make_function_output_iterator([&](const SN::Optimal_sigmoid_neighborhood& r) {
      a_column[i] = r.a;
      b_column[i] = r.b;
      k_column[i] = r.k;
      dimensionality.write(i, r.features, r.error());
      error_equal[i] = r.error_equal;
      k_equal[i] = r.k_equal;
      dimensionality_error[i++] = r.features.error;
    });
    auto point_features = boost::make_function_output_iterator([&](const SN::Point_features& f) { extra->write(j++, f); });
    with_rows(rows, np, [&](const auto& p) {
      if(all_features)
        SN::compute_optimal_point_features<Tag>(point_range(n), records, point_features, p);
      else
        SN::compute_optimal_sigmoid_neighborhoods<Tag>(point_range(n), records, p);
    });
  }
  return columns.dict();
}

} // namespace

void bind_features(py::module_& m)
{
  using namespace pybind11::literals;
  m.def("features", &features, "points"_a, "normals"_a, py::kw_only(), "a"_a = CGAL_PI, "b"_a = CGAL_PI,
        "k"_a = py::int_(SN::defaults::K_MAX), "barycenter"_a = "weighted", "line_angles"_a = false,
        "angle_tolerance"_a = SN::defaults::ANGLE_TOLERANCE, "neighbors"_a = py::none(), "threads"_a = py::none(),
        R"doc(features(points, normals, *, a=pi, b=pi, k=20, barycenter="weighted", line_angles=False, angle_tolerance=1e-6, neighbors=None, threads=None) -> dict

The features of every point's weighted neighborhood for one sigmoid (a, b) at one or several sizes k
(compute_point_features()): N_i(k) is i and its k nearest other points (ties by index), the weights
w_ij = sig_{a,b}(angle(n_i, n_j)), 1 up to angle a, 0 from angle b on, a cosine between
(a = b = pi: equal weights). One neighbor query of the largest size per point serves every size.

Parameters
----------
points, normals : (n, 3) arrays
    normals oriented, non-zero (not necessarily unit length)
a, b : float
    radians, 0 <= a <= b <= pi
k : int or sequence of int
    the size, or several sizes (scales): then every array gains an axis of len(k)
barycenter : {"weighted", "unweighted"}
    the covariance's centre: sum w_ij p_j / sum w_ij (default), or the plain mean (the paper's formula)
line_angles : bool
    weights on the angle between normal lines, min(t, pi - t): for normals of arbitrary sign
angle_tolerance : float
    angles up to it count as 0
neighbors : (indices, offsets), optional
    caller rows (knn()) of at least max(k) neighbors, each ordered by distance; checked
threads : int, optional

Returns
-------
dict of arrays of shape (n,) or (n, len(k)): "eigenvalues" (..., 3) lambda1 >= lambda2 >= lambda3;
"linearity", "planarity", "scattering", "error" (E_dim), "eigenentropy", "label" (int8: index into
LABEL_NAMES), "omnivariance", "anisotropy", "sum_of_eigenvalues", "change_of_curvature",
"verticality", "normal_z", "radius", "k" (uint32), "a", "b". A degenerate neighborhood has every
eigenvalue feature 0, both entropies +inf and the label 3 (degenerate); "normal_z", "radius", "k", "a"
and "b", which do not come from the eigenvalues, keep their values.

Raises
------
ValueError
    fewer than max(k) + 1 points, k < 1, a > b or outside [0, pi], non-finite coordinates, zero or
    non-finite normals (the message names the point), bad neighbor rows (it names the row)
)doc");

  m.def("optimal", &optimal, "points"_a, "normals"_a, py::kw_only(), "k_min"_a = SN::defaults::K_MIN,
        "k_max"_a = SN::defaults::K_MAX, "a_grid"_a = py::none(), "b_grid"_a = py::none(), "barycenter"_a = "weighted",
        "criterion"_a = "dimensionality", "line_angles"_a = false, "angle_tolerance"_a = SN::defaults::ANGLE_TOLERANCE,
        "all_features"_a = true, "neighbors"_a = py::none(), "threads"_a = py::none(),
        R"doc(optimal(points, normals, *, k_min=6, k_max=20, a_grid=None, b_grid=None, barycenter="weighted", criterion="dimensionality", line_angles=False, angle_tolerance=1e-6, all_features=True, neighbors=None, threads=None) -> dict

For every point, the sigmoid parameters and neighborhood size (a*, b*, k*) of least classification
error E_dim over a grid (the paper's Equation 9; compute_optimal_sigmoid_neighborhoods()), and the
best error with equal weights (a = b = pi, best k) in the same pass. Bit for bit the records of the
C++ function and of `sigmoid-neighborhoods optimal` on the same points and normals.

Triples are visited a ascending, b ascending, k ascending (pairs with a <= b only), and one replaces
the best only when smaller by more than 1e-12. A point whose every triple is degenerate is a failure:
k = 0, a and b NaN, error +inf. One kd-tree, queried once per point for k_max neighbors.

Parameters
----------
points, normals : (n, 3) arrays
    normals oriented, non-zero
k_min, k_max : int
    the sizes K = {k_min, ..., k_max}; 1 <= k_min <= k_max, at least k_max + 1 points
a_grid, b_grid : sequence of float, optional
    radians in [0, pi], sorted and deduplicated (default: {0, pi/6, ..., pi})
barycenter : {"weighted", "unweighted"}
criterion : {"dimensionality", "eigenentropy"}
    what the search minimises: E_dim (the paper) or the eigenentropy (Weinmann et al. 2015, pgeof)
line_angles : bool
    weights on the angle between normal lines, for normals of arbitrary sign
angle_tolerance : float
all_features : bool
    also the Point_features of the optimum (compute_optimal_point_features(), in the same pass,
    about a tenth more time): omnivariance ... radius below
neighbors : (indices, offsets), optional
    caller rows (knn()) of at least k_max neighbors, each ordered by distance; checked
threads : int, optional

Returns
-------
dict of arrays of shape (n,): "a", "b" (radians), "k" (uint32), "error" (the criterion at the optimum),
"linearity", "planarity", "scattering", "label" (int8, index into LABEL_NAMES), "error_equal",
"k_equal" (uint32, 0 when all fail), "eigenvalues" (n, 3), "eigenentropy", "dimensionality_error"
(E_dim at the optimum); with all_features: "omnivariance", "anisotropy", "sum_of_eigenvalues",
"change_of_curvature", "verticality", "normal_z", "radius".

Raises
------
ValueError
    bad grid or sizes, fewer than k_max + 1 points, non-finite coordinates, zero or non-finite normals
    (the message names the point), bad neighbor rows (it names the row)
)doc");
}

} // namespace sigmoid_neighborhoods_python
