// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tool on good and bad inputs: exit codes, messages, files left behind, and
// numbers equal to the library's.

#include "test_models.h"

#include <CGAL/Sigmoid_neighborhoods.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/read_polygon_mesh.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

// A scratch folder per test run.
const std::string& scratch()
{
  // removed when the test program ends
  struct Scratch
  {
    std::string root;
    ~Scratch() { std::error_code ec; std::filesystem::remove_all(root, ec); }
  };
  static Scratch scratch;
  static const std::string dir = [] {
    char name[] = "/tmp/sn_cli_XXXXXX";
    const char* made = ::mkdtemp(name);
    REQUIRE(made != nullptr);
    scratch.root = made;
    return std::string(made);
  }();
  return dir;
}

std::string path(const std::string& name) { return scratch() + "/" + name; }

bool exists(const std::string& file) { return std::ifstream(file).good(); }

std::string read_text(const std::string& file)
{
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_text(const std::string& file, const std::string& text) { std::ofstream(file) << text; }

struct Run
{
  int exit_code;
  std::string err;
};

Run run(const std::string& arguments)
{
  const std::string err_file = path("stderr.txt");
  const std::string command = std::string(SN_TOOL_PATH) + " " + arguments + " 2> " + err_file + " > /dev/null";
  const int status = std::system(command.c_str());
  return Run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(err_file)};
}

std::vector<std::vector<std::string>> read_csv(const std::string& file)
{
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
  {
    std::vector<std::string> cells;
    std::stringstream cells_in(line);
    std::string cell;
    while(std::getline(cells_in, cell, ','))
      cells.push_back(cell);
    if(!line.empty() && line.back() == ',')
      cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

std::string cube_off()
{
  const std::string file = path("cube.off");
  if(!exists(file))
    CGAL::IO::write_OFF(file, make_grid_cube(5, 0.2), CGAL::parameters::stream_precision(17));
  return file;
}

// A noisy sphere with outward normals, as `x y z nx ny nz` lines.
std::string sphere_xyz(int n, bool with_normals, const std::string& name)
{
  std::ostringstream out;
  out.precision(17);
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = 2.399963229728653 * i;
    out << r * std::cos(phi) << ' ' << r * std::sin(phi) << ' ' << z;
    if(with_normals)
      out << ' ' << r * std::cos(phi) << ' ' << r * std::sin(phi) << ' ' << z;
    out << '\n';
  }
  write_text(path(name), out.str());
  return path(name);
}

std::string number_line(const Point_3& p)
{
  std::ostringstream out;
  out.precision(17);
  out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  return out.str();
}

const std::string HEADER = "x,y,z,nx,ny,nz,a,b,k,error,linearity,planarity,scattering,label,error_equal,k_equal";

} // namespace

TEST_CASE("CLI: a mesh gives one CSV row per vertex and a PLY with the same values", "[cli]")
{
  const std::string csv = path("cube.csv"), ply = path("cube.ply");
  const Run r = run("optimal " + cube_off() + " -o " + csv + " --ply " + ply);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("152 points") != std::string::npos); // 6 * 5^2 + 2 vertices
  CHECK(r.err.find("0 failures") != std::string::npos);
  const auto rows = read_csv(csv);
  REQUIRE(rows.size() == 153);
  CHECK(read_text(csv).substr(0, HEADER.size() + 1) == HEADER + "\n");
  for(std::size_t i = 1; i < rows.size(); ++i)
  {
    REQUIRE(rows[i].size() == 16);
    const double error = std::stod(rows[i][9]);
    CHECK(error >= 0.);
    CHECK(error <= std::log(3.));
    CHECK(std::stod(rows[i][14]) >= error - 1e-12); // equal weights are one of the candidates
  }

  CGAL::Point_set_3<Point_3, Vector_3> ps;
  REQUIRE(CGAL::IO::read_point_set(ply, ps));
  REQUIRE(ps.size() == 152);
  CHECK(ps.has_normal_map());
  auto error = ps.property_map<double>("scalar_error");
  auto k = ps.property_map<int>("scalar_k");
  REQUIRE(error.second);
  REQUIRE(k.second);
  std::size_t i = 1;
  for(auto it = ps.begin(); it != ps.end(); ++it, ++i)
  {
    CHECK(error.first[*it] == std::stod(rows[i][9]));
    CHECK(k.first[*it] == std::stoi(rows[i][8]));
  }
}

TEST_CASE("CLI: CSV numbers equal the library's, and 1 or 2 threads write the same bytes", "[cli][threads]")
{
  const std::string input = sphere_xyz(400, true, "sphere.xyz");
  const std::string one = path("one.csv"), two = path("two.csv");
  REQUIRE(run("optimal " + input + " -o " + one + " --threads 1").exit_code == 0);
  REQUIRE(run("optimal " + input + " -o " + two + " --threads 2").exit_code == 0);
  CHECK(read_text(one) == read_text(two));

  const SN::Oriented_point_set model = SN::read_oriented_point_set(input);
  std::vector<std::size_t> indices(model.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    indices, std::back_inserter(records),
    CGAL::parameters::point_map(CGAL::make_property_map(model.points)).normal_map(CGAL::make_property_map(model.normals)));
  const auto rows = read_csv(one);
  REQUIRE(rows.size() == records.size() + 1);
  for(std::size_t i = 0; i < records.size(); ++i)
  {
    CHECK(std::stod(rows[i + 1][9]) == records[i].error()); // 17 digits read back bit for bit
    CHECK(std::stod(rows[i + 1][6]) == records[i].a);
    CHECK(std::stoul(rows[i + 1][8]) == records[i].k);
    CHECK(std::stod(rows[i + 1][14]) == records[i].error_equal);
  }
}

TEST_CASE("CLI: options --k-min, --k-max and --barycenter are honoured", "[cli]")
{
  const std::string input = sphere_xyz(300, true, "sphere300.xyz");
  const std::string csv = path("narrow.csv");
  REQUIRE(run("optimal " + input + " -o " + csv + " --k-min 8 --k-max 9 --barycenter unweighted").exit_code == 0);
  const auto rows = read_csv(csv);
  REQUIRE(rows.size() == 301);
  for(std::size_t i = 1; i < rows.size(); ++i)
  {
    const int k = std::stoi(rows[i][8]);
    CHECK((k == 8 || k == 9));
  }
}

TEST_CASE("CLI: a scan without normals gets estimated normals and says so", "[cli]")
{
  const std::string input = sphere_xyz(500, false, "raw.xyz");
  const std::string csv = path("raw.csv");
  const Run r = run("optimal " + input + " -o " + csv);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("normals estimated") != std::string::npos);
  const auto rows = read_csv(csv);
  REQUIRE(rows.size() == 501);
  // MST orientation gives one consistent side: all outward or all inward on a sphere
  int outward = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
  {
    const double dot = std::stod(rows[i][0]) * std::stod(rows[i][3]) + std::stod(rows[i][1]) * std::stod(rows[i][4]) +
                       std::stod(rows[i][2]) * std::stod(rows[i][5]);
    CHECK(std::abs(dot) > 0.95);
    outward += dot > 0;
  }
  CHECK((outward == 0 || outward == 500));
}

// How many rows of an optimal CSV have normals pointing away from the origin (a sphere's outside).
int outward_rows(const std::vector<std::vector<std::string>>& rows)
{
  int outward = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
    outward += std::stod(rows[i][0]) * std::stod(rows[i][3]) + std::stod(rows[i][1]) * std::stod(rows[i][4]) +
                 std::stod(rows[i][2]) * std::stod(rows[i][5]) >
               0.;
  return outward;
}

TEST_CASE("CLI: --normals, --normal-neighbors, --orientation, --viewpoint, --line-angles", "[cli][normals]")
{
  const std::string raw = sphere_xyz(500, false, "raw_options.xyz");
  const std::string with_normals = sphere_xyz(500, true, "oriented_options.xyz");
  const std::string csv = path("options.csv");

  // the default: PCA on 18 neighbors, a spanning forest seeded at the top (+z): outward on a sphere
  Run r = run("optimal " + raw + " -o " + csv);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("normals estimated by pca on 18 neighbors for 500 points, oriented by a spanning forest of 1 tree,") !=
        std::string::npos);
  CHECK(outward_rows(read_csv(csv)) == 500);

  r = run("optimal " + raw + " -o " + csv + " --normals jet --normal-neighbors 12");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("normals estimated by jet on 12 neighbors") != std::string::npos);
  CHECK(outward_rows(read_csv(csv)) == 500);

  // a viewpoint at the center turns every normal inwards
  r = run("optimal " + raw + " -o " + csv + " --viewpoint 0 0 0");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("oriented towards the viewpoint") != std::string::npos);
  CHECK(outward_rows(read_csv(csv)) == 0);

  // the file's normals, or estimated ones in their place
  r = run("optimal " + with_normals + " -o " + csv + " --normals file");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("normals from the file") != std::string::npos);
  r = run("optimal " + with_normals + " -o " + csv + " --normals pca --orientation none");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("normals estimated by pca on 18 neighbors for 500 points, not oriented") != std::string::npos);

  // line angles: the search blind to the signs, so oriented and unoriented normals give one CSV but its normals
  const std::string oriented_csv = path("lines_oriented.csv");
  r = run("optimal " + raw + " -o " + oriented_csv + " --line-angles");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find(", line angles,") != std::string::npos);
  REQUIRE(run("optimal " + raw + " -o " + csv + " --line-angles --orientation none").exit_code == 0);
  const auto a = read_csv(oriented_csv), b = read_csv(csv);
  REQUIRE(a.size() == b.size());
  for(std::size_t i = 1; i < a.size(); ++i)
    CHECK(std::vector<std::string>(a[i].begin() + 6, a[i].end()) == std::vector<std::string>(b[i].begin() + 6, b[i].end()));

  // filter-normals takes the same options
  r = run("filter-normals " + raw + " -o " + path("filtered.xyz") + " --normals jet --line-angles --iterations 2");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("normals estimated by jet on 18 neighbors") != std::string::npos);

  // bad usage: one line, exit 2, no output
  std::remove(csv.c_str());
  for(const auto& bad : std::vector<std::pair<std::string, std::string>>{
        {"--normals file", "the file has no normals"},
        {"--normals best", "--normals must be auto, file, pca or jet, got 'best'"},
        {"--normal-neighbors 1", "--normal-neighbors must be at least 2 for pca"},
        {"--normals jet --normal-neighbors 4", "--normal-neighbors must be at least 5 for jet fitting (degree 2)"},
        {"--orientation sideways", "--orientation must be mst, viewpoint, up or none, got 'sideways'"},
        {"--orientation viewpoint", "--orientation viewpoint needs --viewpoint X Y Z"},
        {"--viewpoint 1 2", "option --viewpoint needs three values: --viewpoint X Y Z"},
        {"--viewpoint 1 2 nan", "option --viewpoint needs three finite numbers, got '1 2 nan'"},
        {"--viewpoint 1 2 3 --orientation mst", "--viewpoint goes with --orientation viewpoint, not mst"}})
  {
    r = run("optimal " + raw + " -o " + csv + " " + bad.first);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(bad.second) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(csv));
  }
}

TEST_CASE("CLI: evaluate records the normals of each model and of the run", "[cli][normals]")
{
  const std::string folder = path("normals_repository");
  std::filesystem::create_directories(folder);
  sphere_xyz(400, false, "normals_repository/raw.xyz");
  sphere_xyz(400, true, "normals_repository/oriented.xyz");
  const std::string out = path("normals_evaluation");
  const Run r = run("evaluate " + folder + " -o " + out + " --normals jet --normal-neighbors 10");
  REQUIRE(r.exit_code == 0);
  const std::string raw = read_text(out + "/models/raw.xyz.json");
  CHECK(raw.find("\"normals\": \"estimated\"") != std::string::npos);
  CHECK(raw.find("\"normal_method\": \"jet\"") != std::string::npos);
  CHECK(raw.find("\"normal_neighbors\": 10") != std::string::npos);
  CHECK(raw.find("\"normal_components\": 1") != std::string::npos);
  // --normals jet estimates where the file has normals too
  CHECK(read_text(out + "/models/oriented.xyz.json").find("\"normal_method\": \"jet\"") != std::string::npos);
  const std::string run_json = read_text(out + "/run.json");
  CHECK(run_json.find("\"points_with_estimated_normals\": 800") != std::string::npos);
  CHECK(run_json.find("\"normals\": \"jet\"") != std::string::npos);
  // a shard with other normal settings does not merge
  const std::string other = path("normals_evaluation_pca");
  const std::string other_file = sphere_xyz(300, false, "normals_other.xyz");
  REQUIRE(run("evaluate " + other_file + " -o " + other + " --repository normals_repository").exit_code == 0);
  const Run merged = run("merge " + out + " " + other + " -o " + path("normals_merged"));
  CHECK(merged.exit_code == 2);
  CHECK(merged.err.find("was computed with other settings than the other models") != std::string::npos);
}

TEST_CASE("CLI: duplicate points are merged and counted", "[cli]")
{
  std::string text = read_text(sphere_xyz(100, true, "dup_base.xyz"));
  const std::string first_line = text.substr(0, text.find('\n') + 1);
  text += first_line + first_line; // two more copies of point 0
  write_text(path("dup.xyz"), text);
  const Run r = run("optimal " + path("dup.xyz") + " -o " + path("dup.csv"));
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("100 points") != std::string::npos);
  CHECK(r.err.find("2 merged duplicates") != std::string::npos);
  CHECK(read_csv(path("dup.csv")).size() == 101);
}

TEST_CASE("CLI: bad inputs exit with 2, one clear line, and no output file", "[cli][bad-input]")
{
  struct Case
  {
    std::string name, content, expected;
  };
  const std::string sphere = read_text(sphere_xyz(60, true, "ok.xyz"));
  const std::vector<Case> cases = {
    {"missing.xyz", "", "cannot open"},
    {"empty.xyz", "", "empty"},
    {"model.abc", "1 2 3\n", "unknown format"},
    {"nan.xyz", sphere + "nan 0 0 0 0 1\n", "non-finite"},
    {"inf.xyz", sphere + "1 inf 0 0 0 1\n", "non-finite"},
    {"zero_normal.xyz", sphere + "5 5 5 0 0 0\n", "zero normal"},
    {"text.xyz", sphere + "1 2 three 0 0 1\n", "not a number"},
    {"columns.xyz", sphere + "1 2 3 4\n", "expected 3"},
    {"few.xyz", "0 0 0 0 0 1\n1 0 0 0 0 1\n2 0 0 0 0 1\n", "at least k_max + 1 = 21"},
    {"duplicates.xyz", std::string(), "at least k_max + 1"},
    {"truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n", "cannot parse"},
    {"garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n", "cannot parse"},
    {"noface.obj", "v 0 0 0\nv 1 0 0\n", "no faces"},
    {"noface.stl", "solid x\nendsolid x\n", "no faces"},
  };
  for(const Case& c : cases)
  {
    INFO(c.name);
    std::string content = c.content;
    if(c.name == "duplicates.xyz")
      for(int i = 0; i < 30; ++i)
        content += "1 1 1 0 0 1\n";
    if(c.name != "missing.xyz")
      write_text(path(c.name), content);
    const std::string csv = path(c.name + ".csv");
    // under --normals auto a zero normal is estimated (test_zero_normals.cpp): refused with file only
    const std::string normals = c.name == "zero_normal.xyz" ? " --normals file" : "";
    const Run r = run("optimal " + path(c.name) + " -o " + csv + " --ply " + csv + ".ply" + normals);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.expected) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(csv));
    CHECK_FALSE(exists(csv + ".ply"));
  }
}

TEST_CASE("CLI: bad usage exits with 2", "[cli][bad-input]")
{
  const std::string input = sphere_xyz(60, true, "usage.xyz");
  CHECK(run("").exit_code == 2);
  CHECK(run("frobnicate").exit_code == 2);
  CHECK(run("optimal " + input).exit_code == 2);                              // no -o
  CHECK(run("optimal " + input + " -o " + path("u.csv") + " --k-max").exit_code == 2);
  CHECK(run("optimal " + input + " -o " + path("u.csv") + " --k-min 9 --k-max 8").exit_code == 2);
  CHECK(run("optimal " + input + " -o " + path("u.csv") + " --barycenter mean").exit_code == 2);
  CHECK(run("optimal " + input + " -o " + path("u.csv") + " --bogus 1").exit_code == 2);
  CHECK(run("optimal " + input + " -o /nonexistent-folder/u.csv").exit_code == 2);
  CHECK_FALSE(exists(path("u.csv")));
  CHECK(run("optimal --help").exit_code == 0);
}

TEST_CASE("CLI: the bad-input corpus gives the expected exit code and message", "[cli][bad-input]")
{
  const std::string dir = std::string(SN_TEST_DATA_DIR) + "/bad";
  std::ifstream manifest(dir + "/EXPECTED.txt");
  REQUIRE(manifest.good());
  std::string line;
  std::size_t cases = 0;
  while(std::getline(manifest, line))
  {
    if(line.empty() || line[0] == '#')
      continue;
    const std::size_t t1 = line.find('\t'), t2 = line.find('\t', t1 + 1);
    REQUIRE(t2 != std::string::npos);
    const std::string file = line.substr(0, t1), expected = line.substr(t2 + 1);
    const int code = std::stoi(line.substr(t1 + 1, t2 - t1 - 1));
    INFO(file);
    const std::string csv = path("bad_" + file + ".csv");
    const Run r = run("optimal '" + dir + "/" + file + "' -o " + csv);
    CHECK(r.exit_code == code);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(exists(csv) == (code == 0));
    // the library reader agrees: it throws exactly for the files it cannot read
    bool thrown = false;
    try
    {
      const SN::Oriented_point_set model = SN::read_oriented_point_set(dir + "/" + file);
      CHECK(model.points.size() == model.normals.size());
    }
    catch(const SN::Input_error& e)
    {
      thrown = true;
      CHECK(r.err.find(e.what()) != std::string::npos);
    }
    if(code == 0)
      CHECK_FALSE(thrown);
    ++cases;
  }
  CHECK(cases >= 30);
  // a folder and a missing file
  const Run folder = run("optimal '" + dir + "' -o " + path("folder.csv"));
  CHECK(folder.exit_code == 2);
  CHECK(folder.err.find("is a folder") != std::string::npos);
  CHECK(run("optimal '" + dir + "/missing.off' -o " + path("missing.csv")).exit_code == 2);
  // jet fitting needs 6 points: fewer estimation neighbors is a caller's error, not the file's
  CHECK_THROWS_AS(SN::read_oriented_point_set(dir + "/two_raw_points.xyz", 1), std::invalid_argument);
  CHECK_THROWS_AS(SN::read_oriented_point_set(dir + "/two_raw_points.xyz", 6), SN::Input_error);
}

// ------------------------------------------------------------------------------------------------
// The readers behind read_oriented_point_set() and read_polygon_mesh(), one format at a time.

namespace {

// A square pyramid: 5 vertices, 4 triangles and the base as a quad, in each mesh format.
const char* const PYRAMID_OFF = "OFF\n5 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
                                "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";
const char* const PYRAMID_OBJ = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                                "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
const char* const PYRAMID_PLY = "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
                                "property double z\nelement face 5\nproperty list uchar int vertex_indices\n"
                                "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
                                "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";

std::string pyramid_stl()
{
  const double v[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  const int t[6][3] = {{0, 3, 2}, {0, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  std::ostringstream out;
  out << "solid pyramid\n";
  for(const auto& f : t)
  {
    out << "facet normal 0 0 0\nouter loop\n";
    for(int c : f)
      out << "vertex " << v[c][0] << ' ' << v[c][1] << ' ' << v[c][2] << '\n';
    out << "endloop\nendfacet\n";
  }
  out << "endsolid pyramid\n";
  return out.str();
}

// `n` points of a sphere as PLY, with or without normals.
std::string sphere_ply(int n, bool with_normals)
{
  std::ostringstream out;
  out.precision(17);
  out << "ply\nformat ascii 1.0\nelement vertex " << n << "\nproperty double x\nproperty double y\nproperty double z\n";
  if(with_normals)
    out << "property double nx\nproperty double ny\nproperty double nz\n";
  out << "end_header\n";
  for(int i = 0; i < n; ++i)
  {
    const double z = 1. - 2. * (i + 0.5) / n, r = std::sqrt(1. - z * z), phi = 2.399963229728653 * i;
    out << r * std::cos(phi) << ' ' << r * std::sin(phi) << ' ' << z;
    if(with_normals)
      out << ' ' << 2 * r * std::cos(phi) << ' ' << 2 * r * std::sin(phi) << ' ' << 2 * z; // not unit
    out << '\n';
  }
  return out.str();
}

// Writes `text` to the scratch file `name` (once) and returns its path: every test case makes the
// files it reads, since ctest runs each in its own process.
std::string scratch_file(const std::string& name, const std::string& text)
{
  if(!exists(path(name)))
    write_text(path(name), text);
  return path(name);
}

std::string pyramid(const std::string& ext)
{
  if(ext == "off")
    return scratch_file("pyramid.off", PYRAMID_OFF);
  if(ext == "obj")
    return scratch_file("pyramid.obj", PYRAMID_OBJ);
  if(ext == "ply")
    return scratch_file("pyramid.ply", PYRAMID_PLY);
  return scratch_file("pyramid.STL", pyramid_stl()); // any case
}

// vertex 5 repeats vertex 1 and is used by one face instead of it; vertex 6 is used by no face
std::string merged_off()
{
  return scratch_file("merged.off", "OFF\n7 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n1 0 0\n9 9 9\n"
                                    "4 0 3 2 1\n3 0 5 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
}

std::string faceless_stl() { return scratch_file("io_faceless.stl", "solid x\nendsolid x\n"); }
std::string empty_off() { return scratch_file("io_empty.off", ""); }
std::string huge_count_off() { return scratch_file("io_huge_count.off", "OFF\n1000000000 0 0\n0 0 0\n"); }

std::string points_off(const SN::Oriented_point_set& set)
{
  std::string off = "OFF\n" + std::to_string(set.points.size()) + " 0 0\n";
  for(const auto& p : set.points)
    off += number_line(p);
  return scratch_file("io_points.off", off);
}

std::string read_error(const std::string& file)
{
  try
  {
    SN::read_oriented_point_set(file);
  }
  catch(const SN::Input_error& e)
  {
    return e.what();
  }
  return "no error";
}

std::string mesh_read_error(const std::string& file)
{
  try
  {
    CGAL::Surface_mesh<Point_3> mesh;
    SN::read_polygon_mesh(file, mesh);
  }
  catch(const SN::Input_error& e)
  {
    return e.what();
  }
  return "no error";
}

} // namespace

TEST_CASE("IO: lower_case_extension() selects the format", "[io]")
{
  CHECK(SN::lower_case_extension("model.PLY") == "ply");
  CHECK(SN::lower_case_extension("/data/v1.2/Model.Off") == "off");
  CHECK(SN::lower_case_extension("/data/v1.2/model") == "");
  CHECK(SN::lower_case_extension("model") == "");
  CHECK(SN::lower_case_extension("C:\\v1.2\\model") == "");
  CHECK(SN::lower_case_extension("archive.tar.GZ") == "gz");
}

TEST_CASE("IO: every mesh format gives the same points, normals and counts", "[io]")
{
  const SN::Oriented_point_set off = SN::read_oriented_point_set(pyramid("off"));
  CHECK(off.is_mesh);
  CHECK_FALSE(off.normals_estimated);
  CHECK(off.points.size() == 5);
  CHECK(off.normals.size() == 5);
  CHECK(off.input_vertices == 5);
  CHECK(off.merged_duplicates == 0);
  CHECK(off.dropped_vertices == 0);
  for(const auto& n : off.normals)
    CHECK(n.squared_length() == Approx(1.));
  CHECK(off.normals[4].z() == Approx(1.)); // the apex's normal points up
  for(const char* ext : {"obj", "ply", "stl"})
  {
    INFO(ext);
    const SN::Oriented_point_set other = SN::read_oriented_point_set(pyramid(ext));
    CHECK(other.is_mesh);
    REQUIRE(other.points.size() == off.points.size());
    REQUIRE(other.normals.size() == off.normals.size());
    for(std::size_t i = 0; i < off.points.size(); ++i) // STL orders the vertices by their first triangle
    {
      const auto j = std::size_t(std::find(other.points.begin(), other.points.end(), off.points[i]) - other.points.begin());
      REQUIRE(j < other.points.size());
      CHECK((other.normals[j] - off.normals[i]).squared_length() < 1e-20);
    }
  }
  // STL stores triangles: 6 x 3 corners at 5 positions, merged by CGAL's reader already
  CHECK(SN::read_oriented_point_set(pyramid("stl")).input_vertices == 5);
}

TEST_CASE("IO: mesh vertices at one position are merged into the first, unused ones dropped", "[io]")
{
  const SN::Oriented_point_set m = SN::read_oriented_point_set(merged_off());
  CHECK(m.input_vertices == 7);
  CHECK(m.merged_duplicates == 1);
  CHECK(m.dropped_vertices == 1);
  CHECK(m.points == SN::read_oriented_point_set(pyramid("off")).points);
}

TEST_CASE("IO: point sets in XYZ, PWN, PLY and OFF without faces", "[io]")
{
  const std::string xyz = sphere_xyz(50, true, "io_sphere.xyz");
  const SN::Oriented_point_set a = SN::read_oriented_point_set(xyz);
  CHECK_FALSE(a.is_mesh);
  CHECK_FALSE(a.normals_estimated);
  CHECK(a.points.size() == 50);
  CHECK(a.normals.size() == 50);

  write_text(path("io_sphere.pwn"), read_text(xyz));
  CHECK(SN::read_oriented_point_set(path("io_sphere.pwn")).points == a.points);

  write_text(path("io_sphere.ply"), sphere_ply(50, true));
  const SN::Oriented_point_set ply = SN::read_oriented_point_set(path("io_sphere.ply"));
  REQUIRE(ply.points.size() == 50);
  REQUIRE(ply.normals.size() == 50);
  for(std::size_t i = 0; i < 50; ++i)
  {
    CHECK(ply.points[i] == a.points[i]);
    CHECK(ply.normals[i].squared_length() == Approx(1.)); // the file's normals have length 2
  }

  // no normals: estimated, or left out with estimation_neighbors = 0
  write_text(path("io_raw.ply"), sphere_ply(50, false));
  const SN::Oriented_point_set raw = SN::read_oriented_point_set(path("io_raw.ply"));
  CHECK(raw.normals_estimated);
  CHECK(raw.normals.size() == 50);
  const SN::Oriented_point_set bare = SN::read_oriented_point_set(path("io_raw.ply"), 0);
  CHECK(bare.points.size() == 50);
  CHECK(bare.normals.empty());
  CHECK_FALSE(bare.normals_estimated);

  const SN::Oriented_point_set points = SN::read_oriented_point_set(points_off(a), 0);
  CHECK_FALSE(points.is_mesh);
  CHECK(points.points.size() == 50);

  // duplicates: the first kept, with its normal
  write_text(path("io_dup.xyz"), "0 0 0 0 0 1\n1 0 0 0 0 1\n0 0 0 1 0 0\n2 0 0 0 0 1\n1 0 0 0 1 0\n");
  const SN::Oriented_point_set dup = SN::read_oriented_point_set(path("io_dup.xyz"));
  CHECK(dup.input_vertices == 5);
  CHECK(dup.merged_duplicates == 2);
  REQUIRE(dup.points.size() == 3);
  CHECK(dup.points[2] == Point_3(2, 0, 0));
  CHECK(dup.normals[0] == Vector_3(0, 0, 1));
  CHECK(dup.normals[1] == Vector_3(0, 0, 1));
}

TEST_CASE("IO: duplicates merged into the first as a search tree of positions merges them", "[io]")
{
  // 20,000 points on a lattice of 8 x 8 x 8 positions (most of them repeated, -0 among them), each
  // with its own normal: the reader keeps the first point of each position, in input order, with
  // its normal, as a map from position to first point does.
  std::mt19937 random(5);
  std::uniform_int_distribution<int> cell(-4, 3);
  std::ostringstream text;
  std::vector<std::array<double, 6>> rows;
  for(int i = 0; i < 20000; ++i)
  {
    const double x = 0.5 * cell(random), y = cell(random) == 0 ? -0. : 0.25 * cell(random), z = 0.125 * cell(random);
    const std::array<double, 6> row{{x, y, z, 1. + (i % 7), double(i % 11), double(i % 13)}};
    rows.push_back(row);
    text << x << ' ' << (y == 0. && std::signbit(y) ? "-0" : std::to_string(y)) << ' ' << z << ' ' << row[3]
         << ' ' << row[4] << ' ' << row[5] << '\n';
  }
  write_text(path("io_many_duplicates.xyz"), text.str());
  const SN::Oriented_point_set read = SN::read_oriented_point_set(path("io_many_duplicates.xyz"));

  std::map<std::array<double, 3>, std::size_t> first_at; // 0 and -0 are one key: they compare equal
  std::vector<std::size_t> kept;
  for(std::size_t i = 0; i < rows.size(); ++i)
    if(first_at.emplace(std::array<double, 3>{{rows[i][0], rows[i][1], rows[i][2]}}, i).second)
      kept.push_back(i);
  CHECK(read.input_vertices == rows.size());
  CHECK(read.merged_duplicates == rows.size() - kept.size());
  REQUIRE(read.points.size() == kept.size());
  std::size_t differing = 0;
  for(std::size_t j = 0; j < kept.size(); ++j)
  {
    const auto& r = rows[kept[j]];
    const Vector_3 n = Vector_3(r[3], r[4], r[5]) / std::sqrt(r[3] * r[3] + r[4] * r[4] + r[5] * r[5]);
    differing += !(read.points[j] == Point_3(r[0], r[1], r[2])) ||
                 std::signbit(read.points[j].y()) != std::signbit(r[1]) ||
                 std::abs(read.normals[j].x() - n.x()) > 1e-12 || std::abs(read.normals[j].y() - n.y()) > 1e-12 ||
                 std::abs(read.normals[j].z() - n.z()) > 1e-12;
  }
  CHECK(differing == 0);
  CHECK(kept.size() == 512); // every position of the lattice drawn: most points are duplicates
}

TEST_CASE("IO: the dispatcher's errors", "[io][bad-input]")
{
  write_text(path("io_model.xyzw"), "1 2 3\n");
  write_text(path("io_noext"), "1 2 3\n");
  write_text(path("io_faceless.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  write_text(path("io_bad_ply.ply"), "ply\nformat ascii 1.0\nproperty double x\nelement vertex 1\nend_header\n1\n");
  CHECK(read_error(path("io_missing.xyz")) == "cannot open the file");
  CHECK(read_error(scratch()) == "is a folder, not a file");
  CHECK(read_error(empty_off()) == "the file is empty");
  CHECK(read_error(path("io_model.xyzw")) == "unknown format '.xyzw': expected .off, .obj, .ply, .stl, .xyz, .pwn, .las or .laz");
  CHECK(read_error(path("io_noext")).find("unknown format '(no extension)'") == 0);
  CHECK(read_error(path("io_faceless.obj")).find("cannot parse the file as obj, or it has no faces") == 0);
  CHECK(read_error(faceless_stl()) == "no faces in the file");
  CHECK(read_error(path("io_bad_ply.ply")) == "cannot parse the file as ply (a property before any element, line 3)");
  CHECK(read_error(huge_count_off()).find("the header announces 1000000000 vertices") == 0);
  CHECK_THROWS_AS(SN::read_oriented_point_set(pyramid("off"), 1), std::invalid_argument);
}

TEST_CASE("IO: read_polygon_mesh() reads as CGAL's read_polygon_mesh(), through the checked readers", "[io]")
{
  const std::string cube = cube_off();
  CGAL::Surface_mesh<Point_3> ours, cgal;
  SN::read_polygon_mesh(cube, ours);
  REQUIRE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(cube, cgal));
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(cgal);
  cgal.collect_garbage();
  REQUIRE(ours.number_of_vertices() == 152);
  REQUIRE(ours.number_of_vertices() == cgal.number_of_vertices());
  CHECK(ours.number_of_faces() == cgal.number_of_faces());
  auto o = ours.vertices().begin();
  for(auto c = cgal.vertices().begin(); c != cgal.vertices().end(); ++c, ++o)
    CHECK(ours.point(*o) == cgal.point(*c));

  // faces as CGAL orients them: one flipped face of a strip is turned, the mesh is kept as it is
  auto face_cycles = [](const CGAL::Surface_mesh<Point_3>& mesh) {
    std::vector<std::vector<Point_3>> cycles;
    for(auto f : mesh.faces())
    {
      cycles.emplace_back();
      for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
        cycles.back().push_back(mesh.point(v));
    }
    return cycles;
  };
  CHECK(face_cycles(ours) == face_cycles(cgal));
  write_text(path("io_flipped.off"), "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 1 0\n3 0 1 2\n3 1 2 3\n3 1 4 3\n");
  CGAL::Surface_mesh<Point_3> flipped_ours, flipped_cgal;
  SN::read_polygon_mesh(path("io_flipped.off"), flipped_ours);
  REQUIRE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path("io_flipped.off"), flipped_cgal));
  CHECK(flipped_ours.number_of_faces() == 3);
  CHECK(face_cycles(flipped_ours) == face_cycles(flipped_cgal));

  // the isolated vertex of merged.off is removed
  CGAL::Surface_mesh<Point_3> merged;
  SN::read_polygon_mesh(merged_off(), merged);
  CHECK(merged.number_of_vertices() == 5);
  CHECK(merged.number_of_faces() == 5);

  const std::string xyz = sphere_xyz(50, true, "io_sphere.xyz");
  CHECK(mesh_read_error(xyz) == "unknown format '.xyz': expected .off, .obj, .ply or .stl");
  CHECK(mesh_read_error(points_off(SN::read_oriented_point_set(xyz))) == "no faces in the file");
  CHECK(mesh_read_error(empty_off()) == "the file is empty");
  CHECK(mesh_read_error(huge_count_off()).find("the header announces") == 0);
  write_text(path("io_huge.off"), "OFF\n3 1 0\n0 0 0\n1 1e200 0\n0 1 0\n3 0 1 2\n");
  CHECK(mesh_read_error(path("io_huge.off")).find("vertex 1 has a coordinate beyond 1e150") == 0);
}

TEST_CASE("CLI: every command reads through the package's reader", "[cli][bad-input]")
{
  // filter-normals and denoise-experiment give the reader's one line, exit code 2 and no output
  const Run filter = run("filter-normals " + faceless_stl() + " -o " + path("f.xyz"));
  CHECK(filter.exit_code == 2);
  CHECK(filter.err.find("io_faceless.stl: no faces in the file") != std::string::npos);
  CHECK_FALSE(exists(path("f.xyz")));
  const Run denoise = run("denoise-experiment " + sphere_xyz(50, true, "io_sphere.xyz") + " -o " + path("denoise_bad"));
  CHECK(denoise.exit_code == 2);
  CHECK(denoise.err.find("unknown format '.xyz'") != std::string::npos);
  CHECK(std::count(denoise.err.begin(), denoise.err.end(), '\n') == 1);
  CHECK_FALSE(exists(path("denoise_bad/table4.md")));
  // a tolerance outside [0, pi) is refused by both commands that take one
  const std::string input = sphere_xyz(60, true, "tolerance.xyz");
  CHECK(run("optimal " + input + " -o " + path("t.csv") + " --angle-tolerance 3.1416").exit_code == 2);
  CHECK(run("filter-normals " + input + " -o " + path("t.xyz") + " --angle-tolerance -1").exit_code == 2);
  CHECK(run("optimal " + input + " -o " + path("t.csv") + " --angle-tolerance 3.14159").exit_code == 0);
}

TEST_CASE("CLI: the tool is a thin shell: no internal names, no shell, no global thread count, no host path",
          "[cli]")
{
  // the tool's commands; its readers (tools/readers) are a library with internals of its own
  const std::filesystem::path tools =
    std::filesystem::path(SN_TEST_DATA_DIR) / ".." / ".." / "tools" / "sigmoid-neighborhoods";
  std::size_t files = 0;
  for(const auto& entry : std::filesystem::recursive_directory_iterator(tools))
  {
    const std::string ext = entry.path().extension().string();
    if(!entry.is_regular_file() || (ext != ".h" && ext != ".cpp"))
      continue;
    ++files;
    INFO(entry.path().string());
    const std::string text = read_text(entry.path().string());
    CHECK(text.find("internal::") == std::string::npos);
    CHECK(text.find("std::system") == std::string::npos);
    CHECK(text.find("omp_set_num_threads") == std::string::npos);
    CHECK(text.find("/usr/share") == std::string::npos);
    CHECK(text.find("3.14159") == std::string::npos);
  }
  CHECK(files >= 10);
}
