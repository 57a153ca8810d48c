// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_INPUT_FILE_H
#define SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_INPUT_FILE_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// A file about to be read: its name, its format (the lower-case extension) and its size, which
// bounds every count the file announces (Byte_budget).
struct Input_file
{
  std::string name;
  std::string extension;
  std::uintmax_t size = (std::numeric_limits<std::uintmax_t>::max)(); // unknown: no bound
};

// Checks that `filename` is a readable, non-empty file of one of `formats` (lower-case extensions);
// `expected` lists them for the message.
inline Input_file open_input_file(const std::string& filename, const std::vector<std::string>& formats,
                                  const std::string& expected)
{
  Input_file file;
  file.name = filename;
  file.extension = lower_case_extension(filename);
  std::error_code ec;
  if(std::filesystem::is_directory(filename, ec))
    throw Input_error("is a folder, not a file");
  {
    std::ifstream probe(filename, std::ios::binary | std::ios::ate);
    if(!probe)
      throw Input_error("cannot open the file");
    const std::streampos end = probe.tellg();
    if(end == std::streampos(0))
      throw Input_error("the file is empty");
    if(end > std::streampos(0))
      file.size = std::uintmax_t(std::streamoff(end));
  }
  if(std::find(formats.begin(), formats.end(), file.extension) == formats.end())
    throw Input_error("unknown format '" +
                      (file.extension.empty() ? std::string("(no extension)") : "." + file.extension) +
                      "': expected " + expected);
  return file;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL
/// \endcond

#endif // SIGMOID_NEIGHBORHOODS_READERS_INTERNAL_INPUT_FILE_H
