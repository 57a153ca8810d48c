// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The scratch folder of a test run, shared by the test files that write files.

#ifndef SN_TEST_SCRATCH_H
#define SN_TEST_SCRATCH_H

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

// The folder `name` of this run's scratch folder (/tmp/sn_test_XXXXXX), created on first use; the
// whole scratch folder is removed at exit.
inline std::string scratch_folder(const std::string& name)
{
  struct Root
  {
    std::string path;
    ~Root()
    {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static Root root = [] {
    char pattern[] = "/tmp/sn_test_XXXXXX";
    const char* made = ::mkdtemp(pattern);
    REQUIRE(made != nullptr);
    return Root{made};
  }();
  const std::string folder = root.path + "/" + name;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  REQUIRE(!ec);
  return folder;
}

#endif // SN_TEST_SCRATCH_H
