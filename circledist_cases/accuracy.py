"""The accuracy cases of every query kind: value layouts, placement, hard scenes, random cases
and their 50-digit references.

Used by bench/accuracy_vs_time.py (which times and judges them for every root policy and
precision through bench/accuracy_vs_time.cpp) and by the stability sweeps (sweeps.py).

A case is a kind ("line-circle", ...) and the flat tuple of its two shapes' values, the layout
bench/accuracy_vs_time.cpp reads: point (x, y, z); line, ray (origin, direction); segment (p0,
p1); circle, disk (center, normal, radius); bezier (k, then k control points). Hard scenes are
written in a local frame (the round shape is the unit circle or disk: center 0, normal +z) and
placed in the world: in that frame, under a generic rotation, translated by 1e6 and 1e8, plus
radius and scale variants. References (``reference_distance``) are of the exact float inputs, by
an independent method: reference.py and reference_round.py minimise a closed-form point-to-shape
distance over ONE parameter in mpmath; no polynomial, no root finding.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from mpmath import mp, mpf

from . import bezier_cases
from . import reference as LREF  # linear shapes vs circle / disk
from . import reference_bezier as BREF  # Bezier against Bezier
from . import reference_round as RREF  # circle, disk and Bezier kinds
from .scenes import SHARED_LINES, SHARED_POINTS, SHARED_RAYS, SHARED_SEGMENTS

mp.dps = 50

KINDS = ["point-circle", "point-disk", "line-circle", "ray-circle", "segment-circle", "line-disk",
         "ray-disk", "segment-disk", "circle-circle", "circle-disk", "disk-disk", "bezier-disk",
         "bezier-circle", "bezier-bezier"]
LINEAR = ("point", "line", "ray", "segment")
ROUND = ("circle", "disk")
SHAPE_SIZE = {"point": 3, "line": 6, "ray": 6, "segment": 6, "circle": 7, "disk": 7}


def shapes_of(kind):
    a, b = kind.split("-")
    return a, b


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
    return [tuple(values[1 + 3 * i: 4 + 3 * i]) for i in range(int(values[0]))]


def bar_scale(kind, values):
    """The scale the bar multiplies besides the distance: the largest radius in the query, or for
    two curves the larger curve size (their control polygons' extent, as tests/test_bezier_bezier.py
    and reference_bezier.py take it)."""
    (a, va), (b, vb) = split_values(kind, values)
    if a == "bezier" and b == "bezier":
        return max(BREF.curve_size(_control_points(va)), BREF.curve_size(_control_points(vb)))
    out = 0.0
    for shape, vals in ((a, va), (b, vb)):
        if shape in ROUND:
            out = max(out, abs(float(vals[6])))
    return out


def to_float32(values):
    """The float run's inputs: every double rounded to the nearest float (as the C++ does)."""
    return tuple(float(np.float32(v)) for v in values)


# ------------------------------------------------------------------------------------------------
# references (independent: one-parameter minimisation of closed forms, no polynomial roots)
# ------------------------------------------------------------------------------------------------
def reference_distance(kind, values):
    """50-digit distance of the scene the float inputs `values` describe exactly (an mpf)."""
    (a, va), (b, vb) = split_values(kind, values)
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


ROTATION = _rotation((0.36, -0.48, 0.8), 0.9)     # a generic rotation: every coordinate rounds
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
RADIUS_SCENES = ["tangent in plane", "tangent lifted 1e-6", "on the axis", "crosses the plane on the rim",
                 "generic"]
# (scale of the whole scene, local radius)
RADIUS_VARIANTS = {"scene x1e-9": (1e-9, 1.0), "scene x1e9": (1e9, 1.0), "radius 1e-9": (1.0, 1e-9),
                   "radius 1e9": (1.0, 1e9)}


def _sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def _axpy(a, x, y):
    return tuple(a * xi + yi for xi, yi in zip(x, y))


def linear_local_scenes(lin):
    """{name: local shape} of one linear kind."""
    out = {}
    if lin == "point":
        return {n: ("point", p) for n, p in POINT_SCENES.items()}
    for name, (o, d) in LINE_SCENES.items():
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
    "degree 7 over the disk": [(-1.2, -0.8, 0.4), (-0.6, 1.1, -0.2), (0.1, -1.3, 0.5), (0.8, 1.2, 0.1),
                               (1.3, -0.4, -0.3), (0.4, 0.9, 0.6), (-0.5, 0.2, 0.2), (1.1, 0.1, 0.3)],
}


def hard_scenes(kind):
    """[(name, a, b, scale)] in local coordinates, before placement."""
    a, b = shapes_of(kind)
    out = []
    if a in LINEAR:
        rnd = UNIT_CIRCLE if b == "circle" else UNIT_DISK
        scenes = linear_local_scenes(a)
        out += [(n, s, rnd, 1.0) for n, s in scenes.items()]
        for base in RADIUS_SCENES if a != "point" else ["on the axis", "generic", "on the rim"]:
            names = [n for n in scenes if n == base or n.endswith(": " + base)]
            for n in names:
                for vname, (s, r) in RADIUS_VARIANTS.items():
                    round_shape = (rnd[0], rnd[1], rnd[2], r)  # shape_values scales it by s
                    out.append((f"{n} [{vname}]", scenes[n], round_shape, s))
    elif kind == "circle-circle":
        out = [(n, x, y, 1.0) for n, (x, y) in CIRCLE_CIRCLE_SCENES.items()]
    elif kind == "circle-disk":
        out = [(n, x, y, 1.0) for n, (x, y) in CIRCLE_DISK_SCENES.items()]
    elif kind == "disk-disk":
        out = [(n, x, y, 1.0) for n, (x, y) in DISK_DISK_SCENES.items()]
    elif kind == "bezier-bezier":
        # tests/test_bezier_bezier.py's hard pairs: crossing, nearly touching, tangent,
        # parallel and identical curves, big against small, translated, degenerate curves
        out = [(scene[0], ("bezier", scene[1]), ("bezier", scene[2]), 1.0) for scene in bezier_cases.hard_scenes()]
    elif a == "bezier":
        rnd = UNIT_CIRCLE if b == "circle" else UNIT_DISK
        out = [(n, ("bezier", pts), rnd, 1.0) for n, pts in BEZIER_SCENES.items()]
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


def random_cases(kind, n):
    rng = np.random.default_rng(7000 + KINDS.index(kind))
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
        else:
            k = 2 + i % 7  # degrees 1..7
            sa = ("bezier", [c + rng.uniform(-2, 2, 3) for _ in range(k)])
        if b == "bezier":
            k = 2 + (3 * i + 2) % 7
            rb = ("bezier", [c + rng.uniform(-1, 1, 3) + rng.uniform(-2, 2, 3) for _ in range(k)])
        out.append(Case(kind, "random", f"random {i:03d}", scene_values(sa, rb)))
    return out


def _flat(shape, data):
    if shape == "bezier":
        return [float(len(data))] + [float(x) for p in data for x in p]
    return [float(x) for x in data]


def differential_cases(kinds, per_pair=2, seed=2026):
    """The adversarial families of the standing differential test (circledist_cases/differential.py: the
    classes the exactness issue listed and those found since: nearly coincident circles, lines
    nearly along the axis, far origins, extreme radius ratios, near-touching disks, huge
    circles, far-reaching Bezier curves, ...), `per_pair` cases per kind pair of each family,
    as hard cases."""
    from . import differential as D

    out = []
    for family, (pairs, _) in D.FAMILIES.items():
        if family == "random":
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
