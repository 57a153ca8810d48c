// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_DENOISE_POINT_SET_H
#define CGAL_SIGMOID_NEIGHBORHOODS_DENOISE_POINT_SET_H

#include <CGAL/Sigmoid_neighborhoods/filter_normals.h>
#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/optimal_search_all.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Vertex_update.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/// \cond SKIP_IN_MANUAL
namespace internal {
// The jet update's normal weights (`jet_vertex_update`): the cosine sigmoid `sig_{a,b}` of the angle
// between the filtered normals with `a` = 30 degrees, so that the neighboring facets into which
// stage 1 turns a curved patch (at most the cut-off cone's 25.8 degrees apart) enter the fit ...
constexpr double JET_FULL_WEIGHT_ANGLE = CGAL_PI / 6.;
// ... and `b` = 60 degrees, so that the faces of a sharp edge do not.
constexpr double JET_ZERO_WEIGHT_ANGLE = CGAL_PI / 3.;
// An edge or corner of stage 2 is projected onto its jet when less than this share of its fit
// window's weight lies beyond the normal sigmoid: then it is a strip of a curved patch, not a
// feature (at a sharp edge, about half of the window lies on the other face).
constexpr double JET_FEATURE_FRACTION = 0.5;
// A smooth point whose fit neighbors' filtered normals turn from its own by less than this angle on
// average (`1 - n_i * n_j` weighted as in the fit) lies on a flat patch: it keeps the planar rule,
// which averages over the patch more than a quadric does (3 degrees).
constexpr double JET_FLAT_ANGLE = CGAL_PI / 60.;
// The radius `r` of the jet fit's distance weights `exp(-|p_j - p_i|^2 / r^2)` is
// `JET_RADIUS_FACTOR * sqrt(sigma m)`, clamped to `[JET_MINIMUM_RADIUS, JET_MAXIMUM_RADIUS] * m`
// (`sigma` the estimated noise level, `m` the scale): the noisier, the wider (0.3 and 0.6 `l` of noise
// give about `1.6 m` and `2.2 m`); the lower bound because the estimate falls short where most
// points lie on feature curves (benchmark/README.md).
constexpr double JET_RADIUS_FACTOR = 3.2;
constexpr double JET_MINIMUM_RADIUS = 1.75;
constexpr double JET_MAXIMUM_RADIUS = 3.;
// The bound `epsilon` on a point's distance to its input position, in units of the scale `m` (the
// authors' code: `2 m`): a move beyond it is refused, so that no point wanders off.
constexpr double DEVIATION_SCALE_FACTOR = 2.;
// The radius `r` of the planar rule's weights, in units of the scale `m` (the authors' code: `2 m`):
// a neighbor's distance term `exp(-4 |p_j - p_i|^2 / r^2)` falls to `exp(-4)` at two spacings, so
// that the rule averages over the point's own ring of neighbors, not across features.
constexpr double PLANAR_WEIGHT_SCALE_FACTOR = 2.;
// The iterations stop once the RMS distance of the points to their input positions reaches this
// factor times the noise level estimated from the input (Morozov's discrepancy principle, which asks
// for a factor above 1: the moves are not all along the noise).
constexpr double DISCREPANCY_FACTOR = 1.1;
// the standard deviation of a Gaussian per median of its absolute value
constexpr double NOISE_LEVEL_PER_MEDIAN = 1.482602218505602;
// the neighbors of the noise estimate's quadric fits: more than the six coefficients, few enough
// that features seldom enter
constexpr unsigned int NOISE_ESTIMATION_NEIGHBORS = 20;
} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsDenoising
  what `denoise_point_set()` did. The class counts are those of the last iteration; the other
  counts are over all iterations, one per point and iteration.
*/
struct Point_set_denoising_summary
{
  std::size_t points = 0;          ///< points denoised
  unsigned int iterations = 0;     ///< iterations run
  double scale = 0.;               ///< the scale `m`: the mean distance of the points to their 12 nearest neighbors
  double maximum_deviation = 0.;   ///< the bound `epsilon` on the distance to the input position
  std::size_t planar = 0;          ///< points classified planar in the last iteration
  std::size_t edges = 0;           ///< points classified edges in the last iteration
  std::size_t corners = 0;         ///< points classified corners in the last iteration
  std::size_t unclassified = 0;    ///< points whose cut-off neighborhood had no extent in the last iteration (they stayed)
  std::size_t smooth = 0;          ///< with `jet_vertex_update`: points on smooth patches in the last iteration, projected onto their jets (among the classes above)
  std::size_t degenerate_fits = 0; ///< with `jet_vertex_update`: jet fits too weak or ill-conditioned, whose points stayed
  std::size_t rank_deficient = 0;  ///< edge and corner solves in which the rank test dropped a direction
  std::size_t refused = 0;         ///< moves refused because they left the ball of radius `epsilon`
  double noise_estimate = 0.;      ///< the noise level `sigma` estimated from the input (see `stop_at_noise_level`)
  bool stopped_at_noise_level = false; ///< the iterations stopped when the displacement reached `sigma`
  bool interrupted = false;        ///< the callback asked to stop
  std::size_t cut_off_votes = 0;   ///< with `optimal_vote_weights`: points without an optimum, which vote with the cut-off
  double mean_displacement = 0.;   ///< the mean distance of the output points to the input points
  double largest_displacement = 0.; ///< the largest such distance
  Normal_filter_summary normal_filter; ///< what stage 1 (the normal filter) did
  Mesh_points_summary mesh;        ///< for a mesh: how its vertices became points
};

/// \cond SKIP_IN_MANUAL
namespace internal {

struct Denoising_settings
{
  Normal_filter_settings filter;
  double step_size = defaults::PLANAR_STEP_SIZE;
  double maximum_deviation = 0.; // 0: DEVIATION_SCALE_FACTOR times the scale
  double weight_radius = 0.;     // 0: PLANAR_WEIGHT_SCALE_FACTOR times the scale
  double rank_threshold = defaults::RANK_THRESHOLD;
  bool in_place = false;         // the authors' Gauss-Seidel order of stages 2 and 3, sequential
  bool authors_vertex_update = false;
  bool jet_vertex_update = true;
  bool stop_at_noise_level = true;
  bool optimal_vote_weights = false; // stage 1 votes with sig_{a*_i, b*_i} of the input
  Search_settings search;            // the search of (a*_i, b*_i)
  std::function<bool(double)> callback;
};

template <typename NamedParameters>
Denoising_settings denoising_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Denoising_settings s;
  s.filter = normal_filter_settings(np);
  s.step_size = choose_parameter(get_parameter(np, internal_np::step_size), defaults::PLANAR_STEP_SIZE);
  s.maximum_deviation = choose_parameter(get_parameter(np, internal_np::maximum_deviation), 0.);
  s.rank_threshold = choose_parameter(get_parameter(np, internal_np::rank_threshold), defaults::RANK_THRESHOLD);
  s.weight_radius = choose_parameter(get_parameter(np, internal_np::planar_weight_radius), 0.);
  s.in_place = choose_parameter(get_parameter(np, internal_np::in_place_updates), false);
  s.authors_vertex_update = choose_parameter(get_parameter(np, internal_np::authors_vertex_update), false);
  s.jet_vertex_update = choose_parameter(get_parameter(np, internal_np::jet_vertex_update), true);
  s.stop_at_noise_level = choose_parameter(get_parameter(np, internal_np::stop_at_noise_level), true);
  s.optimal_vote_weights = choose_parameter(get_parameter(np, internal_np::optimal_vote_weights), false);
  if(s.optimal_vote_weights)
    s.search = search_settings(np);
  s.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  if(!(s.step_size >= 0. && std::isfinite(s.step_size)))
    throw std::invalid_argument("the step size must be finite and >= 0, got " + std::to_string(s.step_size));
  if(!(s.maximum_deviation >= 0. && std::isfinite(s.maximum_deviation)))
    throw std::invalid_argument("the maximum deviation must be finite and >= 0, got " +
                                std::to_string(s.maximum_deviation));
  if(!(s.weight_radius >= 0. && std::isfinite(s.weight_radius)))
    throw std::invalid_argument("the planar weight radius must be finite and >= 0, got " +
                                std::to_string(s.weight_radius));
  if(!(s.rank_threshold >= 0. && s.rank_threshold <= 1.))
    throw std::invalid_argument("the rank threshold must lie in [0, 1], got " + std::to_string(s.rank_threshold));
  return s;
}

// The noise level of the input along the normals: 1.4826 times the median distance of the points to
// the least-squares quadric z = f(x, y) of their NOISE_ESTIMATION_NEIGHBORS nearest neighbors, in the
// neighbors' principal frame, each divided by the standard deviation of the fit's prediction error. The
// point itself is left out, so that it does not pull the fit towards itself; a quadric, so that
// curvature does not count as noise; the median, so that sharp features, where no quadric fits, do
// not count; 1.4826 makes it the standard deviation of Gaussian noise.
template <typename ConcurrencyTag>
double estimate_noise_level(const Neighbor_query& query, unsigned int threads)
{
  const std::size_t n = query.size();
  const std::vector<Double_point>& points = query.points();
  std::vector<double> residuals(n);
  for_each_index<ConcurrencyTag>(
    n, threads, [] { return std::vector<Neighbor>(); },
    [&](std::size_t i, std::vector<Neighbor>& found) {
      query.query(static_cast<std::uint32_t>(i), NOISE_ESTIMATION_NEIGHBORS, found);
      const Eigen::Vector3d p = to_eigen(points[i]);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
      for(const Neighbor& x : found)
      {
        const Eigen::Vector3d d = to_eigen(points[x.index]) - p;
        sum += d;
        moments.noalias() += d * d.transpose();
      }
      const double count = double(found.size());
      const Eigen::Vector3d mean = sum / count;
      const Eigen::Matrix3d covariance = moments / count - mean * mean.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::ComputeEigenvectors);
      const Eigen::Matrix3d frame = solver.eigenvectors(); // columns: normal, then the two tangents
      // The quadric's coefficients by least squares, scaled to the neighborhood's extent.
      const double extent = std::sqrt((std::max)(solver.eigenvalues()[2], 0.));
      residuals[i] = std::abs(frame.col(0).dot(mean));
      if(!(extent > 0.) || found.size() < 12)
        return;
      Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 1> right = Eigen::Matrix<double, 6, 1>::Zero();
      auto monomials = [&](const Eigen::Vector3d& local) {
        const double u = local[1] / extent, v = local[2] / extent;
        Eigen::Matrix<double, 6, 1> m;
        m << 1., u, v, u * u, u * v, v * v;
        return m;
      };
      for(const Neighbor& x : found)
      {
        const Eigen::Vector3d local = frame.transpose() * (to_eigen(points[x.index]) - p - mean);
        const Eigen::Matrix<double, 6, 1> m = monomials(local);
        normal_matrix.noalias() += m * m.transpose();
        right += m * local[0];
      }
      const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solve(normal_matrix);
      if(solve.info() != Eigen::Success || !(solve.rcond() > 1e-12))
        return;
      const Eigen::Matrix<double, 6, 1> coefficients = solve.solve(right);
      const Eigen::Vector3d own = frame.transpose() * (-mean);
      const Eigen::Matrix<double, 6, 1> m = monomials(own);
      // The prediction's own error: the residual's variance is sigma^2 (1 + m^T (X^T X)^-1 m).
      const double leverage = m.dot(solve.solve(m));
      const double residual = (own[0] - m.dot(coefficients)) / std::sqrt(1. + (std::max)(leverage, 0.));
      if(std::isfinite(residual))
        residuals[i] = std::abs(residual);
    });
  std::nth_element(residuals.begin(), residuals.begin() + std::ptrdiff_t(n / 2), residuals.end());
  return NOISE_LEVEL_PER_MEDIAN * residuals[n / 2];
}

// The radius of the jet fit's distance weights (JET_RADIUS_FACTOR).
inline double jet_fit_radius(double noise_level, double scale)
{
  return std::clamp(JET_RADIUS_FACTOR * std::sqrt(noise_level * scale), JET_MINIMUM_RADIUS * scale,
                    JET_MAXIMUM_RADIUS * scale);
}

// The iterations of the three stages on `input` (positions and normals replaced), with the ball
// neighborhoods or `given`.
template <typename ConcurrencyTag>
Point_set_denoising_summary denoise_all(Oriented_points& input, const Neighbor_lists* given,
                                        const Denoising_settings& s)
{
  const std::size_t n = input.size();
  if(n < FILTER_SCALE_NEIGHBORS + 1)
    throw std::invalid_argument("denoise_point_set(): the scale needs at least " +
                                std::to_string(FILTER_SCALE_NEIGHBORS + 1) + " points, got " + std::to_string(n));
  Point_set_denoising_summary summary;
  summary.points = n;

  // The point set's one kd-tree, over the input positions: the scale, the balls, the adaptive k-NN.
  const std::vector<Double_point> original = input.points;
  const Neighbor_query query(original);
  summary.scale = mean_neighbor_distance<ConcurrencyTag>(query, FILTER_SCALE_NEIGHBORS, s.filter.threads);
  Normal_filter_settings filter_settings = s.filter;
  if(given == nullptr && filter_settings.radius == 0.)
    filter_settings.radius = FILTER_RADIUS_FACTOR * summary.scale;
  std::optional<Normal_voting_filter<ConcurrencyTag>> filter;
  try
  {
    filter.emplace(input, &query, given, filter_settings);
  }
  catch(const std::invalid_argument& e)
  {
    throw std::invalid_argument(std::string("denoise_point_set(): ") + e.what());
  }

  if(s.optimal_vote_weights)
  {
    // Every point votes with the sigmoid of its optimal (a*, b*) on the input, where it has one.
    std::vector<std::optional<Cosine_sigmoid>> weights(n);
    try
    {
      optimal_search_all<ConcurrencyTag>(input, query, s.search,
                                         [&](std::size_t i, const Optimal_sigmoid_neighborhood& r) {
                                           if(!r.is_failure())
                                             weights[i].emplace(r.a, r.b, s.filter.angle_tolerance);
                                         });
    }
    catch(const std::invalid_argument& e)
    {
      throw std::invalid_argument(std::string("denoise_point_set(): optimal vote weights: ") + e.what());
    }
    for(const auto& w : weights)
      summary.cut_off_votes += w ? 0 : 1;
    filter->set_vote_weights(std::move(weights));
  }

  summary.maximum_deviation =
    s.maximum_deviation > 0. ? s.maximum_deviation : DEVIATION_SCALE_FACTOR * summary.scale;
  const double squared_deviation = summary.maximum_deviation * summary.maximum_deviation;
  Vertex_update_settings u;
  u.cut_off = s.filter.cut_off;
  u.eigenvalue_threshold = s.filter.eigenvalue_threshold;
  u.step_size = s.step_size;
  u.weight_radius = s.weight_radius > 0. ? s.weight_radius : PLANAR_WEIGHT_SCALE_FACTOR * summary.scale;
  // The authors' width of the normal term is r, a length, so that the term depends on the model's
  // size; the package's is the chord of the cut-off cone, |n_i - n_j| = sqrt(2 (1 - rho)), where the
  // term is exp(-8): neighbors outside the cone do not count, whatever the size.
  u.normal_weight_width = s.authors_vertex_update ? u.weight_radius : std::sqrt(2. * (1. - (std::min)(s.filter.cut_off, 0.99)));
  u.rank_threshold = s.rank_threshold;
  u.weighted_metrics = !s.authors_vertex_update;
  u.line_angles = s.filter.line_angles;
  u.jet_update = s.jet_vertex_update && !s.authors_vertex_update;
  if(s.stop_at_noise_level || u.jet_update)
    summary.noise_estimate = estimate_noise_level<ConcurrencyTag>(query, s.filter.threads);
  if(u.jet_update)
  {
    u.jet_radius = jet_fit_radius(summary.noise_estimate, summary.scale);
    u.jet_sigmoid = Cosine_sigmoid(JET_FULL_WEIGHT_ANGLE, JET_ZERO_WEIGHT_ANGLE, s.filter.angle_tolerance);
    u.jet_feature_fraction = JET_FEATURE_FRACTION;
    u.jet_flat_spread = 1. - std::cos(JET_FLAT_ANGLE);
  }

  std::vector<Vertex_class> classes(n, Vertex_class::UNCLASSIFIED);
  std::vector<std::uint32_t> rank_deficient(n, 0), refused(n, 0);
  std::vector<unsigned char> smooth(n, 0);
  std::vector<std::uint32_t> degenerate_fits(n, 0);
  std::vector<Double_point> next(n);
  for(unsigned int iteration = 0; iteration < s.filter.iterations; ++iteration)
  {
    filter->sweep(input, iteration > 0); // stage 1
    // Stages 2 and 3, the new position of i from the old ones (Jacobi); in place, in index order,
    // with `in_place`.
    auto update = [&](std::size_t i, std::vector<Double_point>& target) {
      const auto neighbors = filter->neighbors(i);
      const Vertex_update r = update_vertex(input.points, original, input.normals, i, neighbors.first, neighbors.second, u);
      classes[i] = r.type;
      smooth[i] = r.smooth ? 1 : 0;
      degenerate_fits[i] += r.degenerate_fit ? 1 : 0;
      rank_deficient[i] += r.rank_deficient ? 1 : 0;
      const Eigen::Vector3d& x = r.position;
      const Double_point& o = original[i];
      const double dx = x[0] - o.x(), dy = x[1] - o.y(), dz = x[2] - o.z();
      if(x.allFinite() && dx * dx + dy * dy + dz * dz < squared_deviation)
        target[i] = Double_point(x[0], x[1], x[2]);
      else
      {
        target[i] = input.points[i];
        ++refused[i];
      }
    };
    if(s.in_place)
      for(std::size_t i = 0; i < n; ++i)
        update(i, input.points);
    else
    {
      for_each_index<ConcurrencyTag>(
        n, s.filter.threads, [] { return 0; }, [&](std::size_t i, int&) { update(i, next); });
      std::swap(input.points, next);
    }
    ++summary.iterations;
    // Morozov's discrepancy principle: the points have moved as far as the noise took them away.
    // The smooth points sit on their jets, which the iterations do not move on: the rule watches the
    // others (all of them stop it at once).
    if(s.stop_at_noise_level)
    {
      double squares = 0.;
      std::size_t counted = 0;
      for(std::size_t i = 0; i < n; ++i)
        if(!smooth[i])
        {
          squares += CGAL::squared_distance(input.points[i], original[i]);
          ++counted;
        }
      if(counted == 0 || std::sqrt(squares / double(counted)) >= DISCREPANCY_FACTOR * summary.noise_estimate)
      {
        summary.stopped_at_noise_level = true;
        break;
      }
    }
    if(s.callback && !s.callback(double(iteration + 1) / double(s.filter.iterations)))
    {
      summary.interrupted = true;
      break;
    }
  }

  summary.normal_filter = filter->summary();
  double total = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    switch(classes[i])
    {
      case Vertex_class::PLANAR: ++summary.planar; break;
      case Vertex_class::EDGE: ++summary.edges; break;
      case Vertex_class::CORNER: ++summary.corners; break;
      default: ++summary.unclassified; break;
    }
    summary.rank_deficient += rank_deficient[i];
    summary.smooth += smooth[i];
    summary.degenerate_fits += degenerate_fits[i];
    summary.refused += refused[i];
    const double d = std::sqrt(CGAL::squared_distance(input.points[i], original[i]));
    total += d;
    summary.largest_displacement = (std::max)(summary.largest_displacement, d);
  }
  summary.mean_displacement = total / double(n);
  return summary;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsDenoising
  \brief denoises a point set with oriented normals by the three stages of Yadav et al. (2018),
  "Constraint-based point set denoising using normal voting tensor and restricted quadratic error
  metrics": the points are moved in place through `point_map` and the filtered normals written
  to `normal_map`.

  Each of the `p` iterations runs, in the authors' order:
  1. **normal filtering**, one sweep of `filter_normals()` (same neighborhoods and parameters);
  2. **classification** of every point from the covariance of `{p_i}` and its neighbors `j` with
     `n_i * n_j > rho` (new normals, current positions): with its eigenvalues scaled to unit
     Euclidean length and compared with `tau`, an *edge* when the two smaller are below `tau`, *planar*
     when only the smallest is, a *corner* otherwise;
  3. **vertex update** over all neighbors: a corner moves to the minimiser of the quadratic error
     metric `sum_j (n_j * (x - p_j))^2`; an edge to its minimiser in the plane through `p_i`
     orthogonal to the edge direction `e` (the covariance's main axis), with the neighbor normals
     projected orthogonally to `e`; a planar point by `alpha` times the weighted mean offset
     `n_i * (p_j - p_i)` along `n_i`, weights `exp(-8 |n_i - n_j|^2 / r^2) exp(-4 |p_j - p_i|^2 / r^2)`, `r = 2 m`.
     A move that ends at `epsilon = 2 m` or farther from the point's input position is refused.
     With `jet_vertex_update` (the default, below), a point on a smooth patch moves onto its jet instead.

  `m` is the mean distance of the input points to their 12 nearest neighbors; the neighborhoods, the
  balls `{j != i : |p_j - p_i| <= 5 m}` of the input positions, are built once.

  **What the package changes against the authors' code**, and why:
  - *A rank test before the edge and corner solves* (`rank_threshold`, default
    `defaults::RANK_THRESHOLD`): the authors invert the 3x3 metric, which is singular wherever the
    neighbor normals agree (a point on a plane or a smooth edge classified as a corner or an edge, one
    in five under noise); its inverse then throws the point along a direction no plane constrains, as
    far as `epsilon` allows. Here a direction whose eigenvalue is below `rank_threshold` times the
    largest is not solved for: the point keeps its coordinate along it (the least-norm minimiser, as
    in QEM vertex placement). `rank_threshold(0)` gives the authors' solve.
  - *Jacobi order*: every new position is computed from the old ones, so that the result is the same,
    bit for bit, for any number of threads. The authors update in place, in index order
    (Gauss-Seidel); `in_place_updates(true)` does so, sequentially.
  - *Metrics at the planar rule's scale, approached by steps*: the authors sum the edge and corner
    metrics over the whole ball of radius `5 m` and jump to their minimisers, which near a feature
    mixes the planes of every face in the ball and throws the point by up to `epsilon` in one
    iteration. Here each neighbor's plane is weighted by the planar rule's distance term
    `exp(-4 |p_j - p_i|^2 / r^2)`, and every class moves by `alpha` towards its target.
  - *A normal term of the planar weights without a length*: the authors divide `|n_i - n_j|^2` by
    `r^2`, a length, so that the weights change with the model's size; here by the squared chord of
    the cut-off cone `2 (1 - rho)`, where the term is `exp(-8)`.
  - *A stopping rule*: the authors run all `p` iterations, and the points drift past their best
    after a while (features erode). Here the iterations stop once the RMS distance of the points to
    their input positions reaches 1.1 times the noise level `sigma` estimated from
    the input (1.4826 times the median distance of a point to the quadric fitted to its 20 nearest
    neighbors): Morozov's discrepancy principle. `stop_at_noise_level(false)` runs all iterations.
  - *A jet update on smooth patches* (`jet_vertex_update`, default `true`): the planar rule moves a
    point towards the weighted mean plane of its neighbors, which on a curved patch lies inside the
    surface, and stage 1 turns the normals of a curved patch into facets that stage 2 classifies as
    strips (edges). Here every planar point, and every edge or corner whose fit window has less than
    half of its weight beyond the normal sigmoid below (a facet, not a feature), is
    *smooth* unless its fit neighbors' normals turn by less than 3 degrees on average (a flat
    patch, where the planar rule averages more): it moves to `p0_i + c0 n_i`, where `c0` is the constant term of the weighted
    least-squares quadric `z = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2` (a jet of order 2) of
    `p0_i` and its neighbors' input positions `p0_j`, in the frame of the filtered normal `n_i`. The
    weights are `sig_{30, 60 degrees}(angle(n_i, n_j)) exp(-|p0_j - p0_i|^2 / r^2)`: the sigmoid takes
    the neighboring facets of a curved patch in and the other face of a sharp edge out, and
    `r = 3.2 sqrt(sigma m)` in `[1.75 m, 3 m]` widens with the estimated noise level `sigma`. The fit is on the input positions, so that iterating does not shrink
    the patch; the current normals decide only who enters it. A fit of total weight below 8 or with
    ill-conditioned normal equations is degenerate: the point stays where it is (small and thin
    inputs). The stopping rule watches the points that are not smooth (all smooth: one iteration).
    The neighbors are those of stage 1: the ball, or with `adaptive_neighborhood_size(true)` the `k`
    nearest of the size chosen per point; the distance weights bound the fit within them.
    `jet_vertex_update(false)` gives the planar rule above.
  - `authors_vertex_update(true)` with `rank_threshold(0)` gives the authors' stage 3 (and no jet update).
  - A point whose cone holds no neighbor keeps its normal (stage 1, as in `filter_normals()`), and a
    point whose cut-off neighborhood has no extent stays where it is (stage 2; the authors skip it too).

  With `adaptive_neighborhood_size(true)` (SPEC §7) every point uses, in all three stages of an
  iteration, its `k` nearest input neighbors with the `k` of least `E_dim` chosen in stage 1 (see
  `filter_normals()`), on the current positions and normals.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag` (OpenMP)
  \tparam PointRange a model of `Range` whose value type is the key type of the maps
  \tparam NamedParameters a sequence of named parameters

  \param points the input points with oriented normals (orientation matters: the cut-off is on the
    signed dot product, unless `line_angles`)
  \param np an optional sequence of named parameters among the ones listed below, and those of
    `filter_normals()` (`number_of_iterations`, `neighbor_radius`, `normal_cut_off`,
    `eigenvalue_threshold`, `damping_factor`, `neighborhoods`, `adaptive_neighborhood_size`,
    `neighborhood_size_range`, `angle_tolerance`, `barycenter`, `line_angles`, `number_of_threads`),
    whose defaults are the authors'

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`; the
        denoised points are written back to it}
      \cgalParamType{a model of `ReadWritePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Point_3` of a CGAL kernel}
      \cgalParamDefault{`CGAL::Identity_property_map<Point_3>`}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map associating oriented normals to the elements of `points`;
        the filtered normals are written back to it, unit length}
      \cgalParamType{a model of `ReadWritePropertyMap` whose key type is the value type of `PointRange`
        and whose value type is a `Vector_3` of a CGAL kernel}
      \cgalParamDefault{none: required (a static assertion fails without it)}
    \cgalParamNEnd
    \cgalParamNBegin{step_size}
      \cgalParamDescription{the step `alpha` of the planar rule}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::PLANAR_STEP_SIZE` (0.1)}
      \cgalParamExtra{finite and `>= 0`, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_deviation}
      \cgalParamDescription{the bound `epsilon`: a move to a position at this distance from the
        input position or farther is refused}
      \cgalParamType{`double`}
      \cgalParamDefault{`2 m` (the authors')}
      \cgalParamExtra{finite and `>= 0` (0 selects the default), otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{planar_weight_radius}
      \cgalParamDescription{the radius `r` of the weights `exp(-4 |p_j - p_i|^2 / r^2)` of the planar
        rule (and of the package's edge and corner metrics)}
      \cgalParamType{`double`}
      \cgalParamDefault{`2 m` (the authors')}
      \cgalParamExtra{finite and `>= 0` (0 selects the default), otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{rank_threshold}
      \cgalParamDescription{the rank test of the edge and corner solves: directions of eigenvalues
        below this fraction of the largest are not solved for}
      \cgalParamType{`double`}
      \cgalParamDefault{`defaults::RANK_THRESHOLD` (0.1)}
      \cgalParamExtra{in `[0, 1]`, otherwise `std::invalid_argument`; 0 is the authors' solve}
    \cgalParamNEnd
    \cgalParamNBegin{in_place_updates}
      \cgalParamDescription{whether stages 2 and 3 update the points in place, in the order of
        `points` (Gauss-Seidel, the authors' code), sequentially, instead of all from the previous positions}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{authors_vertex_update}
      \cgalParamDescription{whether stage 3 is the authors' code: unweighted metrics over the whole
        neighborhood, the full step for edges and corners, the normal term of width `r`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{jet_vertex_update}
      \cgalParamDescription{whether points on smooth patches move onto the quadric fitted to their
        neighborhood (above) instead of towards the weighted mean plane; edges and corners keep the
        restricted quadratic error metrics. Ignored with `authors_vertex_update(true)`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{stop_at_noise_level}
      \cgalParamDescription{whether the iterations stop at the estimated noise level (above)}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{optimal_vote_weights}
      \cgalParamDescription{an experiment beyond the paper: whether in stage 1 the neighbors of `i` vote
        with the weights `sig_{a*_i, b*_i}(angle(n_i, n_j))` of the point's optimal `(a*, b*)` on the
        input (`compute_optimal_sigmoid_neighborhoods()`, on the same kd-tree, with the search's
        named parameters `k_min`, `k_max`, `a_grid`, `b_grid`), `T = sum w_j n_j n_j^T / sum w_j`,
        instead of the binary cut-off `rho`; a point where every triple is degenerate keeps the cut-off}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
      \cgalParamExtra{needs at least `k_max + 1` points, otherwise `std::invalid_argument`}
    \cgalParamNEnd
    \cgalParamNBegin{callback}
      \cgalParamDescription{called after every iteration with the fraction of `number_of_iterations`
        done; the iterations stop when it returns `false`}
      \cgalParamType{`std::function<bool(double)>`}
      \cgalParamDefault{none}
      \cgalParamExtra{a CGAL named parameter}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre no point has a zero or non-finite normal or a non-finite coordinate; at least 13 points;
  otherwise `std::invalid_argument`
  \return what was done
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Point_set_denoising_summary
#else
std::enable_if_t<internal::is_range<PointRange>::value, Point_set_denoising_summary>
#endif
denoise_point_set(PointRange& points, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  static_assert(NP_helper::has_normal_map(), "denoise_point_set() needs a normal map");
  const auto point_map = NP_helper::get_point_map(points, np);
  const auto normal_map = NP_helper::get_normal_map(points, np);
  auto input = internal::copy_oriented_points(points, point_map, normal_map, internal::line_angles(np));
  const internal::Denoising_settings settings = internal::denoising_settings(np);
  const std::optional<internal::Neighbor_lists> given = internal::given_neighborhoods(np, input.size());
  const Point_set_denoising_summary summary =
    internal::denoise_all<ConcurrencyTag>(input, given ? &*given : nullptr, settings);
  typedef typename boost::property_traits<typename NP_helper::Point_map>::value_type Point;
  typedef typename boost::property_traits<typename NP_helper::Normal_map>::value_type Vector;
  std::size_t i = 0;
  for(auto& item : points)
  {
    const internal::Double_point& p = input.points[i];
    const Eigen::Vector3d& n = input.normals[i++];
    put(point_map, item, Point(p.x(), p.y(), p.z()));
    put(normal_map, item, Vector(n[0], n[1], n[2]));
  }
  return summary;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsDenoising
  \brief the same denoising on the vertices of a mesh (a `Surface_mesh`, a `Polyhedron_3` or any
  `FaceListGraph`): the vertices move in place through `vertex_point_map`, the faces are kept.
  Input normals come from `vertex_normal_map` or else
  `Polygon_mesh_processing::compute_vertex_normals()`; vertices at one position are merged for the
  computation and move together; vertices without a face or with an undefined normal stay where they are.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag` (OpenMP)
  \tparam PolygonMesh a model of `FaceListGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3` ...)
  \tparam NamedParameters a sequence of named parameters
  \param mesh the mesh whose vertices are denoised
  \param np the named parameters of the point range overload but `point_map`, `normal_map` and
    `neighborhoods`, and `vertex_point_map` (a `ReadWritePropertyMap`), `vertex_index_map` and
    `vertex_normal_map` (the input normals), as in `filter_normals()`

  \pre at least 13 vertices with a defined normal; otherwise `std::invalid_argument`
  \return what was done, with `Point_set_denoising_summary::mesh` set
*/
template <typename ConcurrencyTag, typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Point_set_denoising_summary
#else
std::enable_if_t<!internal::is_range<PolygonMesh>::value, Point_set_denoising_summary>
#endif
denoise_point_set(PolygonMesh& mesh, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto mesh_points = internal::mesh_points(mesh, np);
  const internal::Denoising_settings settings = internal::denoising_settings(np);
  Point_set_denoising_summary summary = internal::denoise_all<ConcurrencyTag>(mesh_points.input, nullptr, settings);
  summary.mesh = mesh_points.summary;
  auto vertex_points = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
  typedef typename boost::property_traits<decltype(vertex_points)>::value_type Point;
  std::size_t t = 0;
  for(auto vertex : vertices(mesh))
  {
    const std::uint32_t i = mesh_points.point_in_vertex_order[t++];
    if(i != internal::NO_POINT)
    {
      const internal::Double_point& p = mesh_points.input.points[i];
      put(vertex_points, vertex, Point(p.x(), p.y(), p.z()));
    }
  }
  return summary;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_DENOISE_POINT_SET_H
