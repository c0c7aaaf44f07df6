"""Random frames, radii and curves the case families draw from."""

from __future__ import annotations

import math

import numpy as np


def _unit(rng):
    v = rng.normal(size=3)
    return v / np.linalg.norm(v)


def _perp(rng, n):
    """A random unit vector orthogonal to the unit vector n."""
    v = rng.normal(size=3)
    v = v - np.dot(v, n) * n
    return v / np.linalg.norm(v)


def _rot(v, axis, angle):
    """v rotated about the unit axis by angle (Rodrigues)."""
    v, axis = np.asarray(v, float), np.asarray(axis, float)
    return v * math.cos(angle) + np.cross(axis, v) * math.sin(angle) + axis * np.dot(axis, v) * (1 - math.cos(angle))


def _logu(rng, lo, hi):
    return float(10 ** rng.uniform(lo, hi))


def _tiny(rng, lo=-16, hi=-4, zero=0.3):
    """0 with probability `zero`, else +-10^U(lo, hi)."""
    if rng.random() < zero:
        return 0.0
    return float(rng.choice([-1.0, 1.0])) * _logu(rng, lo, hi)


EZ = np.array([0.0, 0.0, 1.0])


class _Frame:
    """Local coordinates (x, y, z) -> world C + x U + y V + z N.  Exact frames are signed axis
    permutations with dyadic centres (so special geometry stays exact in binary64); the others are
    random rotations (special geometry then holds up to rounding)."""

    def __init__(self, rng, exact=None, scale=1.0):
        self.rng = rng
        self.exact = bool(rng.random() < 0.5) if exact is None else exact
        if self.exact:
            perm = rng.permutation(3)
            signs = rng.choice([-1.0, 1.0], 3)
            M = np.zeros((3, 3))
            M[np.arange(3), perm] = signs
            self.Q = M.T  # columns U, V, N
            self.C = rng.integers(-8, 9, 3) / 4.0 * scale
            self.nlen = 2.0 ** int(rng.integers(-3, 4))
        else:
            Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
            self.Q = Q
            self.C = rng.normal(size=3) * scale
            self.nlen = _logu(rng, -1, 1)

    def pos(self, p):
        return [float(x) for x in self.C + self.Q @ np.asarray(p, float)]

    def dirv(self, d, length=1.0):
        return [float(x) for x in (self.Q @ np.asarray(d, float)) * length]

    def dlen(self):
        return 2.0 ** int(self.rng.integers(-2, 3)) if self.exact else _logu(self.rng, -1, 1)

    def param(self, lo, hi):
        """A scalar in [lo, hi]: dyadic in exact frames."""
        if self.exact:
            return float(self.rng.integers(int(lo * 8), int(hi * 8) + 1)) / 8.0
        return float(self.rng.uniform(lo, hi))

    def round(self, c, n, r):
        return self.pos(c) + self.dirv(np.asarray(n, float) / np.linalg.norm(n), self.nlen) + [float(r)]

    def linear(self, kind, X, d, spread):
        """A point/line/ray/segment through the local point X with local unit direction d."""
        X, d = np.asarray(X, float), np.asarray(d, float)
        if kind == "point":
            return self.pos(X)
        if kind == "line":
            o = X + self.param(-2, 2) * spread * d
            return self.pos(o) + self.dirv(d, self.dlen())
        if kind == "ray":
            o = X - self.param(-0.5, 3) * spread * d
            return self.pos(o) + self.dirv(d, self.dlen())
        s0, s1 = self.param(-0.5, 3) * spread, self.param(-0.5, 3) * spread
        return self.pos(X - s0 * d) + self.pos(X + s1 * d)

    def bezier(self, ctrl):
        return [self.pos(p) for p in ctrl]


def _radius(rng, exact):
    return float(rng.choice([0.5, 0.75, 1.0, 1.5, 2.0])) if exact else _logu(rng, -0.5, 0.5)


def _in_plane(rng, exact, r=1.0):
    """(radial, tangent) in-plane unit vectors at a random (exact: axis) angle."""
    th = 0.0 if exact else rng.uniform(0, 2 * math.pi)
    return np.array([math.cos(th), math.sin(th), 0.0]), np.array([-math.sin(th), math.cos(th), 0.0])


def _elevate(ctrl, k_total):
    """Degree elevation of a Bezier control polygon to k_total control points (same curve up to
    rounding)."""
    P = [np.asarray(p, float) for p in ctrl]
    while len(P) < k_total:
        k = len(P)  # degree k-1 -> k
        Q = [P[0]]
        for i in range(1, k):
            Q.append(i / k * P[i - 1] + (1 - i / k) * P[i])
        Q.append(P[-1])
        P = Q
    return P


def _bezier_through(rng, X, size, npts, t0=None):
    """Random control points of extent `size` around X, shifted so that B(t0) = X."""
    P = [X + size * rng.normal(size=3) for _ in range(npts)]
    t0 = rng.uniform(0.1, 0.9) if t0 is None else t0
    k = npts - 1
    B = sum(math.comb(k, i) * t0**i * (1 - t0) ** (k - i) * P[i] for i in range(npts))
    return [p + (X - B) for p in P]


def _npts(rng):
    return int(rng.integers(2, 9))


# ---- round-round helpers (local frame of the first round: centre 0, normal +z) -------------
def _tangent_round(rng, Ra, Rb, exact, phi=None):
    """(centre, normal) of a round of radius Rb whose rim touches A's rim (centre 0, normal z,
    radius Ra) at one point with a common tangent; phi = 0 internal coplanar, pi external
    coplanar, pi/2 standing on the rim."""
    r, t = _in_plane(rng, exact)
    X = Ra * r
    if phi is None:
        phi = float(rng.choice([0.0, math.pi, math.pi / 2, rng.uniform(0, 2 * math.pi)]))
    w = math.cos(phi) * (-r) + math.sin(phi) * EZ
    return X + Rb * w, np.cross(t, w), w
