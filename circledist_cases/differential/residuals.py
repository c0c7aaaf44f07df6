"""Residuals: how far a point is from a shape (long double, offsets in double-double)."""

from __future__ import annotations

import math

import numpy as np

from .base import EPSLD, LD, RIMS
from .closed_forms import _diff_ld, _lin_dist, _nrm, _tdist, _two_sum
from .screen import _linear_target, _rim_parts


# ---- residuals: how far a point is from a shape (long double, offsets in double-double) -------
def residuals(kind, data, pts, params=None):
    """(distance of each point (n, 3) (float64 or long double) from its shape (n cases of `kind`),
    a bound on the long-double evaluation error of that distance).  A Bezier point p is measured
    against B(param) (its own parameter, which must lie in [0, 1]) as |sum_i b_i(t) (p - P_i)|,
    error ~eps sum_i b_i |p - P_i|: small wherever p is near the curve, even for a control point
    1e12 away or a curve translated by 1e12."""
    pts = np.asarray(pts)
    P = pts.astype(LD)
    if kind == "bezier":
        ctrl = np.asarray(data, dtype=float)
        t = np.asarray(params, dtype=LD)
        k = ctrl.shape[1] - 1
        s = 1 - t
        w, mag = 0, 0
        for i in range(k + 1):
            b = math.comb(k, i) * t**i * s ** (k - i)
            d = _pt_minus(P, ctrl[:, i, :])
            w = w + b[:, None] * d
            mag = mag + b * _nrm(d)
        bad = ~((t >= 0) & (t <= 1))
        return np.where(bad, LD(np.inf), _nrm(w)), 16 * LD(EPSLD) * mag
    data = np.asarray(data, dtype=float)
    if kind in RIMS:
        parts = _rim_parts(kind, data)
        tgt = parts["target"]
        w = _pt_minus(P, data[:, :3])
        R = data[:, 6].astype(LD)
        d = _tdist(w[:, None], tgt, kind)[:, 0]
        return d, 16 * LD(EPSLD) * (_nrm(w) + R)
    C0 = data[:, :3]
    w = _pt_minus(P, C0)
    if kind == "point":
        return _nrm(w), 16 * LD(EPSLD) * _nrm(w)
    tgt = _linear_target(kind, data, C0)
    d = _lin_dist(
        w[:, None] - tgt["tb0"][:, None],
        tgt["tm"][:, None],
        tgt["tmm"][:, None],
        tgt["tlo"][:, None],
        tgt["thi"][:, None],
    )[:, 0]
    return d, 16 * LD(EPSLD) * (_nrm(w) + _nrm(tgt["tb0"]))


def _pt_minus(P, C):
    """P (long double or float64 points) - C (float64), accurately."""
    if P.dtype == LD:
        hi = P.astype(np.float64)
        lo = (P - hi.astype(LD)).astype(np.float64)
        d = _two_sum(hi, -C)
        return d[0].astype(LD) + (d[1].astype(LD) + lo.astype(LD))
    return _diff_ld(P, C)
