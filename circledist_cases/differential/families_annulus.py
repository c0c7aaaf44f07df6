"""Case families of the annuli: the disk families applied to annuli, and the annuli's own."""

from __future__ import annotations

import math

import numpy as np

from .base import ANN_PAIRS, FAMILIES, _plain
from .frames import EZ, _Frame, _elevate, _in_plane, _logu, _npts, _perp, _radius, _rot, _tangent_round, _tiny, _unit
from .families_round import _fam_far_translated
from .families_arc import _arc_of


# ---- annuli: the disk families applied to annuli, and the annuli's own ----------------------
# An annulus family takes a base family's case with every annulus drawn as a disk (and every arc
# as a circle, cut to an arc as the arc families do), then cuts a hole in each such disk: inner
# radius 0 (the disk), the outer radius (the circle), 1e-9..1e-6 of it, a quarter, half or three
# quarters (exact in exact frames) or any fraction.  Annulus data: centre, normal, OUTER radius,
# inner radius (RIMS).
def _ann_base_kind(kind):
    return {"arc": "circle", "annulus": "disk"}.get(kind, kind)


def _axis_normal(data):
    """Whether a round's normal is a coordinate axis (an exact frame's)."""
    return sum(1 for x in data[3:6] if x != 0.0) == 1


_HOLES = ("zero", "outer", "tiny", "fraction", "any")


def _hole(rng, disk, holes=_HOLES):
    """The disk's data with a hole: [centre, normal, outer, inner]."""
    R = float(disk[6])
    how = str(rng.choice(holes))
    if how == "zero":
        inner = 0.0
    elif how == "outer":
        inner = R
    elif how == "tiny":
        inner = R * (1e-9 if rng.random() < 0.5 else _logu(rng, -9, -6))
    elif how == "fraction" and _axis_normal(disk):
        inner = R * float(rng.choice([0.25, 0.5, 0.75]))
    else:
        inner = R * float(rng.uniform(0.05, 0.95))
    return [float(x) for x in disk[:7]] + [float(inner)]


def _ann_variant(base, holes=_HOLES):
    """The generator of an annulus family: the base family's case (annuli drawn as disks, arcs as
    circles), its arcs cut (_arc_of) and its annuli holed (_hole)."""

    def gen(rng, ka, kb):
        bka, bkb = _ann_base_kind(ka), _ann_base_kind(kb)
        a, b = FAMILIES[base][1](rng, bka, bkb)
        a, b = _plain(a), _plain(b)
        if ka == "arc":
            a = _arc_of(rng, a, bkb, b)
        if ka == "annulus":
            a = _hole(rng, a, holes)
        return a, _hole(rng, b, holes)

    return gen


def _ann_pairs(base_pairs):
    """The annulus pairs whose disk version (annuli drawn as disks, arcs as circles) the base
    family covers."""
    return [p for p in ANN_PAIRS if (_ann_base_kind(p[0]), "disk") in base_pairs]


def _ann_local(rng, fr, lo=0.3, hi=0.8):
    """The annulus of a local frame (centre 0, normal z): (data, outer, inner); in exact frames
    dyadic radii."""
    Ro = _radius(rng, fr.exact)
    Ri = Ro * (float(rng.choice([0.25, 0.5, 0.75])) if fr.exact else float(rng.uniform(lo, hi)))
    return fr.round(np.zeros(3), EZ, Ro) + [Ri], Ro, Ri


def _lift(rng, R):
    """0 (coplanar) or +-1e-9..1e-3 x R."""
    return _tiny(rng, -9, -3, 0.4) * R


def _inner_circle(b, fr, Ri):
    """The inner rim of the local annulus as a circle's data (world)."""
    return fr.round(np.zeros(3), EZ, Ri)


def _fam_ann_hole(rng, ka, kb):
    """Something in the hole: a point, a segment, a Bezier curve, a circle, arc, disk or annulus
    inside the inner rim, coplanar or lifted by 1e-9..1e-3 radii, concentric or not (a circle's
    radius up to 1e-12 short of touching the inner rim); lines and rays through the hole, in the
    plane (crossing the ring) or tilted through it."""
    fr = _Frame(rng)
    ex = fr.exact
    b, Ro, Ri = _ann_local(rng, fr)
    h = _lift(rng, Ro)
    r, t = _in_plane(rng, ex)
    if ka == "point":
        return fr.pos(r * Ri * fr.param(0, 0.875) + h * EZ), b
    if ka in ("line", "ray", "segment"):
        X = r * Ri * fr.param(0, 0.875) + h * EZ
        if ka == "segment" and rng.random() < 0.5:
            # a short segment wholly inside the hole
            room = math.sqrt(max(Ri * Ri - float(np.dot(X[:2], X[:2])), 0.0))
            s0, s1 = room * rng.uniform(-0.9, 0.9), room * rng.uniform(-0.9, 0.9)
            return fr.pos(X + s0 * t) + fr.pos(X + s1 * t), b
        psi = 0.0 if rng.random() < 0.5 else float(rng.uniform(0.1, 1.5))
        d = math.cos(psi) * t + math.sin(psi) * EZ
        return fr.linear(ka, X, d, Ri), b
    if ka == "bezier":
        ctrl = [np.array([*(rng.normal(size=2) * 0.3 * Ri), h]) for _ in range(_npts(rng))]
        return fr.bezier(ctrl), b
    off = 0.0 if rng.random() < 0.4 else fr.param(0, 0.375)
    c = r * Ri * off + h * EZ
    room = Ri * (1 - off)
    if rng.random() < 0.3:
        Rc = room * (1 - _logu(rng, -12, -3))
    else:
        Rc = room * (float(rng.choice([0.5, 0.75])) if ex else float(rng.uniform(0.1, 0.95)))
    n = EZ * float(rng.choice([-1.0, 1.0]))
    if rng.random() < 0.2 and not ex:
        n = _rot(n, _perp(rng, EZ), _logu(rng, -12, -3))
    a = fr.round(c, n, Rc)
    if ka == "arc":
        a = _arc_of(rng, a, "circle", _inner_circle(b, fr, Ri))
    elif ka == "annulus":
        a = _hole(rng, a, ("fraction", "any", "tiny"))
    return a, b


def _fam_ann_overlap(rng, ka, kb):
    """Coplanar (or parallel at heights 1e-16..1e-6) circles, arcs, disks and annuli over the
    ring: centres anywhere from concentric (exactly, in exact frames) to beyond the outer rim,
    the other's radii from inside the hole to beyond the outer rim."""
    fr = _Frame(rng)
    ex = fr.exact
    b, Ro, Ri = _ann_local(rng, fr)
    h = _tiny(rng, -16, -6, 0.5) * Ro
    r, _ = _in_plane(rng, ex)
    Ra = Ro * (float(rng.choice([0.25, 0.5, 0.75, 1.0, 1.5])) if ex else float(rng.uniform(0.1, 2)))
    off = 0.0 if rng.random() < 0.25 else fr.param(0, 1.5) * (Ra + Ro) / 2
    a = fr.round(off * r + h * EZ, EZ * float(rng.choice([-1.0, 1.0])), Ra)
    if ka == "arc":
        a = _arc_of(rng, a, "circle", _inner_circle(b, fr, Ri) if rng.random() < 0.5 else b[:7])
    elif ka == "annulus":
        a = _hole(rng, a, ("fraction", "any"))
    return a, b


def _fam_ann_degenerate(rng, ka, kb):
    """Annuli of inner radius 0 (the disk's answers, to the bit: _check_hole), equal to the outer
    one (the circle's) or 1e-9 of it, over the random, tangent, axis, coplanar, concentric and
    nearly touching cases."""
    bases = [
        f
        for f in ("random", "tangent", "axis", "coplanar", "concentric", "near_touching")
        if (ka, kb) in _ann_pairs(FAMILIES[f][0])
    ]
    return _ann_variant(str(rng.choice(bases)), holes=("zero", "outer", "tiny"))(rng, ka, kb)


def _fam_ann_inner_tangent(rng, ka, kb):
    """A piece tangent to the inner rim, or 1e-16..1e-4 radii inside or outside it: points by the
    inner rim, lines, rays and segments through the hole grazing it (tilted from the plane by
    0.1..1.4 rad), a Bezier arch grazing it, circles, arcs, disks and annuli touching it from
    inside the hole (coplanar) or standing on it."""
    fr = _Frame(rng)
    ex = fr.exact
    b, Ro, Ri = _ann_local(rng, fr)
    r, t = _in_plane(rng, ex)
    X = Ri * r
    h = _tiny(rng, -16, -4, 0.3) * Ri
    if ka == "point":
        return fr.pos(X + h * (r if ex or rng.random() < 0.5 else _unit(rng))), b
    if ka in ("line", "ray", "segment", "bezier"):
        psi = float(rng.uniform(0.1, 1.4))
        d = math.cos(psi) * t + math.sin(psi) * EZ
        Y = X + h * r
        if ka == "bezier":
            L = Ri * rng.uniform(0.3, 2)
            delta = -r * Ri * rng.uniform(0.05, 0.5)  # bulging into the hole
            ctrl = _elevate([Y - L * d - delta, Y + delta, Y + L * d - delta], max(3, _npts(rng)))
            return fr.bezier(ctrl), b
        return fr.linear(ka, Y, d, Ri), b
    phi = float(rng.choice([0.0, math.pi / 2, rng.uniform(0, 2 * math.pi)]))
    Rc = (
        Ri * (float(rng.choice([0.25, 0.5])) if ex else float(rng.uniform(0.1, 0.9)))
        if phi == 0.0
        else _radius(rng, ex) * Ri
    )
    c, n, w = _tangent_round(rng, Ri, Rc, ex, phi=phi)
    a = fr.round(c + h * w, n, Rc)
    if ka == "arc":
        a = _arc_of(rng, a, "circle", _inner_circle(b, fr, Ri))
    elif ka == "annulus":
        a = _hole(rng, a, ("fraction", "any"))
    return a, b


_ANN_TRANSLATED_BASES = (
    "ann_random",
    "ann_tangent",
    "ann_axis",
    "ann_coplanar",
    "ann_concentric",
    "ann_near_touching",
    "ann_parallel_height",
    "ann_hole",
    "ann_overlap",
    "ann_inner_tangent",
)


def _fam_ann_far_translated(rng, ka, kb):
    return _fam_far_translated(rng, ka, kb, bases=_ANN_TRANSLATED_BASES)
