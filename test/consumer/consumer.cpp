// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/Sigmoid_neighborhoods/Cosine_sigmoid.h>
#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <iostream>

int main()
{
  const CGAL::Sigmoid_neighborhoods::Cosine_sigmoid sigmoid(0., 1.);
  const auto f = CGAL::Sigmoid_neighborhoods::dimensionality_features_from_eigenvalues(3., 2., 1.);
  std::cout << sigmoid(0.5) << " " << f.error << std::endl; // 0.5 and ln 3
  return sigmoid(0.5) == 0.5 ? 0 : 1;
}
