// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_H

#include <CGAL/Sigmoid_neighborhoods/Optimal_sigmoid_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/vector_instructions.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Local_neighborhood.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_lists.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Symmetric_eigenvalues_3.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Vector_lanes.h>
#include <CGAL/Sigmoid_neighborhoods/internal/approximate_cosine.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>
#include <CGAL/Sigmoid_neighborhoods/internal/tie_rule.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

namespace internal {

// An approximation of E_dim is within its own margin of the exact value (see approximation_margin()),
// at most this one.
constexpr double LARGEST_APPROXIMATION_MARGIN = 1e-4;
// The rounding of one evaluation of E_dim, far above its few ulps of ln 3.
constexpr double ENTROPY_ROUNDING = 1e-12;
// Below this trace (at unit scale), the exact path's covariance nears the subnormal numbers and
// loses the accuracy that the margins assume.
constexpr double SMALLEST_TRUSTED_TRACE = 1e-280;
// An approximation is not trusted where the moments cancel by more than a factor 1 / this: the
// rounding of the two paths then exceeds what the margins assume.
constexpr double LARGEST_CANCELLATION = 1e-3;
// Nor where lambda1 - lambda3 is below this share of lambda1: three nearly equal eigenvalues, where
// the closed form's error bound degrades.
constexpr double SMALLEST_EIGENVALUE_SPREAD = 1e-3;
// Nor where the approximate weights move the eigenvalues by more than this share of lambda1.
constexpr double LARGEST_WEIGHT_NOISE = 1e-9;
// The rounding of the covariance from moments and of the exact two-pass covariance, relative to
// what cancelled: 100 eps, rounded up.
constexpr double COVARIANCE_ROUNDING = 1e-13;
// A trace below this share of s0 r^2, near the degenerate threshold, is decided by the exact path.
constexpr double DEGENERATE_TRACE_MARGIN = 1e-6;

// The search of SPEC §5 at every point: every (a, b, k) of the grid evaluated from the neighborhood
// N_i(k_max) it is handed (for_each_neighborhood()), with the result of the plain loop bit for bit.
// Two things save time:
// - pairs whose weights agree on N_i(k) share the exact result of the first of them (the same
//   inputs through the same code give the same bits);
// - every triple first gets a cheap approximate error (weights from a polynomial cosine, moments
//   accumulated over k, closed-form eigenvalues) and a margin within which it is exact; each
//   comparison of the scan is decided from these bounds when they decide it, and from exact errors
//   (exact weights, two-pass covariance, iterative eigen solver) only where the bounds of the
//   triple and of the best so far overlap. Every comparison thus has the plain loop's outcome, and
//   so have the visiting order and the tie rule.
class Optimal_search
{
public:
  struct Scratch
  {
    const Local_neighborhood* local = nullptr; // of the point being searched
    std::vector<double> arguments; // pair-major, weight_stride() per pair: Cosine_sigmoid::transition_argument()
    std::vector<double> weights;   // pair-major, weight_stride() per pair: exact, where has_weights says so
    std::vector<unsigned char> has_weights;
    std::vector<double> approximate_weights; // of the pair being prepared, weight_stride()
    std::vector<double> band_arguments;      // its arguments in the transition band, weight_stride()
    std::vector<std::uint32_t> band_indices; // and their neighbors, weight_stride()
    std::vector<double> approx;  // pair-major, one per k; NaN: not trusted, NOT_EVALUATED: see shares
    std::vector<double> margins; // pair-major, one per k: of approx, once it is evaluated
    // pair-major, one per k: the approximate shares whose entropy is the criterion, (L, P, S) or
    // lambda_i / sum, and the covariance's noise / lambda1
    std::vector<std::array<double, 4>> shares;
    std::vector<Dimensionality_features> exact; // pair-major, one per k, where `computed` says so
    std::vector<unsigned char> computed;
    std::vector<double> columns;              // see approximate_shares()
    Eigen::Matrix<double, 10, Eigen::Dynamic> moments; // per neighbor: 1, q, q q^T (see point_columns())
    std::vector<std::size_t> shared, source; // per pair: prefix shared with an earlier pair
    std::size_t first_all_ones = 0; // the first pair with all weights 1 not repeating an earlier one
  };

  explicit Optimal_search(const Search_settings& settings)
    : m_settings(settings), m_sigmoids(settings.sigmoids())
  {
    for(std::size_t p = 0; p < m_sigmoids.size(); ++p)
      if(m_sigmoids[p].is_equal_weights())
        m_equal_pair = static_cast<int>(p);
  }

  // false when every pair has equal weights (a = b = pi): no angle is needed
  bool needs_angles() const { return m_equal_pair < 0 || m_sigmoids.size() > 1; }

  Scratch make_scratch() const
  {
    Scratch s;
    s.arguments.resize(m_sigmoids.size() * weight_stride(), Cosine_sigmoid::WEIGHT_ZERO);
    s.weights.resize(m_sigmoids.size() * weight_stride());
    s.has_weights.resize(m_sigmoids.size());
    s.approximate_weights.resize(weight_stride());
    s.band_arguments.resize(weight_stride());
    s.band_indices.resize(weight_stride());
    s.approx.resize(m_sigmoids.size() * m_settings.number_of_sizes());
    s.shares.resize(m_sigmoids.size() * m_settings.number_of_sizes());
    s.margins.resize(m_sigmoids.size() * m_settings.number_of_sizes());
    s.exact.resize(m_sigmoids.size() * m_settings.number_of_sizes());
    s.computed.resize(m_sigmoids.size() * m_settings.number_of_sizes());
    s.columns.resize(NUMBER_OF_COLUMNS * column_stride());
    s.shared.resize(m_sigmoids.size());
    s.source.resize(m_sigmoids.size());
    return s;
  }

  // The search on N_i(k_max), `local`, which must outlive the call.
  Optimal_sigmoid_neighborhood operator()(const Local_neighborhood& local, Scratch& s) const
  {
    const unsigned int k_min = m_settings.k_min, k_max = m_settings.k_max;
    const std::size_t pairs = m_sigmoids.size();
    s.local = &local;
    point_columns(s);
    std::fill(s.computed.begin(), s.computed.end(), 0);
    s.first_all_ones = pairs;

    // The scan of SPEC §5, exact wherever it matters, one pair at a time. Skipped triples:
    // - those whose weights on N_i(k) repeat an earlier pair's: that triple, with the same error E,
    //   was visited, so best <= E + tol since, and the triple cannot improve;
    // - with the weighted barycenter, (p, k) where the k-th neighbor has weight 0: its covariance
    //   is (p, k - 1)'s bit for bit (zero weights are skipped), so its error is (p, k - 1)'s, or
    //   +inf where the larger radius makes it degenerate; neither can improve once (p, k - 1) is visited;
    // - every triple once the best error is at most tol: no error, being >= 0, can be below best - tol.
    Running_minimum best;
    std::size_t prepared = 0; // pairs [0, prepared) have their weights, shares and approximations
    for(; prepared < pairs && best.high > TIE_TOLERANCE; ++prepared)
    {
      const std::size_t p = prepared;
      prepare(s, p, p);
      const double* t = &s.arguments[p * weight_stride()];
      for(unsigned int k = (std::max)(k_min, unsigned(std::min<std::size_t>(s.shared[p], k_max + 1))); k <= k_max; ++k)
        if(!repeats_smaller_size(t, k))
          visit(s, p, k, best);
    }

    Optimal_sigmoid_neighborhood result;
    result.criterion = m_settings.criterion;
    if(best.k != 0)
    {
      result.a = m_sigmoids[best.pair].a();
      result.b = m_sigmoids[best.pair].b();
      result.k = best.k;
      result.features = exact_features(s, best.pair, best.k);
    }

    // Equal weights, best k with the same tie rule.
    if(m_equal_pair >= 0 && pairs == 1)
    {
      // the scan above was that search
      result.error_equal = result.error();
      result.k_equal = result.k;
    }
    else if(m_equal_pair >= 0)
    {
      if(std::size_t(m_equal_pair) >= prepared)
        prepare(s, std::size_t(m_equal_pair), prepared);
      Running_minimum equal;
      for(unsigned int k = k_min; k <= k_max; ++k)
        visit(s, std::size_t(m_equal_pair), k, equal);
      if(equal.k != 0)
      {
        result.error_equal = exact_value(s, equal);
        result.k_equal = equal.k;
      }
    }
    else
    {
      const std::vector<double> ones(k_max + 1, 1.);
      const Local_neighborhood::Best_size equal =
        local.best_size(ones.data(), k_min, k_max, m_settings.barycenter, m_settings.criterion);
      result.error_equal = equal.error;
      result.k_equal = equal.k;
    }
    return result;
  }

private:
  // The best triple so far of a scan: its error is known to lie in [low, high], and is exact once
  // low == high (SPEC §5's comparisons need it only when the bounds cannot decide them).
  struct Running_minimum
  {
    double low = std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
    std::size_t pair = 0;
    unsigned int k = 0; // 0: none yet
    // Shares (L, P, S), or e_i, whose sum of squares is at most this cannot improve on [low, high]:
    // Shannon's entropy is at least Renyi's of order 2, E >= -ln(L^2 + P^2 + S^2), so such a triple would be
    // dismissed by the first test of visit() anyway; the logarithms of E are not needed for it.
    double hopeless_squares = 0.;

    void set(double new_low, double new_high)
    {
      low = new_low;
      high = new_high;
      // E~ - M >= high - tol follows from -ln(squares) >= high - tol + M (+ 1e-12 for rounding)
      hopeless_squares = std::exp(-(high - TIE_TOLERANCE + LARGEST_APPROXIMATION_MARGIN + ENTROPY_ROUNDING));
    }
  };

  static constexpr double NOT_EVALUATED = -1.;

  // The weights' arguments of pair p, the earlier pair among [0, candidates) sharing the longest
  // prefix of arguments (hence of weights) with it, and approximations for the sizes it does not
  // share. Its exact weights are computed when an exact value needs them. (Different arguments may
  // still give equal weights, 1 near t = 0 for instance; such pairs are merely not recognised as
  // repeats, and visiting a repeat never changes the outcome of the scan.)
  void prepare(Scratch& s, std::size_t p, std::size_t candidates) const
  {
    const std::size_t m = m_settings.k_max + 1, none = m_sigmoids.size();
    double* t = &s.arguments[p * weight_stride()];
    const bool all_ones = s.local->transition_arguments(m_sigmoids[p], t);
    s.has_weights[p] = 0;
    s.shared[p] = 0;
    s.source[p] = p;
    if(all_ones && s.first_all_ones != none)
    {
      // what the search below finds, without comparing
      s.shared[p] = m;
      s.source[p] = s.first_all_ones;
      return;
    }
    for(std::size_t q = 0; q < candidates && s.shared[p] < m; ++q)
    {
      if(s.shared[q] == m)
        continue; // q repeats an earlier pair entirely: that one is compared instead
      const double* v = &s.arguments[q * weight_stride()];
      std::size_t l = 0;
      while(l < m && v[l] == t[l])
        ++l;
      if(l > s.shared[p])
      {
        s.shared[p] = l;
        s.source[p] = q;
      }
    }
    if(all_ones)
      s.first_all_ones = s.shared[p] < m ? p : s.source[p];
    if(s.shared[p] < m)
      approximate_shares(s, t, s.shared[p], p * m_settings.number_of_sizes());
  }

  // (p, k) with a zero weight on the k-th neighbor repeats (p, k - 1) (see operator()); `t` holds
  // the weights' arguments. (A weight in the transition band that rounds to 0 is not recognised.)
  bool repeats_smaller_size(const double* t, unsigned int k) const
  {
    return m_settings.barycenter == Barycenter::WEIGHTED && k > m_settings.k_min &&
           t[k] == Cosine_sigmoid::WEIGHT_ZERO;
  }

  // The margin of an approximate criterion value, from its shares x (see approximate_shares()) and
  // the covariance's noise relative to lambda1. Its eigenvalues are within noise * lambda1 of the
  // exact path's: the closed form's error, and the covariance's. Each share moves by at most delta:
  // - E_dim: delta = 3 noise (a difference of two eigenvalues over lambda1, and lambda1's own error);
  // - eigenentropy: e_i = lambda_i / T with T the sum, T >= lambda1 and moved by 3 noise lambda1, so
  //   e_i moves by at most (noise + 3 noise e_i) lambda1 / T <= 4 noise / (1 - noise): delta = 5 noise;
  // and -x ln x by at most delta (1 + ln(1 / delta)) (its modulus of continuity on [0, 1] is
  // -delta ln delta), plus 1e-12 for the rounding of E itself. Noise is at most 2.02e-7 (2e-7 from
  // the closed form, at most 1.3e-9 from the covariance where it is trusted), so the margin is at
  // most 4.5e-5, below LARGEST_APPROXIMATION_MARGIN.
  double approximation_margin(const std::array<double, 4>& x) const
  {
    // the gaps lambda1 - lambda2 and lambda2 - lambda3, relative to lambda1: L and P, or from the e_i
    const bool dimensionality = m_settings.criterion == Neighborhood_criterion::DIMENSIONALITY;
    const double relative_gap = dimensionality ? (std::min)(x[0], x[1]) : (std::min)(x[0] - x[1], x[1] - x[2]) / x[0];
    const double noise = closed_form_relative_error(relative_gap) + x[3];
    const double delta = (dimensionality ? 3. : 5.) * noise;
    // ln(1 / delta) <= -e ln 2 for delta >= 2^e: no logarithm needed
    return 3. * delta * (1. - std::ilogb(delta) * 0.6931471805599454) + ENTROPY_ROUNDING;
  }

  double exact_value(Scratch& s, Running_minimum& best) const
  {
    if(best.low != best.high)
    {
      const double exact = exact_error(s, best.pair, best.k);
      best.set(exact, exact);
    }
    return best.low;
  }

  // The pair whose slots hold the results of (p, k): the earliest one with the same weights on N_i(k).
  std::size_t owner(const Scratch& s, std::size_t p, unsigned int k) const
  {
    while(s.source[p] != p && std::size_t(k) + 1 <= s.shared[p])
      p = s.source[p];
    return p;
  }

  // One step of the plain loop, `if(E < best - TIE_TOLERANCE) best = E`, decided from the
  // approximation's bounds [approx - margin, approx + margin] whenever they decide it (rounding of
  // `x - TIE_TOLERANCE` is monotone in x, so bounds on both sides bound the comparison), and from
  // exact errors otherwise. The outcome is the plain loop's, with far fewer exact solves.
  void visit(Scratch& s, std::size_t p, unsigned int k, Running_minimum& best) const
  {
    const std::size_t slot = owner(s, p, k) * m_settings.number_of_sizes() + (k - m_settings.k_min);
    double& approx = s.approx[slot];
    if(approx == NOT_EVALUATED)
    {
      const std::array<double, 4>& x = s.shares[slot];
      if(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] <= best.hopeless_squares)
        return;
      approx = dimensionality_error(x[0], x[1], x[2]); // the entropy of the shares, whichever criterion
      s.margins[slot] = approximation_margin(x);
    }
    // E >= 0: every entropy term is -x ln x with x in [0, 1]
    const double margin = s.margins[slot];
    double low = (std::max)(approx - margin, 0.), high = approx + margin;
    if(std::isnan(approx)) // not trusted
      low = high = exact_error(s, p, k);
    if(low >= best.high - TIE_TOLERANCE)
      return; // E >= low >= best.high - tol >= best - tol: no improvement (nor for E = +inf)
    if(!(high < best.low - TIE_TOLERANCE))
    {
      // the bounds overlap: compare exact values
      if(low != high)
        low = high = exact_error(s, p, k);
      if(!(low < exact_value(s, best) - TIE_TOLERANCE))
        return;
    }
    best.set(low, high);
    best.pair = p;
    best.k = k;
  }

  // The exact features of (pair p, k), computed once for all pairs that share the weights of
  // N_i(k): the same inputs through the same code give the same bits.
  const Dimensionality_features& exact_features(Scratch& s, std::size_t p, unsigned int k) const
  {
    p = owner(s, p, k);
    const std::size_t slot = p * m_settings.number_of_sizes() + (k - m_settings.k_min);
    if(!s.computed[slot])
    {
      double* w = &s.weights[p * weight_stride()];
      if(!s.has_weights[p])
      {
        // the sigmoid's weights, bit for bit: Cosine_sigmoid::operator() is weight_of_argument() of
        // these arguments (Local_neighborhood::weights() gives the same from the cosines)
        const double* t = &s.arguments[p * weight_stride()];
        for(std::size_t j = 0; j <= m_settings.k_max; ++j)
          w[j] = Cosine_sigmoid::weight_of_argument(t[j]);
        s.has_weights[p] = 1;
      }
      s.exact[slot] = s.local->features(w, k, m_settings.barycenter);
      s.computed[slot] = 1;
    }
    return s.exact[slot];
  }

  double exact_error(Scratch& s, std::size_t p, unsigned int k) const
  {
    return criterion_value(exact_features(s, p, k), m_settings.criterion);
  }

  // Approximate (L, P, S) for every k, from weights within APPROXIMATE_WEIGHT_ERROR of the exact
  // ones (`t` holds their arguments), moments accumulated over the neighbors (one pass) and
  // closed-form eigenvalues, with the noise from which visit() derives the margin of E_dim; E_dim
  // itself is evaluated only where a comparison needs it. The approximation is marked NaN (not
  // trusted: the exact path decides) close to the degenerate threshold, where the moments cancel
  // (by more than a factor 1000), near the extremes of the floating-point range, and where all
  // three eigenvalues nearly coincide.
  // Sizes k with k + 1 <= shared are left alone: an earlier pair with the same weights has them;
  // so are the sizes that repeat a smaller one.
  // The prefix sums are taken in one pass; everything after them is independent from one k to the
  // next, solved in batches that Eigen vectorizes.
  void approximate_shares(Scratch& s, const double* t, std::size_t shared, std::size_t first_slot) const
  {
    const Local_neighborhood& local = *s.local;
    const unsigned int k_min = m_settings.k_min, k_max = m_settings.k_max;
    const unsigned int k_first = (std::max)(k_min, unsigned(shared));
    const std::size_t sizes = m_settings.number_of_sizes();
    const bool weighted = m_settings.barycenter == Barycenter::WEIGHTED;
    double* approx = &s.approx[first_slot];
    std::array<double, 4>* shares = &s.shares[first_slot];
    double* margins = &s.margins[first_slot];

    // The weights, without branches: 1 or 0 outside the transition band, a batch at a time (the
    // arguments are padded to a whole batch); in the band the cosine, clamped to [0, 1] where the
    // exact weights lie (so that no rounding makes one negative), on the band's arguments gathered
    // into whole batches: a rough surface has a few per pair, and the cosine is the costly part.
    // (t + 2) clamped to [0, 1] is 1 for WEIGHT_ONE (-1), 0 for WEIGHT_ZERO (-2), and is replaced
    // in the band: min and max vectorize, Eigen 3.4's select on a comparison does not.
    static_assert(Cosine_sigmoid::WEIGHT_ONE == -1. && Cosine_sigmoid::WEIGHT_ZERO == -2., "the clamp below");
    double* const w = s.approximate_weights.data();
    for(std::size_t j = 0; j < weight_stride(); j += Batch::SizeAtCompileTime)
      Eigen::Map<Batch>(w + j) = (Eigen::Map<const Batch>(t + j) + 2.).min(1.).max(0.);
    double* const band_arguments = s.band_arguments.data();
    std::uint32_t* const band_indices = s.band_indices.data();
    std::size_t band_size = 0;
    for(unsigned int j = 0; j <= k_max; ++j)
    {
      band_arguments[band_size] = t[j];
      band_indices[band_size] = j;
      band_size += t[j] >= 0. ? 1 : 0;
    }
    for(std::size_t b = 0; b < band_size; b += Batch::SizeAtCompileTime)
    {
      // the batch's entries past band_size are computed and never read
      const Batch weight =
        (0.5 * approximate_cosine<Batch>(Eigen::Map<const Batch>(band_arguments + b)) + 0.5).max(0.).min(1.);
      for(std::size_t l = b; l < (std::min)(band_size, b + Batch::SizeAtCompileTime); ++l)
        w[band_indices[l]] = weight[Eigen::Index(l - b)];
    }

    // Per k: sums of w, w q and w q q^T over N_i(k) (see point_columns()).
    const std::size_t stride = column_stride();
    double* const columns = s.columns.data();
    auto column = [&](Column i) { return columns + i * stride; };
    {
      Moments sums = Moments::Zero();
      double transition_size = 0.; // neighbors in the transition band, whose weights are approximate
      for(unsigned int j = 0; j <= k_max; ++j)
      {
        transition_size += t[j] >= 0. ? 1. : 0.;
        sums += w[j] * s.moments.col(j).array();
        if(j < k_first)
          continue;
        const std::size_t c = j - k_min;
        for(int i = 0; i < NUMBER_OF_MOMENTS; ++i)
          column(Column(i))[c] = sums[i];
        column(TRANSITION_SIZE)[c] = transition_size;
      }
    }

    // The sizes that need no eigenvalues: the point alone, or a repeat of the smaller size.
    std::size_t first_solved = sizes, end_solved = 0;
    bool others = false; // a neighbor other than the point itself has weight
    for(unsigned int k = 1; k < k_first; ++k)
      others = others || t[k] != Cosine_sigmoid::WEIGHT_ZERO;
    for(unsigned int k = k_first; k <= k_max; ++k)
    {
      others = others || t[k] != Cosine_sigmoid::WEIGHT_ZERO;
      const std::size_t c = k - k_min;
      if(weighted && !others)
      {
        approx[c] = std::numeric_limits<double>::infinity(); // the point alone: C = 0 exactly, degenerate
        margins[c] = 0.;
      }
      else if(repeats_smaller_size(t, k))
        approx[c] = std::numeric_limits<double>::quiet_NaN(); // never visited; exact if it were
      else
      {
        approx[c] = NOT_EVALUATED;
        first_solved = (std::min)(first_solved, c);
        end_solved = c + 1;
      }
    }
    if(first_solved >= end_solved)
      return;

    if(weighted)
      approximate_eigenvalues<true>(m_settings.instructions, columns, stride, first_solved, end_solved);
    else
      approximate_eigenvalues<false>(m_settings.instructions, columns, stride, first_solved, end_solved);

    // Below this, the exact path's covariance, at the input's scale, nears the subnormal numbers
    // and loses the accuracy that the margins assume.
    const double smallest_trace = SMALLEST_TRUSTED_TRACE * local.unit_scale() * local.unit_scale();
    for(std::size_t c = first_solved; c < end_solved; ++c)
    {
      if(approx[c] != NOT_EVALUATED)
        continue;
      const double l1 = column(L1)[c], l2 = column(L2)[c], l3 = column(L3)[c], trace = column(TRACE)[c];
      // The covariance's noise: the rounding of the moments here and of the two passes of the exact
      // path, below 100 eps times what cancelled (at most 1e3 trace where trusted, so at most 3e-10
      // l1), and the weights' error: APPROXIMATE_WEIGHT_ERROR on each neighbor of the transition
      // band moves C by that times |q_j - c|^2 <= 4 r^2 (the first-order change of C with w_j is
      // (q_j - c)(q_j - c)^T, the barycenter's own change cancelling), and the eigenvalues by as
      // much (Weyl); at most 1e-9 l1 where trusted.
      const double weight_noise = 4. * APPROXIMATE_WEIGHT_ERROR * column(TRANSITION_SIZE)[c] * column(RADIUS)[c];
      if(!(column(TRACE_MARGIN)[c] > 0.) || !(trace > smallest_trace) || !has_unscaled_eigenvalues(trace) ||
         !(l1 > 0.) || l1 - l3 < SMALLEST_EIGENVALUE_SPREAD * l1 || weight_noise > LARGEST_WEIGHT_NOISE * l1)
      {
        approx[c] = std::numeric_limits<double>::quiet_NaN(); // not trusted
        continue;
      }
      const double inverse = 1. / l1, noise = (COVARIANCE_ROUNDING * column(CANCELLATION)[c] + weight_noise) * inverse;
      if(m_settings.criterion == Neighborhood_criterion::DIMENSIONALITY)
        shares[c] = {{(l1 - l2) * inverse, (l2 - l3) * inverse, l3 * inverse, noise}};
      else
      {
        const double inverse_sum = 1. / (l1 + l2 + l3);
        shares[c] = {{l1 * inverse_sum, l2 * inverse_sum, l3 * inverse_sum, noise}};
      }
    }
  }

  // Columns of approximate_shares(), each of stride column_stride(): weighted moments of the pair
  // in the order of point_columns()' moments, what does not depend on the pair, then results.
  enum Column { S0, SX, SY, SZ, SXX, SYX, SZX, SYY, SZY, SZZ, NUMBER_OF_MOMENTS = 10, // prefix sums
                UX = NUMBER_OF_MOMENTS, UY, UZ, RADIUS, TRANSITION_SIZE,
                L1, L2, L3, TRACE, TRACE_MARGIN, CANCELLATION, NUMBER_OF_COLUMNS };    // results
  typedef Eigen::Array<double, NUMBER_OF_MOMENTS, 1> Moments;

  // What approximate_shares() needs of the neighborhood whatever the pair: the moments
  // (1, q, q q^T) of every unit offset q (lower triangle, in the order of Column), and per k the
  // unweighted barycenter and the squared radius, all in unit offsets: at that scale the closed
  // form neither overflows nor underflows.
  void point_columns(Scratch& s) const
  {
    const Local_neighborhood& local = *s.local;
    static_assert(int(decltype(s.moments)::RowsAtCompileTime) == int(NUMBER_OF_MOMENTS), "one row per moment");
    const unsigned int k_min = m_settings.k_min, k_max = m_settings.k_max;
    s.moments.resize(NUMBER_OF_MOMENTS, k_max + 1);
    double* const columns = s.columns.data();
    auto column = [&](Column i) { return columns + i * column_stride(); };
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for(unsigned int j = 0; j <= k_max; ++j)
    {
      const Eigen::Vector3d& q = local.unit_offset(j);
      s.moments.col(j) << 1., q[0], q[1], q[2], q[0] * q[0], q[1] * q[0], q[2] * q[0], q[1] * q[1], q[2] * q[1],
        q[2] * q[2];
      sum += q;
      if(j < k_min)
        continue;
      const std::size_t c = j - k_min;
      column(RADIUS)[c] = local.unit_squared_radius(j);
      if(m_settings.barycenter == Barycenter::WEIGHTED)
        continue; // the barycenters are the pair's
      const double inverse_size = 1. / double(j + 1);
      column(UX)[c] = sum[0] * inverse_size;
      column(UY)[c] = sum[1] * inverse_size;
      column(UZ)[c] = sum[2] * inverse_size;
    }
  }

  typedef Eigen::Array<double, 8, 1> Batch; // k per batch: an AVX-512 register, or several narrower ones

  std::size_t column_stride() const { return m_settings.number_of_sizes() + Batch::SizeAtCompileTime; }

  // N_i(k_max) rounded up to whole batches
  std::size_t weight_stride() const
  {
    const std::size_t b = Batch::SizeAtCompileTime;
    return (m_settings.k_max + 1 + b - 1) / b * b;
  }

  // The second half of approximate_shares(): columns [first, end) of the prefix sums to
  // eigenvalues, in batches of sizes k solved together (the last batch reads and writes past `end`,
  // within the stride, where nothing is used), on the vector instructions `instructions`.
  template <bool Weighted>
  static void approximate_eigenvalues(Vector_instructions instructions, double* columns, std::size_t stride,
                                      std::size_t first, std::size_t end)
  {
#ifdef CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_DISPATCH
    switch(instructions)
    {
    case Vector_instructions::AVX512:
      return approximate_eigenvalues_avx512<Weighted>(columns, stride, first, end);
    case Vector_instructions::AVX2:
      return approximate_eigenvalues_avx2<Weighted>(columns, stride, first, end);
    default:
      break;
    }
#else
    (void)instructions;
#endif
    approximate_eigenvalues_of<Batch, Weighted>(columns, stride, first, end);
  }

#ifdef CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_DISPATCH
  // The same source compiled for wider registers: `flatten` inlines the generic code into the
  // target's instructions, `fp-contract=off` keeps every product and sum separately rounded, as
  // on the portable path (AVX-512F has multiply-adds of its own).
  template <bool Weighted>
  __attribute__((target("avx2"), optimize("fp-contract=off"), flatten)) static void
  approximate_eigenvalues_avx2(double* columns, std::size_t stride, std::size_t first, std::size_t end)
  {
    approximate_eigenvalues_of<Lanes4, Weighted>(columns, stride, first, end);
  }
  template <bool Weighted>
  __attribute__((target("avx512f"), optimize("fp-contract=off"), flatten)) static void
  approximate_eigenvalues_avx512(double* columns, std::size_t stride, std::size_t first, std::size_t end)
  {
    approximate_eigenvalues_of<Lanes8, Weighted>(columns, stride, first, end);
  }
#endif

  static Batch load_lanes_of(const double* p, const Batch*) { return Eigen::Map<const Batch>(p); }
  static void store_lanes_of(double* p, const Batch& v)
  {
    Eigen::Map<Batch> target(p);
    target = v;
  }
#ifdef CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_DISPATCH
  template <typename V>
  static If_lanes<V> load_lanes_of(const double* p, const V*) { return load_lanes<V>(p); }
  template <typename V>
  static void store_lanes_of(double* p, const V& v) { store_lanes(p, v); }
#endif
  template <typename T>
  static constexpr int lanes_of(const T*) { return int(T::SizeAtCompileTime); }
#ifdef CGAL_SIGMOID_NEIGHBORHOODS_VECTOR_DISPATCH
  static constexpr int lanes_of(const Lanes4*) { return 4; }
  static constexpr int lanes_of(const Lanes8*) { return 8; }
#endif

  // T: Batch (Eigen's packets) or lanes of Vector_lanes.h; the same operations in the same order.
  template <typename T, bool Weighted>
  static void approximate_eigenvalues_of(double* columns, std::size_t stride, std::size_t first, std::size_t end)
  {
    constexpr int lanes = lanes_of(static_cast<const T*>(nullptr));
    static_assert(lanes <= Batch::SizeAtCompileTime, "the columns are padded by one Batch");
    for(std::size_t c = first; c < end; c += lanes)
    {
      auto load = [&](Column i) { return load_lanes_of(columns + i * stride + c, static_cast<const T*>(nullptr)); };
      auto store = [&](Column i, const T& v) { store_lanes_of(columns + i * stride + c, v); };
      const T s0 = load(S0), sx = load(SX), sy = load(SY), sz = load(SZ);
      // C = S2 - c S1^T - S1 c^T + S0 c c^T, with c the barycenter
      T cx, cy, cz;
      if(Weighted)
      {
        const T inverse_weight = T(1. / s0); // s0 >= w_ii = 1
        cx = sx * inverse_weight;
        cy = sy * inverse_weight;
        cz = sz * inverse_weight;
      }
      else
      {
        cx = load(UX);
        cy = load(UY);
        cz = load(UZ);
      }
      const T sxx = load(SXX), syy = load(SYY), szz = load(SZZ);
      const T c00 = sxx - 2. * cx * sx + s0 * cx * cx;
      const T c11 = syy - 2. * cy * sy + s0 * cy * cy;
      const T c22 = szz - 2. * cz * sz + s0 * cz * cz;
      const T c10 = load(SYX) - cy * sx - cx * sy + s0 * cy * cx;
      const T c20 = load(SZX) - cz * sx - cx * sz + s0 * cz * cx;
      const T c21 = load(SZY) - cz * sy - cy * sz + s0 * cz * cy;
      const T trace = c00 + c11 + c22;
      // the size of the terms that cancelled: the rounding error of C is about 1e-16 of it
      const T cancelled = sxx + syy + szz + s0 * (cx * cx + cy * cy + cz * cz);
      store(TRACE, trace);
      store(TRACE_MARGIN, T(trace - elementwise_max(T(DEGENERATE_TRACE_MARGIN * s0 * load(RADIUS)),
                                                    T(LARGEST_CANCELLATION * cancelled))));
      T l1, l2, l3;
      unscaled_symmetric_eigenvalues_3<T>(c00, c10, c20, c11, c21, c22, l1, l2, l3);
      store(L1, l1);
      store(L2, elementwise_max(l2, 0.));
      store(L3, elementwise_max(l3, 0.));
      store(CANCELLATION, cancelled);
    }
  }

  Search_settings m_settings;
  std::vector<Cosine_sigmoid> m_sigmoids;
  int m_equal_pair = -1;
};

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_OPTIMAL_SEARCH_H
