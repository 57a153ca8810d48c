// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The evaluation: per-point evaluation and mergeable statistics in the library; evaluate, merge,
// resume and report through the command-line tool.

#include "test_models.h"

#include <CGAL/Sigmoid_neighborhoods.h>
#include "evaluation_statistics.h"
#include <CGAL/IO/OFF.h>
#include <CGAL/property_map.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <boost/property_map/property_map.hpp>
#include <map>

#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& file)
{
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int run(const std::string& arguments)
{
  const std::string command = std::string(SN_TOOL_PATH) + " " + arguments + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A folder of models: grid cubes of several sizes, noisy spheres with normals, in sub-folders.
const fs::path& repository()
{
  // removed when the test program ends
  struct Scratch
  {
    fs::path root;
    ~Scratch() { std::error_code ec; fs::remove_all(root, ec); }
  };
  static Scratch scratch;
  static const fs::path dir = [] {
    char name[] = "/tmp/sn_eval_XXXXXX";
    const fs::path root = ::mkdtemp(name);
    scratch.root = root;
    const fs::path models = root / "models";
    fs::create_directories(models / "cubes");
    fs::create_directories(models / "spheres");
    for(int n : {3, 4, 6, 9})
      CGAL::IO::write_OFF((models / "cubes" / ("cube" + std::to_string(n) + ".off")).string(),
                          make_grid_cube(n, 1. / n), CGAL::parameters::stream_precision(17));
    std::mt19937_64 rng(3);
    std::normal_distribution<double> noise(0., 0.002);
    for(int s = 0; s < 3; ++s)
    {
      std::ofstream out(models / "spheres" / ("sphere" + std::to_string(s) + ".xyz"));
      out.precision(17);
      const int n = 300 + 200 * s;
      for(int i = 0; i < n; ++i)
      {
        const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = 2.399963229728653 * i;
        out << r * std::cos(phi) + noise(rng) << ' ' << r * std::sin(phi) + noise(rng) << ' ' << z + noise(rng) << ' '
            << r * std::cos(phi) << ' ' << r * std::sin(phi) << ' ' << z << '\n';
      }
    }
    return root;
  }();
  return dir;
}

fs::path models() { return repository() / "models"; }
fs::path out(const std::string& name) { return repository() / name; }

} // namespace

TEST_CASE("evaluation: per-point optimum equals compute_optimal_sigmoid_neighborhoods", "[evaluation]")
{
  Mesh cube = make_grid_cube(5, 0.2);
  std::vector<Point_with_normal> points;
  std::map<Mesh::Vertex_index, Vector_3> normals;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(cube, boost::make_assoc_property_map(normals));
  for(auto v : cube.vertices())
    points.emplace_back(cube.point(v), normals[v]);
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                    .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>());
  std::vector<SN::Point_evaluation> evaluations;
  std::vector<SN::Optimal_sigmoid_neighborhood> optimal;
  SN::evaluate_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(evaluations), np);
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(points, std::back_inserter(optimal), np);
  REQUIRE(evaluations.size() == points.size());
  std::size_t edges = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const auto& e = evaluations[i];
    CHECK(e.optimal.error() == optimal[i].error());
    CHECK(e.optimal.k == optimal[i].k);
    CHECK(e.optimal.error_equal == optimal[i].error_equal);
    const Point_3& p = points[i].first;
    const int border = (p.x() == 0 || p.x() == 1) + (p.y() == 0 || p.y() == 1) + (p.z() == 0 || p.z() == 1);
    if(border == 2)
    {
      // a cube edge: a* = b* = 0, both at the bottom of Table 3; the cut-off keeps the edge, E = 0
      ++edges;
      CHECK(e.a_lowering == SN::Point_evaluation::Lowering::AT_BOTTOM);
      CHECK(e.b_lowering == SN::Point_evaluation::Lowering::AT_BOTTOM);
      CHECK(e.error_cut_off == Approx(0.).margin(1e-12));
      CHECK(e.cut_off_label == SN::Dimensionality::LINEAR);
    }
  }
  CHECK(edges == 12 * 4);
}

TEST_CASE("evaluation: statistics of two halves merge into the whole", "[evaluation]")
{
  Mesh cube = make_grid_cube(6, 1.);
  std::vector<Point_with_normal> points;
  std::map<Mesh::Vertex_index, Vector_3> normals;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(cube, boost::make_assoc_property_map(normals));
  for(auto v : cube.vertices())
    points.emplace_back(cube.point(v), normals[v]);
  std::vector<SN::Point_evaluation> evaluations;
  SN::evaluate_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    points, std::back_inserter(evaluations),
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
  const auto grid = SN::defaults::angle_grid();
  SN::Evaluation_statistics whole(6, 20, grid, grid), first(6, 20, grid, grid), second(6, 20, grid, grid);
  for(std::size_t i = 0; i < evaluations.size(); ++i)
  {
    whole.add(evaluations[i]);
    (i < 100 ? first : second).add(evaluations[i]);
  }
  first.merge(second);
  CHECK(first.points == whole.points);
  CHECK(first.optimal.count == whole.optimal.count);
  CHECK(first.cut_off.failures == whole.cut_off.failures);
  CHECK(first.optimal.min == whole.optimal.min);
  CHECK(first.optimal.max == whole.optimal.max);
  CHECK(first.optimal.sum == Approx(whole.optimal.sum).epsilon(1e-12));
  CHECK(first.pair_k_histogram == whole.pair_k_histogram);
  CHECK(first.a_lowering == whole.a_lowering);
  CHECK(first.b_lowering == whole.b_lowering);
  CHECK(first.optimal.k_histogram == whole.optimal.k_histogram);
  // Table 3 groups each sum to the points with an optimum
  CHECK(whole.a_lowering[0] + whole.a_lowering[1] + whole.a_lowering[2] == whole.optimal.count);
  CHECK(whole.b_lowering[0] + whole.b_lowering[1] + whole.b_lowering[2] == whole.optimal.count);
  const auto km = whole.k_mean_and_deviation();
  CHECK(km.first >= 6.);
  CHECK(km.first <= 20.);
  SN::Evaluation_statistics other_grid(6, 19, grid, grid);
  CHECK_THROWS_AS(first.merge(other_grid), std::invalid_argument);
}

TEST_CASE("evaluate: three shards merge into the single run, byte for byte", "[evaluation][cli]")
{
  REQUIRE(run("evaluate " + models().string() + " -o " + out("single").string() + " --repository demo") == 0);
  for(int i = 1; i <= 3; ++i)
    REQUIRE(run("evaluate " + models().string() + " -o " + out("shard" + std::to_string(i)).string() +
                " --repository demo --shard " + std::to_string(i) + "/3 --threads 1") == 0);
  std::size_t in_shards = 0;
  for(int i = 1; i <= 3; ++i)
    for(const auto& e : fs::recursive_directory_iterator(out("shard" + std::to_string(i)) / "models"))
      in_shards += e.path().extension() == ".json";
  CHECK(in_shards == 7);
  REQUIRE(run("merge " + out("shard1").string() + " " + out("shard2").string() + " " + out("shard3").string() +
              " -o " + out("merged").string()) == 0);
  const std::string single = read_text(out("single") / "summary.json");
  CHECK(single.find("\"models\": 7") != std::string::npos);
  CHECK(read_text(out("merged") / "summary.json") == single);
  // the same shard twice is refused
  CHECK(run("merge " + out("shard1").string() + " " + out("shard1").string() + " -o " + out("twice").string()) == 2);
}

TEST_CASE("evaluate: a corrupt model lands in failures.json, the others are unaffected", "[evaluation][cli]")
{
  const fs::path with_bad = out("with_bad_inputs");
  fs::create_directories(with_bad);
  fs::copy(models(), with_bad, fs::copy_options::recursive);
  std::ofstream(with_bad / "cubes" / "truncated.off") << "OFF\n8 6 0\n0 0 0\n1 0";
  std::ofstream(with_bad / "empty.xyz");
  REQUIRE(run("evaluate " + with_bad.string() + " -o " + out("bad_run").string() + " --repository demo") == 0);
  const std::string failures = read_text(out("bad_run") / "failures.json");
  CHECK(failures.find("cubes/truncated.off") != std::string::npos);
  CHECK(failures.find("empty.xyz") != std::string::npos);
  if(!fs::exists(out("single") / "summary.json"))
    REQUIRE(run("evaluate " + models().string() + " -o " + out("single").string() + " --repository demo") == 0);
  for(const auto& e : fs::recursive_directory_iterator(out("single") / "models"))
  {
    if(!e.is_regular_file())
      continue;
    const fs::path relative = fs::relative(e.path(), out("single"));
    CHECK(read_text(out("bad_run") / relative) == read_text(e.path()));
  }
  const std::string summary = read_text(out("bad_run") / "summary.json");
  CHECK(summary.find("\"failed_models\": 2") != std::string::npos);
}

TEST_CASE("evaluate: a model too small for the grid is listed apart from the failed ones", "[evaluation][cli]")
{
  const fs::path in = out("small_in");
  fs::create_directories(in);
  fs::copy(models() / "spheres" / "sphere0.xyz", in / "sphere0.xyz");
  {
    std::ofstream tiny(in / "tiny.xyz");
    for(int i = 0; i < 8; ++i)
      tiny << (i & 1) << ' ' << ((i >> 1) & 1) << ' ' << ((i >> 2) & 1) << " 0 0 1\n";
  }
  std::ofstream(in / "empty.xyz");
  REQUIRE(run("evaluate " + in.string() + " -o " + out("small_run").string() + " --repository demo") == 0);
  const std::string failures = read_text(out("small_run") / "failures.json");
  CHECK(failures.find("\"model\": \"tiny.xyz\",\n      \"needed\": 21,\n      \"points\": 8") != std::string::npos);
  const std::string summary = read_text(out("small_run") / "summary.json");
  CHECK(summary.find("\"models\": 1,") != std::string::npos);
  CHECK(summary.find("\"failed_models\": 1,") != std::string::npos);
  CHECK(summary.find("\"too_small_models\": 1,") != std::string::npos);
  CHECK(summary.find("\"failed\": [\n    \"empty.xyz\"\n  ]") != std::string::npos);
  // the report lists both, the failure with its message
  run("report " + out("small_run").string() + " -o " + out("small_report").string());
  const std::string md = read_text(out("small_report") / "report.md");
  CHECK(md.find("| demo | 1 | 1 | 1 | 300 |") != std::string::npos);
  CHECK(md.find("| demo | tiny.xyz | 8 | 21 |") != std::string::npos);
  CHECK(md.find("| demo | empty.xyz | the file is empty |") != std::string::npos);
  // merge keeps both lists: the merged summary is the same
  CHECK(run("merge " + out("small_run").string() + " -o " + out("small_merged").string()) == 0);
  CHECK(read_text(out("small_merged") / "summary.json") == summary);
}

namespace {

// Starts the tool in a child process, stderr to `error_file`; `in_child` runs just before exec.
pid_t spawn_tool(const std::vector<std::string>& arguments, const fs::path& error_file,
                 const std::function<void()>& in_child = {})
{
  const pid_t child = ::fork();
  if(child == 0)
  {
    if(!::freopen(error_file.c_str(), "w", stderr))
      ::_exit(126);
    if(in_child)
      in_child();
    std::vector<char*> argv{const_cast<char*>(SN_TOOL_PATH)};
    for(const std::string& a : arguments)
      argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SN_TOOL_PATH, argv.data());
    ::_exit(127);
  }
  return child;
}

int wait_for(pid_t child)
{
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

const fs::path& single_run()
{
  static const fs::path dir = [] {
    const fs::path d = out("single");
    if(!fs::exists(d / "summary.json"))
      REQUIRE(run("evaluate " + models().string() + " -o " + d.string() + " --repository demo") == 0);
    return d;
  }();
  return dir;
}

// Every model file in `dir` is complete: byte for byte the uninterrupted run's.
void check_model_files_complete(const fs::path& dir)
{
  if(!fs::exists(dir / "models"))
    return;
  for(const auto& e : fs::recursive_directory_iterator(dir / "models"))
    if(e.is_regular_file() && e.path().extension() == ".json")
    {
      INFO(e.path());
      CHECK(read_text(e.path()) == read_text(single_run() / fs::relative(e.path(), dir)));
    }
}

std::size_t count_temporary_files(const fs::path& dir)
{
  std::size_t count = 0;
  if(fs::exists(dir))
    for(const auto& e : fs::recursive_directory_iterator(dir))
      count += e.path().filename().string().find(".tmp.") != std::string::npos;
  return count;
}

} // namespace

TEST_CASE("evaluate: runs killed with SIGKILL at random moments and resumed equal the uninterrupted run",
          "[evaluation][cli][faults]")
{
  const std::string all_models = models().string();
  const std::vector<std::string> arguments = {"evaluate", all_models, "-o", out("killed").string(), "--repository",
                                              "demo", "--threads", "1", "--resume"};
  // the duration of a whole run on this machine (and build) bounds the random moments
  fs::remove_all(out("killed"));
  const auto start = std::chrono::steady_clock::now();
  REQUIRE(WEXITSTATUS(wait_for(spawn_tool(arguments, out("killed.err")))) == 0);
  const double whole_run = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(read_text(out("killed") / "summary.json") == read_text(single_run() / "summary.json"));

  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> moment(0., whole_run);
  int interrupted = 0, rounds = 0;
  for(; interrupted < 6 && rounds < 40; ++rounds)
  {
    fs::remove_all(out("killed"));
    // one or two kills in a row, the second one of a resumed run, then a resume to the end
    for(int kill = 0; kill < 1 + rounds % 2; ++kill)
    {
      const pid_t child = spawn_tool(arguments, out("killed.err"));
      REQUIRE(child > 0);
      std::this_thread::sleep_for(std::chrono::duration<double>(moment(rng)));
      ::kill(child, SIGKILL);
      const int status = wait_for(child);
      interrupted += WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
      check_model_files_complete(out("killed"));
    }
    // a temporary as a kill in the middle of a write leaves it (rare here: the writes are short)
    fs::create_directories(out("killed") / "models" / "cubes");
    std::ofstream(out("killed") / "models" / "cubes" / "cube9.off.json.tmp.4242") << "{\"points\": 3";
    REQUIRE(WEXITSTATUS(wait_for(spawn_tool(arguments, out("killed.err")))) == 0);
    CHECK(read_text(out("killed") / "summary.json") == read_text(single_run() / "summary.json"));
    check_model_files_complete(out("killed"));
    CHECK(count_temporary_files(out("killed")) == 0);
  }
  INFO(rounds << " rounds");
  CHECK(interrupted >= 6);
}

TEST_CASE("evaluate and optimal: a full disk gives a clear error and leaves no half-written file",
          "[evaluation][cli][faults]")
{
  // A file size limit below one model file makes every write fail with EFBIG, as a full disk does
  // with ENOSPC, without needing a small file system.
  const auto limit_file_size = [] {
    ::signal(SIGXFSZ, SIG_IGN);
    const struct rlimit limit = {4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  };
  const fs::path full = out("full");
  fs::remove_all(full);
  int status = wait_for(spawn_tool({"evaluate", models().string(), "-o", full.string(), "--threads", "1"},
                                   out("full.err"), limit_file_size));
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  std::string message = read_text(out("full.err"));
  CHECK(message.find("cannot write") != std::string::npos);
  CHECK(message.find(std::strerror(EFBIG)) != std::string::npos);
  CHECK_FALSE(fs::exists(full / "summary.json"));
  check_model_files_complete(full);
  CHECK(count_temporary_files(full) == 0);

  const std::string mesh = (models() / "cubes" / "cube9.off").string();
  status = wait_for(spawn_tool({"optimal", mesh, "-o", (full / "cube.csv").string(), "--ply", (full / "cube.ply").string()},
                               out("full.err"), limit_file_size));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(read_text(out("full.err")).find(std::strerror(EFBIG)) != std::string::npos);
  CHECK_FALSE(fs::exists(full / "cube.csv"));
  CHECK_FALSE(fs::exists(full / "cube.ply"));
  CHECK(count_temporary_files(full) == 0);
  // a LAS output, whose header is written again at its end
  status = wait_for(spawn_tool({"optimal", mesh, "-o", (full / "cube.las").string()}, out("full.err"), limit_file_size));
  CHECK(WEXITSTATUS(status) == 2);
  message = read_text(out("full.err"));
  CHECK(message.find(std::strerror(EFBIG)) != std::string::npos);
  CHECK(std::count(message.begin(), message.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(full / "cube.las"));
  CHECK(count_temporary_files(full) == 0);

  // an output folder that cannot be created: its parent is a file
  std::ofstream(out("a_file")) << "x";
  status = wait_for(spawn_tool({"evaluate", models().string(), "-o", (out("a_file") / "sub").string()}, out("full.err")));
  CHECK(WEXITSTATUS(status) == 2);
  message = read_text(out("full.err"));
  CHECK(message.find("cannot create") != std::string::npos);
  CHECK(std::count(message.begin(), message.end(), '\n') == 1);
}

TEST_CASE("evaluate: the same input gives the same bytes on 1, 2 and 3 threads and on every run",
          "[evaluation][cli][threads]")
{
  std::vector<fs::path> runs;
  for(const char* threads : {"1", "2", "3", "2"})
  {
    runs.push_back(out(std::string("threads") + threads + "_" + std::to_string(runs.size())));
    fs::remove_all(runs.back());
    REQUIRE(WEXITSTATUS(wait_for(spawn_tool({"evaluate", models().string(), "-o", runs.back().string(), "--threads",
                                             threads, "--per-point", "--repository", "demo"},
                                            out("threads.err")))) == 0);
  }
  std::size_t compared = 0;
  for(const auto& e : fs::recursive_directory_iterator(runs.front()))
  {
    // run.json alone records the date, the host and the duration
    if(!e.is_regular_file() || e.path().filename() == "run.json")
      continue;
    const std::string expected = read_text(e.path());
    for(std::size_t r = 1; r < runs.size(); ++r)
    {
      INFO(runs[r] / fs::relative(e.path(), runs.front()));
      CHECK(read_text(runs[r] / fs::relative(e.path(), runs.front())) == expected);
    }
    ++compared;
  }
  CHECK(compared == 2 + 2 * 7); // summary, failures, and a JSON and a CSV per model
}

TEST_CASE("report: renders for one and for two repositories", "[evaluation][cli]")
{
  if(!fs::exists(out("single") / "summary.json"))
    REQUIRE(run("evaluate " + models().string() + " -o " + out("single").string() + " --repository demo") == 0);
  REQUIRE(run("evaluate " + (models() / "spheres").string() + " -o " + out("spheres").string() +
              " --repository spheres --per-point") == 0);
  const bool can_plot = std::system("/usr/bin/python3 -c 'import matplotlib, numpy' > /dev/null 2>&1") == 0;
  for(const std::string& folders : {out("single").string(), out("single").string() + " " + out("spheres").string()})
  {
    const fs::path dir = out(folders.find(' ') == std::string::npos ? "report1" : "report2");
    const int code = run("report " + folders + " -o " + dir.string());
    const std::string md = read_text(dir / "report.md");
    CHECK(md.find("## Table 2") != std::string::npos);
    CHECK(md.find("## Table 3") != std::string::npos);
    CHECK(md.find("demo: optimal") != std::string::npos);
    CHECK((folders.find(' ') == std::string::npos) == (md.find("spheres: optimal") == std::string::npos));
    if(can_plot)
    {
      CHECK(code == 0);
      for(const char* png : {"figure4_ab_histogram.png", "figure5_k_histogram.png", "figure6_k_deviation.png"})
        CHECK(fs::file_size(dir / png) > 10000);
    }
    else
      WARN("matplotlib not found: figures not checked");
  }
  // the two-repository report found the per-point values of a sphere for Figure 3
  if(can_plot)
    CHECK(fs::exists(out("report2") / "figure3_per_point.png"));
}

TEST_CASE("evaluate: a symbolic link is named by its own path and written inside OUTDIR", "[evaluation][cli]")
{
  const fs::path linked = out("linked");
  fs::create_directories(linked / "in");
  fs::create_symlink(models() / "cubes" / "cube4.off", linked / "in" / "alias.off");
  REQUIRE(run("evaluate " + (linked / "in").string() + " -o " + (linked / "out").string()) == 0);
  CHECK(fs::exists(linked / "out" / "models" / "alias.off.json"));
  CHECK(read_text(linked / "out" / "summary.json").find("\"models\": 1") != std::string::npos);
}
