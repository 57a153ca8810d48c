// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks of the feature options, one set of rules for the command line and the model files, and
// what a set of groups needs, read from the table of groups (feature_groups.cpp).

#include "feature_options.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sigmoid_tool {

namespace {

// A setting's name in a message: its option on the command line, its key in a model file.
struct Setting
{
  const char* option; // nullptr: no option sets it
  const char* key;

  std::string name(Feature_options::Source source) const
  {
    return source == Feature_options::COMMAND_LINE && option != nullptr ? option : key;
  }
};

const Setting GROUPS{"--features", "features.groups"}, FIXED_K{nullptr, "features.fixed_k"},
  K_MIN{nullptr, "features.k_min"}, K_MAX{nullptr, "features.k_max"}, SCALES{"--scales", "features.scales"},
  SIGMOID{"--sigmoid", "features.sigmoid"}, CELL_SIZES{nullptr, "features.cell_sizes"},
  CGAL_SCALES{"--cgal-scales", "features.cgal_scales"}, CGAL_VOXEL{"--cgal-voxel", "features.cgal_voxel"},
  PYRAMID_CELL{"--pyramid-cell", "features.pyramid.cell"}, PYRAMID_LEVELS{"--pyramid-levels", "features.pyramid.levels"},
  PYRAMID_K{nullptr, "features.pyramid.k"}, PYRAMID_SIGMOID_CELLS{"--pyramid-sigmoid-cells", "features.pyramid.sigmoid_cells"};

// The largest neighbor count of any setting, and the most scales or cells of a list: far beyond any
// use, so that a forged model cannot ask for a search of every point's million neighbors.
constexpr unsigned int LARGEST_K = 10000;
constexpr std::size_t LONGEST_LIST = 64;

bool positive_finite(double x) { return x > 0. && std::isfinite(x); }

} // namespace

void Feature_options::check_groups(Source source) const
{
  const std::string option = GROUPS.name(source);
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    if(find_feature_group(groups[g]) == nullptr)
    {
      std::string known;
      for(std::size_t i = 0; i < feature_groups().size(); ++i)
        known += std::string(i == 0 ? "" : i + 1 == feature_groups().size() ? " or " : ", ") + feature_groups()[i].name;
      throw Usage_error(option + ": unknown group '" + groups[g].substr(0, 64) + "': expected " + known);
    }
    if(std::find(groups.begin(), groups.begin() + std::ptrdiff_t(g), groups[g]) != groups.begin() + std::ptrdiff_t(g))
      throw Usage_error(option + ": group '" + groups[g] + "' given twice");
  }
  // at most one group of a family
  for(const Feature_group* g : groups_of(*this))
  {
    if(g->family == nullptr)
      continue;
    std::vector<std::string> family, given;
    for(const Feature_group& other : feature_groups())
      if(other.family != nullptr && std::string(other.family) == g->family)
      {
        family.push_back(other.name);
        if(std::find(groups.begin(), groups.end(), other.name) != groups.end())
          given.push_back(other.name);
      }
    if(given.size() > 1)
    {
      std::string names;
      for(std::size_t i = 0; i < family.size(); ++i)
        names += (i == 0 ? "" : i + 1 == family.size() ? " and " : ", ") + family[i];
      throw Usage_error(option + ": " + names + " share " + g->family + ": give one of them");
    }
  }
}

void Feature_options::check(Source source) const
{
  check_groups(source);
  auto refuse = [&](const Setting& s, const std::string& what) { throw Usage_error(s.name(source) + " " + what); };
  const std::string counts = "must be 1 to " + std::to_string(LARGEST_K);
  if(fixed_k < 1 || fixed_k > LARGEST_K)
    refuse(FIXED_K, counts);
  if(k_min < 1 || k_min > LARGEST_K)
    refuse(K_MIN, counts);
  if(k_max < k_min || k_max > LARGEST_K)
    refuse(K_MAX, "must be " + std::to_string(k_min) + " (k_min) to " + std::to_string(LARGEST_K));
  if(scales.empty() || scales.size() > LONGEST_LIST)
    refuse(SCALES, "must give 1 to " + std::to_string(LONGEST_LIST) + " neighbor counts");
  for(std::size_t s = 0; s < scales.size(); ++s)
    if(scales[s] < 1 || scales[s] > LARGEST_K || (s > 0 && scales[s] <= scales[s - 1]))
      refuse(SCALES, "must be ascending neighbor counts of 1 to " + std::to_string(LARGEST_K) + " (the columns are named by k)");
  if(!(sigmoid_a >= 0. && sigmoid_a <= sigmoid_b && sigmoid_b <= CGAL_PI))
    refuse(SIGMOID, "must be two angles 0 <= a <= b <= pi");
  if(cell_sizes.empty() || cell_sizes.size() > LONGEST_LIST)
    refuse(CELL_SIZES, "must give 1 to " + std::to_string(LONGEST_LIST) + " cell sizes");
  for(double c : cell_sizes)
    if(!positive_finite(c))
      refuse(CELL_SIZES, "must be positive cell sizes in metres");
  if(cgal_scales < 1 || cgal_scales > 32)
    refuse(CGAL_SCALES, "must be 1 to 32");
  if(!positive_finite(cgal_voxel) || !std::isfinite(std::ldexp(cgal_voxel, int(cgal_scales))))
    refuse(CGAL_VOXEL, "must be a positive voxel size in metres");
  if(!positive_finite(pyramid_cell))
    refuse(PYRAMID_CELL, "must be a positive cell size in metres");
  if(pyramid_levels < 1 || pyramid_levels > 32)
    refuse(PYRAMID_LEVELS, "must be 1 to 32");
  if(!std::isfinite(pyramid_cell_sizes().back()))
    refuse(PYRAMID_CELL, "is too large for " + std::to_string(pyramid_levels) + " levels");
  if(pyramid_k < 1 || pyramid_k > LARGEST_K)
    refuse(PYRAMID_K, counts);
  const std::vector<double> cells = pyramid_cell_sizes();
  for(double c : pyramid_sigmoid_cells)
    if(std::find(cells.begin(), cells.end(), c) == cells.end())
      throw Usage_error(PYRAMID_SIGMOID_CELLS.name(source) + ": " + number17(c) + " is not a cell size of the pyramid (" +
                        PYRAMID_CELL.name(source) + " x 2^l)");
}

const Feature_group* find_feature_group(const std::string& name)
{
  for(const Feature_group& g : feature_groups())
    if(name == g.name)
      return &g;
  return nullptr;
}

std::vector<const Feature_group*> groups_of(const Feature_options& o)
{
  std::vector<const Feature_group*> result;
  for(const std::string& name : o.groups)
    if(const Feature_group* g = find_feature_group(name))
      result.push_back(g);
  return result;
}

std::string feature_groups_usage()
{
  std::string text = std::string("  --features GROUPS: comma-separated, in any combination (default ") +
                     DEFAULT_FEATURE_GROUPS +
                     ":\n      the best in cross-validation at the training density and trained 4x thinner, "
                     "benchmark/README.md):\n";
  const std::size_t column = 16; // the help after the names, aligned
  for(const Feature_group& g : feature_groups())
  {
    const std::string name = g.name;
    text += "      " + name + (name.size() < column ? std::string(column - name.size(), ' ') : std::string(2, ' '));
    for(const char* c = g.help; *c != '\0'; ++c)
      text += *c == '\n' ? "\n" + std::string(6 + column, ' ') : std::string(1, *c);
    text += '\n';
  }
  return text;
}

std::vector<std::string> parse_feature_groups(const std::string& text)
{
  if(text.empty())
    throw Usage_error("--features: no group");
  Feature_options o;
  o.groups = split(text, ',');
  o.check_groups(Feature_options::COMMAND_LINE);
  return o.groups;
}

unsigned int largest_neighborhood(const Feature_options& o)
{
  unsigned int k = 0;
  for(const Feature_group* g : groups_of(o))
    k = std::max(k, g->neighbors(o));
  return k;
}

double cell_halo(const Feature_options& o, bool first_guess)
{
  double halo = 0.;
  for(const Feature_group* g : groups_of(o))
    halo = std::max(halo, g->halo(o, first_guess));
  return halo;
}

std::string whole_set_groups(const Feature_options& o)
{
  for(const Feature_group* g : groups_of(o))
    if(!g->on_tiles(o))
      return g->name;
  return "";
}

} // namespace sigmoid_tool
