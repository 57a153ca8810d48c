// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times, on the same points in one run:
//  (a) CGAL's Classification::Local_eigen_analysis at k = 20 (plain PCA features),
//  (b) the plain loop: every one of the 420 triples, one covariance and one eigen solve each,
//  (c) the package's optimal search, (d) the package's features for one fixed (a, b, k),
//  (e) the equal-weights search (a_grid = b_grid = {pi}: the best k alone, Weinmann's optimal size),
//  (f) the optimal search with the classification features at each optimum (compute_optimal_point_features()),
//  (g) the peer: pgeof's optimal size (k = 6..20, float32) on nanoflann (pgeof_peer.h), where nanoflann is installed,
//  (h) nanoflann's k-NN query on the same points (doubles) and k as the package's k-NN share,
// and checks that (b) and (c) give the same (a*, b*, k*, E) on every point.
//
//   optimal_search_benchmark [--points N] [--threads T] [--data sphere|fandisk|scan|all]
//                            [--fandisk FILE] [--scan FILE] [--skip-plain] [--repeat R]
//                            [--order hilbert|random] [--scan-order as-read|hilbert|random]
//                            [--only a,c,d,e,f,g,h,knn]  (the others print 0 s)

#include <Sigmoid_neighborhoods_readers/option_names.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Classification/Local_eigen_analysis.h>
#include <CGAL/Classification/Point_set_neighborhood.h>
#include <CGAL/Random.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Sigmoid_neighborhoods.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/property_map.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/range/iterator_range.hpp>

#include <Eigen/Core>

#ifdef SN_BENCHMARK_HAS_NANOFLANN
#include "pgeof_peer.h"
#endif

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
namespace SN = CGAL::Sigmoid_neighborhoods;

struct Data
{
  std::string name;
  std::vector<Point_3> points;
  std::vector<Vector_3> normals;
  std::string order = "as read";
};

// Uniform random points on the unit sphere, normals pointing out.
Data sampled_sphere(std::size_t n)
{
  Data d{"sphere", {}, {}, "random"};
  std::mt19937_64 rng(1);
  std::normal_distribution<double> g;
  for(std::size_t i = 0; i < n; ++i)
  {
    Vector_3 v(g(rng), g(rng), g(rng));
    v = v / std::sqrt(v.squared_length());
    d.points.push_back(CGAL::ORIGIN + v);
    d.normals.push_back(v);
  }
  return d;
}

// Random points on the fandisk's triangles, normals interpolated from the vertex normals.
Data upsampled_fandisk(const std::string& file, std::size_t n)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  Mesh mesh;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(file, mesh) || mesh.is_empty())
    throw std::runtime_error("cannot read " + file);
  auto vn = mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:n").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, vn);
  std::vector<Mesh::Face_index> faces(mesh.faces().begin(), mesh.faces().end());
  std::vector<double> area;
  for(auto f : faces)
  {
    auto h = mesh.halfedge(f);
    area.push_back(std::sqrt(CGAL::squared_area(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                                mesh.point(mesh.target(mesh.next(h))))));
  }
  std::mt19937_64 rng(2);
  std::discrete_distribution<std::size_t> pick(area.begin(), area.end());
  std::uniform_real_distribution<double> u(0., 1.);
  Data d{"fandisk", {}, {}, "random"};
  for(std::size_t i = 0; i < n; ++i)
  {
    auto h = mesh.halfedge(faces[pick(rng)]);
    Mesh::Vertex_index v[3] = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
    double s = u(rng), t = u(rng);
    if(s + t > 1.)
    {
      s = 1. - s;
      t = 1. - t;
    }
    const double w[3] = {1. - s - t, s, t};
    Vector_3 p = CGAL::NULL_VECTOR, nn = CGAL::NULL_VECTOR;
    for(int c = 0; c < 3; ++c)
    {
      p = p + w[c] * (mesh.point(v[c]) - CGAL::ORIGIN);
      nn = nn + w[c] * vn[v[c]];
    }
    d.points.push_back(CGAL::ORIGIN + p);
    d.normals.push_back(nn / std::sqrt(nn.squared_length()));
  }
  return d;
}

// The points in Hilbert order, as a scan or a mesh gives them: neighbors in space are mostly
// neighbors in memory. Generated samples are otherwise in random order, where every query and every
// neighbor is a cache miss once the points outgrow the cache.
void shuffle(Data& d)
{
  std::vector<std::size_t> order(d.points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(3));
  Data shuffled{d.name, {}, {}, "random"};
  for(std::size_t i : order)
  {
    shuffled.points.push_back(d.points[i]);
    shuffled.normals.push_back(d.normals[i]);
  }
  d = std::move(shuffled);
}

void put_in_hilbert_order(Data& d)
{
  std::vector<std::size_t> order(d.points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const auto point_map = CGAL::make_property_map(static_cast<const std::vector<Point_3>&>(d.points));
  CGAL::hilbert_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, decltype(point_map)>(point_map));
  Data sorted{d.name, {}, {}, "Hilbert"};
  sorted.points.reserve(order.size());
  sorted.normals.reserve(order.size());
  for(std::size_t i : order)
  {
    sorted.points.push_back(d.points[i]);
    sorted.normals.push_back(d.normals[i]);
  }
  d = std::move(sorted);
}

Data scan(const std::string& file)
{
  // One thread: a file without normals has them estimated here, in the parent, and OpenMP threads
  // started before a fork() would leave the measuring child waiting for them forever.
  SN::Normal_options options;
  options.threads = 1;
  const SN::Oriented_point_set s = SN::read_oriented_point_set(file, options);
  return Data{std::filesystem::path(file).filename().string(), s.points, s.normals};
}

// The plain loop of SPEC §5 on the package's public building blocks: the neighborhoods of
// compute_k_nearest_neighbors(), the weights of Cosine_sigmoid, and for every triple one
// weighted_covariance() and one dimensionality_features() (an iterative eigen solve).
std::vector<SN::Optimal_sigmoid_neighborhood> plain_loop(const Data& data, unsigned int threads)
{
  const std::size_t n = data.points.size();
  const unsigned int k_min = SN::defaults::K_MIN, k_max = SN::defaults::K_MAX;
  std::vector<SN::Cosine_sigmoid> sigmoids; // a ascending, then b ascending (SPEC §5)
  for(double a : SN::defaults::angle_grid())
    for(double b : SN::defaults::angle_grid())
      if(a <= b)
        sigmoids.emplace_back(a, b);
  std::vector<std::uint32_t> rows;
  std::vector<std::size_t> offsets;
  SN::compute_k_nearest_neighbors<CGAL::Parallel_tag>(data.points, k_max, rows, offsets,
                                                      SN::parameters::number_of_threads(threads));
  // unit normals as SPEC §1 makes them: normals unit to 1e-12 are kept as given
  std::vector<Eigen::Vector3d> normals;
  for(const Vector_3& v : data.normals)
  {
    Eigen::Vector3d m(v.x(), v.y(), v.z());
    if(std::abs(m.squaredNorm() - 1.) > 1e-12)
      m /= std::sqrt(m.squaredNorm());
    normals.push_back(m);
  }
  std::vector<SN::Optimal_sigmoid_neighborhood> result(n);
  const std::int64_t count = std::int64_t(n);
#pragma omp parallel num_threads(int(threads))
  {
    std::vector<Point_3> neighborhood;
    std::vector<double> angles, w;
#pragma omp for schedule(dynamic, 16)
    for(std::int64_t i = 0; i < count; ++i)
    {
      neighborhood.assign(1, data.points[std::size_t(i)]);
      angles.assign(1, 0.);
      for(std::size_t e = offsets[std::size_t(i)]; e < offsets[std::size_t(i) + 1]; ++e)
      {
        neighborhood.push_back(data.points[rows[e]]);
        angles.push_back(SN::normal_angle(normals[std::size_t(i)], normals[rows[e]]));
      }
      w.resize(angles.size());
      SN::Optimal_sigmoid_neighborhood& r = result[std::size_t(i)];
      for(const SN::Cosine_sigmoid& sigmoid : sigmoids)
      {
        for(std::size_t j = 0; j < angles.size(); ++j)
          w[j] = sigmoid(angles[j]);
        for(unsigned int k = k_min; k <= k_max; ++k)
        {
          const double e = SN::dimensionality_features(
                             SN::weighted_covariance(boost::make_iterator_range(neighborhood.begin(),
                                                                                neighborhood.begin() + k + 1),
                                                     boost::make_iterator_range(w.begin(), w.begin() + k + 1)))
                             .error;
          if(e < r.error() - 1e-12) // the tie rule of SPEC §5
          {
            r.a = sigmoid.a();
            r.b = sigmoid.b();
            r.k = k;
            r.features.error = e;
          }
        }
      }
    }
  }
  return result;
}

std::size_t current_rss_bytes()
{
  long pages = 0, resident = 0;
  if(FILE* f = std::fopen("/proc/self/statm", "r"))
  {
    if(std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
      resident = 0;
    std::fclose(f);
  }
  return std::size_t(resident) * std::size_t(::sysconf(_SC_PAGESIZE));
}

// Runs `work` in a child process; returns its seconds, its peak memory above the start and the
// number `work` returns. A child per measurement isolates the peak memory; the parent itself never
// starts OpenMP threads, which a forked child could not use.
struct Measure
{
  double seconds = 0.;
  double extra_bytes = 0.;
  double value = 0.;
};

Measure measure(const std::function<double()>& work)
{
  int pipe_fd[2];
  if(::pipe(pipe_fd) != 0)
    throw std::runtime_error("pipe");
  const pid_t child = ::fork();
  if(child == 0)
  {
    ::close(pipe_fd[0]);
    // A forked child inherits its parent's peak memory (reading a file can exceed the search):
    // memory freed earlier goes back to the system, and the peak is reset to the current size.
    ::malloc_trim(0);
    if(FILE* f = std::fopen("/proc/self/clear_refs", "w"))
    {
      std::fputs("5", f);
      std::fclose(f);
    }
    const double before = double(current_rss_bytes());
    CGAL::Real_timer t;
    t.start();
    const double value = work();
    t.stop();
    struct rusage usage;
    ::getrusage(RUSAGE_SELF, &usage);
    const double m[3] = {t.time(), double(usage.ru_maxrss) * 1024. - before, value};
    if(::write(pipe_fd[1], m, sizeof(m)) != sizeof(m))
      ::_exit(1);
    ::_exit(0);
  }
  ::close(pipe_fd[1]);
  double m[3] = {0., 0., 0.};
  if(::read(pipe_fd[0], m, sizeof(m)) != sizeof(m))
    throw std::runtime_error("measurement failed");
  ::close(pipe_fd[0]);
  int status;
  ::waitpid(child, &status, 0);
  return Measure{m[0], m[1], m[2]};
}

// The fastest of `repeat` runs: on a shared machine, other load only ever adds time.
Measure measure(int repeat, const std::function<double()>& work)
{
  Measure best = measure(work);
  for(int r = 1; r < repeat; ++r)
  {
    const Measure m = measure(work);
    if(m.seconds < best.seconds)
      best = m;
  }
  return best;
}

// --only: the measurements to run (letters a, c, d, e, f, g, h and "knn"); empty: all
std::string only_measurements;
bool selected(const std::string& what)
{
  if(only_measurements.empty())
    return true;
  std::size_t start = 0;
  while(start <= only_measurements.size())
  {
    const std::size_t comma = only_measurements.find(',', start);
    const std::size_t end = comma == std::string::npos ? only_measurements.size() : comma;
    if(only_measurements.compare(start, end - start, what) == 0)
      return true;
    start = end + 1;
  }
  return false;
}

// The measurement, or a zero one when --only leaves it out.
Measure measure_if(const std::string& what, int repeat, const std::function<double()>& work)
{
  return selected(what) ? measure(repeat, work) : Measure{};
}

void run(const Data& data, int threads, bool with_plain, int repeat)
{
  const std::size_t n = data.points.size();
  std::vector<std::uint32_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = std::uint32_t(i);
  const auto np = SN::parameters::number_of_threads(unsigned(threads),
                                                    CGAL::parameters::point_map(CGAL::make_property_map(data.points))
                                                      .normal_map(CGAL::make_property_map(data.normals)));
  const double input_bytes = double(n) * (sizeof(Point_3) + sizeof(Vector_3));

  // (a) CGAL's PCA features at k = 20 (Sequential: CGAL's parallel code needs TBB).
  const Measure a = measure_if("a", repeat, [&] {
    typedef CGAL::Classification::Point_set_neighborhood<Kernel, std::vector<Point_3>,
                                                         CGAL::Identity_property_map<Point_3>> Neighborhood;
    Neighborhood neighborhood(data.points, CGAL::Identity_property_map<Point_3>(), CGAL::Sequential_tag());
    auto eigen = CGAL::Classification::Local_eigen_analysis::create_from_point_set(
      data.points, CGAL::Identity_property_map<Point_3>(), neighborhood.k_neighbor_query(20), CGAL::Sequential_tag());
    return double(eigen.eigenvalue(0)[0]);
  });
  // the k-NN share: one query of k_max = 20 neighbors per point
  const Measure knn = measure_if("knn", repeat, [&] {
    std::vector<std::uint32_t> rows;
    std::vector<std::size_t> offsets;
    SN::compute_k_nearest_neighbors<CGAL::Parallel_tag>(data.points, 20, rows, offsets,
                                                        SN::parameters::number_of_threads(unsigned(threads)));
    return double(rows.size());
  });
  // A search with `search_np`. The records are consumed as they come: the memory measured is the library's own.
  auto measure_search = [&](const std::string& what, const auto& search_np) {
    return measure_if(what, repeat, [&] {
      double checksum = 0.;
      SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(
        indices, boost::make_function_output_iterator([&](const SN::Optimal_sigmoid_neighborhood& r) {
          checksum += r.k;
        }), search_np);
      return checksum;
    });
  };
  // (c) the optimal search
  const Measure c = measure_search("c", np);
  // (e) equal weights only: the best k of SPEC §5 with a = b = pi
  const std::vector<double> pi{CGAL_PI};
  const auto equal_np = SN::parameters::a_grid(pi, SN::parameters::b_grid(pi, np));
  const Measure e = measure_search("e", equal_np);
  // (f) the optimal search and the point features at every optimum, in the search's pass
  const Measure f = measure_if("f", repeat, [&] {
    double checksum = 0.;
    SN::compute_optimal_point_features<CGAL::Parallel_tag>(
      indices, boost::make_function_output_iterator([&](const SN::Point_features& p) { checksum += p.verticality; }),
      np);
    return checksum;
  });
#ifdef SN_BENCHMARK_HAS_NANOFLANN
  // (g) the peer, from its float32 array as its users hand it (converted before the clock starts)
  std::vector<std::array<double, 3>> coordinates;
  for(const Point_3& p : data.points)
    coordinates.push_back({{p.x(), p.y(), p.z()}});
  const pgeof_peer::Peer_points peer_points(coordinates);
  const Measure g = measure_if("g", repeat, [&] {
    const std::vector<pgeof_peer::Result> r = pgeof_peer::optimal_features(peer_points, threads);
    double checksum = 0.;
    for(const pgeof_peer::Result& x : r)
      checksum += x.k;
    return checksum;
  });
  // (h) nanoflann's tree and its queries of the point and its 20 nearest, on the doubles
  const Measure h = measure_if("h", repeat, [&] { return double(pgeof_peer::nanoflann_k_nearest(peer_points, 21, threads)); });
#endif
  // (d) one fixed triple
  const Measure d = measure_if("d", repeat, [&] {
    std::vector<SN::Dimensionality_features> features;
    features.reserve(n);
    SN::compute_sigmoid_features<CGAL::Parallel_tag>(indices, SN::Cosine_sigmoid(0., CGAL_PI / 3), 20,
                                                     std::back_inserter(features), np);
    return features.back().error;
  });
  Measure b;
  std::string identical = "not-checked";
  if(with_plain)
  {
    b = measure(repeat, [&] {
      plain_loop(data, unsigned(threads));
      return 0.;
    });
    // (a*, b*, k*, E) of (b) and (c) on every point: the number of points where they differ
    const Measure check = measure([&] {
      const auto plain = plain_loop(data, unsigned(threads));
      std::vector<SN::Optimal_sigmoid_neighborhood> optimal, equal;
      SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(indices, std::back_inserter(optimal), np);
      SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_tag>(indices, std::back_inserter(equal), equal_np);
      std::size_t differ = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        const auto &p = plain[i], &o = optimal[i];
        const bool same = p.k == o.k && (p.k == 0 || (p.a == o.a && p.b == o.b)) &&
                          std::memcmp(&p.features.error, &o.features.error, sizeof(double)) == 0;
        // (e) is (c)'s equal-weights part
        const bool same_equal = equal[i].k == o.k_equal &&
                                std::memcmp(&equal[i].features.error, &o.error_equal, sizeof(double)) == 0;
        differ += !same || !same_equal;
      }
      return double(differ);
    });
    identical = check.value == 0. ? "yes" : "no";
    if(check.value != 0.)
      std::printf("  (b) and (c), or (c) and (e), differ on %.0f points\n", check.value);
  }
  auto rate = [n](const Measure& m) { return m.seconds > 0 ? double(n) / m.seconds : 0.; };
  std::printf("%s, %zu points (%s order), %d threads\n", data.name.c_str(), n, data.order.c_str(), threads);
  std::printf("  (a) CGAL Local_eigen_analysis k=20: %10.0f points/s (%.2f s, sequential)\n", rate(a), a.seconds);
  if(with_plain)
    std::printf("  (b) plain loop, 420 triples:       %10.0f points/s (%.2f s)\n", rate(b), b.seconds);
  std::printf("  vector instructions: %s\n", SN::vector_instructions_name(SN::widest_vector_instructions()));
  std::printf("  (c) optimal search:                 %10.0f points/s (%.2f s), %.0f bytes/point above the input\n",
              rate(c), c.seconds, c.extra_bytes / double(n));
  std::printf("  (d) features, one (a, b, k):        %10.0f points/s (%.2f s)\n", rate(d), d.seconds);
  std::printf("  (e) equal-weights search, 15 sizes: %10.0f points/s (%.2f s), %.0f bytes/point above the input\n",
              rate(e), e.seconds, e.extra_bytes / double(n));
  std::printf("  (f) (c) with the point features:    %10.0f points/s (%.2f s), %.1f %% above (c)\n", rate(f),
              f.seconds, 100. * (f.seconds / c.seconds - 1.));
  std::printf("  k-NN share of (c): %.1f %% (%.2f s for one 20-NN query per point)\n",
              100. * knn.seconds / c.seconds, knn.seconds);
  std::string peer_ratios = " optimal_over_pgeof=nan equal_over_pgeof=nan knn_over_nanoflann=nan";
#ifdef SN_BENCHMARK_HAS_NANOFLANN
  if(g.seconds > 0.)
  {
    std::printf("  (g) pgeof's optimal k = 6..20 on nanoflann (float32): %10.0f points/s (%.2f s), %.0f bytes/point\n",
                rate(g), g.seconds, g.extra_bytes / double(n));
    std::printf("  (c)/(g) %.2f, (e)/(g) %.2f\n", c.seconds / g.seconds, e.seconds / g.seconds);
    peer_ratios = " optimal_over_pgeof=" + std::to_string(c.seconds / g.seconds) +
                  " equal_over_pgeof=" + std::to_string(e.seconds / g.seconds);
  }
  else
    peer_ratios = " optimal_over_pgeof=nan equal_over_pgeof=nan";
  // (h) alone (--only knn,h) needs no (g)
  if(h.seconds > 0.)
  {
    std::printf("  (h) nanoflann's 20-NN query (doubles): %.2f s; the package's %.2f s (%.2fx)\n", h.seconds,
                knn.seconds, knn.seconds / h.seconds);
    peer_ratios += " knn_over_nanoflann=" + std::to_string(knn.seconds / h.seconds);
  }
  else
    peer_ratios += " knn_over_nanoflann=nan";
#endif
  std::printf("  input %.1f MB, (c) peak %.1f MB above it\n", input_bytes / 1e6, c.extra_bytes / 1e6);
  std::printf("summary: data=%s points=%zu threads=%d optimal_over_cgal_pca=%.2f equal_over_cgal_pca=%.2f "
              "plain_over_optimal=%s identical=%s%s\n",
              data.name.c_str(), n, threads, c.seconds / a.seconds, e.seconds / a.seconds,
              with_plain ? std::to_string(b.seconds / c.seconds).c_str() : "nan", identical.c_str(),
              peer_ratios.c_str());
  std::fflush(stdout);
}

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {100000, 1000000, 10000000};
  std::vector<int> threads = {1};
#ifdef _OPENMP
  if(omp_get_max_threads() > 1)
    threads.push_back(omp_get_max_threads());
#endif
  std::string which = "all", fandisk = SN_BENCHMARK_FANDISK, scan_file;
  bool with_plain = true;
  int repeat = 1;
  bool hilbert = true;
  std::string scan_order = "as-read";
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--points")
      sizes = {std::size_t(std::stod(next()))};
    else if(arg == "--threads")
      threads = {std::stoi(next())};
    else if(arg == "--data")
      which = next();
    else if(arg == "--fandisk")
      fandisk = next();
    else if(arg == "--scan")
      scan_file = next();
    else if(arg == "--skip-plain")
      with_plain = false;
    else if(arg == "--order")
    {
      const std::string order = next();
      if(order != "hilbert" && order != "random")
        throw std::runtime_error("--order takes hilbert or random");
      hilbert = order == "hilbert";
    }
    else if(arg == "--only")
      only_measurements = next();
    else if(arg == "--scan-order")
    {
      scan_order = next();
      if(scan_order != "as-read" && scan_order != "hilbert" && scan_order != "random")
        throw std::runtime_error("--scan-order takes as-read, hilbert or random");
    }
    else if(arg == "--repeat")
      repeat = (std::max)(1, std::stoi(next()));
    else
    {
      std::cerr << "usage: " << argv[0]
                << " [--points N] [--threads T] [--data sphere|fandisk|scan|all] [--fandisk FILE] [--scan FILE]"
                   " [--skip-plain] [--repeat R] [--order hilbert|random]"
                   " [--scan-order as-read|hilbert|random] [--only a,c,d,e,f,g,h,knn]\n";
      return 2;
    }
  }
  if(scan_file.empty() && std::filesystem::exists(SN_BENCHMARK_SHARED_DATA "/scanned"))
  {
    std::uintmax_t largest = 0;
    for(const auto& e : std::filesystem::directory_iterator(SN_BENCHMARK_SHARED_DATA "/scanned"))
      if(e.is_regular_file() && e.file_size() > largest)
      {
        largest = e.file_size();
        scan_file = e.path().string();
      }
  }
  for(std::size_t n : sizes)
  {
    std::vector<Data> data;
    if(which == "sphere" || which == "all")
      data.push_back(sampled_sphere(n));
    if((which == "fandisk" || which == "all") && std::filesystem::exists(fandisk))
      data.push_back(upsampled_fandisk(fandisk, n));
    for(Data& d : data)
      if(hilbert)
        put_in_hilbert_order(d);
    for(const Data& d : data)
      for(int t : threads)
        run(d, t, with_plain, repeat);
  }
  if((which == "scan" || which == "all") && !scan_file.empty())
  {
    Data d = scan(scan_file);
    if(scan_order == "random")
      shuffle(d);
    else if(scan_order == "hilbert")
      put_in_hilbert_order(d);
    for(int t : threads)
      run(d, t, with_plain, repeat);
  }
  return 0;
}
