# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The module against analytic cases, invariants, the C++ command line bit for bit, its array
conventions (dtypes, layouts, no copies, the GIL) and bad input."""

import math
import os
import pathlib
import subprocess
import threading
import time
import tracemalloc

import numpy as np
import pytest

import sigmoid_neighborhoods as sn

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
FANDISK = os.environ.get("SN_FANDISK", str(REPOSITORY / "build/test-models/data/meshes/fandisk.off"))
TOOL = os.environ.get("SN_TOOL", str(REPOSITORY / "build/tools/sigmoid-neighborhoods/sigmoid-neighborhoods"))
SHARED_DATA = pathlib.Path(os.environ.get("SN_SHARED_DATA_DIR", str(REPOSITORY.parent / "shared/data")))
BAD_INPUT = REPOSITORY / "test/data/bad"


def needs(path):
    if not os.path.exists(path):
        pytest.skip(f"not found: {path}")
    return path


@pytest.fixture(scope="module")
def fandisk():
    model = sn.read(needs(FANDISK))
    return model["points"], model["normals"]


def grid_plane(n=12, spacing=0.1):
    """An n x n grid in the plane z = 0 (jittered so that no distances tie), normals +z."""
    rng = np.random.default_rng(3)
    x, y = np.meshgrid(np.arange(n) * spacing, np.arange(n) * spacing)
    points = np.column_stack([x.ravel(), y.ravel(), np.zeros(n * n)])
    points[:, :2] += rng.uniform(-0.01, 0.01, (n * n, 2)) * spacing
    normals = np.tile([0.0, 0.0, 1.0], (n * n, 1))
    return points, normals


def assert_same(x, y):
    """Bit for bit, NaN equal to NaN."""
    x, y = np.asarray(x), np.asarray(y)
    assert x.shape == y.shape and x.dtype == y.dtype
    assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f")


def assert_same_dict(r, s):
    assert sorted(r) == sorted(s)
    for key in r:
        assert_same(r[key], s[key])


# --- analytic cases and invariants -------------------------------------------------------------------


def test_plane_is_planar():
    points, normals = grid_plane()
    f = sn.features(points, normals, k=24)
    inside = np.all((points[:, :2] > 0.25) & (points[:, :2] < 0.85), axis=1)  # a full 5 x 5 block around
    assert inside.sum() >= 25
    assert np.all(f["label"][inside] == sn.LABEL_NAMES.index("planar"))
    assert np.all(f["planarity"][inside] > 0.5)
    assert np.all(f["scattering"] < 1e-12)
    assert np.all(f["eigenvalues"][:, 2] < 1e-15)
    assert np.allclose(f["verticality"], 0.0, atol=1e-9)
    assert np.all(f["k"] == 24) and np.all(f["a"] == math.pi) and np.all(f["b"] == math.pi)
    assert np.allclose(f["normal_z"], 1.0)


def test_line_is_linear():
    t = np.linspace(0.0, 1.0, 50) ** 1.1  # uneven spacing: no ties
    points = np.column_stack([t, 2 * t, -t])
    normals = np.tile([2.0, -1.0, 0.0], (50, 1))  # orthogonal to the line, not unit length
    f = sn.features(points, normals, k=6)
    assert np.allclose(f["linearity"], 1.0, atol=1e-12)
    assert np.all(f["label"] == 0)
    assert np.allclose(f["error"], 0.0, atol=1e-10)


def test_cube_corner_is_scattered():
    # the three faces of a cube corner, each a grid, with their face normals
    s = np.linspace(0.05, 1.0, 8)
    u, v = [a.ravel() for a in np.meshgrid(s, s)]
    zero = np.zeros_like(u)
    points = np.vstack([np.column_stack([u, v, zero]), np.column_stack([u, zero, v]), np.column_stack([zero, u, v]),
                        [[0.0, 0.0, 0.0]]])
    normals = np.vstack([np.tile([0, 0, 1.0], (64, 1)), np.tile([0, 1.0, 0], (64, 1)), np.tile([1.0, 0, 0], (64, 1)),
                         [[1.0, 1.0, 1.0]]])
    f = sn.features(points, normals, k=30)
    corner = f["eigenvalues"][-1]
    # the corner's neighborhood spreads over three orthogonal faces: no eigenvalue near 0
    assert corner[2] > 0.3 * corner[0] and f["scattering"][-1] > 0.3
    # with weights that cut at 30 degrees only the corner's own (diagonal) normal counts: no neighbors
    assert sn.features(points, normals, a=0.0, b=math.pi / 6, k=30)["label"][-1] == sn.LABEL_NAMES.index("degenerate")


def test_invariants_on_fandisk(fandisk):
    r = sn.optimal(*fandisk)
    ok = r["k"] > 0
    assert ok.mean() > 0.99
    total = r["linearity"] + r["planarity"] + r["scattering"]
    assert np.allclose(total[ok], 1.0, atol=1e-12)
    assert np.all((r["error"][ok] >= 0) & (r["error"][ok] <= math.log(3) + 1e-12))
    assert np.all(r["error"][ok] <= r["error_equal"][ok] + 1e-12)  # equal weights are in the grid
    assert np.all((r["k"][ok] >= sn.DEFAULT_K_MIN) & (r["k"][ok] <= sn.DEFAULT_K_MAX))
    assert np.all(r["a"][ok] <= r["b"][ok])
    assert np.all(np.diff(r["eigenvalues"][ok], axis=1) <= 0)
    assert np.all(np.isinf(r["error"][~ok])) and np.all(np.isnan(r["a"][~ok]))


# --- the C++ command line, bit for bit ---------------------------------------------------------------


def test_optimal_equals_the_command_line_csv(fandisk, tmp_path):
    needs(TOOL)
    csv = tmp_path / "fandisk.csv"
    subprocess.run([TOOL, "optimal", FANDISK, "-o", str(csv)], check=True, capture_output=True)
    header = csv.read_text().splitlines()[0].split(",")
    rows = [line.split(",") for line in csv.read_text().splitlines()[1:]]
    column = {name: [row[i] for row in rows] for i, name in enumerate(header)}

    def numbers(name, empty):
        return np.array([float(v) if v else empty for v in column[name]])

    points, normals = fandisk
    r = sn.optimal(points, normals)
    assert len(rows) == len(points)
    # every double is printed with 17 significant digits: the text gives the value back exactly
    assert_same(numbers("x", math.nan), points[:, 0])
    assert_same(numbers("nz", math.nan), normals[:, 2])
    assert_same(numbers("a", math.nan), r["a"])
    assert_same(numbers("b", math.nan), r["b"])
    assert_same(numbers("k", 0).astype(np.uint32), r["k"])
    assert_same(numbers("error", math.nan), r["error"])
    failed = r["k"] == 0
    for name in ("linearity", "planarity", "scattering"):
        assert_same(numbers(name, 0.0)[~failed], r[name][~failed])
    assert column["label"] == [sn.LABEL_NAMES[i] for i in r["label"]]
    assert_same(numbers("error_equal", math.nan), r["error_equal"])
    assert_same(numbers("k_equal", 0).astype(np.uint32), r["k_equal"])


def test_estimate_normals_equals_read_of_a_file_without_normals(fandisk, tmp_path):
    points = fandisk[0]
    xyz = tmp_path / "points.xyz"
    np.savetxt(xyz, points, fmt="%.17g")
    model = sn.read(xyz)
    assert model["normals_estimated"] and not model["is_mesh"]
    assert_same(model["points"], points)
    assert_same(model["normals"], sn.estimate_normals(points, 18))
    up = sn.estimate_normals(points, 12, method="jet", orientation="up")
    assert np.all(up[:, 2] >= 0)
    assert np.allclose(np.linalg.norm(up, axis=1), 1.0)


def test_optimal_point_features_agree_with_the_search(fandisk):
    points, normals = fandisk
    plain = sn.optimal(points, normals, all_features=False)
    full = sn.optimal(points, normals)
    for key in plain:
        assert_same(plain[key], full[key])
    ok = full["k"] > 0
    # the features of one fixed triple are those of a search over that triple alone
    one = sn.optimal(points, normals, k_min=12, k_max=12, a_grid=[math.pi / 6], b_grid=[math.pi / 2])
    fixed = sn.features(points, normals, a=math.pi / 6, b=math.pi / 2, k=12)
    for key in ("eigenvalues", "linearity", "planarity", "scattering", "eigenentropy", "omnivariance", "verticality",
                "radius", "sum_of_eigenvalues"):
        assert_same(one[key], fixed[key])
    assert_same(one["dimensionality_error"], fixed["error"])
    assert np.all(full["radius"][ok] > 0)


def test_several_sizes_equal_one_size_each(fandisk):
    points, normals = fandisk
    several = sn.features(points, normals, a=0.0, b=math.pi / 3, k=[25, 8])
    assert several["linearity"].shape == (len(points), 2) and several["eigenvalues"].shape == (len(points), 2, 3)
    for column, k in enumerate((25, 8)):
        one = sn.features(points, normals, a=0.0, b=math.pi / 3, k=k)
        for key in one:
            assert_same(several[key][:, column], one[key])


def test_eigenentropy_criterion(fandisk):
    r = sn.optimal(*fandisk, criterion="eigenentropy", a_grid=[math.pi], b_grid=[math.pi])
    ok = r["k"] > 0
    assert_same(r["error"], r["eigenentropy"])
    assert np.all(r["error"][ok] <= math.log(3) + 1e-12)


# --- conventions: dtypes, layouts, copies, threads, the GIL -------------------------------------------


def test_float32_is_float64_of_the_same_values(fandisk):
    points, normals = (a.astype(np.float32) for a in fandisk)
    assert_same_dict(sn.optimal(points, normals), sn.optimal(points.astype(np.float64), normals.astype(np.float64)))


def test_any_layout_gives_the_same_result(fandisk):
    points, normals = fandisk
    expected = sn.optimal(points, normals)
    assert_same_dict(sn.optimal(np.asfortranarray(points), np.asfortranarray(normals)), expected)
    # strided views: every other row, and columns of a wider array
    wide = np.zeros((len(points), 7))
    wide[:, 1:4], wide[:, 4:7] = points, normals
    assert_same_dict(sn.optimal(wide[:, 1:4], wide[:, 4:7]), expected)
    half = sn.optimal(points[::2], normals[::2])
    assert_same_dict(half, sn.optimal(points[::2].copy(), normals[::2].copy()))
    # integers are converted to float64
    grid = np.array([[x, y, 0] for x in range(6) for y in range(6)], dtype=np.int64)
    up = np.tile([0, 0, 1], (36, 1))
    assert_same_dict(sn.features(grid, up, k=8), sn.features(grid.astype(float), up.astype(float), k=8))


def test_outputs_are_numpy_arrays_and_inputs_are_not_copied(fandisk):
    points, normals = fandisk
    before = points.copy(), normals.copy()
    tracemalloc.start()
    r = sn.optimal(points, normals, all_features=False)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    outputs = sum(a.nbytes for a in r.values())
    # numpy's allocations are traced: the outputs, and nothing of the size of the input
    assert peak < outputs + points.nbytes // 2
    for a in r.values():
        assert a.flags.owndata and a.flags.c_contiguous and a.flags.writeable
    indices, offsets = sn.knn(points, 5)
    assert indices.dtype == np.uint32 and offsets.dtype == np.uint64 and indices.flags.writeable
    del r, indices, offsets  # the capsule frees the rows
    assert_same(points, before[0])
    assert_same(normals, before[1])


def test_threads_do_not_change_results(fandisk):
    one = sn.optimal(*fandisk, threads=1)
    assert_same_dict(one, sn.optimal(*fandisk, threads=2))
    assert_same_dict(one, sn.optimal(*fandisk))
    with pytest.raises(ValueError, match="threads must be at least 1"):
        sn.optimal(*fandisk, threads=0)


def test_the_gil_is_released():
    rng = np.random.default_rng(1)
    points = rng.normal(size=(60000, 3))
    normals = points / np.linalg.norm(points, axis=1)[:, None]
    done = threading.Event()
    result = {}

    def work():
        result["r"] = sn.optimal(points, normals, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    start = time.perf_counter()
    worker.start()
    ticks = 0
    while not done.is_set():  # pure Python: it runs only while the worker does not hold the GIL
        ticks += 1
    worker.join()
    elapsed = time.perf_counter() - start
    assert elapsed > 0.2  # long enough that a held GIL would show
    assert ticks > 10000
    assert len(result["r"]["k"]) == 60000


def test_caller_rows_give_the_same_result(fandisk):
    points, normals = fandisk
    indices, offsets = sn.knn(points, 20)
    assert offsets[-1] == 20 * len(points)
    expected = sn.optimal(points, normals)
    assert_same_dict(sn.optimal(points, normals, neighbors=(indices, offsets)), expected)
    # as scikit-learn or scipy give them: int64, and longer rows than needed
    longer, longer_offsets = sn.knn(points, 30)
    assert_same_dict(sn.optimal(points, normals, neighbors=(longer.astype(np.int64), longer_offsets.astype(np.int64))),
                     expected)
    assert_same(sn.estimate_normals(points, 18, neighbors=(indices, offsets)), sn.estimate_normals(points, 18))
    assert_same_dict(sn.features(points, normals, k=[5, 20], neighbors=(indices, offsets)),
                     sn.features(points, normals, k=[5, 20]))


def test_bad_caller_rows_name_the_row(fandisk):
    points, normals = fandisk
    indices, offsets = sn.knn(points, 20)
    rows = indices.astype(np.int64)

    def refused(bad_indices, bad_offsets, message, k_max=20):
        with pytest.raises(ValueError, match=message):
            sn.optimal(points, normals, k_max=k_max, neighbors=(bad_indices, bad_offsets))

    missing = rows.copy()
    missing[20 * 7 + 3] = -1  # scipy's and faiss's "no neighbor"
    refused(missing, offsets, r"indices\[143\] is -1: negative")
    beyond = rows.copy()
    beyond[20 * 9] = len(points)
    refused(beyond, offsets, "row 9: index 6475 is out of range")
    itself = rows.copy()
    itself[20 * 11 + 4] = 11
    refused(itself, offsets, "row 11 contains the point itself")
    unsorted = rows.copy()
    unsorted[20 * 5], unsorted[20 * 5 + 19] = rows[20 * 5 + 19], rows[20 * 5]
    refused(unsorted, offsets, "row 5 is not ordered by distance")
    short = np.delete(rows, 20 * 4)
    short_offsets = offsets.astype(np.int64)
    short_offsets[5:] -= 1
    refused(short, short_offsets, "row 4 has 19 neighbors, at least 20 are needed")
    refused(rows, offsets[:-1], "offsets must hold n \\+ 1")
    with pytest.raises(TypeError, match="pair"):
        sn.optimal(points, normals, neighbors=rows)
    with pytest.raises(TypeError, match="integers"):
        sn.optimal(points, normals, neighbors=(rows.astype(float), offsets))


# --- files --------------------------------------------------------------------------------------------


def test_read_a_labeled_las_tile():
    tile = needs(SHARED_DATA / "labeled/ign_lidarhd_77050_627755.las")
    model = sn.read(tile, k=0)  # no normals estimated
    assert model["normals"] is None and not model["normals_estimated"]
    assert model["input_vertices"] == 73355
    n = len(model["points"])
    assert n + model["merged_duplicates"] == 73355
    labels = model["labels"]
    assert labels.dtype == np.int32 and len(labels) == n
    assert set(np.unique(labels)) == {1, 2, 3, 4, 5, 6}
    assert abs(int(np.sum(labels == 2)) - 13881) <= model["merged_duplicates"]
    assert model["intensity"].dtype == np.uint16 and len(model["gps_time"]) == n
    assert 770500 <= model["points"][:, 0].min() and model["points"][:, 0].max() <= 770541.69


def test_read_a_laz_tile_like_its_las_twin():
    las = sn.read(needs(SHARED_DATA / "labeled/ign_lidarhd_77050_627755.las"), k=0)
    for threads in (1, 2):
        laz = sn.read(needs(SHARED_DATA / "laz/test_data_77050_627755_LA93_IGN69.laz"), k=0, threads=threads)
        for field in ("points", "labels", "intensity", "return_number", "number_of_returns", "gps_time"):
            assert np.array_equal(laz[field], las[field]), field
        assert laz["merged_duplicates"] == las["merged_duplicates"]


@pytest.mark.parametrize("extension", ["las", "laz"])
def test_write_reads_back_through_read_within_half_a_scale_unit(tmp_path, extension):
    rng = np.random.default_rng(3)
    points = rng.uniform(-50.0, 50.0, size=(500, 3)) + [651000.0, 6860000.0, 120.0]
    labels = rng.integers(0, 20, size=500)
    intensity = rng.integers(0, 65536, size=500).astype(np.uint16)
    gps_time = 3.0e8 + np.arange(500) * 1e-5
    path = tmp_path / ("out." + extension)
    sn.write(path, points, {"height": points[:, 2].astype(np.float32), "k": np.full(500, 17, dtype=np.uint8)},
             labels=labels, intensity=intensity, return_number=np.full(500, 2), number_of_returns=np.full(500, 3),
             gps_time=gps_time)
    back = sn.read(path, k=0)
    assert back["input_vertices"] == 500 and back["merged_duplicates"] == 0
    scale = 1e-7  # half extent about 50: the smallest power of ten for which it takes at most 2^30 units
    # half a unit, and the rounding of the doubles of both sides (coordinates of 6.9e6: 9.3e-10 apart)
    assert np.abs(back["points"] - points).max() <= scale / 2 + 4 * np.spacing(np.abs(points).max())
    assert np.array_equal(back["labels"], labels)
    assert np.array_equal(back["intensity"], intensity)
    assert np.all(back["return_number"] == 2) and np.all(back["number_of_returns"] == 3)
    assert np.array_equal(back["gps_time"], gps_time)
    data = path.read_bytes()
    format_byte = 6 | (0x80 if extension == "laz" else 0)  # LAZ: LASzip's compression bit
    assert data[104] == format_byte and int.from_bytes(data[105:107], "little") == 30 + 4 + 1  # float32, uint8
    assert b"height" in data and b"LASF_Spec" in data
    assert (b"laszip encoded" in data) == (extension == "laz")
    assert not list(tmp_path.glob("*.tmp"))


def test_write_refuses_what_it_cannot_write(tmp_path):
    points = np.zeros((3, 3))
    with pytest.raises(ValueError, match="writes LAS"):
        sn.write(tmp_path / "out.ply", points)
    with pytest.raises(ValueError, match="shape"):
        sn.write(tmp_path / "out.las", points, {"a": np.zeros(2)})
    with pytest.raises(ValueError, match="32 characters"):
        sn.write(tmp_path / "out.las", points, {"x" * 33: np.zeros(3)})
    with pytest.raises(ValueError, match="not finite"):
        sn.write(tmp_path / "out.las", np.array([[0.0, np.nan, 0.0]]))
    assert not list(tmp_path.iterdir())


def test_read_refuses_wave_packets_and_damaged_laz(tmp_path):
    with pytest.raises(OSError, match="wave packets"):
        sn.read(needs(SHARED_DATA / "laz/fullwave.laz"), k=0)
    cut = tmp_path / "cut.laz"
    cut.write_bytes(needs(SHARED_DATA / "laz/simple.laz").read_bytes()[:9000])
    with pytest.raises(OSError, match="cannot decode the file as laz"):
        sn.read(cut, k=0)


def test_read_estimates_zero_normals_from_their_neighbors(fandisk, tmp_path):
    points, normals = fandisk
    xyz = tmp_path / "zero.xyz"
    with_zeros = normals.copy()
    with_zeros[[5, 50, 500]] = 0.0
    np.savetxt(xyz, np.hstack([points, with_zeros]), fmt="%.17g")
    model = sn.read(xyz)
    assert model["zero_normals"] == 3 and not model["normals_estimated"]
    assert np.allclose(np.linalg.norm(model["normals"], axis=1), 1.0)
    assert np.all(np.sum(model["normals"][[5, 50, 500]] * normals[[5, 50, 500]], axis=1) > 0)  # the file's side
    with pytest.raises(OSError, match="point 5 has a zero normal"):
        sn.read(xyz, normals="file")


def test_read_errors_are_os_errors_with_the_readers_message(tmp_path):
    with pytest.raises(OSError, match="cannot open"):
        sn.read(tmp_path / "missing.ply")
    expected = {}
    for line in (BAD_INPUT / "EXPECTED.txt").read_text().splitlines():
        if line and not line.startswith("#"):
            name, status, message = line.split("\t")
            expected[name] = (int(status), message)
    checked = 0
    for name, (status, message) in expected.items():
        if status != 2 or not (BAD_INPUT / name).exists():
            continue
        # what the command line refuses, the module refuses: the file when reading it (OSError with the
        # same message), or the search on what was read (too few points for the grid: ValueError)
        try:
            model = sn.read(BAD_INPUT / name)
        except OSError as error:
            assert message in str(error), name
            checked += 1
            continue
        assert len(model["points"]) < 21, name
        with pytest.raises(ValueError if model["normals"] is not None else TypeError):
            sn.optimal(model["points"], model["normals"])
    assert checked >= 20
    with pytest.raises(ValueError, match="unknown normals"):
        sn.read(FANDISK, normals="guess")


def test_bad_arrays_are_refused_with_the_cpp_message():
    points, normals = grid_plane()
    zero = normals.copy()
    zero[3] = 0
    with pytest.raises(ValueError, match="point 3 has a zero normal"):
        sn.optimal(points, zero)
    nan = points.copy()
    nan[7, 1] = np.nan
    with pytest.raises(ValueError, match="point 7"):
        sn.features(nan, normals, k=5)
    with pytest.raises(ValueError, match="at least k_max \\+ 1 = 21 points"):
        sn.optimal(points[:20], normals[:20])
    with pytest.raises(ValueError, match="shape \\(n, 3\\), got \\(144, 2\\)"):
        sn.optimal(points[:, :2], normals)
    with pytest.raises(ValueError, match="differ in length"):
        sn.optimal(points, normals[:-1])
    with pytest.raises(TypeError, match="real numbers"):
        sn.knn(points.astype(complex), 3)
    with pytest.raises(ValueError, match="k_min"):
        sn.optimal(points, normals, k_min=0)
    with pytest.raises(ValueError, match="unknown criterion"):
        sn.optimal(points, normals, criterion="entropy")
    with pytest.raises(ValueError):
        sn.optimal(points, normals, a_grid=[4.0])


# --- the filter, the denoiser, the height features ----------------------------------------------------


def test_filter_and_denoise_leave_their_inputs_and_smooth_a_noisy_plane():
    rng = np.random.default_rng(7)
    points, _ = grid_plane(20, 0.1)
    points[:, 2] += rng.normal(scale=0.005, size=len(points))
    normals = np.tile([0.0, 0.0, 1.0], (len(points), 1)) + rng.normal(scale=0.2, size=(len(points), 3))
    normals[:, 2] = np.abs(normals[:, 2]) + 0.5
    before = points.copy(), normals.copy()
    filtered, summary = sn.filter_normals(points, normals, iterations=10)
    assert summary["iterations"] == 10 and summary["points"] == len(points)
    assert np.allclose(np.linalg.norm(filtered, axis=1), 1.0)
    unit = normals / np.linalg.norm(normals, axis=1)[:, None]
    # the filter takes the normals to the plane's: their mean deviation falls to a quarter at most
    assert np.mean(np.arccos(filtered[:, 2])) < 0.25 * np.mean(np.arccos(unit[:, 2]))
    moved, new_normals, info = sn.denoise(points, normals, iterations=5, stop_at_noise_level=False)
    assert info["iterations"] == 5 and moved.shape == points.shape
    assert np.std(moved[:, 2]) < np.std(points[:, 2])
    assert_same(points, before[0])
    assert_same(normals, before[1])


def test_height_features_of_two_cells():
    points = np.array([[0.5, 0.5, 1.0], [0.2, 0.9, 4.0], [1.5, 0.5, 2.0], [-0.5, 0.5, 7.0]])
    h = sn.height_features(points, 1.0)
    assert_same(h["height_above_lowest"], np.array([0.0, 3.0, 0.0, 0.0]))
    assert_same(h["height_below_highest"], np.array([3.0, 0.0, 0.0, 0.0]))
    assert_same(h["vertical_range"], np.array([3.0, 3.0, 0.0, 0.0]))
    with pytest.raises(ValueError, match="cell size"):
        sn.height_features(points, 0.0)


def test_help_reads_like_the_reference():
    for function in (sn.read, sn.knn, sn.estimate_normals, sn.features, sn.optimal, sn.filter_normals, sn.denoise,
                     sn.height_features):
        assert function.__doc__.startswith(function.__name__ + "(")
        assert "Returns" in function.__doc__
    assert sn.write.__doc__.startswith("write(") and "Raises" in sn.write.__doc__
    assert "Equation 9" in sn.optimal.__doc__ and "k_min" in sn.optimal.__doc__
    stub = pathlib.Path(sn.__file__).with_name("__init__.pyi")
    assert stub.exists() and "def optimal(" in stub.read_text()
