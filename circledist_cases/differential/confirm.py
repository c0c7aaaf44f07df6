"""Confirmation of findings with the 50-digit references (imported on first use)."""

from __future__ import annotations

import math

import numpy as np

from .base import BARS, LINEAR, _key, _load, _piece_points
from .closed_forms import _two_sum
from .families import bar_scale, to_float32_case


_REF_CACHE = {}
# a Bezier curve against a point, line, ray, segment, circle or disk: the reference's refined local
# minima over the curve's t, [(distance, t)] lowest first (reused by reference_unique)
_CURVE_MINIMA = {}


def mp_reference(case):
    """The 50-digit reference distance (mpf) of a case (canonical order), cached."""
    key = _key(case)
    if key in _REF_CACHE:
        return _REF_CACHE[key]
    L, R = _load("reference_linear_round"), _load("reference_round")
    ka, a, kb, b = key
    if kb == "annulus":
        ref = _ann_reference(ka, a, b)
    elif kb == "arc":
        ref = _load("reference_arc").case_reference(ka, list(a), kb, list(b))
    elif kb in LINEAR and ka in LINEAR:
        ref = _load("reference_linear").linear_linear(ka, a, kb, b)
    elif kb in LINEAR:
        full = R.bezier_other([list(p) for p in a], kb, *_piece_points(kb, b))
        _CURVE_MINIMA[key] = [(p.value, p.t) for p in full.pairs]
        ref = full.distance
    elif ka in LINEAR:
        ref = L.reference(ka, a, kb, b).distance
    elif ka == "bezier":
        f = R.bezier_disk if kb == "disk" else R.bezier_circle
        full = f([list(p) for p in a], b[:3], b[3:6], b[6])
        _CURVE_MINIMA[key] = [(p.value, p.t) for p in full.pairs]
        ref = full.distance
    else:
        f = {("circle", "circle"): R.circle_circle, ("circle", "disk"): R.circle_disk, ("disk", "disk"): R.disk_disk}[
            (ka, kb)
        ]
        ref = f(a[:3], a[3:6], a[6], b[:3], b[3:6], b[6]).distance
    _REF_CACHE[key] = ref
    return ref


def ann_shape(kind, data):
    """reference_annulus's tuple of a shape given as the differential's flat data list (an
    annulus: centre, normal, outer, inner here; (center, normal, inner, outer) there)."""
    if kind == "annulus":
        d = [float(x) for x in data]
        return _load("reference_annulus").annulus(d[:3], d[3:6], d[7], d[6])
    return _load("reference_arc").shape(kind, data)


def _ann_reference(ka, a, b):
    """The 50-digit distance of a case with an annulus (canonical order: the annulus second):
    reference_annulus's minimum of closed forms over the other shape's parameter, and rim by
    rim for regions (its docstring says why that is exact); a Bezier curve: over its t."""
    RA = _load("reference_annulus")
    if ka == "bezier":
        return RA.bezier_reference_mp(ann_shape("annulus", b), [list(p) for p in a])
    return RA.reference_mp(ann_shape("annulus", b), ann_shape(ka, a))


def _mp_piece_distance(p, kind, data):
    """The 50-digit distance (reference_round's context) from the mp point p to a linear piece."""
    R = _load("reference_round")
    if kind == "point":
        return R.dist(p, R.vec(data[:3]))
    return R.point_linear_closest(p, kind, R.vec(data[:3]), R.vec(data[3:6]))[0]


def _mp_line_point(ka, a, C, x):
    """The point (reference_round's context) of the line, ray or segment a at the screen's
    parameter x: relative to the anchor (a's point nearest C), in units of the direction scaled
    by the power of two sc of _anchor: t = tc + x sc."""
    L, R = _load("reference_linear_round"), _load("reference_round")
    lin = L.Linear(ka, a)
    if lin.mm == 0:
        t = L.mpf(0)
    else:
        m = np.asarray(a[3:6], float)
        if ka == "segment":
            m = _two_sum(m, -np.asarray(a[:3], float))[0]
        sc = 2.0 ** -math.floor(math.log2(max(float(np.max(np.abs(m))), 1e-300)))
        tc = -L._dot(L._sub(lin.B, L._v(C)), lin.m) / lin.mm
        t = lin.clamp(tc + L.mpf(R.ctx.nstr(x, 60)) * L.mpf(sc))
    return tuple(R.mpf(L.mp.nstr(c, 60)) for c in lin.point(t))


def _mpf_ld(x):
    R = _load("reference_round")
    p, q = np.longdouble(x).as_integer_ratio()
    return R.mpf(p) / q


def mp_screen_value(case, form, param):
    """The screen's best pair re-evaluated at 50 digits: the exact distance between the genuine
    point the screen's parameter names and the other shape (an upper bound of the truth)."""
    L, R = _load("reference_linear_round"), _load("reference_round")
    ka, kb = case["a"], case["b"]
    a, b = case["a_data"], case["b_data"]
    x = _mpf_ld(param) if not isinstance(param, tuple) else None
    ctx = R.ctx
    if form == "point":
        return _mp_rim_distance(R.vec(a[:3]), kb, b)
    if form in ("rim|linear", "rim_inner|linear"):
        p = _mp_rim(kb, b, x, inner=form == "rim_inner|linear")
        return L.Linear(ka, a).distance_to_point(tuple(L.mpf(ctx.nstr(c, 60)) for c in p))
    if form == "line|round":
        return _mp_rim_distance(_mp_line_point(ka, a, b[:3], x), kb, b)
    if form == "point|linear":
        return _mp_piece_distance(R.vec(a[:3]), kb, b)
    if form == "line|linear":
        C, s = param
        return _mp_piece_distance(_mp_line_point(ka, a, C, _mpf_ld(s)), kb, b)
    if form in ("bezier|linear", "bezier_reversed|linear"):
        lo_, hi_, u = param
        t = R.mpf(lo_) + _mpf_ld(u) * (R.mpf(hi_) - R.mpf(lo_))
        return _mp_piece_distance(R.bezier_point(a, t if form == "bezier|linear" else 1 - t), kb, b)
    if form in ("bezier|round", "bezier_reversed|round"):
        lo_, hi_, u = param
        t = R.mpf(lo_) + _mpf_ld(u) * (R.mpf(hi_) - R.mpf(lo_))
        return _mp_rim_distance(R.bezier_point(a, t if form == "bezier|round" else 1 - t), kb, b)
    if form in ("rim_a|b", "rim_a_inner|b"):
        return _mp_rim_distance(_mp_rim(ka, a, x, inner=form == "rim_a_inner|b"), kb, b)
    return _mp_rim_distance(_mp_rim(kb, b, x, inner=form == "rim_b_inner|a"), ka, a)


def _mp_rim(kind, data, x, inner=False):
    """The point (reference_round's context) at the screen's angle x of a circle or disk's rim
    (the frame of _ld_frame, which the references build alike), of an annulus's outer or (inner)
    inner rim (the same frame) or of an arc (from its start)."""
    if kind == "arc":
        A = _load("reference_arc")
        return A.ArcMP(A.shape(kind, data)).at(x)
    return _load("reference_round").make_round(data[:3], data[3:6], data[7] if inner else data[6]).rim_point(x)


def _mp_rim_distance(p, kind, data):
    """The 50-digit distance from the mp point p to a circle, disk, arc or annulus (closed forms)."""
    if kind == "annulus":
        return _load("reference_annulus").AnnulusMP(ann_shape(kind, data)).point_distance(p)
    A = _load("reference_arc")
    return A.point_distance_function(A.shape(kind, data))(p)


def confirm(finding, case, screen_info):
    """Judge an accuracy finding (above_bound / below_bound / distance_vs_closest_points) against
    the 50-digit reference.  Adds reference, reference_screen (the screen's pair at 50 digits),
    reference_missed (the screen's pair beats the reference: the reference is wrong there),
    error (relative) and confirmed."""
    f32 = finding["precision"] == "float32"
    c = to_float32_case(case) if f32 else case
    ref = mp_reference(c)
    form = screen_info["form32" if f32 else "form"]
    param = screen_info["param32" if f32 else "param"]
    try:
        scr = mp_screen_value(c, form, param)
    except Exception as e:  # noqa: BLE001
        scr = None
        finding["reference_screen_error"] = str(e)
    best = ref
    finding["basis"] = "mpmath reference"
    if scr is not None:
        finding["reference_screen"] = float(scr)
        R = _load("reference_round")
        scale_ = max(abs(ref), R.mpf(bar_scale(c)), R.mpf("1e-300"))
        if scr < ref - R.mpf(MISS_REL) * scale_:
            finding["reference_missed"] = True
            finding["basis"] = "the screen's pair at 50 digits (the mpmath reference missed the minimum)"
            best = scr
    finding["reference"] = float(best)
    scale_ = max(float(best), bar_scale(c))
    bar = BARS[finding["precision"]] * scale_
    vals = [finding[k] for k in ("library", "distance", "closest_points") if k in finding]
    # long-double answers are stored as 25-digit text (exact far below their ulp)
    errs = [abs(_mp_num(v) - best) for v in vals if not (isinstance(v, str) and v in ("nan", "inf"))]
    finding["error"] = float(max(errs) / scale_) if errs and scale_ > 0 else None
    finding["confirmed"] = bool(errs) and bool(max(errs) > bar)
    return finding


def confirm_point(finding, case):
    """Re-measure point_off_shape at 50 digits (closed forms; Bezier: the 50-digit point-curve
    distance by the reference's one-parameter minimisation)."""
    L, R = _load("reference_linear_round"), _load("reference_round")
    ka, kb = finding["kinds"]
    a, b = finding["a_data"], finding["b_data"]
    offs = []
    for kind, data, p in ((ka, a, finding["point_a"]), (kb, b, finding["point_b"])):
        # points are stored exactly (long-double ones as 25-digit text)
        if kind == "bezier":
            offs.append(float(R.bezier_disk(data, list(p), (0.0, 0.0, 1.0), 0.0).distance))
        elif kind == "arc":
            A = _load("reference_arc")
            offs.append(float(A.ArcMP(A.shape(kind, data)).point_distance(tuple(_mp_num(x) for x in p))))
        elif kind == "annulus":
            offs.append(float(_mp_rim_distance(tuple(_mp_num(x) for x in p), kind, data)))
        else:
            offs.append(float(L.distance_to_shape(tuple(L.mpf(x) for x in p), kind, tuple(data))))
    finding["off_a_mp"], finding["off_b_mp"] = offs
    finding["confirmed"] = max(offs) > finding["allowed"]
    return finding


ACCURACY_CHECKS = ("above_bound", "below_bound", "distance_vs_closest_points")
# a genuine pair (the screen's, at 50 digits) below the reference by more than this (relative to
# max(reference, largest radius)) means the reference missed the minimum: 1e-3 of the tightest bar
MISS_REL = "1e-18"


EXACT_CHECKS = (
    "within",
    "within_vs_inaccurate_distance",
    "asymmetric",
    "batch_scalar",
    "dtype",
    "float32_value",
    "whole_arc_vs_circle",
    "degenerate_annulus_vs_disk",
    "degenerate_annulus_vs_circle",
    "unique",
    "exception",
    "non_finite",
)


def _mp_num(v):
    R = _load("reference_round")
    return R.mpf(v) if isinstance(v, str) else R.mpf(float(v))


def confirm_separation(finding):
    """Re-measure a separation mismatch at 50 digits from the stored points."""
    R = _load("reference_round")
    pa = [_mp_num(x) for x in finding["point_a"]]
    pb = [_mp_num(x) for x in finding["point_b"]]
    sep = R.norm(R.sub(tuple(pa), tuple(pb)))
    finding["separation_mp"] = float(sep)
    finding["confirmed"] = bool(abs(sep - _mp_num(finding["library"])) > _mp_num(finding["allowed"]))
    return finding


def confirm_finding(finding, case, screen_info):
    """Confirm one finding: accuracy findings against the 50-digit reference, point findings by
    50-digit residuals; the exact consistency checks (within, symmetry, batch == scalar, dtypes,
    exceptions) need no reference and are confirmed as they stand."""
    check = finding["check"]
    if check in ACCURACY_CHECKS:
        return confirm(finding, case, screen_info)
    if check == "point_off_shape":
        return confirm_point(finding, case)
    if check == "separation":
        return confirm_separation(finding)
    finding["confirmed"] = True
    return finding
