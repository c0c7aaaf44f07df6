"""The screen's closed forms: point-circle, point-disk, point-arc, point-annulus and
point-linear distances in any float dtype, with double-double helpers for offsets and a
line's anchor.
"""

from __future__ import annotations

import math

import numpy as np

from .base import EPSLD, LD, RIMS, TARGET_REGION


# ---- double-double helpers (float64 arrays), for offsets and the line anchor ------------------
def _two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _quick(a, b):
    s = a + b
    return s, b - (s - a)


def _split(a):
    t = 134217729.0 * a
    hi = t - (t - a)
    return hi, a - hi


def _two_prod(a, b):
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _dd_add(x, y):
    s, e = _two_sum(x[0], y[0])
    return _quick(s, e + x[1] + y[1])


def _dd_mul(x, y):
    p, e = _two_prod(x[0], y[0])
    return _quick(p, e + (x[0] * y[1] + x[1] * y[0]))


def _dd_neg(x):
    return -x[0], -x[1]


def _dd_div(x, y):
    q1 = x[0] / y[0]
    r = _dd_add(x, _dd_neg(_dd_mul((q1, np.zeros_like(q1)), y)))
    q2 = r[0] / y[0]
    r = _dd_add(r, _dd_neg(_dd_mul((q2, np.zeros_like(q2)), y)))
    q3 = r[0] / y[0]
    s = _quick(q1, q2)
    return _dd_add(s, (q3, np.zeros_like(q3)))


def _dd_dot(x, y):
    """x, y: (hi, lo) pairs of (n, 3) arrays."""
    acc = _dd_mul((x[0][:, 0], x[1][:, 0]), (y[0][:, 0], y[1][:, 0]))
    for i in (1, 2):
        acc = _dd_add(acc, _dd_mul((x[0][:, i], x[1][:, i]), (y[0][:, i], y[1][:, i])))
    return acc


def _ld(x):
    return x[0].astype(LD) + x[1].astype(LD)


def _diff_ld(p, q):
    """p - q (float64 arrays) as long double, via the exact double-double difference."""
    return _ld(_two_sum(np.asarray(p, float), -np.asarray(q, float)))


def _ld_frame(N):
    """Unit normal n and in-plane U, V (long double): U from the coordinate axis least aligned with
    n (Gram-Schmidt), V = n x U -- the construction of the references, built independently."""
    Nl = N.astype(LD)
    Nl = Nl / np.max(np.abs(Nl), axis=1, keepdims=True)
    n = Nl / np.sqrt(np.sum(Nl * Nl, axis=1, keepdims=True))
    k = np.argmin(np.abs(n), axis=1)
    e = np.zeros_like(n)
    e[np.arange(len(k)), k] = 1
    u = e - np.sum(e * n, axis=1, keepdims=True) * n
    u = u / np.sqrt(np.sum(u * u, axis=1, keepdims=True))
    return n, u, _cross(n, u)


def _cross(a, b):
    return np.stack(
        [
            a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
            a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
            a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0],
        ],
        axis=-1,
    )


def _dot(a, b):
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def _nrm(a):
    return np.sqrt(_dot(a, a))


# ---- closed forms (any float dtype; arrays broadcast (n, k, 3) against (n, 1, 3)) -------------
def _round_dist(w, n, R, disk, with_rho=False, span=None, inner=None):
    """Distance of the points w (relative to the centre) from the round; with_rho: also their
    distance rho from its axis.  span (an arc: its unit u, v = n x u, angle and whether it is
    the whole circle, broadcast like n, n, R, R): the circle restricted to the angles [0, angle]
    from u -- the ring's distance where the angle phi of w's projection lies in the span (or w is
    on the axis), else the nearer end's (the distance to the ring's point at theta grows with
    |theta - phi| up to pi, so the nearer end in angle is the nearer in distance; both are taken,
    each a genuine point's distance)."""
    z = _dot(w, n)
    a = w - z[..., None] * n
    rho = _nrm(a)
    e = rho - R
    d = np.sqrt(z * z + e * e)
    if disk:
        d = np.where(rho <= R, np.abs(z), d)
    if inner is not None:
        # an annulus (disk=True): over its hole the inner rim's distance (docs/derivations/annulus.md (1))
        d = np.where(rho < inner, np.sqrt(z * z + (inner - rho) * (inner - rho)), d)
    if span is not None:
        u, v, ang, whole = span
        phi = np.arctan2(_dot(w, v), _dot(w, u))
        two_pi = 2 * np.arctan2(phi.dtype.type(0), phi.dtype.type(-1))
        phi = np.where(phi < 0, phi + two_pi, phi)
        off = (whole == 0) & (phi > ang) & (rho > 0)
        e0 = _nrm(w - R[..., None] * u)
        e1 = _nrm(w - R[..., None] * (np.cos(ang)[..., None] * u + np.sin(ang)[..., None] * v))
        d = np.where(off, np.minimum(e0, e1), d)
    return (d, rho) if with_rho else d


def _span(P, x1=True):
    """The span parameters of an arc target in P (None for a circle or disk), shaped for
    (n, k) points (x1) or (n,) points."""
    if "tu" not in P:
        return None
    f = _x1 if x1 else (lambda v: v)
    return f(P["tu"]), f(P["tv"]), f(P["tang"]), f(P["twhole"])


def _tdist(X, P, kind, x1=True, with_rho=False):
    """The closed-form distance of the points X from a circle, disk, arc or annulus target whose
    parameters (_rim_parts' "target": n, R, an arc's span, an annulus's inner radius Rin) are in
    P, shaped (n, k) (x1) or (n,)."""
    f = _x1 if x1 else (lambda v: v)
    inner = f(P["Rin"]) if "Rin" in P else None
    return _round_dist(X, f(P["n"]), f(P["R"]), kind in TARGET_REGION, with_rho, span=_span(P, x1), inner=inner)


def _lin_dist(w, m, mm, lo, hi):
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.where(mm > 0, _dot(w, m) / np.where(mm > 0, mm, 1), 0)
    s = np.minimum(np.maximum(s, lo), hi)
    return _nrm(w - s[..., None] * m)


class _P:
    """Per-case parameters of one formulation, in float64 and long double."""

    def __init__(self, **arrays):
        self.ld = {k: (np.asarray(v).astype(LD) if isinstance(v, np.ndarray) else v) for k, v in arrays.items()}
        self.f64 = {
            k: (np.asarray(v).astype(np.float64) if isinstance(v, np.ndarray) else v) for k, v in arrays.items()
        }

    def get(self, dtype):
        return self.ld if dtype == LD else self.f64

    def take(self, idx):
        """The parameters of cases idx (repeats allowed): one row per candidate of a flat batch."""
        out = _P.__new__(_P)
        out.ld = {k: (v[idx] if isinstance(v, np.ndarray) else v) for k, v in self.ld.items()}
        out.f64 = {k: (v[idx] if isinstance(v, np.ndarray) else v) for k, v in self.f64.items()}
        return out


def _x1(a):
    """(n, ...) -> (n, 1, ...) for broadcasting against (n, k) parameters."""
    return a[:, None]


class _Form:
    """One formulation: distance = min over a parameter x in [lo, hi] (periodic or not) of
    f(x), f evaluated as  target_closed_form(moving_point(x))."""

    def __init__(self, name, moving, target, params, lo, hi, periodic, grid):
        self.name, self.moving, self.target = name, moving, target
        self.p = params
        self.lo, self.hi, self.periodic, self.grid = lo, hi, periodic, grid

    def take(self, idx):
        """This formulation for cases idx (one row per candidate)."""
        return _Form(
            self.name,
            self.moving,
            self.target,
            self.p.take(idx),
            np.asarray(self.lo)[idx],
            np.asarray(self.hi)[idx],
            self.periodic,
            self.grid,
        )

    def points(self, x, P):
        if self.moving == "rim":
            c, s = np.cos(x), np.sin(x)
            return _x1(P["D"]) + _x1(P["Ra"])[..., None] * (c[..., None] * _x1(P["Ua"]) + s[..., None] * _x1(P["Va"]))
        if self.moving == "line":
            return _x1(P["b0"]) + self.line_s(x, P)[..., None] * _x1(P["m"])
        # bezier: Bernstein sum of control points relative to the target centre
        ctrl = P["ctrl"]  # (n, K, 3)
        k = ctrl.shape[1] - 1
        t = x
        s = 1 - t
        tp, sp = [None, t], [None, s]
        for _ in range(2, k + 1):
            tp.append(tp[-1] * t)
            sp.append(sp[-1] * s)
        out = 0
        for i in range(k + 1):
            w = tp[i] if k == i else (sp[k - i] if i == 0 else tp[i] * sp[k - i])
            c = math.comb(k, i)
            out = out + ((w * c) if c != 1 else w)[..., None] * ctrl[:, None, i, :]
        return out

    @staticmethod
    def line_s(x, P):
        """A line's parameter s at x: x itself, or S0 sinh(x) clamped to the piece's interval
        [slo, shi] (the pairs among linear pieces: uniform steps in x are steps by a constant
        ratio in s, every magnitude of s from S0 to the window's ends alike; the clamp keeps the
        rounding of sinh(asinh(lo / S0)) on the piece)."""
        if "S0" not in P:
            return x
        S0, lo, hi = (P[k] if np.ndim(x) == 1 else _x1(P[k]) for k in ("S0", "slo", "shi"))
        return np.minimum(np.maximum(S0 * np.sinh(x), lo), hi)

    def value(self, x, P):
        X = self.points(x, P)
        if self.target in RIMS:
            return _tdist(X, P, self.target)
        d = _lin_dist(X - _x1(P["tb0"]), _x1(P["tm"]), _x1(P["tmm"]), _x1(P["tlo"]), _x1(P["thi"]))
        if "mperp" not in P:
            return d
        inside, s = self.perp_inside(x, P)
        return np.where(inside, _nrm(_x1(P["cperp"]) + s[..., None] * _x1(P["mperp"])), d)

    def perp_inside(self, x, P):
        """(a line against a linear target with _perp_parts) whether the target's projection of
        the point lies inside the target by more than its rounding (there the perpendicular form
        holds), and the line's parameter s."""
        s = self.line_s(x, P)
        x1 = (lambda k: P[k]) if np.ndim(x) == 1 else (lambda k: _x1(P[k]))
        st = (x1("cu") + s * x1("mu")) / x1("uu")
        margin = 64 * EPSLD * (np.abs(x1("cu")) + np.abs(s * x1("mu"))) / x1("uu")
        return (st - margin >= x1("tlo")) & (st + margin <= x1("thi")), s

    def f(self, x):
        P = self.p.get(x.dtype.type)
        with np.errstate(invalid="ignore", over="ignore"):
            v = self.value(x, P)
        return np.where(np.isnan(v), np.inf, v)

    def f_rho(self, x):
        """f and the points' distance from the (round) target's axis, for the zoom."""
        P = self.p.get(x.dtype.type)
        if self.target not in RIMS:
            # a point or a linear piece: its local minima lie apart by about the distance itself
            # (see reference_round.bezier_other), which stands in for rho
            v = self.f(x)
            return v, v
        with np.errstate(invalid="ignore", over="ignore"):
            v, rho = _tdist(self.points(x, P), P, self.target, with_rho=True)
        return np.where(np.isnan(v), np.inf, v), rho

    def magnitude(self, x):
        """Size of the quantities that cancel at x (for the rounding slack)."""
        P = self.p.get(LD)
        X = self.points(x[:, None], P)[:, 0]
        mag = _nrm(X)
        if self.target in RIMS:
            mag = mag + P["R"]
        else:
            mag = mag + _nrm(P["tb0"])
        if "mperp" in P:
            # the perpendicular parts are double-double results (2^-100 of what they cancel:
            # |m_perp| = |m| sin(angle), 1e-17 |m| for pieces parallel within 1e-17)
            inside, s = self.perp_inside(x, P)
            full = _nrm(P["b0"]) + np.abs(s) * _nrm(P["m"])
            return np.where(
                inside,
                _nrm(P["cperp"])
                + np.abs(s) * _nrm(P["mperp"])
                + LD(2.0**-100 / (16 * EPSLD)) * (full + _nrm(P["tb0"])),
                mag + full,
            )
        if self.moving == "rim":
            mag = mag + _nrm(P["D"]) + P["Ra"]
        elif self.moving == "line":
            mag = mag + _nrm(P["b0"]) + np.abs(self.line_s(x, P)) * _nrm(P["m"])
        else:
            ctrl = P["ctrl"]
            k = ctrl.shape[1] - 1
            t = x
            mag = mag + sum(math.comb(k, i) * t**i * (1 - t) ** (k - i) * _nrm(ctrl[:, i, :]) for i in range(k + 1))
        return mag


_THETA_GRID = np.arange(512) / 512.0


def _bezier_grid():
    """Normalised samples of a half curve [0, 1/2] (the grid is scaled by the interval): uniform,
    plus samples clustered at the end the half is parametrised from."""
    u = np.linspace(0, 1, 385)
    ends = 10.0 ** -np.arange(1, 20.05, 0.1)
    return np.unique(np.concatenate([u, ends]))


_T_GRID = _bezier_grid()
_S_GRID = np.linspace(0, 1, 513)
