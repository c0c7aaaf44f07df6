"""The accuracy cases of every query kind: value layouts, placement, hard scenes, random cases
and their 50-digit references.

Used by bench/accuracy_vs_time.py (which times and judges them for every root policy and
precision through bench/accuracy_vs_time.cpp) and by the stability sweeps (sweeps.py).

A case is a kind ("line-circle", ...) and the flat tuple of its two shapes' values, the layout
bench/accuracy_vs_time.cpp reads: point (x, y, z); line, ray (origin, direction); segment (p0,
p1); circle, disk (center, normal, radius); arc (center, normal, radius, start, angle); annulus
(center, normal, inner radius, outer radius); bezier (k, then k control points). Hard scenes are
written in a local frame (the round shape is the unit circle or disk, the arc of angle 3 pi / 2
from +x on the unit circle, the annulus of radii 0.5 and 1: center 0, normal +z) and placed in
the world: in that frame, under a generic rotation, translated by 1e6 and 1e8, plus radius and
scale variants. References (``reference_distance``) are of the exact float inputs, by an
independent method: reference_linear_round.py, reference_round.py, reference_arc.py and reference_annulus.py
minimise a closed-form point-to-shape distance over ONE parameter in mpmath; no polynomial, no
root finding.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from mpmath import mp, mpf

from . import bezier_cases
from . import reference_linear_round as LREF  # linear shapes vs circle / disk
from . import reference_annulus as NREF  # every kind against an annulus
from . import reference_arc as AREF  # every kind but the annulus against an arc
from . import reference_bezier as BREF  # Bezier against Bezier
from . import reference_round as RREF  # circle, disk and Bezier kinds
from .scenes import SHARED_LINES, SHARED_POINTS, SHARED_RAYS, SHARED_SEGMENTS

mp.dps = 50

KINDS = [
    "point-circle",
    "point-disk",
    "line-circle",
    "ray-circle",
    "segment-circle",
    "line-disk",
    "ray-disk",
    "segment-disk",
    "circle-circle",
    "circle-disk",
    "disk-disk",
    "bezier-disk",
    "bezier-circle",
    "bezier-bezier",
    # arcs and annuli, the arc or annulus second
    "point-arc",
    "line-arc",
    "ray-arc",
    "segment-arc",
    "circle-arc",
    "disk-arc",
    "arc-arc",
    "bezier-arc",
    "point-annulus",
    "line-annulus",
    "ray-annulus",
    "segment-annulus",
    "circle-annulus",
    "disk-annulus",
    "arc-annulus",
    "annulus-annulus",
    "bezier-annulus",
    # the first shape in the arc's plane (the toolpath case: arcs and lines in one plane)
    "point-arc-coplanar",
    "line-arc-coplanar",
    "ray-arc-coplanar",
    "segment-arc-coplanar",
    "circle-arc-coplanar",
]
LINEAR = ("point", "line", "ray", "segment")
ROUND = ("circle", "disk")
SHAPE_SIZE = {"point": 3, "line": 6, "ray": 6, "segment": 6, "circle": 7, "disk": 7, "arc": 11, "annulus": 8}


def shapes_of(kind):
    """The two shape kinds of a kind ("line-arc", "line-arc-coplanar": line and arc)."""
    a, b = kind.split("-")[:2]
    return a, b


def _coplanar_kind(kind):
    return kind.endswith("-coplanar")


def _in_the_arc_plane(a, b):
    """Whether local shape a lies in the plane z = 0 of arc b (normal along z, center at z = 0):
    its points at z = 0, its directions and a round's normal-free part flat."""
    if b[0] != "arc" or b[1][2] != 0 or b[2][0] != 0 or b[2][1] != 0:
        return False
    kind, *f = a
    if kind == "point":
        return f[0][2] == 0
    if kind in ("line", "ray", "segment"):
        return f[0][2] == 0 and f[1][2] == 0
    if kind == "circle":
        return f[0][2] == 0 and f[1][0] == 0 and f[1][1] == 0
    return False


def split_values(kind, values):
    """((shape kind, values), (shape kind, values)) of a case."""
    a, b = shapes_of(kind)
    if a == "bezier":
        n = 1 + 3 * int(values[0])
    else:
        n = SHAPE_SIZE[a]
    return (a, tuple(values[:n])), (b, tuple(values[n:]))


def _control_points(values):
    """A Bezier curve's control points from its values (k, then k points)."""
    return [tuple(values[1 + 3 * i : 4 + 3 * i]) for i in range(int(values[0]))]


def bar_scale(kind, values):
    """The scale the bar multiplies besides the distance: the largest radius in the query, or for
    two curves the larger curve size (their control polygons' extent, as tests/pairs/test_bezier_bezier.py
    and reference_bezier.py take it)."""
    (a, va), (b, vb) = split_values(kind, values)
    if a == "bezier" and b == "bezier":
        return max(BREF.curve_size(_control_points(va)), BREF.curve_size(_control_points(vb)))
    out = 0.0
    for shape, vals in ((a, va), (b, vb)):
        if shape in ROUND or shape == "arc":
            out = max(out, abs(float(vals[6])))
        elif shape == "annulus":  # the outer radius
            out = max(out, abs(float(vals[7])))
    return out


def to_float32(values):
    """The float run's inputs: every double rounded to the nearest float (as the C++ does)."""
    return tuple(float(np.float32(v)) for v in values)


# ------------------------------------------------------------------------------------------------
# references (independent: one-parameter minimisation of closed forms, no polynomial roots)
# ------------------------------------------------------------------------------------------------
def _plain_shape(kind, vals):
    """A shape as reference_arc / reference_annulus take it: a plain tuple (kind, *fields)."""
    if kind == "annulus":
        return NREF.annulus(vals[0:3], vals[3:6], vals[6], vals[7])
    return AREF.shape(kind, vals)


def reference_distance(kind, values):
    """50-digit distance of the scene the float inputs `values` describe exactly (an mpf)."""
    (a, va), (b, vb) = split_values(kind, values)
    if b == "annulus":  # reference_annulus: the other shape's parameter against the closed form
        ring = _plain_shape(b, vb)
        if a == "bezier":
            return mpf(NREF.bezier_reference_mp(ring, _control_points(va)))
        if a == "segment" and tuple(va[:3]) == tuple(va[3:6]):  # zero length: its point (the
            return mpf(NREF.reference_mp(ring, ("point", tuple(va[:3]))))  # reference divides by |p1 - p0|^2)
        return mpf(NREF.reference_mp(ring, _plain_shape(a, va)))
    if b == "arc":  # reference_arc: the arc's angle against the other shape's closed form
        arc_b = _plain_shape(b, vb)
        if a == "bezier":
            return mpf(AREF.bezier_arc(_control_points(va), arc_b))
        return mpf(AREF.reference_mp(arc_b, _plain_shape(a, va)))
    if a in LINEAR:
        return mpf(LREF.reference(a, va, b, vb).distance)
    if b == "bezier":
        return mpf(str(BREF.bezier_bezier(_control_points(va), _control_points(vb)).distance))
    ra = (va[0:3], va[3:6], va[6]) if a in ROUND else None
    rb = (vb[0:3], vb[3:6], vb[6])
    if a == "circle" and b == "circle":
        ref = RREF.circle_circle(*ra, *rb)
    elif a == "circle" and b == "disk":
        ref = RREF.circle_disk(*ra, *rb)
    elif a == "disk" and b == "disk":
        ref = RREF.disk_disk(*ra, *rb)
    elif a == "bezier":
        fn = RREF.bezier_disk if b == "disk" else RREF.bezier_circle
        ref = fn(_control_points(va), *rb)
    else:
        raise ValueError(kind)
    return mpf(str(ref.distance))


# ------------------------------------------------------------------------------------------------
# scenes: local descriptions placed in the world
# ------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Case:
    kind: str
    group: str  # random | hard | sweep
    name: str
    values: tuple
    exact: object = None  # analytic distance of the inputs (sweeps), used instead of the reference


def _rotation(axis, angle):
    a = np.asarray(axis, float)
    a /= np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


ROTATION = _rotation((0.36, -0.48, 0.8), 0.9)  # a generic rotation: every coordinate rounds
OFFSET_DIRECTION = np.array([1.0, -0.7, 0.4])
PLACEMENTS = [("z", 0.0), ("rot", 0.0), ("z", 1e6), ("z", 1e8), ("rot", 1e6), ("rot", 1e8)]


def shape_values(shape, orient="z", offset=0.0, scale=1.0):
    """World values of a local shape: ('point', p) | ('line'|'ray', o, d) | ('segment', p0, p1)
    | ('circle'|'disk', c, n, r) | ('bezier', [p...]). Positions are scaled by `scale`, rotated,
    then translated by offset * OFFSET_DIRECTION; directions and normals are only rotated."""
    Q = np.eye(3) if orient == "z" else ROTATION
    T = offset * OFFSET_DIRECTION

    def pos(p):
        return [float(x) for x in Q @ (scale * np.asarray(p, float)) + T]

    def vec(d):
        return [float(x) for x in Q @ np.asarray(d, float)]

    kind = shape[0]
    if kind == "point":
        return pos(shape[1])
    if kind in ("line", "ray"):
        return pos(shape[1]) + vec(shape[2])
    if kind == "segment":
        return pos(shape[1]) + pos(shape[2])
    if kind in ROUND:
        return pos(shape[1]) + vec(shape[2]) + [float(scale * shape[3])]
    if kind == "arc":  # ('arc', c, n, r, start, angle): start is a direction, angle unscaled
        return pos(shape[1]) + vec(shape[2]) + [float(scale * shape[3])] + vec(shape[4]) + [float(shape[5])]
    if kind == "annulus":  # ('annulus', c, n, inner, outer)
        return pos(shape[1]) + vec(shape[2]) + [float(scale * shape[3]), float(scale * shape[4])]
    if kind == "bezier":
        out = [float(len(shape[1]))]
        for p in shape[1]:
            out += pos(p)
        return out
    raise ValueError(kind)


def scene_values(a, b, orient="z", offset=0.0, scale=1.0):
    return tuple(shape_values(a, orient, offset, scale) + shape_values(b, orient, offset, scale))


Z = (0.0, 0.0, 1.0)
ORIGIN = (0.0, 0.0, 0.0)
UNIT_CIRCLE = ("circle", ORIGIN, Z, 1.0)
UNIT_DISK = ("disk", ORIGIN, Z, 1.0)
T9 = 1e-9

# Lines against the unit circle / disk (center 0, normal +z): (origin, direction). The scenes the
# accuracy tests run too are scenes.py's SHARED_*; these are the benchmark's own on top.
LINE_SCENES = {
    **SHARED_LINES,
    "axis tilted 1e-8": ((0, 0, 0.5), (math.sin(1e-8), 0, math.cos(1e-8))),
    "axis tilted 1e-12": ((0, 0, 0.5), (math.sin(1e-12), 0, math.cos(1e-12))),
    "crosses 1e-9 inside the rim": ((1 - T9, 0, 0), (0.375, 0.5, 0.75)),
    "crosses 1e-9 outside the rim": ((1 + T9, 0, 0), (0.375, 0.5, 0.75)),
    "in plane 1e-9 outside tangent": ((0, 1 + T9, 0), (1, 0, 0)),
}
# Rays and segments: around every line scene, from its special point, and a few of their own.
RAY_EXTRA = SHARED_RAYS
SEGMENT_EXTRA = SHARED_SEGMENTS
POINT_SCENES = {**SHARED_POINTS, "over the rim 1e-9": (1, 0, T9), "in plane 1e-9 outside": (1 + T9, 0, 0)}
RADIUS_SCENES = ["tangent in plane", "tangent lifted 1e-6", "on the axis", "crosses the plane on the rim", "generic"]
# (scale of the whole scene, local radius)
RADIUS_VARIANTS = {
    "scene x1e-9": (1e-9, 1.0),
    "scene x1e9": (1e9, 1.0),
    "radius 1e-9": (1.0, 1e-9),
    "radius 1e9": (1.0, 1e9),
}


def _sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def _axpy(a, x, y):
    return tuple(a * xi + yi for xi, yi in zip(x, y))


def linear_local_scenes(lin, lines=None, points=None):
    """{name: local shape} of one linear kind: around the lines (origin, direction) and points
    given (default LINE_SCENES, POINT_SCENES), plus the rays' and segments' own."""
    lines = LINE_SCENES if lines is None else lines
    points = POINT_SCENES if points is None else points
    out = {}
    if lin == "point":
        return {n: ("point", p) for n, p in points.items()}
    for name, (o, d) in lines.items():
        if lin == "line":
            out[name] = ("line", o, d)
        elif lin == "ray":
            out["through: " + name] = ("ray", _axpy(-2, d, o), d)
            out["from: " + name] = ("ray", o, d)
        else:
            out["over: " + name] = ("segment", _axpy(-2, d, o), _axpy(2, d, o))
            out["ending at: " + name] = ("segment", o, _axpy(2, d, o))
    if lin == "ray":
        out.update({n: ("ray", o, d) for n, (o, d) in RAY_EXTRA.items()})
    if lin == "segment":
        out.update({n: ("segment", p, q) for n, (p, q) in SEGMENT_EXTRA.items()})
    return out


def _tilt(angle, axis="x"):
    """The +z normal tilted by `angle` about the x (or y) axis."""
    s, c = math.sin(angle), math.cos(angle)
    return (0.0, s, c) if axis == "x" else (s, 0.0, c)


def _c(center, normal, r):
    return ("circle", center, normal, r)


def _d(center, normal, r):
    return ("disk", center, normal, r)


def _bernstein_from_power(coefs, n):
    """Bernstein coefficients (degree n) of the polynomial sum_j coefs[j] t^j."""
    a = list(coefs) + [0.0] * (n + 1 - len(coefs))
    return [sum(math.comb(i, j) / math.comb(n, j) * a[j] for j in range(i + 1)) for i in range(n + 1)]


def _poly_curve(xs, ys, zs, n):
    """Bezier control points of the polynomial curve (x(t), y(t), z(t)) of degree n."""
    bx, by, bz = (_bernstein_from_power(c, n) for c in (xs, ys, zs))
    return list(zip(bx, by, bz))


CIRCLE_CIRCLE_SCENES = {
    "concentric coplanar": (_c(ORIGIN, Z, 1), _c(ORIGIN, Z, 2)),
    "coplanar disjoint": (_c(ORIGIN, Z, 1), _c((3, 0, 0), Z, 0.5)),
    "coplanar nested": (_c(ORIGIN, Z, 2), _c((0.7, 0.2, 0), Z, 0.5)),
    "coplanar crossing": (_c(ORIGIN, Z, 1), _c((1, 0, 0), Z, 1)),
    "coplanar touching outside": (_c(ORIGIN, Z, 1), _c((2.5, 0, 0), Z, 1.5)),
    "coplanar touching inside": (_c(ORIGIN, Z, 2), _c((1, 0, 0), Z, 1)),
    "coaxial": (_c(ORIGIN, Z, 1), _c((0, 0, 0.75), Z, 1.5)),
    "linked": (_c(ORIGIN, Z, 1), _c((0.6, 0, 0), (0, 1, 0), 0.6)),
    "linked, crossing once": (_c(ORIGIN, Z, 1), _c((0.8, 0, 0.3), (0, 1, 0), math.sqrt(0.13))),
    "orthogonal touching": (_c(ORIGIN, Z, 1), _c((2, 0, 0), (0, 1, 0), 1)),
    "near-coplanar 1e-9 concentric": (_c(ORIGIN, Z, 1), _c(ORIGIN, _tilt(T9, "y"), 2)),
    "near-coplanar 1e-9 nested": (_c(ORIGIN, Z, 2), _c((0.7, 0.2, 0), _tilt(T9), 0.5)),
    "near-coplanar 1e-9 disjoint": (_c(ORIGIN, Z, 1), _c((3, 0, 0), _tilt(T9), 0.5)),
    "near-coplanar 1e-9 crossing": (_c(ORIGIN, Z, 1), _c((1, 0, 0), _tilt(T9), 1)),
    "parallel 1e-9 apart, nested": (_c(ORIGIN, Z, 2), _c((0.7, 0.2, T9), Z, 0.5)),
    "radius ratio 1e-6 near the rim": (_c((0.6, 0.8, 1e-3), (0.3, -0.5, 0.8), 1e-6), _c(ORIGIN, Z, 1)),
    "radius ratio 1e6, linked": (_c(ORIGIN, Z, 1e6), _c((1e6 - 0.25, 0.5, 0.1), (0.2, 1, 0.1), 1)),
    "same center, orthogonal": (_c(ORIGIN, (1, 1, 0), 1), _c(ORIGIN, (1, -1, 0), 2)),
}
CIRCLE_DISK_SCENES = {
    "in plane inside": (_c((0.2, 0.1, 0), Z, 0.5), UNIT_DISK[:3] + (2.0,)),
    "concentric coplanar outside": (_c(ORIGIN, Z, 3), _d(ORIGIN, Z, 2)),
    "coplanar crossing the rim": (_c((1.5, 0, 0), Z, 1), UNIT_DISK),
    "coplanar disjoint": (_c((4, 0, 0), Z, 1), _d(ORIGIN, (0, 0, -1), 2)),
    "coplanar touching the rim": (_c((2, 0, 0), Z, 1), UNIT_DISK),
    "coaxial above, smaller": (_c((0, 0, 0.7), Z, 1), _d(ORIGIN, Z, 2)),
    "coaxial above, larger": (_c((0, 0, 0.5), Z, 3), _d(ORIGIN, Z, 2)),
    "parallel 1e-9 above, nested": (_c((0.3, 0.2, T9), Z, 0.5), UNIT_DISK),
    "near-coplanar 1e-9 outside": (_c(ORIGIN, _tilt(T9), 3), _d(ORIGIN, Z, 2)),
    "near-coplanar 1e-9 disjoint": (_c((3, 0, 0), _tilt(T9), 1), UNIT_DISK),
    "near-coplanar 1e-9 inside": (_c((0.2, 0.1, 0), _tilt(T9), 0.5), UNIT_DISK),
    "linked through the disk": (_c((0.6, 0, 0), (0, 1, 0), 0.6), UNIT_DISK),
    "touching the face": (_c((0.3, 0, 1), (0, 1, 0), 1), UNIT_DISK),
    "1e-9 above the face": (_c((0.3, 0, 1 + T9), (0, 1, 0), 1), UNIT_DISK),
    "touching the rim from above": (_c((1, 0, 1), (0, 1, 0), 1), UNIT_DISK),
    "radius ratio 1e-6 over the rim": (_c((1, 0, 1e-3), (0.3, -0.5, 0.8), 1e-6), UNIT_DISK),
}
DISK_DISK_SCENES = {
    "coplanar overlapping": (UNIT_DISK, _d((1.5, 0, 0), Z, 1)),
    "coplanar disjoint": (UNIT_DISK, _d((3, 0, 0), Z, 1)),
    "coplanar touching": (UNIT_DISK, _d((2, 0, 0), Z, 1)),
    "stacked coaxial": (UNIT_DISK, _d((0, 0, 0.5), Z, 1)),
    "stacked, offset past the rim": (UNIT_DISK, _d((2.5, 0, 0.5), Z, 1)),
    "parallel 1e-9 apart, overlapping": (UNIT_DISK, _d((0.5, 0, T9), Z, 1)),
    "near-coplanar 1e-9 disjoint": (UNIT_DISK, _d((3, 0, 0), _tilt(T9), 1)),
    "near-coplanar 1e-9 concentric": (UNIT_DISK, _d(ORIGIN, _tilt(T9), 2)),
    "perpendicular, touching the face": (UNIT_DISK, _d((0.3, 0, 1), (0, 1, 0), 1)),
    "perpendicular, 1e-9 above the face": (UNIT_DISK, _d((0.3, 0, 1 + T9), (0, 1, 0), 1)),
    "perpendicular, through": (UNIT_DISK, _d((0.3, 0, 0.5), (0, 1, 0), 1)),
    "perpendicular, rim to rim": (UNIT_DISK, _d((2, 0, 0), (0, 1, 0), 1)),
    "generic disjoint": (UNIT_DISK, _d((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8)),
}
_WAVY = _poly_curve([-1.5, 3.0], [0.3], [0.15, 2.13, -3.89, 4.49, -1.53, 0.45], 5)
BEZIER_SCENES = {
    "straight, tangent in plane": [(1, -1, 0), (1, -1 / 3, 0), (1, 1 / 3, 0), (1, 1, 0)],
    "straight, tangent lifted 1e-9": [(1, -1, T9), (1, -1 / 3, T9), (1, 1 / 3, T9), (1, 1, T9)],
    "straight, crossing on the rim": [(0.625, -0.5, -0.75), (1.375, 0.5, 0.75)],
    "straight, along the axis": [(0, 0, 0.5), (0, 0, 1), (0, 0, 1.5)],
    "parabola touching the center": [(-1, 0, 1), (0, 0, -1), (1, 0, 1)],
    "parabola touching the rim": [(0, 0, 1), (1, 0, -1), (2, 0, 1)],
    "arc in plane crossing the rim": [(0.5, -1.5, 0), (1.5, 0, 0), (0.5, 1.5, 0)],
    "wavy quintic": _WAVY,
    "degree 7 over the disk": [
        (-1.2, -0.8, 0.4),
        (-0.6, 1.1, -0.2),
        (0.1, -1.3, 0.5),
        (0.8, 1.2, 0.1),
        (1.3, -0.4, -0.3),
        (0.4, 0.9, 0.6),
        (-0.5, 0.2, 0.2),
        (1.1, 0.1, 0.3),
    ],
}


# ------------------------------------------------------------------------------------------------
# arcs and annuli. The local arc is the unit circle's from +x (theta = 0, its start
# end, exact) to -y (theta = 3 pi / 2, its far end, rounded: cos(3 pi / 2) is -1.8e-16): the
# gap theta in (3 pi / 2, 2 pi) is where the full circle's closest point can miss the arc. The
# local annulus has radii 0.5 (the hole) and 1 (the unit circle's rim, where the shared scenes
# of the circle and disk kinds are tangent or cross).
# ------------------------------------------------------------------------------------------------
X = (1.0, 0.0, 0.0)
Y = (0.0, 1.0, 0.0)
TWO_PI = 2 * math.pi  # float64's 2 pi: an arc of this angle is the whole circle (docs/derivations/arc.md)
ARC_ANGLE = 1.5 * math.pi
GAP = 1.75 * math.pi  # the middle of the local arc's gap


def _arc(center=ORIGIN, normal=Z, r=1.0, start=X, angle=ARC_ANGLE):
    return ("arc", center, normal, r, start, angle)


def _ann(center=ORIGIN, normal=Z, inner=0.5, outer=1.0):
    return ("annulus", center, normal, inner, outer)


def _on(theta, r=1.0, z=0.0):
    """The point at angle theta and distance r from the axis, at height z (local frame)."""
    return (r * math.cos(theta), r * math.sin(theta), z)


def _add(p, q):
    return tuple(x + y for x, y in zip(p, q))


UNIT_ARC = _arc()
UNIT_ANNULUS = _ann()
# Variants of the local arc / annulus that selected scenes run against too: an arc whose gap is
# 1e-9 wide and the whole circle (the circle's answers), a quarter; an annulus without a hole
# (the disk), without width (the circle) and with a hole 1e-9 of its outer radius.
ARC_VARIANTS = {
    "angle 2pi - 1e-9": _arc(angle=TWO_PI - T9),
    "angle 2pi, the circle": _arc(angle=TWO_PI),
    "angle pi/2": _arc(angle=math.pi / 2),
}
ANNULUS_VARIANTS = {
    "inner 0, the disk": _ann(inner=0.0),
    "inner = outer, the circle": _ann(inner=1.0),
    "inner 1e-9 of outer": _ann(inner=1e-9),
}

# Linear shapes against the arc, on top of the circle's scenes (several of which are already
# tangent to or cross the circle at the arc's start end (1, 0, 0), or lie on its axis).
ARC_POINTS = {
    "past the start end 1e-9": _on(-T9, 2.0, 0.25),  # the circle's closest point 1e-9 off the arc
    "past the far end 1e-9": _on(ARC_ANGLE + T9, 2.0, 0.25),
    "in the gap, as far from both ends": _on(GAP, 0.5),
    "in the gap, outside the ring": _on(GAP, 1.5, 0.1),
    "on the far end": _on(ARC_ANGLE),
}
ARC_LINES = {
    "tangent at the far end": ((0.0, -1.0, 0.0), X),
    "tangent at the far end, lifted 1e-9": ((0.0, -1.0, T9), X),
    "tangent 1e-9 past the start end": (_on(-T9), (math.sin(T9), math.cos(T9), 0.0)),
    "tangent 1e-9 past the start end, lifted 1e-6": (_on(-T9, 1.0, 1e-6), (math.sin(T9), math.cos(T9), 0.0)),
    "in plane through both ends": (X, (1.0, 1.0, 0.0)),
    "in plane crossing the ring in the gap": ((0.6, -0.6, 0.0), (1.0, 1.0, 0.0)),
    "along the normal through the start end": ((1.0, 0.0, 0.5), Z),
    "along the normal through the gap": (_on(GAP, 0.5, 0.5), Z),
}
ARC_VARIANT_BASES = [
    "on the axis",
    "tangent in plane",
    "generic",
    "on the rim",
    "past the start end 1e-9",
    "tangent 1e-9 past the start end",
]

ANNULUS_POINTS = {
    "in the hole, in plane": (0.2, 0.1, 0.0),
    "on the inner rim": (0.5, 0.0, 0.0),
    "over the inner rim 1e-9": (0.5, 0.0, T9),
    "in plane 1e-9 inside the inner rim": (0.5 - T9, 0.0, 0.0),
    "in plane 1e-9 outside the inner rim": (0.5 + T9, 0.0, 0.0),
    "over the hole": (0.1, 0.1, 0.5),
}
ANNULUS_LINES = {  # "on the axis" (shared) is the line through the hole along the axis
    "along the axis 1e-9 inside the inner rim": ((0.5 - T9, 0.0, 0.5), Z),
    "along the axis through the inner rim": ((0.5, 0.0, 0.5), Z),
    "along the axis 1e-9 outside the inner rim": ((0.5 + T9, 0.0, 0.5), Z),
    "tangent to the inner rim, lifted 1e-9": ((0.5, 0.0, T9), Y),
    "crosses the plane in the hole": ((0.2, 0.1, 0.0), (0.375, 0.5, 0.75)),
    "crosses the plane 1e-9 inside the inner rim": ((0.5 - T9, 0.0, 0.0), (0.375, 0.5, 0.75)),
    "through the hole, tilted 1e-9 from the axis": ((0.0, 0.0, 0.5), (math.sin(T9), 0.0, math.cos(T9))),
}
ANNULUS_VARIANT_BASES = [
    "on the axis",
    "generic",
    "tangent in plane",
    "in the hole, in plane",
    "over the inner rim 1e-9",
    "crosses the plane in the hole",
]

CIRCLE_ARC_SCENES = {
    "coplanar touching the start end outside": (_c((2, 0, 0), Z, 1), UNIT_ARC),
    "coplanar touching the start end inside": (_c((0.5, 0, 0), Z, 0.5), UNIT_ARC),
    "orthogonal touching the start end": (_c((2, 0, 0), Y, 1), UNIT_ARC),
    "tangent at the far end, lifted 1e-9": (_c((0, -2, T9), Z, 1), UNIT_ARC),
    "start end on the circle's axis": (_c((1, 0, 0.75), Z, 0.5), UNIT_ARC),
    "start end on the tilted circle's axis": (_c((1.45, 0, 0.6), (0.6, 0, 0.8), 0.5), UNIT_ARC),
    "far end on the circle's axis": (_c(_on(ARC_ANGLE, 1.0, 0.75), Z, 0.5), UNIT_ARC),
    "the ring's closest point 1e-9 past the start": (_c(_on(-T9, 1.5), Z, 0.25), UNIT_ARC),
    "coplanar crossing the ring in the gap": (_c(_on(GAP, 0.9), Z, 0.3), UNIT_ARC),
    "linked with the ring in the gap": (_c(_on(GAP), _on(GAP + math.pi / 2), 0.4), UNIT_ARC),
    "linked with the arc": (_c(_on(0.75 * math.pi), _on(0.75 * math.pi + math.pi / 2), 0.4), UNIT_ARC),
    "concentric coplanar": (_c(ORIGIN, Z, 2), UNIT_ARC),
    "coaxial above": (_c((0, 0, 0.75), Z, 1.5), UNIT_ARC),
    "near-coplanar 1e-9 concentric": (_c(ORIGIN, _tilt(T9, "y"), 2), UNIT_ARC),
    "radius ratio 1e-6 just past the start end": (_c((1, -1e-3, 1e-3), (0.3, -0.5, 0.8), 1e-6), UNIT_ARC),
    "generic": (_c((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8), UNIT_ARC),
}
DISK_ARC_SCENES = {
    "coplanar touching the start end outside": (_d((2, 0, 0), Z, 1), UNIT_ARC),
    "the arc on a coplanar disk": (_d((0.2, 0.1, 0), Z, 3), UNIT_ARC),
    "start end touching a perpendicular disk's face": (_d((1, 0, 0.5), X, 1), UNIT_ARC),
    "start end 1e-9 from a perpendicular disk's face": (_d((1 + T9, 0, 0.5), X, 1), UNIT_ARC),
    "start end on the disk's axis": (_d((1, 0, 0.75), Z, 0.5), UNIT_ARC),
    "far end on the tilted disk's axis": (_d(_add(_on(ARC_ANGLE), (0.45, 0, 0.6)), (0.6, 0, 0.8), 0.5), UNIT_ARC),
    "over the gap, lifted": (_d(_on(GAP, 1.0, 0.5), Z, 0.5), UNIT_ARC),
    "coplanar crossing the ring in the gap": (_d(_on(GAP, 0.9), Z, 0.3), UNIT_ARC),
    "parallel 1e-9 above, over part of the arc": (_d((0.5, 0.5, T9), Z, 1), UNIT_ARC),
    "near-coplanar 1e-9 concentric": (_d(ORIGIN, _tilt(T9), 2), UNIT_ARC),
    "perpendicular across the gap": (_d(_on(GAP), _on(GAP + math.pi / 2), 0.4), UNIT_ARC),
    "coaxial above, larger": (_d((0, 0, 0.5), Z, 3), UNIT_ARC),
    "generic": (_d((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8), UNIT_ARC),
}
ARC_ARC_SCENES = {
    "end to end, coplanar": (_arc((2, 0, 0), Z, 1, (-1, 0, 0), math.pi / 2), UNIT_ARC),
    "end to end, orthogonal": (_arc((2, 0, 0), Y, 1, (-1, 0, 0), math.pi), UNIT_ARC),
    "same circle, the gap's arc 1e-9 short of both ends": (
        _arc(ORIGIN, Z, 1, _on(ARC_ANGLE + T9), math.pi / 2 - 2 * T9),
        UNIT_ARC,
    ),
    "same circle, overlapping": (_arc(ORIGIN, Z, 1, (-1, 0, 0), math.pi), UNIT_ARC),
    "concentric coplanar, overlapping ranges": (_arc(ORIGIN, Z, 2, X, math.pi), UNIT_ARC),
    "concentric coplanar, disjoint ranges": (_arc(ORIGIN, Z, 2, _on(-math.pi / 4), 0.5), UNIT_ARC),
    "start end on the other's axis": (_arc((1, 0, 0.5), Z, 0.5, X, math.pi), UNIT_ARC),
    "linked": (_arc((0.6, 0, 0), Y, 0.6, X, ARC_ANGLE), UNIT_ARC),
    "linked with the ring in the gap": (_arc(_on(GAP), _on(GAP + math.pi / 2), 0.4, Z, ARC_ANGLE), UNIT_ARC),
    "coaxial above": (_arc((0, 0, 0.75), Z, 1.5, _on(math.pi / 4), math.pi), UNIT_ARC),
    "tangent at the far end, lifted 1e-9": (_arc((0, -2, T9), Z, 1, Y, math.pi / 2), UNIT_ARC),
    "radius ratio 1e-6 just past the start end": (_arc((1, -1e-3, 1e-3), (0.3, -0.5, 0.8), 1e-6, X, 3.0), UNIT_ARC),
    "both whole (angle 2pi), linked": (_arc((0.6, 0, 0), Y, 0.6, X, TWO_PI), _arc(angle=TWO_PI)),
    "both 2pi - 1e-9, concentric coplanar": (_arc(ORIGIN, Z, 2, X, TWO_PI - T9), _arc(angle=TWO_PI - T9)),
    "generic": (_arc((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8, X, 2.5), UNIT_ARC),
}
ROUND_ARC_VARIANT_BASES = [
    "concentric coplanar",
    "coaxial above",
    "coaxial above, larger",
    "generic",
    "start end on the circle's axis",
    "start end on the disk's axis",
    "the ring's closest point 1e-9 past the start",
    "linked",
    "over the gap, lifted",
]

CIRCLE_ANNULUS_SCENES = {
    "in the hole, coplanar": (_c((0.1, 0.05, 0), Z, 0.3), UNIT_ANNULUS),
    "in the hole, concentric coplanar": (_c(ORIGIN, Z, 0.25), UNIT_ANNULUS),
    "in the hole, 1e-9 from the inner rim": (_c(ORIGIN, Z, 0.5 - T9), UNIT_ANNULUS),
    "in the hole, lifted": (_c((0.1, 0.05, 0.5), Z, 0.3), UNIT_ANNULUS),
    "over the hole, concentric": (_c((0, 0, 0.5), Z, 0.25), UNIT_ANNULUS),
    "on the inner rim": (_c(ORIGIN, Z, 0.5), UNIT_ANNULUS),
    "coplanar crossing the inner rim": (_c((0.5, 0, 0), Z, 0.25), UNIT_ANNULUS),
    "near-coplanar 1e-9 in the hole": (_c(ORIGIN, _tilt(T9), 0.25), UNIT_ANNULUS),
    "perpendicular in the hole": (_c(ORIGIN, X, 0.3), UNIT_ANNULUS),
    "linked through the hole and the ring": (_c((0.25, 0, 0), Y, 0.5), UNIT_ANNULUS),
    "coaxial above, over the ring": (_c((0, 0, 0.5), Z, 0.75), UNIT_ANNULUS),
    "coaxial above, outside": (_c((0, 0, 0.5), Z, 1.5), UNIT_ANNULUS),
    "coplanar touching the outer rim": (_c((2, 0, 0), Z, 1), UNIT_ANNULUS),
    "concentric coplanar outside": (_c(ORIGIN, Z, 2), UNIT_ANNULUS),
    "generic": (_c((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8), UNIT_ANNULUS),
}
DISK_ANNULUS_SCENES = {
    "lying in the hole, coplanar": (_d((0.1, 0.05, 0), Z, 0.3), UNIT_ANNULUS),
    "in the hole, concentric coplanar": (_d(ORIGIN, Z, 0.25), UNIT_ANNULUS),
    "in the hole, 1e-9 from the inner rim": (_d(ORIGIN, Z, 0.5 - T9), UNIT_ANNULUS),
    "over the hole, lifted": (_d((0, 0, 0.5), Z, 0.25), UNIT_ANNULUS),
    "covering the hole, coplanar": (_d(ORIGIN, Z, 0.75), UNIT_ANNULUS),
    "covering the hole, 1e-9 above": (_d((0, 0, T9), Z, 0.75), UNIT_ANNULUS),
    "perpendicular in the hole": (_d(ORIGIN, X, 0.3), UNIT_ANNULUS),
    "perpendicular through the ring": (_d(ORIGIN, X, 0.6), UNIT_ANNULUS),
    "perpendicular touching the ring's face": (_d((0.75, 0, 0.5), X, 0.5), UNIT_ANNULUS),
    "coplanar overlapping the ring": (_d((1.2, 0, 0), Z, 0.5), UNIT_ANNULUS),
    "near-coplanar 1e-9 in the hole": (_d(ORIGIN, _tilt(T9), 0.25), UNIT_ANNULUS),
    "parallel 1e-9 above, overlapping": (_d((0.5, 0, T9), Z, 1), UNIT_ANNULUS),
    "generic": (_d((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8), UNIT_ANNULUS),
}
ARC_ANNULUS_SCENES = {
    "in the hole, coplanar": (_arc(ORIGIN, Z, 0.25), UNIT_ANNULUS),
    "start end on the inner rim, in the hole": (_arc((0.25, 0, 0), Z, 0.25, X, math.pi), UNIT_ANNULUS),
    "start end 1e-9 inside the inner rim": (_arc((0.25 - T9, 0, 0), Z, 0.25, X, math.pi), UNIT_ANNULUS),
    "over the hole, lifted": (_arc((0, 0, 0.5), Z, 0.25, X, math.pi), UNIT_ANNULUS),
    "perpendicular in the hole": (_arc(ORIGIN, X, 0.3, Z, math.pi), UNIT_ANNULUS),
    "perpendicular, far end touching the ring's face": (_arc((0.75, 0, 0.5), Y, 0.5, Z, math.pi), UNIT_ANNULUS),
    "perpendicular, far end 1e-9 above the ring's face": (_arc((0.75, 0, 0.5 + T9), Y, 0.5, Z, math.pi), UNIT_ANNULUS),
    "concentric coplanar outside": (_arc(ORIGIN, Z, 2), UNIT_ANNULUS),
    "whole (angle 2pi), in the hole": (_arc((0.1, 0.05, 0), Z, 0.3, X, TWO_PI), UNIT_ANNULUS),
    "generic": (_arc((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.8, X, 2.5), UNIT_ANNULUS),
}
ANNULUS_ANNULUS_SCENES = {
    "coplanar overlapping": (_ann((1.2, 0, 0)), UNIT_ANNULUS),
    "concentric coplanar, nested rings": (_ann(inner=1.5, outer=2), UNIT_ANNULUS),
    "concentric coplanar, in the other's hole": (_ann(inner=0.1, outer=0.25), UNIT_ANNULUS),
    "concentric coplanar, the same": (UNIT_ANNULUS, UNIT_ANNULUS),
    "concentric coplanar, 1e-9 apart": (_ann(inner=1 + T9, outer=2), UNIT_ANNULUS),
    "coplanar, in the other's hole": (_ann((0.1, 0.05, 0), Z, 0.1, 0.3), UNIT_ANNULUS),
    "stacked coaxial": (_ann((0, 0, 0.5)), UNIT_ANNULUS),
    "stacked coaxial, rings apart": (_ann((0, 0, 0.5), Z, 1.5, 2), UNIT_ANNULUS),
    "parallel 1e-9 apart, overlapping": (_ann((0.5, 0, T9)), UNIT_ANNULUS),
    "near-coplanar 1e-9 concentric": (_ann(ORIGIN, _tilt(T9, "y"), 1.5, 2), UNIT_ANNULUS),
    "perpendicular in the hole": (_ann(ORIGIN, X, 0.1, 0.3), UNIT_ANNULUS),
    "perpendicular through the ring": (_ann((0.75, 0, 0), Y, 0.1, 0.2), UNIT_ANNULUS),
    "linked, through the hole and past the rim": (_ann((1.0, 0, 0), Y, 0.7, 0.9), UNIT_ANNULUS),
    "generic": (_ann((1.5, 1, 1.2), (0.3, 0.8, 0.4), 0.3, 0.8), UNIT_ANNULUS),
}
ROUND_ANNULUS_VARIANT_BASES = [
    "in the hole, coplanar",
    "lying in the hole, coplanar",
    "perpendicular in the hole",
    "coaxial above, outside",
    "over the hole, lifted",
    "coplanar, in the other's hole",
    "stacked coaxial",
    "generic",
]
BEZIER_VARIANT_BASES = [
    "straight, tangent in plane",
    "straight, along the axis",
    "parabola touching the center",
    "wavy quintic",
]
_ROUND_TARGETS = {"circle": UNIT_CIRCLE, "disk": UNIT_DISK, "arc": UNIT_ARC, "annulus": UNIT_ANNULUS}
_PAIR_SCENES = {
    "circle-arc": CIRCLE_ARC_SCENES,
    "disk-arc": DISK_ARC_SCENES,
    "arc-arc": ARC_ARC_SCENES,
    "circle-annulus": CIRCLE_ANNULUS_SCENES,
    "disk-annulus": DISK_ANNULUS_SCENES,
    "arc-annulus": ARC_ANNULUS_SCENES,
    "annulus-annulus": ANNULUS_ANNULUS_SCENES,
}


def _with_radius(shape, r):
    """The local round, arc or annulus with outer radius r (an annulus keeps its ratio)."""
    if shape[0] == "annulus":
        return shape[:3] + (shape[3] * r / shape[4], r)
    return shape[:3] + (r,) + shape[4:]


def _variants(scenes, target, bases):
    """(name, a, b) of the scenes named in bases (or around them: 'through: ...') against each
    variant of the arc or annulus `target` (its kind's)."""
    variants = ARC_VARIANTS if target == "arc" else ANNULUS_VARIANTS
    out = []
    for n, a in scenes.items():
        if n in bases or any(n.endswith(": " + x) for x in bases):
            out += [(f"{n} {{{vname}}}", a, v) for vname, v in variants.items()]
    return out


def hard_scenes(kind):
    """[(name, a, b, scale)] in local coordinates, before placement. A coplanar kind: its base
    kind's scenes that lie in the arc's plane."""
    if _coplanar_kind(kind):
        base = kind[: -len("-coplanar")]
        return [scene for scene in hard_scenes(base) if _in_the_arc_plane(scene[1], scene[2])]
    a, b = shapes_of(kind)
    out = []
    if a in LINEAR:
        rnd = _ROUND_TARGETS[b]
        if b == "arc":
            scenes = linear_local_scenes(a, {**LINE_SCENES, **ARC_LINES}, {**POINT_SCENES, **ARC_POINTS})
        elif b == "annulus":
            scenes = linear_local_scenes(a, {**LINE_SCENES, **ANNULUS_LINES}, {**POINT_SCENES, **ANNULUS_POINTS})
        else:
            scenes = linear_local_scenes(a)
        out += [(n, s, rnd, 1.0) for n, s in scenes.items()]
        for base in RADIUS_SCENES if a != "point" else ["on the axis", "generic", "on the rim"]:
            names = [n for n in scenes if n == base or n.endswith(": " + base)]
            for n in names:
                for vname, (s, r) in RADIUS_VARIANTS.items():
                    round_shape = _with_radius(rnd, r)  # shape_values scales it by s
                    out.append((f"{n} [{vname}]", scenes[n], round_shape, s))
        if b in ("arc", "annulus"):
            bases = ARC_VARIANT_BASES if b == "arc" else ANNULUS_VARIANT_BASES
            out += [(n, x, y, 1.0) for n, x, y in _variants(scenes, b, bases)]
    elif kind in _PAIR_SCENES:
        scenes = _PAIR_SCENES[kind]
        out = [(n, x, y, 1.0) for n, (x, y) in scenes.items()]
        bases = ROUND_ARC_VARIANT_BASES if b == "arc" else ROUND_ANNULUS_VARIANT_BASES
        standard = {n: x for n, (x, y) in scenes.items() if y == _ROUND_TARGETS[b]}  # against the local one
        out += [(n, x, y, 1.0) for n, x, y in _variants(standard, b, bases)]
    elif kind == "circle-circle":
        out = [(n, x, y, 1.0) for n, (x, y) in CIRCLE_CIRCLE_SCENES.items()]
    elif kind == "circle-disk":
        out = [(n, x, y, 1.0) for n, (x, y) in CIRCLE_DISK_SCENES.items()]
    elif kind == "disk-disk":
        out = [(n, x, y, 1.0) for n, (x, y) in DISK_DISK_SCENES.items()]
    elif kind == "bezier-bezier":
        # tests/pairs/test_bezier_bezier.py's hard pairs: crossing, nearly touching, tangent,
        # parallel and identical curves, big against small, translated, degenerate curves
        out = [(scene[0], ("bezier", scene[1]), ("bezier", scene[2]), 1.0) for scene in bezier_cases.hard_scenes()]
    elif a == "bezier":
        rnd = _ROUND_TARGETS[b]
        out = [(n, ("bezier", pts), rnd, 1.0) for n, pts in BEZIER_SCENES.items()]
        if b in ("arc", "annulus"):
            curves = {n: ("bezier", pts) for n, pts in BEZIER_SCENES.items()}
            out += [(n, x, y, 1.0) for n, x, y in _variants(curves, b, BEZIER_VARIANT_BASES)]
    return out


def hard_cases(kind):
    out = []
    for name, a, b, s in hard_scenes(kind):
        # Radius variants are not translated: a radius of 1e-9 at 1e8 (ulp 1.5e-8) asks for an
        # absolute error below the rounding of the line's own anchor, in any precision.
        placements = [("z", 0.0), ("rot", 0.0)] if "[" in name else PLACEMENTS
        for orient, off in placements:
            tag = orient + ("" if off == 0 else f" +{off:.0e}")
            out.append(Case(kind, "hard", f"{name} ({tag})", scene_values(a, b, orient, off, s)))
    return out


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def _random_coplanar_cases(kind, n, rng):
    """Shape a in the plane of a random arc (formed in double: in the plane to rounding)."""
    a, _ = shapes_of(kind)
    out = []
    for i in range(n):
        c, nrm = rng.normal(size=3), rng.normal(size=3) * (1.0 if rng.random() < 0.5 else rng.uniform(0.1, 10.0))
        e1 = _unit(np.cross(nrm, rng.normal(size=3)))
        e2 = np.cross(_unit(nrm), e1)

        def at(scale):
            x, y = rng.normal(scale=scale, size=2)
            return c + x * e1 + y * e2

        arc = ("arc", c, nrm, rng.uniform(0.2, 2.0), rng.normal(size=3), rng.uniform(0.2, TWO_PI))
        if a == "point":
            sa = ("point", at(1.5))
        elif a in ("line", "ray"):
            sa = (a, at(1.5), at(1.0) - c)
        elif a == "segment":
            p0 = at(1.5)
            sa = ("segment", p0, p0 + at(1.5) - c)
        else:
            sa = ("circle", at(1.5), nrm * (1.0 if rng.random() < 0.5 else -2.0), rng.uniform(0.2, 2.0))
        out.append(Case(kind, "random", f"random {i:03d}", scene_values(sa, arc)))
    return out


def random_cases(kind, n):
    rng = np.random.default_rng(7000 + KINDS.index(kind))
    if _coplanar_kind(kind):
        return _random_coplanar_cases(kind, n, rng)
    a, b = shapes_of(kind)
    out = []
    for i in range(n):
        c = rng.normal(size=3)
        nrm = rng.normal(size=3) * (1.0 if rng.random() < 0.5 else rng.uniform(0.1, 10.0))
        rb = (b, c, nrm, rng.uniform(0.2, 2.0))
        if a == "point":
            sa = ("point", c + rng.normal(scale=1.5, size=3))
        elif a in ("line", "ray"):
            sa = (a, c + rng.normal(scale=1.5, size=3), rng.normal(size=3))
        elif a == "segment":
            p0 = c + rng.normal(scale=1.5, size=3)
            sa = ("segment", p0, p0 + rng.normal(scale=1.5, size=3))
        elif a in ROUND:
            sa = (a, c + rng.uniform(-2, 2, 3), rng.normal(size=3), rng.uniform(0.2, 2.0))
        elif a == "arc":  # a random start and an angle in [0.2, 2 pi)
            sa = (
                a,
                c + rng.uniform(-2, 2, 3),
                rng.normal(size=3),
                rng.uniform(0.2, 2.0),
                rng.normal(size=3),
                rng.uniform(0.2, TWO_PI),
            )
        elif a == "annulus":  # a hole of 5 to 95 % of the outer radius
            outer = rng.uniform(0.2, 2.0)
            sa = (a, c + rng.uniform(-2, 2, 3), rng.normal(size=3), outer * rng.uniform(0.05, 0.95), outer)
        else:
            k = 2 + i % 7  # degrees 1..7
            sa = ("bezier", [c + rng.uniform(-2, 2, 3) for _ in range(k)])
        if b == "bezier":
            k = 2 + (3 * i + 2) % 7
            rb = ("bezier", [c + rng.uniform(-1, 1, 3) + rng.uniform(-2, 2, 3) for _ in range(k)])
        elif b == "arc":
            rb = rb + (rng.normal(size=3), rng.uniform(0.2, TWO_PI))
        elif b == "annulus":
            rb = (b, c, nrm, rb[3] * rng.uniform(0.05, 0.95), rb[3])
        out.append(Case(kind, "random", f"random {i:03d}", scene_values(sa, rb)))
    return out


def _flat(shape, data):
    """A differential case's shape data in this module's layout. The differential test stores an
    annulus as (center, normal, outer, inner) (differential.make_shape), this layout as (center,
    normal, inner, outer)."""
    if shape == "bezier":
        return [float(len(data))] + [float(x) for p in data for x in p]
    if shape == "annulus":
        return [float(x) for x in data[:6]] + [float(data[7]), float(data[6])]
    return [float(x) for x in data]


def differential_cases(kinds, per_pair=2, seed=2026):
    """The adversarial families of the standing differential test (circledist_cases/differential/: the
    classes the exactness issue listed and those found since: nearly coincident circles, lines
    nearly along the axis, far origins, extreme radius ratios, near-touching disks, huge
    circles, far-reaching Bezier curves, ...), `per_pair` cases per kind pair of each family,
    as hard cases."""
    from . import differential as D

    out = []
    for family, (pairs, _) in D.FAMILIES.items():
        if family == "random" or family.endswith("_random"):  # the random ones: not adversarial
            continue
        for i in range(per_pair * len(pairs)):
            c = D.generate_one(family, seed, i)
            (ka, va), (kb, vb) = (c["a"], c["a_data"]), (c["b"], c["b_data"])
            if f"{ka}-{kb}" not in KINDS:
                (ka, va), (kb, vb) = (kb, vb), (ka, va)
            kind = f"{ka}-{kb}"
            if kind in kinds:
                out.append(Case(kind, "hard", f"{family} ({c['id']})", tuple(_flat(ka, va) + _flat(kb, vb))))
    return out


def generate_cases(n_random, kinds):
    """Every kind's random cases, then its hard ones, then the differential families' hard cases."""
    cases = []
    for kind in kinds:
        cases += random_cases(kind, n_random)
        cases += hard_cases(kind)
    return cases + differential_cases(kinds)


# ------------------------------------------------------------------------------------------------
# errors against the references
# ------------------------------------------------------------------------------------------------
def parse_distance(text):
    """An mpf from the program's exact hexfloat (glibc %La, e.g. 0xc.ccccccccccccccdp-7) or from a
    decimal string; None for NaN, inf or garbage."""
    if text is None:
        return None
    t = text.strip().lower()
    if t.lstrip("+-").startswith("0x"):
        sign = -1 if t.startswith("-") else 1
        mant, _, exp = t.lstrip("+-")[2:].partition("p")
        whole, _, frac = mant.partition(".")
        digits = whole + frac
        m = int(digits, 16) if digits else 0
        return sign * mp.ldexp(mpf(m), int(exp or 0) - 4 * len(frac))
    try:
        d = mpf(t)
    except (ValueError, TypeError):
        return None
    return d if mp.isfinite(d) else None


def relative_error(d_text, ref, radius):
    """|d - ref| / max(ref, radius) in 50 digits; inf for NaN / inf / missing."""
    d = parse_distance(d_text)
    if d is None:
        return math.inf
    denom = max(ref, mpf(radius))
    err = abs(d - ref)
    if denom == 0:
        return 0.0 if err == 0 else math.inf
    return float(err / denom)
