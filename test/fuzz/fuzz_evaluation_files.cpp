// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// A libFuzzer target over the readers of the evaluation files (evaluation_json.h), which `report`
// and `merge` use on files that come back from other machines or were edited by hand.
//
// The first byte of an input selects the file; the other bytes are its content (see README.md):
//   byte % 3 == 0: models/m.json, read by read_model_json() as the file of model "m"
//   byte % 3 == 1: failures.json, read by read_failures_json()
//   byte % 3 == 2: summary.json of a folder without models, read by read_summary()
//
// Expected outcomes: success, or a Usage_error (the commands' exit code 2). Findings: a crash, a
// sanitizer report, a hang, an allocation over -malloc_limit_mb or a peak over -rss_limit_mb, any
// other exception (an uncaught one aborts).
//
// Built with SIGMOID_NEIGHBORHOODS_LIBFUZZER (clang, -fsanitize=fuzzer) this is the fuzzer;
// without it, a `main` replays the files and folders given on the command line (ctest).

#include "evaluation_json.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// Inputs up to the largest summary file read, selector byte excluded.
constexpr std::size_t MAX_INPUT_BYTES = sigmoid_tool::LARGEST_SUMMARY_FILE;

// An evaluation folder of its own per process, removed however the run ends.
struct Folder
{
  fs::path root;
  Folder()
  {
    const char* tmp = std::getenv("TMPDIR");
    root = fs::path((tmp != nullptr && *tmp != '\0') ? tmp : "/tmp") /
           ("sigmoid_neighborhoods_fuzz_evaluation_" + std::to_string(::getpid()));
    fs::create_directories(root / "models");
  }
  ~Folder()
  {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

void write(const fs::path& path, const std::uint8_t* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if(!out)
  {
    std::fprintf(stderr, "fuzz_evaluation_files: cannot write %s\n", path.c_str());
    std::abort();
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1 || size - 1 > MAX_INPUT_BYTES)
    return 0;
  static Folder folder;
  std::error_code ec;
  for(const char* name : {"models/m.json", "failures.json", "summary.json"})
    fs::remove(folder.root / name, ec);
  const unsigned int which = data[0] % 3;
  const fs::path file = folder.root / (which == 0 ? "models/m.json" : which == 1 ? "failures.json" : "summary.json");
  write(file, data + 1, size - 1);
  try
  {
    if(which == 0)
    {
      sigmoid_tool::Evaluation_settings settings;
      const sigmoid_tool::Model_result m = sigmoid_tool::read_model_json(file.string(), "m", settings);
      if(m.points != m.statistics.points || m.statistics.pair_k_histogram.size() % (settings.k_max - settings.k_min + 1) != 0)
        std::abort(); // the reader promises consistent counts and sizes
    }
    else if(which == 1)
    {
      std::vector<sigmoid_tool::Model_failure> failures;
      std::vector<sigmoid_tool::Small_model> small;
      sigmoid_tool::read_failures_json(file.string(), failures, small);
      for(const auto& m : small)
        if(m.points >= m.needed)
          std::abort(); // the reader promises models smaller than the grid
    }
    else
      sigmoid_tool::read_summary(folder.root.string());
  }
  catch(const sigmoid_tool::Usage_error&)
  {
    // refused with a message: expected
  }
  return 0;
}

#ifndef SIGMOID_NEIGHBORHOODS_LIBFUZZER

// The replay driver: every file given, and every file under every folder given, in path order.
int main(int argc, char** argv)
{
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
      std::cerr << "fuzz_evaluation_files: no such file or folder: " << argument << '\n';
      return EXIT_FAILURE;
    }
  }
  std::sort(files.begin(), files.end());
  if(files.empty())
  {
    std::cerr << "usage: fuzz_evaluation_files FILE_OR_FOLDER...\n";
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
      std::cerr << "fuzz_evaluation_files: " << path << ": unexpected exception: " << e.what() << '\n';
      return EXIT_FAILURE;
    }
  }
  std::cout << "replayed " << files.size() << " inputs" << std::endl;
  return EXIT_SUCCESS;
}

#endif // SIGMOID_NEIGHBORHOODS_LIBFUZZER
