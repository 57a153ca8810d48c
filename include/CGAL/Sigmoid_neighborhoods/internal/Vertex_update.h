// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VERTEX_UPDATE_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VERTEX_UPDATE_H

#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdint>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// Stages 2 and 3 of Yadav et al.'s denoising (yadav-normal-filtering.md §6) for one point: the
// class of the point from the covariance of its cut-off neighborhood, then the restricted
// quadratic error metric update of its class.

enum class Vertex_class : unsigned char
{
  PLANAR,
  EDGE,
  CORNER,
  UNCLASSIFIED // the cut-off neighborhood has no extent: the point stays
};

struct Vertex_update_settings
{
  double cut_off = 0.9;            // rho, on n_i . n_j (|n_i . n_j| with line angles)
  double eigenvalue_threshold = 0.25; // tau, on the covariance's eigenvalues scaled to unit length
  double step_size = 0.1;          // alpha of the planar rule
  double weight_radius = 0.;       // r of the planar rule's weights
  double normal_weight_width = 0.; // the width of its normal term: r in the authors' code
  double rank_threshold = 0.;      // directions of the QEM's eigenvalues below it times the largest are not solved
  // The package's rules: the edge and corner metrics weighted by the planar rule's distance term and
  // their minimisers approached by `step_size`, like the planar rule. false: the authors' (unweighted,
  // the full step).
  bool weighted_metrics = true;
  bool line_angles = false;
  // The package's rule on smooth patches (jet_vertex_update): the projection onto the local quadric
  // of the input positions instead of a step towards the weighted mean plane, which flattens a
  // curved patch. A planar point is smooth; an edge or a corner too when its fit window has less
  // than `jet_feature_fraction` of its weight across the normal sigmoid (a facet of a curved patch,
  // which stage 1 turns into strips, rather than a sharp feature).
  bool jet_update = true;
  double jet_radius = 0.;           // r of the fit's distance weights exp(-|p_j - p_i|^2 / r^2)
  Cosine_sigmoid jet_sigmoid{0., CGAL_PI}; // the fit's normal weights on angle(n_i, n_j)
  double jet_feature_fraction = 0.5;
  double jet_flat_spread = 0.;      // a window whose mean 1 - n_i . n_j is below it is flat: the planar rule
  double jet_minimum_weight = 8.;   // the fit's total weight below which it is degenerate
  double jet_minimum_pivot = 1e-6;  // the normal equations' smallest LDLT pivot per largest below which too
};

struct Vertex_update
{
  Eigen::Vector3d position;        // the new position (the old one when the point stays)
  Vertex_class type = Vertex_class::UNCLASSIFIED;
  bool rank_deficient = false;     // the QEM solve dropped a direction
  bool smooth = false;             // a smooth patch: onto its jet (or stayed, when degenerate)
  bool degenerate_fit = false;     // a smooth point whose fit was degenerate (it stayed)
};

inline Eigen::Vector3d to_eigen(const Double_point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

// The minimiser of the quadratic (x - p_i)^T A (x - p_i) - 2 (x - p_i)^T b nearest to p_i:
// x = p_i + sum over kept eigenpairs (mu, v) of A of v (v . b) / mu, where an eigenpair is kept when
// mu > rank_threshold * mu_max (and mu > 0). A direction the neighbors' planes do not constrain is
// not solved for, and the point keeps its coordinate along it (Lindstrom's rule for QEM vertex
// placement): the authors' code inverts A, which is near-singular wherever the neighbor normals agree.
// The `fixed` directions of the smallest eigenvalues are never solved for, nor counted as dropped.
inline Eigen::Vector3d qem_offset(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double rank_threshold,
                                  bool& rank_deficient, int fixed = 0)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a, Eigen::ComputeEigenvectors);
  const Eigen::Vector3d& mu = solver.eigenvalues();
  const Eigen::Matrix3d& v = solver.eigenvectors();
  const double largest = mu[2];
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  rank_deficient = false;
  if(!(largest > 0.))
  {
    rank_deficient = true;
    return x;
  }
  for(int k = fixed; k < 3; ++k)
  {
    if(mu[k] > rank_threshold * largest && mu[k] > 0.)
      x += v.col(k) * (v.col(k).dot(b) / mu[k]);
    else
      rank_deficient = true;
  }
  return x;
}

// The height over p_i, along n_i, of the weighted least-squares quadric (a jet of order 2)
// z = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2 of the neighbors and p_i itself (weight 1) in the
// frame of n_i, x and y scaled by the fit's radius: c0. The weights are the cosine sigmoid of
// angle(n_i, n_j) times a Gaussian of the distance, so that a fit does not reach across an edge.
// `excluded`: the share of the window's distance weight that the sigmoid takes away. false when the
// fit is degenerate (too little weight, ill-conditioned normal equations): the point stays.
template <typename PointVector>
bool jet_height(const PointVector& points, const std::vector<Eigen::Vector3d>& normals, std::size_t i,
                const std::uint32_t* begin, const std::uint32_t* end, const Vertex_update_settings& s,
                double& height, double& excluded, double& spread)
{
  const Eigen::Vector3d p = to_eigen(points[i]);
  const Eigen::Vector3d& n = normals[i];
  // a tangent frame of n, the same for the same n
  const Eigen::Vector3d u =
    (std::abs(n[0]) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()).cross(n).normalized();
  const Eigen::Vector3d v = n.cross(u);
  const double scale = 1. / s.jet_radius, r2 = scale * scale;
  typedef Eigen::Matrix<double, 6, 1> Vector6;
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Vector6 right = Vector6::Zero();
  normal_matrix(0, 0) = 1.; // p_i at the origin, height 0
  double total = 1., window = 1.;
  excluded = 0.;
  spread = 0.;
  for(const std::uint32_t* j = begin; j != end; ++j)
  {
    const double c = n.dot(normals[*j]);
    const double wn = s.jet_sigmoid.weight_from_cosine(s.line_angles ? std::abs(c) : c);
    const Eigen::Vector3d d = to_eigen(points[*j]) - p;
    const double wd = std::exp(-d.squaredNorm() * r2);
    window += wd;
    excluded += (1. - wn) * wd;
    if(wn == 0.)
      continue;
    const double w = wn * wd;
    spread += w * (1. - (s.line_angles ? std::abs(c) : c));
    const double x = scale * u.dot(d), y = scale * v.dot(d);
    Vector6 m;
    m << 1., x, y, x * x, x * y, y * y;
    normal_matrix.noalias() += (w * m) * m.transpose();
    right += (w * n.dot(d)) * m;
    total += w;
  }
  excluded /= window;
  spread /= total;
  if(!(total >= s.jet_minimum_weight))
    return false;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solve(normal_matrix);
  // The pivots of the (pivoting) factorisation: a direction of the six without data, such as y on
  // points along a line, leaves a pivot near 0 (Eigen's rcond() estimate misses exact zeros).
  const Vector6 pivots = solve.vectorD();
  if(solve.info() != Eigen::Success || !(pivots.minCoeff() > s.jet_minimum_pivot * pivots.maxCoeff()))
    return false;
  height = solve.solve(right)[0];
  return std::isfinite(height);
}

// Stages 2 and 3 for point i with neighbors [begin, end) (never i), positions `points` (`original`:
// the input's), filtered normals `normals`. For an edge, the direction e along the edge is not an eigenvalue of the QEM
// to solve: it is fixed (A = e e^T + sum n^_j n^_j^T with n^_j orthogonal to e, so the minimiser keeps
// p_i's coordinate along e), and the rank test applies to the two others.
template <typename PointVector>
Vertex_update update_vertex(const PointVector& points, const PointVector& original,
                            const std::vector<Eigen::Vector3d>& normals, std::size_t i,
                            const std::uint32_t* begin, const std::uint32_t* end, const Vertex_update_settings& s)
{
  Vertex_update result;
  const Eigen::Vector3d p = to_eigen(points[i]);
  const Eigen::Vector3d& n = normals[i];
  result.position = p;

  // Stage 2: Q_i = {i} and the neighbors in the cut-off cone; covariance about their centroid.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  std::size_t count = 1; // i itself, at offset 0
  for(const std::uint32_t* j = begin; j != end; ++j)
  {
    const double c = n.dot(normals[*j]);
    if((s.line_angles ? std::abs(c) : c) > s.cut_off)
    {
      const Eigen::Vector3d d = to_eigen(points[*j]) - p;
      sum += d;
      moments.noalias() += d * d.transpose();
      ++count;
    }
  }
  const Eigen::Vector3d mean = sum / double(count);
  const Eigen::Matrix3d covariance = moments / double(count) - mean * mean.transpose();
  if(!(covariance.trace() > 0.))
    return result;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> shape(covariance, Eigen::ComputeEigenvectors);
  Eigen::Vector3d lambda = shape.eigenvalues().cwiseMax(0.);
  const double length = lambda.norm();
  if(!(length > 0.))
    return result;
  lambda /= length;
  const double tau = s.eigenvalue_threshold;
  if(lambda[0] < tau && lambda[1] < tau && lambda[2] > tau)
    result.type = Vertex_class::EDGE;
  else if(lambda[0] < tau && lambda[1] > tau && lambda[2] > tau)
    result.type = Vertex_class::PLANAR;
  else
    result.type = Vertex_class::CORNER;

  // Stage 3 over all neighbors, without the cut-off.
  const double r2 = s.weight_radius * s.weight_radius;
  auto distance_weight = [&](const Eigen::Vector3d& d) { return std::exp(-4. * d.squaredNorm() / r2); };
  if(s.jet_update)
  {
    // The fit is on the input positions, so that iterating it does not shrink the patch; the
    // normals of the current sweep only decide who enters it.
    double height = 0., excluded = 0., spread = 0.;
    const bool fitted = jet_height(original, normals, i, begin, end, s, height, excluded, spread);
    if(result.type == Vertex_class::PLANAR || excluded < s.jet_feature_fraction)
    {
      // A degenerate fit leaves the point where it is (never worse than the input); a flat window
      // keeps the rules below, which average over it more than a quadric does.
      if(!fitted)
      {
        result.smooth = true;
        result.degenerate_fit = true;
        return result;
      }
      if(!(spread < s.jet_flat_spread))
      {
        result.smooth = true;
        result.position = to_eigen(original[i]) + height * n;
        return result;
      }
    }
  }
  if(result.type == Vertex_class::PLANAR)
  {
    const double w2 = s.normal_weight_width * s.normal_weight_width;
    double weighted = 0., total = 0.;
    for(const std::uint32_t* j = begin; j != end; ++j)
    {
      const Eigen::Vector3d d = to_eigen(points[*j]) - p;
      const double w = std::exp(-8. * (n - normals[*j]).squaredNorm() / w2) * distance_weight(d);
      weighted += w * n.dot(d);
      total += w;
    }
    if(total > 0.)
      result.position = p + (s.step_size * weighted / total) * n;
    return result;
  }
  const double step = s.weighted_metrics ? s.step_size : 1.;
  if(result.type == Vertex_class::CORNER)
  {
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for(const std::uint32_t* j = begin; j != end; ++j)
    {
      const Eigen::Vector3d& m = normals[*j];
      const Eigen::Vector3d d = to_eigen(points[*j]) - p;
      const double w = s.weighted_metrics ? distance_weight(d) : 1.;
      a.noalias() += w * m * m.transpose();
      b += w * m * m.dot(d);
    }
    result.position = p + step * qem_offset(a, b, s.rank_threshold, result.rank_deficient);
    return result;
  }
  // Edge: e the direction of the largest eigenvalue, the neighbor normals projected orthogonally to it.
  const Eigen::Vector3d e = shape.eigenvectors().col(2);
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for(const std::uint32_t* j = begin; j != end; ++j)
  {
    const Eigen::Vector3d m = normals[*j] - e.dot(normals[*j]) * e;
    const Eigen::Vector3d d = to_eigen(points[*j]) - p;
    const double w = s.weighted_metrics ? distance_weight(d) : 1.;
    a.noalias() += w * m * m.transpose();
    b += w * m * m.dot(d);
  }
  // a has e in its kernel: solved on its two largest eigenpairs, the point keeps its coordinate along e.
  const Eigen::Vector3d x = qem_offset(a, b, s.rank_threshold, result.rank_deficient, 1);
  result.position = p + step * x;
  return result;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VERTEX_UPDATE_H
