// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The peer of the optimal search in optimal_search_benchmark: pgeof's optimal neighborhood size
// (compute_features_optimal, after Weinmann et al. 2015) as pgeof 0.3.3 computes it (the release,
// commit 9c2e7b96a31a88865ff0d2e009e8ebb5f8f16d23, github.com/drprojects/point_geometric_features),
// written again on Debian's nanoflann so that every run times both on the same machine:
//  - the coordinates centred at their bounding box's centre, then float32 (as pgeof's users hand them);
//  - one k-NN query of 20 points per point (the point itself among them): pgeof's knn_search
//    (include/nn_search.hpp), nanoflann's kd-tree with leaves of 10 and the squared L2 distance;
//  - for k = 6..20 (k_min = k_min_search = 6, k_step = 1): pgeof's pca_from_neighborhood
//    (include/pca.hpp): the k nearest copied into a row-major k x 3 matrix, centred at their mean,
//    covariance C^T C / k, Eigen's SelfAdjointEigenSolver (eigenvalues and eigenvectors), the
//    eigenvalues taken largest first and clamped at 0, the smallest one's eigenvector turned to
//    z >= 0; compute_eigentropy with pgeof's epsilon 1e-3; the first k of least eigenentropy wins
//    (compute_geometric_features_optimal, include/pgeof.hpp);
//  - at that k pgeof's 11 features (compute_features, include/pca.hpp).
// Earlier pgeof (before commit db3696d, April 2024, released in 0.2.0) solved with Eigen's general
// EigenSolver and sorted its complex eigenvalues; 0.3.3 relies on SelfAdjointEigenSolver's real
// eigenvalues in increasing order. pca.hpp is followed as stored before that change (commit 47d7025)
// with the change as pgeof's pull requests #13 and #19 describe it (benchmark/notes/pgeof-peer.md:
// the text of pca.hpp at 9c2e7b9 was not at hand). pgeof runs its points on a taskflow executor;
// the peer on OpenMP, `threads` threads, static schedule (taskflow's StaticPartitioner). Nothing here
// is the package's: it measures what a user of that library gets. Its own translation unit,
// compiled as pgeof compiles (-O3, no -march, without CGAL's -frounding-math).

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

// The k nearest of every point (itself included), `k` per point: pgeof's nanoflann_knn_search
// (include/nn_search.hpp, 0.3.3) with the cloud as its own query.
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

// pgeof's types (include/pca.hpp, 0.3.3): PointCloud, Vec3, PCAResult, epsilon<float>.
typedef Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> Point_cloud;
typedef Eigen::RowVector3f Vec3;
constexpr float epsilon = 1e-3f;

struct Pca_result
{
  Vec3 val; // largest first, each at least 0
  Vec3 v0;  // eigenvector of val(0)
  Vec3 v1;  // eigenvector of val(1)
  Vec3 v2;  // eigenvector of val(2), z >= 0
};

// pgeof's pca_from_pointcloud (include/pca.hpp, 0.3.3).
inline Pca_result pca_from_pointcloud(const Point_cloud& cloud)
{
  const Point_cloud centered_cloud = cloud.rowwise() - cloud.colwise().mean();
  const Eigen::Matrix3f cov = (centered_cloud.transpose() * centered_cloud) / float(cloud.rows());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> es(cov);
  // the eigenvalues come in increasing order: the largest is the last
  const Eigen::Vector3f& ev = es.eigenvalues();
  Pca_result r;
  r.val = Vec3((std::max)(ev(2), 0.f), (std::max)(ev(1), 0.f), (std::max)(ev(0), 0.f));
  r.v0 = es.eigenvectors().col(2).transpose();
  r.v1 = es.eigenvectors().col(1).transpose();
  r.v2 = es.eigenvectors().col(0).transpose();
  // only the third eigenvector is turned to the z+ half-space (the only one read with its sign)
  if(r.v2(2) < 0.f)
    r.v2 = -1.f * r.v2;
  return r;
}

// pgeof's pca_from_neighborhood (include/pca.hpp, 0.3.3): the first k of the point's row.
inline Pca_result pca_from_neighborhood(const Cloud& cloud, const std::uint32_t* row, unsigned int k)
{
  Point_cloud points(k, 3);
  for(unsigned int j = 0; j < k; ++j)
    points.row(j) = Eigen::Map<const Vec3>(cloud.xyz[row[j]].data());
  return pca_from_pointcloud(points);
}

// pgeof's compute_eigentropy (include/pca.hpp, 0.3.3).
inline float compute_eigentropy(const Pca_result& pca)
{
  const float val_sum = pca.val.sum() + epsilon;
  const Vec3 e = pca.val / val_sum;
  return -e(0) * std::log(e(0) + epsilon) - e(1) * std::log(e(1) + epsilon) - e(2) * std::log(e(2) + epsilon);
}

// pgeof's compute_features (include/pca.hpp, 0.3.3), in its order: linearity, planarity, scattering,
// verticality, normal x y z, length, surface, volume, curvature. Verticality stays 0 where the
// largest eigenvalue is 0 (pgeof's array is zeroed before).
inline std::array<float, 11> compute_features(const Pca_result& pca)
{
  constexpr float sq_eps = 1e-6f;
  constexpr float cub_eps = 1e-9f;
  constexpr float one_third = 1.f / 3.f;
  const float val0 = std::sqrt(pca.val(0));
  const float val1 = std::sqrt(pca.val(1));
  const float val2 = std::sqrt(pca.val(2));
  const float val0_fact = 1.f / (val0 + epsilon);
  std::array<float, 11> f{};
  f[4] = pca.v2(0);
  f[5] = pca.v2(1);
  f[6] = pca.v2(2);
  f[0] = (val0 - val1) * val0_fact;
  f[1] = (val1 - val2) * val0_fact;
  f[2] = val2 * val0_fact;
  f[7] = val0;
  f[8] = std::sqrt(val0 * val1 + sq_eps);
  f[9] = std::pow(val0 * val1 * val2 + cub_eps, one_third);
  f[10] = val2 / (val0 + val1 + val2 + epsilon);
  if(val0 > 0.f)
  {
    const Vec3 unary_vector(
      pca.val(0) * std::abs(pca.v0(0)) + pca.val(1) * std::abs(pca.v1(0)) + pca.val(2) * std::abs(pca.v2(0)),
      pca.val(0) * std::abs(pca.v0(1)) + pca.val(1) * std::abs(pca.v1(1)) + pca.val(2) * std::abs(pca.v2(1)),
      pca.val(0) * std::abs(pca.v0(2)) + pca.val(1) * std::abs(pca.v1(2)) + pca.val(2) * std::abs(pca.v2(2)));
    f[3] = unary_vector(2) / unary_vector.norm();
  }
  return f;
}

} // namespace

Peer_points::Peer_points(const std::vector<std::array<double, 3>>& points)
  : floats(std::make_shared<Cloud>(centred_cloud<float>(points))),
    doubles(std::make_shared<Cloud_of<double>>(centred_cloud<double>(points)))
{}

// pgeof's compute_geometric_features_optimal (include/pgeof.hpp, 0.3.3) with k_min = k_min_search =
// `k_min`, k_step = 1 and `k_max` neighbors per point: every k from k0 to k_max is solved.
std::vector<Result> optimal_features(const Peer_points& points, int threads, unsigned int k_min, unsigned int k_max)
{
  const Cloud& cloud = *points.floats;
  const Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  const std::vector<std::uint32_t> rows = k_nearest(cloud, tree, k_max, threads);
  const std::int64_t n = std::int64_t(cloud.xyz.size());
  std::vector<Result> results(static_cast<std::size_t>(n));
  const unsigned int k_nn = k_max;
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::int64_t i = 0; i < n; ++i)
  {
    if(k_nn < k_min)
      continue; // pgeof leaves such a point's features at 0
    const std::uint32_t* row = &rows[std::size_t(i) * k_max];
    const unsigned int k0 = (std::min)(k_min, k_nn);
    Pca_result pca_optimal;
    float eigenentropy_optimal = 1.f;
    unsigned int k_optimal = k_nn;
    for(unsigned int k = k0; k <= k_nn; ++k)
    {
      const Pca_result pca = pca_from_neighborhood(cloud, row, k);
      const float eigenentropy = compute_eigentropy(pca);
      if(k == k0 || eigenentropy < eigenentropy_optimal)
      {
        eigenentropy_optimal = eigenentropy;
        k_optimal = k;
        pca_optimal = pca;
      }
    }
    results[std::size_t(i)].features = compute_features(pca_optimal);
    results[std::size_t(i)].k = std::uint8_t(k_optimal);
  }
  return results;
}

std::size_t nanoflann_k_nearest(const Peer_points& points, unsigned int k, int threads)
{
  const Tree_of<double> tree(3, *points.doubles, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  return k_nearest(*points.doubles, tree, k, threads).size();
}

} // namespace pgeof_peer
