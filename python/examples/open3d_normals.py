#!/usr/bin/env python3
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Open3D and the module on one point cloud: normals from both, compared, then the optimal search.

An open3d.geometry.PointCloud is filled from a file Open3D reads (o3d.io.read_point_cloud: .ply .pcd
.xyz .xyzn .pts ...) or, for what it does not read as a point cloud (OFF, OBJ, STL meshes, LAS), from
the points of the module's read() through o3d.utility.Vector3dVector. np.asarray(pcd.points) is a
float64 (n, 3) view of Open3D's own buffer, which the module reads in place, without a copy.

Normals are estimated by both libraries with PCA on the same neighborhoods: the module's k nearest
other points plus the point itself, and Open3D's KDTreeSearchParamKNN(knn=k + 1), whose knn counts
the point itself. Their angle, up to sign (Open3D does not orient them), is printed: mean, maximum
and the share of points below 1 degree. The module's oriented normals then go back into the
PointCloud (pcd.normals) and optimal() runs on the cloud's arrays. Nothing is displayed.

Exits with status 77 when Open3D cannot be imported (Debian: python3-open3d).

Run:

    PYTHONPATH=build/python python3 python/examples/open3d_normals.py \\
        build/test-models/data/meshes/fandisk.off --k 18
"""

import argparse
import os
import pathlib
import sys

import numpy as np

import sigmoid_neighborhoods as sn

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
DEFAULT_INPUT = os.environ.get("SN_FANDISK", str(REPOSITORY / "build/test-models/data/meshes/fandisk.off"))
# what o3d.io.read_point_cloud reads as a point cloud; anything else goes through the module's reader
OPEN3D_POINT_CLOUDS = {".ply", ".pcd", ".xyz", ".xyzn", ".xyzrgb", ".pts"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", nargs="?", type=pathlib.Path, default=pathlib.Path(DEFAULT_INPUT),
                        help=f"a point cloud or mesh (default $SN_FANDISK, else {DEFAULT_INPUT})")
    parser.add_argument("--k", type=int, default=18, help="neighbors per normal, the point excluded (default 18)")
    parser.add_argument("--threads", type=int, default=None, help="the module's threads (default: OpenMP's)")
    args = parser.parse_args()

    try:
        import open3d as o3d
    except ImportError as error:
        print(f"open3d_normals.py needs Open3D (Debian: python3-open3d): {error}", file=sys.stderr)
        return 77
    if not args.input.exists():
        print(f"not found: {args.input}", file=sys.stderr)
        return 2

    pcd = None
    if args.input.suffix.lower() in OPEN3D_POINT_CLOUDS:
        pcd = o3d.io.read_point_cloud(str(args.input))
        source = "o3d.io.read_point_cloud"
    if pcd is None or not pcd.has_points():
        # A mesh's vertices, duplicates merged and unreferenced ones dropped, as the module reads them.
        model = sn.read(args.input, normals="auto", threads=args.threads)
        pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(model["points"]))
        source = "sigmoid_neighborhoods.read"

    points = np.asarray(pcd.points)  # a view of Open3D's buffer: float64, (n, 3), C order
    assert points.dtype == np.float64 and points.flags.c_contiguous

    # The module: PCA on the point and its k nearest other points, oriented by a spanning forest.
    normals = sn.estimate_normals(points, args.k, method="pca", orientation="mst", threads=args.threads)

    # Open3D: the same PCA, but its knn counts the point itself, hence k + 1. The accurate eigen solver
    # (not the fast closed form) so that differences come from the neighborhoods, not from rounding.
    reference = o3d.geometry.PointCloud(pcd)  # a copy, so that pcd keeps no Open3D normals
    reference.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(knn=args.k + 1), fast_normal_computation=False)
    open3d_normals = np.asarray(reference.normals)

    # Up to sign: Open3D's normals are not oriented (a cloud without normals gets arbitrary signs).
    cosine = np.abs(np.einsum("ij,ij->i", normals, open3d_normals))
    cosine /= np.linalg.norm(normals, axis=1) * np.linalg.norm(open3d_normals, axis=1)
    angles = np.degrees(np.arccos(np.clip(cosine, 0.0, 1.0)))
    print(f"{args.input.name}: {len(points)} points ({source}), k = {args.k} (Open3D knn = {args.k + 1})")
    print(f"normals, module vs Open3D, up to sign: mean {angles.mean():.4f} deg, max {angles.max():.4f} deg, "
          f"below 1 deg {100.0 * np.mean(angles < 1.0):.2f} %")

    # Where the k-th and (k + 1)-th nearest other points are equally far, the two libraries may keep
    # different neighbors (the module breaks ties by index): that, not the PCA, is what differs there.
    indices, offsets = sn.knn(points, args.k + 1, threads=args.threads)
    if len(points) > args.k + 1:
        rows = indices.reshape(len(points), args.k + 1)
        distance = np.linalg.norm(points[rows[:, -2:]] - points[:, None, :], axis=2)
        tie = distance[:, 0] == distance[:, 1]
        elsewhere = angles[~tie].max() if (~tie).any() else 0.0
        print(f"points with a distance tie at the k-th neighbor: {int(tie.sum())} "
              f"(angles above 1 deg among them: {int(np.sum(angles[tie] >= 1.0))}); "
              f"max angle elsewhere {elsewhere:.4f} deg")

    # The module's oriented normals into the PointCloud, then the search on the cloud's own arrays.
    pcd.normals = o3d.utility.Vector3dVector(normals)
    result = sn.optimal(np.asarray(pcd.points), np.asarray(pcd.normals), all_features=False, threads=args.threads)
    finite = np.isfinite(result["error"])
    finite_equal = np.isfinite(result["error_equal"])
    print(f"optimal on the PointCloud: mean E_dim {result['error'][finite].mean():.6f} (optimal weights), "
          f"{result['error_equal'][finite_equal].mean():.6f} (equal weights), failures {int(np.sum(~finite))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
