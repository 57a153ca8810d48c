// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_ESTIMATE_NORMALS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_ESTIMATE_NORMALS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Normal_estimation_method.h>
#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Jet fitting divides by the square of the neighborhood's extent: below this it underflows to 0.
constexpr double SMALLEST_JET_EXTENT = 1e-150;
// A neighborhood whose middle eigenvalue is at most this share of the trace is a line (or a point):
// its normal is undefined. The degenerate test of the covariance (SPEC §4) uses the same share.
constexpr double FLAT_NEIGHBORHOOD_THRESHOLD = DEGENERATE_TRACE_THRESHOLD;

struct Normal_estimation_scratch
{
  std::vector<Neighbor> neighbors;
  std::vector<Eigen::Vector3d> offsets;
  std::vector<double> weights;
  std::vector<Double_point> points;
};

// PCA on the point and its neighbors: offsets from the point (as the features take them), scaled
// by a power of 2 (exactly) to a largest length in [1, 2) so that no square underflows or
// overflows, the two-pass covariance about their centroid, Eigen's iterative solver (SPEC §4).
inline Eigen::Vector3d pca_normal(const std::vector<Double_point>& points, std::uint32_t i,
                                  Normal_estimation_scratch& s)
{
  const Double_point& p = points[i];
  s.offsets.assign(1, Eigen::Vector3d::Zero());
  double largest = 0.;
  for(const Neighbor& n : s.neighbors)
  {
    const Double_point& q = points[n.index];
    s.offsets.emplace_back(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
    largest = (std::max)(largest, s.offsets.back().lpNorm<Eigen::Infinity>());
  }
  if(!(largest > 0.))
    throw std::invalid_argument("point " + std::to_string(i) + " and its " + std::to_string(s.neighbors.size()) +
                                " nearest points coincide: no normal (pca)");
  const double scale = std::ldexp(1., -std::ilogb(largest));
  for(Eigen::Vector3d& offset : s.offsets)
    offset *= scale;
  s.weights.assign(s.offsets.size(), 1.);
  Weighted_covariance covariance;
  accumulate_covariance(s.offsets.data(), s.weights.data(), s.offsets.size(), Barycenter::UNWEIGHTED, covariance);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance.matrix, Eigen::ComputeEigenvectors);
  const double trace = covariance.matrix.trace();
  if(!(solver.eigenvalues()[1] > FLAT_NEIGHBORHOOD_THRESHOLD * trace))
    throw std::invalid_argument("point " + std::to_string(i) + " and its " + std::to_string(s.neighbors.size()) +
                                " nearest points lie on a line: no normal (pca)");
  return solver.eigenvectors().col(0);
}

// Jet fitting on the point and its neighbors, nearest first, as CGAL's jet_estimate_normals() does.
inline Eigen::Vector3d jet_normal(const std::vector<Double_point>& points, std::uint32_t i, unsigned int degree,
                                  Normal_estimation_scratch& s)
{
  typedef CGAL::Monge_via_jet_fitting<Double_kernel> Monge_fitting;
  s.points.assign(1, points[i]);
  for(const Neighbor& n : s.neighbors)
    s.points.push_back(points[n.index]);
  if(!(s.neighbors.back().squared_distance >= SMALLEST_JET_EXTENT * SMALLEST_JET_EXTENT))
    throw std::invalid_argument("point " + std::to_string(i) + " and its " + std::to_string(s.neighbors.size()) +
                                " nearest points lie within 1e-150 of each other: no normal (jet)");
  Monge_fitting fitting;
  const Monge_fitting::Monge_form form = fitting(s.points.begin(), s.points.end(), degree, 1);
  const Double_kernel::Vector_3 n = form.normal_direction();
  const Eigen::Vector3d normal(n.x(), n.y(), n.z());
  if(!normal.allFinite() || !(normal.squaredNorm() > 0.))
    throw std::invalid_argument("point " + std::to_string(i) + ": the jet fitted to its " +
                                std::to_string(s.neighbors.size()) + " nearest points has no normal (jet)");
  return normal;
}

// Writes one unit normal per item of `points` through the normal map of `np`.
template <typename PointRange, typename NamedParameters>
void write_normals(PointRange& points, const std::vector<Eigen::Vector3d>& normals, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename boost::property_traits<typename NP_helper::Normal_map>::value_type Vector;
  const auto normal_map = NP_helper::get_normal_map(points, np);
  std::size_t i = 0;
  for(auto& item : points)
  {
    const Eigen::Vector3d& n = normals[i++];
    put(normal_map, item, Vector(n[0], n[1], n[2]));
  }
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief estimates an unoriented unit normal at every point from the point and its `k` nearest other
  points (ties by index, SPEC §2; CGAL's convention for `k`), and writes it to `normal_map`.

  `Normal_estimation_method::PCA` (the default): the eigenvector of the smallest eigenvalue of the
  covariance of the `k + 1` points, from Eigen's iterative solver (SPEC §4), as
  `CGAL::pca_estimate_normals()`; `Normal_estimation_method::JET`: the normal of the jet of degree
  `degree_fitting` fitted by `CGAL::Monge_via_jet_fitting`, as `CGAL::jet_estimate_normals()`. PCA is
  the default for its speed (4 to 5 times jet fitting's) and its accuracy on noisy data
  (`benchmark/README.md`, "Normal estimation"); jet fitting is more accurate on curved surfaces
  without noise. On the same
  neighbors, both give CGAL's normals up to rounding and sign. The neighbors come from the
  package's kd-tree, or from `neighbor_indices` and `neighbor_offsets` (the first `k` entries
  of each row). Every point is computed on its own, in the package's parallel loop: the normals
  are the same, bit for bit, for any number of threads. Their sign is not decided (orientation is
  a separate step).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `Range` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters

  \param points the points
  \param k the number of neighbors of each point: each fit takes `k + 1` points
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose value type is a `Point_3` of a CGAL kernel}
      \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map receiving the unit normals}
      \cgalParamType{a model of `WritablePropertyMap` whose value type is a `Vector_3` of a CGAL kernel}
      \cgalParamDefault{none: required (a static assertion fails without it)}
    \cgalParamNEnd
    \cgalParamNBegin{normal_estimation_method}
      \cgalParamDescription{PCA or jet fitting}
      \cgalParamType{`Normal_estimation_method`}
      \cgalParamDefault{`Normal_estimation_method::PCA`}
    \cgalParamNEnd
    \cgalParamNBegin{degree_fitting}
      \cgalParamDescription{the degree of the jet (CGAL's named parameter)}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`DEFAULT_JET_DEGREE` (2)}
      \cgalParamExtra{jet fitting needs `k + 1 >= (d + 1)(d + 2) / 2` points}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_threads}
      \cgalParamDescription{the threads of a call with `CGAL::Parallel_tag`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{0: OpenMP's or TBB's default}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `k >= 2` (PCA) or `k + 1 >= (d + 1)(d + 2) / 2` (jet); at least `k + 1` points; finite coordinates;
  no point whose neighbors coincide with it or lie on a line (PCA) or within `1e-150` of it (jet): otherwise
  `std::invalid_argument`, never a zero normal
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
void estimate_normals(PointRange& points, unsigned int k, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "estimate_normals() needs a normal map");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Normal_estimation_method method =
    choose_parameter(get_parameter(np, internal_np::normal_estimation_method), DEFAULT_NORMAL_ESTIMATION_METHOD);
  const unsigned int degree = choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), DEFAULT_JET_DEGREE);
  // points per fit: a plane needs 3, a jet of degree d its (d + 1)(d + 2) / 2 coefficients
  const unsigned int fewest = method == Normal_estimation_method::PCA ? 3u : (degree + 1) * (degree + 2) / 2;
  if(std::size_t(k) + 1 < fewest)
    throw std::invalid_argument("estimate_normals(): " +
                                std::string(method == Normal_estimation_method::PCA ? "pca" : "jet fitting of degree " +
                                                                                                  std::to_string(degree)) +
                                " needs at least " + std::to_string(fewest - 1) + " neighbors per point, got k = " +
                                std::to_string(k));

  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np));
  if(copy.size() < std::size_t(k) + 1)
    throw std::invalid_argument("estimate_normals(): needs at least k + 1 = " + std::to_string(k + 1) +
                                " points, got " + std::to_string(copy.size()));
  const internal::Neighbor_query query = internal::neighbor_query(copy, np);
  internal::check_neighborhood_size(query, k);

  std::vector<Eigen::Vector3d> normals(copy.size());
  internal::for_each_index<ConcurrencyTag>(
    copy.size(), internal::number_of_threads(np), [] { return internal::Normal_estimation_scratch(); },
    [&](std::size_t i, internal::Normal_estimation_scratch& s) {
      query.query(static_cast<std::uint32_t>(i), k, s.neighbors);
      normals[i] = method == Normal_estimation_method::PCA
                     ? internal::pca_normal(copy, static_cast<std::uint32_t>(i), s)
                     : internal::jet_normal(copy, static_cast<std::uint32_t>(i), degree, s);
    });

  internal::write_normals(points, normals, np);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_ESTIMATE_NORMALS_H
