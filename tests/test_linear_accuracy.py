"""Points, lines, rays and segments against each other, against an independent 50-digit reference.

The reference (circledist_cases/reference_linear.py, shared with the differential test) minimizes
over one parameter: s -> dist(A(s), B), the distance from a point of A to the piece B (its
projection clamped, in mpmath), is convex in s, so a bracket search (golden section) finds its minimum;
s = tan(phi) maps an infinite interval onto a finite one (a monotone change of variable keeps the
function unimodal). Nothing of the library is used.

The bar: |error| <= 1e-12 x max(true distance, the query's size), the size being the largest
distance from A's first point to any point that defines the query (origins, segment ends):
translating a scene does not change it. Families: random pieces; nearly parallel pieces that
cross or pass at a tiny distance (angles 1e-2 .. 1e-12, where the plain cross product of the
directions cancels); scenes 1e6 .. 1e12 from the world's origin; zero-length segments; points on
the pieces.
"""

import itertools

import mpmath as mp
import numpy as np
import pytest

import circledist as cd
from circledist_cases import reference_linear as RL

KINDS = RL.KINDS
PAIRS = [(a, b) for a, b in itertools.combinations_with_replacement(KINDS, 2)]
piece, point_to_piece, reference = RL.piece, RL.point_to_piece, RL.reference


def make(kind, p, q):
    return {"point": lambda: cd.Point(p), "line": lambda: cd.Line(p, q), "ray": lambda: cd.Ray(p, q),
            "segment": lambda: cd.Segment(p, q)}[kind]()


def size(ka, a, kb, b):
    return RL.query_size(ka, np.concatenate(a), kb, np.concatenate(b))


def rotate(v, axis, angle):
    axis = axis / np.linalg.norm(axis)
    return v * np.cos(angle) + np.cross(axis, v) * np.sin(angle) + axis * axis.dot(v) * (1 - np.cos(angle))


def cases():
    rng = np.random.default_rng(20261126)
    out = []
    for ka, kb in PAIRS:
        for i in range(6):  # random
            out.append(("random", ka, (rng.normal(size=3), rng.normal(size=3)), kb,
                        (rng.normal(size=3), rng.normal(size=3))))
        for angle in (1e-2, 1e-5, 1e-8, 1e-12):  # nearly parallel, crossing or just apart
            for gap in (0.0, 1e-15, 1e-9):
                x = rng.normal(size=3)
                u = rng.normal(size=3)
                v = rotate(u, np.cross(u, rng.normal(size=3)), angle)
                normal = np.cross(u, v)
                normal = normal / np.linalg.norm(normal) if np.linalg.norm(normal) > 0 else rng.normal(size=3)
                sa, sb = rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5)
                pa, pb = x - sa * u, x - sb * v + gap * normal
                qa = pa + 2 * sa * u if ka == "segment" else u
                qb = pb + 2 * sb * v if kb == "segment" else v
                out.append((f"parallel {angle:g} gap {gap:g}", ka, (pa, qa), kb, (pb, qb)))
        for shift in (1e6, 1e9, 1e12):  # far from the world's origin
            t = rng.normal(size=3) * shift
            pa, pb = t + rng.normal(size=3), t + rng.normal(size=3)
            qa = pa + rng.normal(size=3) if ka == "segment" else rng.normal(size=3)
            qb = pb + rng.normal(size=3) if kb == "segment" else rng.normal(size=3)
            out.append((f"far {shift:g}", ka, (pa, qa), kb, (pb, qb)))
        if "segment" in (ka, kb):  # a zero-length segment
            p = rng.normal(size=3)
            a = (p, p.copy()) if ka == "segment" else (rng.normal(size=3), rng.normal(size=3))
            b = (p + 0.5, p + 0.5) if kb == "segment" else (rng.normal(size=3), rng.normal(size=3))
            out.append(("zero-length", ka, a, kb, b))
        if kb != "point":  # a point of B's piece as A's first point
            pb, qb = rng.normal(size=3), rng.normal(size=3)
            on = pb + 0.3 * (qb - pb if kb == "segment" else qb)
            a = (on, on + rng.normal(size=3)) if ka == "segment" else (on, rng.normal(size=3))
            out.append(("on the piece", ka, a, kb, (pb, qb)))
    # Found by a random search: crossing segments 1e-5 rad apart answered 1.5e-11 for 5.8e-18.
    out.append(("found: crossing segments", "segment",
                ([0.469088546821133, 0.026205966427920835, 1.8590472355014187],
                 [-1.0934957465634532, 0.7561085485942733, 0.22038671559146072]), "segment",
                ([1.9660258787094098, -0.6730321024438254, 3.428864695992459],
                 [-0.3778505617265781, 0.4218217708477871, 0.9708739150794374])))
    return [(name, ka, tuple(np.asarray(x, float) for x in a), kb, tuple(np.asarray(x, float) for x in b))
            for name, ka, a, kb, b in out]


CASES = cases()


@pytest.mark.parametrize("case", CASES, ids=[f"{c[1]}-{c[3]}-{c[0]}-{i}" for i, c in enumerate(CASES)])
def test_linear_pairs_against_the_reference(case):
    name, ka, a, kb, b = case
    exact = reference(piece(ka, *a), piece(kb, *b))
    truth = float(exact)
    bar = 1e-12 * max(truth, size(ka, a, kb, b))
    A, B = make(ka, *a), make(kb, *b)
    for first, second in ((A, B), (B, A)):  # long double: the same inputs, the 1e-15 bar
        d = cd.distance(first, second, precision="longdouble")
        assert abs(mp.mpf(repr(float(d))) + mp.mpf(repr(float(d - np.longdouble(float(d))))) - exact) <= 1e-15 * max(truth, size(ka, a, kb, b)), f"{name}: long double {d!r}"
    for solver in ("bracketing", "companion"):
        for first, second, swapped in ((A, B, False), (B, A, True)):
            d = float(cd.distance(first, second, solver=solver))
            r = cd.closest_points(first, second, solver=solver)
            assert abs(d - truth) <= bar, f"{name}: distance {d!r}, truth {truth!r}"
            assert float(r.distance) == d, "closest_points().distance differs from distance()"
            pa, pb = (r.point_b, r.point_a) if swapped else (r.point_a, r.point_b)
            on_a = float(point_to_piece(tuple(mp.mpf(float(x)) for x in pa), piece(ka, *a)))
            on_b = float(point_to_piece(tuple(mp.mpf(float(x)) for x in pb), piece(kb, *b)))
            # The points are rounded to doubles: they lie on their pieces within that rounding.
            slack = bar + 4 * np.finfo(float).eps * max(np.abs(pa).max(), np.abs(pb).max())
            assert on_a <= slack and on_b <= slack, f"{name}: points off their pieces by {on_a:.3g}, {on_b:.3g}"
            assert abs(float(np.linalg.norm(np.subtract(pa, pb))) - truth) <= slack
