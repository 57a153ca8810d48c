// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_FILTER_NORMALS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_FILTER_NORMALS_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

// The named parameters of `filter_normals()` are declared in parameters.h with the others.

/// \cond SKIP_IN_MANUAL
namespace internal {
// The scale `m` of the default ball radius `5 m` is the mean distance to this many neighbors.
constexpr unsigned int FILTER_SCALE_NEIGHBORS = 12;
// The default ball radius is this factor times the scale `m`.
constexpr double FILTER_RADIUS_FACTOR = 5.;
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  what `filter_normals()` did. Counts over sweeps count one per point and sweep.
*/
struct Normal_filter_summary
{
  std::size_t points = 0;        ///< points filtered
  unsigned int iterations = 0;   ///< sweeps run
  double radius = 0.;            ///< ball radius of the default neighborhoods (0 when they were given)
  double mean_neighbors = 0.;    ///< mean size `k_i` of the default neighborhoods
  std::size_t empty_cones = 0;   ///< point-sweeps in which no neighbor voted: the normal was kept
  std::size_t fallbacks = 0;     ///< adaptive: point-sweeps with every size degenerate (default neighborhood, equal weights)
  double mean_selected_size = 0.; ///< adaptive: mean selected `k` over the other point-sweeps
  Mesh_points_summary mesh;      ///< for a mesh: how its vertices became points
};

/// \cond SKIP_IN_MANUAL
namespace internal {

struct Normal_filter_settings
{
  unsigned int iterations = defaults::FILTER_ITERATIONS;
  double cut_off = defaults::NORMAL_CUT_OFF;
  double eigenvalue_threshold = defaults::EIGENVALUE_THRESHOLD;
  double damping = defaults::DAMPING_FACTOR;
  double radius = 0.; // 0: FILTER_RADIUS_FACTOR times the mean distance to FILTER_SCALE_NEIGHBORS neighbors
  bool adaptive = false;
  unsigned int size_range = defaults::NEIGHBORHOOD_SIZE_RANGE;
  double angle_tolerance = defaults::ANGLE_TOLERANCE;
  Barycenter barycenter = Barycenter::WEIGHTED;
  unsigned int threads = 0; // of a call with Parallel_tag; 0: the default
  bool line_angles = false;  // the cut-off on |n_i . n_j|: normals whose signs mean nothing
};

template <typename NamedParameters>
Normal_filter_settings normal_filter_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Normal_filter_settings s;
  s.iterations =
    choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), defaults::FILTER_ITERATIONS);
  s.cut_off = choose_parameter(get_parameter(np, internal_np::normal_cut_off), defaults::NORMAL_CUT_OFF);
  s.eigenvalue_threshold =
    choose_parameter(get_parameter(np, internal_np::eigenvalue_threshold), defaults::EIGENVALUE_THRESHOLD);
  s.damping = choose_parameter(get_parameter(np, internal_np::damping_factor), defaults::DAMPING_FACTOR);
  s.radius = choose_parameter(get_parameter(np, CGAL::internal_np::neighbor_radius), 0.);
  s.adaptive = choose_parameter(get_parameter(np, internal_np::adaptive_neighborhood_size), false);
  s.size_range =
    choose_parameter(get_parameter(np, internal_np::neighborhood_size_range), defaults::NEIGHBORHOOD_SIZE_RANGE);
  s.angle_tolerance = choose_parameter(get_parameter(np, internal_np::angle_tolerance), defaults::ANGLE_TOLERANCE);
  s.barycenter = choose_parameter(get_parameter(np, internal_np::barycenter), Barycenter::WEIGHTED);
  s.threads = number_of_threads(np);
  s.line_angles = line_angles(np);
  if(!(s.cut_off >= -1. && s.cut_off <= 1.))
    throw std::invalid_argument("the normal cut-off must lie in [-1, 1], got " + std::to_string(s.cut_off));
  if(!std::isfinite(s.eigenvalue_threshold))
    throw std::invalid_argument("the eigenvalue threshold must be finite");
  if(!(s.damping >= 0. && std::isfinite(s.damping)))
    throw std::invalid_argument("the damping factor must be finite and >= 0, got " + std::to_string(s.damping));
  if(!(s.radius >= 0. && std::isfinite(s.radius)))
    throw std::invalid_argument("the neighbor radius must be finite and > 0, got " + std::to_string(s.radius));
  if(!(s.angle_tolerance >= 0. && s.angle_tolerance < CGAL_PI))
    throw std::invalid_argument("angle tolerance must be in [0, pi), got " + std::to_string(s.angle_tolerance));
  return s;
}

// One damped update n_i <- normalize(T~ n_i + d n_i) from the normal voting tensor of the neighbors
// that vote (n_i * n_j > cut-off, or all of them with `equal_weights`), yadav-normal-filtering.md §3;
// with `sigmoid`, every neighbor votes with the weight sigmoid(angle(n_i, n_j)) instead.
// Returns false, with `result = n_i`, when no neighbor votes (or the update vanishes, d = 0).
template <typename Iterator, typename IndexOf>
bool voting_tensor_update(const std::vector<Eigen::Vector3d>& normals, std::size_t i, Iterator begin, Iterator end,
                          IndexOf index_of, bool equal_weights, const Normal_filter_settings& s,
                          Eigen::Vector3d& result, const Cosine_sigmoid* sigmoid = nullptr)
{
  const Eigen::Vector3d& n = normals[i];
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  std::size_t count = 0;
  double total = 0.;
  for(Iterator it = begin; it != end; ++it)
  {
    const Eigen::Vector3d& m = normals[index_of(*it)];
    const double c = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
    const double cosine = s.line_angles ? std::abs(c) : c;
    if(sigmoid != nullptr && !equal_weights)
    {
      const double w = sigmoid->weight_from_cosine(cosine);
      if(w > 0.)
      {
        tensor.noalias() += w * (m * m.transpose());
        total += w;
        ++count;
      }
    }
    else if(equal_weights || cosine > s.cut_off)
    {
      tensor.noalias() += m * m.transpose();
      ++count;
    }
  }
  result = n;
  if(count == 0)
    return false;
  tensor /= sigmoid != nullptr && !equal_weights ? total : double(count);
  // Eigenvalues ascending: index 2 is the largest, always kept; the others when >= tau.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(tensor, Eigen::ComputeEigenvectors);
  const Eigen::Vector3d& lambda = solver.eigenvalues();
  const Eigen::Matrix3d& e = solver.eigenvectors();
  Eigen::Matrix3d binary = e.col(2) * e.col(2).transpose();
  if(lambda[1] >= s.eigenvalue_threshold)
    binary += e.col(1) * e.col(1).transpose();
  if(lambda[0] >= s.eigenvalue_threshold)
    binary += e.col(0) * e.col(0).transpose();
  const Eigen::Vector3d v = binary * n + s.damping * n;
  const double norm = v.norm();
  if(!(norm > 0.))
    return false;
  result = v / norm;
  return true;
}

// The normal voting filter's state between sweeps: its neighborhoods Omega_i (the balls of
// yadav-normal-filtering.md §2 built once, or the caller's), and with adaptive sizes the k-NN rows
// and the sizes chosen. filter_normals() runs its sweeps; the denoiser runs one per iteration and
// reads the neighborhoods of the last sweep for its other two stages.
template <typename ConcurrencyTag>
class Normal_voting_filter
{
public:
  // `query`, the point set's one neighbor structure, is read for the scale, the balls and the
  // adaptive k-NN: it may be null when `given` holds the neighborhoods of a plain filter.
  Normal_voting_filter(const Oriented_points& input, const Neighbor_query* query, const Neighbor_lists* given,
                       const Normal_filter_settings& s)
    : m_settings(s), m_given(given), m_n(input.size())
  {
    const std::size_t n = m_n;
    if(n == 0)
      throw std::invalid_argument("no points");
    if(n > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
      throw std::invalid_argument("too many points");
    CGAL_precondition(query != nullptr || (given != nullptr && !s.adaptive));
    m_summary.points = n;

    if(given == nullptr)
    {
      double radius = s.radius;
      if(radius == 0.)
      {
        if(n < FILTER_SCALE_NEIGHBORS + 1)
          throw std::invalid_argument("the default radius needs at least " + std::to_string(FILTER_SCALE_NEIGHBORS + 1) +
                                      " points, got " + std::to_string(n) + " (or give neighbor_radius or neighborhoods)");
        radius = FILTER_RADIUS_FACTOR * mean_neighbor_distance<ConcurrencyTag>(*query, FILTER_SCALE_NEIGHBORS, s.threads);
      }
      m_summary.radius = radius;
      m_ball = ball_neighborhoods<ConcurrencyTag>(*query, radius, s.threads);
    }
    m_summary.mean_neighbors = double(omega().indices.size()) / double(n);

    // Adaptive sizes (SPEC §7): one k-NN query of k_i + range neighbors per point, the sizes
    // {k_i - range, ..., k_i + range} (positive, at most n - 1) evaluated on it in every sweep.
    if(!s.adaptive)
      return;
    m_knn_offsets.assign(n + 1, 0);
    m_k_low.assign(n, 0);
    m_k_high.assign(n, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t k_i = omega().count(i);
      m_k_low[i] = k_i > s.size_range ? unsigned(k_i - s.size_range) : 1u;
      m_k_high[i] = unsigned((std::min)(k_i + s.size_range, n - 1));
      m_knn_offsets[i + 1] = m_knn_offsets[i] + m_k_high[i];
    }
    m_knn.resize(m_knn_offsets[n]);
    for_each_index<ConcurrencyTag>(
      n, s.threads, [] { return std::vector<Neighbor>(); },
      [&](std::size_t i, std::vector<Neighbor>& found) {
        query->query(static_cast<std::uint32_t>(i), m_k_high[i], found);
        for(std::size_t j = 0; j < found.size(); ++j)
          m_knn[m_knn_offsets[i] + j] = found[j].index;
      });
    m_cached_weights.assign(m_knn_offsets[n] + n, 0);
    m_cached.assign(n, 0);
    m_chosen.assign(n, 0);
    m_selected_sizes.assign(n, 0);
    m_fallbacks.assign(n, 0);
  }

  // Every point votes with its own weights sigmoid_i(angle) instead of the cut-off; a point without one
  // (empty optional) keeps the cut-off.
  void set_vote_weights(std::vector<std::optional<Cosine_sigmoid>> weights) { m_vote_weights = std::move(weights); }

  // The neighborhoods Omega_i: the balls or the caller's.
  const Neighbor_lists& omega() const { return m_given != nullptr ? *m_given : m_ball; }

  // The neighbors of i in the last sweep: Omega_i, or with adaptive sizes the k chosen nearest.
  std::pair<const std::uint32_t*, const std::uint32_t*> neighbors(std::size_t i) const
  {
    if(m_settings.adaptive && m_chosen[i] != 0)
      return {m_knn.data() + m_knn_offsets[i], m_knn.data() + m_knn_offsets[i] + m_chosen[i]};
    return {omega().begin(i), omega().end(i)};
  }

  // One sweep (Jacobi): every new normal from the old ones. `positions_moved`: the positions
  // changed since the last sweep, so that an adaptive size is chosen again even where the cut-off
  // weights did not change.
  void sweep(Oriented_points& input, bool positions_moved = false)
  {
    const Normal_filter_settings& s = m_settings;
    const std::size_t n = m_n;
    if(m_empty_cones.empty())
      m_empty_cones.assign(n, 0);
    const double cut_off_angle = std::acos(s.cut_off);
    const Cosine_sigmoid sigmoid(cut_off_angle, cut_off_angle, s.angle_tolerance);
    struct Scratch
    {
      std::vector<Neighbor> neighbors;
      Local_neighborhood local;
      std::vector<double> weights;
    };
    m_next.resize(n);
    const std::vector<Eigen::Vector3d>& normals = input.normals;
    const Neighbor_lists& omega = this->omega();
    auto own_index = [](std::uint32_t j) { return j; };
    for_each_index<ConcurrencyTag>(
      n, s.threads, [] { return Scratch(); },
      [&](std::size_t i, Scratch& scratch) {
        bool voted = false;
        const Cosine_sigmoid* vote_weights =
          m_vote_weights.empty() || !m_vote_weights[i] ? nullptr : &*m_vote_weights[i];
        if(!s.adaptive)
          voted = voting_tensor_update(normals, i, omega.begin(i), omega.end(i), own_index, false, s, m_next[i],
                                       vote_weights);
        else
        {
          // The size of least E_dim with the cut-off weights a = b = arccos(rho) of the current
          // normals. Unless positions moved, equal weights give the same choice as last time.
          const std::uint32_t* found = m_knn.data() + m_knn_offsets[i];
          const std::size_t count = m_knn_offsets[i + 1] - m_knn_offsets[i];
          unsigned char* weights = m_cached_weights.data() + m_knn_offsets[i] + i;
          bool same = m_cached[i] != 0 && !positions_moved;
          for(std::size_t j = 0; j < count; ++j)
          {
            const unsigned char w = sigmoid.weight_from_cosine(input.cosine(i, found[j])) > 0. ? 1 : 0;
            if(weights[j + 1] != w)
              same = false;
            weights[j + 1] = w;
          }
          if(!same)
          {
            weights[0] = 1;
            scratch.neighbors.resize(count);
            for(std::size_t j = 0; j < count; ++j)
              scratch.neighbors[j] = Neighbor{found[j], 0.};
            scratch.local.assign(input, static_cast<std::uint32_t>(i), scratch.neighbors);
            scratch.weights.resize(scratch.local.size());
            scratch.local.weights(sigmoid, scratch.weights.data());
            m_chosen[i] = scratch.local.best_size(scratch.weights.data(), m_k_low[i], m_k_high[i], s.barycenter).k;
            m_cached[i] = 1;
          }
          if(m_chosen[i] == 0)
          {
            // Every size degenerate: the default neighborhood with equal weights.
            ++m_fallbacks[i];
            voted = voting_tensor_update(normals, i, omega.begin(i), omega.end(i), own_index, true, s, m_next[i]);
          }
          else
          {
            m_selected_sizes[i] += m_chosen[i];
            voted = voting_tensor_update(normals, i, found, found + m_chosen[i], own_index, false, s, m_next[i],
                                         vote_weights);
          }
        }
        if(!voted)
          ++m_empty_cones[i];
      });
    std::swap(input.normals, m_next);
    ++m_summary.iterations;
  }

  // What the sweeps did so far.
  Normal_filter_summary summary() const
  {
    Normal_filter_summary summary = m_summary;
    std::uint64_t selected_total = 0;
    for(std::size_t i = 0; i < m_empty_cones.size(); ++i)
      summary.empty_cones += m_empty_cones[i];
    for(std::size_t i = 0; i < m_fallbacks.size(); ++i)
    {
      summary.fallbacks += m_fallbacks[i];
      selected_total += m_selected_sizes[i];
    }
    const std::size_t selections = std::size_t(summary.iterations) * m_n - summary.fallbacks;
    if(m_settings.adaptive && selections > 0)
      summary.mean_selected_size = double(selected_total) / double(selections);
    return summary;
  }

private:
  Normal_filter_settings m_settings;
  const Neighbor_lists* m_given;
  std::size_t m_n;
  Neighbor_lists m_ball;
  Normal_filter_summary m_summary;
  // adaptive: the k-NN rows, the size range, the cut-off weights of the last evaluation (point
  // first), the size chosen (0: fallback), and the counts of the summary
  std::vector<std::size_t> m_knn_offsets;
  std::vector<std::uint32_t> m_knn;
  std::vector<unsigned int> m_k_low, m_k_high;
  std::vector<unsigned char> m_cached_weights, m_cached;
  std::vector<unsigned int> m_chosen;
  std::vector<std::uint64_t> m_selected_sizes;
  std::vector<std::uint32_t> m_fallbacks, m_empty_cones;
  std::vector<Eigen::Vector3d> m_next;
  std::vector<std::optional<Cosine_sigmoid>> m_vote_weights;
};

// The sweeps of the filter on `input` (normals replaced), with the ball neighborhoods or `given`.
template <typename ConcurrencyTag>
Normal_filter_summary filter_normals_all(Oriented_points& input, const Neighbor_lists* given,
                                         const Normal_filter_settings& s)
{
  try
  {
    // The one kd-tree of the filter: none when the caller gives the neighborhoods of a plain filter.
    std::optional<Neighbor_query> query;
    if(given == nullptr || s.adaptive)
      query.emplace(input.points);
    Normal_voting_filter<ConcurrencyTag> filter(input, query ? &*query : nullptr, given, s);
    for(unsigned int iteration = 0; iteration < s.iterations; ++iteration)
      filter.sweep(input);
    return filter.summary();
  }
  catch(const std::invalid_argument& e)
  {
    throw std::invalid_argument(std::string("filter_normals(): ") + e.what());
  }
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  \brief filters the normals of a point set by the normal voting tensor of Yadav et al. (2018),
  stage 1 of their denoising (`yadav-normal-filtering.md`), and writes them back to `normal_map`.

  Each of the `p` sweeps computes every new normal from the old ones (Jacobi): the neighbors `j`
  of `i` with `n_i * n_j > rho` vote with the mean tensor `T = mean(n_j n_j^T)`; its eigenvalues
  below `tau` become 0, the largest and the others 1 (`T~`); then `n_i <- normalize(T~ n_i + d n_i)`.
  A point whose cone holds no neighbor keeps its normal. Normals never flip.

  The default neighborhood of `i` is the ball `{j != i : |p_j - p_i| <= 5 m}`, `m` the mean
  distance of the points to their 12 nearest neighbors, built once from the input positions.

  With `adaptive_neighborhood_size(true)` (SPEC §7), in every sweep, before its update, every point
  takes its `k` nearest neighbors (ties by index) with the `k` of least `E_dim` (weights
  `sig_{a,a}`, `a = arccos(rho)`, the core's covariance and features) among
  `{k_i - r, ..., k_i + r}` (positive values, at most `n - 1`), `k_i` the size of its default
  neighborhood, `r` = `neighborhood_size_range`; ties go to the smallest `k`. A point for which
  every size is degenerate uses its default neighborhood with equal weights (every neighbor votes).

  The result is the same, bit for bit, for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag` (OpenMP)
  \tparam PointRange a model of `Range` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters

  \param points the input points with oriented normals
  \param np an optional sequence of named parameters among the ones listed below: CGAL's
    (`CGAL::parameters`) and the package's (`CGAL::Sigmoid_neighborhoods::parameters`, which come
    first in a chain, see \ref Sigmoid_neighborhoods_named_parameters)

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Point_3` of a CGAL kernel}
      \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map associating oriented normals to the elements of `points`;
        the filtered normals are written back to it, unit length}
      \cgalParamType{a model of `ReadWritePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Vector_3` of a CGAL kernel}
      \cgalParamDefault{none: required (a static assertion fails without it)}
      \cgalParamExtra{normals need not be unit length; a zero or non-finite normal is an error}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the number of sweeps `p`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::FILTER_ITERATIONS` (50)}
      \cgalParamExtra{a CGAL named parameter}
    \cgalParamNEnd
    \cgalParamNBegin{neighbor_radius}
      \cgalParamDescription{the radius of the default ball neighborhoods}
      \cgalParamType{`double`}
      \cgalParamDefault{`5 m`, `m` the mean distance of the points to their 12 nearest neighbors}
      \cgalParamExtra{a CGAL named parameter; finite and `>= 0` (0 selects the default), otherwise
        `std::invalid_argument`; not read when `neighborhoods` is given}
    \cgalParamNEnd
    \cgalParamNBegin{normal_cut_off}
      \cgalParamDescription{the dot-product cut-off `rho`: neighbor `j` votes for `i` when `n_i * n_j > rho`}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::NORMAL_CUT_OFF` (0.9)}
      \cgalParamExtra{in `[-1, 1]`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{eigenvalue_threshold}
      \cgalParamDescription{the threshold `tau` of the binary eigenvalue optimisation: eigenvalues of
        the voting tensor below it become 0, the others 1 (the largest always 1)}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::EIGENVALUE_THRESHOLD` (0.25)}
      \cgalParamExtra{finite, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{damping_factor}
      \cgalParamDescription{the damping factor `d` of the update `n_i <- normalize(T~ n_i + d n_i)`}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::DAMPING_FACTOR` (3)}
      \cgalParamExtra{finite and `>= 0`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{neighborhoods}
      \cgalParamDescription{the caller's neighborhoods instead of the balls}
      \cgalParamType{a range of ranges of integer indices (`std::cref()` of one avoids a copy)}
      \cgalParamDefault{the ball neighborhoods}
      \cgalParamExtra{one range per point, in the order of `points`, of indices into `points`,
        never the point itself, otherwise `std::invalid_argument`; with it, `neighbor_radius` is not read}
    \cgalParamNEnd
    \cgalParamNBegin{adaptive_neighborhood_size}
      \cgalParamDescription{whether every point chooses, in every sweep, its `k` nearest neighbors with
        the `k` of least `E_dim` (weights `sig_{a,a}`, `a = arccos(rho)`) among
        `{k_i - r, ..., k_i + r}`, `k_i` the size of its default neighborhood}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
      \cgalParamExtra{a point for which every size is degenerate uses its default neighborhood
        with equal weights}
    \cgalParamNEnd
    \cgalParamNBegin{neighborhood_size_range}
      \cgalParamDescription{the half width `r` of the adaptive sizes}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::NEIGHBORHOOD_SIZE_RANGE` (10)}
      \cgalParamExtra{only positive sizes, at most `n - 1`, are tried}
    \cgalParamNEnd
    \cgalParamNBegin{angle_tolerance}
      \cgalParamDescription{angles up to it (radians) count as 0 in the adaptive `E_dim`}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::ANGLE_TOLERANCE` (`1e-6`)}
      \cgalParamExtra{in `[0, pi)`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix of the adaptive `E_dim`}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
  \cgalNamedParamsEnd


  \pre no point has a zero or non-finite normal or a non-finite coordinate; at least 13 points
  when the default radius is used; otherwise `std::invalid_argument`.
  \return what was done
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Normal_filter_summary
#else
std::enable_if_t<internal::is_range<PointRange>::value, Normal_filter_summary>
#endif
filter_normals(PointRange& points, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "filter_normals() needs a normal map");
  const auto normal_map = NP_helper::get_normal_map(points, np);
  auto input = internal::copy_oriented_points(points, NP_helper::get_const_point_map(points, np), normal_map,
                                              internal::line_angles(np));
  const internal::Normal_filter_settings settings = internal::normal_filter_settings(np);
  const std::optional<internal::Neighbor_lists> given = internal::given_neighborhoods(np, input.size());
  const Normal_filter_summary summary =
    internal::filter_normals_all<ConcurrencyTag>(input, given ? &*given : nullptr, settings);
  typedef typename boost::property_traits<typename NP_helper::Normal_map>::value_type Vector;
  std::size_t i = 0;
  for(auto& item : points)
  {
    const Eigen::Vector3d& n = input.normals[i++];
    put(normal_map, item, Vector(n[0], n[1], n[2]));
  }
  return summary;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsNormalFilter
  \brief the same filter on the vertices of a mesh, a `Surface_mesh`, a `Polyhedron_3` or any `FaceListGraph` (SPEC §1): input normals from
  `vertex_normal_map` or else `Polygon_mesh_processing::compute_vertex_normals()`, vertices at one
  position merged (the smallest index kept; its copies get its normal), vertices without a face or
  with an undefined normal left out (they get the zero vector).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag` (OpenMP)
  \tparam PolygonMesh a model of `FaceListGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3` ...)
  \tparam VertexNormalMap a `WritablePropertyMap` from vertex descriptors to `Vector_3`
  \tparam NamedParameters a sequence of named parameters
  \param mesh the input mesh; vertex positions are read from `vertex_point_map`
  \param filtered_normals receives the filtered normal of every vertex (it may be the input map)
  \param np an optional sequence of named parameters among the ones listed below: CGAL's
    (`CGAL::parameters`) and the package's (`CGAL::Sigmoid_neighborhoods::parameters`, which come
    first in a chain, see \ref Sigmoid_neighborhoods_named_parameters)

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as key type and
        a `Point_3` of a CGAL kernel as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{a property map associating to each vertex of `mesh` a unique index}
      \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as key type and
        `std::size_t` as value type}
      \cgalParamDefault{an automatically indexed internal map}
      \cgalParamExtra{vertices at one position are merged into the one of smallest index}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{a property map associating the input normals to the vertices of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as key type and
        a `Vector_3` of the kernel of `Point` as value type}
      \cgalParamDefault{the normals of `CGAL::Polygon_mesh_processing::compute_vertex_normals()`}
      \cgalParamExtra{a vertex whose normal is zero or not finite is left out}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the number of sweeps `p`}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::FILTER_ITERATIONS` (50)}
      \cgalParamExtra{a CGAL named parameter}
    \cgalParamNEnd
    \cgalParamNBegin{neighbor_radius}
      \cgalParamDescription{the radius of the default ball neighborhoods}
      \cgalParamType{`double`}
      \cgalParamDefault{`5 m`, `m` the mean distance of the points to their 12 nearest neighbors}
      \cgalParamExtra{a CGAL named parameter; finite and `>= 0` (0 selects the default), otherwise
        `std::invalid_argument`; not read when `neighborhoods` is given}
    \cgalParamNEnd
    \cgalParamNBegin{normal_cut_off}
      \cgalParamDescription{the dot-product cut-off `rho`: neighbor `j` votes for `i` when `n_i * n_j > rho`}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::NORMAL_CUT_OFF` (0.9)}
      \cgalParamExtra{in `[-1, 1]`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{eigenvalue_threshold}
      \cgalParamDescription{the threshold `tau` of the binary eigenvalue optimisation: eigenvalues of
        the voting tensor below it become 0, the others 1 (the largest always 1)}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::EIGENVALUE_THRESHOLD` (0.25)}
      \cgalParamExtra{finite, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{damping_factor}
      \cgalParamDescription{the damping factor `d` of the update `n_i <- normalize(T~ n_i + d n_i)`}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::DAMPING_FACTOR` (3)}
      \cgalParamExtra{finite and `>= 0`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{neighborhoods}
      \cgalParamDescription{the caller's neighborhoods instead of the balls}
      \cgalParamType{a range of ranges of integer indices (`std::cref()` of one avoids a copy)}
      \cgalParamDefault{the ball neighborhoods}
      \cgalParamExtra{one range per vertex index (`std::size_t(v)`, removed vertices included)
        of neighboring vertex indices, never the vertex itself, otherwise `std::invalid_argument`;
        with it, `neighbor_radius` is not read}
    \cgalParamNEnd
    \cgalParamNBegin{adaptive_neighborhood_size}
      \cgalParamDescription{whether every point chooses, in every sweep, its `k` nearest neighbors with
        the `k` of least `E_dim` (weights `sig_{a,a}`, `a = arccos(rho)`) among
        `{k_i - r, ..., k_i + r}`, `k_i` the size of its default neighborhood}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
      \cgalParamExtra{a point for which every size is degenerate uses its default neighborhood
        with equal weights}
    \cgalParamNEnd
    \cgalParamNBegin{neighborhood_size_range}
      \cgalParamDescription{the half width `r` of the adaptive sizes}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`defaults::NEIGHBORHOOD_SIZE_RANGE` (10)}
      \cgalParamExtra{only positive sizes, at most `n - 1`, are tried}
    \cgalParamNEnd
    \cgalParamNBegin{angle_tolerance}
      \cgalParamDescription{angles up to it (radians) count as 0 in the adaptive `E_dim`}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::ANGLE_TOLERANCE` (`1e-6`)}
      \cgalParamExtra{in `[0, pi)`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{barycenter}
      \cgalParamDescription{the centre of the covariance matrix of the adaptive `E_dim`}
      \cgalParamType{`Barycenter`}
      \cgalParamDefault{`Barycenter::WEIGHTED`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre finite coordinates; at least 13 points when the default radius is used; otherwise
  `std::invalid_argument`
  \return what was done, with `Normal_filter_summary::mesh` set
*/
template <typename ConcurrencyTag, typename PolygonMesh, typename VertexNormalMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Normal_filter_summary
#else
std::enable_if_t<!internal::is_range<PolygonMesh>::value, Normal_filter_summary>
#endif
filter_normals(const PolygonMesh& mesh, VertexNormalMap filtered_normals,
               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::get_parameter_reference;
  using CGAL::parameters::is_default_parameter;
  auto mesh_points = internal::mesh_points(mesh, np);
  const internal::Normal_filter_settings settings = internal::normal_filter_settings(np);
  Normal_filter_summary summary;
  if constexpr(!is_default_parameter<CGAL_NP_CLASS, internal_np::neighborhoods_t>::value)
  {
    // Vertex lists to point lists: a point's list is its kept vertex's, without dropped vertices
    // and without the copies of the point itself.
    const auto& lists = get_parameter_reference(np, internal_np::neighborhoods);
    const std::size_t vertex_slots = mesh_points.point_of_vertex.size();
    if(std::size_t(std::distance(std::begin(lists), std::end(lists))) != vertex_slots)
      throw std::invalid_argument("the neighborhoods must hold one list per vertex index (" +
                                  std::to_string(vertex_slots) + ")");
    std::vector<std::vector<std::uint32_t>> point_lists(mesh_points.input.size());
    std::vector<bool> done(mesh_points.input.size(), false);
    std::size_t v = 0;
    for(const auto& list : lists)
    {
      const std::uint32_t i = mesh_points.point_of_vertex[v];
      if(i != internal::NO_POINT && !done[i])
      {
        done[i] = true;
        for(const auto& u : list)
        {
          if(!internal::index_in_range(u, vertex_slots))
            throw std::invalid_argument("neighborhood of vertex " + std::to_string(v) + ": vertex " +
                                        std::to_string(u) + " is out of range");
          if(std::size_t(u) == v)
            throw std::invalid_argument("neighborhood of vertex " + std::to_string(v) + " contains the vertex itself");
          const std::uint32_t j = mesh_points.point_of_vertex[std::size_t(u)];
          if(j != internal::NO_POINT && j != i)
            point_lists[i].push_back(j);
        }
      }
      ++v;
    }
    const internal::Neighbor_lists given = internal::neighbor_lists(point_lists, mesh_points.input.size());
    summary = internal::filter_normals_all<ConcurrencyTag>(mesh_points.input, &given, settings);
  }
  else
    summary = internal::filter_normals_all<ConcurrencyTag>(mesh_points.input, nullptr, settings);
  summary.mesh = mesh_points.summary;
  typedef typename boost::property_traits<VertexNormalMap>::value_type Vector;
  std::size_t t = 0;
  for(auto vertex : vertices(mesh))
  {
    const std::uint32_t i = mesh_points.point_in_vertex_order[t++];
    if(i == internal::NO_POINT)
      put(filtered_normals, vertex, Vector(0., 0., 0.));
    else
    {
      const Eigen::Vector3d& n = mesh_points.input.normals[i];
      put(filtered_normals, vertex, Vector(n[0], n[1], n[2]));
    }
  }
  return summary;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_FILTER_NORMALS_H
