// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tile catalogs: every tile read with its halo gives the records of the union, bit for bit (points,
// normals, labels, the optimal search), on a grid full of distance ties with points on the seams,
// and on the six IGN LiDAR HD tiles of the shared data; without halos, the share of points whose
// records differ (the border effect); the catalog's refusals.

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/read_tile_catalog.h>
#include <Sigmoid_neighborhoods_readers/read_tile_with_halo.h>
#include <CGAL/Sigmoid_neighborhoods/compute_optimal_sigmoid_neighborhoods.h>

#include <catch2/catch.hpp>

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

// A fresh folder of this run, removed at exit.
std::string catalog_scratch(const std::string& name)
{
  struct Scratch
  {
    std::string root;
    ~Scratch()
    {
      std::error_code ec;
      std::filesystem::remove_all(root, ec);
    }
  };
  static Scratch scratch;
  if(scratch.root.empty())
  {
    char dir[] = "/tmp/sn_catalog_XXXXXX";
    REQUIRE(::mkdtemp(dir) != nullptr);
    scratch.root = dir;
  }
  const std::string path = scratch.root + "/" + name;
  std::filesystem::create_directories(path);
  return path;
}

std::uint64_t bits(double v)
{
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof(u));
  return u;
}

// Everything a record holds, as bits: equal rows are equal records, NaNs included.
std::vector<std::uint64_t> record_bits(const SN::Optimal_sigmoid_neighborhood& r)
{
  const auto& f = r.features;
  return {bits(r.a), bits(r.b), r.k, bits(f.linearity), bits(f.planarity), bits(f.scattering), bits(f.error),
          bits(f.eigenentropy), bits(f.eigenvalues[0]), bits(f.eigenvalues[1]), bits(f.eigenvalues[2]),
          std::uint64_t(f.label), bits(r.error_equal), r.k_equal};
}

typedef std::array<std::uint64_t, 3> Position_bits;

Position_bits position_bits(const SN::Oriented_point_set::Point_3& p) { return {bits(p.x()), bits(p.y()), bits(p.z())}; }

std::vector<SN::Optimal_sigmoid_neighborhood> optimal_records(const SN::Oriented_point_set& s, unsigned int k_max)
{
  std::vector<std::uint32_t> indices(s.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = std::uint32_t(i);
  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  const auto maps = SN::parameters::k_max(
    k_max, CGAL::parameters::point_map(CGAL::make_property_map(s.points)).normal_map(CGAL::make_property_map(s.normals)));
  if(s.neighbor_offsets.empty())
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(indices, std::back_inserter(records), maps);
  else
    SN::compute_optimal_sigmoid_neighborhoods<CGAL::Parallel_if_available_tag>(
      indices, std::back_inserter(records),
      SN::parameters::neighbor_indices(std::cref(s.neighbor_indices),
                                       SN::parameters::neighbor_offsets(std::cref(s.neighbor_offsets), maps)));
  return records;
}

struct Union_records
{
  SN::Oriented_point_set points;
  std::vector<SN::Optimal_sigmoid_neighborhood> records;
};

Union_records union_records(const Lidar_io::Tile_catalog& catalog, const SN::Normal_options& normals, unsigned int k_max)
{
  SN::Normal_options kept = normals;
  kept.kept_neighbors = k_max;
  Union_records u;
  u.points = SN::read_catalog_union(catalog, kept);
  u.records = optimal_records(u.points, k_max);
  return u;
}

// Every tile with its halo against the union: the same points, in the same order, with the same
// normals, labels and records, bit for bit. Returns the tiles' halo widths.
std::vector<double> check_tiles_equal_union(const Lidar_io::Tile_catalog& catalog, const SN::Normal_options& normals,
                                            unsigned int k_max, const Union_records& u,
                                            const SN::Halo_options& halo = SN::Halo_options())
{
  const SN::Oriented_point_set& all = u.points;
  const auto& all_records = u.records;
  std::size_t next = 0; // the union's point the next tile starts with
  std::vector<double> widths;
  std::map<Position_bits, std::size_t> union_index;
  for(std::size_t i = 0; i < all.points.size(); ++i)
    union_index.emplace(position_bits(all.points[i]), i);
  for(std::size_t t = 0; t < catalog.tiles.size(); ++t)
  {
    INFO("tile " << catalog.tiles[t].name);
    const SN::Tile_with_halo tile = SN::read_tile_with_halo(catalog, t, k_max, normals, halo);
    CHECK(tile.exact);
    CHECK(tile.readings <= 2); // a halo too narrow bounds one that holds
    widths.push_back(tile.halo_width);
    const auto records = optimal_records(tile.points, k_max);
    std::size_t differing = 0;
    for(std::size_t i = tile.first; i < tile.last; ++i, ++next)
    {
      REQUIRE(next < all.points.size());
      const bool same = position_bits(tile.points.points[i]) == position_bits(all.points[next]) &&
                        bits(tile.points.normals[i].x()) == bits(all.normals[next].x()) &&
                        bits(tile.points.normals[i].y()) == bits(all.normals[next].y()) &&
                        bits(tile.points.normals[i].z()) == bits(all.normals[next].z()) &&
                        (all.labels.empty() || tile.points.labels[i] == all.labels[next]) &&
                        record_bits(records[i]) == record_bits(all_records[next]);
      differing += !same;
    }
    CHECK(differing == 0);
    // a LAS tile's records: each with its point, the union's at its position (a seam duplicate's is
    // an earlier tile's point, in the halo, whose record and normal are the union's too)
    const std::string extension = SN::lower_case_extension(catalog.tiles[t].path);
    if(extension != "las" && extension != "laz")
      CHECK(tile.point_of_record.empty());
    else if(tile.size() > 0)
    {
      CHECK(tile.point_of_record.size() == tile.input_points);
      std::size_t wrong = 0, seams = 0;
      for(std::size_t point : tile.point_of_record)
      {
        REQUIRE(point < tile.points.points.size());
        seams += point < tile.first;
        const auto u = union_index.find(position_bits(tile.points.points[point]));
        wrong += u == union_index.end() || record_bits(records[point]) != record_bits(all_records[u->second]) ||
                 tile.points.normals[point] != all.normals[u->second];
      }
      CHECK(wrong == 0);
      CHECK(seams == tile.seam_duplicates);
    }
  }
  CHECK(next == all.points.size()); // the tiles' own points, one after the other, are the union
  return widths;
}

// A grid of integer positions (ties of distances everywhere), heights of a few levels, cut into
// 3 x 2 tiles of 20 x 20 as XYZ files; the points of a seam in both tiles, as surveys deliver them.
Lidar_io::Tile_catalog grid_catalog(bool with_normals)
{
  const std::string dir = catalog_scratch(with_normals ? "grid_with_normals" : "grid");
  for(int tx = 0; tx < 3; ++tx)
    for(int ty = 0; ty < 2; ++ty)
    {
      std::ofstream out(dir + "/tile_" + std::to_string(tx) + "_" + std::to_string(ty) + ".xyz");
      for(int y = 20 * ty; y <= 20 * ty + 20; ++y)
        for(int x = 20 * tx; x <= 20 * tx + 20; ++x)
        {
          const double z = 0.25 * ((x * x + 3 * y) % 3) + 0.5 * (x > 27 && x < 33 && y > 12); // a step
          out << x << ' ' << y << ' ' << z;
          if(with_normals)
            out << " 0 " << (x % 2 == 0 ? 0.6 : 0.) << ' ' << (x % 2 == 0 ? 0.8 : 1.);
          out << '\n';
        }
    }
  return SN::read_tile_catalog(dir);
}

} // namespace

TEST_CASE("Tile catalog: tiles with halos equal the union on a grid of ties and seam duplicates", "[catalog]")
{
  const Lidar_io::Tile_catalog catalog = grid_catalog(false);
  REQUIRE(catalog.tiles.size() == 6);
  CHECK(catalog.tiles[0].name == "tile_0_0");
  CHECK(catalog.tiles[1].name == "tile_0_1");
  CHECK(catalog.tiles[0].points == 21 * 21);
  CHECK(catalog.tiles[0].extent == CGAL::Bbox_2(0, 0, 20, 20));
  CHECK_FALSE(catalog.tiles[0].extent_from_header);

  SN::Normal_options up;
  up.orientation = SN::Normal_orientation::UPWARD;
  const auto widths = check_tiles_equal_union(catalog, up, 20, union_records(catalog, up, 20));
  for(double w : widths)
    CHECK(w > 0.);

  // the union: 61 x 41 distinct positions; the seams' copies belong to the tile before
  SN::Normal_options kept = up;
  kept.kept_neighbors = 20;
  CHECK(SN::read_catalog_union(catalog, kept).points.size() == 61 * 41);
  const SN::Tile_with_halo second = SN::read_tile_with_halo(catalog, 1, 20, up); // tile_0_1: y 20..40
  CHECK(second.seam_duplicates == 21);                                          // its row y = 20
  CHECK(second.size() == 21 * 20);

  SECTION("normals from the files: the rows alone need the halo")
  {
    const Lidar_io::Tile_catalog with_normals = grid_catalog(true);
    check_tiles_equal_union(with_normals, SN::Normal_options(), 12,
                            union_records(with_normals, SN::Normal_options(), 12));
  }
  SECTION("viewpoint orientation and jet fitting are exact too; the forest is not promised")
  {
    SN::Normal_options o;
    o.source = SN::Normal_source::JET;
    o.orientation = SN::Normal_orientation::VIEWPOINT;
    o.viewpoint = SN::Oriented_point_set::Point_3(30, 20, 100);
    check_tiles_equal_union(catalog, o, 8, union_records(catalog, o, 8));
    CHECK_FALSE(SN::read_tile_with_halo(catalog, 0, 8, SN::Normal_options()).exact);
  }
  SECTION("the narrowest and the first halo are honoured; a small first halo grows")
  {
    // every tile read twice: the second halo, bounded from the first one's rows, holds
    SN::Halo_options tiny;
    tiny.initial_width = 0.01;
    SN::Normal_options jet = up;
    jet.source = SN::Normal_source::JET;
    check_tiles_equal_union(catalog, jet, 20, union_records(catalog, jet, 20), tiny);
    SN::Halo_options wide;
    wide.minimum_width = 15.;
    CHECK(SN::read_tile_with_halo(catalog, 2, 20, up, wide).halo_width >= 15.);
    SN::Halo_options narrow;
    narrow.initial_width = 0.01;
    const SN::Tile_with_halo grown = SN::read_tile_with_halo(catalog, 2, 20, up, narrow);
    CHECK(grown.readings == 2);
    CHECK(grown.halo_width > 0.01);
  }
}

// [shared-data]: a ctest entry of its own, skipped where ../shared/data is missing (test/CMakeLists.txt)
TEST_CASE("Tile catalog: the six IGN LiDAR HD tiles, with and without halos", "[catalog][las][shared-data]")
{
  const std::string dir = SN_SHARED_DATA_DIR "/labeled";
  REQUIRE(std::filesystem::exists(dir + "/ign_lidarhd_77050_627755.las"));
  // the six adjacent tiles, listed: the folder holds other surveys too
  const std::string list = catalog_scratch("six_ign_tiles") + "/tiles.txt";
  {
    std::ofstream out(list);
    for(const char* tile : {"77050_627755", "77050_627760", "77055_627755", "77055_627760", "77060_627755",
                            "77060_627760"})
      out << dir << "/ign_lidarhd_" << tile << ".las\n";
  }
  const Lidar_io::Tile_catalog catalog = SN::read_tile_catalog(list);
  REQUIRE(catalog.tiles.size() == 6);
  CHECK(catalog.tiles[0].name == "ign_lidarhd_77050_627755");
  CHECK(catalog.tiles[0].points == 73355);
  CHECK(catalog.tiles[0].extent_from_header);
  CHECK(catalog.tiles[0].extent.xmax() == Approx(770541.69).margin(1e-9)); // 770541.68 and a scale step

  SN::Normal_options up;
  up.orientation = SN::Normal_orientation::UPWARD;
  const Union_records u = union_records(catalog, up, SN::defaults::K_MAX);
  check_tiles_equal_union(catalog, up, SN::defaults::K_MAX, u);

  // Without halos, each file alone, as one gets it without a catalog: the points near the seams
  // get other neighborhoods. Matched by position (a seam's copy in the later tile has the record of
  // the union's point at its position).
  const SN::Oriented_point_set& all = u.points;
  const auto& all_records = u.records;
  std::map<Position_bits, std::size_t> union_index;
  for(std::size_t i = 0; i < all.points.size(); ++i)
    union_index.emplace(position_bits(all.points[i]), i);
  std::size_t points = 0, differing = 0;
  for(const Lidar_io::Catalog_tile& t : catalog.tiles)
  {
    SN::Normal_options alone = up;
    alone.kept_neighbors = SN::defaults::K_MAX;
    const SN::Oriented_point_set s = SN::read_oriented_point_set(t.path, alone);
    const auto records = optimal_records(s, SN::defaults::K_MAX);
    for(std::size_t i = 0; i < s.points.size(); ++i)
    {
      const std::size_t u = union_index.at(position_bits(s.points[i]));
      ++points;
      differing += record_bits(records[i]) != record_bits(all_records[u]) || s.normals[i] != all.normals[u];
    }
  }
  const double share = double(differing) / double(points);
  WARN("without halos: " << differing << " of " << points << " points (" << 100. * share
                         << " %) get records other than the union's");
  CHECK(points == 405905); // 405,937 records, 32 duplicates within the files
  CHECK(share > 0.02);     // measured: 2.81 % on these 50 m tiles
  CHECK(share < 0.04);
}

TEST_CASE("Tile catalog: refusals", "[catalog]")
{
  const std::string empty = catalog_scratch("empty");
  CHECK_THROWS_WITH(SN::read_tile_catalog(empty), Catch::Contains("no tiles"));
  CHECK_THROWS_WITH(SN::read_tile_catalog(empty + "/absent"), Catch::Contains("no such folder or file"));

  const std::string twice = catalog_scratch("twice");
  std::ofstream(twice + "/a.xyz") << "0 0 0\n1 0 0\n0 1 0\n";
  std::ofstream(twice + "/a.ply") << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                     "property float z\nend_header\n0 0 0\n";
  CHECK_THROWS_WITH(SN::read_tile_catalog(twice), Catch::Contains("a second tile named 'a'"));

  // a list file: paths relative to it, comments and blank lines skipped, the order as listed
  const std::string listed = catalog_scratch("listed");
  std::filesystem::create_directories(listed + "/tiles");
  std::ofstream(listed + "/tiles/west.xyz") << "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n1 1 0 0 0 1\n";
  std::ofstream(listed + "/tiles/east.xyz") << "2 0 0\n3 0 0\n2 1 0\n3 1 0\n";
  std::ofstream(listed + "/list.txt") << "# west first\ntiles/west.xyz\n\n  tiles/east.xyz  \n";
  const Lidar_io::Tile_catalog list = SN::read_tile_catalog(listed + "/list.txt");
  REQUIRE(list.tiles.size() == 2);
  CHECK(list.tiles[0].name == "west");
  CHECK(list.index_of("east") == 1);
  CHECK_THROWS_WITH(list.index_of("north"), Catch::Contains("no tile named 'north'"));
  // one tile with normals, one without
  SN::Normal_options o;
  o.neighbors = 3;
  CHECK_THROWS_WITH(SN::read_catalog_union(list, o), Catch::Contains("east.xyz: has no normals"));
  CHECK_THROWS_AS(SN::read_tile_with_halo(list, 2, 3, o), std::invalid_argument);
  CHECK_THROWS_AS(SN::read_tile_with_halo(list, 0, 0, o), std::invalid_argument);
  SN::Halo_options negative;
  negative.minimum_width = -1.;
  CHECK_THROWS_AS(SN::read_tile_with_halo(list, 0, 3, o, negative), std::invalid_argument);

  // a LAS header whose bounding box misses points: refused when the tile is read
  const std::string ign = SN_SHARED_DATA_DIR "/labeled/ign_lidarhd_77050_627755.las";
  if(std::filesystem::exists(ign))
  {
    const std::string forged = catalog_scratch("forged");
    std::filesystem::copy_file(ign, forged + "/tile.las");
    std::fstream f(forged + "/tile.las", std::ios::in | std::ios::out | std::ios::binary);
    const double max_x = 770520.; // the header's max x at byte 179: half the points lie beyond
    f.seekp(179);
    f.write(reinterpret_cast<const char*>(&max_x), sizeof(max_x)); // little-endian hosts only, as the tests run
    f.close();
    const Lidar_io::Tile_catalog bad = SN::read_tile_catalog(forged);
    CHECK_THROWS_WITH(SN::read_tile_with_halo(bad, 0, 20, SN::Normal_options()),
                      Catch::Contains("lies outside the tile's extent in the catalog (the header's bounding box is wrong)"));
  }
}

TEST_CASE("Tile catalog: duplicates within and across tiles, a tile of seam duplicates alone", "[catalog]")
{
  const std::string dir = catalog_scratch("seams");
  // a: a 3 x 3 grid with (1, 1, 0) twice and (2, 0, 0) written as (2, -0, 0); b: copies of a's points
  std::ofstream(dir + "/a.xyz") << "0 0 0\n1 0 0\n2 -0 0\n0 1 0\n1 1 0\n2 1 0.1\n0 2 0\n1 2 0\n2 2 0\n1 1 0\n";
  std::ofstream(dir + "/b.xyz") << "2 0 0\n2 1 0.1\n";
  std::ofstream(dir + "/c.xyz") << "3 0 0\n3 1 0.2\n3 2 0\n4 0 0\n4 1 0\n4 2 0.1\n";
  const Lidar_io::Tile_catalog catalog = SN::read_tile_catalog(dir);
  REQUIRE(catalog.tiles.size() == 3);
  SN::Normal_options o;
  o.neighbors = 4;
  o.orientation = SN::Normal_orientation::UPWARD;
  const SN::Oriented_point_set all = SN::read_catalog_union(catalog, o);
  CHECK(all.points.size() == 15); // 9 of a, none of b, 6 of c
  CHECK(all.merged_duplicates == 3); // a's second (1, 1, 0) and b's two points
  CHECK(all.input_vertices == 18);
  CHECK(all.points[2] == SN::Oriented_point_set::Point_3(2, 0, 0));
  CHECK(std::signbit(all.points[2].y())); // the first of (2, -0, 0) and (2, 0, 0) kept, as written
  CHECK(all.points[9] == SN::Oriented_point_set::Point_3(3, 0, 0));    // c after a, in file order

  const SN::Tile_with_halo b = SN::read_tile_with_halo(catalog, 1, 4, o);
  CHECK(b.size() == 0);
  CHECK(b.points.points.empty());
  CHECK(b.seam_duplicates == 2);
  CHECK(b.input_points == 2);
  const SN::Tile_with_halo c = SN::read_tile_with_halo(catalog, 2, 4, o);
  CHECK(c.size() == 6);
  CHECK(c.input_points == 6);
  CHECK(SN::read_tile_with_halo(catalog, 0, 4, o).input_points == 10);
  CHECK(c.seam_duplicates == 0);
  REQUIRE(c.points.points.size() >= c.last);
  for(std::size_t i = c.first; i < c.last; ++i)
    CHECK(c.points.points[i] == all.points[9 + i - c.first]);
}
