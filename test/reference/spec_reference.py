# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent reference of SPEC.md sections 2-5 (neighborhoods, sigmoid weights, weighted covariance
features, optimal (a, b, k) triple) in plain numpy, used to cross-check the C++ results.

It reads the CSV written by the command-line tool, takes only x,y,z,nx,ny,nz as input, recomputes every
other column and compares. `--self-test` checks analytic facts on this implementation alone.
Run with an interpreter that has numpy, e.g. `/usr/bin/python3 spec_reference.py RESULT.csv`.
"""
import argparse
import csv
import math
import sys

import numpy as np

HEADER = ("x,y,z,nx,ny,nz,a,b,k,error,linearity,planarity,scattering,label,error_equal,k_equal").split(",")
LABELS = ("linear", "planar", "scattered")
GRID = np.arange(7) * np.pi / 6  # A = B = {0, pi/6, ..., pi} (SPEC 5), i.e. k*np.pi/6
PAIRS = [(ia, ib) for ia in range(len(GRID)) for ib in range(ia, len(GRID))]  # a <= b, a then b ascending
EQUAL = (len(GRID) - 1, len(GRID) - 1)  # a = b = pi: the equal-weights baseline
TIE = 1e-12  # SPEC 5: a triple replaces the best only if smaller by more than this
DEGENERATE = 1e-12  # SPEC 4: degenerate if trace(C) <= DEGENERATE * sum(w) * r^2
EXACT = 1e-14  # errors this close are an exact tie (same weights): the visiting order decides them alike


def knn(P, kmax, queries):
    """Rows [i, then the kmax nearest other points] per query i, by squared distance, ties by index (SPEC 2)."""
    n = len(P)
    out = np.empty((len(queries), kmax + 1), dtype=np.int64)
    out[:, 0] = queries
    step = max(1, min(512, 10_000_000 // n))  # bounds each (rows x n) block to ~80 MB
    for s in range(0, len(queries), step):
        q = queries[s:s + step]
        m = len(q)
        d2 = (P[q, 0:1] - P[:, 0]) ** 2  # differences first, (dx^2 + dy^2) + dz^2 like a plain squared_distance
        d2 += (P[q, 1:2] - P[:, 1]) ** 2
        d2 += (P[q, 2:3] - P[:, 2]) ** 2
        d2[np.arange(m), q] = np.inf  # the point itself is not one of its k neighbors
        kth = np.partition(d2, kmax - 1, axis=1)[:, kmax - 1]
        # Every point up to the k-th distance, ties included, then sort by (distance, index) within a row.
        rows, cols = np.nonzero(d2 <= kth[:, None])
        order = np.lexsort((cols, d2[rows, cols], rows))
        rows, cols = rows[order], cols[order]
        rank = np.arange(len(rows)) - np.searchsorted(rows, rows)  # position within its row
        keep = rank < kmax
        out[s + rows[keep], 1 + rank[keep]] = cols[keep]
    return out


def angles(N, nbr, angle_tol):
    """x_ij = angle(n_i, n_j) in [0, pi]; angles <= angle_tol count as exactly 0 (SPEC 3 decision)."""
    dots = (N[nbr] * N[nbr[:, :1]]).sum(axis=2)
    # The C library's acos, correctly rounded: numpy's arccos can differ by one ulp, which decides
    # whether a normal exactly at a grid angle (e.g. perpendicular, pi/2) is kept by a cut-off.
    x = np.frompyfunc(math.acos, 1, 1)(np.clip(dots, -1.0, 1.0)).astype(np.float64)
    x[x <= angle_tol] = 0.0
    return x


def sigmoid(x, a, b):
    """Cosine sigmoid sig_{a,b} (SPEC 3); a = b is the sharp cut-off that keeps x = a."""
    if not 0.0 <= a <= b <= np.pi:
        raise ValueError("need 0 <= a <= b <= pi")
    if a == b:
        return np.where(x <= a, 1.0, 0.0)
    w = 0.5 * np.cos(np.pi * (x - a) / (b - a)) + 0.5
    return np.where(x < a, 1.0, np.where(x > b, 0.0, w))


def features(d, w, weighted=True):
    """E_dim (inf where degenerate) and (L, P, S) (nan there) for neighborhoods d (m, k+1, 3) centred at
    p_i, row 0 being p_i itself, with weights w (m, k+1) (SPEC 4). Also returns the eigenvalues."""
    sw = w.sum(axis=1)
    if weighted:
        c = np.einsum("mj,mjx->mx", w, d) / np.where(sw > 0, sw, 1.0)[:, None]
    else:
        c = d.mean(axis=1)  # the paper's literal formula: plain mean of all k+1 points
    e = d - c[:, None, :]
    C = np.einsum("mj,mjx,mjy->mxy", w, e, e)
    trace = C[:, 0, 0] + C[:, 1, 1] + C[:, 2, 2]
    r2 = (d * d).sum(axis=2).max(axis=1)  # r_i^2 over all of N_i(k), weights not considered
    lam = np.clip(np.linalg.eigvalsh(C)[:, ::-1], 0.0, None)  # descending, rounding negatives clamped
    bad = (sw <= 0) | (trace <= DEGENERATE * sw * r2) | (lam[:, 0] <= 0)
    l1 = np.where(bad, 1.0, lam[:, 0])
    lps = np.stack([lam[:, 0] - lam[:, 1], lam[:, 1] - lam[:, 2], lam[:, 2]], axis=1) / l1[:, None]
    xlnx = np.where(lps > 0, lps * np.log(np.where(lps > 0, lps, 1.0)), 0.0)  # 0 ln 0 = 0
    E = -(xlnx[:, 0] + xlnx[:, 1] + xlnx[:, 2])
    E[bad] = np.inf
    lps[bad] = np.nan
    return E, lps, lam


def margins(errs, best):
    """Per row: gap = smallest (e - e_best) over the other columns; amb = the same over the columns not
    within EXACT of e_best. gap > tol: unique minimum; amb > tol: every competitor is clearly worse or an
    exact tie that the visiting order decides, so the triple is still determined."""
    rows = np.arange(len(errs))
    e = errs[rows, best]
    with np.errstate(invalid="ignore"):
        diff = errs - e[:, None]
        diff[rows, best] = np.inf
        diff[np.isnan(diff)] = np.inf  # inf - inf: both failed, no competitor
        amb = np.where(np.abs(diff) <= EXACT, np.inf, diff)
    return diff.min(axis=1), amb.min(axis=1)


def optimise(P, N, nbr, ks, weighted=True, angle_tol=1e-6, theirs=None, chunk=4096):
    """Plain loop over a ascending, b ascending, k ascending (SPEC 5), vectorised over points.
    theirs: optional (ia, ib, k) int arrays (-1 = none); our E and L,P,S at that triple are recorded."""
    q, ks = len(nbr), list(ks)
    full = lambda v, *shape: np.full((q,) + shape, v)
    r = dict(err=full(np.inf), ia=full(-1), ib=full(-1), k=full(-1), col=full(0), lps=full(np.nan, 3),
             gap=full(np.inf), amb=full(np.inf), eq_err=full(np.inf), eq_k=full(-1), eq_gap=full(np.inf),
             eq_amb=full(np.inf), at_err=full(np.nan), at_lps=full(np.nan, 3))
    for s in range(0, q, chunk):
        sl = slice(s, min(q, s + chunk))
        nb = nbr[sl]
        d = P[nb] - P[nb[:, :1]]  # coordinates centred at p_i (SPEC 4)
        x = angles(N, nb, angle_tol)
        errs = np.empty((len(nb), len(PAIRS) * len(ks)))  # every triple's error, for the tie margins
        for ia, ib in PAIRS:
            w = sigmoid(x, GRID[ia], GRID[ib])
            w[:, 0] = 1.0  # w_ii = 1 always
            for k in ks:
                col = PAIRS.index((ia, ib)) * len(ks) + ks.index(k)
                E, lps, _ = features(d[:, :k + 1], w[:, :k + 1], weighted)
                errs[:, col] = E
                up = E < r["err"][sl] - TIE
                for key, val in (("err", E), ("ia", ia), ("ib", ib), ("k", k), ("col", col), ("lps", lps)):
                    r[key][sl][up] = val[up] if isinstance(val, np.ndarray) else val
                if (ia, ib) == EQUAL:
                    up = E < r["eq_err"][sl] - TIE
                    r["eq_err"][sl][up], r["eq_k"][sl][up] = E[up], k
                if theirs is not None:
                    at = (theirs[0][sl] == ia) & (theirs[1][sl] == ib) & (theirs[2][sl] == k)
                    r["at_err"][sl][at], r["at_lps"][sl][at] = E[at], lps[at]
        r["gap"][sl], r["amb"][sl] = margins(errs, r["col"][sl])
        eq = errs[:, -len(ks):]  # EQUAL is the last pair
        r["eq_gap"][sl], r["eq_amb"][sl] = margins(eq, np.maximum(r["eq_k"][sl] - ks[0], 0))
    return r


def read_csv(path):
    """Columns as float arrays (empty -> nan) plus the label column as strings."""
    with open(path, newline="") as f:
        rows = csv.reader(f)
        header = next(rows, None)
        if header is None or [h.strip() for h in header] != HEADER:
            raise ValueError(f"unexpected header {header!r}; expected {','.join(HEADER)}")
        data = [row for row in rows if row]
    if any(len(row) != len(HEADER) for row in data):
        raise ValueError("a row has the wrong number of fields")
    cols = {h: [row[i].strip() for row in data] for i, h in enumerate(HEADER)}
    out = {h: np.array([float(v) if v else np.nan for v in cols[h]]) for h in HEADER if h != "label"}
    out["label"] = np.array(cols["label"])
    return out


def grid_index(v):
    """Index of a radian value in GRID, -1 where missing or off the grid."""
    idx = np.full(len(v), -1)
    ok = np.isfinite(v)
    near = np.rint(np.where(ok, v, 0) / (np.pi / 6)).astype(int).clip(0, len(GRID) - 1)
    hit = ok & (np.abs(v - GRID[near]) <= 1e-9)
    idx[hit] = near[hit]
    return idx


def close(ours, theirs, tol):
    """|diff| <= tol, inf == inf agreeing (nan never agrees)."""
    with np.errstate(invalid="ignore"):
        return (np.abs(ours - theirs) <= tol) | (np.isinf(ours) & np.isinf(theirs) & (ours == theirs))


def fmt_triple(ia, ib, k):
    return "none" if ia < 0 else f"({ia}pi/6, {ib}pi/6, {k})"


def compare(args):
    try:
        t = read_csv(args.csv)
    except (OSError, ValueError, UnicodeDecodeError) as err:
        print(f"spec_reference: cannot read {args.csv}: {err}", file=sys.stderr)
        return 2
    P = np.stack([t["x"], t["y"], t["z"]], axis=1)
    N = np.stack([t["nx"], t["ny"], t["nz"]], axis=1)
    n = len(P)
    if not (1 <= args.k_min <= args.k_max < n) or not (np.isfinite(P).all() and np.isfinite(N).all()):
        print(f"spec_reference: need 1 <= k-min <= k-max < points ({n}) and finite x..nz", file=sys.stderr)
        return 2
    q = n if args.max_points is None else max(0, min(n, args.max_points))
    ks = range(args.k_min, args.k_max + 1)
    tia, tib = grid_index(t["a"][:q]), grid_index(t["b"][:q])
    tk = np.where(np.isfinite(t["k"][:q]), t["k"][:q], -1).astype(int)
    nbr = knn(P, args.k_max, np.arange(q))
    r = optimise(P, N, nbr, ks, args.barycenter == "weighted", args.angle_tolerance, (tia, tib, tk))
    tol = args.tolerance
    bad = []  # (index, what, ours, theirs), for the first few disagreeing rows

    def tally(name, ok, mask, ours, theirs, worst=None):
        ok_n, tot = int((ok & mask).sum()), int(mask.sum())
        line = f"{name:<13} agree {ok_n}/{tot}" + (f" ({100.0 * ok_n / tot:.3f} %)" if tot else "")
        if worst is not None and (mask & np.isfinite(worst)).any():
            w = np.where(mask & np.isfinite(worst), worst, -1.0)
            line += f"; worst |diff| {w.max():.3g} at #{int(w.argmax())}"
        print(line)
        for i in np.flatnonzero(mask & ~ok)[:5]:
            bad.append((int(i), name, ours(i), theirs(i)))
        return ok_n, tot

    with np.errstate(invalid="ignore"):
        print(f"spec_reference: {args.csv}")
        print(f"points checked: {q} of {n} (k {args.k_min}..{args.k_max}, barycenter {args.barycenter}, "
              f"angle tolerance {args.angle_tolerance:g}, tolerance {tol:g})")
        every = np.ones(q, dtype=bool)
        ok_e, _ = tally("error", close(r["err"], t["error"][:q], tol), every, lambda i: r["err"][i],
                        lambda i: t["error"][i], np.abs(r["err"] - t["error"][:q]))
        ok_q, _ = tally("error_equal", close(r["eq_err"], t["error_equal"][:q], tol), every, lambda i: r["eq_err"][i],
                        lambda i: t["error_equal"][i], np.abs(r["eq_err"] - t["error_equal"][:q]))
        # The triple is checked where it is decided: a unique minimum (every other triple worse by more than
        # tol) or exact ties (within EXACT) that the visiting order resolves; near-ties are only counted.
        fin = np.isfinite(r["err"])
        uniq, decided = fin & (r["gap"] > tol), fin & (r["amb"] > tol)
        same = (r["ia"] == tia) & (r["ib"] == tib) & (r["k"] == tk)
        ours_t = lambda i: fmt_triple(r["ia"][i], r["ib"][i], r["k"][i])
        theirs_t = lambda i: fmt_triple(tia[i], tib[i], tk[i])
        ok_u, tot_u = tally("(a,b,k) uniq", same, uniq, ours_t, theirs_t)
        ok_t, tot_t = tally("(a,b,k) ties", same, decided & ~uniq, ours_t, theirs_t)
        near = fin & ~decided
        print(f"{'':<13} near-tie points (not checked): {int(near.sum())}, "
              f"of which same triple: {int((near & same).sum())}")
        tek = np.where(np.isfinite(t["k_equal"][:q]), t["k_equal"][:q], -1).astype(int)
        tally("k_equal", r["eq_k"] == tek, every, lambda i: r["eq_k"][i], lambda i: tek[i])
        ok_ke, tot_ke = tally("k_equal decid", r["eq_k"] == tek, np.isfinite(r["eq_err"]) & (r["eq_amb"] > tol),
                              lambda i: r["eq_k"][i], lambda i: tek[i])
        # L, P, S, label and E recomputed at the C++ triple: where both triples agree this is the optimal one.
        has = tk >= 0
        tally("E at C++ abk", close(r["at_err"], t["error"][:q], tol), has, lambda i: r["at_err"][i],
              lambda i: t["error"][i], np.abs(r["at_err"] - t["error"][:q]))
        for j, name in enumerate(("linearity", "planarity", "scattering")):
            tally(name, close(r["at_lps"][:, j], t[name][:q], tol), has, lambda i, j=j: r["at_lps"][i, j],
                  lambda i, name=name: t[name][i], np.abs(r["at_lps"][:, j] - t[name][:q]))
        fin = np.isfinite(r["at_lps"]).all(axis=1)
        argmax = np.argmax(np.nan_to_num(r["at_lps"], nan=-1.0), axis=1)  # ties to the first
        ours_lab = np.where(fin, np.array(LABELS)[argmax], "degenerate")
        tally("label", ours_lab == t["label"][:q], has, lambda i: ours_lab[i], lambda i: t["label"][i])
        print(f"failures (every triple degenerate): ours {int(np.isinf(r['err']).sum())}, "
              f"C++ {int(np.isinf(t['error'][:q]).sum())}")
    if bad:
        print("first disagreements (index, quantity: ours vs C++):")
        for i, name, o, th in sorted(bad)[:12]:
            print(f"  #{i} {name}: {o!r} vs {th!r}")
    rate = lambda ok: ok / q if q else 1.0
    passed = (rate(ok_e) >= args.min_agreement and rate(ok_q) >= args.min_agreement
              and ok_u == tot_u and ok_t == tot_t and ok_ke == tot_ke)
    print("result: " + ("PASS" if passed else "FAIL"))
    return 0 if passed else 1


def self_test():
    """Analytic facts (SPEC 2-5) checked on this implementation only."""
    rng = np.random.default_rng(7)
    results = []

    def check(name, ok):
        results.append(bool(ok))
        print(("OK   " if ok else "FAIL ") + name)

    def frame(u):  # two unit vectors orthogonal to u
        v = np.cross(u, [1.0, 0.0, 0.0] if abs(u[0]) < 0.9 else [0.0, 1.0, 0.0])
        v /= np.linalg.norm(v)
        return v, np.cross(u, v)

    def single(P, N, k, a, b, weighted=True):  # features of point 0 for one triple, through knn and weights
        nb = knn(P, k, np.array([0]))
        w = sigmoid(angles(N, nb, 1e-6), a, b)
        w[:, 0] = 1.0
        E, lps, lam = features(P[nb] - P[nb[:, :1]], w, weighted)
        return E[0], lps[0], lam[0], w[0]

    u = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    v, z = frame(u)
    line = np.outer([0.0, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 9.0], u) + 0.5  # one far point not in N_0(6)
    E, lps, _, _ = single(line, np.tile(v, (8, 1)), 6, np.pi, np.pi)
    check("collinear, k=6, equal weights: L = 1, E = 0", abs(lps[0] - 1) <= 1e-12 and abs(E) <= 1e-12)
    t = np.arange(6) * np.pi / 3
    hexa = np.vstack([[0, 0, 0], np.outer(np.cos(t), u) + np.outer(np.sin(t), v)]) + [0.3, -1.2, 2.0]
    E, lps, lam, _ = single(hexa, np.tile(z, (7, 1)), 6, np.pi, np.pi)
    check("hexagon ring, k=6: lambda1 = lambda2, E = 0", abs(lam[0] - lam[1]) <= 1e-12 * lam[0] and abs(E) <= 1e-12)
    r = optimise(hexa, np.tile(z, (7, 1)), knn(hexa, 6, np.arange(1)), [6])
    check("all 28 (a, b) tie: the order rule picks a = b = 0", (r["ia"][0], r["ib"][0], r["k"][0]) == (0, 0, 6))
    flipped = np.tile(z, (7, 1))
    flipped[0] = -z
    E, lps, lam, w = single(hexa, flipped, 6, 0.0, 0.0)
    check("flipped normal, a = b = 0: sum w = 1, C = 0, degenerate", w.sum() == 1.0 and np.isinf(E) and lam[0] == 0)
    r = optimise(hexa, flipped, knn(hexa, 6, np.arange(1)), [6])
    check("flipped normal: optimum is finite and not a = b = 0", np.isfinite(r["err"][0]) and r["ib"][0] > 0)
    x = np.array([0.0, 0.2, 0.5, 0.8, 1.0, 1.2])
    check("sigmoid: 1 below a, 1/2 midway, 0 at and beyond b; a = b keeps x = a",
          np.allclose(sigmoid(x, 0.2, 0.8), [1, 1, 0.5, 0, 0, 0], atol=1e-15)
          and list(sigmoid(x, 0.5, 0.5)) == [1, 1, 1, 0, 0, 0])
    # Random data: L + P + S = 1 and 0 <= E <= ln 3 on every non-degenerate triple.
    P = rng.normal(size=(300, 3))
    N = rng.normal(size=(300, 3))
    N /= np.linalg.norm(N, axis=1)[:, None]
    nb = knn(P, 20, np.arange(300))
    d, xa = P[nb] - P[nb[:, :1]], angles(N, nb, 1e-6)
    sums, Es, fails = [], [], 0
    for ia, ib in PAIRS:
        w = sigmoid(xa, GRID[ia], GRID[ib])
        w[:, 0] = 1.0
        for k in (6, 13, 20):
            for weighted in (True, False):
                E, lps, _ = features(d[:, :k + 1], w[:, :k + 1], weighted)
                fin = np.isfinite(E)
                fails += int((~fin).sum())
                sums.append(lps[fin].sum(axis=1))
                Es.append(E[fin])
    sums, Es = np.concatenate(sums), np.concatenate(Es)
    check("random: L + P + S = 1", np.abs(sums - 1).max() <= 1e-12)
    check("random: 0 <= E <= ln 3", Es.min() >= 0 and Es.max() <= math.log(3) + 1e-12)
    check("random: a = b = 0 with random normals has degenerate triples", fails > 0)
    # k-NN on an integer grid (many exact distance ties) against a plain full sort by (distance, index).
    G = np.stack(np.meshgrid(*[np.arange(5.0)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)[rng.permutation(125)]
    ours = knn(G, 20, np.arange(125))
    ref = np.empty_like(ours)
    for i in range(125):
        d2 = ((G - G[i]) ** 2).sum(axis=1)
        d2[i] = -1.0  # the point itself first
        ref[i] = np.lexsort((np.arange(125), d2))[:21]
    check("k-NN with ties: distance order, ties by index", (ours == ref).all())
    print("self-test: " + ("OK" if all(results) else "FAIL"))
    return 0 if all(results) else 1


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csv", nargs="?", metavar="RESULT.csv", help="CSV written by the C++ command-line tool")
    ap.add_argument("--k-min", type=int, default=6)
    ap.add_argument("--k-max", type=int, default=20)
    ap.add_argument("--barycenter", choices=("weighted", "unweighted"), default="weighted")
    ap.add_argument("--angle-tolerance", type=float, default=1e-6, help="angles <= this count as 0 (radians)")
    ap.add_argument("--tolerance", type=float, default=1e-9, help="absolute tolerance on errors and L, P, S; "
                    "also the margin that makes a minimum unique")
    ap.add_argument("--min-agreement", type=float, default=0.999, help="share of points whose error and "
                    "error_equal must agree")
    ap.add_argument("--max-points", type=int, default=None, help="check only the first N points as queries")
    ap.add_argument("--self-test", action="store_true", help="check analytic facts on this implementation")
    args = ap.parse_args(argv)
    if args.self_test:
        return self_test()
    if args.csv is None:
        ap.print_usage(sys.stderr)
        return 2
    return compare(args)


if __name__ == "__main__":
    sys.exit(main())
