// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The accuracy of normal estimation and orientation on points sampled on CAD meshes with known face
// normals, with isotropic Gaussian noise of 0, 0.25 % and 0.5 % of the bounding-box diagonal (the
// measures of the PCPNet benchmark): CGAL's pca_estimate_normals() and jet_estimate_normals() with
// mst_orient_normals(), and the package's estimate_normals() with orient_normals_by_spanning_forest(),
// at equal neighbor counts, each on one thread.
//
//   normal_estimation_benchmark [--points N] [--neighbors K] [--seed S] [--csv FILE] [MESH...]
//   normal_estimation_benchmark --scaling SCAN [--threads T] [--neighbors K]
//
// Without meshes: the CAD models of CGAL's data (the `make corpus` copy) and of ../shared/data found
// on this machine; missing ones are skipped. --scaling times the steps of a raw scan's normals (the
// neighbor rows, PCA, jet fitting, the spanning forest) on 1 and T threads (default 2), fastest of 3.

#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/estimate_normals.h>
#include <CGAL/Sigmoid_neighborhoods/orient_normals.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/read_polygon_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#ifndef SN_BENCHMARK_CGAL_MESHES
#define SN_BENCHMARK_CGAL_MESHES "build/cgal-data/data/meshes"
#endif
#ifndef SN_BENCHMARK_SHARED_DATA
#define SN_BENCHMARK_SHARED_DATA "../shared/data"
#endif

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace SNP = SN::parameters;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::pair<Point, Vector> Point_with_normal;
typedef std::vector<Point_with_normal> Points;

namespace {

const std::vector<std::string> DEFAULT_MESHES = {
  SN_BENCHMARK_CGAL_MESHES "/fandisk.off",         SN_BENCHMARK_CGAL_MESHES "/anchor.off",
  SN_BENCHMARK_CGAL_MESHES "/joint.off",           SN_BENCHMARK_CGAL_MESHES "/couplingdown.off",
  SN_BENCHMARK_SHARED_DATA "/clean/trimesh_ADIS16480.STL", SN_BENCHMARK_SHARED_DATA "/clean/trimesh_featuretype.STL",
  SN_BENCHMARK_SHARED_DATA "/clean/gd_block.obj"};

// PCPNet's noise levels, as shares of the bounding-box diagonal.
const double NOISE_LEVELS[] = {0., 0.0025, 0.005};
// Within this angle a normal counts as accurate (PCPNet's "PGP10"-like share).
constexpr double ACCURATE_DEGREES = 10.;

struct Sample
{
  Points points;              // noisy positions, zero normals
  std::vector<Vector> truth;  // the unit normal of the face each point was drawn on
};

// Points uniform by area on the faces, isotropic Gaussian noise of `noise` times the diagonal.
Sample sample_mesh(const Mesh& mesh, std::size_t n, double noise, unsigned seed)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Mesh::Face_index> faces(mesh.faces().begin(), mesh.faces().end());
  std::vector<double> areas;
  for(auto f : faces)
    areas.push_back(PMP::face_area(f, mesh));
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  std::mt19937_64 rng(seed);
  std::discrete_distribution<std::size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> u(0., 1.);
  std::normal_distribution<double> gauss(0., noise * diagonal);
  Sample s;
  while(s.points.size() < n)
  {
    const auto f = faces[pick(rng)];
    const Vector normal = PMP::compute_face_normal(f, mesh);
    std::vector<Point> corners;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners.push_back(mesh.point(v));
    // a triangle fan for polygons, each triangle by its share of the face's area
    std::size_t t = 1;
    if(corners.size() > 3)
    {
      std::vector<double> fan;
      for(std::size_t i = 1; i + 1 < corners.size(); ++i)
        fan.push_back(std::sqrt(CGAL::cross_product(corners[i] - corners[0], corners[i + 1] - corners[0]).squared_length()));
      t = 1 + std::discrete_distribution<std::size_t>(fan.begin(), fan.end())(rng);
    }
    double r1 = std::sqrt(u(rng)), r2 = u(rng);
    const Vector p = (1 - r1) * (corners[0] - CGAL::ORIGIN) + r1 * (1 - r2) * (corners[t] - CGAL::ORIGIN) +
                     r1 * r2 * (corners[t + 1] - CGAL::ORIGIN);
    s.points.emplace_back(CGAL::ORIGIN + p + Vector(gauss(rng), gauss(rng), gauss(rng)), CGAL::NULL_VECTOR);
    s.truth.push_back(normal);
  }
  return s;
}

struct Accuracy
{
  double rms_degrees = 0., share_accurate = 0., share_flipped = 0., seconds = 0.;
};

Accuracy measure(const Points& estimated, const std::vector<Vector>& truth)
{
  Accuracy a;
  std::size_t accurate = 0, flipped = 0;
  double sum = 0.;
  for(std::size_t i = 0; i < truth.size(); ++i)
  {
    const Vector& n = estimated[i].second;
    const double cosine = n * truth[i] / std::sqrt(n.squared_length());
    const double degrees =
      std::atan2(std::sqrt(CGAL::cross_product(n, truth[i]).squared_length() / n.squared_length()), std::abs(cosine)) *
      180. / CGAL_PI;
    sum += degrees * degrees;
    accurate += degrees <= ACCURATE_DEGREES;
    flipped += cosine < 0.;
  }
  a.rms_degrees = std::sqrt(sum / double(truth.size()));
  a.share_accurate = double(accurate) / double(truth.size());
  a.share_flipped = double(flipped) / double(truth.size());
  return a;
}

auto maps()
{
  return CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
    .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>());
}

struct Row
{
  std::string model, method;
  double noise;
  Accuracy accuracy;
  std::size_t unoriented = 0, trees = 0;
};

template <typename Run>
Accuracy timed(Points& points, const std::vector<Vector>& truth, const Run& run)
{
  CGAL::Real_timer timer;
  timer.start();
  run(points);
  timer.stop();
  Accuracy a = measure(points, truth);
  a.seconds = timer.time();
  return a;
}

// The fastest of three runs of `run()`, in seconds.
template <typename Run>
double fastest(const Run& run)
{
  double best = std::numeric_limits<double>::infinity();
  for(int i = 0; i < 3; ++i)
  {
    CGAL::Real_timer timer;
    timer.start();
    run();
    timer.stop();
    best = std::min(best, timer.time());
  }
  return best;
}

int scaling(const std::string& file, unsigned int threads, unsigned int k)
{
  SN::Oriented_point_set scan = SN::read_oriented_point_set(file, 0);
  std::vector<std::uint32_t> ids(scan.points.size());
  std::iota(ids.begin(), ids.end(), 0u);
  scan.normals.assign(scan.points.size(), Vector(0, 0, 1));
  const auto maps = CGAL::parameters::point_map(CGAL::make_property_map(scan.points))
                      .normal_map(CGAL::make_property_map(scan.normals));
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  std::printf("%s: %zu points, k = %u\n\n| step | 1 thread (s) | %u threads (s) | parallel efficiency |\n|---|---:|---:|---:|\n",
              file.c_str(), scan.points.size(), k, threads);
  auto row = [&](const char* step, const auto& run) {
    const double one = fastest([&] { run(1u); }), many = fastest([&] { run(threads); });
    std::printf("| %s | %.3f | %.3f | %.0f %% |\n", step, one, many, 100. * one / (many * threads));
  };
  row("k-nearest-neighbor rows", [&](unsigned t) {
    SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(ids, k, indices, offsets, SNP::number_of_threads(t, maps));
  });
  auto rows = [&](unsigned t) {
    return SNP::neighbor_indices(std::cref(indices), SNP::neighbor_offsets(std::cref(offsets), SNP::number_of_threads(t, maps)));
  };
  row("pca", [&](unsigned t) { SN::estimate_normals<SN::Parallel_if_available_tag>(ids, k, rows(t)); });
  row("jet fitting", [&](unsigned t) {
    SN::estimate_normals<SN::Parallel_if_available_tag>(
      ids, k, SNP::normal_estimation_method(SN::Normal_estimation_method::JET, rows(t)));
  });
  row("spanning forest", [&](unsigned t) { SN::orient_normals_by_spanning_forest<SN::Parallel_if_available_tag>(ids, k, rows(t)); });
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t n = 20000;
  unsigned int k = SN::DEFAULT_ESTIMATION_NEIGHBORS;
  unsigned seed = 1;
  std::string csv, scan;
  unsigned int threads = 2;
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--points" && i + 1 < argc)
      n = std::stoul(argv[++i]);
    else if(arg == "--neighbors" && i + 1 < argc)
      k = unsigned(std::stoul(argv[++i]));
    else if(arg == "--seed" && i + 1 < argc)
      seed = unsigned(std::stoul(argv[++i]));
    else if(arg == "--csv" && i + 1 < argc)
      csv = argv[++i];
    else if(arg == "--scaling" && i + 1 < argc)
      scan = argv[++i];
    else if(arg == "--threads" && i + 1 < argc)
      threads = unsigned(std::stoul(argv[++i]));
    else if(!arg.empty() && arg[0] != '-')
      meshes.push_back(arg);
    else
    {
      std::cerr << "usage: normal_estimation_benchmark [--points N] [--neighbors K] [--seed S] [--csv FILE] [MESH...]\n"
                   "       normal_estimation_benchmark --scaling SCAN [--threads T] [--neighbors K]\n";
      return 2;
    }
  }
  if(!scan.empty())
    return scaling(scan, threads, k);
  if(meshes.empty())
    for(const std::string& m : DEFAULT_MESHES)
      if(std::filesystem::exists(m))
        meshes.push_back(m);
  if(meshes.empty())
  {
    std::cerr << "no meshes found (run make corpus, or give meshes)\n";
    return 0;
  }

  std::vector<Row> rows;
  for(const std::string& file : meshes)
  {
    Mesh mesh;
    try
    {
      SN::read_polygon_mesh(file, mesh);
    }
    catch(const std::exception& e)
    {
      std::cerr << file << ": skipped (" << e.what() << ")\n";
      continue;
    }
    const std::string model = std::filesystem::path(file).stem().string();
    for(double noise : NOISE_LEVELS)
    {
      const Sample s = sample_mesh(mesh, n, noise, seed);
      std::cerr << model << " noise " << noise << ": " << s.points.size() << " points\n";
      auto add = [&](const std::string& method, const Accuracy& a, std::size_t unoriented, std::size_t trees) {
        rows.push_back(Row{model, method, noise, a, unoriented, trees});
      };
      // CGAL's k, as the package's, counts the other points: the same neighbors (up to ties).
      Points cgal_pca = s.points, cgal_jet = s.points, pca = s.points, jet = s.points;
      add("CGAL pca", timed(cgal_pca, s.truth, [&](Points& p) { CGAL::pca_estimate_normals<CGAL::Sequential_tag>(p, k, maps()); }), 0, 0);
      add("CGAL jet", timed(cgal_jet, s.truth, [&](Points& p) { CGAL::jet_estimate_normals<CGAL::Sequential_tag>(p, k, maps()); }), 0, 0);
      std::size_t unoriented = 0;
      const Accuracy mst = timed(cgal_jet, s.truth, [&](Points& p) {
        unoriented = std::size_t(std::distance(CGAL::mst_orient_normals(p, k, maps()), p.end()));
      });
      add("CGAL jet + mst", mst, unoriented, 1);
      add("pca", timed(pca, s.truth, [&](Points& p) {
        SN::estimate_normals<CGAL::Sequential_tag>(p, k, maps()); // PCA, the default
      }), 0, 0);
      add("jet", timed(jet, s.truth, [&](Points& p) {
        SN::estimate_normals<CGAL::Sequential_tag>(p, k, SNP::normal_estimation_method(SN::Normal_estimation_method::JET, maps()));
      }), 0, 0);
      for(auto method : {std::make_pair("pca + forest", &pca), std::make_pair("jet + forest", &jet)})
      {
        std::size_t trees = 0;
        const Accuracy a = timed(*method.second, s.truth, [&](Points& p) {
          trees = SN::orient_normals_by_spanning_forest<CGAL::Sequential_tag>(p, k, maps());
        });
        add(method.first, a, 0, trees);
      }
    }
  }

  std::printf("| model | noise (%% diag) | method | RMS angle (deg) | within %.0f deg | flipped | unoriented | trees | s |\n",
              ACCURATE_DEGREES);
  std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|\n");
  for(const Row& r : rows)
  {
    const bool oriented = r.method.find('+') != std::string::npos;
    std::printf("| %s | %.2f | %s | %.2f | %.1f %% | %s | %s | %s | %.3f |\n", r.model.c_str(), 100. * r.noise,
                r.method.c_str(), r.accuracy.rms_degrees, 100. * r.accuracy.share_accurate,
                oriented ? (std::to_string(100. * r.accuracy.share_flipped).substr(0, 5) + " %").c_str() : "–",
                oriented ? std::to_string(r.unoriented).c_str() : "–", oriented ? std::to_string(r.trees).c_str() : "–",
                r.accuracy.seconds);
  }
  if(!csv.empty())
  {
    std::ofstream out(csv);
    out << "model,noise,method,rms_degrees,share_within_10_degrees,share_flipped,unoriented,trees,seconds\n";
    for(const Row& r : rows)
      out << r.model << ',' << r.noise << ',' << r.method << ',' << r.accuracy.rms_degrees << ','
          << r.accuracy.share_accurate << ',' << r.accuracy.share_flipped << ',' << r.unoriented << ',' << r.trees
          << ',' << r.accuracy.seconds << '\n';
  }
  return 0;
}
