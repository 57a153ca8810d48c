# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module sigmoid_neighborhoods, built against the package's headers and Debian's CGAL,
Eigen, Boost, GMP, MPFR and OpenMP. Without network, from the repository root:

    /usr/bin/python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation --no-index ./python

(`make python` does this.) Debian's /usr/bin/python3 sees Debian's numpy; another python3 may not.
"""

import pathlib
import re

from pybind11.setup_helpers import ParallelCompile, Pybind11Extension, build_ext
from setuptools import setup

HERE = pathlib.Path(__file__).resolve().parent
REPOSITORY = HERE.parent
VERSION = re.search(r"project\(Sigmoid_neighborhoods VERSION ([0-9.]+)", (REPOSITORY / "CMakeLists.txt").read_text())[1]

# NPY_NUM_BUILD_JOBS=N compiles the translation units in parallel
ParallelCompile("NPY_NUM_BUILD_JOBS").install()

# The units, the longest first (CPU with -O3: about 30, 25 to 30, 20 and 15 s), so that two compilers
# finish together (the first free takes denoising.cpp, the other the last unit): the one reader the
# module calls (../tools/readers/src/read_oriented_point_set.cpp, the point-set reader of readers.cpp alone,
# compiled once: SIGMOID_NEIGHBORHOODS_READERS_COMPILED),
# the kernels (src/Sigmoid_neighborhoods/core.cpp, compiled once: CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE),
# then the bindings: denoising.cpp, and points.cpp, features.cpp and module.cpp in one unit
# (src/points_features_module.cpp includes them).
UNITS = ["../tools/readers/src/read_oriented_point_set.cpp", "../src/Sigmoid_neighborhoods/core.cpp",
         "src/denoising.cpp", "src/points_features_module.cpp"]
INCLUDED = ["src/points.cpp", "src/features.cpp", "src/module.cpp"]
assert sorted(UNITS + INCLUDED) == sorted(UNITS[:2] +
                                          [str(p.relative_to(HERE)) for p in (HERE / "src").glob("*.cpp")]), \
    "a file of src/ is neither a unit nor included by one"


class build_ext_in_order(build_ext):
    """setuptools sorts an extension's sources by name (reproducible objects); this compiles them in
    the order of UNITS instead (the objects are the same, linked in that order)."""

    def build_extension(self, ext):
        compile_sorted = self.compiler.compile

        def compile_in_order(sources, *args, **kwargs):
            return compile_sorted(sorted(sources, key=UNITS.index), *args, **kwargs)

        self.compiler.compile = compile_in_order
        try:
            super().build_extension(ext)
        finally:
            del self.compiler.compile


core = Pybind11Extension(
    "sigmoid_neighborhoods._core",
    UNITS,
    depends=INCLUDED,  # a change to one of them rebuilds the module
    include_dirs=[str(REPOSITORY / "include"), str(REPOSITORY / "lidar_io" / "include"),
                  str(REPOSITORY / "tools" / "readers" / "include"), "/usr/include/eigen3"],
    define_macros=[("NDEBUG", None), ("CGAL_EIGEN3_ENABLED", None), ("SIGMOID_NEIGHBORHOODS_READERS_COMPILED", None),
                   ("CGAL_SIGMOID_NEIGHBORHOODS_COMPILED_CORE", None), ("SIGMOID_NEIGHBORHOODS_VERSION", f'"{VERSION}"')],
    # the flags of the CMake build (Release): the same code as the C++ library's tests check
    # -frounding-math: CGAL's interval arithmetic (the exact predicates of the readers) needs it, as CGAL's CMake sets
    extra_compile_args=["-O3", "-g0", "-fopenmp", "-frounding-math", "-Wno-psabi"],
    extra_link_args=["-fopenmp"],
    libraries=["gmp", "mpfr"],
    cxx_std=17,
)

setup(
    name="sigmoid_neighborhoods",
    version=VERSION,
    description="Shape-aware neighborhoods of point sets: sigmoid-weighted covariance features and optimal (a, b, k)",
    license="GPL-3.0-or-later",
    packages=["sigmoid_neighborhoods"],
    package_data={"sigmoid_neighborhoods": ["__init__.pyi", "py.typed"]},
    ext_modules=[core],
    cmdclass={"build_ext": build_ext_in_order},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
