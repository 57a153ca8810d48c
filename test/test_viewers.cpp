// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's PLY files in the viewers: every field through the real CloudCompare (headless) equal to
// the CSV, MeshLab's `quality` and colors in the header and data (and through meshlabserver when it
// can run), CGAL's Point_set_3 reading each property by its documented name; and the --a-grid,
// --b-grid options, whose equal-weights-only run is the default run's equal-weights baseline.

#include "test_models.h"

#include "../tools/sigmoid-neighborhoods/ply_output.h"

#include <CGAL/IO/OFF.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string& scratch()
{
  // removed when the test program ends
  struct Scratch
  {
    std::string root;
    ~Scratch() { std::error_code ec; fs::remove_all(root, ec); }
  };
  static Scratch scratch;
  static const std::string dir = [] {
    char name[] = "/tmp/sn_viewers_XXXXXX";
    const char* made = ::mkdtemp(name);
    REQUIRE(made != nullptr);
    scratch.root = made;
    return std::string(made);
  }();
  return dir;
}

std::string path(const std::string& name) { return scratch() + "/" + name; }

std::string read_text(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Run
{
  int exit_code;
  std::string err;
};

// `command` through the shell, its stderr kept.
Run shell(const std::string& command)
{
  const std::string err_file = path("stderr.txt");
  const int status = std::system((command + " 2> " + err_file + " > /dev/null").c_str());
  return Run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(err_file)};
}

Run run_tool(const std::string& arguments) { return shell(std::string(SN_TOOL_PATH) + " " + arguments); }

bool has_program(const std::string& name)
{
  return std::system(("command -v " + name + " > /dev/null 2>&1").c_str()) == 0;
}

typedef std::vector<std::string> Row;

std::vector<Row> read_rows(const std::string& file, char separator)
{
  std::vector<Row> rows;
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
  {
    Row cells;
    std::stringstream cells_in(line);
    std::string cell;
    if(separator == ' ')
      while(cells_in >> cell)
        cells.push_back(cell);
    else
    {
      while(std::getline(cells_in, cell, separator))
        cells.push_back(cell);
      if(!line.empty() && line.back() == separator)
        cells.push_back("");
    }
    rows.push_back(cells);
  }
  return rows;
}

// A CSV or an exported table: the column index of every name of the first row.
std::map<std::string, std::size_t> columns(const Row& header)
{
  std::map<std::string, std::size_t> index;
  for(std::size_t i = 0; i < header.size(); ++i)
    index[header[i]] = i;
  return index;
}

// A number of the CSV or of an export: empty is NaN ("inf", "nan" as strtod reads them).
double number(const std::string& text)
{
  return text.empty() ? std::numeric_limits<double>::quiet_NaN() : std::strtod(text.c_str(), nullptr);
}

// The PLY's value of a CSV cell: labels are numbers there, an empty k is 0.
double ply_value(const std::string& column, const std::string& cell)
{
  if(column == "label")
  {
    const char* names[] = {"linear", "planar", "scattered", "degenerate"};
    for(int i = 0; i < 4; ++i)
      if(cell == names[i])
        return i;
    FAIL("unknown label " << cell);
  }
  if((column == "k" || column == "k_equal") && cell.empty())
    return 0.;
  return number(cell);
}

// Equal as floats (CloudCompare's scalars), or both NaN, or the same infinity.
bool close_as_float(double expected, double got, double tolerance)
{
  if(std::isnan(expected) || std::isnan(got))
    return std::isnan(expected) && std::isnan(got);
  if(std::isinf(expected) || std::isinf(got))
    return expected == got;
  return std::abs(expected - got) <= tolerance * (1. + std::abs(expected));
}

// The grid cube of the CLI tests (152 vertices: flat faces, edges, corners).
std::string cube_off()
{
  const std::string file = path("cube.off");
  if(!fs::exists(file))
    CGAL::IO::write_OFF(file, make_grid_cube(5, 0.2), CGAL::parameters::stream_precision(17));
  return file;
}

// The PLY header's lines up to end_header.
std::vector<std::string> ply_header(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> lines;
  std::string line;
  while(std::getline(in, line) && line != "end_header")
    lines.push_back(line);
  return lines;
}

bool has_line(const std::vector<std::string>& lines, const std::string& line)
{
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

typedef CGAL::Point_set_3<Point_3, Vector_3> Point_set;

const std::vector<std::string> CSV_COLUMNS_IN_PLY = {"a",          "b",         "k",          "error",
                                                     "linearity",  "planarity", "scattering", "label",
                                                     "error_equal", "k_equal"};

// The documented legend of --color label: linear, planar, scattered, degenerate.
const std::map<std::string, sigmoid_tool::Rgb> LABEL_COLORS = {{"linear", {213, 94, 0}},
                                                              {"planar", {0, 114, 178}},
                                                              {"scattered", {240, 228, 66}},
                                                              {"degenerate", {128, 128, 128}}};

} // namespace

TEST_CASE("Viewers: CGAL's Point_set_3 reads every PLY property back by its documented name", "[viewers]")
{
  const std::string csv = path("names.csv"), ply = path("names.ply");
  REQUIRE(run_tool("optimal " + cube_off() + " -o " + csv + " --ply " + ply).exit_code == 0);
  const auto rows = read_rows(csv, ',');
  REQUIRE(rows.size() == 153);
  auto column = columns(rows[0]);

  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(ply, ps));
  REQUIRE(ps.size() == 152);
  REQUIRE(ps.has_normal_map());
  std::map<std::string, Point_set::Property_map<double>> doubles;
  for(const std::string name : {"a", "b", "error", "linearity", "planarity", "scattering", "error_equal"})
  {
    auto map = ps.property_map<double>("scalar_" + name);
    REQUIRE(map.second);
    doubles[name] = map.first;
  }
  auto k = ps.property_map<std::int32_t>("scalar_k");
  auto k_equal = ps.property_map<std::int32_t>("scalar_k_equal");
  auto label = ps.property_map<std::uint8_t>("scalar_label");
  auto quality = ps.property_map<float>("quality");
  auto red = ps.property_map<std::uint8_t>("red");
  auto green = ps.property_map<std::uint8_t>("green");
  auto blue = ps.property_map<std::uint8_t>("blue");
  REQUIRE((k.second && k_equal.second && label.second && quality.second && red.second && green.second && blue.second));
  CHECK(!ps.property_map<double>("error").second); // no unprefixed duplicates

  std::size_t i = 1;
  for(auto it = ps.begin(); it != ps.end(); ++it, ++i)
  {
    const Row& row = rows[i];
    for(const auto& d : doubles) // 17 digits in the CSV: the same doubles
    {
      const double expected = ply_value(d.first, row[column[d.first]]);
      CHECK((d.second[*it] == expected || (std::isnan(expected) && std::isnan(d.second[*it]))));
    }
    CHECK(k.first[*it] == ply_value("k", row[column["k"]]));
    CHECK(k_equal.first[*it] == ply_value("k_equal", row[column["k_equal"]]));
    CHECK(label.first[*it] == ply_value("label", row[column["label"]]));
    CHECK(quality.first[*it] == float(number(row[column["error"]])));
    CHECK(ps.point(*it).x() == number(row[column["x"]]));
    CHECK(ps.normal(*it).z() == number(row[column["nz"]]));
  }
}

TEST_CASE("Viewers: CloudCompare loads every field of optimal --ply, equal to the CSV", "[viewers][cloudcompare]")
{
  if(!has_program("CloudCompare"))
  {
    WARN("CloudCompare is not installed (Debian: apt-get install cloudcompare; make test installs it): skipped");
    return;
  }
  const std::string csv = path("cc.csv"), ply = path("cc.ply"), exported = path("cc_export.asc");
  REQUIRE(run_tool("optimal " + cube_off() + " -o " + csv + " --ply " + ply).exit_code == 0);
  // Headless: Qt's offscreen platform, no X server needed.
  const Run cc = shell("cd " + scratch() + " && QT_QPA_PLATFORM=offscreen timeout 120 CloudCompare -SILENT -NO_TIMESTAMP -O " +
                       ply + " -C_EXPORT_FMT ASC -ADD_HEADER -SAVE_CLOUDS FILE " + exported);
  INFO(cc.err);
  REQUIRE(cc.exit_code == 0);
  REQUIRE(fs::exists(exported));

  const auto rows = read_rows(csv, ',');
  auto exported_rows = read_rows(exported, ' ');
  REQUIRE(rows.size() == 153);
  REQUIRE(exported_rows.size() == rows.size());
  REQUIRE(!exported_rows[0].empty());
  REQUIRE(exported_rows[0][0].substr(0, 2) == "//"); // -ADD_HEADER: "//X Y Z R G B a b ... Nx Ny Nz"
  exported_rows[0][0] = exported_rows[0][0].substr(2);
  auto csv_column = columns(rows[0]);
  auto cc_column = columns(exported_rows[0]);
  // every scalar field, by the name CloudCompare gives it (scalar_ taken off), and the colors
  for(const std::string& name : CSV_COLUMNS_IN_PLY)
    REQUIRE(cc_column.count(name) == 1);
  for(const char* name : {"X", "Y", "Z", "Nx", "Ny", "Nz", "R", "G", "B"})
    REQUIRE(cc_column.count(name) == 1);
  CHECK(exported_rows[0].size() == CSV_COLUMNS_IN_PLY.size() + 9); // nothing else: `quality` is MeshLab's

  Point_set ps; // the colors as written, to compare with CloudCompare's
  REQUIRE(CGAL::IO::read_PLY(ply, ps));
  auto red = ps.property_map<std::uint8_t>("red").first, green = ps.property_map<std::uint8_t>("green").first,
       blue = ps.property_map<std::uint8_t>("blue").first;
  for(std::size_t i = 1; i < rows.size(); ++i)
  {
    const Row& row = rows[i];
    const Row& got = exported_rows[i];
    REQUIRE(got.size() == exported_rows[0].size());
    // CloudCompare stores coordinates and scalars as floats and normals compressed (about 1e-3)
    const char* coordinates[][2] = {{"x", "X"}, {"y", "Y"}, {"z", "Z"}};
    for(const auto& c : coordinates)
      CHECK(close_as_float(number(row[csv_column[c[0]]]), number(got[cc_column[c[1]]]), 1e-6));
    const char* normals[][2] = {{"nx", "Nx"}, {"ny", "Ny"}, {"nz", "Nz"}};
    for(const auto& c : normals)
      CHECK(std::abs(number(row[csv_column[c[0]]]) - number(got[cc_column[c[1]]])) <= 2e-3);
    for(const std::string& name : CSV_COLUMNS_IN_PLY)
    {
      INFO("row " << i << ", " << name << ": CSV " << row[csv_column[name]] << ", CloudCompare " << got[cc_column[name]]);
      CHECK(close_as_float(ply_value(name, row[csv_column[name]]), number(got[cc_column[name]]), 1e-6));
    }
    const auto index = *(ps.begin() + std::ptrdiff_t(i - 1));
    CHECK(number(got[cc_column["R"]]) == red[index]);
    CHECK(number(got[cc_column["G"]]) == green[index]);
    CHECK(number(got[cc_column["B"]]) == blue[index]);
  }

  // filter-normals writes positions and normals only: CloudCompare loads both.
  const std::string filtered = path("filtered.ply"), filtered_export = path("filtered.asc");
  REQUIRE(run_tool("filter-normals " + cube_off() + " -o " + filtered + " --iterations 2").exit_code == 0);
  REQUIRE(shell("cd " + scratch() + " && QT_QPA_PLATFORM=offscreen timeout 120 CloudCompare -SILENT -NO_TIMESTAMP -O " +
                filtered + " -C_EXPORT_FMT ASC -ADD_HEADER -SAVE_CLOUDS FILE " + filtered_export)
            .exit_code == 0);
  const auto filtered_rows = read_rows(filtered_export, ' ');
  REQUIRE(filtered_rows.size() == 153);
  CHECK(filtered_rows[0] == Row{"//X", "Y", "Z", "Nx", "Ny", "Nz"});
}

TEST_CASE("Viewers: the colormap is viridis over [0, ln 3], the labels have fixed colors", "[viewers]")
{
  using sigmoid_tool::error_color;
  using sigmoid_tool::Rgb;
  // matplotlib's viridis (its full 256-entry table, interpolated) at E_dim / ln 3
  const std::vector<std::pair<double, Rgb>> reference = {
    {0., {68, 1, 84}},     {0.25, {62, 76, 138}}, {0.5, {37, 133, 142}},         {std::log(3.) / 2, {33, 144, 140}},
    {0.8, {81, 196, 105}}, {1., {195, 224, 35}},  {std::log(3.), {253, 231, 37}}};
  for(const auto& r : reference)
    for(int c = 0; c < 3; ++c)
    {
      INFO("E_dim " << r.first << ", channel " << c);
      CHECK(std::abs(int(error_color(r.first)[c]) - int(r.second[c])) <= 1);
    }
  CHECK(error_color(-1e-17) == error_color(0.));         // rounding below the range
  CHECK(error_color(2.) == error_color(std::log(3.)));    // and above it
  CHECK(error_color(std::numeric_limits<double>::infinity()) == sigmoid_tool::FAILURE_GRAY);
  CHECK(error_color(std::nan("")) == sigmoid_tool::FAILURE_GRAY);
  typedef CGAL::Sigmoid_neighborhoods::Dimensionality D;
  CHECK(sigmoid_tool::label_color(D::LINEAR) == LABEL_COLORS.at("linear"));
  CHECK(sigmoid_tool::label_color(D::PLANAR) == LABEL_COLORS.at("planar"));
  CHECK(sigmoid_tool::label_color(D::SCATTERED) == LABEL_COLORS.at("scattered"));
  CHECK(sigmoid_tool::label_color(D::DEGENERATE) == LABEL_COLORS.at("degenerate"));
}

TEST_CASE("Viewers: MeshLab's quality and colors are in the PLY's header and data", "[viewers][meshlab]")
{
  const std::string csv = path("ml.csv");
  const auto write = [&](const std::string& ply, const std::string& color) {
    REQUIRE(run_tool("optimal " + cube_off() + " -o " + csv + " --ply " + ply + color).exit_code == 0);
  };
  const std::string by_error = path("ml_error.ply"), by_label = path("ml_label.ply"), plain = path("ml_none.ply");
  write(by_error, "");
  write(by_label, " --color label");
  write(plain, " --color none");
  const auto rows = read_rows(csv, ',');
  REQUIRE(rows.size() == 153);
  auto column = columns(rows[0]);

  for(const std::string& file : {by_error, by_label, plain})
  {
    const auto header = ply_header(file);
    CHECK(has_line(header, "format binary_little_endian 1.0"));
    CHECK(has_line(header, "property float quality"));
    for(const char* c : {"red", "green", "blue"})
      CHECK(has_line(header, std::string("property uchar ") + c) == (file != plain));
  }

  const auto colors_of = [](const std::string& file) {
    Point_set ps;
    REQUIRE(CGAL::IO::read_PLY(file, ps));
    std::vector<sigmoid_tool::Rgb> colors;
    auto red = ps.property_map<std::uint8_t>("red"), green = ps.property_map<std::uint8_t>("green"),
         blue = ps.property_map<std::uint8_t>("blue");
    REQUIRE((red.second && green.second && blue.second));
    for(auto it = ps.begin(); it != ps.end(); ++it)
      colors.push_back({red.first[*it], green.first[*it], blue.first[*it]});
    return colors;
  };
  const auto error_colors = colors_of(by_error), label_colors = colors_of(by_label);
  REQUIRE(error_colors.size() == 152);
  REQUIRE(label_colors.size() == 152);
  std::size_t flat = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
  {
    const double error = number(rows[i][column["error"]]);
    CHECK(error_colors[i - 1] == sigmoid_tool::error_color(error));
    if(error == 0.)
    {
      ++flat;
      CHECK(error_colors[i - 1] == sigmoid_tool::Rgb{68, 1, 84}); // viridis' first color
    }
    CHECK(label_colors[i - 1] == LABEL_COLORS.at(rows[i][column["label"]]));
  }
  CHECK(flat > 0); // the cube's flat faces

  // Through MeshLab itself where it can run: meshlabserver needs an OpenGL context, so an X server.
  if(!has_program("meshlabserver") || !has_program("xvfb-run"))
  {
    WARN("meshlabserver or xvfb-run is not installed (Debian: meshlab, xvfb): MeshLab itself not run");
    return;
  }
  const std::string saved = path("ml_saved.ply");
  const Run ml = shell("timeout 120 xvfb-run -a meshlabserver -i " + by_error + " -o " + saved + " -m vc vq vn sa");
  INFO(ml.err);
  REQUIRE(ml.exit_code == 0);
  const auto header = ply_header(saved);
  CHECK(has_line(header, "property float quality"));
  CHECK(has_line(header, "property uchar red"));
  const auto saved_rows = read_rows(saved, ' ');
  REQUIRE(saved_rows.size() == header.size() + 1 + 152);
  std::vector<std::string> properties;
  for(const std::string& line : header)
    if(line.rfind("property ", 0) == 0 && line.find(" list ") == std::string::npos && properties.size() < 64)
      properties.push_back(line.substr(line.rfind(' ') + 1));
  std::map<std::string, std::size_t> at;
  for(std::size_t j = 0; j < properties.size(); ++j)
    at[properties[j]] = j;
  for(std::size_t i = 0; i < 152; ++i)
  {
    const Row& got = saved_rows[header.size() + 1 + i];
    CHECK(close_as_float(number(rows[i + 1][column["error"]]), number(got[at["quality"]]), 1e-5)); // %g
    CHECK(number(got[at["red"]]) == error_colors[i][0]);
    CHECK(number(got[at["green"]]) == error_colors[i][1]);
    CHECK(number(got[at["blue"]]) == error_colors[i][2]);
  }
}

TEST_CASE("Viewers: a bad --color exits with 2, one line and no output", "[viewers][bad-input]")
{
  const std::string csv = path("bad_color.csv"), ply = path("bad_color.ply");
  const Run r = run_tool("optimal " + cube_off() + " -o " + csv + " --ply " + ply + " --color rainbow");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--color must be error, label or none, got 'rainbow'") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(!fs::exists(csv));
  CHECK(!fs::exists(ply));
}

TEST_CASE("Grids: --a-grid pi --b-grid pi is the equal-weights search of a default run", "[viewers][grid]")
{
  const std::string defaults = path("grid_default.csv"), equal = path("grid_equal.csv"),
                    degrees = path("grid_degrees.csv"), listed = path("grid_listed.csv");
  REQUIRE(run_tool("optimal " + cube_off() + " -o " + defaults).exit_code == 0);
  REQUIRE(run_tool("optimal " + cube_off() + " -o " + equal + " --a-grid pi --b-grid pi").exit_code == 0);
  REQUIRE(run_tool("optimal " + cube_off() + " -o " + degrees + " --a-grid 180deg --b-grid=180deg").exit_code == 0);
  CHECK(read_text(equal) == read_text(degrees));
  // the default grid written out, in degrees and in any order: the same bytes
  REQUIRE(run_tool("optimal " + cube_off() + " -o " + listed +
                   " --a-grid 0,30deg,60deg,90deg,120deg,150deg,pi --b-grid 180deg,150deg,120deg,90deg,60deg,30deg,0")
            .exit_code == 0);
  CHECK(read_text(listed) == read_text(defaults));

  const auto d = read_rows(defaults, ','), e = read_rows(equal, ',');
  REQUIRE(d.size() == 153);
  REQUIRE(e.size() == d.size());
  auto column = columns(d[0]);
  const std::string pi = "3.141592653589793"; // the shortest text that reads back to CGAL_PI
  for(std::size_t i = 1; i < d.size(); ++i)
  {
    CHECK(e[i][column["a"]] == pi);
    CHECK(e[i][column["b"]] == pi);
    CHECK(e[i][column["k"]] == d[i][column["k_equal"]]);
    CHECK(e[i][column["error"]] == d[i][column["error_equal"]]);
    CHECK(e[i][column["k_equal"]] == d[i][column["k_equal"]]);
  }

  // evaluate takes the grids too and records them in its settings
  const std::string outdir = path("grid_evaluation");
  REQUIRE(run_tool("evaluate " + cube_off() + " -o " + outdir + " --a-grid pi --b-grid 90deg,pi").exit_code == 0);
  const std::string json = read_text(outdir + "/models/cube.off.json");
  const std::size_t a_at = json.find("\"a_grid\""), b_at = json.find("\"b_grid\"");
  REQUIRE(a_at != std::string::npos);
  REQUIRE(b_at != std::string::npos);
  const std::string a_grid = json.substr(a_at, json.find(']', a_at) - a_at);
  const std::string b_grid = json.substr(b_at, json.find(']', b_at) - b_at);
  // JSON writes the shortest text that reads back to the double (the CSV writes 17 digits)
  const std::string pi_json = "3.141592653589793\n";
  CHECK(a_grid.find(pi_json) != std::string::npos);
  CHECK(a_grid.find(',') == std::string::npos);
  CHECK(b_grid.find("1.5707963267948966") != std::string::npos);
  CHECK(b_grid.find(pi_json) != std::string::npos);
}

TEST_CASE("Grids: bad --a-grid and --b-grid values exit with 2, one line and no output", "[viewers][grid][bad-input]")
{
  const std::string csv = path("bad_grid.csv");
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"--a-grid 200deg", "--a-grid: 200deg is not in [0, pi]"},
    {"--b-grid 3.2", "--b-grid: 3.2 is not in [0, pi]"},
    {"--a-grid -0.5", "--a-grid: -0.5 is not in [0, pi]"},
    {"--a-grid ''", "--a-grid needs at least one angle"},
    {"--a-grid 0,,pi", "--a-grid needs comma-separated angles in radians or degrees"},
    {"--b-grid 30degrees", "--b-grid needs comma-separated angles in radians or degrees"},
    {"--a-grid nan", "--a-grid needs comma-separated angles"},
    {"--a-grid pi --b-grid 0,90deg", "--a-grid and --b-grid have no pair with a <= b"}};
  for(const auto& c : cases)
  {
    INFO(c.first);
    const Run r = run_tool("optimal " + cube_off() + " -o " + csv + " " + c.first);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.second) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(csv));
  }
}
