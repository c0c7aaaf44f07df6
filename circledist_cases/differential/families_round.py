"""Case families of the pairs with a circle or disk."""

from __future__ import annotations

import math

import numpy as np

from .base import FAMILIES, ROUND
from .frames import (
    EZ,
    _Frame,
    _bezier_through,
    _elevate,
    _in_plane,
    _logu,
    _npts,
    _perp,
    _radius,
    _rot,
    _tangent_round,
    _tiny,
    _unit,
)


# ---- families --------------------------------------------------------------------------------
def _fam_random(rng, ka, kb):
    fr = _Frame(rng, exact=False)
    Rb = _radius(rng, False)
    b = fr.round(np.zeros(3), EZ, Rb)
    if ka in ROUND:
        Ra = _radius(rng, False)
        a = fr.round(rng.normal(size=3) * 0.75 * (Ra + Rb), _unit(rng), Ra)
    elif ka == "bezier":
        a = fr.bezier([rng.normal(size=3) * 1.5 * Rb for _ in range(_npts(rng))])
    else:
        a = fr.linear(ka, rng.normal(size=3) * 1.5 * Rb, _unit(rng), Rb)
    return a, b


def _fam_tangent(rng, ka, kb):
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    if ka in ROUND:
        Ra = _radius(rng, ex)
        h = _tiny(rng, -16, -6) * max(Ra, Rb)
        mode = int(rng.integers(0, 3 if "disk" in (ka, kb) else 2))
        if mode == 2:
            # a rim touching the disk's face at an interior point (the disk is local, centre 0)
            disk_is_b = kb == "disk"
            Rd, Rr = (Rb, Ra) if disk_is_b else (Ra, Rb)
            r, t = _in_plane(rng, ex)
            P = r * Rd * fr.param(0, 0.875)
            e = _perp(rng, EZ) if not ex else np.array([1.0, 0.0, 0.0])
            c, n = P + (Rr + abs(h)) * EZ, np.cross(EZ, e)
            other = fr.round(c, n, Rr)
            disk = fr.round(np.zeros(3), EZ, Rd)
            return (other, disk) if disk_is_b else (disk, other)
        c, n, w = _tangent_round(rng, Ra, Rb, ex)
        return fr.round(np.zeros(3), EZ, Ra), fr.round(c + h * w, n, Rb)
    b = fr.round(np.zeros(3), EZ, Rb)
    r, t = _in_plane(rng, ex)
    X = Rb * r
    h = _tiny(rng) * Rb
    mode = int(rng.integers(0, 4 if kb == "disk" else 3))
    if ka == "point":
        return fr.pos(X + h * (_unit(rng) if not ex else r)), b
    if mode == 0:  # in-plane tangent, moved radially by h
        X, d = X + h * r, t
    elif mode == 1:  # tangent, lifted by |h|
        X, d = X + abs(h) * EZ, t
    elif mode == 2:  # through the rim point, orthogonal to the radius
        psi = rng.uniform(0.1, 1.4)
        X, d = X + h * r, math.cos(psi) * t + math.sin(psi) * EZ
    else:  # touching the disk's face from above
        X = r * Rb * fr.param(0, 0.875) + abs(h) * EZ
        d = t
    if ka == "bezier":
        npts = max(3, _npts(rng))
        L = Rb * rng.uniform(0.3, 2)
        away = EZ if mode in (1, 3) else (r if mode != 2 else r)
        delta = away * Rb * rng.uniform(0.05, 1)
        ctrl = _elevate([X - L * d + delta, X - delta, X + L * d + delta], npts)
        return fr.bezier(ctrl), b
    return fr.linear(ka, X, d, Rb), b


_RHO_CHOICES = ("zero", "R", "R(1+e)", "inside", "outside", "tiny", "huge")


def _fam_axis(rng, ka, kb):
    """Lines, rays, segments on and nearly parallel to the axis (tilt 0 or 1e-16..1e-10 rad), at
    any offset from the axis, including exactly at the radius; points on / near the axis."""
    fr = _Frame(rng)
    ex = fr.exact
    R = _radius(rng, ex)
    b = fr.round(np.zeros(3), EZ, R)
    kind = rng.choice(_RHO_CHOICES)
    rho = {
        "zero": 0.0,
        "R": R,
        "R(1+e)": R * (1 + _tiny(rng, -16, -8, 0)),
        "inside": R * rng.uniform(0, 1),
        "outside": R * rng.uniform(1, 3),
        "tiny": R * _logu(rng, -12, -3),
        "huge": R * _logu(rng, 0, 3),
    }[kind]
    beta = 0.0 if ex else rng.uniform(0, 2 * math.pi)
    X = np.array([rho * math.cos(beta), rho * math.sin(beta), 0.0])
    if ka == "point":
        return fr.pos(X + fr.param(-2, 2) * R * EZ), b
    psi = 0.0 if rng.random() < 0.35 else _logu(rng, -16, -10)
    alpha = 0.0 if ex else rng.uniform(0, 2 * math.pi)
    d = np.array([math.sin(psi) * math.cos(alpha), math.sin(psi) * math.sin(alpha), math.cos(psi)])
    if rng.random() < 0.5:
        d = -d
    return fr.linear(ka, X, d, R), b


def _fam_shadow_center(rng, ka, kb):
    """Lines, rays and segments whose shadow on the round's plane crosses the centre (exactly, or
    1e-16..1e-12 radii beside it), tilted from the plane by 1e-4..1 rad, at heights 1e-6..2
    radii: the line's distance then has a second local minimum over the ring, mirroring the
    global one, which rays and segments starting between the two hold (a ray from within a
    radius of the centre's shadow, toward it or away)."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    b = fr.round(np.zeros(3), EZ, R)
    alpha = 0.0 if fr.exact else rng.uniform(0, 2 * math.pi)
    psi = _logu(rng, -4, 0) * float(rng.choice([-1.0, 1.0]))
    along = np.array([math.cos(alpha), math.sin(alpha), 0.0])
    across = np.array([-math.sin(alpha), math.cos(alpha), 0.0])
    d = math.cos(psi) * along + math.sin(psi) * EZ
    height = R * (rng.uniform(0.1, 2) if rng.random() < 0.7 else _logu(rng, -6, -1))
    X = height * EZ + _tiny(rng, -16, -12, 0.6) * R * across + fr.param(-1, 1) * R * d
    if rng.random() < 0.5:
        d = -d
    return fr.linear(ka, X, d, R / 4), b


def _fam_piece_near_plane(rng, ka, kb):
    """Lines, rays and segments nearly in the round's plane: at heights 1e-12..1e-6 radii,
    parallel to it or tilted by up to 1e-9. The line's minimum over the ring is then nearly tied
    with its mirror image, where closest_points takes its pair from the general path and must
    keep distance()'s value (7112 of 50,000 such segments disagreed by 1-2 ulps before)."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    b = fr.round(np.zeros(3), EZ, R)
    r, t = _in_plane(rng, fr.exact)
    height = _logu(rng, -12, -6) * R * float(rng.choice([-1.0, 1.0]))
    X = r * fr.param(0, 2) * R + height * EZ
    d = t + _tiny(rng, -12, -9, 0.5) * EZ
    return fr.linear(ka, X, d / np.linalg.norm(d), R), b


def _fam_coplanar(rng, ka, kb):
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    b = fr.round(np.zeros(3), EZ, Rb)
    r, t = _in_plane(rng, ex)
    if ka in ROUND:
        Ra = Rb * float(rng.choice([1.0, 0.5, 2.0])) if ex else Rb * rng.uniform(0.1, 3)
        c = r * fr.param(0, 1.5) * (Ra + Rb)
        n = EZ * float(rng.choice([-1.0, 1.0]))
        return fr.round(c, n, Ra), b
    X = r * fr.param(0, 2) * Rb
    if ka == "bezier":
        ctrl = [np.array([*(rng.normal(size=2) * 1.5 * Rb), 0.0]) for _ in range(_npts(rng))]
        return fr.bezier(ctrl), b
    return fr.linear(ka, X, t if rng.random() < 0.5 else _perp(rng, EZ), Rb), b


def _tilted_normal(rng, exact):
    psi = float(rng.choice([0.0, 1e-9, _logu(rng, -12, -1), rng.uniform(0, math.pi / 2), math.pi / 2]))
    axis = np.array([1.0, 0.0, 0.0]) if exact else _perp(rng, EZ)
    return _rot(EZ, axis, psi), psi


def _fam_concentric(rng, ka, kb, offset=0.0):
    fr = _Frame(rng)
    ex = fr.exact and offset == 0.0
    Rb = _radius(rng, ex)
    b = fr.round(np.zeros(3), EZ, Rb)
    off = offset * Rb * _unit(rng)
    if ka in ROUND:
        n, _ = _tilted_normal(rng, ex)
        Ra = Rb * float(rng.choice([1.0, 1.0 + _tiny(rng, -15, -6, 0), rng.uniform(0.2, 3)]))
        return fr.round(off, n, Ra), b
    if ka == "point":
        if not offset:
            off = np.zeros(3) if rng.random() < 0.7 else _tiny(rng, -15, -6, 0) * Rb * _unit(rng)
        return fr.pos(off), b
    if ka == "bezier":
        npts = _npts(rng)
        half = [rng.normal(size=3) * Rb for _ in range((npts + 1) // 2)]
        ctrl = half[: npts // 2] + ([np.zeros(3)] if npts % 2 else []) + [-p for p in reversed(half[: npts // 2])]
        return fr.bezier([p + off for p in ctrl]), b
    n, psi = _tilted_normal(rng, ex)
    d = (
        _rot(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]), -psi)
        if ex
        else math.cos(psi) * _perp(rng, EZ) + math.sin(psi) * EZ
    )
    d = d / np.linalg.norm(d)
    return fr.linear(ka, off - np.dot(off, d) * d, d, Rb), b


def _fam_near_concentric(rng, ka, kb):
    return _fam_concentric(rng, ka, kb, offset=_logu(rng, -15, -6))


def _translate(kind, data, T):
    if kind == "bezier":
        return [[float(x) for x in np.asarray(p) + T] for p in data]
    data = list(data)
    npos = {"point": 3, "line": 3, "ray": 3, "segment": 6, "circle": 3, "disk": 3, "arc": 3, "annulus": 3}[kind]
    for i in range(npos):
        data[i] = float(data[i] + T[i % 3])
    return data


_TRANSLATED_BASES = ("random", "tangent", "coplanar", "concentric", "axis", "near_touching", "parallel_height")


def _fam_far_translated(rng, ka, kb, bases=_TRANSLATED_BASES):
    bases = [f for f in bases if (ka, kb) in FAMILIES[f][0]]
    base = str(rng.choice(bases))
    a, b = FAMILIES[base][1](rng, ka, kb)
    if rng.random() < 0.3:
        T = np.zeros(3)
        T[rng.integers(0, 3)] = float(rng.choice([-1.0, 1.0])) * _logu(rng, 6, 12)
    else:
        T = _unit(rng) * _logu(rng, 6, 12)
    return _translate(ka, a, T), _translate(kb, b, T)


def _interesting_line(rng, fr, R, kb):
    """A local (X, d) near the round: random, tangent, near the axis or in the plane."""
    mode = int(rng.integers(0, 4))
    r, t = _in_plane(rng, fr.exact)
    if mode == 0:
        return rng.normal(size=3) * R, _unit(rng)
    if mode == 1:
        return R * r + _tiny(rng) * R * r, t
    if mode == 2:
        psi = 0.0 if rng.random() < 0.3 else _logu(rng, -16, -10)
        return r * R * float(rng.choice([0.0, 1.0, rng.uniform(0, 2)])), _rot(EZ, t, psi)
    return r * R * rng.uniform(0, 2), _perp(rng, EZ)


def _fam_far_origin(rng, ka, kb):
    """Line origins / segment ends 1e6..1e12 radii along the line."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    b = fr.round(np.zeros(3), EZ, R)
    X, d = _interesting_line(rng, fr, R, kb)
    return _far_piece(rng, fr, ka, X, d, R), b


def _far_piece(rng, fr, kind, X, d, R):
    """A line, ray or segment through the local point X along d whose origin / one end (or both)
    lies 1e6..1e12 x R along it; a point stays at X."""
    if kind == "point":
        return fr.pos(X)
    d = d / np.linalg.norm(d)
    far = _logu(rng, 6, 12) * R
    sgn = float(rng.choice([-1.0, 1.0]))
    if kind == "line":
        return fr.pos(X - sgn * far * d) + fr.dirv(d, fr.dlen())
    if kind == "ray":
        if rng.random() < 0.8:
            return fr.pos(X - far * d) + fr.dirv(d, fr.dlen())
        return fr.pos(X + far * d) + fr.dirv(d, fr.dlen())
    far2 = _logu(rng, 6, 12) * R if rng.random() < 0.5 else rng.uniform(-0.5, 2) * R
    ends = [fr.pos(X - far * d), fr.pos(X + far2 * d)]
    if rng.random() < 0.5:
        ends.reverse()
    return ends[0] + ends[1]


def _fam_radius_ratio(rng, ka, kb):
    """Extreme radius ratios: 1e-9 and 1e9."""
    fr = _Frame(rng, exact=False)
    ratio = float(rng.choice([1e-9, 1e9]))
    if ka in ROUND:
        Ra = _logu(rng, -0.5, 0.5)
        Rb = Ra * ratio * (1.0 if rng.random() < 0.5 else rng.uniform(0.5, 2))
        big, small = max(Ra, Rb), min(Ra, Rb)
        mode = int(rng.integers(0, 3))
        nb = _unit(rng)
        if mode == 0:  # the small one near the big one's rim
            if Rb > Ra:
                u = _perp(rng, nb)
                cb = -Rb * u + small * rng.normal(size=3) * 2
            else:
                r, _ = _in_plane(rng, False)
                cb = Ra * r + small * rng.normal(size=3) * 2
        elif mode == 1:  # near the big one's centre
            cb = small * rng.normal(size=3) * 2
        else:  # anywhere at the big one's scale
            cb = big * rng.normal(size=3)
        return fr.round(np.zeros(3), EZ, Ra), fr.round(cb, nb, Rb)
    R = ratio * (1.0 if rng.random() < 0.5 else rng.uniform(0.5, 2))
    scale = R if rng.random() < 0.5 else 1.0
    b = fr.round(np.zeros(3), EZ, R)
    if ka == "bezier":
        return fr.bezier([rng.normal(size=3) * 1.5 * scale for _ in range(_npts(rng))]), b
    return fr.linear(ka, rng.normal(size=3) * scale, _unit(rng), scale), b


def _fam_near_touching(rng, ka, kb):
    """Rounds nearly touching: gap 1e-14..1e-9 x radius."""
    fr = _Frame(rng)
    ex = fr.exact
    Ra, Rb = _radius(rng, ex), _radius(rng, ex)
    g = _logu(rng, -14, -9) * max(Ra, Rb)
    modes = ["coplanar", "rims"] + (["face", "parallel"] if "disk" in (ka, kb) else [])
    mode = str(rng.choice(modes))
    A = fr.round(np.zeros(3), EZ, Ra)
    r, t = _in_plane(rng, ex)
    if mode == "coplanar":
        return A, fr.round((Ra + Rb + g) * r, EZ * float(rng.choice([-1.0, 1.0])), Rb)
    if mode == "rims":
        c, n, w = _tangent_round(rng, Ra, Rb, ex, phi=float(rng.choice([math.pi, math.pi / 2, rng.uniform(0.3, 5.9)])))
        return A, fr.round(c + g * w, n, Rb)
    disk_is_b = kb == "disk"
    Rd, Rr = (Rb, Ra) if disk_is_b else (Ra, Rb)
    D = fr.round(np.zeros(3), EZ, Rd)
    if mode == "face":
        P = r * Rd * fr.param(0, 0.875)
        e = np.array([1.0, 0.0, 0.0]) if ex else _perp(rng, EZ)
        O = fr.round(P + (Rr + g) * EZ, np.cross(EZ, e), Rr)
    else:
        c = r * (Rd + Rr) * fr.param(0, 0.875) + g * EZ
        O = fr.round(c, EZ, Rr)
    return (O, D) if disk_is_b else (D, O)


def _fam_parallel_height(rng, ka, kb):
    """A circle (or disk) parallel to a disk (or circle) at heights 0 or 1e-16..1e-6."""
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    B = fr.round(np.zeros(3), EZ, Rb)
    Ra = Rb * float(rng.choice([rng.uniform(0.1, 0.9), 1.0, 1.0 + _tiny(rng, -15, -6, 0), rng.uniform(1.1, 3)]))
    h = _tiny(rng, -16, -6, 0.15) * Rb
    r, _ = _in_plane(rng, ex)
    where = rng.choice(["centre", "inside", "rim", "outside"])
    off = {
        "centre": 0.0,
        "inside": rng.uniform(0, 1) * abs(Rb - Ra),
        "rim": Rb + rng.choice([-1.0, 1.0]) * Ra + _tiny(rng, -14, -6) * Rb,
        "outside": Rb + Ra + rng.uniform(0, 2) * Rb,
    }[where]
    n = EZ * float(rng.choice([-1.0, 1.0]))
    return fr.round(off * r + h * EZ, n, Ra), B


def _fam_bezier_large(rng, ka, kb):
    """Bezier curves 1e2..1e5 times larger than the round, passing near it."""
    fr = _Frame(rng, exact=False)
    R = _radius(rng, False)
    b = fr.round(np.zeros(3), EZ, R)
    r, t = _in_plane(rng, False)
    X = [R * r, R * r * rng.uniform(0, 1) + _tiny(rng, -14, -6) * R * EZ, rng.normal(size=3) * 2 * R, np.zeros(3)][
        int(rng.integers(0, 4))
    ]
    size = _logu(rng, 2, 5) * R
    return fr.bezier(_bezier_through(rng, X, size, _npts(rng))), b


def _fam_bezier_far_control(rng, ka, kb):
    """One control point 1e6..1e12 radii away."""
    fr = _Frame(rng, exact=False)
    R = _radius(rng, False)
    b = fr.round(np.zeros(3), EZ, R)
    ctrl = [rng.normal(size=3) * 1.5 * R for _ in range(_npts(rng))]
    ctrl[int(rng.integers(0, len(ctrl)))] = _unit(rng) * _logu(rng, 6, 12) * R
    return fr.bezier(ctrl), b


def _fam_bezier_plane(rng, ka, kb):
    """A Bezier curve in a plane parallel to the round's at height 1e-9 (x radius), translated by
    1e6."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    h = 1e-9 * R * float(rng.choice([-1.0, 1.0]))
    b = fr.round(np.zeros(3), EZ, R)
    ctrl = [np.array([*(rng.normal(size=2) * 1.2 * R), h]) for _ in range(_npts(rng))]
    a = fr.bezier(ctrl)
    T = (_unit(rng) if rng.random() < 0.7 else np.array([1.0, 0.0, 0.0])) * 1e6
    return _translate("bezier", a, T), _translate(kb, b, T)


def _fam_huge_circle(rng, ka, kb):
    """A huge circle (radius 1e3..1e9) passing near a small disk or circle."""
    fr = _Frame(rng, exact=False)
    r_small = _logu(rng, -1, 0.3)
    Rh = _logu(rng, 3, 9)
    huge_is_a = not (ka == "circle" and kb == "disk" and rng.random() < 0.3)
    r, t = _in_plane(rng, False)
    mode = int(rng.integers(0, 4))
    g = _tiny(rng, -12, 0, 0.3) * r_small
    X = [
        r_small * r + g * _unit(rng),
        r * r_small * rng.uniform(0, 1) + abs(g) * EZ,
        rng.normal(size=3) * 2 * r_small,
        g * _unit(rng),
    ][mode]
    nh = _unit(rng)
    uh = _perp(rng, nh)
    huge = fr.round(X - Rh * uh, nh, Rh)
    small = fr.round(np.zeros(3), EZ, r_small)
    return (huge, small) if huge_is_a else (small, huge)
