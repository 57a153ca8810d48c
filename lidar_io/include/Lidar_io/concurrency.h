// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_CONCURRENCY_H
#define LIDAR_IO_CONCURRENCY_H

#include <CGAL/tags.h>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  `CGAL::Parallel_tag` in a build with OpenMP, otherwise `CGAL::Sequential_tag`: the LAZ codec
  compresses and decompresses its chunks with OpenMP. The number of threads of one call is an
  argument (0: OpenMP's default); no global setting is read or changed.
*/
#if defined(_OPENMP)
typedef CGAL::Parallel_tag Parallel_if_available_tag;
#else
typedef CGAL::Sequential_tag Parallel_if_available_tag;
#endif

} // namespace Lidar_io

#endif // LIDAR_IO_CONCURRENCY_H
