// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_COMPUTE_ANCHORED_CGAL_FEATURES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_COMPUTE_ANCHORED_CGAL_FEATURES_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Origin_grid.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>
#include <CGAL/Sigmoid_neighborhoods/internal/voxel_eigen_analysis.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace Classification {

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  which features of CGAL's generator `compute_anchored_cgal_features()` computes
*/
enum class Anchored_cgal_features
{
  ALL,       ///< the generator's point-based features: eigenvalues, distance to plane, grids, verticality
  GRIDS_ONLY ///< the planimetric grids' alone: dispersion, elevation, heights below and above, range
};

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  \brief computes the point-based features of CGAL's `Point_set_feature_generator` with the voxel
  `voxel_size` on `scales` scales (the voxel doubled per scale), with its planimetric grids anchored
  at the origin instead of the point set's bounding box, so that a point's features depend on the
  points near it alone: a tile read with a halo of `anchored_cgal_grid_reach()` and of
  `anchored_cgal_neighbor_reach()` around its points gets the same values, bit for bit, as the union
  of the tiles.

  The features, their names (e.g. `eigenvalue0_0` ... `verticality_4`), order and arithmetic are the
  generator's (`CGAL::Sequential_tag`), with three differences: the grids' cells (floor(x / r),
  floor(y / r)); the elevation's terrain model kept in `float` (CGAL stores it in 256 steps of the
  whole set's height range); the height above a cell's top computed in `double` (CGAL's form when
  its grid has more cells than points). Neighbors are the package's: ties between equally distant
  points broken by index (the first scale's) or by voxel order (the voxel scales'), where CGAL's
  tree order decides. Where the generator's grid is anchored at a multiple of the coarsest cell
  and its voxel is a power of two, the other values equal the generator's (tested).

  Each feature is written to `out` as a `std::pair<std::string, std::vector<float>>`, one value per
  point. The result is the same for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \param points the points (distinct positions, as the package reads them)
  \param voxel_size the first scale's voxel and grid cell, in the points' unit, `> 0`
  \param scales the number of scales, `>= 1`
  \param which all features, or the grids' alone
  \param out receives the features
  \param np optional: `point_map` (CGAL), `number_of_threads` and `neighbor_search`
  \pre finite coordinates; fewer than `2^32` points; otherwise `std::invalid_argument`
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
OutputIterator compute_anchored_cgal_features(const PointRange& points, float voxel_size, unsigned int scales,
                                              Anchored_cgal_features which, OutputIterator out,
                                              const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  typedef internal::Double_kernel::Vector_3 Vector;
  typedef internal::Double_kernel::Plane_3 Plane;
  if(!(voxel_size > 0.f) || !std::isfinite(voxel_size) || scales < 1)
    throw std::invalid_argument("compute_anchored_cgal_features(): the voxel must be positive and scales >= 1");
  const unsigned int threads = internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np));
  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np), threads);
  if(copy.size() > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw std::invalid_argument("compute_anchored_cgal_features(): more than 2^32 - 1 points");
  const std::size_t n = copy.size();
  const auto no_scratch = [] { return 0; };
  auto column = [&](const std::string& name, unsigned int s, std::vector<float>&& values) {
    *out++ = std::make_pair(name + "_" + std::to_string(s), std::move(values));
  };

  // the voxel of each scale, doubled in float as the generator doubles it
  std::vector<float> voxels(scales, voxel_size);
  for(unsigned int s = 1; s < scales; ++s)
    voxels[s] = voxels[s - 1] * 2;

  std::vector<internal::Eigen_records> eigen;
  if(which == Anchored_cgal_features::ALL)
    for(unsigned int s = 0; s < scales; ++s)
    {
      // the first scale on every point, the others on their voxels' representatives; 12 neighbors
      const std::vector<std::uint32_t> candidates =
        s == 0 ? std::vector<std::uint32_t>() : internal::voxel_representatives<ConcurrencyTag>(copy, voxels[s], threads);
      eigen.push_back(internal::neighbor_eigen_analysis<ConcurrencyTag>(copy, candidates, 12, threads, nullptr,
                                                                        internal::neighbor_search(np)));
    }
  auto per_point = [&](const auto& value) {
    std::vector<float> values(n);
    internal::for_each_index<ConcurrencyTag>(n, threads, no_scratch, [&](std::size_t i, int) { values[i] = value(i); },
                                             4096);
    return values;
  };
  // Local_eigen_analysis::normal_vector()
  auto normal = [](const internal::Eigen_records& e, std::size_t i) {
    const auto& v = e.smallest_eigenvectors[i];
    return Vector(double(v[0]), double(v[1]), double(1. - (v[0] + v[1])));
  };

  if(which == Anchored_cgal_features::ALL)
  {
    using CGAL::Classification::decompress_float;
    for(unsigned int j = 0; j < 3; ++j)
      for(unsigned int s = 0; s < scales; ++s)
        column("eigenvalue" + std::to_string(j), s, per_point([&](std::size_t i) {
                 const auto& c = eigen[s].eigenvalues[i];
                 const float e1 = decompress_float(c[0]), e2 = decompress_float(c[1]);
                 return j == 0 ? 1.f - (e1 + e2) : j == 1 ? e1 : e2;
               }));
    for(unsigned int s = 0; s < scales; ++s)
      column("distance_to_plane", s, per_point([&](std::size_t i) {
               const auto& c = eigen[s].centroids[i];
               const Plane plane{internal::Double_point(double(c[0]), double(c[1]), double(c[2])), normal(eigen[s], i)};
               return float(CGAL::sqrt(CGAL::squared_distance(copy[i], plane)));
             }));
  }
  std::vector<internal::Origin_grid_features> grids;
  {
    const internal::Origin_grid grid(copy, voxel_size, scales);
    for(unsigned int s = 0; s < scales; ++s)
      grids.push_back(internal::origin_grid_features<ConcurrencyTag>(grid, s, voxels[s] * 3, voxels[s] * 10, threads));
  }
  for(unsigned int s = 0; s < scales; ++s)
    column("vertical_dispersion", s, std::move(grids[s].dispersion));
  for(unsigned int s = 0; s < scales; ++s)
    column("elevation", s, std::move(grids[s].elevation));
  for(unsigned int s = 0; s < scales; ++s)
    column("height_below", s, std::move(grids[s].height_below));
  for(unsigned int s = 0; s < scales; ++s)
    column("height_above", s, std::move(grids[s].height_above));
  for(unsigned int s = 0; s < scales; ++s)
    column("vertical_range", s, std::move(grids[s].vertical_range));
  if(which == Anchored_cgal_features::ALL)
    for(unsigned int s = 0; s < scales; ++s)
      column("verticality", s, per_point([&](std::size_t i) {
               Vector v = normal(eigen[s], i);
               v = v / CGAL::sqrt(v * v);
               return 1.f - float(CGAL::abs(v * Vector(0., 0., 1.)));
             }));
  return out;
}

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  \brief how far in x and y from a point the grid cells that its grid features read reach, for
  `compute_anchored_cgal_features()` with the same `voxel_size` and `scales`: a tile read with a halo
  this wide (plus a margin for the rounding of the cells' borders) holds them whole.
*/
inline double anchored_cgal_grid_reach(float voxel_size, unsigned int scales)
{
  return internal::origin_grid_reach(voxel_size, scales, voxel_size);
}

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  \brief for each point `first` ... `last - 1`, how far in x and y the points that its eigen
  features in `compute_anchored_cgal_features()` read can lie: its 12th nearest point, and on each
  voxel scale its 12th nearest representative plus a voxel's diagonal in x and y (a voxel meeting
  that ball must be whole). A tile read with a halo that holds every point within that distance of
  each of its points gets the union's values; infinity where a scale has fewer than 12 candidates.
  \param points the whole point set (the tile with its halo, or the union)
  \param voxel_size the smallest voxel, as given to `compute_anchored_cgal_features()`
  \param scales the number of voxel scales, as given to `compute_anchored_cgal_features()`
  \param first the first point whose reach is wanted
  \param last one past the last point whose reach is wanted
  \param np optional: `point_map` (CGAL), `number_of_threads` and `neighbor_search`
  \returns `last - first` distances, in the points' units
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<double> anchored_cgal_neighbor_reach(const PointRange& points, float voxel_size, unsigned int scales,
                                                 std::size_t first, std::size_t last,
                                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  const unsigned int threads = internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np));
  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np), threads);
  if(first > last || last > copy.size())
    throw std::invalid_argument("anchored_cgal_neighbor_reach(): the points first ... last - 1 are not in the set");
  const std::size_t k = 12;
  std::vector<double> reach(last - first, 0.);
  float voxel = voxel_size;
  for(unsigned int s = 0; s < (std::max)(1u, scales); ++s, voxel = voxel * 2)
  {
    std::vector<internal::Double_point> candidates;
    double diagonal = 0.;
    if(s == 0)
      candidates = copy;
    else
    {
      for(std::uint32_t r : internal::voxel_representatives<ConcurrencyTag>(copy, voxel, threads))
        candidates.push_back(copy[r]);
      diagonal = std::sqrt(2.) * double(voxel);
    }
    const internal::Neighbor_query tree(candidates, threads, internal::neighbor_search(np));
    internal::for_each_index<ConcurrencyTag>(last - first, threads, [] { return std::vector<internal::Neighbor>(); },
                                             [&](std::size_t q, std::vector<internal::Neighbor>& nearest) {
      tree.query_position(copy[first + q], unsigned(k), nearest);
      const double d = nearest.size() < k ? (std::numeric_limits<double>::infinity)()
                                          : std::sqrt(nearest.back().squared_distance) + diagonal;
      reach[q] = (std::max)(reach[q], d);
    }, 256);
  }
  return reach;
}

} // namespace Classification
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_COMPUTE_ANCHORED_CGAL_FEATURES_H
