// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The point-set denoising comparison: noise on the vertices of clean meshes, then the package's
// denoiser (Yadav et al.'s three stages, default and adaptive) and CGAL's smoothing
// (jet_smooth_point_set, bilateral_smooth_point_set), each measured by the distance of its points
// to the clean surface (CGAL's AABB_tree) and the mean squared error of its normals.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_DENOISING_COMPARISON_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_DENOISING_COMPARISON_H

#include "table4_data.h"

#include <CGAL/Sigmoid_neighborhoods/denoise_point_set.h>
#include "normal_noise.h"
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Real_timer.h>
#include <CGAL/bilateral_smooth_point_set.h>
#include <CGAL/jet_smooth_point_set.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

// The settings of the CGAL methods, stated in the table.
constexpr unsigned int COMPARISON_PCA_NEIGHBORS = 12;      // the initial normals (the authors')
constexpr unsigned int JET_SMOOTHING_NEIGHBORS = 18;       // jet_smooth_point_set, degree 2 fitting and monge
constexpr unsigned int BILATERAL_NEIGHBORS = 18;           // bilateral_smooth_point_set
constexpr double BILATERAL_SHARPNESS_ANGLE = 25.;          // degrees, CGAL's example
constexpr unsigned int BILATERAL_ITERATIONS = 3;           // CGAL's example

enum class Noise_direction
{
  NORMAL,    // p + e n, e ~ N(0, sigma^2), n the clean normal
  ISOTROPIC  // p + (e_x, e_y, e_z), each ~ N(0, sigma^2): the same spread along the normal, and across
};

typedef std::pair<Denoise_point, Denoise_vector> Denoise_item;

// What one method gave on one noisy model.
struct Method_result
{
  std::string method;
  double mean_distance = 0., rms_distance = 0., max_distance = 0., normal_mse = -1.; // normal_mse < 0: the method gives none
  double seconds = 0.;
  std::vector<double> distances; // per point
  std::vector<Denoise_point> points; // the method's output
  std::string note;
  // A reference rather than a competitor (the package at a fixed iteration count, which only the
  // clean surface tells how to choose): not ranked, not drawn.
  bool reference = false;
};

// The noisy points of a clean model: in vertex order, with the clean normals.
inline std::vector<Denoise_point> noisy_points(const std::vector<Denoise_point>& clean,
                                               const std::vector<Denoise_vector>& truth, double sigma,
                                               Noise_direction direction, std::uint64_t seed)
{
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> offset(0., sigma);
  std::vector<Denoise_point> result;
  result.reserve(clean.size());
  for(std::size_t i = 0; i < clean.size(); ++i)
  {
    if(direction == Noise_direction::NORMAL)
    {
      const Denoise_vector n = truth[i] / std::sqrt(truth[i].squared_length());
      result.push_back(clean[i] + offset(engine) * n);
    }
    else
    {
      const double x = offset(engine), y = offset(engine), z = offset(engine);
      result.push_back(clean[i] + Denoise_vector(x, y, z));
    }
  }
  return result;
}

// The distances of points to a clean surface.
class Surface_distance
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Denoise_mesh> Primitive;
  typedef CGAL::AABB_traits<Denoise_kernel, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

public:
  explicit Surface_distance(const Denoise_mesh& mesh) : m_tree(faces(mesh).first, faces(mesh).second, mesh)
  {
    m_tree.accelerate_distance_queries();
  }

  template <typename PointRange, typename PointMap>
  void measure(const PointRange& points, PointMap point_map, Method_result& r) const
  {
    r.distances.clear();
    r.max_distance = 0.;
    double sum = 0., squares = 0.;
    for(const auto& item : points)
    {
      const double d2 = m_tree.squared_distance(get(point_map, item));
      r.distances.push_back(std::sqrt(d2));
      sum += std::sqrt(d2);
      squares += d2;
      r.max_distance = (std::max)(r.max_distance, std::sqrt(d2));
    }
    const double n = double(r.distances.size());
    r.mean_distance = sum / n;
    r.rms_distance = std::sqrt(squares / n);
  }

private:
  Tree m_tree;
};

// Initial normals of noisy points: PCA on COMPARISON_PCA_NEIGHBORS neighbors, each turned to agree
// with the clean normal (as the experiments of yadav-normal-filtering.md §5), so that no orientation
// error enters the comparison.
inline std::vector<Denoise_item> with_pca_normals(const std::vector<Denoise_point>& points,
                                                  const std::vector<Denoise_vector>& truth, unsigned int threads)
{
  std::vector<Denoise_item> items;
  items.reserve(points.size());
  for(const auto& p : points)
    items.emplace_back(p, CGAL::NULL_VECTOR);
  SN::estimate_normals<SN::Parallel_if_available_tag>(
    items, COMPARISON_PCA_NEIGHBORS,
    SN::parameters::number_of_threads(threads)
      .point_map(CGAL::First_of_pair_property_map<Denoise_item>())
      .normal_map(CGAL::Second_of_pair_property_map<Denoise_item>()));
  for(std::size_t i = 0; i < items.size(); ++i)
    if(items[i].second * truth[i] < 0)
      items[i].second = -items[i].second;
  return items;
}

inline double items_normal_mse(const std::vector<Denoise_item>& items, const std::vector<Denoise_vector>& truth)
{
  std::vector<Denoise_vector> unit_truth, normals;
  for(std::size_t i = 0; i < items.size(); ++i)
  {
    unit_truth.push_back(truth[i] / std::sqrt(truth[i].squared_length()));
    const double length = std::sqrt(items[i].second.squared_length());
    normals.push_back(length > 0. ? items[i].second / length : items[i].second);
  }
  return SN::normal_mse(unit_truth, normals);
}

// The methods of the comparison on one noisy model, in the order of the table.
// `fixed_iterations`: references, the package's defaults without the stopping rule at each of these
// iteration counts (what the best stopping rule could give).
inline std::vector<Method_result> compare_denoisers(const std::vector<Denoise_item>& noisy,
                                                    const std::vector<Denoise_vector>& truth,
                                                    const Surface_distance& surface, unsigned int threads,
                                                    const std::vector<unsigned int>& fixed_iterations = {})
{
  const CGAL::First_of_pair_property_map<Denoise_item> point_map;
  const CGAL::Second_of_pair_property_map<Denoise_item> normal_map;
  std::vector<Method_result> results;
  auto run = [&](const std::string& name, bool has_normals,
                 const std::function<std::string(std::vector<Denoise_item>&)>& method) {
    Method_result r;
    r.method = name;
    std::vector<Denoise_item> items = noisy;
    CGAL::Real_timer timer;
    timer.start();
    r.note = method(items);
    timer.stop();
    r.seconds = timer.time();
    surface.measure(items, point_map, r);
    for(const auto& item : items)
      r.points.push_back(item.first);
    if(has_normals)
      r.normal_mse = items_normal_mse(items, truth);
    results.push_back(std::move(r));
  };
  run("noisy input", true, [](std::vector<Denoise_item>&) { return std::string(); });
  auto package = [&](const std::string& name, const auto& parameters) {
    run(name, true, [&](std::vector<Denoise_item>& items) {
      const SN::Point_set_denoising_summary s = SN::denoise_point_set<SN::Parallel_if_available_tag>(
        items, parameters.point_map(point_map).normal_map(normal_map));
      return std::to_string(s.iterations) + " iterations, noise level " + std::to_string(s.noise_estimate) + ", " +
             std::to_string(s.smooth) + " smooth, " + std::to_string(s.degenerate_fits) + " degenerate fits, " +
             std::to_string(s.planar) + " planar, " + std::to_string(s.edges) + " edges, " +
             std::to_string(s.corners) + " corners, " + std::to_string(s.refused) + " refused, " +
             std::to_string(s.rank_deficient) + " rank-deficient";
    });
  };
  namespace SNP = SN::parameters;
  package("package", SNP::number_of_threads(threads));
  // the package's stage 3 before the jet update: every planar point towards the weighted mean plane
  package("package, plane update", SNP::jet_vertex_update(false, SNP::number_of_threads(threads)));
  package("package, adaptive", SNP::adaptive_neighborhood_size(true, SNP::number_of_threads(threads)));
  // beyond the paper: every point's optimal sigmoid (a*, b*) weighs its votes
  package("package, (a*, b*) vote", SNP::optimal_vote_weights(true, SNP::number_of_threads(threads)));
  // the authors' order of stages 2 and 3 (Gauss-Seidel), and the authors' stage 3 itself
  package("package, in place", SNP::in_place_updates(true, SNP::number_of_threads(threads)));
  package("authors' stage 3", SNP::authors_vertex_update(true, SNP::rank_threshold(0., SNP::number_of_threads(threads))));
  for(unsigned int n : fixed_iterations)
  {
    package("package, " + std::to_string(n) + (n == 1 ? " iteration" : " iterations"),
            SNP::stop_at_noise_level(false, SNP::number_of_threads(threads)).number_of_iterations(n));
    results.back().reference = true;
  }
  run("CGAL jet", false, [&](std::vector<Denoise_item>& items) {
    CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(items, JET_SMOOTHING_NEIGHBORS,
                                                                CGAL::parameters::point_map(point_map));
    return std::string();
  });
  run("CGAL bilateral", true, [&](std::vector<Denoise_item>& items) {
    for(unsigned int i = 0; i < BILATERAL_ITERATIONS; ++i)
      CGAL::bilateral_smooth_point_set<CGAL::Parallel_if_available_tag>(
        items, BILATERAL_NEIGHBORS,
        CGAL::parameters::point_map(point_map).normal_map(normal_map).sharpness_angle(BILATERAL_SHARPNESS_ANGLE));
    return std::string();
  });
  return results;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_DENOISING_COMPARISON_H
