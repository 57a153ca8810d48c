// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_EVALUATE_SIGMOID_NEIGHBORHOODS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_EVALUATE_SIGMOID_NEIGHBORHOODS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/Point_evaluation.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Optimal_search.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {

inline bool is_degenerate_triple(const Local_neighborhood& local, double a, double b, unsigned int k,
                                 const Search_settings& s, std::vector<double>& w)
{
  w.resize(local.size());
  local.weights(Cosine_sigmoid(a, b, s.angle_tolerance), w.data());
  return local.covariance(w.data(), k, s.barycenter).is_degenerate();
}

// `sink(i, evaluation)` receives the evaluations in index order.
template <typename ConcurrencyTag, typename Sink>
void evaluate_all(const Oriented_points& input, const Neighbor_query& query, const Search_settings& settings,
                  double cut_off_angle, unsigned int fixed_k, const Sink& sink)
{
  check_enough_points(input.size(), settings.k_max);
  check_neighborhood_size(query, settings.k_max);
  if(!(fixed_k >= settings.k_min && fixed_k <= settings.k_max))
    throw std::invalid_argument("fixed_k must lie in [k_min, k_max]");
  const Cosine_sigmoid cut_off(cut_off_angle, cut_off_angle, settings.angle_tolerance);
  const Optimal_search search(settings);
  struct Scratch
  {
    Optimal_search::Scratch search;
    std::vector<double> w;
  };
  for_each_neighborhood<ConcurrencyTag, Point_evaluation>(
    input, query, settings.k_max, settings.threads, [&search] { return Scratch{search.make_scratch(), {}}; },
    [&](std::size_t, const Local_neighborhood& local, Scratch& s) {
      Point_evaluation e;
      e.optimal = search(local, s.search);
      // the cut-off at its best k
      s.w.resize(local.size());
      local.weights(cut_off, s.w.data());
      const Local_neighborhood::Best_size best = local.best_size(s.w.data(), settings.k_min, settings.k_max,
                                                                 settings.barycenter);
      e.error_cut_off = best.error;
      e.k_cut_off = best.k;
      e.cut_off_label =
        best.k == 0 ? Dimensionality::DEGENERATE : local.features(s.w.data(), best.k, settings.barycenter).label;
      s.w.assign(local.size(), 1.);
      if(e.optimal.k_equal != 0)
        e.equal_label = local.features(s.w.data(), e.optimal.k_equal, settings.barycenter).label;
      const Dimensionality_features fixed = local.features(s.w.data(), fixed_k, settings.barycenter);
      e.error_fixed_k = fixed.error;
      e.fixed_k_label = fixed.label;
      if(e.optimal.is_failure())
        return e;
      // Table 3: the next smaller grid value of a (same b*, k*), and of b that stays >= a* (same a*, k*).
      const auto& A = settings.a_grid;
      const auto& B = settings.b_grid;
      const auto a_it = std::lower_bound(A.begin(), A.end(), e.optimal.a);
      if(a_it != A.begin())
        e.a_lowering = is_degenerate_triple(local, *(a_it - 1), e.optimal.b, e.optimal.k, settings, s.w)
                         ? Point_evaluation::Lowering::FAILS : Point_evaluation::Lowering::STILL_VALID;
      const auto b_it = std::lower_bound(B.begin(), B.end(), e.optimal.b);
      if(e.optimal.b != e.optimal.a && b_it != B.begin() && *(b_it - 1) >= e.optimal.a)
        e.b_lowering = is_degenerate_triple(local, e.optimal.a, *(b_it - 1), e.optimal.k, settings, s.w)
                         ? Point_evaluation::Lowering::FAILS : Point_evaluation::Lowering::STILL_VALID;
      return e;
    },
    sink);
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsEvaluation
  \brief evaluates every point as the paper's Section 5 does: the optimal `(a*, b*, k*)`, equal
  weights and the sharp cut-off `a = b = cut_off_angle` each at their best `k`, equal weights at
  `fixed_k`, and the Table 3 tests of lowering `a*` and `b*` by one grid step.

  One k-NN query per point serves all of them. Results do not depend on the number of threads.
  The optimal triple and the equal-weights baseline are those of
  `compute_optimal_sigmoid_neighborhoods()`, with the same tie rule.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Sigmoid_neighborhoods::Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the maps
  \tparam OutputIterator an output iterator accepting `Point_evaluation`
  \tparam NamedParameters a sequence of named parameters

  \param points the input points, with oriented normals
  \param output receives one record per point, in the order of `points`
  \param np an optional sequence of named parameters among the ones listed below: CGAL's
    (`CGAL::parameters`) and the package's (`CGAL::Sigmoid_neighborhoods::parameters`, which come
    first in a chain, see \ref Sigmoid_neighborhoods_named_parameters)

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Point_3` of a CGAL kernel}
      \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
      \cgalParamExtra{coordinates are converted to `double`; they must be finite}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map associating oriented normals to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Vector_3` of a CGAL kernel}
      \cgalParamDefault{none: required (a static assertion fails without it), except for a
        `CGAL::Point_set_3`, whose normal map is the default}
      \cgalParamExtra{normals need not be unit length; a zero or non-finite normal is an error}
    \cgalParamNEnd
    \cgalParamNBegin{k_min}
      \cgalParamDescription{the smallest neighborhood size of the search, `K = {k_min, ..., k_max}`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::K_MIN` (6)}
      \cgalParamExtra{`1 <= k_min <= k_max`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{k_max}
      \cgalParamDescription{the largest neighborhood size of the search}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::K_MAX` (20)}
      \cgalParamExtra{at least `k_max + 1` points are needed}
    \cgalParamNEnd
    \cgalParamNBegin{a_grid}
      \cgalParamDescription{the values of `a` (radians) that the search visits}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{`defaults::angle_grid()`: `{0, pi/6, pi/3, pi/2, 2pi/3, 5pi/6, pi}`}
      \cgalParamExtra{values in `[0, pi]`, sorted and deduplicated; only pairs with `a <= b` are searched}
    \cgalParamNEnd
    \cgalParamNBegin{b_grid}
      \cgalParamDescription{the values of `b` (radians) that the search visits}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{`defaults::angle_grid()`}
      \cgalParamExtra{as `a_grid`; at least one pair `a <= b` must exist}
    \cgalParamNEnd
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
    \cgalParamNBegin{angle_tolerance}
      \cgalParamDescription{angles between normals up to it (radians) count as 0}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::ANGLE_TOLERANCE` (`1e-6`)}
      \cgalParamExtra{in `[0, pi)`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{cut_off_angle}
      \cgalParamDescription{the angle `a = b` (radians) of the sharp cut-off weights}
      \cgalParamType{`double`}
      \cgalParamDefault{`std::acos(0.9)`}
      \cgalParamExtra{in `[0, pi]`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{fixed_k}
      \cgalParamDescription{the neighborhood size of the fixed-`k` equal-weights baseline}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{the value of `k_max`}
      \cgalParamExtra{in `[k_min, k_max]`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre at least `k_max + 1` points; finite coordinates; non-zero finite normals
  (otherwise `std::invalid_argument`)
  \return the output iterator past the last `Point_evaluation`
  \sa `Evaluation_statistics`, which sums the records up
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
OutputIterator evaluate_sigmoid_neighborhoods(const PointRange& points, OutputIterator output,
                                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "evaluate_sigmoid_neighborhoods() needs a normal map");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np),
                                                    internal::line_angles(np));
  internal::Search_settings settings = internal::search_settings(np);
  settings.criterion = Neighborhood_criterion::DIMENSIONALITY; // the paper's statistics are of E_dim
  const double cut_off = choose_parameter(get_parameter(np, internal_np::cut_off_angle), std::acos(0.9));
  const unsigned int fixed_k = choose_parameter(get_parameter(np, internal_np::fixed_k), settings.k_max);
  const internal::Neighbor_query query = internal::neighbor_query<ConcurrencyTag>(input.points, np);
  internal::evaluate_all<ConcurrencyTag>(input, query, settings, cut_off, fixed_k,
                                         [&output](std::size_t, const Point_evaluation& e) { *output++ = e; });
  return output;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_EVALUATE_SIGMOID_NEIGHBORHOODS_H
