"""Arcs against lines, rays, segments and points in the arc's own plane (the toolpath case: G2/G3
arcs and lines in one plane; linear_arc.hpp's piece_arc_planar, docs/derivations/arc.md "A line,
ray or segment in the arc's plane"), against the independent 50-digit reference of
circledist_cases/reference_arc.py (the arc sampled from its own definition, the other shape's
distance in closed form, minimized over the arc's angle).

The family, in each of four planes (the xy plane at a height, the toolpath's, with normals of
either sign and any length; a tilted plane whose points are rounded into it, coplanar to
rounding; the same lifted 1e-12 off it, near-coplanar; the tilted plane 1e6 from the origin):
random pieces and points, and the hard cases, lines tangent to the circle on, at and just
beside the arc's ends, lines and segments crossing the circle just inside and just outside the
arc's span, through its ends, missing it with the nearest point just inside and outside the
span, segments ending just short of the arc, pieces whose closest point is an end, and radii of
1e-3 and 1e3 against unit-sized pieces. Bar: 1e-12 x max(distance, radius); distance() and
closest_points().distance equal to the bit in both orders (both_orders); `unique` where the
geometry decides it (two crossings on the arc: two pairs at distance 0).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from circledist_cases import reference_kit as K
from circledist_cases.kind_checks import as_floats, both_orders
from circledist_cases.kind_checks import check as _check
from circledist_cases.reference_arc import ArcMP, arc, point_distance_function, reference

REL = 1e-12
ANGLE = 2.0  # the arc's span in the hard cases: t in [0, 2]


class Plane:
    """A plane: the point of its 2-D coordinates (x, y) at height z, in double, as a user would
    form it (rounded: a tilted plane's points are coplanar to rounding)."""

    def __init__(self, name, origin, e1, e2, normal, lift=0.0):
        self.name, self.origin, self.lift = name, np.asarray(origin, float), lift
        self.e1, self.e2, self.normal = np.asarray(e1, float), np.asarray(e2, float), np.asarray(normal, float)

    def point(self, x, y):
        unit = self.normal / np.linalg.norm(self.normal)
        return as_floats(self.origin + x * self.e1 + y * self.e2 + self.lift * unit)

    def vector(self, x, y):
        return as_floats(x * self.e1 + y * self.e2)

    def arc(self, radius, angle, start_angle=0.0, center=(0.0, 0.0)):
        c = self.origin + center[0] * self.e1 + center[1] * self.e2
        start = math.cos(start_angle) * self.e1 + math.sin(start_angle) * self.e2
        return arc(c, self.normal, radius, start, angle)


def _tilted():
    n = np.array([0.3, -0.5, 0.8])
    e1 = np.cross(n, [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n / np.linalg.norm(n), e1)
    return e1, e2, n


_E1, _E2, _N = _tilted()
PLANES = [
    Plane("xy-plane", (0.25, -0.5, 1.75), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 2.0)),
    Plane("xy-plane-down", (0.25, -0.5, -3.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, -0.5)),
    Plane("tilted", (0.3, 0.2, -0.4), _E1, _E2, _N),
    Plane("near-coplanar-1e-12", (0.3, 0.2, -0.4), _E1, _E2, _N, lift=1e-12),
    Plane("tilted-at-1e6", (1e6, -5e5, 2.5e5), _E1, _E2, _N),
]


def _polar(r, t):
    return r * math.cos(t), r * math.sin(t)


def hard_cases(p):
    """(name, arc, other, unique or None) of plane p: a unit arc from t = 0 to 2 about the plane's
    origin (the arc's t is the plane's angle), and radii 1e-3 and 1e3."""
    a = p.arc(1.0, ANGLE)
    cases = []

    def line(name, point, direction, unique=None, kind="line", arc_=a):
        cases.append((name, arc_, (kind, p.point(*point), p.vector(*direction)), unique))

    def segment(name, p0, p1, unique=None, arc_=a):
        cases.append((name, arc_, ("segment", p.point(*p0), p.point(*p1)), unique))

    for label, t in (
        ("inside", 1.0),
        ("at-start", 0.0),
        ("at-end", ANGLE),
        ("just-inside-end", ANGLE - 1e-9),
        ("just-outside-end", ANGLE + 1e-9),
        ("just-outside-start", -1e-9),
        ("off-the-arc", 4.0),
    ):
        # tangent at angle t (distance 0 where t is on the arc), and 1e-6 outside the circle
        x, y = _polar(1.0, t)
        tx, ty = -math.sin(t), math.cos(t)
        line(f"tangent-{label}", (x - 3 * tx, y - 3 * ty), (tx, ty))
        x, y = _polar(1.0 + 1e-6, t)
        line(f"missing-by-1e-6-{label}", (x + 2 * tx, y + 2 * ty), (-tx, -ty))
        # a line through the circle at angle t and at angle t + 2.5 (chord): its crossings
        x2, y2 = _polar(1.0, t + 2.5)
        x, y = _polar(1.0, t)
        line(f"crossing-{label}", (x, y), (x2 - x, y2 - y))
        # a segment from outside ending 1e-9 short of the circle at angle t, and exactly on it
        xo, yo = _polar(1.5, t)
        xs, ys = _polar(1.0 + 1e-9, t)
        segment(f"segment-short-of-{label}", (xo, yo), (xs, ys))
        segment(f"segment-ending-on-{label}", (xo, yo), (x, y))
        # a ray from inside the circle out through angle t
        cases.append((f"ray-out-through-{label}", a, ("ray", p.point(0.2 * x, 0.2 * y), p.vector(x, y)), None))

    # a line crossing the arc twice (two pairs at distance 0), once, or not at all (the ends decide)
    def chord(name, t1, t2, unique):
        x1, y1 = _polar(1.0, t1)
        x2, y2 = _polar(1.0, t2)
        line(name, (x1, y1), (x2 - x1, y2 - y1), unique)

    # (1e6 from the origin the chord's ends round by 1e-10 off the circle: its two crossings'
    # distances differ there, and the pair is unique.)
    chord("two-crossings-on-the-arc", 0.3, 1.7, False if np.linalg.norm(p.origin) < 10 else None)
    chord("one-crossing-on-the-arc", 1.0, 3.0, True)
    chord("crossing-in-the-gap", 2.5, 5.0, True)
    segment("segment-inside-the-circle", (-0.2, 0.3), (0.4, 0.1))
    segment("segment-beyond-the-gap", (0.5, -1.5), (-0.5, -1.8))
    segment("segment-through-both-ends", _polar(1.0, 0.0), _polar(1.0, ANGLE))
    segment("segment-short", (0.9, 0.9), (0.95, 0.9))
    cases.append(("point-inside-the-span", a, ("point", p.point(0.3, 0.6)), True))
    cases.append(("point-outside-the-span", a, ("point", p.point(0.2, -0.7)), True))
    cases.append(("point-beyond-an-end", a, ("point", p.point(*_polar(1.7, ANGLE + 0.3))), True))
    # radius ratios: a tiny arc and a huge one against unit-sized pieces
    small, big = p.arc(1e-3, ANGLE), p.arc(1e3, 0.01)
    line("tiny-arc-crossing-line", (0.0, 5e-4), (1.0, 0.1), arc_=small)
    segment("tiny-arc-segment-beside", (1.5e-3, -0.5), (1.5e-3, 0.5), arc_=small)
    line("huge-arc-tangent-line", (1e3, -1.0), (0.0, 1.0), arc_=big)
    segment("huge-arc-segment-inside", (999.0, 2.0), (999.5, 4.0), arc_=big)
    segment("huge-arc-segment-crossing", (999.0, 3.0), (1001.0, 3.5), arc_=big)
    return cases


def random_cases(p, n, seed):
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        radius = float(rng.uniform(0.2, 2.0))
        a = p.arc(radius, float(rng.uniform(0.3, 6.2)), float(rng.uniform(-math.pi, math.pi)), rng.uniform(-1, 1, 2))
        kind = ("line", "ray", "segment", "point")[i % 4]
        q = rng.uniform(-3, 3, 2)
        if kind == "point":
            other = ("point", p.point(*q))
        elif kind == "segment":
            other = ("segment", p.point(*q), p.point(*(q + rng.uniform(-3, 3, 2))))
        else:
            other = (kind, p.point(*q), p.vector(*rng.normal(size=2)))
        out.append((f"random-{kind}-{i}", a, other, None))
    return out


CASES = [(p.name, *c) for p in PLANES for c in hard_cases(p) + random_cases(p, 8, 7)]


def _quick(case):
    """The quick loop's share (the rest is marked slow): the xy plane's cases at and beside the
    arc's ends, where the span test decides."""
    return case[0] == "xy-plane" and ("just-" in case[1] or "at-" in case[1])


PARAMS = [pytest.param(c, marks=() if _quick(c) else pytest.mark.slow, id=f"{c[0]}-{c[1]}") for c in CASES]


def _check_pair(a, b, r, ref):
    """The closest points lie on their shapes (the arc's by the reference's own point-arc closed
    form), their separation is the distance, and the arc's t gives its point."""
    pa, pb = np.asarray(r.point_a, float), np.asarray(r.point_b, float)
    tol = 1e-12 * max(ref, a[3]) + 16 * np.finfo(float).eps * float(np.abs([pa, pb]).max())
    assert abs(float(np.linalg.norm(pa - pb)) - ref) <= tol
    arc_mp = ArcMP(a)
    assert float(arc_mp.point_distance(K.vec(pa))) <= tol
    assert float(point_distance_function(b)(K.vec(pb))) <= tol
    t = float(r.param_a[0])
    assert 0 <= t <= a[5]
    assert float(K.dist(arc_mp.at(K.to_mp(t)), K.vec(pa))) <= tol


@pytest.mark.parametrize("case", PARAMS)
def test_coplanar_family_against_the_reference(case):
    _, name, a, b, unique = case
    d, r = both_orders(a, b)  # distance == closest_points().distance to the bit, both orders
    ref = _check(a, b, d, reference(a, b), REL)
    _check_pair(a, b, r, ref)
    if unique is not None:
        assert bool(r.unique) is unique, name
