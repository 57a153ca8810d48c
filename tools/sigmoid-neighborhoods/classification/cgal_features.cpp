// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "cgal_features.h"
#include "for_each_item.h"

#include <CGAL/Sigmoid_neighborhoods/Classification/compute_anchored_cgal_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <CGAL/Classification/Feature_set.h>
#include <CGAL/Classification/Point_set_feature_generator.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/bounding_box.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

namespace {

typedef SN::Oriented_point_set::Kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3> Point_set;
typedef Point_set::Point_map Point_map;
// the generator's types, with its defaults
typedef CGAL::Classification::Point_set_feature_generator<Kernel, Point_set, Point_map, CGAL::Sequential_tag>
  Generator;
typedef Generator::Neighborhood Neighborhood;
typedef Generator::Planimetric_grid Grid;
typedef CGAL::Classification::Local_eigen_analysis Eigen_analysis;
typedef CGAL::Default_diagonalize_traits<float, 3> Diagonalize_traits;

// One scale of the generator (Point_set_feature_generator::Scale): a neighborhood on the points (the
// first scale) or on their voxel grid, the eigen analysis of every point's 12 nearest neighbors in it,
// and the planimetric grid.
struct Scale
{
  float voxel_size = -1.f;
  std::unique_ptr<Neighborhood> neighborhood;
  std::unique_ptr<Eigen_analysis> eigen;
  std::unique_ptr<Grid> grid;

  void build_neighborhood(const Point_set& points, bool first)
  {
    if(first)
      neighborhood = std::make_unique<Neighborhood>(points, points.point_map(), CGAL::Sequential_tag());
    else
      neighborhood = std::make_unique<Neighborhood>(points, points.point_map(), voxel_size, CGAL::Sequential_tag());
  }

  // Every point's analysis depends on that point alone, so CGAL's parallel loop gives the sequential
  // one's values; only its mean range, a sum in the threads' order, differs in its last bits: a scale
  // whose voxel comes from it (the first of the group cgal) is analysed sequentially.
  template <typename ConcurrencyTag>
  void build_eigen(const Point_set& points, ConcurrencyTag tag)
  {
    eigen = std::make_unique<Eigen_analysis>(Eigen_analysis::create_from_point_set(
      points, points.point_map(), neighborhood->k_neighbor_query(12), tag, Diagonalize_traits()));
    if(voxel_size < 0)
      voxel_size = eigen->mean_range();
  }
  float radius_neighbors() const { return voxel_size * 3; }
  float radius_dtm() const { return voxel_size * 10; }
};

// The features' values, a column per thread at a time (each value depends on its point alone).
void append_columns(const CGAL::Classification::Feature_set& features, std::size_t size, unsigned int threads,
                    std::vector<Feature_column>& columns)
{
  // allocated before the parallel loop: an exception (out of memory) must not leave it
  const std::size_t first = columns.size();
  columns.resize(first + features.size());
  for(std::size_t f = 0; f < features.size(); ++f)
  {
    columns[first + f].name = features[f]->name();
    columns[first + f].values.resize(size);
  }
  const std::ptrdiff_t count = std::ptrdiff_t(features.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads == 0 ? omp_get_max_threads() : int(threads))
#endif
  for(std::ptrdiff_t f = 0; f < count; ++f)
  {
    Feature_column& c = columns[first + std::size_t(f)];
    for(std::size_t i = 0; i < size; ++i)
      c.values[i] = features[std::size_t(f)]->value(i);
  }
}

#ifdef CGAL_LINKED_WITH_TBB
typedef CGAL::Parallel_tag Per_point_tag;
#else
typedef CGAL::Sequential_tag Per_point_tag;
#endif

// The scales as the generator's constructor builds them, one after the other there: the voxel of
// scale s is the first's times 2^s, the first's CGAL's choice from its eigen analysis when not given.
// `grid_only`: the planimetric grids alone.
std::vector<Scale> build_scales(const Point_set& points, const Kernel::Iso_cuboid_3& bbox, unsigned int scale_count,
                                double voxel, unsigned int threads, bool grid_only)
{
  std::vector<Scale> scales(std::max(1u, scale_count));
  std::size_t first_parallel = 0;
  if(voxel > 0.)
    scales[0].voxel_size = float(voxel);
  else
  {
    scales[0].build_neighborhood(points, true);
    scales[0].build_eigen(points, CGAL::Sequential_tag());
    first_parallel = 1;
  }
  for(std::size_t s = 1; s < scales.size(); ++s)
    scales[s].voxel_size = scales[s - 1].voxel_size * 2;
  if(!grid_only)
  {
    // the neighborhoods (a kd-tree, a voxel grid) side by side, then each scale's points on every thread
    for_each_item(first_parallel, scales.size(), threads,
                  [&](std::size_t s) { scales[s].build_neighborhood(points, s == 0); });
    for(std::size_t s = first_parallel; s < scales.size(); ++s)
      scales[s].build_eigen(points, Per_point_tag());
  }
  scales[0].grid = std::make_unique<Grid>(points, points.point_map(), bbox, scales[0].voxel_size);
  for(std::size_t s = 1; s < scales.size(); ++s)
    scales[s].grid = std::make_unique<Grid>(scales[s - 1].grid.get());
  return scales;
}

// The features of generate_point_based_features(), in its order, computed side by side on TBB. The
// feature set keeps references to lvalue arguments until end_parallel_additions(): the index of an
// eigenvalue is given as a copy.
void add_generator_features(CGAL::Classification::Feature_set& features, const Point_set& points,
                            const Point_map& point_map, const std::vector<Scale>& scales, bool grid_only)
{
  using namespace CGAL::Classification::Feature;
  features.begin_parallel_additions();
  if(!grid_only)
  {
    for(unsigned int j = 0; j < 3; ++j)
      for(std::size_t s = 0; s < scales.size(); ++s)
        features.add_with_scale_id<Eigenvalue>(s, points, *scales[s].eigen, static_cast<unsigned int>(j));
    for(std::size_t s = 0; s < scales.size(); ++s)
      features.add_with_scale_id<Generator::Distance_to_plane>(s, points, point_map, *scales[s].eigen);
  }
  for(std::size_t s = 0; s < scales.size(); ++s)
    features.add_with_scale_id<Generator::Dispersion>(s, points, point_map, *scales[s].grid,
                                                      scales[s].radius_neighbors());
  for(std::size_t s = 0; s < scales.size(); ++s)
    features.add_with_scale_id<Generator::Elevation>(s, points, point_map, *scales[s].grid, scales[s].radius_dtm());
  for(std::size_t s = 0; s < scales.size(); ++s)
    features.add_with_scale_id<Generator::Height_below>(s, points, point_map, *scales[s].grid);
  for(std::size_t s = 0; s < scales.size(); ++s)
    features.add_with_scale_id<Generator::Height_above>(s, points, point_map, *scales[s].grid);
  for(std::size_t s = 0; s < scales.size(); ++s)
    features.add_with_scale_id<Generator::Vertical_range>(s, points, point_map, *scales[s].grid);
  if(!grid_only)
    for(std::size_t s = 0; s < scales.size(); ++s)
      features.add_with_scale_id<Generator::Verticality>(s, points, *scales[s].eigen);
  features.end_parallel_additions();
}

} // namespace

void append_cgal_features(const SN::Oriented_point_set& model, unsigned int scale_count, double voxel,
                          unsigned int threads, std::vector<Feature_column>& columns, bool grid_only)
{
  CGAL_precondition(!grid_only || voxel > 0.);
  Point_set points;
  points.reserve(model.points.size());
  for(const auto& p : model.points)
    points.insert(p);
  const Point_map point_map = points.point_map();
  const Kernel::Iso_cuboid_3 bbox = CGAL::bounding_box(
    CGAL::make_transform_iterator_from_property_map(points.begin(), point_map),
    CGAL::make_transform_iterator_from_property_map(points.end(), point_map));

  if(threads == 1 && !grid_only)
  {
    // one thread: CGAL's generator itself, the reference of the path below
    Generator generator(points, point_map, std::max(1u, scale_count), voxel > 0. ? float(voxel) : -1.f);
    CGAL::Classification::Feature_set features;
    generator.generate_point_based_features(features);
    append_columns(features, points.size(), 1, columns);
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  // --threads bounds CGAL's loops over the points, the eigen analyses' and the features'
  std::unique_ptr<tbb::global_control> limit;
  if(threads != 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#endif
  const std::vector<Scale> scales = build_scales(points, bbox, scale_count, voxel, threads, grid_only);
  CGAL::Classification::Feature_set features;
  add_generator_features(features, points, point_map, scales, grid_only);
  append_columns(features, points.size(), threads, columns);
}

void append_anchored_cgal_features(const SN::Oriented_point_set& model, unsigned int scales, double voxel,
                                   unsigned int threads, std::vector<Feature_column>& columns, bool grid_only)
{
  namespace SNC = SN::Classification;
  std::vector<std::pair<std::string, std::vector<float>>> features;
  SNC::compute_anchored_cgal_features<SN::Parallel_if_available_tag>(
    model.points, float(voxel), scales, grid_only ? SNC::Anchored_cgal_features::GRIDS_ONLY : SNC::Anchored_cgal_features::ALL,
    std::back_inserter(features), SN::parameters::neighbor_search(CLASSIFICATION_NEIGHBOR_SEARCH, SN::parameters::number_of_threads(threads)));
  // the columns in double, one per thread at a time (each allocated and filled by its thread)
  const std::size_t first = columns.size();
  for(const auto& f : features)
    columns.push_back(Feature_column{f.first, {}});
  for_each_item(0, features.size(), threads, [&](std::size_t c) {
    std::vector<float>& values = features[c].second;
    columns[first + c].values.assign(values.begin(), values.end());
    std::vector<float>().swap(values);
  });
}

double anchored_cgal_grid_reach(const Feature_options& o)
{
  return SN::Classification::anchored_cgal_grid_reach(float(o.cgal_voxel), o.cgal_scales);
}

double anchored_cgal_halo_width(const SN::Oriented_point_set& model, unsigned int scales, double voxel, bool grid_only,
                                unsigned int threads, const CGAL::Bbox_2& extent, std::size_t first, std::size_t last)
{
  double width = SN::Classification::anchored_cgal_grid_reach(float(voxel), scales) * (1. + 1e-6);
  if(grid_only || first == last)
    return width;
  const std::vector<double> reach = SN::Classification::anchored_cgal_neighbor_reach<SN::Parallel_if_available_tag>(
    model.points, float(voxel), scales, first, last, SN::parameters::neighbor_search(CLASSIFICATION_NEIGHBOR_SEARCH, SN::parameters::number_of_threads(threads)));
  for(std::size_t i = first; i < last; ++i)
    width = std::max(width, halo_needed(model.points[i].x(), model.points[i].y(), extent, reach[i - first]));
  return width;
}

} // namespace sigmoid_tool
