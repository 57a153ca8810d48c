// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_LOCAL_NEIGHBORHOOD_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_LOCAL_NEIGHBORHOOD_H

#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/Neighborhood_criterion.h>
#include <CGAL/Sigmoid_neighborhoods/weighted_covariance.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>
#include <CGAL/Sigmoid_neighborhoods/internal/tie_rule.h>

#include <CGAL/number_utils.h>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The neighborhood N_i(k_max) of one point: offsets p_j - p_i, normal angles, and the running
// largest squared radius, from which every (a, b, k) with k <= k_max is evaluated. The angles are
// kept as cosines and their arc cosines taken when first asked for: the weights of one sigmoid need
// them in its transition band only (Cosine_sigmoid::weight_from_cosine()).
class Local_neighborhood
{
public:
  // `with_angles` false leaves every angle 0: for callers whose every weight is 1 whatever the angle.
  void assign(const Oriented_points& input, std::uint32_t i, const std::vector<Neighbor>& neighbors,
              bool with_angles = true)
  {
    const std::size_t m = neighbors.size() + 1;
    m_offsets.resize(m);
    m_cosines.resize(m);
    m_squared_radius.resize(m);
    m_offsets[0].setZero();
    m_cosines[0] = 1.; // acos(1) = 0: a point's own angle
    m_squared_radius[0] = 0.;
    m_angles.clear(); // angles() takes them from the cosines when first asked
    m_largest_angle = 0.;
    if(!with_angles)
      m_angles.assign(m, 0.); // every angle 0, without an arc cosine
    const Double_point& p = input.points[i];
    const Eigen::Vector3d& n = input.normals[i];
    for(std::size_t j = 1; j < m; ++j)
    {
      const std::uint32_t index = neighbors[j - 1].index;
      const Double_point& q = input.points[index];
      m_offsets[j] = Eigen::Vector3d(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
      m_cosines[j] = with_angles ? normal_cosine(n, input.normals[index], input.line_angles) : 1.;
      m_squared_radius[j] = (std::max)(m_squared_radius[j - 1], m_offsets[j].squaredNorm());
    }
    // Scaled by a power of 2 (exactly) to a largest radius in [1, 2): covariances at that scale
    // keep their cubes far from overflow and underflow.
    const double largest = m_squared_radius[m - 1];
    const double scale = largest > 0. ? std::ldexp(1., -std::ilogb(std::sqrt(largest))) : 1.;
    m_unit_scale = scale;
    m_unit_offsets.resize(m);
    m_unit_squared_radius.resize(m);
    for(std::size_t j = 0; j < m; ++j)
    {
      m_unit_offsets[j] = m_offsets[j] * scale;
      m_unit_squared_radius[j] = m_squared_radius[j] * (scale * scale);
    }
  }

  std::size_t size() const { return m_offsets.size(); }
  const Eigen::Vector3d& offset(std::size_t j) const { return m_offsets[j]; }
  double squared_radius(unsigned int k) const { return m_squared_radius[k]; }
  // the offsets and squared radii scaled so that the largest radius lies in [1, 2)
  const Eigen::Vector3d& unit_offset(std::size_t j) const { return m_unit_offsets[j]; }
  double unit_squared_radius(unsigned int k) const { return m_unit_squared_radius[k]; }
  double unit_scale() const { return m_unit_scale; } // unit offset / offset, a power of 2

  // w_ij = sigmoid(angle j) for all j in N_i(k_max), bit for bit; w_ii = sig(0) = 1.
  void weights(const Cosine_sigmoid& sigmoid, double* w) const
  {
    for(std::size_t j = 0; j < m_cosines.size(); ++j)
      w[j] = sigmoid.weight_from_cosine(m_cosines[j]);
  }

  // Cosine_sigmoid::transition_argument() for all j in N_i(k_max), from which weights() follow;
  // returns true when all weights are 1 because every angle is below a (or within the tolerance):
  // on smooth surfaces, most pairs of the grid.
  bool transition_arguments(const Cosine_sigmoid& sigmoid, double* t) const
  {
    const std::vector<double>& x = angles();
    if(m_largest_angle <= sigmoid.angle_tolerance() || m_largest_angle < sigmoid.a())
    {
      // what transition_argument(x) gives for every x <= m_largest_angle
      std::fill(t, t + x.size(), Cosine_sigmoid::WEIGHT_ONE);
      return true;
    }
    sigmoid.transition_arguments(x.data(), x.size(), t);
    return false;
  }

  // the normal angles of N_i(k_max), normal_angle() (or normal_line_angle()) bit for bit
  const std::vector<double>& angles() const
  {
    if(m_angles.size() != m_cosines.size())
    {
      m_angles.resize(m_cosines.size());
      m_largest_angle = 0.;
      for(std::size_t j = 0; j < m_cosines.size(); ++j)
      {
        m_angles[j] = std::acos(m_cosines[j]);
        m_largest_angle = (std::max)(m_largest_angle, m_angles[j]);
      }
    }
    return m_angles;
  }

  Weighted_covariance covariance(const double* w, unsigned int k, Barycenter barycenter) const
  {
    Weighted_covariance result;
    result.squared_radius = m_squared_radius[k];
    accumulate_covariance(m_offsets.data(), w, std::size_t(k) + 1, barycenter, result);
    return result;
  }

  Dimensionality_features features(const double* w, unsigned int k, Barycenter barycenter) const
  {
    return dimensionality_features(covariance(w, k, barycenter));
  }

  // The size k in [k_first, k_last] of least criterion value (E_dim by default) with the weights w,
  // by the tie rule of SPEC §5
  // (sizes ascending, a smaller error by more than TIE_TOLERANCE replaces the best): the one scan
  // over k of every algorithm. k = 0 and E = +inf when every size is degenerate.
  struct Best_size
  {
    double error = std::numeric_limits<double>::infinity();
    unsigned int k = 0;
  };

  Best_size best_size(const double* w, unsigned int k_first, unsigned int k_last, Barycenter barycenter,
                      Neighborhood_criterion criterion = Neighborhood_criterion::DIMENSIONALITY) const
  {
    Best_size best;
    for(unsigned int k = k_first; k <= k_last; ++k)
    {
      const double error = criterion_value(features(w, k, barycenter), criterion);
      if(error < best.error - TIE_TOLERANCE)
      {
        best.error = error;
        best.k = k;
      }
    }
    return best;
  }

private:
  std::vector<Eigen::Vector3d> m_offsets;
  std::vector<double> m_cosines; // normal_cosine() of each neighbor
  mutable std::vector<double> m_angles; // their arc cosines, once angles() is called; empty before
  std::vector<double> m_squared_radius;
  std::vector<Eigen::Vector3d> m_unit_offsets;
  std::vector<double> m_unit_squared_radius;
  double m_unit_scale = 1.;
  mutable double m_largest_angle = 0.; // of m_angles
};

// How for_each_neighborhood() visits the points of an input whose order has no locality
// (Neighbor_query::has_scattered_order()).
enum class Scattered_input
{
  IN_INDEX_ORDER, // a block of results at a time: the least memory
  IN_SPATIAL_ORDER // in the tree's leaf order, every result held until all are done
};

// Runs `compute(i, local, scratch)` on the neighborhood N_i(k) of every point i from the shared
// `query`, one `scratch` per thread from `make_scratch()`, and passes the results to
// `sink(i, result)` in index order, a block at a time (for_each_index_in_blocks()). `with_angles`:
// see Local_neighborhood::assign().
// With IN_SPATIAL_ORDER, an input whose order has no locality is visited in the tree's leaf order,
// where consecutive queries share their neighbors in the cache (2.4 times faster on a shuffled
// scan), at the cost of holding every result; the results are the same bits, as each depends on its
// point only.
template <typename ConcurrencyTag, typename Result, typename MakeScratch, typename Compute, typename Sink>
void for_each_neighborhood(const Oriented_points& input, const Neighbor_query& query, unsigned int k,
                           unsigned int threads, const MakeScratch& make_scratch, const Compute& compute,
                           const Sink& sink, bool with_angles = true,
                           Scattered_input scattered = Scattered_input::IN_INDEX_ORDER)
{
  typedef decltype(make_scratch()) Inner;
  struct Scratch
  {
    std::vector<Neighbor> neighbors;
    Local_neighborhood local;
    Inner inner;
  };
  auto run = [&](std::size_t i, Scratch& s) {
    query.query(static_cast<std::uint32_t>(i), k, s.neighbors);
    s.local.assign(input, static_cast<std::uint32_t>(i), s.neighbors, with_angles);
    return compute(i, static_cast<const Local_neighborhood&>(s.local), s.inner);
  };
  auto scratch = [&make_scratch] { return Scratch{{}, {}, make_scratch()}; };
  if(scattered == Scattered_input::IN_SPATIAL_ORDER && query.has_scattered_order())
  {
    const std::vector<std::uint32_t>& order = query.spatial_order();
    std::vector<Result> results(input.size());
    for_each_index<ConcurrencyTag>(order.size(), threads, scratch, [&](std::size_t position, Scratch& s) {
      results[order[position]] = run(order[position], s);
    });
    for(std::size_t i = 0; i < results.size(); ++i)
      sink(i, results[i]);
    return;
  }
  for_each_index_in_blocks<ConcurrencyTag, Result>(input.size(), threads, scratch, run, sink);
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_LOCAL_NEIGHBORHOOD_H
