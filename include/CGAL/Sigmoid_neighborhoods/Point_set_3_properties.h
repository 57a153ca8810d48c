// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_PROPERTIES_H
#define CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_PROPERTIES_H

#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  the prefix of the properties the `CGAL::Point_set_3` overloads add: CloudCompare loads a PLY
  property named `scalar_<name>` as the scalar field `<name>`, so that `CGAL::IO::write_PLY()` of
  the point set gives a file that CloudCompare opens with every field, and `CGAL::IO::read_PLY()`
  gives the same names back.
*/
const std::string POINT_SET_PROPERTY_PREFIX = "scalar_";

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_POINT_SET_3_PROPERTIES_H
