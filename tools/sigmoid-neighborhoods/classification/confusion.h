// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The confusion matrix of a classification against its ground truth and the scores read from it.
// (CGAL 5.5's Evaluation::confusion(ground_truth, result) returns the transposed count, so the
// matrix is counted here, rows the truth, columns the prediction.)

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CONFUSION_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CONFUSION_H

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sigmoid_tool {

class Confusion
{
public:
  explicit Confusion(std::size_t classes) : m_classes(classes), m_counts(classes * classes, 0) {}

  // a point of class `truth` predicted as `predicted`; points with a negative truth are not counted
  void add(int truth, int predicted)
  {
    if(truth < 0)
      return;
    if(std::size_t(truth) >= m_classes || predicted < 0 || std::size_t(predicted) >= m_classes)
      throw std::logic_error("class index out of range");
    ++m_counts[std::size_t(truth) * m_classes + std::size_t(predicted)];
  }

  void merge(const Confusion& other)
  {
    for(std::size_t i = 0; i < m_counts.size(); ++i)
      m_counts[i] += other.m_counts[i];
  }

  std::size_t classes() const { return m_classes; }
  std::uint64_t count(std::size_t truth, std::size_t predicted) const { return m_counts[truth * m_classes + predicted]; }

  std::uint64_t total() const
  {
    std::uint64_t t = 0;
    for(std::uint64_t c : m_counts)
      t += c;
    return t;
  }
  std::uint64_t true_count(std::size_t c) const { return sum_row(c); }
  std::uint64_t predicted_count(std::size_t c) const
  {
    std::uint64_t s = 0;
    for(std::size_t t = 0; t < m_classes; ++t)
      s += count(t, c);
    return s;
  }

  // NaN where undefined (a class never predicted has no precision)
  double precision(std::size_t c) const { return ratio(count(c, c), predicted_count(c)); }
  double recall(std::size_t c) const { return ratio(count(c, c), true_count(c)); }
  double f1(std::size_t c) const { return ratio(2 * count(c, c), true_count(c) + predicted_count(c)); }
  double iou(std::size_t c) const { return ratio(count(c, c), true_count(c) + predicted_count(c) - count(c, c)); }
  double overall_accuracy() const
  {
    std::uint64_t diagonal = 0;
    for(std::size_t c = 0; c < m_classes; ++c)
      diagonal += count(c, c);
    return ratio(diagonal, total());
  }
  // means over the classes present in the truth
  double mean_f1() const { return mean_over_present(&Confusion::f1); }
  double mean_iou() const { return mean_over_present(&Confusion::iou); }

private:
  static double ratio(std::uint64_t a, std::uint64_t b)
  {
    return b == 0 ? std::numeric_limits<double>::quiet_NaN() : double(a) / double(b);
  }
  std::uint64_t sum_row(std::size_t t) const
  {
    std::uint64_t s = 0;
    for(std::size_t p = 0; p < m_classes; ++p)
      s += count(t, p);
    return s;
  }
  double mean_over_present(double (Confusion::*score)(std::size_t) const) const
  {
    double sum = 0.;
    std::size_t present = 0;
    for(std::size_t c = 0; c < m_classes; ++c)
      if(true_count(c) > 0)
      {
        sum += (this->*score)(c);
        ++present;
      }
    return present == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / double(present);
  }

  std::size_t m_classes;
  std::vector<std::uint64_t> m_counts;
};

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_CONFUSION_H
