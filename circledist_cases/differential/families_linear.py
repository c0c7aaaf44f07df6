"""Case families of the pairs without a round: points, lines, rays, segments and Bezier
curves.
"""

from __future__ import annotations

import math

import numpy as np

from .frames import EZ, _Frame, _bezier_through, _elevate, _logu, _npts, _perp, _radius, _rot, _tiny, _unit
from .families_round import _fam_far_translated, _far_piece


# ---- families of the pairs without a round: points, lines, rays, segments and Bezier curves ----
# (S: the scene's size; the pieces' local geometry in a _Frame as above)
EX = np.array([1.0, 0.0, 0.0])
EY = np.array([0.0, 1.0, 0.0])


def _size(rng, exact):
    return _radius(rng, exact)


def _fam_linear_random(rng, ka, kb):
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    b = fr.linear(kb, rng.normal(size=3) * S, _unit(rng), S)
    if ka == "bezier":
        return fr.bezier([rng.normal(size=3) * 1.5 * S for _ in range(_npts(rng))]), b
    return fr.linear(ka, rng.normal(size=3) * S, _unit(rng), S), b


def _parallel_pair(rng, exact, S):
    """Local (X_a, d_a, X_b, d_b) of two nearly parallel pieces: directions 1e-12..1e-2 rad
    apart (or parallel), crossing, 1e-15..1e-9 x S apart (along their common normal) or
    collinear."""
    mode = str(rng.choice(["cross", "gap", "collinear", "parallel"]))
    angle = 0.0 if mode in ("collinear", "parallel") else _logu(rng, -12, -2)
    gap = {"cross": 0.0, "collinear": 0.0}.get(mode, _logu(rng, -15, -9) * S)
    sgn = float(rng.choice([-1.0, 1.0]))
    d_b = sgn * (math.cos(angle) * EX + math.sin(angle) * EY)
    # the crossing point (or the place of nearest approach) anywhere near the pieces
    X_b = (0.0 if exact else rng.uniform(-2, 2) * S) * EX + gap * EZ
    return np.zeros(3), EX, X_b, d_b


def _fam_near_parallel(rng, ka, kb):
    """Nearly parallel lines, rays and segments: crossing at 1e-12..1e-2 rad, passing
    1e-15..1e-9 apart, parallel a hair apart, collinear (overlapping or not)."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    X_a, d_a, X_b, d_b = _parallel_pair(rng, fr.exact, S)
    return fr.linear(ka, X_a, d_a, S), fr.linear(kb, X_b, d_b, S)


def _fam_linear_far_origin(rng, ka, kb):
    """Line origins / segment ends 1e6..1e12 x S along the pieces (one or both), on random or
    nearly parallel pieces; a Bezier curve against such a line, ray or segment."""
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    if ka == "bezier":
        X, d = rng.normal(size=3) * S, _unit(rng)
        ctrl = _bezier_through(rng, X + _tiny(rng, -15, -1) * S * _perp(rng, d), S, max(2, _npts(rng)))
        return fr.bezier(ctrl), _far_piece(rng, fr, kb, X, d, S)
    if rng.random() < 0.5:
        X_a, d_a, X_b, d_b = _parallel_pair(rng, False, S)
    else:
        X_a, d_a, X_b, d_b = rng.normal(size=3) * S, _unit(rng), rng.normal(size=3) * S, _unit(rng)
    which = int(rng.integers(0, 3))  # far: a, b or both
    a = _far_piece(rng, fr, ka, X_a, d_a, S) if which != 1 else fr.linear(ka, X_a, d_a, S)
    b = _far_piece(rng, fr, kb, X_b, d_b, S) if which != 0 else fr.linear(kb, X_b, d_b, S)
    return a, b


def _fam_zero_length(rng, ka, kb):
    """Zero-length segments (both ends equal) against a point, line, ray, segment (zero-length
    or not) or curve, at 0, tiny or ordinary distances."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    P = np.zeros(3)
    h = _tiny(rng, -16, 0, 0.3) * S
    Q = P + h * (EZ if fr.exact else _unit(rng))  # the other piece passes through Q
    zero = fr.pos(P)
    if ka == "bezier":
        return fr.bezier(_bezier_through(rng, Q, S, _npts(rng))), zero + zero
    if ka == "segment" and rng.random() < 0.5:  # both zero-length
        return fr.pos(Q) + fr.pos(Q), zero + zero
    if ka == "segment":  # the first one zero-length, the other not
        return zero + zero, fr.linear(kb, Q, EX if fr.exact else _unit(rng), S)
    return fr.linear(ka, Q, EX if fr.exact else _unit(rng), S), zero + zero


def _fam_on_piece(rng, ka, kb):
    """A point of one piece as the other's point, ray origin or segment end (computed exactly in
    exact frames), and segment ends / ray origins exactly at, or 1e-16..1e-6 x S off, the other
    piece's closest point (the piece leaving it at a right or an oblique angle)."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    b = fr.linear(kb, np.zeros(3), EX, S)  # b along local x through 0
    c = fr.param(-1, 1) * S
    if kb == "segment" and rng.random() < 0.3:  # at b's end
        c = float(np.dot(np.asarray(b[3:6]) - fr.C, fr.Q[:, 0])) if fr.exact else c
    h = 0.0 if rng.random() < 0.5 else _tiny(rng, -16, -6, 0) * S
    E = c * EX + h * EZ
    side = EZ if h or fr.exact else _perp(rng, EX)
    d = side if rng.random() < 0.5 else _rot(side, np.cross(EX, side), -rng.uniform(0.2, 1.4))
    L = fr.dlen() * S
    if ka == "point":
        return fr.pos(E), b
    if ka == "segment":
        return fr.pos(E) + fr.pos(E + L * d), b
    if ka == "ray":
        return fr.pos(E) + fr.dirv(d, fr.dlen()), b
    return fr.pos(E) + fr.dirv(d, fr.dlen()), b


def _fam_bezier_tangent_line(rng, ka, kb):
    """A line, ray or segment tangent to a curve at an interior point (exactly or 1e-16..1e-4 x S
    off, on either side), or parallel to the curve's end tangent (through the end, or beside it)."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    h = _tiny(rng, -16, -4, 0.4) * S
    if rng.random() < 0.6:  # the apex of a symmetric arch (degree-elevated): tangent EX at X = 0
        L = S * rng.uniform(0.3, 2)
        delta = EY * S * rng.uniform(0.05, 1)
        ctrl = _elevate([-L * EX + delta, -delta, L * EX + delta], max(3, _npts(rng)))
        return fr.bezier(ctrl), fr.linear(kb, h * EY, EX, S)
    ctrl = [rng.normal(size=3) * S for _ in range(max(3, _npts(rng)))]
    d0 = ctrl[1] - ctrl[0]
    d0 = d0 / np.linalg.norm(d0)
    X = ctrl[0] + h * _perp(rng, d0)
    return fr.bezier(ctrl), fr.linear(kb, X, -d0 if rng.random() < 0.5 else d0, S)


def _fam_bezier_crossing(rng, ka, kb):
    """A line, ray or segment crossing a curve (exactly at a rounded curve point, or 1e-16..1e-6
    x S beside it), at any angle."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    X = np.zeros(3)
    ctrl = _bezier_through(rng, X, S, max(2, _npts(rng)))
    Y = X + _tiny(rng, -16, -6, 0.4) * S * _unit(rng)
    return fr.bezier(ctrl), fr.linear(kb, Y, _unit(rng), S)


def _fam_bezier_far_control_linear(rng, ka, kb):
    """A curve with one control point 1e6..1e12 x S away against a point, line, ray or segment
    near its other control points."""
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    ctrl = [rng.normal(size=3) * 1.5 * S for _ in range(_npts(rng))]
    ctrl[int(rng.integers(0, len(ctrl)))] = _unit(rng) * _logu(rng, 6, 12) * S
    return fr.bezier(ctrl), fr.linear(kb, rng.normal(size=3) * S, _unit(rng), S)


def _fam_bezier_large_linear(rng, ka, kb):
    """A curve 1e2..1e5 times larger than the other piece (a segment of length ~S, a point, a
    line or ray near it), passing through a point on, near or beside that piece."""
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    d = _unit(rng)
    b = fr.linear(kb, np.zeros(3), d, S)
    X = [
        rng.uniform(0, 1) * S * d,
        rng.uniform(0, 1) * S * d + _tiny(rng, -14, -6) * S * _perp(rng, d),
        rng.normal(size=3) * 2 * S,
    ][int(rng.integers(0, 3))]
    return fr.bezier(_bezier_through(rng, X, _logu(rng, 2, 5) * S, _npts(rng))), b


_LINEAR_TRANSLATED_BASES = (
    "linear_random",
    "near_parallel",
    "zero_length",
    "on_piece",
    "bezier_tangent_line",
    "bezier_crossing",
)


def _fam_linear_far_translated(rng, ka, kb):
    return _fam_far_translated(rng, ka, kb, bases=_LINEAR_TRANSLATED_BASES)
