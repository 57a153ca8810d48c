// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_H

#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/compute_sigmoid_features.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>
#include <CGAL/Sigmoid_neighborhoods/Point_set_3_properties.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Iterator_range.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename Point, typename Vector>
void require_normal_map(const CGAL::Point_set_3<Point, Vector>& points, const char* function)
{
  if(!points.has_normal_map())
    throw std::invalid_argument(std::string(function) +
                                "(): the point set has no normal map (estimate_normals() adds and fills one)");
}

// The indices of the point set as a plain range: what the range overloads take (not these ones).
template <typename Point, typename Vector>
auto point_set_indices(const CGAL::Point_set_3<Point, Vector>& points)
{
  return CGAL::make_range(points.begin(), points.end());
}

// The point set's own maps on top of the caller's parameters.
template <typename Point, typename Vector, typename NamedParameters>
auto with_point_set_maps(const CGAL::Point_set_3<Point, Vector>& points, const NamedParameters& np)
{
  return np.point_map(points.point_map()).normal_map(points.normal_map());
}

// The property `name` (prefixed): the existing one, else added with `value`; one of that name
// and another type is an error (it would be left as it is).
template <typename T, typename Point, typename Vector>
typename CGAL::Point_set_3<Point, Vector>::template Property_map<T>
point_set_property(CGAL::Point_set_3<Point, Vector>& points, const std::string& name, const T& value)
{
  const std::string full_name = POINT_SET_PROPERTY_PREFIX + name;
  // CGAL keeps properties of one name and several types side by side: a PLY would get both
  const std::vector<std::string> names = points.properties();
  if(std::find(names.begin(), names.end(), full_name) != names.end() &&
     !points.template property_map<T>(full_name).second)
    throw std::invalid_argument("the point set has a property " + full_name + " of another type");
  return points.template add_property_map<T>(full_name, value).first;
}

template <typename Point, typename Vector>
void write_features(CGAL::Point_set_3<Point, Vector>& points, const std::vector<Dimensionality_features>& features)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto linearity = point_set_property<double>(points, "linearity", nan);
  auto planarity = point_set_property<double>(points, "planarity", nan);
  auto scattering = point_set_property<double>(points, "scattering", nan);
  auto error = point_set_property<double>(points, "error", nan);
  auto label = point_set_property<std::uint8_t>(points, "label", std::uint8_t(Dimensionality::DEGENERATE));
  std::size_t i = 0;
  for(const auto index : points)
  {
    const Dimensionality_features& f = features[i++];
    // a degenerate neighborhood has no features: NaN, as in the tool's PLY
    linearity[index] = f.is_degenerate() ? nan : f.linearity;
    planarity[index] = f.is_degenerate() ? nan : f.planarity;
    scattering[index] = f.is_degenerate() ? nan : f.scattering;
    error[index] = f.error;
    label[index] = std::uint8_t(f.label);
  }
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `compute_optimal_sigmoid_neighborhoods()` on a `CGAL::Point_set_3` with normals, the
  records written to its properties: `scalar_a`, `scalar_b`, `scalar_error`, `scalar_linearity`,
  `scalar_planarity`, `scalar_scattering`, `scalar_error_equal` (`double`), `scalar_k`,
  `scalar_k_equal` (`int`) and `scalar_label` (`std::uint8_t`: 0 linear, 1 planar, 2 scattered,
  3 degenerate), the columns of the tool's CSV. A failure has NaN `a`, `b` and features, `k = 0` and
  an infinite error. Existing properties of these names are overwritten.

  \param points the point set; its point and normal maps are used
  \param np the named parameters of `compute_optimal_sigmoid_neighborhoods()` but the maps
  \return the number of failures (points whose every triple is degenerate)
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`; the preconditions of the range overload
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t compute_optimal_sigmoid_neighborhoods(CGAL::Point_set_3<Point, Vector>& points,
                                                  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "compute_optimal_sigmoid_neighborhoods");
  std::vector<Optimal_sigmoid_neighborhood> records;
  records.reserve(points.size());
  compute_optimal_sigmoid_neighborhoods<ConcurrencyTag>(internal::point_set_indices(points), std::back_inserter(records),
                                                        internal::with_point_set_maps(points, np));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto a = internal::point_set_property<double>(points, "a", nan);
  auto b = internal::point_set_property<double>(points, "b", nan);
  auto k = internal::point_set_property<int>(points, "k", 0);
  auto error_equal = internal::point_set_property<double>(points, "error_equal", nan);
  auto k_equal = internal::point_set_property<int>(points, "k_equal", 0);
  std::vector<Dimensionality_features> features;
  features.reserve(records.size());
  std::size_t i = 0, failures = 0;
  for(const auto index : points)
  {
    const Optimal_sigmoid_neighborhood& r = records[i++];
    failures += r.is_failure();
    a[index] = r.a;
    b[index] = r.b;
    k[index] = int(r.k);
    error_equal[index] = r.error_equal;
    k_equal[index] = int(r.k_equal);
    features.push_back(r.features);
  }
  internal::write_features(points, features);
  return failures;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `compute_sigmoid_features()` on a `CGAL::Point_set_3` with normals, the features written
  to its properties `scalar_linearity`, `scalar_planarity`, `scalar_scattering`, `scalar_error`
  (`double`; NaN for a degenerate neighborhood but the error, infinite) and `scalar_label`
  (`std::uint8_t`): the names of the optimal search's, whose values they replace.

  \param points the point set; its point and normal maps are used
  \param sigmoid the weights
  \param k the neighborhood size
  \param np the named parameters of `compute_sigmoid_features()` but the maps
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`; the preconditions of the range overload
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
void compute_sigmoid_features(CGAL::Point_set_3<Point, Vector>& points, const Cosine_sigmoid& sigmoid, unsigned int k,
                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "compute_sigmoid_features");
  std::vector<Dimensionality_features> features;
  features.reserve(points.size());
  compute_sigmoid_features<ConcurrencyTag>(internal::point_set_indices(points), sigmoid, k, std::back_inserter(features),
                                           internal::with_point_set_maps(points, np));
  internal::write_features(points, features);
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `filter_normals()` on a `CGAL::Point_set_3` with normals: its normal map is filtered in place.
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
Normal_filter_summary filter_normals(CGAL::Point_set_3<Point, Vector>& points,
                                     const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "filter_normals");
  auto indices = internal::point_set_indices(points);
  return filter_normals<ConcurrencyTag>(indices, internal::with_point_set_maps(points, np));
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `denoise_point_set()` on a `CGAL::Point_set_3` with normals: its points move in place and its
  normal map receives the filtered normals.
  \pre `points.has_normal_map()`, otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
Point_set_denoising_summary denoise_point_set(CGAL::Point_set_3<Point, Vector>& points,
                                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  internal::require_normal_map(points, "denoise_point_set");
  auto indices = internal::point_set_indices(points);
  return denoise_point_set<ConcurrencyTag>(indices, internal::with_point_set_maps(points, np));
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief `estimate_normals()` on a `CGAL::Point_set_3`, then orientation: its normal map (added when
  it has none) receives normals estimated on the `k` nearest points and oriented by
  `orient_normals_by_spanning_forest()`, both on one k-nearest-neighbor structure.

  \param points the point set
  \param k the neighbors of the estimation and of the spanning forest
  \param np the named parameters of `estimate_normals()` (`normal_estimation_method`,
  `degree_fitting`, `number_of_threads`) but the maps
  \return the number of trees of the spanning forest (connected components)
*/
template <typename ConcurrencyTag, typename Point, typename Vector, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t estimate_and_orient_normals(CGAL::Point_set_3<Point, Vector>& points, unsigned int k,
                                        const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  if(!points.has_normal_map())
    points.add_normal_map();
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  const auto maps = internal::with_point_set_maps(points, np);
  auto range = internal::point_set_indices(points);
  compute_k_nearest_neighbors<ConcurrencyTag>(range, k, indices, offsets, maps);
  const auto rows = parameters::neighbor_indices(std::cref(indices), parameters::neighbor_offsets(std::cref(offsets), maps));
  estimate_normals<ConcurrencyTag>(range, k, rows);
  return orient_normals_by_spanning_forest<ConcurrencyTag>(range, k, rows);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_H
