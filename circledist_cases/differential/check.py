"""The checker (``check_cases``).

The checker (``check_cases``): for every (solver, precision) combination and both argument
orders it calls distance, closest_points, within, distance_if_within and intersects, batched
and (for the chosen cases) scalar, and reports findings: answers above the screen's bound or
below every verified bound (beyond the bar), closest points off their shapes, separations
that differ from the reported distance, distance(a, b) != distance(b, a), batch != scalar,
within / intersects inconsistent with the distance, non-finite answers or wrong dtypes, and
an arc of angle 2 pi whose answers are not its circle's to the bit (distance, points,
`unique`, the other side's parameter; docs/derivations/arc.md), and an annulus of inner 0 / inner = outer
whose are not its disk's / circle's (docs/derivations/annulus.md).
The bound an answer is held against is the screen's, or lower: the separation (plus the
measured distances off their shapes) of any combination's closest points, a genuine pair too.
``confirm`` re-judges an accuracy finding against the 50-digit mpmath references of
circledist_cases/reference_linear_round.py, reference_round.py (Bezier curves, also against linear pieces:
bezier_other), reference_arc.py (arcs: the arc's angle against the other's closed form) and
reference_linear.py (linear pieces among themselves: the search of
tests/accuracy/test_linear_accuracy.py), reference_annulus.py (annuli: the other shape's parameter
against the point-annulus closed form, rim by rim for regions), and evaluates the screen's own
best pair at 50 digits, so a reference that missed the minimum is caught, not trusted.
closest_points().unique is checked against an independent rule (expected_unique, the comment
above it gives it in full) on every kind pair: it must be False where the inputs are exactly
(rational arithmetic on the given floats) a configuration with a continuum of closest pairs
by symmetry -- a point, line, ray or segment on the axis of a circle, an arc or an annulus
with a hole; two coaxial shapes among circle, disk, annulus and arc (not two arcs) -- and True
where a closed form or strict convexity proves one closest pair with a margin of 1e-6 (a
point against a point, a linear piece or a disk; a point against a circle, an arc or an
annulus, its nearest candidate better than the others by 1e-6 x max(d, R); two linear pieces
at least 1e-3 rad from parallel).  Elsewhere (curve pairs, near-continua that rounding breaks)
it is not checked by the screen-driven checker; the direct 50-digit comparison
(reference_check, the CI slice's first case of each family and pair) adds True where the
reference's own local minima show it for a circle or arc against a convex shape (line, ray,
segment, disk: reference_unique -- a single strict minimum over the rim's angle, every other
distinct local minimum worse by 1e-6 x max(d, R), not flat within 1e-4 rad).
"""

from __future__ import annotations

import collections
import math
from fractions import Fraction

import numpy as np

from .base import BARS, EPSLD, LD, OUT_EPS, RIMS, ULPS, combos
from .closed_forms import _nrm
from .screen import screen
from .residuals import residuals
from .families import bar_scale, scene_scale, to_float32_case
from .unique import expected_unique


def _dtype(precision):
    return {"float32": np.float32, "float64": np.float64, "longdouble": np.float64}[precision]


def make_shape(cd, kind, data, dtype=np.float64):
    """A circledist shape (scalar, or a batch when data has a leading batch axis)."""
    arr = np.asarray(data, dtype=dtype)
    if kind == "bezier":
        return cd.Bezier(arr)
    if kind == "point":
        return cd.Point(arr[..., :3])
    if kind in ("line", "ray"):
        return getattr(cd, kind.capitalize())(arr[..., :3], arr[..., 3:6])
    if kind == "segment":
        return cd.Segment(arr[..., :3], arr[..., 3:6])
    if kind == "arc":
        return cd.Arc(arr[..., :3], arr[..., 3:6], arr[..., 6], arr[..., 7:10], arr[..., 10])
    if kind == "annulus":
        return cd.Annulus(arr[..., :3], arr[..., 3:6], arr[..., 7], arr[..., 6])
    return getattr(cd, kind.capitalize())(arr[..., :3], arr[..., 3:6], arr[..., 6])


def pair_scale(case):
    """The pair's length scale of within()'s documented tolerance 64 eps (s + d) (bounds.hpp
    pair_scale: the sizes and separation of the bounding balls; a line or ray counts by its
    distance from the other's centre, two of them by the separation of their origins)."""

    def ball(kind, data):
        d = np.asarray(data, float)
        if kind == "point":
            return d[:3], 0.0
        if kind in ("line", "ray"):
            return d[:3], math.inf
        if kind == "segment":
            return (d[:3] + d[3:6]) / 2, float(np.linalg.norm(d[3:6] - d[:3])) / 2
        if kind in RIMS:
            return d[:3], float(d[6])
        lo, hi = d.min(axis=0), d.max(axis=0)
        c = (lo + hi) / 2
        return c, float(max(np.linalg.norm(p - c) for p in d))

    def from_line(kind, data, c):
        # in exact rationals: a ray's origin 3e8 away cancels to 0 in doubles
        o, u, cc = ([Fraction(float(x)) for x in v] for v in (data[:3], data[3:6], c))
        t = sum((ci - oi) * ui for ci, oi, ui in zip(cc, o, u)) / sum(ui * ui for ui in u)
        if kind == "ray":
            t = max(t, Fraction(0))
        return math.sqrt(float(sum((oi + t * ui - ci) ** 2 for oi, ui, ci in zip(o, u, cc))))

    ka, kb = case["a"], case["b"]
    ca, ra = ball(ka, case["a_data"])
    cb, rb = ball(kb, case["b_data"])
    if math.isfinite(ra) and math.isfinite(rb):
        s = max(ra, rb, float(np.linalg.norm(ca - cb)))
    elif math.isfinite(rb):
        s = max(rb, from_line(ka, case["a_data"], cb))
    elif math.isfinite(ra):
        s = max(ra, from_line(kb, case["b_data"], ca))
    else:
        s = float(np.linalg.norm(ca - cb))
    return s if s > 0 else 1.0


def _eq(x, y):
    """Bitwise-equal answers (NaN equal to NaN)."""
    x, y = np.asarray(x), np.asarray(y)
    return (x == y) | (np.isnan(x.astype(float)) & np.isnan(y.astype(float)))


def _finding(check, case, solver, precision, order, entry, **info):
    ka, kb = (case["a"], case["b"]) if order == "ab" else (case["b"], case["a"])
    f = dict(
        check=check,
        family=case["family"],
        case_id=case["id"],
        pair=f"{case['a']}-{case['b']}",
        kinds=[ka, kb],
        solver=solver,
        precision=precision,
        order=order,
        entry=entry,
    )
    f["a_data"] = case["a_data"] if order == "ab" else case["b_data"]
    f["b_data"] = case["b_data"] if order == "ab" else case["a_data"]
    for k, v in info.items():
        f[k] = _jsonable(v)
    return f


def _jsonable(v):
    if isinstance(v, np.longdouble) and np.finfo(np.longdouble).nmant > 52:
        # full long-double digits (25 significant: exact to far below one ulp)
        return np.format_float_scientific(v, unique=False, precision=24) if np.isfinite(v) else str(v)
    if isinstance(v, (np.floating, float)):
        return float(v) if np.isfinite(float(v)) else str(float(v))
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.bool_,)):
        return bool(v)
    if isinstance(v, np.ndarray):
        return [_jsonable(x) for x in v]
    if isinstance(v, (list, tuple)):
        return [_jsonable(x) for x in v]
    return v


def _group(cases):
    groups = {}
    for i, c in enumerate(cases):
        key = (c["a"], c["b"], len(c["a_data"]) if c["a"] == "bezier" else 0)
        groups.setdefault(key, []).append(i)
    return groups


def _call(fn, *args, **kw):
    try:
        return fn(*args, **kw), None
    except Exception as e:  # noqa: BLE001 - any exception is a finding
        return None, f"{type(e).__name__}: {e}"


def _run_batch(cd, ka, kb, A, Bd, solver, precision, n):
    dt = _dtype(precision)
    SA, SB = make_shape(cd, ka, A, dt), make_shape(cd, kb, Bd, dt)
    kw = dict(solver=solver, precision=precision)
    out = {}
    for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
        d, err = _call(cd.distance, x, y, **kw)
        r, err2 = _call(cd.closest_points, x, y, **kw)
        out[order] = dict(d=d, r=r, err=err or err2)
    return out, SA, SB


def _within_limits(D, s, eps, bar_abs):
    """Limits just above and below D that the documented tolerance 64 eps (s + d) cannot blur."""
    band = 4 * 64 * eps * (s + D)
    hi = D + np.maximum(band, bar_abs)
    lo = D - np.maximum(band, bar_abs)
    return lo, hi, band


def check_cases(cd, cases, combo_list=None, scalar=None, screens=None, within=True):
    """Run every combination on `cases` (any mix of families and kinds), both orders, and return
    (findings, stats).  scalar: indices of cases that also get scalar calls (default all);
    screens: {case index: (value, slack, f32 value, f32 slack)} to reuse."""
    combo_list = combo_list or combos()
    if scalar is None:
        scalar = set(range(len(cases)))
    scalar = set(scalar)
    findings = []
    # answers: every value the library returned for one query, per entry point (a batched call of
    # n cases gives n; each within / distance_if_within probe is one)
    stats = {"cases": len(cases), "answers": collections.Counter(), "unique_checked": collections.Counter()}
    screens = {} if screens is None else screens
    for (ka, kb, _), idx in _group(cases).items():
        group = [cases[i] for i in idx]
        need64 = [j for j, i in enumerate(idx) if i not in screens]
        if need64:
            s64 = screen([group[j] for j in need64])
            precs = {p for _, p in combo_list}
            if "float32" in precs:
                s32 = screen([to_float32_case(group[j]) for j in need64], use_ld=False)
            for q, j in enumerate(need64):
                screens[idx[j]] = dict(
                    value=s64.value[q],
                    slack=s64.slack[q],
                    form=s64.forms[q],
                    param=s64.params[q],
                    value32=s32.value[q] if "float32" in precs else None,
                    slack32=s32.slack[q] if "float32" in precs else None,
                    form32=s32.forms[q] if "float32" in precs else None,
                    param32=s32.params[q] if "float32" in precs else None,
                )
        findings += _check_group(cd, ka, kb, idx, group, combo_list, scalar, screens, within, stats)
    return findings, stats


def _check_group(cd, ka, kb, idx, group, combo_list, scalar, screens, within, stats):
    findings = []
    n = len(group)
    data = {
        "f64": (
            np.array([c["a_data"] for c in group], dtype=float),
            np.array([c["b_data"] for c in group], dtype=float),
        )
    }
    g32 = [to_float32_case(c) for c in group]
    data["f32"] = (np.array([c["a_data"] for c in g32], dtype=float), np.array([c["b_data"] for c in g32], dtype=float))
    radius = {"f64": np.array([bar_scale(c) for c in group]), "f32": np.array([bar_scale(c) for c in g32])}
    sscale = {"f64": np.array([scene_scale(c) for c in group]), "f32": np.array([scene_scale(c) for c in g32])}
    pscale = {"f64": np.array([pair_scale(c) for c in group]), "f32": np.array([pair_scale(c) for c in g32])}
    U = {
        "f64": np.array([screens[i]["value"] for i in idx], dtype=LD),
        "f32": np.array(
            [screens[i]["value32"] if screens[i]["value32"] is not None else np.nan for i in idx], dtype=LD
        ),
    }
    slack = {
        "f64": np.array([screens[i]["slack"] for i in idx]),
        "f32": np.array([screens[i]["slack32"] if screens[i]["slack32"] is not None else 0 for i in idx]),
    }
    runs = {}
    # ---- batched calls and per-answer checks -----------------------------------------------
    for solver, precision in combo_list:
        scene = "f32" if precision == "float32" else "f64"
        A, Bd = data[scene]
        if ka == "bezier":
            A = A.reshape(n, -1, 3)
        res, SA, SB = _run_batch(cd, ka, kb, A, Bd, solver, precision, n)
        for order in res.values():
            stats["answers"]["distance"] += n if order["d"] is not None else 0
            stats["answers"]["closest_points"] += n if order["r"] is not None else 0
        runs[(solver, precision)] = (res, SA, SB)
    # verified pairs: upper bounds from every combination's closest points (per input scene)
    upair = {"f64": np.full(n, LD(np.inf), dtype=LD), "f32": np.full(n, LD(np.inf), dtype=LD)}
    resid = {}
    for (solver, precision), (res, SA, SB) in runs.items():
        scene = "f32" if precision == "float32" else "f64"
        A, Bd = data[scene]
        if ka == "bezier":
            A = A.reshape(n, -1, 3)
        for order in ("ab", "ba"):
            r = res[order]["r"]
            if r is None:
                continue
            pa, pb = np.asarray(r.point_a), np.asarray(r.point_b)
            qa, qb = (pa, pb) if order == "ab" else (pb, pa)  # qa on shape a, qb on shape b
            par = np.asarray(r.param_a if order == "ab" else r.param_b)
            with np.errstate(all="ignore"):
                ra_, ea = residuals(ka, A, qa, par[:, 0] if ka == "bezier" else None)
                rb_, eb = residuals(kb, Bd, qb)
                sep = _nrm(qa.astype(LD) - qb.astype(LD))
            resid[(solver, precision, order)] = (ra_, rb_, sep)
            # a genuine pair: the truth is at most its separation plus both points' distances off
            # their shapes (each rounded up by its evaluation error, and the separation's)
            bound = sep + ra_ + rb_ + ea + eb + 16 * LD(EPSLD) * sep
            ok = np.isfinite(bound)
            upair[scene] = np.where(ok, np.minimum(upair[scene], bound), upair[scene])
    for (solver, precision), (res, SA, SB) in runs.items():
        scene = "f32" if precision == "float32" else "f64"
        bar = BARS[precision]
        eps_out = OUT_EPS[precision]
        Us, sl = U[scene], slack[scene]
        Ub = np.minimum(Us, upair[scene])
        scale_ = np.maximum(Ub.astype(float), radius[scene])
        bar_abs = bar * scale_
        ulps = ULPS * eps_out * sscale[scene]
        gcases = g32 if scene == "f32" else group
        d_orders = {}
        inaccurate = {}
        for order in ("ab", "ba"):
            rr = res[order]
            if rr["err"] is not None:
                for j in range(n):
                    findings.append(
                        _finding(
                            "exception", gcases[j], solver, precision, order, "distance/closest_points", error=rr["err"]
                        )
                    )
                continue
            d = np.asarray(rr["d"])
            r = rr["r"]
            cdist = np.asarray(r.distance)
            d_orders[order] = d
            want = {"float32": np.float32, "float64": np.float64, "longdouble": np.longdouble}[precision]
            if d.dtype != want or cdist.dtype != want:
                findings.append(
                    _finding(
                        "dtype",
                        gcases[0],
                        solver,
                        precision,
                        order,
                        "distance",
                        got=str(d.dtype),
                        expected=np.dtype(want).name,
                    )
                )
            dl, cl = d.astype(LD), cdist.astype(LD)
            ra_, rb_, sep = resid[(solver, precision, order)]
            ulps_o = ulps
            if ka not in RIMS and kb not in RIMS:
                # without a round the closest points can lie far outside the scene (1e5 along two
                # lines 1e-5 rad apart): each is rounded by ulps of its own size
                with np.errstate(invalid="ignore"):
                    pmag = np.maximum(
                        np.abs(np.asarray(r.point_a, dtype=float)).max(axis=1),
                        np.abs(np.asarray(r.point_b, dtype=float)).max(axis=1),
                    )
                ulps_o = ULPS * eps_out * np.maximum(sscale[scene], pmag)
            acc_bad = inaccurate.setdefault(order, set())
            for j in range(n):
                c = gcases[j]
                info = dict(
                    screen=Us[j],
                    screen_slack=sl[j],
                    verified_pair_bound=upair[scene][j],
                    bar_abs=bar_abs[j],
                    bar_scale=radius[scene][j],
                )
                for entry, val in (("distance", dl[j]), ("closest_points", cl[j])):
                    if not np.isfinite(val) or val < 0:
                        findings.append(_finding("non_finite", c, solver, precision, order, entry, library=val))
                        continue
                    if val > Ub[j] + bar_abs[j] + sl[j]:
                        findings.append(
                            _finding(
                                "above_bound",
                                c,
                                solver,
                                precision,
                                order,
                                entry,
                                library=val,
                                excess=(val - Ub[j]) / scale_[j],
                                **info,
                            )
                        )
                        acc_bad.add(j)
                    elif val < Us[j] - bar_abs[j] - sl[j] and val < upair[scene][j] - bar_abs[j] - sl[j]:
                        findings.append(
                            _finding(
                                "below_bound",
                                c,
                                solver,
                                precision,
                                order,
                                entry,
                                library=val,
                                excess=(val - Ub[j]) / scale_[j],
                                **info,
                            )
                        )
                        acc_bad.add(j)
                # closest points on their shapes; separation equals the reported distance
                if not (ra_[j] <= ulps_o[j] and rb_[j] <= ulps_o[j]):
                    findings.append(
                        _finding(
                            "point_off_shape",
                            c,
                            solver,
                            precision,
                            order,
                            "closest_points",
                            off_a=ra_[j],
                            off_b=rb_[j],
                            allowed=ulps_o[j],
                            point_a=np.asarray(r.point_a)[j],
                            point_b=np.asarray(r.point_b)[j],
                        )
                    )
                if not abs(sep[j] - cl[j]) <= bar_abs[j] + ulps_o[j]:
                    findings.append(
                        _finding(
                            "separation",
                            c,
                            solver,
                            precision,
                            order,
                            "closest_points",
                            separation=sep[j],
                            library=cl[j],
                            allowed=bar_abs[j] + ulps_o[j],
                            point_a=np.asarray(r.point_a)[j],
                            point_b=np.asarray(r.point_b)[j],
                        )
                    )
                # the same number, to the bit (README: the two never disagree)
                if not (dl[j] == cl[j] or (np.isnan(dl[j]) and np.isnan(cl[j]))):
                    findings.append(
                        _finding(
                            "distance_vs_closest_points",
                            c,
                            solver,
                            precision,
                            order,
                            "both",
                            distance=dl[j],
                            closest_points=cl[j],
                            allowed=0.0,
                        )
                    )
                if precision == "float32" and float(np.float32(d[j])) != float(d[j]):
                    findings.append(_finding("float32_value", c, solver, precision, order, "distance", library=d[j]))
        # symmetry: distance(a, b) == distance(b, a) (README; the closest points of a non-unique
        # pair may legitimately differ between the orders, so only the distances are compared)
        if len(d_orders) == 2:
            r1, r2 = res["ab"]["r"], res["ba"]["r"]
            same = _eq(d_orders["ab"], d_orders["ba"]) & _eq(np.asarray(r1.distance), np.asarray(r2.distance))
            for j in np.flatnonzero(~same):
                findings.append(
                    _finding(
                        "asymmetric",
                        gcases[j],
                        solver,
                        precision,
                        "ab",
                        "distance",
                        ab=d_orders["ab"][j],
                        ba=d_orders["ba"][j],
                        cp_ab=np.asarray(r1.distance)[j],
                        cp_ba=np.asarray(r2.distance)[j],
                    )
                )
        # within / distance_if_within / intersects, batched
        wres = {}
        if within and d_orders:
            fw, wres = _check_within(
                cd, res, SA, SB, d_orders, solver, precision, gcases, pscale[scene], bar_abs, inaccurate, stats
            )
            findings += fw
        # an arc of angle 2 pi is the whole circle, answered by the circle's query (docs/derivations/arc.md)
        if "arc" in (ka, kb) and d_orders:
            A, Bd = data[scene]
            findings += _check_whole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats)
        # an annulus of inner radius 0 is the disk, of inner radius = outer the circle: the disk's
        # or circle's query answers it (docs/derivations/annulus.md), to the bit
        if "annulus" in (ka, kb) and d_orders:
            A, Bd = data[scene]
            findings += _check_hole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats)
        # closest_points().unique against the independent rule (expected_unique)
        if d_orders:
            findings += _check_unique(res, d_orders, solver, precision, gcases, stats)
        # batched == scalar
        sel = [j for j, i in enumerate(idx) if i in scalar]
        if sel:
            findings += _check_scalar(cd, ka, kb, res, d_orders, wres, sel, gcases, solver, precision, stats)
    return findings


def _check_whole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats):
    """Cases whose arcs all have angle 2 pi (as given: float32's 2 pi rounds above float64's)
    must give the answers of the same query with each arc replaced by its circle, to the bit
    (arc.hpp: the circle's query is called): distance, closest_points' distance, points,
    `unique` and the parameter of a side that is not an arc.  An arc's own parameter is its
    t = theta - theta0, the circle's angle moved to the arc's start (ArcSpan::param_of): not the
    circle's number (tests/pairs/test_arc.py checks that t gives the arc's point)."""
    rows = np.ones(len(gcases), dtype=bool)
    for kind, X in ((ka, A), (kb, Bd)):
        if kind == "arc":
            rows &= X[:, 10] >= 2 * math.pi
    sel = np.flatnonzero(rows)
    if not len(sel):
        return []
    kinds = ["circle" if k == "arc" else k for k in (ka, kb)]
    dt = _dtype(precision)
    SA = make_shape(cd, kinds[0], A[sel, :7] if ka == "arc" else A[sel], dt)
    SB = make_shape(cd, kinds[1], Bd[sel, :7] if kb == "arc" else Bd[sel], dt)
    same = (ka != "arc", kb != "arc")  # which side's parameter must be the circle query's
    return _compare_replaced(
        cd,
        (ka, kb),
        SA,
        SB,
        sel,
        res,
        d_orders,
        solver,
        precision,
        gcases,
        stats,
        "whole_arc_vs_circle",
        "whole arc as circle",
        same,
    )


def _check_hole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats):
    """Cases with an annulus of inner radius 0 or inner = outer > 0 (as given: float32 scenes keep
    both) must give the answers of the same query with that annulus replaced by its disk or its
    outer circle, to the bit (docs/derivations/annulus.md: the disk's / circle's query is called): distance,
    closest_points' distance, points, parameters and `unique`; the circle's parameter (theta, 0)
    on the annulus's side reported as (outer radius, theta).  An annulus-annulus case with only
    one degenerate annulus is compared with the disk-annulus or circle-annulus query."""
    out = []
    for which, kind, X in (("a", ka, A), ("b", kb, Bd)):
        if kind != "annulus":
            continue
        # inner = outer = 0 is the disk's case (annulus.md: inner 0 is the disk, whatever outer)
        for as_kind, rows in (("disk", X[:, 7] == 0), ("circle", (X[:, 7] == X[:, 6]) & (X[:, 7] > 0))):
            sel = np.flatnonzero(rows)
            if not len(sel):
                continue
            dt = _dtype(precision)
            if which == "a":
                SA, SB = make_shape(cd, as_kind, A[sel, :7], dt), make_shape(cd, kb, Bd[sel], dt)
            else:
                SA, SB = make_shape(cd, ka, A[sel], dt), make_shape(cd, as_kind, Bd[sel, :7], dt)
            rim = None if as_kind == "disk" else (which, X[sel, 6])
            out += _compare_replaced(
                cd,
                (ka, kb),
                SA,
                SB,
                sel,
                res,
                d_orders,
                solver,
                precision,
                gcases,
                stats,
                "degenerate_annulus_vs_" + as_kind,
                f"annulus as {as_kind}",
                (True, True),
                rim=rim,
            )
    return out


def _compare_replaced(
    cd, kinds, SA, SB, sel, res, d_orders, solver, precision, gcases, stats, check, what, same, rim=None
):
    """The rows `sel` of the batch's answers `res` (case kinds `kinds`) against the same query on
    the replaced shapes SA, SB (both orders), to the bit: distance(); closest_points()' distance,
    points and `unique`; the parameter of case side a / b where same[0] / same[1].  rim = (side,
    outer radii) of an annulus replaced by its circle: an annulus side answered by a circle has
    its (theta, 0) expected as (radius, theta), a circle side answered by an annulus (theta, 0).
    Where the two replaced shapes are the same set (_identical_rows) the answer may also be the
    replaced one with its two sides exchanged: a query between a shape and itself may report
    either point first."""
    out = []
    for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
        if order not in d_orders:
            continue
        d, err = _call(cd.distance, x, y, solver=solver, precision=precision)
        r, err2 = _call(cd.closest_points, x, y, solver=solver, precision=precision)
        if err or err2:
            out.append(_finding("exception", gcases[sel[0]], solver, precision, order, what, error=err or err2))
            continue
        stats["answers"][f"distance ({what})"] += len(sel)
        stats["answers"][f"closest_points ({what})"] += len(sel)
        d = np.asarray(d)
        for q in np.flatnonzero(~_eq(d, d_orders[order][sel])):
            out.append(
                _finding(
                    check,
                    gcases[sel[q]],
                    solver,
                    precision,
                    order,
                    "distance",
                    library=d_orders[order][sel[q]],
                    replaced=d[q],
                )
            )
        mine = res[order]["r"]
        if mine is None:
            continue
        # the answer's first / second field is case side a / b in order "ab", b / a in "ba"
        sides = ("a", "b") if order == "ab" else ("b", "a")

        def expected(swap):
            """The replaced answer's fields, as the case's answer must show them; swap: with its two
            sides exchanged (for two identical shapes either side's point may be reported first)."""
            fields = [("distance", np.asarray(r.distance)), ("unique", np.asarray(r.unique))]
            replaced_kinds = (x.kind.lower(), y.kind.lower())
            for k, side in enumerate(sides):
                j = 1 - k if swap else k  # the replaced answer's side that gives this one
                fields.append((("point_a", "point_b")[k], np.asarray(getattr(r, ("point_a", "point_b")[j]))))
                if not same["ab".index(side)]:
                    continue
                theirs = np.array(np.asarray(getattr(r, ("param_a", "param_b")[j])), copy=True)
                mine_kind = kinds["ab".index(side)]
                if rim is not None and mine_kind == "annulus" and replaced_kinds[j] == "circle":
                    theirs = np.stack([np.asarray(rim[1], dtype=theirs.dtype), theirs[:, 0]], axis=1)  # (R, theta)
                elif mine_kind == "circle" and replaced_kinds[j] == "annulus":
                    theirs = np.stack([theirs[:, 1], np.zeros_like(theirs[:, 1])], axis=1)  # (theta, 0)
                fields.append((("param_a", "param_b")[k], theirs))
            return fields

        def mismatches(fields):
            out_ = []
            for name, rep in fields:
                bad = ~_eq(np.asarray(getattr(mine, name))[sel], rep)
                if bad.ndim > 1:
                    bad = bad.any(axis=tuple(range(1, bad.ndim)))
                out_.append((name, rep, bad))
            return out_

        direct = mismatches(expected(False))
        failed = np.zeros(len(sel), dtype=bool)
        for _, _, bad in direct:
            failed |= bad
        twins = _identical_rows(x, y, len(sel))
        if (failed & twins).any():
            swapped_bad = np.zeros(len(sel), dtype=bool)
            for _, _, bad in mismatches(expected(True)):
                swapped_bad |= bad
            failed &= ~(twins & ~swapped_bad)
        for name, rep, bad in direct:
            for q in np.flatnonzero(bad & failed):
                out.append(
                    _finding(
                        check,
                        gcases[sel[q]],
                        solver,
                        precision,
                        order,
                        f"closest_points {name}",
                        library=np.asarray(getattr(mine, name))[sel][q],
                        replaced=rep[q],
                    )
                )
    return out


def _identical_rows(x, y, n):
    """Which of the n elements of the batched shapes x and y are the same set (every field equal;
    an annulus of inner radius 0 is its disk, of inner = outer its circle): their closest pairs
    are symmetric, so a query may name either point first."""
    fx, fy = _round_fields(x, n), _round_fields(y, n)
    if fx is None or fy is None:
        return np.zeros(n, dtype=bool)
    same = np.ones(n, dtype=bool)
    for field in ("kind", "center", "normal", "radius", "inner", "start", "angle"):
        eq = fx[field] == fy[field]
        same &= eq if eq.ndim == 1 else eq.all(axis=1)
    return same


def _round_fields(shape, n):
    """A batch of circles, disks, annuli or arcs as comparable per-element arrays (kind code,
    center, normal, radius, inner radius, start, angle), an annulus of inner 0 as its disk and of
    inner = outer as its circle; None for other kinds."""
    codes = {"Circle": 0, "Disk": 1, "Annulus": 2, "Arc": 3}
    if shape.kind not in codes:
        return None
    f = shape.to_arrays()
    vec = lambda v: np.broadcast_to(np.asarray(v, dtype=float), (n, 3))  # noqa: E731
    num = lambda v: np.broadcast_to(np.asarray(v, dtype=float), (n,))  # noqa: E731
    out = dict(
        kind=np.full(n, codes[shape.kind]),
        center=vec(f["center"]),
        normal=vec(f["normal"]),
        inner=np.zeros(n),
        start=np.zeros((n, 3)),
        angle=np.zeros(n),
    )
    if shape.kind == "Annulus":
        inner, outer = num(f["inner_radius"]), num(f["outer_radius"])
        out["radius"] = outer
        out["kind"] = np.where(inner == 0, codes["Disk"], np.where(inner == outer, codes["Circle"], codes["Annulus"]))
        out["inner"] = np.where(out["kind"] == codes["Annulus"], inner, 0.0)
    else:
        out["radius"] = num(f["radius"])
    if shape.kind == "Arc":
        out["start"], out["angle"] = vec(f["start"]), num(f["angle"])
    return out


def _check_unique(res, d_orders, solver, precision, gcases, stats):
    """closest_points().unique against expected_unique, both orders."""
    out = []
    exp = [expected_unique(c) for c in gcases]
    rows = [j for j, (e, _) in enumerate(exp) if e is not None]
    if not rows:
        return out
    for order in d_orders:
        u = np.asarray(res[order]["r"].unique)
        # (not library answers of their own: counted apart, by expectation)
        for j in rows:
            stats["unique_checked"][str(exp[j][0])] += 1
        for j in rows:
            if bool(u[j]) != exp[j][0]:
                out.append(
                    _finding(
                        "unique",
                        gcases[j],
                        solver,
                        precision,
                        order,
                        "closest_points",
                        library=bool(u[j]),
                        expected=exp[j][0],
                        why=exp[j][1],
                        distance=np.asarray(res[order]["r"].distance)[j],
                    )
                )
    return out


def _d_array(x, precision):
    return np.asarray(x, dtype={"float32": np.float32, "float64": np.float64, "longdouble": np.longdouble}[precision])


def _check_within(cd, res, SA, SB, d_orders, solver, precision, gcases, ps, bar_abs, inaccurate, stats):
    """within / distance_if_within / intersects against the library's own distance D and the
    documented rule  within(a, b, d) == (D <= d + 64 eps (s + d)):  probed at D +- 4x that
    tolerance (at least the bar), where the rule leaves no latitude.  Where D itself failed the
    accuracy check the finding is filed as "within_vs_inaccurate_distance" (a symptom)."""
    out = []
    wres = {}
    kw = dict(solver=solver, precision=precision)
    eps = OUT_EPS[precision]
    for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
        if order not in d_orders:
            continue
        dd = d_orders[order]
        Df = dd.astype(float)
        lo, hi, band = _within_limits(Df, ps, eps, bar_abs)
        lo = np.maximum(lo, 0.0)
        hi_a, lo_a = _d_array(hi, precision), _d_array(lo, precision)
        w_hi, e1 = _call(cd.within, x, y, hi_a, **kw)
        w_lo, e2 = _call(cd.within, x, y, lo_a, **kw)
        b_hi, e3 = _call(cd.distance_if_within, x, y, hi_a, **kw)
        b_lo, e4 = _call(cd.distance_if_within, x, y, lo_a, **kw)
        it, e5 = _call(cd.intersects, x, y, **kw)
        n = len(gcases)
        for entry, v in (
            ("within", w_hi),
            ("within", w_lo),
            ("distance_if_within", b_hi),
            ("distance_if_within", b_lo),
            ("intersects", it),
        ):
            stats["answers"][entry] += n if v is not None else 0
        err = e1 or e2 or e3 or e4 or e5
        if err:
            out.append(_finding("exception", gcases[0], solver, precision, order, "within", error=err))
            continue
        w_hi, w_lo, it = np.asarray(w_hi), np.asarray(w_lo), np.asarray(it)
        b_hi, b_lo = np.asarray(b_hi), np.asarray(b_lo)
        wres[order] = (hi_a, lo_a, w_hi, w_lo, it)
        for j in range(len(gcases)):
            bad = []
            if not w_hi[j]:
                bad.append(f"within(d={float(hi[j])!r}) is False")
            if lo[j] > 0 and w_lo[j]:
                bad.append(f"within(d={float(lo[j])!r}) is True")
            if not _eq(b_hi[j], dd[j]):
                bad.append(f"distance_if_within(d={float(hi[j])!r}) = {b_hi[j]!r}")
            if lo[j] > 0 and not np.isinf(b_lo[j]):
                bad.append(f"distance_if_within(d={float(lo[j])!r}) = {b_lo[j]!r}")
            if Df[j] == 0 and not it[j]:
                bad.append("intersects is False at distance 0")
            if Df[j] > 4 * 64 * eps * ps[j] and Df[j] > bar_abs[j] and it[j]:
                bad.append("intersects is True")
            if bad:
                check = "within_vs_inaccurate_distance" if j in inaccurate.get(order, ()) else "within"
                out.append(
                    _finding(
                        check,
                        gcases[j],
                        solver,
                        precision,
                        order,
                        "within/intersects",
                        library=dd[j],
                        problems=bad,
                        pair_scale=ps[j],
                    )
                )
    return out, wres


def _check_scalar(cd, ka, kb, res, d_orders, wres, sel, gcases, solver, precision, stats):
    """Scalar calls must give exactly the batch's answers (distance, closest points, within at
    the batch's probe limits, intersects)."""
    out = []
    kw = dict(solver=solver, precision=precision)
    dt = _dtype(precision)
    for j in sel:
        c = gcases[j]
        sa = make_shape(cd, ka, c["a_data"], dt)
        sb = make_shape(cd, kb, c["b_data"], dt)
        for order, (x, y) in (("ab", (sa, sb)), ("ba", (sb, sa))):
            if order not in d_orders:
                continue
            d, e1 = _call(cd.distance, x, y, **kw)
            r, e2 = _call(cd.closest_points, x, y, **kw)
            stats["answers"]["scalar distance"] += not e1
            stats["answers"]["scalar closest_points"] += not e2
            if e1 or e2:
                out.append(_finding("exception", c, solver, precision, order, "scalar", error=e1 or e2))
                continue
            rb = res[order]["r"]
            problems = []
            if not _eq(d, d_orders[order][j]):
                problems.append(f"distance: scalar {d!r} batch {d_orders[order][j]!r}")
            if not _eq(r.distance, np.asarray(rb.distance)[j]):
                problems.append(f"closest_points.distance: scalar {r.distance!r} batch {np.asarray(rb.distance)[j]!r}")
            if not (
                np.all(_eq(np.asarray(r.point_a), np.asarray(rb.point_a)[j]))
                and np.all(_eq(np.asarray(r.point_b), np.asarray(rb.point_b)[j]))
            ):
                problems.append(
                    "closest points differ: scalar %r %r batch %r %r"
                    % (
                        np.asarray(r.point_a),
                        np.asarray(r.point_b),
                        np.asarray(rb.point_a)[j],
                        np.asarray(rb.point_b)[j],
                    )
                )
            if order in wres:
                hi_a, lo_a, w_hi, w_lo, it = wres[order]
                for lim, wb in ((hi_a[j], w_hi[j]), (lo_a[j], w_lo[j])):
                    ws, e3 = _call(cd.within, x, y, lim, **kw)
                    stats["answers"]["scalar within"] += not e3
                    if e3:
                        problems.append(f"within raised {e3}")
                    elif bool(ws) != bool(wb):
                        problems.append(f"within(d={lim!r}): scalar {ws} batch {wb}")
                its, e4 = _call(cd.intersects, x, y, **kw)
                stats["answers"]["scalar intersects"] += not e4
                if e4 or bool(its) != bool(it[j]):
                    problems.append(f"intersects: scalar {its} batch {it[j]} {e4 or ''}")
            if problems:
                out.append(_finding("batch_scalar", c, solver, precision, order, "scalar", problems=problems))
    return out
