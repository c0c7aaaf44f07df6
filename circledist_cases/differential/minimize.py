"""The screen's one-parameter minimisation: dense sampling, a vectorised beam search in float64,
long-double levels around the best, and the Lipschitz zoom for a moving shape much larger than
the target's features (see screen's docstring).
"""

from __future__ import annotations

import math

import numpy as np

from .base import LD
from .closed_forms import _Form, _P, _S_GRID, _dd_add, _dd_mul, _ld


def _beam(form, lo, hi, beam, levels, K, dtype, start=None):
    """Nested re-sampling: keep the `beam` best sampled local minima per case, re-sample each
    bracket at K+1 points per level.  start: (a, b) brackets (n, m) to begin from instead of the
    grid.  Returns (best value, best x, final bracket centres (n, beam), their values)."""
    n = lo.shape[0]
    lo, hi = lo.astype(dtype), hi.astype(dtype)
    w = hi - lo
    inf = dtype(np.inf)
    if start is None:
        g = form.grid.astype(dtype)
        X = lo[:, None] + g[None, :] * w[:, None]
        if not form.periodic:
            X[:, -1] = hi
        F = form.f(X)
        if form.periodic:
            Fl, Fr = np.roll(F, 1, 1), np.roll(F, -1, 1)
            Xl = np.concatenate([X[:, -1:] - w[:, None], X[:, :-1]], 1)
            Xr = np.concatenate([X[:, 1:], X[:, :1] + w[:, None]], 1)
        else:
            pad = np.full((n, 1), inf, dtype=dtype)
            Fl, Fr = np.concatenate([pad, F[:, :-1]], 1), np.concatenate([F[:, 1:], pad], 1)
            Xl = np.concatenate([X[:, :1], X[:, :-1]], 1)
            Xr = np.concatenate([X[:, 1:], X[:, -1:]], 1)
        # sampled local minima; a run of equal samples counts once (strict on the right), so that
        # plateaus (a curve's end point sampled at clustered parameters, a flat function) do not
        # fill the beam; a row without any (a flat periodic function) keeps its smallest sample
        lm = (F <= Fl) & (F < Fr)
        none = ~lm.any(axis=1)
        lm[none, np.argmin(F[none], axis=1)] = True
        Fm = np.where(lm, F, inf)
        idx = np.argsort(Fm, axis=1, kind="stable")[:, :beam]
        a = np.take_along_axis(Xl, idx, 1)
        b = np.take_along_axis(Xr, idx, 1)
        va = np.take_along_axis(Fm, idx, 1)
        j = np.argmin(F, axis=1)
        best_v = F[np.arange(n), j]
        best_x = X[np.arange(n), j]
        centres = np.take_along_axis(X, idx, 1)
    else:
        a, b = start
        a, b = a.astype(dtype), b.astype(dtype)
        va = np.zeros(a.shape, dtype=dtype)
        best_v = np.full(n, inf, dtype=dtype)
        best_x = a[:, 0].copy()
        centres = (a + b) / 2
    tt = np.linspace(0, 1, K + 1).astype(dtype)
    m = a.shape[1]
    for _ in range(levels):
        h = (b - a) / K
        P = a[..., None] + (b - a)[..., None] * tt
        if not form.periodic:
            P = np.minimum(np.maximum(P, lo[:, None, None]), hi[:, None, None])
        V = form.f(P.reshape(n, -1)).reshape(n, m, K + 1)
        V = np.where(np.isfinite(va)[..., None], V, inf)
        padc = np.full((n, m, 1), inf, dtype=dtype)
        lm = (V <= np.concatenate([padc, V[..., :-1]], 2)) & (V < np.concatenate([V[..., 1:], padc], 2))
        Vm = np.where(lm, V, inf).reshape(n, -1)
        flat = ~np.isfinite(Vm).any(axis=1)
        if flat.any():
            Vr = V.reshape(n, -1)
            Vm[flat, np.argmin(Vr[flat], axis=1)] = Vr[flat].min(axis=1)
        jj = np.argsort(Vm, axis=1, kind="stable")[:, :beam]
        bi, kk = np.divmod(jj, K + 1)
        Pf = P.reshape(n, -1)
        hb = np.take_along_axis(h, bi, 1)
        centres = np.take_along_axis(Pf, jj, 1)
        lo_i = np.where(kk > 0, np.take_along_axis(Pf, np.maximum(jj - 1, 0), 1), centres - hb)
        hi_i = np.where(kk < K, np.take_along_axis(Pf, np.minimum(jj + 1, Pf.shape[1] - 1), 1), centres + hb)
        a, b = lo_i, hi_i
        if not form.periodic:
            a = np.maximum(a, lo[:, None])
            b = np.minimum(b, hi[:, None])
        va = np.take_along_axis(Vm, jj, 1)
        m = a.shape[1]
        j = np.argmin(V.reshape(n, -1), axis=1)
        v = V.reshape(n, -1)[np.arange(n), j]
        better = v < best_v
        best_v = np.where(better, v, best_v)
        best_x = np.where(better, Pf[np.arange(n), j], best_x)
    return best_v, best_x, centres, va


# The zoom: a uniform scan of a shape far larger than the other one (a curve 2e4 long passing a
# ring of radius 0.8, a huge circle passing a small disk) has steps much longer than the other
# shape, so two local minima a fraction of its size apart fall between the same two samples and a
# search from the best sample finds one of them, possibly the higher (5.9e-13 higher for the far
# curve of tests/accuracy/test_regressions.py::test_far_curve_near_tied_minima, below float64's resolution
# of a point 2e4 away, so no float64 ranking can choose between them).  The zoom re-samples, in
# float64, every interval that could hold a value below the best sample until one step moves the
# point by at most max(R, rho) / ZOOM_FRACTION (R the target round's radius, rho the distance from
# its axis: the scale on which the distance to the round can have distinct local minima, see
# reference_round._feature_scale), and hands EVERY sampled local minimum (the ZOOM_KEEP lowest
# per case) to the long-double stage, each refined on its own.
ZOOM_FRACTION = 8  # resolution: max(R, rho) / this
ZOOM_SPLIT = 8  # pieces per split interval and pass
ZOOM_PASSES = 24  # 8^24: from a grid step to ~1e-22 of it
ZOOM_CAP = 2048  # intervals split per case and pass (lowest bounds first; reached only by
# curves with a control point 1e6+ away, which the value-driven beam covers)
ZOOM_KEEP = 6  # sampled local minima per case refined in long double


def _zoom(form, lo, hi, lip, R):
    """Lipschitz zoom of form on [lo, hi] (float64 arrays (n,)).  lip(c, a, b): a bound on the
    point's speed |dX/dx| on the intervals [a, b] of cases c (flat arrays); R (n,): the target
    round's radius.  f is 1-Lipschitz in the moving point, so nothing on [a, b] lies below
    (f(a) + f(b))/2 - L (b - a)/2: intervals above the best sample are dropped, the others split
    until L (b - a) <= max(R, rho) / ZOOM_FRACTION (rho: a lower bound of the distance from the
    target's axis on [a, b]).  Returns flat candidates (case, x, half-width h, value): the
    ZOOM_KEEP lowest sampled local minima of each case (h: the step around it; the minimum lies
    in [x - h, x + h]), and zoomed (n,): whether a case needed any split."""
    n = lo.shape[0]
    w = hi - lo
    X = lo[:, None] + form.grid[None, :] * w[:, None]
    if form.periodic:  # the interval that wraps round, closed by the first sample one period on
        X = np.concatenate([X, X[:, :1] + w[:, None]], 1)
    else:
        X[:, -1] = hi
    F, RHO = form.f_rho(X)
    RHO = RHO.astype(float)
    best = F.min(axis=1)
    G = X.shape[1]
    c = np.repeat(np.arange(n), G - 1)
    a, b = X[:, :-1].ravel(), X[:, 1:].ravel()
    fa, fb = F[:, :-1].ravel(), F[:, 1:].ravel()
    ra, rb = RHO[:, :-1].ravel(), RHO[:, 1:].ravel()
    zoomed = np.zeros(n, dtype=bool)
    done = []
    tt = np.arange(1, ZOOM_SPLIT) / ZOOM_SPLIT
    for pass_ in range(ZOOM_PASSES + 1):
        lh = lip(c, a, b) * (b - a)
        lb = (fa + fb - lh) / 2
        alive = lb <= best[c]
        res = np.maximum(R[c], np.minimum(ra, rb) - lh / 2) / ZOOM_FRACTION
        split = alive & (lh > res) & (pass_ < ZOOM_PASSES)
        fin = alive & ~split
        done.append((c[fin], a[fin], b[fin], fa[fin], fb[fin], lb[fin]))
        if not split.any():
            break
        c, a, b, fa, fb, ra, rb, lb = (v[split] for v in (c, a, b, fa, fb, ra, rb, lb))
        zoomed[c] = True
        # at most ZOOM_CAP per case, the lowest bounds first (c is sorted: intervals stay in order)
        order = np.lexsort((lb, c))
        rank = np.empty(len(c), dtype=np.int64)
        rank[order] = np.arange(len(c)) - np.searchsorted(c[order], c[order])
        keep = rank < ZOOM_CAP
        c, a, b, fa, fb, ra, rb = (v[keep] for v in (c, a, b, fa, fb, ra, rb))
        P = a[:, None] + (b - a)[:, None] * tt
        V, RH = form.take(c).f_rho(P)
        np.minimum.at(best, c, V.min(axis=1))
        XX = np.concatenate([a[:, None], P, b[:, None]], 1)
        FF = np.concatenate([fa[:, None], V, fb[:, None]], 1)
        RR = np.concatenate([ra[:, None], RH.astype(float), rb[:, None]], 1)
        c = np.repeat(c, ZOOM_SPLIT)
        a, b = XX[:, :-1].ravel(), XX[:, 1:].ravel()
        fa, fb = FF[:, :-1].ravel(), FF[:, 1:].ravel()
        ra, rb = RR[:, :-1].ravel(), RR[:, 1:].ravel()
    c, a, b, fa, fb, lb = (np.concatenate(v) for v in zip(*done))
    live = lb <= best[c]  # the best sample kept falling: drop what it now excludes
    c, a, b, fa, fb = (v[live] for v in (c, a, b, fa, fb))
    # the samples (both ends of the intervals kept), in order per case, each with its step
    h = b - a
    cc, xx, ff, hh = np.concatenate([c, c]), np.concatenate([a, b]), np.concatenate([fa, fb]), np.concatenate([h, h])
    if form.periodic:
        xx = np.where(xx >= hi[cc], xx - w[cc], xx)
    order = np.lexsort((xx, cc))
    cc, xx, ff, hh = cc[order], xx[order], ff[order], hh[order]
    first = np.ones(len(cc), dtype=bool)
    first[1:] = (cc[1:] != cc[:-1]) | (xx[1:] != xx[:-1])
    starts = np.flatnonzero(first)
    hh = np.maximum.reduceat(hh, starts)  # a sample between a fine and a coarse interval: both sides
    cc, xx, ff = cc[starts], xx[starts], ff[starts]
    # sampled local minima; a run of equal samples counts once (strict on the right); at the ends
    # of a case's samples the neighbour is the other end (periodic) or nothing
    m = len(cc)
    gs = np.ones(m, dtype=bool)
    gs[1:] = cc[1:] != cc[:-1]
    ge = np.ones(m, dtype=bool)
    ge[:-1] = cc[1:] != cc[:-1]
    gstart = np.maximum.accumulate(np.where(gs, np.arange(m), 0))
    gend = np.minimum.accumulate(np.where(ge, np.arange(m), m)[::-1])[::-1]
    prev = np.where(gs, gend, np.arange(m) - 1)
    nxt = np.where(ge, gstart, np.arange(m) + 1)
    fprev = np.where(gs & (not form.periodic), np.inf, ff[prev])
    fnext = np.where(ge & (not form.periodic), np.inf, ff[nxt])
    lm = (ff <= fprev) & (ff < fnext)
    has = np.zeros(n, dtype=bool)
    has[cc[lm]] = True
    lm |= ~has[cc] & (ff == best[cc])  # a flat case: its best sample
    cc, xx, ff, hh = cc[lm], xx[lm], ff[lm], hh[lm]
    order = np.lexsort((ff, cc))
    cc, xx, ff, hh = cc[order], xx[order], ff[order], hh[order]
    rank = np.arange(len(cc)) - np.searchsorted(cc, cc)
    keep = rank < ZOOM_KEEP
    return (cc[keep], xx[keep], hh[keep], ff[keep]), zoomed


def _refine_ld(form, cc, a, b, ld_levels, K):
    """Long-double beam search of form on the brackets [a, b] of cases cc (flat: one row per
    candidate, each refined on its own).  Returns (value, x) per row."""
    sub = form.take(cc)
    lo, hi = np.asarray(sub.lo, dtype=LD), np.asarray(sub.hi, dtype=LD)
    vv, xx, _, _ = _beam(sub, lo, hi, 2, ld_levels, K, LD, start=(a[:, None], b[:, None]))
    return vv, xx


def _least(n, cc, v, *cols):
    """Per case (0..n-1) the row of cc with the least v: (has a row, v, cols...) per case."""
    order = np.lexsort((v, cc))
    cc_s = cc[order]
    first = np.ones(len(cc_s), dtype=bool)
    first[1:] = cc_s[1:] != cc_s[:-1]
    pick = order[first]
    has = np.zeros(n, dtype=bool)
    has[cc[pick]] = True
    outs = []
    for col in (v,) + cols:
        o = np.zeros(n, dtype=col.dtype)
        o[cc[pick]] = col[pick]
        outs.append(o)
    return (has, *outs)


def _minimize(form, lo, hi, beam=5, levels=14, ld_levels=30, K=8, use_ld=True, lip=None, R=None):
    """Float64 beam search from the grid, then (use_ld) long-double levels around the two best
    final brackets; with lip/R (see _zoom) the cases whose grid is too coarse for R are zoomed
    too and each of their sampled local minima is refined in long double on its own.  Returns
    (value (long double), x (long double))."""
    n = lo.shape[0]
    v64, x64, centres, vals = _beam(form, lo, hi, beam, levels, K, np.float64)
    zc = None
    if lip is not None:
        (zc, zx, zh, zf), zoomed = _zoom(form, lo.astype(float), hi.astype(float), lip, R)
        sel = zoomed[zc]
        zc, zx, zh, zf = zc[sel], zx[sel], zh[sel], zf[sel]
        if not use_ld and len(zc):
            has, zv, zxx = _least(n, zc, zf, zx)
            better = has & (zv < v64)
            v64, x64 = np.where(better, zv, v64), np.where(better, zxx, x64)
    xl = x64.astype(LD)
    vl = form.f(xl[:, None])[:, 0] if use_ld else v64.astype(LD)
    if not use_ld:
        return vl, xl
    width = (hi - lo).astype(LD)
    hw = np.maximum(width * LD(1e-7), LD(0))[:, None]
    order = np.argsort(vals, axis=1, kind="stable")[:, :2]
    cx = np.take_along_axis(centres, order, 1).astype(LD)
    a, b = cx - hw, cx + hw
    vv, xx, _, _ = _beam(form, lo.astype(LD), hi.astype(LD), 2, ld_levels, K, LD, start=(a, b))
    better = vv < vl
    vl, xl = np.where(better, vv, vl), np.where(better, xx, xl)
    if zc is not None and len(zc):
        zv, zxx = _refine_ld(form, zc, (zx - zh).astype(LD), (zx + zh).astype(LD), ld_levels, K)
        has, zv, zxx = _least(n, zc, zv, zxx)
        better = has & (zv < vl)
        vl, xl = np.where(better, zv, vl), np.where(better, zxx, xl)
    return vl, xl


def _sub_bezier_dd(ctrl_dd, a, b):
    """Control points (long double) of the piece of the curve on [a, b] (a, b: float64 arrays):
    Q_j = blossom(a, .., a, b, .., b) (k - j a's, j b's) by de Casteljau steps in double-double,
    so the piece is the same curve up to ~1e-32 of the control points' size."""
    hi, lo = ctrl_dd
    k = hi.shape[1] - 1
    out = []
    for j in range(k + 1):
        ph, pl = hi, lo
        for tau in [a] * (k - j) + [b] * j:
            t = np.broadcast_to(tau[:, None, None], ph[:, 1:].shape)
            d = _dd_add((ph[:, 1:], pl[:, 1:]), (-ph[:, :-1], -pl[:, :-1]))
            d = _dd_mul(d, (t, np.zeros(t.shape)))
            ph, pl = _dd_add((ph[:, :-1], pl[:, :-1]), d)
        out.append(_ld((ph[:, 0], pl[:, 0])))
    return np.stack(out, axis=1)


def _lipschitz(dP, a, b):
    """Bound on |B'(t)| for t in [a, b] (arrays (n, m)): B' = k sum_i b_{i,k-1}(t) (P_{i+1} - P_i),
    and each Bernstein basis function is unimodal with its maximum at i/(k-1), so
    |B'| <= k sum_i |P_{i+1} - P_i| max_[a,b] b_{i,k-1}."""
    k = dP.shape[1]
    if k == 1:
        return np.broadcast_to(dP[:, :1], a.shape)
    out = 0
    for i in range(k):
        t = np.clip(i / (k - 1), a, b)
        out = out + dP[:, i : i + 1] * (math.comb(k - 1, i) * t**i * (1 - t) ** (k - 1 - i))
    return k * out * (1 + 1e-9)


def _minimize_bezier(form, ctrl_dd, target, res, ld_levels=30, K=8):
    """A half curve: float64 value-driven beam search and zoom (_zoom) on t in [0, 1/2], then a
    long-double search of every candidate on its own piece of the curve, re-parametrised on
    [0, 1] with its control points computed in double-double (a curve 1e5 times larger than the
    round is then resolved to ~1e-19 of the round, not of the curve): the pieces [t - h, t + h]
    around the zoom's sampled local minima (h its step there) and [t - 5e-8, t + 5e-8] around the
    beam's three best.  target: the target's parameters (n, R of a round; _linear_target's of a
    linear piece) per case; res: the zoom's resolution scale per case (a round's radius).
    Returns (value, a, b, u, magnitude) with the best point at t = a + u (b - a)."""
    n = ctrl_dd[0].shape[0]
    lo, hi = np.zeros(n), np.full(n, 0.5)
    P64 = ctrl_dd[0] + ctrl_dd[1]
    dP = np.linalg.norm(np.diff(P64, axis=1), axis=2)  # (n, k) hodograph norms
    # two searches: a value-driven beam (follows the sampled minima: curves with a far control
    # point, whose Lipschitz bound is useless away from the ends) and the zoom (keeps every local
    # minimum: curves much larger than the round)
    # (several crossings of a rim by a curve in a plane just above it are near-ties: the beam is
    # wider, and keeps its three best)
    vb, xb, bcentres, bvals = _beam(form, lo, hi, 8, 14, K, np.float64)
    (zc, zx, zh, _), _ = _zoom(
        form, lo, hi, lambda c, a, b: _lipschitz(dP[c], a[:, None], b[:, None])[:, 0], np.asarray(res, dtype=float)
    )
    border = np.argsort(bvals, axis=1, kind="stable")
    beam_x = [xb] + [np.take_along_axis(bcentres, border[:, q : q + 1], 1)[:, 0] for q in (1, 2) if q < border.shape[1]]
    cc = np.concatenate([zc] + [np.arange(n)] * len(beam_x))
    tc = np.concatenate([zx] + beam_x)
    hw = np.concatenate([np.maximum(zh, 5e-8)] + [np.full(n, 5e-8)] * len(beam_x))
    a = np.maximum(tc - hw, 0.0)
    b = np.minimum(tc + hw, 0.5)
    Q = _sub_bezier_dd((ctrl_dd[0][cc], ctrl_dd[1][cc]), a, b)
    m = len(cc)
    sub = _Form(
        form.name,
        "bezier",
        form.target,
        _P(ctrl=Q, **{k: v[cc] for k, v in target.items()}),
        np.zeros(m),
        np.ones(m),
        False,
        _S_GRID,
    )
    vv, uu, _, _ = _beam(
        sub, np.zeros(m, dtype=LD), np.ones(m, dtype=LD), 2, ld_levels, K, LD, start=(np.zeros((m, 1)), np.ones((m, 1)))
    )
    # the candidate itself (a sampled end point can be the best point seen)
    u0 = ((tc - a) / np.where(b > a, b - a, 1)).astype(LD)
    v0 = sub.f(u0[:, None])[:, 0]
    take0 = v0 < vv
    vv, uu = np.where(take0, v0, vv), np.where(take0, u0, uu)
    mag = sub.magnitude(uu)
    _, best, ba, bb, bu, bm = _least(n, cc, vv, a, b, uu, mag)
    return best, ba, bb, bu, bm
