// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The extension module sigmoid_neighborhoods._core: the package's public C++ API on numpy arrays.

#include "bindings.h"

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>

#include <pybind11/pybind11.h>

#include <exception>

#ifndef SIGMOID_NEIGHBORHOODS_VERSION
#define SIGMOID_NEIGHBORHOODS_VERSION "0.1.0"
#endif

PYBIND11_MODULE(_core, m)
{
  namespace py = pybind11;
  m.doc() =
    "Shape-aware neighborhoods of point sets: cosine-sigmoid weights of the normal deviation, weighted\n"
    "covariance features, the optimal (a, b, k) per point, normal estimation, filtering and denoising.\n\n"
    "Arrays in: (n, 3) float32 or float64, C or Fortran order, read in place (other real or integer\n"
    "types are converted to float64, a copy); the computation is in double. Arrays out: float64\n"
    "(uint32 for sizes, int8 for labels), owned by numpy. The GIL is released while the C++ code runs;\n"
    "threads=None uses OpenMP's default, threads=1 one thread; results do not depend on it.\n"
    "Errors: ValueError (bad arguments or data, with the C++ message), OSError (files), MemoryError.";
  m.attr("__version__") = SIGMOID_NEIGHBORHOODS_VERSION;
  m.attr("DEFAULT_K_MIN") = CGAL::Sigmoid_neighborhoods::defaults::K_MIN;
  m.attr("DEFAULT_K_MAX") = CGAL::Sigmoid_neighborhoods::defaults::K_MAX;
  m.attr("LABEL_NAMES") = py::make_tuple("linear", "planar", "scattered", "degenerate");

  // an unusable file is an OSError, with the reader's one-line message
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const CGAL::Sigmoid_neighborhoods::Input_error& e)
    {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });

  sigmoid_neighborhoods_python::bind_points(m);
  sigmoid_neighborhoods_python::bind_features(m);
  sigmoid_neighborhoods_python::bind_denoising(m);
}
