// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_OPTION_NAMES_H
#define SIGMOID_NEIGHBORHOODS_READERS_OPTION_NAMES_H

#include <CGAL/Sigmoid_neighborhoods/Neighborhood_criterion.h>
#include <CGAL/Sigmoid_neighborhoods/Normal_estimation_method.h>
#include <CGAL/Sigmoid_neighborhoods/Point_features.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/vector_instructions.h>

#include <cstddef>
#include <stdexcept>
#include <string>

// The names the command line, the tool's files and the Python module give the package's options and
// labels: a convention of those programs, not of the geometry package, whose enums they name.
namespace CGAL {
namespace Sigmoid_neighborhoods {

// `pca` or `jet`
inline const char* normal_estimation_method_name(Normal_estimation_method m)
{
  return m == Normal_estimation_method::JET ? "jet" : "pca";
}

// the method named `name`; std::invalid_argument for any other name
inline Normal_estimation_method normal_estimation_method_from_name(const std::string& name)
{
  if(name == "pca")
    return Normal_estimation_method::PCA;
  if(name == "jet")
    return Normal_estimation_method::JET;
  throw std::invalid_argument("unknown normal estimation method '" + name + "': expected pca or jet");
}

// `weighted` or `unweighted`
inline const char* barycenter_name(Barycenter b) { return b == Barycenter::UNWEIGHTED ? "unweighted" : "weighted"; }

// the barycenter named `name`; std::invalid_argument for any other name
inline Barycenter barycenter_from_name(const std::string& name)
{
  if(name == "weighted")
    return Barycenter::WEIGHTED;
  if(name == "unweighted")
    return Barycenter::UNWEIGHTED;
  throw std::invalid_argument("unknown barycenter '" + name + "': expected weighted or unweighted");
}

// `dimensionality` or `eigenentropy`
inline const char* criterion_name(Neighborhood_criterion c)
{
  return c == Neighborhood_criterion::EIGENENTROPY ? "eigenentropy" : "dimensionality";
}

// the criterion named `name`; std::invalid_argument for any other name
inline Neighborhood_criterion criterion_from_name(const std::string& name)
{
  if(name == "dimensionality")
    return Neighborhood_criterion::DIMENSIONALITY;
  if(name == "eigenentropy")
    return Neighborhood_criterion::EIGENENTROPY;
  throw std::invalid_argument("unknown criterion '" + name + "': expected dimensionality or eigenentropy");
}

// `linear`, `planar`, `scattered` or `degenerate`
inline const char* dimensionality_name(Dimensionality d)
{
  switch(d)
  {
    case Dimensionality::LINEAR: return "linear";
    case Dimensionality::PLANAR: return "planar";
    case Dimensionality::SCATTERED: return "scattered";
    default: return "degenerate";
  }
}

// `portable`, `avx2` or `avx512`
inline const char* vector_instructions_name(Vector_instructions v)
{
  return v == Vector_instructions::AVX512 ? "avx512" : v == Vector_instructions::AVX2 ? "avx2" : "portable";
}

// the feature whose point_feature_name() is `name`; std::invalid_argument for an unknown name
inline Point_feature point_feature_from_name(const std::string& name)
{
  for(std::size_t i = 0; i <= std::size_t(Point_feature::RADIUS); ++i)
    if(name == point_feature_name(Point_feature(i)))
      return Point_feature(i);
  throw std::invalid_argument("unknown point feature '" + name + "'");
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // SIGMOID_NEIGHBORHOODS_READERS_OPTION_NAMES_H
