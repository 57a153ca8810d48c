// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tool on good and bad inputs: exit codes, messages, files left behind, and
// numbers equal to the library's.

#include "test_models.h"

#include <CGAL/Sigmoid_neighborhoods.h>
#include <CGAL/Sigmoid_neighborhoods/IO/read_oriented_point_set.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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
  auto error = ps.property_map<double>("error");
  auto k = ps.property_map<int>("k");
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
    const Run r = run("optimal " + path(c.name) + " -o " + csv + " --ply " + csv + ".ply");
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
  CHECK_THROWS_AS(SN::read_oriented_point_set(dir + "/two_raw_points.xyz", 3), std::invalid_argument);
  CHECK_THROWS_AS(SN::read_oriented_point_set(dir + "/two_raw_points.xyz", 6), SN::Input_error);
}
