// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_NORMAL_ESTIMATION_METHOD_H
#define CGAL_SIGMOID_NEIGHBORHOODS_NORMAL_ESTIMATION_METHOD_H

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

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_NORMAL_ESTIMATION_METHOD_H
