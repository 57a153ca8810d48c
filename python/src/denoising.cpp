// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// filter_normals and denoise (Yadav et al. 2018): new arrays out, the inputs left as they are.

#include "bindings.h"
#include "numpy_arrays.h"

#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>

#include <pybind11/stl.h>

#include <functional>
#include <stdexcept>

namespace sigmoid_neighborhoods_python {

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = CGAL::Sigmoid_neighborhoods::parameters;
typedef SN::Parallel_if_available_tag Tag;

namespace {

py::dict filter_summary(const SN::Normal_filter_summary& s)
{
  py::dict d;
  d["points"] = s.points;
  d["iterations"] = s.iterations;
  d["radius"] = s.radius;
  d["mean_neighbors"] = s.mean_neighbors;
  d["empty_cones"] = s.empty_cones;
  d["fallbacks"] = s.fallbacks;
  d["mean_selected_size"] = s.mean_selected_size;
  return d;
}

struct Filter_arguments
{
  unsigned int iterations;
  double cut_off, eigenvalue_threshold, damping;
  std::optional<double> radius;
  bool adaptive;
  unsigned int size_range;
  bool line_angles;
  unsigned int threads;
};

// The filter's named parameters on the output arrays, then `run` with them and the caller's rows.
template <typename Run>
void with_filter_parameters(const Filter_arguments& f, double* points, double* normals,
                            const std::optional<Neighbor_rows>& rows, const Run& run)
{
  const auto np = SNP::normal_cut_off(
    f.cut_off,
    SNP::eigenvalue_threshold(
      f.eigenvalue_threshold,
      SNP::damping_factor(
        f.damping,
        SNP::adaptive_neighborhood_size(
          f.adaptive,
          SNP::neighborhood_size_range(
            f.size_range,
            SNP::line_angles(f.line_angles,
                             SNP::number_of_threads(f.threads,
                                                    CGAL::parameters::point_map(Output_rows_map<Point_3>{points})
                                                      .normal_map(Output_rows_map<Vector_3>{normals})
                                                      .number_of_iterations(f.iterations)
                                                      .neighbor_radius(f.radius ? *f.radius : 0.))))))));
  if(f.radius && !(*f.radius > 0.))
    throw std::invalid_argument("the radius must be positive (or None: 5 times the mean spacing), got " +
                                std::to_string(*f.radius));
  if(rows)
    run(SNP::neighbor_indices(std::cref(rows->indices), SNP::neighbor_offsets(std::cref(rows->offsets), np)));
  else
    run(np);
}

void check_lengths(const Rows_3& points, const Rows_3& normals)
{
  if(normals.size() != points.size())
    throw std::invalid_argument("points and normals differ in length: " + std::to_string(points.size()) + " and " +
                                std::to_string(normals.size()));
}

py::tuple filter_normals(const py::object& points_object, const py::object& normals_object, unsigned int iterations,
                         double cut_off, double eigenvalue_threshold, double damping, const std::optional<double>& radius,
                         bool adaptive, unsigned int size_range, bool line_angles, const py::object& neighbors,
                         const std::optional<int>& threads)
{
  const Rows_3 points(points_object, "points"), normals(normals_object, "normals");
  check_lengths(points, normals);
  const std::optional<Neighbor_rows> rows = neighbor_rows(neighbors, points, 0, false);
  const Filter_arguments f{iterations, cut_off, eigenvalue_threshold, damping, radius, adaptive, size_range,
                           line_angles, threads_of(threads)};
  py::array_t<double> point_copy = copy_rows(points), result = copy_rows(normals);
  double *p = point_copy.mutable_data(), *q = result.mutable_data();
  SN::Normal_filter_summary summary;
  {
    py::gil_scoped_release release;
    with_filter_parameters(f, p, q, rows, [&](const auto& np) {
      auto range = point_range(points.size()); // written through the maps
      summary = SN::filter_normals<Tag>(range, np);
    });
  }
  return py::make_tuple(result, filter_summary(summary));
}

py::tuple denoise(const py::object& points_object, const py::object& normals_object, unsigned int iterations,
                  double cut_off, double eigenvalue_threshold, double damping, const std::optional<double>& radius,
                  bool adaptive, unsigned int size_range, double step_size, const std::optional<double>& maximum_deviation,
                  const std::optional<double>& planar_weight_radius, double rank_threshold, bool stop_at_noise_level,
                  bool line_angles, const py::object& neighbors, const std::optional<int>& threads)
{
  const Rows_3 points(points_object, "points"), normals(normals_object, "normals");
  check_lengths(points, normals);
  const std::optional<Neighbor_rows> rows = neighbor_rows(neighbors, points, 0, false);
  const Filter_arguments f{iterations, cut_off, eigenvalue_threshold, damping, radius, adaptive, size_range,
                           line_angles, threads_of(threads)};
  for(const auto& [value, name] : {std::make_pair(maximum_deviation, "maximum_deviation"),
                                   std::make_pair(planar_weight_radius, "planar_weight_radius")})
    if(value && !(*value > 0.))
      throw std::invalid_argument(std::string(name) + " must be positive (or None: the default), got " +
                                  std::to_string(*value));
  py::array_t<double> new_points = copy_rows(points), new_normals = copy_rows(normals);
  double *p = new_points.mutable_data(), *q = new_normals.mutable_data();
  SN::Point_set_denoising_summary summary;
  {
    py::gil_scoped_release release;
    with_filter_parameters(f, p, q, rows, [&](const auto& filter_np) {
      auto range = point_range(points.size()); // written through the maps
      summary = SN::denoise_point_set<Tag>(
        range,
        SNP::step_size(step_size,
                       SNP::maximum_deviation(maximum_deviation ? *maximum_deviation : 0.,
                                              SNP::planar_weight_radius(planar_weight_radius ? *planar_weight_radius : 0.,
                                                                        SNP::rank_threshold(rank_threshold,
                                                                                            SNP::stop_at_noise_level(stop_at_noise_level,
                                                                                                                     filter_np))))));
    });
  }
  py::dict d;
  d["points"] = summary.points;
  d["iterations"] = summary.iterations;
  d["scale"] = summary.scale;
  d["maximum_deviation"] = summary.maximum_deviation;
  d["planar"] = summary.planar;
  d["edges"] = summary.edges;
  d["corners"] = summary.corners;
  d["unclassified"] = summary.unclassified;
  d["rank_deficient"] = summary.rank_deficient;
  d["refused"] = summary.refused;
  d["noise_estimate"] = summary.noise_estimate;
  d["stopped_at_noise_level"] = summary.stopped_at_noise_level;
  d["mean_displacement"] = summary.mean_displacement;
  d["largest_displacement"] = summary.largest_displacement;
  d["normal_filter"] = filter_summary(summary.normal_filter);
  return py::make_tuple(new_points, new_normals, d);
}

} // namespace

void bind_denoising(py::module_& m)
{
  using namespace pybind11::literals;
  m.def("filter_normals", &filter_normals, "points"_a, "normals"_a, py::kw_only(),
        "iterations"_a = SN::defaults::FILTER_ITERATIONS, "cut_off"_a = SN::defaults::NORMAL_CUT_OFF,
        "eigenvalue_threshold"_a = SN::defaults::EIGENVALUE_THRESHOLD, "damping"_a = SN::defaults::DAMPING_FACTOR,
        "radius"_a = py::none(), "adaptive"_a = false, "size_range"_a = SN::defaults::NEIGHBORHOOD_SIZE_RANGE,
        "line_angles"_a = false, "neighbors"_a = py::none(), "threads"_a = py::none(),
        R"doc(filter_normals(points, normals, *, iterations=50, cut_off=0.9, eigenvalue_threshold=0.25, damping=3.0, radius=None, adaptive=False, size_range=10, line_angles=False, neighbors=None, threads=None) -> (normals, summary)

Filters the normals by the normal voting tensor of Yadav et al. (2018), stage 1 of their denoising
(filter_normals()). Each sweep computes every new normal from the old ones: the neighbors j of i with
n_i . n_j > cut_off vote with T = mean(n_j n_j^T); its eigenvalues below eigenvalue_threshold become 0,
the others 1; then n_i <- normalize(T~ n_i + damping n_i). A point whose cone holds no neighbor keeps its
normal. The default neighborhood of i is the ball of radius 5 m around it, m the mean distance to the
12 nearest neighbors. With adaptive=True (SPEC section 7) every sweep takes, per point, the k of least
E_dim among {k_i - size_range, ..., k_i + size_range}. The same for any number of threads.

Parameters
----------
points, normals : (n, 3) arrays (not modified)
iterations : int
cut_off, eigenvalue_threshold, damping : float
radius : float, optional
    of the ball neighborhoods (None: 5 m)
adaptive : bool
size_range : int
line_angles : bool
    the cut-off on |n_i . n_j|, for normals whose signs mean nothing
neighbors : (indices, offsets), optional
    caller neighborhoods instead of the balls, in any order (see knn()); checked
threads : int, optional

Returns
-------
normals : new (n, 3) float64 array of unit normals
summary : dict: points, iterations, radius, mean_neighbors, empty_cones, fallbacks, mean_selected_size
)doc");

  m.def("denoise", &denoise, "points"_a, "normals"_a, py::kw_only(), "iterations"_a = SN::defaults::FILTER_ITERATIONS,
        "cut_off"_a = SN::defaults::NORMAL_CUT_OFF, "eigenvalue_threshold"_a = SN::defaults::EIGENVALUE_THRESHOLD,
        "damping"_a = SN::defaults::DAMPING_FACTOR, "radius"_a = py::none(), "adaptive"_a = false,
        "size_range"_a = SN::defaults::NEIGHBORHOOD_SIZE_RANGE, "step_size"_a = SN::defaults::PLANAR_STEP_SIZE,
        "maximum_deviation"_a = py::none(), "planar_weight_radius"_a = py::none(),
        "rank_threshold"_a = SN::defaults::RANK_THRESHOLD, "stop_at_noise_level"_a = true, "line_angles"_a = false,
        "neighbors"_a = py::none(), "threads"_a = py::none(),
        R"doc(denoise(points, normals, *, iterations=50, cut_off=0.9, eigenvalue_threshold=0.25, damping=3.0, radius=None, adaptive=False, size_range=10, step_size=0.1, maximum_deviation=None, planar_weight_radius=None, rank_threshold=0.1, stop_at_noise_level=True, line_angles=False, neighbors=None, threads=None) -> (points, normals, summary)

Denoises a point set with oriented normals by the three stages of Yadav et al. (2018)
(denoise_point_set()): per iteration, one sweep of the normal filter (filter_normals()), the
classification of every point as planar, edge or corner, and the vertex update. The package's changes
against the authors' code (a rank test before the edge and corner solves, Jacobi order, metrics at the
planar rule's scale, a stopping rule at the estimated noise level) are described in the C++ reference.

Parameters
----------
points, normals : (n, 3) arrays (not modified)
iterations, cut_off, eigenvalue_threshold, damping, radius, adaptive, size_range, line_angles :
    as filter_normals()
step_size : float
    the step alpha of the planar rule
maximum_deviation : float, optional
    a move ending this far from the input position or farther is refused (None: 2 m)
planar_weight_radius : float, optional
    the radius r of the planar rule's weights (None: 2 m)
rank_threshold : float
    in [0, 1]; 0 is the authors' solve
stop_at_noise_level : bool
    stop once the RMS displacement reaches 1.1 times the noise level estimated from the input
neighbors : (indices, offsets), optional
threads : int, optional

Returns
-------
points, normals : new (n, 3) float64 arrays
summary : dict: points, iterations, scale, maximum_deviation, planar, edges, corners, unclassified,
    rank_deficient, refused, noise_estimate, stopped_at_noise_level, mean_displacement,
    largest_displacement, normal_filter (the filter's summary)
)doc");
}

} // namespace sigmoid_neighborhoods_python
