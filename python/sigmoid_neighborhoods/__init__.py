# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Shape-aware neighborhoods of point sets, on numpy arrays.

Weights w_ij = sig_{a,b}(angle(n_i, n_j)), a cosine sigmoid of the normal deviation; the weighted
covariance's eigenvalue features; per point the optimal (a, b, k) of least E_dim; normal estimation,
the normal filter and the denoising of Yadav et al. (2018); height features for classification.
Every function is the package's C++ function of the same name (see help() of each).
"""

from ._core import (  # noqa: F401
    DEFAULT_K_MAX,
    DEFAULT_K_MIN,
    LABEL_NAMES,
    __doc__ as _core_doc,
    __version__,
    denoise,
    estimate_normals,
    features,
    filter_normals,
    height_features,
    knn,
    optimal,
    read,
    write,
)

__all__ = [
    "DEFAULT_K_MAX",
    "DEFAULT_K_MIN",
    "LABEL_NAMES",
    "denoise",
    "estimate_normals",
    "features",
    "filter_normals",
    "height_features",
    "knn",
    "optimal",
    "read",
    "write",
]

__doc__ = __doc__ + "\n" + _core_doc
