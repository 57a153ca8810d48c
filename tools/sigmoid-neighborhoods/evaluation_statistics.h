// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's statistics of an evaluation (Tables 2, 3, Figures 4, 5): sums of the package's
// Point_evaluation records, merged exactly across shards.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_STATISTICS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_STATISTICS_H

#include <CGAL/Sigmoid_neighborhoods/Point_evaluation.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*
  mergeable statistics of `E_dim` under one weighting (SPEC §6): counts, sums, extremes, labels and
  the histogram of the chosen `k`. Two disjoint parts merge into exactly the statistics of the whole
  (counts, extremes, histograms); sums agree up to rounding, and exactly when merged in the same order.
*/
struct Error_statistics
{
  std::size_t count = 0;     ///< points with a finite error
  std::size_t failures = 0;  ///< points where the weighting is degenerate at every `k`
  /// the sum of the finite errors
  double sum = 0.;
  /// the sum of their squares
  double sum_of_squares = 0.;
  /// the least finite error, `+inf` when there is none
  double min = std::numeric_limits<double>::infinity();
  /// the largest finite error, `-inf` when there is none
  double max = -std::numeric_limits<double>::infinity();
  std::array<std::size_t, 3> labels{{0, 0, 0}}; ///< linear, planar, scattered
  std::vector<std::size_t> k_histogram;         ///< index `k - k_min`; empty for a fixed `k`

  /*
    adds one point: a failure when `error` is not finite, otherwise its error, its `label` and,
    when `k_histogram` is not empty, its `k` (counted at `k - k_min`).
  */
  void add(double error, Dimensionality label, unsigned int k, unsigned int k_min)
  {
    if(!std::isfinite(error))
    {
      ++failures;
      return;
    }
    ++count;
    sum += error;
    sum_of_squares += error * error;
    min = (std::min)(min, error);
    max = (std::max)(max, error);
    if(label != Dimensionality::DEGENERATE)
      ++labels[std::size_t(label)];
    if(!k_histogram.empty() && k >= k_min && k - k_min < k_histogram.size())
      ++k_histogram[k - k_min];
  }

  /*
    adds the statistics of disjoint points.
    \pre `other.k_histogram` has the size of `k_histogram`, otherwise `std::invalid_argument`
  */
  void merge(const Error_statistics& other)
  {
    count += other.count;
    failures += other.failures;
    sum += other.sum;
    sum_of_squares += other.sum_of_squares;
    min = (std::min)(min, other.min);
    max = (std::max)(max, other.max);
    for(std::size_t l = 0; l < 3; ++l)
      labels[l] += other.labels[l];
    if(k_histogram.size() != other.k_histogram.size())
      throw std::invalid_argument("cannot merge statistics of different k ranges");
    for(std::size_t i = 0; i < k_histogram.size(); ++i)
      k_histogram[i] += other.k_histogram[i];
  }

  /// the mean finite error, NaN when `count == 0`
  double mean() const { return count ? sum / double(count) : std::numeric_limits<double>::quiet_NaN(); }
  /// the population standard deviation of the finite errors, NaN when `count == 0`
  double standard_deviation() const
  {
    if(!count)
      return std::numeric_limits<double>::quiet_NaN();
    const double m = mean();
    return std::sqrt((std::max)(0., sum_of_squares / double(count) - m * m));
  }
};

/*
  mergeable statistics of a model or a repository under the weightings of the paper's Section 5:
  Table 2 (`E_dim` per weighting), Table 3 (lowering `a*`, `b*`), Figure 4 (`(a*, b*)` split by `k*`)
  and Figure 5 (`k*`).
*/
struct Evaluation_statistics
{
  /// \name Sizes and Grids
  /// The sizes `{k_min, ..., k_max}` and the grids of `a` and `b` (sorted, deduplicated) of the evaluation.
  /// @{

  /// the smallest and the largest `k`
  unsigned int k_min = 0, k_max = 0;
  /// the grids of `a` and of `b`
  std::vector<double> a_grid, b_grid;
  /// @}
  /// the points added, failures included
  std::size_t points = 0;
  Error_statistics equal;    ///< `a = b = pi`, best `k`
  Error_statistics cut_off;  ///< `a = b = cut_off_angle`, best `k`
  Error_statistics optimal;  ///< `(a*, b*, k*)`
  Error_statistics fixed_k;  ///< `a = b = pi` at a fixed `k`
  /// counts per `(a, b)` pair (a ascending, then b, pairs with `a <= b`) and `k`: `pair * sizes + k - k_min`
  std::vector<std::size_t> pair_k_histogram;
  std::array<std::size_t, 3> a_lowering{{0, 0, 0}}; ///< `a = 0`, `a-`, `not a-`
  std::array<std::size_t, 3> b_lowering{{0, 0, 0}}; ///< `b = a`, `b-`, `not b-`

  /// empty statistics without grids, to be assigned; only statistics with equal grids merge.
  Evaluation_statistics() = default;
  /*
    empty statistics of the evaluation with the sizes `{k_min_, ..., k_max_}` and the grids `a`, `b`
    (sorted and deduplicated here), as given to `evaluate_sigmoid_neighborhoods()`.
    \pre `k_min_ <= k_max_` (not checked)
  */
  Evaluation_statistics(unsigned int k_min_, unsigned int k_max_, std::vector<double> a, std::vector<double> b)
    : k_min(k_min_), k_max(k_max_), a_grid(std::move(a)), b_grid(std::move(b))
  {
    if(!(k_min >= 1 && k_min <= k_max))
      throw std::invalid_argument("Evaluation_statistics: needs 1 <= k_min <= k_max");
    std::sort(a_grid.begin(), a_grid.end());
    a_grid.erase(std::unique(a_grid.begin(), a_grid.end()), a_grid.end());
    std::sort(b_grid.begin(), b_grid.end());
    b_grid.erase(std::unique(b_grid.begin(), b_grid.end()), b_grid.end());
    const std::size_t sizes = k_max - k_min + 1;
    equal.k_histogram.assign(sizes, 0);
    cut_off.k_histogram.assign(sizes, 0);
    optimal.k_histogram.assign(sizes, 0);
    pair_k_histogram.assign(pairs().size() * sizes, 0);
  }

  /// the `(a, b)` pairs in the order of `pair_k_histogram`
  std::vector<std::pair<double, double>> pairs() const
  {
    std::vector<std::pair<double, double>> result;
    for(double a : a_grid)
      for(double b : b_grid)
        if(a <= b)
          result.emplace_back(a, b);
    return result;
  }

  /// adds the record of one point, as `evaluate_sigmoid_neighborhoods()` writes it.
  void add(const Point_evaluation& e)
  {
    ++points;
    const Optimal_sigmoid_neighborhood& o = e.optimal;
    equal.add(o.error_equal, e.equal_label, o.k_equal, k_min);
    cut_off.add(e.error_cut_off, e.cut_off_label, e.k_cut_off, k_min);
    optimal.add(o.error(), o.features.label, o.k, k_min);
    fixed_k.add(e.error_fixed_k, e.fixed_k_label, 0, k_min);
    if(o.is_failure())
      return;
    const auto all = pairs();
    const auto it = std::find(all.begin(), all.end(), std::make_pair(o.a, o.b));
    if(it != all.end())
      ++pair_k_histogram[std::size_t(it - all.begin()) * (k_max - k_min + 1) + (o.k - k_min)];
    ++a_lowering[std::size_t(e.a_lowering)];
    ++b_lowering[std::size_t(e.b_lowering)];
  }

  /*
    adds the statistics of disjoint points (another shard, model or repository).
    \pre equal `k_min`, `k_max`, `a_grid` and `b_grid`, otherwise `std::invalid_argument`
  */
  void merge(const Evaluation_statistics& other)
  {
    if(other.k_min != k_min || other.k_max != k_max || other.a_grid != a_grid || other.b_grid != b_grid)
      throw std::invalid_argument("cannot merge statistics of different grids or k ranges");
    points += other.points;
    equal.merge(other.equal);
    cut_off.merge(other.cut_off);
    optimal.merge(other.optimal);
    fixed_k.merge(other.fixed_k);
    for(std::size_t i = 0; i < pair_k_histogram.size(); ++i)
      pair_k_histogram[i] += other.pair_k_histogram[i];
    for(std::size_t i = 0; i < 3; ++i)
    {
      a_lowering[i] += other.a_lowering[i];
      b_lowering[i] += other.b_lowering[i];
    }
  }

  /// mean and population standard deviation of `k*` over the points with an optimum
  std::pair<double, double> k_mean_and_deviation() const
  {
    double n = 0., s = 0., q = 0.;
    for(std::size_t i = 0; i < optimal.k_histogram.size(); ++i)
    {
      const double k = double(k_min + i), c = double(optimal.k_histogram[i]);
      n += c;
      s += c * k;
      q += c * k * k;
    }
    if(n == 0.)
      return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    const double m = s / n;
    return {m, std::sqrt((std::max)(0., q / n - m * m))};
  }
};

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EVALUATION_STATISTICS_H
