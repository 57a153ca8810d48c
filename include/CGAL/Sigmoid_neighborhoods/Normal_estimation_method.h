// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_NORMAL_ESTIMATION_METHOD_H
#define CGAL_SIGMOID_NEIGHBORHOODS_NORMAL_ESTIMATION_METHOD_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the method of `estimate_normals()`: the value type of the named parameter `normal_estimation_method`.
*/
enum class Normal_estimation_method
{
  PCA, ///< the eigenvector of the smallest eigenvalue of the neighborhood's covariance, as `CGAL::pca_estimate_normals()`
  JET  ///< the normal of a jet (a polynomial height field) fitted by `CGAL::Monge_via_jet_fitting`, as `CGAL::jet_estimate_normals()`
};

/// \ingroup PkgSigmoidNeighborhoodsRef
/// The default method of `estimate_normals()` and of the readers.
constexpr Normal_estimation_method DEFAULT_NORMAL_ESTIMATION_METHOD = Normal_estimation_method::PCA;

/// \ingroup PkgSigmoidNeighborhoodsRef
/// The default degree of the jet of `Normal_estimation_method::JET`, CGAL's.
constexpr unsigned int DEFAULT_JET_DEGREE = 2;

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the name of a method on the command line and in files: `pca` or `jet`.
*/
inline const char* normal_estimation_method_name(Normal_estimation_method m)
{
  return m == Normal_estimation_method::JET ? "jet" : "pca";
}

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the method named `name` (`pca` or `jet`).
  \throws std::invalid_argument for any other name
*/
inline Normal_estimation_method normal_estimation_method_from_name(const std::string& name)
{
  if(name == "pca")
    return Normal_estimation_method::PCA;
  if(name == "jet")
    return Normal_estimation_method::JET;
  throw std::invalid_argument("unknown normal estimation method '" + name + "': expected pca or jet");
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_NORMAL_ESTIMATION_METHOD_H
