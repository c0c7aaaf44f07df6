"""50-digit references for Bezier curves against Bezier curves (bezier_bezier.hpp).

Nothing here uses circledist or polynomial root finding. The distance min over s, t in [0, 1] of
|A(s) - B(t)| is the smallest of

* the four edges (s or t at 0 or 1): an end point of one curve against the other curve, by
  reference_round.bezier_other (mpmath: dense sampling of the curve's t, zoomed on its speed
  bound, and golden section on every sampled local minimum);
* the interior stationary points: starts are found in double (coordinates relative to A's first
  control point): the local minima of F(s, t) = |A(s) - B(t)|^2 on a dense grid, and the sampled
  local minima of min over t of |A(s) - B(t)| (each sample's best t refined by Newton steps, so
  that a valley narrower than the grid's step is resolved), and the same with the curves'
  roles exchanged; from each, Newton steps with a backtracking line search on F in 50-digit
  arithmetic (mpmath, exact conversions of the inputs) descend to the minimum of its basin; a
  descent that leaves the square is dropped (its minimum is on an edge, above). The three best
  are then minimized once more in one parameter, g(s) = min over t of |A(s) - B(t)| by golden
  section on s (_valley): where F is nearly flat along a valley (a tangency rounded by a
  translation, nearly parallel curves) the 2-D descent can stop short of the valley's lowest
  point (2.4e-9 against 6.1e-10 for tangent arches rotated and translated by 1e8).

Every value kept is the distance between two genuine points of the curves, hence an upper bound
of the true distance, and the reference is the smallest. `scale` is the largest curve size in
the query: the larger control polygon extent (largest distance of a control point from its
curve's first one).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import List, Sequence

import numpy as np

from . import reference_kit as K
from . import reference_round as R
from .reference_store import stored

mpf = K.mpf
ctx = K.ctx
GRID = 384  # grid intervals per parameter
MAX_STARTS = 12  # grid local minima refined
NEWTON_STEPS = 400  # Newton iterations per start (tangencies converge linearly)


def curve_size(ctrl) -> float:
    pts = [K.vec(p) for p in ctrl]
    return max(float(K.norm(K.sub(p, pts[0]))) for p in pts)


def _grid_points(ctrl: np.ndarray, origin: np.ndarray, ts: np.ndarray) -> np.ndarray:
    k = len(ctrl) - 1
    rel = ctrl - origin
    out = np.zeros((len(ts), 3))
    for i in range(k + 1):
        out += math.comb(k, i) * (ts**i * (1 - ts) ** (k - i))[:, None] * rel[i]
    return out


def _grid_jet(ctrl: np.ndarray, origin: np.ndarray, ts: np.ndarray):
    """B(t), B'(t), B''(t) at many t in double (the starts only)."""
    k = len(ctrl) - 1
    rel = ctrl - origin
    d1 = k * np.diff(rel, axis=0)
    d2 = (k - 1) * np.diff(d1, axis=0) if k >= 2 else np.zeros((1, 3))
    p = _grid_points(rel, np.zeros(3), ts)
    p1 = _grid_points(d1, np.zeros(3), ts)
    p2 = _grid_points(d2, np.zeros(3), ts) if k >= 2 else np.zeros_like(p)
    return p, p1, p2


def _starts(ca: np.ndarray, cb: np.ndarray):
    """Starts for the 50-digit descents, found in double: the local minima of a dense grid of F,
    and, for each sampled s (then each sampled t), the best t of the grid moved by Newton steps to
    the closest point of the other curve, g(s) = min over t of |A(s) - B(t)|, whose sampled local
    minima seed the descents too (a valley narrower than the grid's step, two nearly parallel
    stretches, is resolved by the inner Newton steps where the grid alone sees noise)."""
    origin = ca[0]
    ts = np.linspace(0.0, 1.0, GRID + 1)
    ga = _grid_points(ca, origin, ts)
    gb = _grid_points(cb, origin, ts)
    f = ((ga[:, None, :] - gb[None, :, :]) ** 2).sum(axis=2)
    padded = np.pad(f, 1, constant_values=np.inf)
    local = np.ones_like(f, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                local &= f <= padded[1 + di : 1 + di + f.shape[0], 1 + dj : 1 + dj + f.shape[1]]
    idx = np.argwhere(local)
    idx = idx[np.argsort(f[local])][:MAX_STARTS]
    out = [(ts[i], ts[j]) for i, j in idx]
    for moving, other, fm, swap in ((ca, cb, f, False), (cb, ca, f.T, True)):
        pm = _grid_points(moving, origin, ts)
        u = ts[np.argmin(fm, axis=1)].copy()
        for _ in range(30):  # Newton on |P - Q(u)|^2 in u, for every sample at once
            q, q1, q2 = _grid_jet(other, origin, u)
            r = q - pm
            slope = (r * q1).sum(axis=1)
            curvature = (q1 * q1).sum(axis=1) + (r * q2).sum(axis=1)
            step = np.where(curvature > 0, -slope / np.where(curvature > 0, curvature, 1), 0.0)
            u = np.clip(u + step, 0.0, 1.0)
        g = ((_grid_points(other, origin, u) - pm) ** 2).sum(axis=1)
        inner = np.flatnonzero((g[1:-1] <= g[:-2]) & (g[1:-1] <= g[2:])) + 1
        inner = inner[np.argsort(g[inner])][:MAX_STARTS]
        out += [((u[i], ts[i]) if swap else (ts[i], u[i])) for i in inner]
    return out


def _jet(pts: List[K.Vec], t):
    """B(t), B'(t), B''(t) by de Casteljau on the curve and its hodographs, in mpmath."""
    k = len(pts) - 1

    def casteljau(q, x):
        q = list(q)
        while len(q) > 1:
            q = [K.add(q[i], K.scale(x, K.sub(q[i + 1], q[i]))) for i in range(len(q) - 1)]
        return q[0] if q else (mpf(0), mpf(0), mpf(0))

    d1 = [K.scale(k, K.sub(pts[i + 1], pts[i])) for i in range(k)]
    d2 = [K.scale(k - 1, K.sub(d1[i + 1], d1[i])) for i in range(k - 1)]
    zero = (mpf(0), mpf(0), mpf(0))
    return casteljau(pts, t), casteljau(d1, t) if d1 else zero, casteljau(d2, t) if d2 else zero


def _descend(pa: List[K.Vec], pb: List[K.Vec], s, t):
    """Newton on F(s, t) = |A(s) - B(t)|^2 from (s, t), each step halved until F decreases;
    None when it leaves [0, 1]^2 (an edge minimum). Returns (distance, s, t)."""

    def state(x, y):
        a, a1, a2 = _jet(pa, x)
        b, b1, b2 = _jet(pb, y)
        r = K.sub(a, b)
        f = K.dot(r, r)
        g = (K.dot(r, a1), -K.dot(r, b1))
        h = (K.dot(a1, a1) + K.dot(r, a2), -K.dot(a1, b1), K.dot(b1, b1) - K.dot(r, b2))
        return f, g, h

    s, t = mpf(s), mpf(t)
    f, g, h = state(s, t)
    for _ in range(NEWTON_STEPS):
        det = h[0] * h[2] - h[1] * h[1]
        if h[0] > 0 and det > 0:
            ds = (-g[0] * h[2] + g[1] * h[1]) / det
            dt = (-g[1] * h[0] + g[0] * h[1]) / det
        else:  # not convex here: steepest descent, scaled to the curvature's size
            scale_h = abs(h[0]) + abs(h[2]) + mpf("1e-30")
            ds, dt = -g[0] / scale_h, -g[1] / scale_h
        step = 1
        moved = False
        for _ in range(80):
            ns, nt = s + step * ds, t + step * dt
            if 0 <= ns <= 1 and 0 <= nt <= 1:
                nf, ng, nh = state(ns, nt)
                if nf < f:
                    s, t, f, g, h = ns, nt, nf, ng, nh
                    moved = True
                    break
            step /= 2
        if not moved:
            break
        if abs(step * ds) + abs(step * dt) < mpf("1e-45"):
            break
    # Held at the square's edge with the slope pointing out: an edge minimum, not ours.
    for x, gx in ((s, g[0]), (t, g[1])):
        if (x <= mpf("1e-30") and gx > 0) or (x >= 1 - mpf("1e-30") and gx < 0):
            return None
    return ctx.sqrt(f), s, t


def _nearest_t(pb: List[K.Vec], p, t):
    """The t in [0, 1] nearest B(t) to p, by Newton on |p - B(t)|^2 from t (50 digits), with the
    ends compared: (squared distance, t)."""

    def f(x):
        r = K.sub(p, _jet(pb, x)[0])
        return K.dot(r, r)

    t = mpf(t)
    for _ in range(60):
        b, b1, b2 = _jet(pb, t)
        r = K.sub(p, b)
        slope, curvature = -K.dot(r, b1), K.dot(b1, b1) - K.dot(r, b2)
        if not curvature > 0:
            break
        nt = min(max(t - slope / curvature, mpf(0)), mpf(1))
        if abs(nt - t) < mpf("1e-45"):
            t = nt
            break
        t = nt
    return min((f(x), x) for x in (t, mpf(0), mpf(1)))


def _valley(pa: List[K.Vec], pb: List[K.Vec], s, t, width=mpf("1e-2")):
    """The lowest point near (s, t) of g(s) = min over t of |A(s) - B(t)|: golden section on s at
    50 digits (the bracket widened while the minimum sits on its inner edge), each g by
    _nearest_t. Where F is nearly flat along a valley (a tangency, nearly parallel curves) the
    2-D descent can stop short of the valley's lowest point; one parameter cannot. Returns
    (distance, s, t)."""
    memo = {}

    def g(x):
        if x not in memo:
            memo[x] = _nearest_t(pb, R.bezier_point(pa, x), t)
        return memo[x][0]

    s = mpf(s)
    for _ in range(8):
        lo, hi = max(mpf(0), s - width), min(mpf(1), s + width)
        golden = (ctx.sqrt(5) - 1) / 2
        a, b = lo, hi
        c, d = b - golden * (b - a), a + golden * (b - a)
        for _ in range(160):
            if g(c) < g(d):
                b = d
            else:
                a = c
            c, d = b - golden * (b - a), a + golden * (b - a)
            if b - a < mpf("1e-40"):
                break
        s = (a + b) / 2
        if not ((lo > 0 and s - lo < width / 100) or (hi < 1 and hi - s < width / 100)):
            break
        width *= 8
    value, t = _nearest_t(pb, R.bezier_point(pa, s), t)
    return ctx.sqrt(value), s, t


@dataclass
class BezierPair:
    value: object
    s: object
    t: object
    pa: object
    pb: object


@dataclass(repr=False)
class BezierReference:
    distance: object
    pairs: list
    scale: float

    def __float__(self):
        return float(self.distance)

    def __repr__(self):
        return f"BezierReference({K.ctx.nstr(self.distance, 20)}, scale={self.scale:.3g})"


@stored
def bezier_bezier(ctrl_a: Sequence, ctrl_b: Sequence) -> BezierReference:
    pa = [K.vec(p) for p in ctrl_a]
    pb = [K.vec(p) for p in ctrl_b]
    pairs = []
    # The edges.
    for which, s in ((0, 0), (len(pa) - 1, 1)):
        ref = R.bezier_other(ctrl_b, "point", ctrl_a[which])
        for q in ref.pairs[:1]:
            pairs.append(BezierPair(q.value, mpf(s), q.t, q.pb, q.pa))
    for which, t in ((0, 0), (len(pb) - 1, 1)):
        ref = R.bezier_other(ctrl_a, "point", ctrl_b[which])
        for q in ref.pairs[:1]:
            pairs.append(BezierPair(q.value, q.t, mpf(t), q.pa, q.pb))
    # The interior: starts from the grid (below), descended in 50 digits.
    edges = len(pairs)
    if len(pa) > 1 and len(pb) > 1:
        for s0, t0 in _starts(np.array(ctrl_a, dtype=float), np.array(ctrl_b, dtype=float)):
            found = _descend(pa, pb, mpf(s0), mpf(t0))
            if found is None:
                continue
            value, s, t = found
            pairs.append(BezierPair(value, s, t, R.bezier_point(pa, s), R.bezier_point(pb, t)))
        # The best interior pairs once more, in one parameter along their valley (_valley).
        interior = sorted(pairs[edges:], key=lambda q: q.value)[:3]
        for q in interior:
            value, s, t = _valley(pa, pb, q.s, q.t)
            pairs.append(BezierPair(value, s, t, R.bezier_point(pa, s), R.bezier_point(pb, t)))
    pairs.sort(key=lambda q: q.value)
    return BezierReference(pairs[0].value, pairs, max(curve_size(ctrl_a), curve_size(ctrl_b)))
