// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VOXEL_EIGEN_ANALYSIS_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VOXEL_EIGEN_ANALYSIS_H

#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>
#include <CGAL/Sigmoid_neighborhoods/internal/sort_on_threads.h>

#include <CGAL/Classification/compressed_float.h>
#include <CGAL/Default_diagonalize_traits.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// The representatives of CGAL's voxel neighborhoods (CGAL::Classification::Point_set_neighborhood
// with a voxel size): the points in voxels (floor(x / v), floor(y / v), floor(z / v)), anchored at
// the origin as CGAL's are, and per voxel the point nearest (in float) to the centroid of its
// points, the first in index order on ties; in the voxels' lexicographic order, as CGAL's map
// holds them. Returns their indices.
template <typename ConcurrencyTag>
std::vector<std::uint32_t> voxel_representatives(const std::vector<Double_point>& points, float voxel_size,
                                                 unsigned int threads)
{
  struct Keyed
  {
    double x, y, z;
    std::uint32_t index;
  };
  std::vector<Keyed> keyed(points.size());
  for_each_index<ConcurrencyTag>(points.size(), threads, [] { return 0; }, [&](std::size_t i, int) {
    keyed[i] = Keyed{std::floor(points[i].x() / voxel_size), std::floor(points[i].y() / voxel_size),
                     std::floor(points[i].z() / voxel_size), std::uint32_t(i)};
  }, 4096);
  sort_on_threads(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    if(a.x != b.x)
      return a.x < b.x;
    if(a.y != b.y)
      return a.y < b.y;
    if(a.z != b.z)
      return a.z < b.z;
    return a.index < b.index;
  }, kernel_threads<ConcurrencyTag>(threads));
  std::vector<std::size_t> voxel_begin;
  for(std::size_t e = 0; e < keyed.size(); ++e)
    if(e == 0 || keyed[e].x != keyed[e - 1].x || keyed[e].y != keyed[e - 1].y || keyed[e].z != keyed[e - 1].z)
      voxel_begin.push_back(e);
  voxel_begin.push_back(keyed.size());
  std::vector<std::uint32_t> representatives(voxel_begin.size() - 1);
  for_each_index<ConcurrencyTag>(representatives.size(), threads, [] { return std::vector<Double_point>(); },
                                 [&](std::size_t v, std::vector<Double_point>& voxel) {
    voxel.clear();
    for(std::size_t e = voxel_begin[v]; e < voxel_begin[v + 1]; ++e)
      voxel.push_back(points[keyed[e].index]);
    const Double_point centroid = CGAL::centroid(voxel.begin(), voxel.end());
    std::uint32_t chosen = 0;
    float min_dist = (std::numeric_limits<float>::max)();
    for(std::size_t e = voxel_begin[v]; e < voxel_begin[v + 1]; ++e)
    {
      const float dist = float(CGAL::squared_distance(points[keyed[e].index], centroid));
      if(dist < min_dist)
      {
        min_dist = dist;
        chosen = keyed[e].index;
      }
    }
    representatives[v] = chosen;
  }, 64);
  return representatives;
}

// CGAL::Classification::Local_eigen_analysis of every point: the covariance (in float) of its
// neighbors around their centroid, its eigenvalues normalized to sum 1 and stored compressed, the
// centroid and the smallest eigenvector as CGAL stores them, with CGAL's arithmetic.
struct Eigen_records
{
  std::vector<std::array<CGAL::Classification::compressed_float, 2>> eigenvalues;
  std::vector<std::array<float, 3>> centroids;
  std::vector<std::array<float, 2>> smallest_eigenvectors;

  explicit Eigen_records(std::size_t n) : eigenvalues(n), centroids(n), smallest_eigenvectors(n) {}

  void compute(std::size_t index, const Double_point& query, const std::vector<Double_point>& neighbors)
  {
    using CGAL::Classification::compress_float;
    using CGAL::Classification::compressed_float;
    if(neighbors.empty())
    {
      eigenvalues[index] = {{compressed_float(0), compressed_float(0)}};
      centroids[index] = {{float(query.x()), float(query.y()), float(query.z())}};
      smallest_eigenvectors[index] = {{0.f, 0.f}};
      return;
    }
    const Double_point centroid = CGAL::centroid(neighbors.begin(), neighbors.end());
    centroids[index] = {{float(centroid.x()), float(centroid.y()), float(centroid.z())}};
    std::array<float, 6> covariance = {{0.f, 0.f, 0.f, 0.f, 0.f, 0.f}};
    for(const Double_point& p : neighbors)
    {
      const Double_kernel::Vector_3 d = p - centroid;
      covariance[0] += float(d.x() * d.x());
      covariance[1] += float(d.x() * d.y());
      covariance[2] += float(d.x() * d.z());
      covariance[3] += float(d.y() * d.y());
      covariance[4] += float(d.y() * d.z());
      covariance[5] += float(d.z() * d.z());
    }
    std::array<float, 3> values = {{0.f, 0.f, 0.f}};
    std::array<float, 9> vectors = {{0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f}};
    CGAL::Default_diagonalize_traits<float, 3>::diagonalize_selfadjoint_covariance_matrix(covariance, values, vectors);
    float sum = values[0] + values[1] + values[2];
    if(sum > 0.f)
      for(std::size_t i = 0; i < 3; ++i)
        values[i] = values[i] / sum;
    eigenvalues[index] = {{compress_float(values[1]), compress_float(values[2])}};
    sum = vectors[0] + vectors[1] + vectors[2];
    if(sum > 0.f)
      for(std::size_t i = 0; i < 3; ++i)
        vectors[i] = vectors[i] / sum;
    smallest_eigenvectors[index] = {{float(vectors[0]), float(vectors[1])}};
  }
};

// The eigen analysis of every point of `points` on its `k` nearest among `candidates` (indices of
// points; all of them when empty), ties broken by candidate order: CGAL's generator on its first
// scale (every point, k = 12) or on a voxel scale (the representatives). `reach`, when given,
// receives each point's distance to its k-th neighbor (infinity with fewer than k).
template <typename ConcurrencyTag>
Eigen_records neighbor_eigen_analysis(const std::vector<Double_point>& points,
                                      const std::vector<std::uint32_t>& candidates, std::size_t k,
                                      unsigned int threads, std::vector<double>* reach = nullptr,
                                      Neighbor_search structure = Neighbor_search::CGAL_KD_TREE)
{
  const bool all = candidates.empty();
  std::vector<Double_point> candidate_points;
  if(!all)
    for(std::uint32_t c : candidates)
      candidate_points.push_back(points[c]);
  const std::vector<Double_point>& tree_points = all ? points : candidate_points;
  const Neighbor_query tree(tree_points, threads, structure);
  Eigen_records records(points.size());
  if(reach != nullptr)
    reach->assign(points.size(), 0.);
  struct Scratch
  {
    std::vector<Neighbor> nearest;
    std::vector<Double_point> neighbors;
  };
  for_each_index<ConcurrencyTag>(points.size(), threads, [] { return Scratch(); },
                                 [&](std::size_t i, Scratch& scratch) {
    tree.query_position(points[i], unsigned(k), scratch.nearest);
    scratch.neighbors.clear();
    for(const Neighbor& m : scratch.nearest)
      scratch.neighbors.push_back(tree_points[m.index]);
    records.compute(i, points[i], scratch.neighbors);
    if(reach != nullptr)
      (*reach)[i] = scratch.nearest.size() < k ? (std::numeric_limits<double>::infinity)()
                                               : std::sqrt(scratch.nearest.back().squared_distance);
  }, 256);
  return records;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_VOXEL_EIGEN_ANALYSIS_H
