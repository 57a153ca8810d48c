# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of sigmoid_neighborhoods: the signatures of the compiled module (help() of each
function has its full reference)."""

import os
from typing import Any, Dict, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
DEFAULT_K_MIN: int
DEFAULT_K_MAX: int
LABEL_NAMES: Tuple[str, str, str, str]

# (n, 3) float32 or float64 in any layout, read in place; other real or integer types are converted
Coordinates = npt.ArrayLike
# (indices, offsets) in compressed rows, any integer types, as knn() returns them
NeighborRows = Tuple[npt.ArrayLike, npt.ArrayLike]
Arrays = Dict[str, npt.NDArray[Any]]

def read(
    path: Union[str, os.PathLike[str]],
    *,
    normals: Literal["auto", "file", "pca", "jet"] = "auto",
    k: int = 18,
    orientation: Literal["mst", "viewpoint", "up", "none"] = "mst",
    viewpoint: Optional[Sequence[float]] = None,
    threads: Optional[int] = None,
) -> Dict[str, Any]: ...
def write(
    path: Union[str, os.PathLike[str]],
    points: Coordinates,
    fields: Optional[Dict[str, npt.ArrayLike]] = None,
    *,
    labels: Optional[npt.ArrayLike] = None,
    intensity: Optional[npt.ArrayLike] = None,
    return_number: Optional[npt.ArrayLike] = None,
    number_of_returns: Optional[npt.ArrayLike] = None,
    gps_time: Optional[npt.ArrayLike] = None,
) -> None: ...
def knn(
    points: Coordinates, k: int, *, threads: Optional[int] = None
) -> Tuple[npt.NDArray[np.uint32], npt.NDArray[np.uint64]]: ...
def estimate_normals(
    points: Coordinates,
    k: int = 18,
    *,
    method: Literal["pca", "jet"] = "pca",
    orientation: Literal["mst", "viewpoint", "up", "none"] = "mst",
    viewpoint: Optional[Sequence[float]] = None,
    neighbors: Optional[NeighborRows] = None,
    threads: Optional[int] = None,
) -> npt.NDArray[np.float64]: ...
def features(
    points: Coordinates,
    normals: Coordinates,
    *,
    a: float = ...,
    b: float = ...,
    k: Union[int, Sequence[int]] = 20,
    barycenter: Literal["weighted", "unweighted"] = "weighted",
    line_angles: bool = False,
    angle_tolerance: float = 1e-6,
    neighbors: Optional[NeighborRows] = None,
    threads: Optional[int] = None,
) -> Arrays: ...
def optimal(
    points: Coordinates,
    normals: Coordinates,
    *,
    k_min: int = 6,
    k_max: int = 20,
    a_grid: Optional[Sequence[float]] = None,
    b_grid: Optional[Sequence[float]] = None,
    barycenter: Literal["weighted", "unweighted"] = "weighted",
    criterion: Literal["dimensionality", "eigenentropy"] = "dimensionality",
    line_angles: bool = False,
    angle_tolerance: float = 1e-6,
    all_features: bool = True,
    neighbors: Optional[NeighborRows] = None,
    threads: Optional[int] = None,
) -> Arrays: ...
def height_features(points: Coordinates, cell_size: float) -> Dict[str, npt.NDArray[np.float64]]: ...
def filter_normals(
    points: Coordinates,
    normals: Coordinates,
    *,
    iterations: int = 50,
    cut_off: float = 0.9,
    eigenvalue_threshold: float = 0.25,
    damping: float = 3.0,
    radius: Optional[float] = None,
    adaptive: bool = False,
    size_range: int = 10,
    line_angles: bool = False,
    neighbors: Optional[NeighborRows] = None,
    threads: Optional[int] = None,
) -> Tuple[npt.NDArray[np.float64], Dict[str, Any]]: ...
def denoise(
    points: Coordinates,
    normals: Coordinates,
    *,
    iterations: int = 50,
    cut_off: float = 0.9,
    eigenvalue_threshold: float = 0.25,
    damping: float = 3.0,
    radius: Optional[float] = None,
    adaptive: bool = False,
    size_range: int = 10,
    step_size: float = 0.1,
    maximum_deviation: Optional[float] = None,
    planar_weight_radius: Optional[float] = None,
    rank_threshold: float = 0.1,
    stop_at_noise_level: bool = True,
    line_angles: bool = False,
    neighbors: Optional[NeighborRows] = None,
    threads: Optional[int] = None,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], Dict[str, Any]]: ...
