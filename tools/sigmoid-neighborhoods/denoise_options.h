// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The options the denoising commands share: noise levels, iteration counts, the seed.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_DENOISE_OPTIONS_H
#define SIGMOID_NEIGHBORHOODS_TOOL_DENOISE_OPTIONS_H

#include "command_line.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace sigmoid_tool {

// "0.3,0.6": positive noise levels
inline std::vector<double> parse_noise_levels(const std::string& text)
{
  std::vector<double> levels;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if(item.empty() || *end != '\0' || !(v > 0.) || !std::isfinite(v))
      throw Usage_error("--noise needs positive numbers separated by commas, got '" + text + "'");
    levels.push_back(v);
  }
  if(levels.empty())
    throw Usage_error("--noise needs at least one level");
  return levels;
}

// "5,10,20": positive iteration counts, at most Arguments::LARGEST_UNSIGNED_OPTION each
inline std::vector<unsigned int> parse_iteration_counts(const std::string& text)
{
  std::vector<unsigned int> counts;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
  {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(item.c_str(), &end, 10);
    if(item.empty() || *end != '\0' || errno != 0 || v < 1 || v > Arguments::LARGEST_UNSIGNED_OPTION)
      throw Usage_error("--fixed-iterations needs positive integers separated by commas, got '" + text + "'");
    counts.push_back(static_cast<unsigned int>(v));
  }
  if(counts.empty())
    throw Usage_error("--fixed-iterations needs at least one count");
  return counts;
}

inline std::uint64_t parse_seed(const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const unsigned long long seed = std::strtoull(text.c_str(), &end, 10);
  if(text.empty() || *end != '\0' || errno != 0 || text[0] == '-')
    throw Usage_error("--seed needs a non-negative integer, got '" + text + "'");
  return seed;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_DENOISE_OPTIONS_H
