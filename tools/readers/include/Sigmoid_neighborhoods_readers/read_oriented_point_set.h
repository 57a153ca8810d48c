// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef SIGMOID_NEIGHBORHOODS_READERS_READ_ORIENTED_POINT_SET_H
#define SIGMOID_NEIGHBORHOODS_READERS_READ_ORIENTED_POINT_SET_H

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Sigmoid_neighborhoods_readers/Normal_options.h>
#include <Sigmoid_neighborhoods_readers/Oriented_point_set.h>
#include <Sigmoid_neighborhoods_readers/config.h>

#include <string>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \brief reads a mesh (OFF, PLY, OBJ, STL) or a point set (XYZ/PWN lines `x y z [nx ny nz]`,
  PLY with or without `nx ny nz`, OFF without faces, LAS and LAZ) into distinct points with
  oriented unit normals, as SPEC §1 prescribes.

  Meshes: one point per vertex that has a face, its normal from
  `Polygon_mesh_processing::compute_vertex_normals()` (inconsistent orientations are repaired by
  `orient_polygon_soup()` first); vertices at one position merged, the first kept.
  Point sets: duplicates merged, the first kept, with its label and LAS fields.
  LAS 1.0 to 1.4, point data formats 0 to 10: the points (`X * scale + offset` in double) without
  normals, the classification in `Oriented_point_set::labels`, and the intensity, return number,
  number of returns and GPS time (formats other than 0 and 2) in the other per-point vectors. LAZ
  (a compressed point data format, whatever the extension) is decoded, `options.threads` chunks in
  parallel, to the records of its uncompressed twin: LASzip's point-wise and layered chunked
  compressors, fixed and variable chunks; wave packets are refused (manual, "Compressed Lidar").
  A PLY point set with a vertex property `label`, `class` or `classification` whose values are
  integers gets them in `Oriented_point_set::labels`.
  Normals, as `options` says: the file's, or estimated by `estimate_normals()` (PCA by default) on the
  `options.neighbors` nearest points and oriented by `orient_normals_by_spanning_forest()` (every
  connected component from its highest point) or towards a viewpoint, both steps on one
  k-nearest-neighbor structure. With `Normal_source::AUTO`, a file without normals gets estimated ones,
  or none when `options.neighbors` is 0 (`normals` then comes back empty). Zero normals in a point
  set's file, with `Normal_source::AUTO`: all of them zero is a file without normals; a few are each
  estimated (PCA on `options.neighbors` neighbors) and turned to agree with their neighbors' normals;
  both counted in `Oriented_point_set::zero_normals`. With `Normal_source::PCA` or `JET` the file's
  normals, zero or not, are replaced; with `Normal_source::FROM_FILE` a zero normal is an error.

  \param filename the file; its extension (any case) selects the format: `.off`, `.obj`, `.ply`,
  `.stl`, `.xyz`, `.pwn`, `.las` or `.laz`
  \param options where the normals come from and how they are estimated and oriented
  \return the points, their normals, how they were obtained, counts of merged and dropped points

  \throws Input_error with a one-line message on anything unusable: a missing, unreadable or empty
  file, an unknown extension, a syntax error, a count beyond the file, a damaged LAZ file or one with
  wave packets (the message names the chunk), non-finite coordinates,
  non-finite normals, zero normals with `Normal_source::FROM_FILE` (or with `Normal_source::AUTO` and
  `options.neighbors` 0, unless all are zero), no points, no normals with `Normal_source::FROM_FILE`,
  points on which no normal can be estimated (too few, on a line, coincident).
  \throws std::invalid_argument on options no file can satisfy: `options.neighbors` below what the
  method needs (2 for PCA, 5 for jet fitting; 0 is allowed with `Normal_source::AUTO` only).
*/
SIGMOID_NEIGHBORHOODS_READERS_FUNCTION Oriented_point_set
read_oriented_point_set(const std::string& filename, const Normal_options& options);

/*!
  \brief `read_oriented_point_set(filename, options)` with `Normal_source::AUTO` and
  `estimation_neighbors` neighbors (0: a file without normals comes back without normals).
*/
inline Oriented_point_set read_oriented_point_set(const std::string& filename,
                                                  unsigned int estimation_neighbors = DEFAULT_ESTIMATION_NEIGHBORS)
{
  Normal_options options;
  options.neighbors = estimation_neighbors;
  return read_oriented_point_set(filename, options);
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#ifndef SIGMOID_NEIGHBORHOODS_READERS_COMPILED
#include <Sigmoid_neighborhoods_readers/internal/read_oriented_point_set_impl.h>
#endif

#endif // SIGMOID_NEIGHBORHOODS_READERS_READ_ORIENTED_POINT_SET_H
