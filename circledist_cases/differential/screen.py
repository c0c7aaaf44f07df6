"""The fast screen (``screen``).

The fast screen (``screen``): an independent one-parameter minimisation in NumPy.  Every
distance is the minimum over one parameter of a closed form (point-circle, point-disk,
point-line; point-arc: the circle's where the angle of the point's projection lies in the
span, else the nearer end's): a circle's angle against the other shape (both ways round for
two rounds), a line's parameter against the round and the round's angle against the line, an
arc's angle over [0, angle] wherever a circle's runs over [0, 2 pi) and the arc's closed form
wherever a round's is the target; an annulus as a target: the point-annulus closed form (|z|
over the ring, the inner rim's distance over the hole, the outer's beyond), and as a moving
shape both its rims (its inner rim is one more form: against a region, the rims of each
region against the other's closed form are exact, see reference_annulus's docstring; against
a curve the other's parameter against the closed form is exact, the rims only add genuine
pairs), a Bezier curve's t against the round (each half from its
own end, so parameters near an end keep their full precision).  Dense sampling, then a
vectorised beam search (nested re-sampling around the
best few sampled local minima) in float64, then long-double levels around the best.  Where
the sampling step is long for the target round's features (a curve or a huge circle passing a
much smaller round) a Lipschitz zoom (``_zoom``: hodograph or radius bounds on the point's
speed) re-samples every interval that could hold a value below the best sample until a step
moves the point by at most max(R, rho)/8 (rho: distance from the round's axis), and EVERY
sampled local minimum it leaves is refined in long double on its own, the least kept: two
near-tied minima (5.9e-13 apart on a curve 2e4 long, below float64's resolution there) are
both refined, not one chosen by a float64 ranking.  Bezier curves' long-double stage works
on pieces around each candidate whose control points are computed in double-double (a curve
1e5 times larger than the round is resolved to ~1e-19 of the round).  Coordinates are taken relative to the
round's centre;
offsets between inputs (B - C, p1 - p0, P_i - C) and the anchoring of a line at its point
nearest the centre are computed in double-double, so far-translated scenes and far line
origins lose nothing.  Every value is the distance between two genuine points (up to the
long-double rounding reported as ``slack``), hence an UPPER bound of the true distance.  The
screen is a sampling method, not a proof: its misses show up as alarms the 50-digit
reference refutes (counted as "refuted", never as findings).
Pairs without a round: a linear piece's parameter against the other piece's closed form (the
projection clamped; inside the other piece the parts perpendicular to it, in double-double),
s = S0 sinh(x) over every magnitude of s, in long double, re-anchored pass by pass at the
best point found (``_screen_linear``); a Bezier curve's halves against the
piece's closed form, as against a round (``_screen_bezier_linear``); a point: the closed form.
"""

from __future__ import annotations

import math

import numpy as np

from .base import EPS64, EPSLD, LD, LINEAR
from .closed_forms import (
    _Form,
    _P,
    _S_GRID,
    _THETA_GRID,
    _T_GRID,
    _cross,
    _dd_add,
    _dd_div,
    _dd_dot,
    _dd_mul,
    _dd_neg,
    _diff_ld,
    _dot,
    _ld,
    _ld_frame,
    _lin_dist,
    _nrm,
    _tdist,
    _two_sum,
)
from .minimize import _beam, _minimize, _minimize_bezier


def _stack(case_list, key):
    return np.array([c[key] for c in case_list], dtype=float)


def _anchor(kind, data, C, dd=False):
    """A linear shape relative to the centre C, anchored at its point nearest C (double-double):
    returns long-double b0, m, lo, hi with S = {b0 + s m : s in [lo, hi]} (dd: and b0, m as
    double-double pairs of (n, 3) arrays)."""
    n = data.shape[0]
    zeros = np.zeros((n, 3))
    b = _two_sum(data[:, :3], -C)
    if kind == "point":
        out = _ld(b), np.zeros((n, 3), dtype=LD), np.zeros(n, dtype=LD), np.zeros(n, dtype=LD)
        return out + (b, (zeros, zeros)) if dd else out
    if kind == "segment":
        m = _two_sum(data[:, 3:6], -data[:, :3])
    else:
        m = (data[:, 3:6].copy(), zeros)
    # scale m to moderate length exactly (a power of two) so that squares neither overflow nor underflow
    sc = 2.0 ** -np.floor(np.log2(np.maximum(np.max(np.abs(m[0]), axis=1), 1e-300)))
    m = (m[0] * sc[:, None], m[1] * sc[:, None])
    mm = _dd_dot(m, m)
    bm = _dd_dot(b, m)
    ok = mm[0] > 0
    safe = (np.where(ok, mm[0], 1.0), np.where(ok, mm[1], 0.0))
    tc = _dd_neg(_dd_div(bm, safe))
    tc = (np.where(ok, tc[0], 0.0), np.where(ok, tc[1], 0.0))
    b0 = tuple(
        np.stack(c, axis=1)
        for c in zip(*[_dd_add((b[0][:, i], b[1][:, i]), _dd_mul(tc, (m[0][:, i], m[1][:, i]))) for i in range(3)])
    )
    lo_raw = {"line": -np.inf, "ray": 0.0, "segment": 0.0}[kind]
    hi_raw = {"line": np.inf, "ray": np.inf, "segment": 1.0}[kind]
    tcl = _ld(tc)
    lo = (LD(lo_raw) / LD(1)) * np.ones(n, dtype=LD)
    hi = LD(hi_raw) * np.ones(n, dtype=LD)
    lo = lo - tcl
    if kind == "segment":
        # The far end's parameter from its own offset, (p1 - C).m / m.m in double-double: as
        # 1/sc - tc it cancelled to eps * 1e10 along a segment whose other end is 1e10 away.
        th = _dd_div(_dd_dot(_two_sum(data[:, 3:6], -C), m), safe)
        hi = np.where(ok, _ld(th), LD(0))
    else:
        hi = hi - tcl
    return (_ld(b0), _ld(m), lo, hi) + ((b0, m) if dd else ())


def _linear_target(kind, data, C):
    b0, m, lo, hi = _anchor(kind, data, C)
    return dict(tb0=b0, tm=m, tmm=np.sum(m * m, axis=1), tlo=lo, thi=hi)


def _window(b0, m, lo, hi, R):
    """Parameter window holding every minimiser of s -> dist(b0 + s m, round)."""
    mm = np.sum(m * m, axis=1)
    s0 = np.minimum(np.maximum(LD(0), lo), hi)
    dref = _nrm(b0 + s0[:, None] * m)
    b2 = np.sum(b0 * b0, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        W = np.sqrt(np.maximum((dref + 2 * R) ** 2 - b2, 0) / np.where(mm > 0, mm, 1)) * LD(1.001)
    W = np.where(mm > 0, W, 0) + LD(1e-30) * (1 + np.abs(s0))
    wlo = np.minimum(np.maximum(-W, lo), hi)
    whi = np.minimum(np.maximum(W, lo), hi)
    return wlo, whi


def _rim_parts(kind, data):
    """A circle's, disk's or arc's screen parameters (long double) from its data rows (n, 7; an
    arc's n, 11): the normal n; the moving rim's basis (U, V), interval [0, hi], periodicity and
    grid (a circle: the frame of _ld_frame, [0, 2 pi) periodic; an arc: u, the unit projection of
    its start, v = n x u, [0, angle] with both ends sampled, the whole [0, 2 pi] for an angle of
    at least float64's 2 pi); target: the parameters of its closed form (an arc's span too)."""
    n, U, V = _ld_frame(data[:, 3:6])
    Rl = data[:, 6].astype(LD)
    m = len(data)
    target = dict(n=n, R=Rl)
    if kind == "annulus":
        # (its inner rim moves too: "inner"; its features' scale, for the zooms: the least of its
        # positive radii and width)
        Rin = data[:, 7].astype(LD)
        target.update(Rin=Rin)
        width = data[:, 6] - data[:, 7]
        feat = np.min(np.where(np.stack([data[:, 7], width]) > 0, np.stack([data[:, 7], width]), np.inf), axis=0)
        return dict(
            n=n,
            U=U,
            V=V,
            R=Rl,
            inner=Rin,
            feature=np.minimum(data[:, 6], feat),
            hi=np.full(m, 2 * math.pi),
            periodic=True,
            grid=_THETA_GRID,
            target=target,
        )
    if kind != "arc":
        return dict(
            n=n,
            U=U,
            V=V,
            R=Rl,
            hi=np.full(m, 2 * math.pi),
            periodic=True,
            grid=_THETA_GRID,
            target=target,
            feature=data[:, 6],
        )
    S = data[:, 7:10].astype(LD)
    S = S / np.max(np.abs(S), axis=1, keepdims=True)
    u = S - _dot(S, n)[:, None] * n
    u = u / _nrm(u)[:, None]
    v = _cross(n, u)
    ang = data[:, 10]
    whole = ang >= 2 * math.pi
    target.update(tu=u, tv=v, tang=ang.astype(LD), twhole=whole.astype(float))
    return dict(
        n=n,
        U=u,
        V=v,
        R=Rl,
        hi=np.where(whole, 2 * math.pi, ang),
        periodic=False,
        grid=_S_GRID,
        target=target,
        feature=data[:, 6],
    )


class ScreenResult:
    """value: long-double upper bound per case; slack: its rounding allowance; how: (form name,
    parameter as long double) of the best pair, for a 50-digit re-evaluation."""

    def __init__(self, value, slack, forms, params):
        self.value, self.slack, self.forms, self.params = value, slack, forms, params


def screen(cases, use_ld=True):
    """Screen upper bounds for cases of ONE kind pair (canonical order, same number of Bezier
    control points).  use_ld=False (float32 scenes, whose bar is far coarser) skips the
    long-double stage except for Bezier curves."""
    with np.errstate(all="ignore"):
        return _screen(cases, use_ld)


def _screen(cases, use_ld):
    ka, kb = cases[0]["a"], cases[0]["b"]
    if kb in LINEAR:
        return _screen_bezier_linear(cases) if ka == "bezier" else _screen_linear(cases, use_ld)
    n = len(cases)
    B = _stack(cases, "b_data")
    Cb, Rb = B[:, :3], B[:, 6]
    rb = _rim_parts(kb, B)
    Ub, Vb, Rbl, tb = rb["U"], rb["V"], rb["R"], rb["target"]
    forms = []
    if ka == "point":
        A = _stack(cases, "a_data")
        w = _diff_ld(A[:, :3], Cb)
        v = _tdist(w[:, None], tb, kb)[:, 0]
        slack = 16 * EPSLD * (_nrm(w) + Rbl)
        return ScreenResult(v, slack.astype(float), ["point"] * n, [LD(0)] * n)
    if ka in ("line", "ray", "segment"):
        A = _stack(cases, "a_data")
        tgt = _linear_target(ka, A, Cb)
        # (1) the round's rim (an arc's: over its span) against the linear shape's closed form
        p1 = _P(D=np.zeros((n, 3), dtype=LD), Ra=Rbl, Ua=Ub, Va=Vb, **tgt)
        forms.append(_Form("rim|linear", "rim", "linear", p1, np.zeros(n), rb["hi"], rb["periodic"], rb["grid"]))
        zooms = [None]
        if "inner" in rb:
            # (1') an annulus's inner rim too (every form is an upper bound from genuine points)
            p1i = _P(D=np.zeros((n, 3), dtype=LD), Ra=rb["inner"], Ua=Ub, Va=Vb, **tgt)
            forms.append(_Form("rim_inner|linear", "rim", "linear", p1i, np.zeros(n), rb["hi"], True, rb["grid"]))
            zooms.append(None)
        # (2) the linear shape's parameter against the round's (the arc's) closed form
        wlo, whi = _window(tgt["tb0"], tgt["tm"], tgt["tlo"], tgt["thi"], Rbl)
        p2 = _P(b0=tgt["tb0"], m=tgt["tm"], **tb)
        forms.append(_Form("line|round", "line", kb, p2, wlo, whi, False, _S_GRID))
        # (the point moves by |m| per unit of s; the rim's own form is sampled at 1/80 of its radius)
        speed = np.sqrt(tgt["tmm"].astype(float))
        zooms.append((lambda c, a, b: speed[c], rb["feature"]))
    elif ka == "bezier":
        # two halves, each parametrised from its end (t on [0, 1/2], and s = 1 - t on [0, 1/2] with
        # the control points reversed): parameters near an end keep their full relative precision,
        # which a curve with a control point 1e12 away needs (there 1 ulp of t near 1 moves the
        # point by 1e-4)
        ctrl = np.array([c["a_data"] for c in cases], dtype=float)  # (n, K, 3)
        rel_dd = _two_sum(ctrl, -Cb[:, None, :])  # exact
        best = np.full(n, LD(np.inf), dtype=LD)
        names, params = [None] * n, [None] * n
        slack = np.zeros(n)
        for name, order in (("bezier|round", slice(None)), ("bezier_reversed|round", slice(None, None, -1))):
            dd = (rel_dd[0][:, order, :].copy(), rel_dd[1][:, order, :].copy())
            form = _Form(name, "bezier", kb, _P(ctrl=_ld(dd), **tb), np.zeros(n), np.full(n, 0.5), False, _T_GRID)
            # (always refined in long double: a float32 scene of a curve 1e5 times larger than the
            # round needs it for the float32 bar too)
            v, a, b, u, mag = _minimize_bezier(form, dd, tb, rb["feature"].astype(LD))
            for j in np.flatnonzero(v < best):
                best[j], names[j], params[j] = v[j], name, (float(a[j]), float(b[j]), LD(u[j]))
                slack[j] = 16 * EPSLD * float(mag[j])
        return ScreenResult(best, slack, names, params)
    else:
        # two rounds (or arcs): each one's rim (an arc's over its span) against the other's closed form
        A = _stack(cases, "a_data")
        Ca, Ra = A[:, :3], A[:, 6]
        ra = _rim_parts(ka, A)
        Dab = _diff_ld(Ca, Cb)
        pa = _P(D=Dab, Ra=ra["R"], Ua=ra["U"], Va=ra["V"], **tb)
        forms.append(_Form("rim_a|b", "rim", kb, pa, np.zeros(n), ra["hi"], ra["periodic"], ra["grid"]))
        pb = _P(D=-Dab, Ra=Rbl, Ua=Ub, Va=Vb, **ra["target"])
        forms.append(_Form("rim_b|a", "rim", ka, pb, np.zeros(n), rb["hi"], rb["periodic"], rb["grid"]))
        # a rim point moves by its radius per radian (a huge circle passing a small round)
        zooms = [(lambda c, a, b: Ra[c], rb["feature"]), (lambda c, a, b: Rb[c], ra["feature"])]
        # an annulus's inner rim against the other's closed form too
        if "inner" in ra:
            Ria = A[:, 7]
            pai = _P(D=Dab, Ra=ra["inner"], Ua=ra["U"], Va=ra["V"], **tb)
            forms.append(_Form("rim_a_inner|b", "rim", kb, pai, np.zeros(n), ra["hi"], True, ra["grid"]))
            zooms.append((lambda c, a, b: Ria[c], rb["feature"]))
        if "inner" in rb:
            Rib = B[:, 7]
            pbi = _P(D=-Dab, Ra=rb["inner"], Ua=Ub, Va=Vb, **ra["target"])
            forms.append(_Form("rim_b_inner|a", "rim", ka, pbi, np.zeros(n), rb["hi"], True, rb["grid"]))
            zooms.append((lambda c, a, b: Rib[c], ra["feature"]))
    best = np.full(n, LD(np.inf), dtype=LD)
    best_x = np.zeros(n, dtype=LD)
    best_f = np.zeros(n, dtype=int)
    slack = np.zeros(n)
    for fi, form in enumerate(forms):
        lip, R = zooms[fi] or (None, None)
        v, x = _minimize(
            form, np.asarray(form.lo, dtype=LD), np.asarray(form.hi, dtype=LD), use_ld=use_ld, lip=lip, R=R
        )
        better = v < best
        best = np.where(better, v, best)
        best_x = np.where(better, x, best_x)
        best_f = np.where(better, fi, best_f)
    for fi, form in enumerate(forms):
        sel = best_f == fi
        if sel.any():
            mag = form.magnitude(best_x)
            slack = np.where(sel, (16 * EPSLD if use_ld else 16 * EPS64) * mag.astype(float), slack)
    return ScreenResult(best, slack, [forms[i].name for i in best_f], list(best_x))


# ---- pairs without a round: linear pieces among themselves, Bezier curves against them ---------
_SINH_SPAN = LD(1e22)  # the line parameter's window: S0 = r / (|m| _SINH_SPAN) .. r _SINH_SPAN / |m|
LINEAR_PASSES = 5  # re-anchored searches of a linear pair (see _screen_linear)


def _segment_extent(tgt):
    """The linear target's finite extent |m| (hi - lo) (0 for points, lines and rays)."""
    ext = np.sqrt(tgt["tmm"]) * (tgt["thi"] - tgt["tlo"])
    return np.where(np.isfinite(ext), ext, LD(0))


def _screen_linear(cases, use_ld):
    """Two linear pieces (a the earlier kind).  A point: the closed form against b, anchored at
    its point nearest the point in double-double.  Otherwise a's parameter against b's closed
    form, s = S0 sinh(x) (every magnitude of s alike: a convex function of s, unimodal in x; the
    window +-1e22 r / |m|, r the size of the anchors' offsets, holds the minimiser unless the
    directions are parallel within 1e-22, where the function is flat), searched in long double
    (a beam in x), in LINEAR_PASSES passes: relative to b's first point, then each time relative
    to the best point found so far (rounded to float64), both pieces anchored at their points
    nearest that reference point in double-double.  Each pass leaves offsets of the size of the
    distance from the reference point to the minimiser, so the rounding shrinks pass by pass:
    far origins, far ends, far-translated scenes and pieces parallel within 1e-17 whose
    minimiser lies 1e10 along them (where a long-double point is rounded by 1e-9) are resolved.
    The parameter reported is (reference point, s).  use_ld is not used: the search is cheap."""
    ka, kb = cases[0]["a"], cases[0]["b"]
    n = len(cases)
    A, B = _stack(cases, "a_data"), _stack(cases, "b_data")
    eps = 16 * EPSLD
    if ka == "point":
        tgt = _linear_target(kb, B, A[:, :3])
        w = -tgt["tb0"]
        v = _lin_dist(w[:, None], tgt["tm"][:, None], tgt["tmm"][:, None], tgt["tlo"][:, None], tgt["thi"][:, None])[
            :, 0
        ]
        slack = (eps * _nrm(w)).astype(float) + _anchor_error(kb, B, A[:, :3])
        return ScreenResult(v, slack, ["point|linear"] * n, [LD(0)] * n)
    C = B[:, :3].copy()
    best = np.full(n, LD(np.inf), dtype=LD)
    slack = np.zeros(n)
    params = [None] * n
    todo = np.arange(n)
    for _ in range(LINEAR_PASSES):
        v, mag, s, nxt = _linear_pass(ka, kb, A[todo], B[todo], C[todo])
        mag = mag + (_anchor_error(ka, A[todo], C[todo]) + _anchor_error(kb, B[todo], C[todo])) / eps
        # passes compared by their certified bounds (value + rounding slack)
        for q in np.flatnonzero(v + eps * mag < best[todo] + slack[todo]):
            j = todo[q]
            best[j], params[j] = v[q], (tuple(float(c) for c in C[j]), LD(s[q]))
            slack[j] = eps * float(mag[q])
        # the next pass where the best point moved the reference point (else it would repeat)
        moved = np.isfinite(nxt).all(axis=1) & (nxt != C[todo]).any(axis=1)
        C[todo[moved]] = nxt[moved]
        todo = todo[moved]
        if not len(todo):
            break
    return ScreenResult(best, slack, ["line|linear"] * n, params)


def _anchor_error(kind, data, C):
    """A bound on the error of _anchor's double-double anchor of a piece relative to C: 2^-100 of
    the offsets it cancels (an origin 1e10 from C anchored within 1e-7 of it: 1e-20)."""
    off = np.linalg.norm(data[:, :3] - C, axis=1)
    if kind == "segment":
        off = off + np.linalg.norm(data[:, 3:6] - C, axis=1)
    return 2.0**-100 * off


def _dd_vec(v, i):
    return v[0][:, i], v[1][:, i]


def _dd_vsub(x, y):
    """x - y for double-double (n, 3) vectors."""
    return tuple(np.stack(c, axis=1) for c in zip(*[_dd_add(_dd_vec(x, i), _dd_neg(_dd_vec(y, i))) for i in range(3)]))


def _perp_parts(ka, kb, A, B, C):
    """The moving piece a against the target piece b, both anchored at their points nearest C:
    the target's parameters (_linear_target's) and, in double-double rounded to long double, the
    parts of c = b0 - tb0 and of m perpendicular to b's direction u, with c.u, m.u and u.u: where
    b's projection of a(s) lies inside b, the distance is |c_perp + s m_perp|, free of the
    cancellation of |w - (w.u / u.u) u| for w = c + s m (1e7 long: 1e-12 of rounding, against a
    distance that varies by 1e-14 over 1e7 along two lines parallel within 1e-17)."""
    b0, m, lo, hi, b0_dd, m_dd = _anchor(ka, A, C, dd=True)
    tb0, tm, tlo, thi, tb0_dd, u = _anchor(kb, B, C, dd=True)
    uu = _dd_dot(u, u)
    ok = uu[0] > 0
    uu_safe = (np.where(ok, uu[0], 1.0), np.where(ok, uu[1], 0.0))

    def perp(v):
        k = _dd_div(_dd_dot(v, u), uu_safe)
        k = (np.where(ok, k[0], 0.0), np.where(ok, k[1], 0.0))
        return tuple(
            np.stack(c, axis=1)
            for c in zip(*[_dd_add(_dd_vec(v, i), _dd_neg(_dd_mul(k, _dd_vec(u, i)))) for i in range(3)])
        )

    c_dd = _dd_vsub(b0_dd, tb0_dd)
    tgt = dict(tb0=tb0, tm=tm, tmm=np.sum(tm * tm, axis=1), tlo=tlo, thi=thi)
    extra = dict(
        cperp=_ld(perp(c_dd)),
        mperp=_ld(perp(m_dd)),
        cu=_ld(_dd_dot(c_dd, u)),
        mu=_ld(_dd_dot(m_dd, u)),
        uu=_ld(uu_safe),
    )
    return b0, m, lo, hi, tgt, extra


def _linear_pass(ka, kb, A, B, C):
    """One pass of _screen_linear relative to the reference points C: (value, magnitude of the
    cancelling quantities, parameter s, the best point rounded to float64) per case."""
    eps = 16 * EPSLD
    b0, m, lo, hi, tgt, extra = _perp_parts(ka, kb, A, B, C)
    mn = _nrm(m)
    r = np.maximum(_nrm(b0) + _nrm(tgt["tb0"]) + _segment_extent(tgt), LD(1e-280))
    ok = mn > 0
    S0 = np.where(ok, r / np.where(ok, mn, 1) / _SINH_SPAN, LD(1))
    Smax = S0 * _SINH_SPAN * _SINH_SPAN
    xlo = np.where(ok, np.arcsinh(np.maximum(lo, -Smax) / S0), LD(0))
    xhi = np.where(ok, np.arcsinh(np.minimum(hi, Smax) / S0), LD(0))
    form = _Form(
        "line|linear", "line", "linear", _P(b0=b0, m=m, S0=S0, slo=lo, shi=hi, **tgt, **extra), xlo, xhi, False, _S_GRID
    )
    v, x, _, _ = _beam(form, xlo, xhi, 3, 40, 8, LD)
    mag = form.magnitude(x)
    s = form.line_s(x, form.p.ld)
    nxt = (C.astype(LD) + b0 + s[:, None] * m).astype(float)
    # the anchor itself (x = 0) where it is as good up to the rounding: on a flat function
    # (parallel pieces) the search may stop anywhere, 1e8 away where the rounding is large
    x0 = np.minimum(np.maximum(LD(0), xlo), xhi)
    v0, mag0 = form.f(x0[:, None])[:, 0], form.magnitude(x0)
    take0 = v0 + eps * mag0 <= v + eps * mag
    return (np.where(take0, v0, v), np.where(take0, mag0, mag), np.where(take0, form.line_s(x0, form.p.ld), s), nxt)


def _bezier_eval64(ctrl, t):
    """B(t) (float64, de Casteljau) of curves (n, K, 3) at t (n,)."""
    P = ctrl.copy()
    while P.shape[1] > 1:
        P = P[:, :-1] + t[:, None, None] * (P[:, 1:] - P[:, :-1])
    return P[:, 0]


def _screen_bezier_linear(cases):
    """A Bezier curve against a point, line, ray or segment: the curve's t against the piece's
    closed form, by the halves of the Bezier-round screen (_minimize_bezier; the zoom resolves
    1e-4 of the query's size, or the distance itself where larger, as reference_round.bezier_other
    does), twice: relative to the control point nearest the piece, then relative to the best
    point found (rounded to float64); the piece anchored at its point nearest that reference point
    in double-double, the control points taken relative to it exactly."""
    kb = cases[0]["b"]
    n = len(cases)
    ctrl = np.array([c["a_data"] for c in cases], dtype=float)  # (n, K, 3)
    B = _stack(cases, "b_data")
    ext = np.max(np.linalg.norm(ctrl - ctrl[:, :1], axis=2), axis=1)
    if kb == "segment":
        ext = np.maximum(ext, np.linalg.norm(B[:, 3:6] - B[:, :3], axis=1))
    res = np.maximum(1e-4 * ext, 1e-300)
    o = B[:, :3]
    m = np.zeros((n, 3)) if kb == "point" else (B[:, 3:6] - o if kb == "segment" else B[:, 3:6])
    lo, hi = {"point": (0.0, 0.0), "line": (-np.inf, np.inf), "ray": (0.0, np.inf), "segment": (0.0, 1.0)}[kb]
    near = _lin_dist(ctrl - o[:, None], m[:, None], np.sum(m * m, axis=1)[:, None], lo, hi)
    C = ctrl[np.arange(n), np.argmin(np.where(np.isfinite(near), near, np.inf), axis=1)]
    best = np.full(n, LD(np.inf), dtype=LD)
    names, params = [None] * n, [None] * n
    slack = np.zeros(n)
    t_best = np.zeros(n)
    todo = np.arange(n)
    for pass_ in range(2):
        sub = [ctrl[todo], B[todo], C[todo], res[todo]]
        for name, v, a, b, u, mag in _bezier_linear_pass(kb, *sub):
            mag = mag + _anchor_error(kb, B[todo], C[todo]) / (16 * EPSLD)
            # halves and passes compared by their certified bounds (value + rounding slack)
            for q in np.flatnonzero(v + 16 * EPSLD * mag < best[todo] + slack[todo]):
                j = todo[q]
                best[j], names[j], params[j] = v[q], name, (float(a[q]), float(b[q]), LD(u[q]))
                slack[j] = 16 * EPSLD * float(mag[q])
                t = float(a[q]) + float(u[q]) * (float(b[q]) - float(a[q]))
                t_best[j] = t if name == "bezier|linear" else 1 - t
        # the second pass where the rounding slack is not negligible against the long-double bar
        # (1e-15 of the query's size): the reference point far from the minimum
        todo = np.flatnonzero(slack > 1e-17 * np.maximum(best.astype(float), ext))
        if pass_ == 1 or not len(todo):
            break
        nxt = _bezier_eval64(ctrl[todo], t_best[todo])
        keep = np.isfinite(nxt).all(axis=1)
        todo = todo[keep]
        C[todo] = nxt[keep]
    return ScreenResult(best, slack, names, params)


def _bezier_linear_pass(kb, ctrl, B, C, res):
    """Both halves of _screen_bezier_linear relative to the reference points C: yields (form
    name, value, a, b, u, magnitude) per half."""
    n = len(ctrl)
    rel_dd = _two_sum(ctrl, -C[:, None, :])
    tgt = _linear_target(kb, B, C)
    for name, order in (("bezier|linear", slice(None)), ("bezier_reversed|linear", slice(None, None, -1))):
        dd = (rel_dd[0][:, order, :].copy(), rel_dd[1][:, order, :].copy())
        form = _Form(name, "bezier", "linear", _P(ctrl=_ld(dd), **tgt), np.zeros(n), np.full(n, 0.5), False, _T_GRID)
        yield (name,) + tuple(_minimize_bezier(form, dd, tgt, res))
