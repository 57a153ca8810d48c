// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The peer of optimal_search_benchmark (pgeof_peer.cpp): pgeof 0.3.3's optimal neighborhood size on
// nanoflann, compiled apart, as pgeof is.

#ifndef SIGMOID_NEIGHBORHOODS_BENCHMARK_PGEOF_PEER_H
#define SIGMOID_NEIGHBORHOODS_BENCHMARK_PGEOF_PEER_H

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace pgeof_peer {

template <class Real>
struct Cloud_of;

// The points as the peer's users hand them: centred at their bounding box's centre, in float32
// (and in doubles for nanoflann's k-NN against the package's). Built before the clock starts.
struct Peer_points
{
  explicit Peer_points(const std::vector<std::array<double, 3>>& points);
  std::shared_ptr<const Cloud_of<float>> floats;
  std::shared_ptr<const Cloud_of<double>> doubles;
};

struct Result
{
  // linearity, planarity, scattering, verticality, normal x y z, length, surface, volume, curvature
  std::array<float, 11> features;
  std::uint8_t k = 0;
};

// pgeof 0.3.3's compute_features_optimal: one k-NN query of k_max points (the point among them) per
// point, the k in [k_min, k_max] of least eigenentropy, the features there. Tree included.
std::vector<Result> optimal_features(const Peer_points& points, int threads, unsigned int k_min = 6,
                                     unsigned int k_max = 20);

// nanoflann's tree over the doubles and one query of the k nearest per point; returns the rows' size.
std::size_t nanoflann_k_nearest(const Peer_points& points, unsigned int k, int threads);

} // namespace pgeof_peer

#endif // SIGMOID_NEIGHBORHOODS_BENCHMARK_PGEOF_PEER_H
