// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The peer of the optimal search in optimal_search_benchmark: pgeof's published optimal
// neighborhood size (compute_features_optimal of pgeof 0.3, after Weinmann et al. 2015), written
// again on Debian's nanoflann so that every run times both on the same machine:
//  - the coordinates centred at their bounding box's centre, then float32;
//  - one k-NN query of 20 points per point (the point itself among them), nanoflann's kd-tree with
//    leaves of 10 points and the squared L2 distance, as pgeof's knn_search builds it;
//  - for k = 6..20: the two-pass covariance of the k nearest divided by k, its eigenvalues by
//    Eigen's general EigenSolver (pgeof's choice), sorted, clamped at 0, the eigenentropy with
//    pgeof's epsilon 1e-3; the first k of least eigenentropy wins;
//  - at that k pgeof's 11 features (the eigenvectors of the same solver).
// Nothing here is the package's: it measures what a user of that library gets. Its own translation
// unit, compiled as pgeof compiles (-O3, without CGAL's -frounding-math).

#include "pgeof_peer.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <nanoflann.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pgeof_peer {

// Points as nanoflann reads them: float for the peer, double for the k-NN comparison.
template <class Real>
struct Cloud_of
{
  std::vector<std::array<Real, 3>> xyz;
  std::size_t kdtree_get_point_count() const { return xyz.size(); }
  Real kdtree_get_pt(std::size_t i, std::size_t d) const { return xyz[i][d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
typedef Cloud_of<float> Cloud;

template <class Real>
using Tree_of = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<Real, Cloud_of<Real>>,
                                                    Cloud_of<Real>, 3, std::uint32_t>;
typedef Tree_of<float> Tree;

namespace {

template <class Real>
Cloud_of<Real> centred_cloud(const std::vector<std::array<double, 3>>& points)
{
  std::array<double, 3> low{{1e300, 1e300, 1e300}}, high{{-1e300, -1e300, -1e300}};
  for(const auto& p : points)
    for(int d = 0; d < 3; ++d)
    {
      low[d] = (std::min)(low[d], p[d]);
      high[d] = (std::max)(high[d], p[d]);
    }
  Cloud_of<Real> cloud;
  cloud.xyz.reserve(points.size());
  for(const auto& p : points)
  {
    std::array<Real, 3> q;
    for(int d = 0; d < 3; ++d)
      q[d] = Real(p[d] - 0.5 * (low[d] + high[d]));
    cloud.xyz.push_back(q);
  }
  return cloud;
}

// The k nearest of every point (itself included), `k` per point.
template <class Real>
std::vector<std::uint32_t> k_nearest(const Cloud_of<Real>& cloud, const Tree_of<Real>& tree, unsigned int k,
                                     int threads)
{
  const std::int64_t n = std::int64_t(cloud.xyz.size());
  std::vector<std::uint32_t> rows(std::size_t(n) * k);
#pragma omp parallel num_threads(threads)
  {
    std::vector<Real> distances(k);
#pragma omp for schedule(static)
    for(std::int64_t i = 0; i < n; ++i)
    {
      nanoflann::KNNResultSet<Real, std::uint32_t, std::uint32_t> result(k);
      result.init(&rows[std::size_t(i) * k], distances.data());
      tree.findNeighbors(result, cloud.xyz[std::size_t(i)].data(), nanoflann::SearchParams());
    }
  }
  return rows;
}

struct Pca
{
  Eigen::Vector3f values;  // descending, at least 0
  Eigen::Matrix3f vectors; // columns in the same order
};

inline Pca pca(const Cloud& cloud, const std::uint32_t* row, unsigned int k)
{
  Eigen::Matrix<float, Eigen::Dynamic, 3> points(k, 3);
  for(unsigned int j = 0; j < k; ++j)
    points.row(j) = Eigen::Map<const Eigen::RowVector3f>(cloud.xyz[row[j]].data());
  const Eigen::Matrix<float, Eigen::Dynamic, 3> centred = points.rowwise() - points.colwise().mean();
  const Eigen::Matrix3f covariance = (centred.adjoint() * centred) / float(k);
  Eigen::EigenSolver<Eigen::Matrix3f> solver(covariance);
  const Eigen::Vector3f ev = solver.eigenvalues().real();
  std::array<int, 3> order{{0, 1, 2}};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return ev[a] > ev[b]; });
  Pca r;
  for(int c = 0; c < 3; ++c)
  {
    r.values[c] = (std::max)(ev[order[c]], 0.f);
    r.vectors.col(c) = solver.eigenvectors().col(order[c]).real();
  }
  if(r.vectors(2, 2) < 0.f)
    r.vectors.col(2) = -r.vectors.col(2);
  return r;
}

inline float eigenentropy(const Pca& p)
{
  const float epsilon = 1e-3f;
  const Eigen::Vector3f e = p.values / (p.values.sum() + epsilon);
  return -e[0] * std::log(e[0] + epsilon) - e[1] * std::log(e[1] + epsilon) - e[2] * std::log(e[2] + epsilon);
}

inline std::array<float, 11> features(const Pca& p)
{
  const float epsilon = 1e-3f;
  const float v0 = std::sqrt(p.values[0]), v1 = std::sqrt(p.values[1]), v2 = std::sqrt(p.values[2]);
  const float inverse = 1.f / (v0 + epsilon);
  std::array<float, 11> f{};
  f[0] = (v0 - v1) * inverse;
  f[1] = (v1 - v2) * inverse;
  f[2] = v2 * inverse;
  if(v0 > 0.f)
  {
    const Eigen::Vector3f unary = p.vectors.cwiseAbs() * p.values;
    f[3] = unary[2] / unary.norm();
  }
  f[4] = p.vectors(0, 2);
  f[5] = p.vectors(1, 2);
  f[6] = p.vectors(2, 2);
  f[7] = v0;
  f[8] = std::sqrt(v0 * v1 + 1e-6f);
  f[9] = std::pow(v0 * v1 * v2 + 1e-9f, 1.f / 3.f);
  f[10] = v2 / (v0 + v1 + v2 + epsilon);
  return f;
}

} // namespace

Peer_points::Peer_points(const std::vector<std::array<double, 3>>& points)
  : floats(std::make_shared<Cloud>(centred_cloud<float>(points))),
    doubles(std::make_shared<Cloud_of<double>>(centred_cloud<double>(points)))
{}

std::vector<Result> optimal_features(const Peer_points& points, int threads, unsigned int k_min, unsigned int k_max)
{
  const Cloud& cloud = *points.floats;
  const Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  const std::vector<std::uint32_t> rows = k_nearest(cloud, tree, k_max, threads);
  const std::int64_t n = std::int64_t(cloud.xyz.size());
  std::vector<Result> results(static_cast<std::size_t>(n));
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::int64_t i = 0; i < n; ++i)
  {
    const std::uint32_t* row = &rows[std::size_t(i) * k_max];
    Pca best;
    float best_entropy = 1.f;
    unsigned int best_k = k_max;
    for(unsigned int k = k_min; k <= k_max; ++k)
    {
      const Pca p = pca(cloud, row, k);
      const float e = eigenentropy(p);
      if(k == k_min || e < best_entropy)
      {
        best_entropy = e;
        best_k = k;
        best = p;
      }
    }
    results[std::size_t(i)].features = features(best);
    results[std::size_t(i)].k = std::uint8_t(best_k);
  }
  return results;
}

std::size_t nanoflann_k_nearest(const Peer_points& points, unsigned int k, int threads)
{
  const Tree_of<double> tree(3, *points.doubles, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  return k_nearest(*points.doubles, tree, k, threads).size();
}

} // namespace pgeof_peer
