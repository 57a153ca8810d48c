// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// A libFuzzer target over what `sigmoid-neighborhoods optimal` does with a file: read it with
// `read_oriented_point_set()` exactly as the command does (`read_model()`), then run the optimal
// search on a small grid and format the CSV rows.
//
// The first byte of an input selects the format and the search settings (see README.md):
//   extension  = {off, obj, ply, stl, xyz, pwn}[byte % 6]
//   barycenter = weighted if (byte / 6) is even, unweighted if odd
//   (k_min, k_max) = {(3, 6), (1, 2), (2, 4), (5, 8)}[(byte / 12) % 4]
// The other bytes are written to a file with that extension (the reader takes a file name); when
// they start with the LAS signature "LASF", with the extension las whatever the byte.
//
// Expected outcomes: success, `Input_error` from the reader (bad input, as the command's exit
// code 2). Findings: a crash, a sanitizer report, a hang, an allocation over libFuzzer's
// -malloc_limit_mb or a peak over its -rss_limit_mb, any other exception (an uncaught one aborts),
// and a broken postcondition of the search checked below, std::invalid_argument from the search
// included: the reader promises points and normals that the search accepts.
//
// Built with SIGMOID_NEIGHBORHOODS_LIBFUZZER (clang, -fsanitize=fuzzer) this is the fuzzer;
// without it, a `main` replays the files and folders given on the command line (ctest).

#include "optimal_command.h"

#include <CGAL/Sigmoid_neighborhoods.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace SN = CGAL::Sigmoid_neighborhoods;

// Inputs up to the size of the bound on memory and time (no file under 1 MiB may make the
// reader use more than 256 MiB: run with -rss_limit_mb=512 -malloc_limit_mb=256, as `make fuzz`
// does); the search on few points keeps one run well below a second under sanitizers.
constexpr std::size_t MAX_INPUT_BYTES = 1024 * 1024; // selector byte excluded
constexpr std::size_t MAX_SEARCH_POINTS = 512;       // the search runs on the first points only

const char* const EXTENSIONS[] = {"off", "obj", "ply", "stl", "xyz", "pwn"};
constexpr unsigned int NUMBER_OF_FORMATS = 6;
const char LAS_SIGNATURE[] = {'L', 'A', 'S', 'F'}; // a LAS input goes to a .las file, whatever its selector

struct K_range
{
  unsigned int k_min, k_max;
};
const K_range K_RANGES[] = {{3, 6}, {1, 2}, {2, 4}, {5, 8}};

// A broken postcondition: a finding, reported like a crash.
#define SN_FUZZ_CHECK(condition)                                                                     \
  do                                                                                                 \
  {                                                                                                  \
    if(!(condition))                                                                                 \
    {                                                                                                \
      std::fprintf(stderr, "fuzz_read_and_optimal: check failed: %s (line %d)\n", #condition, __LINE__); \
      std::abort();                                                                                  \
    }                                                                                                \
  } while(false)

std::string temporary_file(const char* extension)
{
  const char* folder = std::getenv("TMPDIR");
  std::string path = (folder != nullptr && *folder != '\0') ? folder : "/tmp";
  return path + "/sigmoid_neighborhoods_fuzz_" + std::to_string(::getpid()) + "." + extension;
}

// Removes the temporary file however the run ends, exceptions included.
struct Removed_on_exit
{
  std::string path;
  ~Removed_on_exit()
  {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

void run_search(const SN::Oriented_point_set& model, const K_range& k, SN::Barycenter barycenter)
{
  namespace SNP = SN::parameters;
  const std::vector<double> grid = SN::defaults::angle_grid(); // 0, pi/6, ..., pi
  const std::size_t n = (std::min)(model.points.size(), MAX_SEARCH_POINTS);
  const std::vector<SN::Oriented_point_set::Point_3> points(model.points.begin(), model.points.begin() + n);
  const std::vector<SN::Oriented_point_set::Vector_3> normals(model.normals.begin(), model.normals.begin() + n);
  std::vector<std::uint32_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = std::uint32_t(i);
  // 6 pairs a <= b, sharp cut-offs (a = b) and the equal weights (a = b = pi) among them.
  const std::vector<double> a_grid = {grid[0], grid[2], grid[6]};
  const std::vector<double> b_grid = {grid[0], grid[3], grid[6]};
  std::vector<SN::Optimal_sigmoid_neighborhood> records;
  SN::compute_optimal_sigmoid_neighborhoods<CGAL::Sequential_tag>(
    indices, std::back_inserter(records),
    SNP::k_min(k.k_min, SNP::k_max(k.k_max, SNP::a_grid(a_grid, SNP::b_grid(b_grid, SNP::barycenter(barycenter)))))
      .point_map(CGAL::make_property_map(points))
      .normal_map(CGAL::make_property_map(normals)));

  SN_FUZZ_CHECK(records.size() == n);
  for(const auto& r : records)
  {
    if(r.is_failure())
    {
      // Every triple is degenerate, the equal weights (a = b = pi) included.
      SN_FUZZ_CHECK(std::isinf(r.error()) && r.k_equal == 0);
      continue;
    }
    SN_FUZZ_CHECK(r.k >= k.k_min && r.k <= k.k_max);
    SN_FUZZ_CHECK(r.a <= r.b);
    SN_FUZZ_CHECK(std::isfinite(r.error()) && r.error() >= -1e-12);
    // Equal weights are among the triples: the optimum is at most as bad.
    SN_FUZZ_CHECK(r.error() <= r.error_equal + 1e-12);
  }
  // The command's CSV rows, failures included.
  sigmoid_tool::Text_rows csv;
  for(std::size_t i = 0; i < n; ++i)
    sigmoid_tool::write_optimal_row(csv, points[i], normals[i], records[i]);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1 || size - 1 > MAX_INPUT_BYTES)
    return 0;
  const unsigned int selector = data[0];
  const bool is_las =
    size - 1 >= sizeof(LAS_SIGNATURE) && std::memcmp(data + 1, LAS_SIGNATURE, sizeof(LAS_SIGNATURE)) == 0;
  const char* extension = is_las ? "las" : EXTENSIONS[selector % NUMBER_OF_FORMATS];
  const SN::Barycenter barycenter =
    (selector / NUMBER_OF_FORMATS) % 2 == 0 ? SN::Barycenter::WEIGHTED : SN::Barycenter::UNWEIGHTED;
  const K_range k = K_RANGES[(selector / (2 * NUMBER_OF_FORMATS)) % 4];

  const Removed_on_exit file{temporary_file(extension)};
  {
    std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    if(!out)
    {
      std::fprintf(stderr, "fuzz_read_and_optimal: cannot write %s\n", file.path.c_str());
      std::abort();
    }
  }

  SN::Oriented_point_set model;
  try
  {
    model = sigmoid_tool::read_model(file.path, k.k_max);
  }
  catch(const SN::Input_error&)
  {
    return 0; // bad input, refused with a message: expected
  }
  SN_FUZZ_CHECK(model.points.size() == model.normals.size());
  SN_FUZZ_CHECK(model.points.size() >= std::size_t(k.k_max) + 1);
  for(const auto& n : model.normals)
    SN_FUZZ_CHECK(std::abs(n.squared_length() - 1.) < 1e-6);
  run_search(model, k, barycenter);
  return 0;
}

#ifndef SIGMOID_NEIGHBORHOODS_LIBFUZZER

// The replay driver: every file given, and every file under every folder given, in path order.
int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for(int i = 1; i < argc; ++i)
  {
    const fs::path argument(argv[i]);
    if(fs::is_directory(argument))
    {
      for(const auto& entry : fs::recursive_directory_iterator(argument))
        if(entry.is_regular_file())
          files.push_back(entry.path());
    }
    else if(fs::is_regular_file(argument))
      files.push_back(argument);
    else
    {
      std::cerr << "fuzz_read_and_optimal: no such file or folder: " << argument << '\n';
      return EXIT_FAILURE;
    }
  }
  std::sort(files.begin(), files.end());
  if(files.empty())
  {
    std::cerr << "usage: fuzz_read_and_optimal FILE_OR_FOLDER...\n";
    return EXIT_FAILURE;
  }
  for(const fs::path& path : files)
  {
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << path.string() << std::endl;
    try
    {
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    catch(const std::exception& e)
    {
      std::cerr << "fuzz_read_and_optimal: " << path << ": unexpected exception: " << e.what() << '\n';
      return EXIT_FAILURE;
    }
  }
  std::cout << "replayed " << files.size() << " inputs" << std::endl;
  return EXIT_SUCCESS;
}

#endif // SIGMOID_NEIGHBORHOODS_LIBFUZZER
