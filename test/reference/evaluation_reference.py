# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent numpy check of the statistics written by `sigmoid-neighborhoods evaluate --per-point`.

For every model of an evaluation folder (OUTDIR/models/<path>.json with its per-point <path>.csv) it
reads only x,y,z,nx,ny,nz from the CSV and recomputes, with the machinery of spec_reference.py (SPEC
2-5), per point: the optimal (a, b, k) triple (tie rule of SPEC 5), equal weights a = b = pi at their
best k, the cut-off a = b = arccos(0.9) at its best k, equal weights at settings.fixed_k, the labels,
and the Table 3 lowering tests (doc/specification.md, "The evaluation"; SPEC 6). It aggregates them per
model (count, failures, sum, sum of squares, min, max, mean, population sd, label counts, k histograms,
the (a*, b*) x k* histogram, Table 3, mean and sd of k*) and compares every number with the model's
JSON, then folds the models into the repository totals and compares them with summary.json.

Counts and histograms must be equal, except where a near-tie makes the choice legitimately ambiguous:
two triples (or two k) whose errors lie within 1e-9 of each other but not within 1e-14 (an exact tie,
which the visiting order decides alike in both implementations), or two of L, P, S within 1e-9 for a
label. Such points are counted; where the tool picked another member of the near-tie its choice is
adopted (the "adjusted" aggregate, which must match exactly), and the raw differences are reported.
Floating values must agree to 1e-9, relative above 1 and absolute below (|d| <= 1e-9 max(1, |x|, |y|)).
Angles within 1e-9 of a weight edge are recomputed with the C library's acos (see angles_libm): numpy's
arccos can be one ulp off there, which flips a sharp cut-off x <= a.

Usage: /usr/bin/python3 evaluation_reference.py OUTDIR [--max-points-per-model N]
Exit status: 0 agreement, 1 disagreement, 2 bad usage or unreadable folder.
"""
import argparse
import csv
import json
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import spec_reference as ref  # noqa: E402  (SPEC 2-5: knn, angles, sigmoid, features)

HEADER = ("x,y,z,nx,ny,nz,a,b,k,error,linearity,planarity,scattering,label,error_equal,k_equal,label_equal,"
          "error_cut_off,k_cut_off,label_cut_off,error_fixed_k,label_fixed_k").split(",")
LABELS = ref.LABELS  # linear, planar, scattered; index 3 = no label (failure)
NEAR = 1e-9  # two choices closer than this are a near-tie: either one is legitimate
EXACT = ref.EXACT  # closer than this: an exact tie that the visiting order decides alike
TIE = ref.TIE  # SPEC 5: replace the best only if smaller by more than this
TOL = 1e-9  # floating values: |d| <= TOL * max(1, |ours|, |theirs|)
WEIGHTINGS = ("equal", "cut_off", "optimal", "fixed_k")
TABLE3 = ("a_zero", "a_lower_valid", "a_lower_fails", "b_equals_a", "b_lower_valid", "b_lower_fails")


class UsageError(Exception):
    pass


# ----------------------------------------------------------------------------------------------------
# Input

def read_csv(path):
    with open(path, newline="") as f:
        rows = csv.reader(f)
        header = next(rows, None)
        if header is None or [h.strip() for h in header] != HEADER:
            raise UsageError(f"{path}: unexpected header {header!r}")
        data = [row for row in rows if row]
    if any(len(row) != len(HEADER) for row in data):
        raise UsageError(f"{path}: a row has the wrong number of fields")
    out = {}
    for i, h in enumerate(HEADER):
        col = [row[i].strip() for row in data]
        if h.startswith("label"):
            out[h] = np.array([LABELS.index(v) if v in LABELS else 3 for v in col], dtype=np.int64)
        else:
            out[h] = np.array([float(v) if v else np.nan for v in col])
    return out


def grid_index(values, grid):
    """Index of each value in grid (within 1e-9), -1 where missing or off the grid."""
    idx = np.full(len(values), -1)
    for j, g in enumerate(grid):
        idx[np.isfinite(values) & (np.abs(values - g) <= 1e-9)] = j
    return idx


def int_or(values, missing=-1):
    ok = np.isfinite(values) & (values > 0)
    return np.where(ok, np.nan_to_num(values), missing).astype(np.int64)


# ----------------------------------------------------------------------------------------------------
# Per-point recomputation

def labels_of(lps):
    """Label index (argmax, ties to the first; 3 if not finite) and a bit mask of the labels within NEAR
    of the largest (the labels a legitimate implementation may report)."""
    fin = np.isfinite(lps).all(axis=1)
    z = np.where(fin[:, None], lps, -1.0)
    lab = np.where(fin, np.argmax(z, axis=1), 3)
    top = z.max(axis=1)
    alt = np.zeros(len(lps), dtype=np.uint8)
    for j in range(3):
        alt |= np.where(fin & (z[:, j] >= top - NEAR), 1 << j, 0).astype(np.uint8)
    alt |= np.where(fin, 0, 1 << 3).astype(np.uint8)
    return lab, alt


def angles_libm(N, nb, tol, edges):
    """ref.angles, except that angles within 1e-9 of a weight edge (a grid value or the cut-off) are
    recomputed with the C library's acos (math.acos): numpy's arccos is not correctly rounded, and one ulp
    decides a sharp cut-off at x = a (measured: arccos(-5.33e-17) gives pi/2 in numpy, pi/2 + 1 ulp in
    libm). Returns the angles and how many of them changed."""
    x = ref.angles(N, nb, tol)
    edge = np.zeros(x.shape, dtype=bool)
    for v in edges:
        edge |= np.abs(x - v) <= 1e-9
    if not edge.any():
        return x, 0
    dots = np.clip((N[nb] * N[nb[:, :1]]).sum(axis=2), -1.0, 1.0)
    y = np.array([math.acos(v) for v in dots[edge]])
    y[y <= tol] = 0.0
    changed = int((y != x[edge]).sum())
    x[edge] = y
    return x, changed


def sequential_best(errs):
    """SPEC 5: visit the columns in order, replace only if smaller by more than TIE. -1 = failure."""
    best = np.full(len(errs), np.inf)
    col = np.full(len(errs), -1)
    for c in range(errs.shape[1]):
        up = errs[:, c] < best - TIE
        best[up] = errs[up, c]
        col[up] = c
    return col


def decide(errs, lab, alt, tool_col, tool_lab):
    """Our choice (col, -1 = failure) and the adjusted choice: the tool's where it is a member of a
    near-tie with ours. Same for labels. Returns a dict of per-point arrays."""
    m = len(errs)
    rows = np.arange(m)
    col = sequential_best(errs)
    ok = col >= 0
    best = np.where(ok, errs[rows, np.maximum(col, 0)], np.inf)
    with np.errstate(invalid="ignore"):
        diff = np.abs(errs - best[:, None])
    cand = np.isfinite(diff) & (diff <= NEAR)
    amb = (cand & (diff > EXACT)).any(axis=1)  # a competitor within NEAR that is not an exact tie
    tc = np.maximum(tool_col, 0)
    tool_in = (tool_col >= 0) & cand[rows, tc]
    adj = np.where((col != tool_col) & amb & tool_in, tool_col, col)
    a0 = np.maximum(adj, 0)
    lab_raw = np.where(ok, lab[rows, np.maximum(col, 0)], 3)
    lab_adj = np.where(adj >= 0, lab[rows, a0], 3)
    alt_adj = np.where(adj >= 0, alt[rows, a0], 1 << 3)
    lab_amb = (adj >= 0) & (np.bitwise_count(alt_adj) > 1 if hasattr(np, "bitwise_count")
                            else np.array([bin(v).count("1") > 1 for v in alt_adj], dtype=bool))
    take = (adj == tool_col) & (tool_lab != lab_adj) & (((alt_adj >> np.clip(tool_lab, 0, 3)) & 1) == 1)
    lab_adj = np.where(take, tool_lab, lab_adj)
    return dict(col=col, adj=adj, amb=amb, lab=lab_raw, lab_adj=lab_adj, lab_amb=lab_amb,
                err=np.where(ok, errs[rows, np.maximum(col, 0)], np.inf),
                err_adj=np.where(adj >= 0, errs[rows, a0], np.inf))


def evaluate_points(P, N, t, s, chunk=1024):
    """Recompute every weighting per point. s: settings (lists A, B, ks, fixed_k, cut, weighted, tol)."""
    n = len(P)
    A, B, ks = s["A"], s["B"], s["ks"]
    pairs = [(ia, ib) for ia in range(len(A)) for ib in range(len(B)) if A[ia] <= B[ib]]
    nk = len(ks)
    kq = max(ks[-1], s["fixed_k"])
    nbr = ref.knn(P, kq, np.arange(n))
    # The tool's choices from its CSV, as columns.
    tia, tib = grid_index(t["a"], A), grid_index(t["b"], B)
    tk = int_or(t["k"])
    pair_of = {p: i for i, p in enumerate(pairs)}
    tp = np.array([pair_of.get((ia, ib), -1) for ia, ib in zip(tia, tib)])
    tool_opt = np.where((tp >= 0) & (tk >= ks[0]) & (tk <= ks[-1]), tp * nk + tk - ks[0], -1)
    tool_eq = np.where(int_or(t["k_equal"]) >= ks[0], int_or(t["k_equal"]) - ks[0], -1)
    tool_co = np.where(int_or(t["k_cut_off"]) >= ks[0], int_or(t["k_cut_off"]) - ks[0], -1)
    tool_fx = np.where(np.isfinite(t["error_fixed_k"]), 0, -1)
    res = {w: {} for w in WEIGHTINGS}
    res["libm_angles"] = 0
    edges = sorted(set(A) | set(B) | {s["cut"], math.pi, s["tol"]})
    ta = {"raw": np.full(n, -1), "adj": np.full(n, -1)}
    tb = {"raw": np.full(n, -1), "adj": np.full(n, -1)}
    parts = {w: [] for w in WEIGHTINGS}
    for s0 in range(0, n, chunk):
        sl = slice(s0, min(n, s0 + chunk))
        nb = nbr[sl]
        m = len(nb)
        d = P[nb] - P[nb[:, :1]]
        x, changed = angles_libm(N, nb, s["tol"], edges)
        res["libm_angles"] += changed

        def run(a, b, klist):
            w = ref.sigmoid(x, a, b)
            w[:, 0] = 1.0
            e = np.empty((m, len(klist)))
            lab = np.empty((m, len(klist)), dtype=np.int64)
            alt = np.empty((m, len(klist)), dtype=np.uint8)
            for j, k in enumerate(klist):
                E, lps, _ = ref.features(d[:, :k + 1], w[:, :k + 1], s["weighted"])
                e[:, j] = E
                lab[:, j], alt[:, j] = labels_of(lps)
            return e, lab, alt

        blocks = [run(A[ia], B[ib], ks) for ia, ib in pairs]
        errs = np.concatenate([b[0] for b in blocks], axis=1)
        lab = np.concatenate([b[1] for b in blocks], axis=1)
        alt = np.concatenate([b[2] for b in blocks], axis=1)
        opt = decide(errs, lab, alt, tool_opt[sl], t["label"][sl])
        # Table 3 at our and at the adjusted triple: validity of (prev a*, b*, k*) and (a*, prev b*, k*).
        for key, c in (("raw", opt["col"]), ("adj", opt["adj"])):
            ok = c >= 0
            c0 = np.maximum(c, 0)
            p, j = c0 // nk, c0 % nk
            ia = np.array([pairs[q][0] for q in p])
            ib = np.array([pairs[q][1] for q in p])
            a_cls = np.full(m, -1)
            b_cls = np.full(m, -1)
            for r in np.flatnonzero(ok):
                if ia[r] == 0:
                    a_cls[r] = 0
                else:
                    q = pair_of.get((ia[r] - 1, ib[r]))  # A[ia-1] < A[ia] <= B[ib]: always a pair
                    a_cls[r] = 1 if np.isfinite(errs[r, q * nk + j[r]]) else 2
                if A[ia[r]] == B[ib[r]]:
                    b_cls[r] = 3
                else:
                    q = pair_of.get((ia[r], ib[r] - 1))
                    if q is None:  # prev(b*) < a*: not a pair (never on the default grids)
                        b_cls[r] = 5
                    else:
                        b_cls[r] = 4 if np.isfinite(errs[r, q * nk + j[r]]) else 5
            ta[key][sl], tb[key][sl] = a_cls, b_cls
        # Equal weights at each k and at fixed_k; cut-off at each k.
        e_eq, l_eq, a_eq = run(np.pi, np.pi, ks)
        eq = decide(e_eq, l_eq, a_eq, tool_eq[sl], t["label_equal"][sl])
        e_co, l_co, a_co = run(s["cut"], s["cut"], ks)
        co = decide(e_co, l_co, a_co, tool_co[sl], t["label_cut_off"][sl])
        e_fx, l_fx, a_fx = run(np.pi, np.pi, [s["fixed_k"]])
        fx = decide(e_fx, l_fx, a_fx, tool_fx[sl], t["label_fixed_k"][sl])
        for w, r in (("optimal", opt), ("equal", eq), ("cut_off", co), ("fixed_k", fx)):
            parts[w].append(r)
    for w in WEIGHTINGS:
        res[w] = {key: np.concatenate([r[key] for r in parts[w]]) for key in parts[w][0]}
    res["table3"] = {"raw": (ta["raw"], tb["raw"]), "adj": (ta["adj"], tb["adj"])}
    res["tool"] = dict(optimal=tool_opt, equal=tool_eq, cut_off=tool_co, fixed_k=tool_fx)
    res["pairs"] = pairs
    return res


# ----------------------------------------------------------------------------------------------------
# Aggregation (kept as raw material so that folding is exact) and derived statistics

def raw_aggregate(res, nk, which):
    """which: 'raw' (our choices) or 'adj' (the tool's where a near-tie allows). Arrays per model."""
    col, err, lab = ("col", "err", "lab") if which == "raw" else ("adj", "err_adj", "lab_adj")
    g = {"points": len(res["optimal"]["col"])}
    for w in WEIGHTINGS:
        r = res[w]
        ok = r[col] >= 0
        g[w] = dict(values=r[err][ok], failures=int((~ok).sum()),
                    labels=np.bincount(r[lab][ok], minlength=4)[:3].astype(np.int64))
        if w != "fixed_k":
            kidx = r[col][ok] % nk
            g[w]["k_histogram"] = np.bincount(kidx, minlength=nk).astype(np.int64)
    c = res["optimal"][col]
    ok = c >= 0
    g["pair_k_histogram"] = np.bincount(c[ok], minlength=len(res["pairs"]) * nk).astype(np.int64)
    g["kstar"] = (c[ok] % nk).astype(np.float64)  # + k_min later
    a_cls, b_cls = res["table3"][which]
    g["table3"] = np.bincount(np.concatenate([a_cls[ok], b_cls[ok]]), minlength=6).astype(np.int64)
    return g


def fold(aggs):
    out = {"points": sum(g["points"] for g in aggs)}
    for w in WEIGHTINGS:
        out[w] = dict(values=np.concatenate([g[w]["values"] for g in aggs]),
                      failures=sum(g[w]["failures"] for g in aggs),
                      labels=sum(g[w]["labels"] for g in aggs))
        if w != "fixed_k":
            out[w]["k_histogram"] = sum(g[w]["k_histogram"] for g in aggs)
    for key in ("pair_k_histogram", "table3"):
        out[key] = sum(g[key] for g in aggs)
    out["kstar"] = np.concatenate([g["kstar"] for g in aggs])
    return out


def moments(v):
    """(mean, population sd) computed two-pass; nan when empty."""
    if len(v) == 0:
        return math.nan, math.nan
    mean = math.fsum(v) / len(v)
    return mean, math.sqrt(math.fsum((v - mean) ** 2) / len(v))


def statistics(g, k_min):
    st = {"points": g["points"]}
    for w in WEIGHTINGS:
        v = g[w]["values"]
        mean, sd = moments(v)
        d = {"count": len(v), "failures": g[w]["failures"], "sum": math.fsum(v),
             "sum_of_squares": math.fsum(v * v), "min": float(v.min()) if len(v) else math.inf,
             "max": float(v.max()) if len(v) else -math.inf, "mean": mean, "standard_deviation": sd,
             "labels": {name: int(c) for name, c in zip(LABELS, g[w]["labels"])}}
        if "k_histogram" in g[w]:
            d["k_histogram"] = [int(c) for c in g[w]["k_histogram"]]
        st[w] = d
    st["k_mean"], st["k_standard_deviation"] = moments(g["kstar"] + k_min)
    st["table3"] = {name: int(c) for name, c in zip(TABLE3, g["table3"])}
    st["pair_k_histogram"] = [int(c) for c in g["pair_k_histogram"]]
    return st


# ----------------------------------------------------------------------------------------------------
# Comparison

def scaled(a, b):
    return abs(a - b) / max(1.0, abs(a), abs(b))


def compare(ours, theirs, path=""):
    """Mismatches [(path, ours, theirs)], worst scaled difference of the floats."""
    bad, worst = [], 0.0
    if isinstance(ours, dict):
        if not isinstance(theirs, dict):
            return [(path, "object", theirs)], worst
        for key, val in ours.items():
            if key not in theirs:
                bad.append((f"{path}.{key}".lstrip("."), val, "missing"))
                continue
            b, w = compare(val, theirs[key], f"{path}.{key}".lstrip("."))
            bad += b
            worst = max(worst, w)
    elif isinstance(ours, list):
        if not isinstance(theirs, list) or len(theirs) != len(ours):
            return [(path, f"list of {len(ours)}", f"{type(theirs).__name__} of "
                     f"{len(theirs) if isinstance(theirs, list) else '-'}")], worst
        for i, (o, t) in enumerate(zip(ours, theirs)):
            b, w = compare(o, t, f"{path}[{i}]")
            bad += b
            worst = max(worst, w)
    elif isinstance(ours, (int, np.integer)) and not isinstance(ours, bool):
        if not (isinstance(theirs, (int, float)) and not isinstance(theirs, bool) and theirs == ours):
            bad.append((path, int(ours), theirs))
    elif isinstance(ours, str):
        if ours != theirs:
            bad.append((path, ours, theirs))
    else:
        o = float(ours)
        if theirs is None:
            if math.isfinite(o):
                bad.append((path, o, None))
        elif not isinstance(theirs, (int, float)) or isinstance(theirs, bool) or not math.isfinite(o):
            bad.append((path, o, theirs))
        else:
            w = scaled(o, float(theirs))
            worst = max(worst, w)
            if w > TOL:
                bad.append((path, o, theirs))
    return bad, worst


def settings_of(js, path):
    try:
        st = js["settings"]
        A = [float(v) for v in st["a_grid"]]
        B = [float(v) for v in st["b_grid"]]
        k_min, k_max, fixed_k = int(st["k_min"]), int(st["k_max"]), int(st["fixed_k"])
        s = dict(A=A, B=B, ks=list(range(k_min, k_max + 1)), fixed_k=fixed_k, cut=float(st["cut_off_angle"]),
                 weighted={"weighted": True, "unweighted": False}[st["barycenter"]],
                 tol=float(st["angle_tolerance"]))
    except (KeyError, TypeError, ValueError) as err:
        raise UsageError(f"{path}: settings unreadable ({err!r})")
    notes = []
    if s["cut"] != math.acos(0.9):
        notes.append(f"settings.cut_off_angle {s['cut']!r} != arccos(0.9) {math.acos(0.9)!r}")
    for name, g in (("a_grid", A), ("b_grid", B)):
        if g != sorted(set(g)) or g[0] < 0 or g[-1] > math.pi:
            notes.append(f"settings.{name} not sorted, unique and in [0, pi]")
    if A[0] != 0.0:
        notes.append("a_grid does not start at 0: 'a_zero' is taken as a* = a_grid[0]")
    return s, notes


def count_csv_rows(path):
    with open(path, "rb") as f:
        return max(0, sum(1 for line in f if line.strip()) - 1)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("outdir", help="folder written by `sigmoid-neighborhoods evaluate --per-point`")
    ap.add_argument("--max-points-per-model", type=int, default=30000,
                    help="skip (and say so) models with more points than this; default 30000")
    ap.add_argument("--show", type=int, default=6, help="mismatches listed per model (default 6)")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 2 if e.code else 0
    try:
        return run(args)
    except UsageError as err:
        print(f"evaluation_reference: {err}", file=sys.stderr)
        return 2


def run(args):
    models_dir = os.path.join(args.outdir, "models")
    summary_path = os.path.join(args.outdir, "summary.json")
    if not os.path.isdir(models_dir) or not os.path.isfile(summary_path):
        raise UsageError(f"{args.outdir}: not an evaluation folder (need models/ and summary.json)")
    try:
        with open(summary_path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as err:
        raise UsageError(f"{summary_path}: {err}")
    names = []
    for root, _, files in os.walk(models_dir):
        for fn in files:
            if fn.endswith(".json"):
                names.append(os.path.relpath(os.path.join(root, fn), models_dir)[:-len(".json")])
    names.sort(key=lambda s: s.encode())  # byte order of the paths, as the summary folds them
    if not names:
        raise UsageError(f"{models_dir}: no model files")
    for name in names:
        if not os.path.isfile(os.path.join(models_dir, name + ".csv")):
            raise UsageError(f"{os.path.join(models_dir, name + '.csv')} missing: run the evaluation with --per-point")
    failed = False
    ours_raw, ours_adj, theirs_models = [], [], []
    print(f"evaluation_reference: {args.outdir} ({len(names)} models, max {args.max_points_per_model} "
          f"points per model checked)")
    print(f"{'model':<34} {'points':>7} {'worst':>9} {'near-ties o/e/c/lab':>19} "
          f"{'tool took':>9} {'libm':>4} {'raw diff':>8} {'adj diff':>8} {'pt diff':>7} {'sec':>6}  result")
    details = []
    setting_ref = None
    k_min = None
    for name in names:
        jpath = os.path.join(models_dir, name + ".json")
        cpath = os.path.join(models_dir, name + ".csv")
        try:
            with open(jpath) as f:
                js = json.load(f)
        except (OSError, ValueError) as err:
            raise UsageError(f"{jpath}: {err}")
        s, notes = settings_of(js, jpath)
        if setting_ref is None:
            setting_ref, k_min = js["settings"], s["ks"][0]
            for note in notes:
                print(f"note: {note}")
        elif js["settings"] != setting_ref:
            details.append(f"{name}: settings differ from the first model's")
            failed = True
        theirs_models.append((name, js))
        n = count_csv_rows(cpath)
        if n > args.max_points_per_model:
            print(f"{name:<34} {n:>7}  skipped: more than {args.max_points_per_model} points "
                  "(its own JSON statistics are folded into the summary check)")
            ours_raw.append(None)
            ours_adj.append(None)
            continue
        t0 = time.time()
        t = read_csv(cpath)
        P = np.stack([t["x"], t["y"], t["z"]], axis=1)
        N = np.stack([t["nx"], t["ny"], t["nz"]], axis=1)
        kq = max(s["ks"][-1], s["fixed_k"])
        if not (np.isfinite(P).all() and np.isfinite(N).all()) or n < kq + 1:
            raise UsageError(f"{cpath}: non-finite x..nz or fewer than {kq + 1} points")
        res = evaluate_points(P, N, t, s)
        nk = len(s["ks"])
        g_raw, g_adj = raw_aggregate(res, nk, "raw"), raw_aggregate(res, nk, "adj")
        ours_raw.append(g_raw)
        ours_adj.append(g_adj)

        def model_stats(g):
            st = statistics(g, k_min)
            return {"points": g["points"], "failures": st["optimal"]["failures"],
                    "k_standard_deviation": st["k_standard_deviation"], "statistics": st}
        bad_adj, worst = compare(model_stats(g_adj), js)
        bad_raw, _ = compare(model_stats(g_raw), js)
        if js.get("model") != name:
            bad_adj.append(("model", name, js.get("model")))
        # Per-point diagnosis against the CSV: choices and labels beyond any near-tie, and errors.
        amb = [int(res[w]["amb"].sum()) for w in ("optimal", "equal", "cut_off")]
        lab_amb = int(sum(res[w]["lab_amb"].sum() for w in WEIGHTINGS))
        took = int(sum(((res[w]["col"] != res[w]["adj"])).sum() for w in WEIGHTINGS))
        took_lab = 0
        pt_bad = []
        for w, ecol, lcol in (("optimal", "error", "label"), ("equal", "error_equal", "label_equal"),
                              ("cut_off", "error_cut_off", "label_cut_off"),
                              ("fixed_k", "error_fixed_k", "label_fixed_k")):
            r = res[w]
            tool = res["tool"][w]
            wrong = np.flatnonzero(r["adj"] != tool)
            pt_bad += [(int(i), f"{w} choice", r["col"][i], tool[i]) for i in wrong]
            took_lab += int(((r["lab_adj"] != r["lab"]) & (r["adj"] == r["col"])).sum())
            wl = np.flatnonzero((r["lab_adj"] != t[lcol]) & (r["adj"] == tool))
            pt_bad += [(int(i), f"{w} label", LABELS[r["lab_adj"][i]] if r["lab_adj"][i] < 3 else "none",
                        LABELS[t[lcol][i]] if t[lcol][i] < 3 else "none") for i in wl]
            with np.errstate(invalid="ignore"):
                e_ok = (np.abs(r["err_adj"] - t[ecol]) <= NEAR) | (np.isinf(r["err_adj"]) & np.isinf(t[ecol]))
            pt_bad += [(int(i), f"{w} error", r["err_adj"][i], t[ecol][i]) for i in np.flatnonzero(~e_ok)]
        secs = time.time() - t0
        ok = not bad_adj and not pt_bad
        failed |= not ok
        print(f"{name:<34} {n:>7} {worst:>9.2e} {'/'.join(map(str, amb)) + f'/{lab_amb}':>19} "
              f"{took + took_lab:>9} {res['libm_angles']:>4} {len(bad_raw):>8} {len(bad_adj):>8} {len(pt_bad):>7} {secs:>6.1f}  "
              f"{'OK' if ok else 'FAIL'}")
        for p, o, th in bad_raw[:args.show] if bad_raw and not bad_adj else []:
            details.append(f"{name}: raw {p}: ours {o} vs tool {th} (explained by near-ties)")
        for p, o, th in bad_adj[:args.show]:
            details.append(f"{name}: {p}: ours {o!r} vs tool {th!r}")
        for i, what, o, th in sorted(pt_bad)[:args.show]:
            details.append(f"{name}: point #{i} {what}: ours {o!r} vs tool {th!r}")
    # Repository totals: our aggregates (the JSON's own statistics for models that were skipped).
    print("summary.json:")
    sbad = []
    for key, expect in (("models", len(names)), ("failed_models", 0)):
        if summary.get(key) != expect:
            sbad.append((key, expect, summary.get(key)))
    for key in ("merged_duplicates", "dropped_vertices"):
        tot = sum(int(js.get(key, 0)) for _, js in theirs_models)
        if summary.get(key) != tot:
            sbad.append((key + " (sum of the model files)", tot, summary.get(key)))
    if summary.get("settings") != setting_ref:
        sbad.append(("settings", "as in the model files", "different"))
    per_model = summary.get("per_model", [])
    want = [{"model": nm, "points": js["points"], "k_standard_deviation": js["k_standard_deviation"]}
            for nm, js in theirs_models]
    b, _ = compare(want, per_model, "per_model")
    sbad += b
    skipped = [nm for (nm, _), g in zip(theirs_models, ours_adj) if g is None]
    if len(skipped) == len(names):
        print("  every model was skipped: only the fold of the model files is checked")
    worst_all = 0.0
    for label, aggs in (("adjusted", ours_adj), ("raw", ours_raw)):
        checked = [g for g in aggs if g is not None]
        if not checked:
            continue
        st = statistics(fold(checked), k_min)
        if skipped:  # fold the skipped models' own figures into ours
            st = fold_json([st] + [js["statistics"] for (nm, js), g in zip(theirs_models, aggs) if g is None])
        b, worst = compare({"points": st["points"], "statistics": st}, summary)
        if label == "adjusted":
            worst_all = worst
            sbad += b
            print(f"  ours ({len(checked)} models recomputed"
                  + (f", {len(skipped)} skipped and taken from their files" if skipped else "")
                  + f"): {len(b)} mismatches, worst scaled difference {worst:.2e}")
        else:
            print(f"  raw (our own near-tie choices): {len(b)} mismatches")
    # The summary is the fold of the model files: check that independently of our recomputation.
    st = fold_json([js["statistics"] for _, js in theirs_models])
    b, worst = compare({"points": st["points"], "statistics": st}, summary)
    print(f"  fold of the {len(names)} model files: {len(b)} mismatches, worst scaled difference {worst:.2e}")
    sbad += [(f"(fold of model files) {p}", o, th) for p, o, th in b]
    for p, o, th in sbad[:3 * args.show]:
        details.append(f"summary: {p}: ours {o!r} vs tool {th!r}")
    failed |= bool(sbad)
    if details:
        print("details:")
        for line in details:
            print("  " + line)
    print(f"worst scaled difference in the summary: {worst_all:.2e}")
    print("result: " + ("FAIL" if failed else "PASS"))
    return 1 if failed else 0


def fold_json(stats):
    """Fold per-model statistics objects (ours or the tool's) into totals: counts, sums and histograms
    add, min/max fold, mean and sd from the sums (population)."""
    num = lambda v: math.nan if v is None else float(v)
    out = {"points": sum(int(s["points"]) for s in stats)}
    for w in WEIGHTINGS:
        c = sum(int(s[w]["count"]) for s in stats)
        sm = math.fsum(num(s[w]["sum"]) for s in stats)
        sq = math.fsum(num(s[w]["sum_of_squares"]) for s in stats)
        mins = [num(s[w]["min"]) for s in stats if s[w]["count"]]
        maxs = [num(s[w]["max"]) for s in stats if s[w]["count"]]
        mean = sm / c if c else math.nan
        d = {"count": c, "failures": sum(int(s[w]["failures"]) for s in stats), "sum": sm, "sum_of_squares": sq,
             "min": min(mins) if mins else math.inf, "max": max(maxs) if maxs else -math.inf, "mean": mean,
             "standard_deviation": math.sqrt(max(0.0, sq / c - mean * mean)) if c else math.nan,
             "labels": {name: sum(int(s[w]["labels"][name]) for s in stats) for name in LABELS}}
        if "k_histogram" in stats[0][w]:
            d["k_histogram"] = [sum(v) for v in zip(*(s[w]["k_histogram"] for s in stats))]
        out[w] = d
    c = out["optimal"]["count"]
    ksum = math.fsum(num(s["k_mean"]) * int(s["optimal"]["count"]) for s in stats if s["optimal"]["count"])
    ksq = math.fsum((num(s["k_standard_deviation"]) ** 2 + num(s["k_mean"]) ** 2) * int(s["optimal"]["count"])
                    for s in stats if s["optimal"]["count"])
    out["k_mean"] = ksum / c if c else math.nan
    out["k_standard_deviation"] = math.sqrt(max(0.0, ksq / c - out["k_mean"] ** 2)) if c else math.nan
    out["table3"] = {name: sum(int(s["table3"][name]) for s in stats) for name in TABLE3}
    out["pair_k_histogram"] = [sum(v) for v in zip(*(s["pair_k_histogram"] for s in stats))]
    return out


if __name__ == "__main__":
    sys.exit(main())
