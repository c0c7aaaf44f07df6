"""Points, lines, rays and segments against each other, against an independent 50-digit reference.

The reference (circledist_cases/reference_linear.py, shared with the differential test) minimizes
over one parameter: s -> dist(A(s), B), the distance from a point of A to the piece B (its
projection clamped, in mpmath), is convex in s, so a bracket search (golden section) finds its minimum;
s = tan(phi) maps an infinite interval onto a finite one (a monotone change of variable keeps the
function unimodal). Nothing of the library is used.

The bar: |error| <= 1e-12 x max(true distance, 1e-12 x the query's size), the size being the
largest distance from A's first point to any point that defines the query (origins, segment
ends): the answer is held to its own size wherever the origins lie, and only pieces that touch
within the inputs' rounding to the floor. Families: random pieces; nearly parallel pieces that
cross or pass at a tiny distance (angles 1e-2 .. 1e-12, where the plain cross product of the
directions cancels); scenes 1e6 .. 1e12 from the world's origin; origins and segment ends 1e6 ..
1e12 along the pieces from where they pass (crossing, or parallel within 1e-8 .. 1e-16 rad);
lines and rays 1e-9 .. 1e-13 rad apart whose origins lie near each other and far from where they
pass;
zero-length segments; points on the pieces.
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
    return {
        "point": lambda: cd.Point(p),
        "line": lambda: cd.Line(p, q),
        "ray": lambda: cd.Ray(p, q),
        "segment": lambda: cd.Segment(p, q),
    }[kind]()


def floor(ka, a, kb, b):
    return RL.bar_scale(ka, np.concatenate(a), kb, np.concatenate(b))


def rotate(v, axis, angle):
    axis = axis / np.linalg.norm(axis)
    return v * np.cos(angle) + np.cross(axis, v) * np.sin(angle) + axis * axis.dot(v) * (1 - np.cos(angle))


def cases():
    rng = np.random.default_rng(20261126)
    out = []
    for ka, kb in PAIRS:
        for i in range(6):  # random
            out.append(
                ("random", ka, (rng.normal(size=3), rng.normal(size=3)), kb, (rng.normal(size=3), rng.normal(size=3)))
            )
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
        for far in (1e6, 1e9, 1e12):  # origins / ends far along the pieces from where they pass
            for angle in (1.0, 1e-8, 1e-16):
                x = rng.normal(size=3)
                u = rng.normal(size=3)
                u /= np.linalg.norm(u)
                v = rotate(u, np.cross(u, rng.normal(size=3)), angle) if angle < 1 else rng.normal(size=3)
                gap = rng.normal(size=3) * 10.0 ** rng.uniform(-9, 0)
                pieces = []
                for kind, y, d in ((ka, x, u), (kb, x + gap, v)):
                    sign = rng.choice([-1.0, 1.0])
                    if kind == "point":
                        pieces.append((y, y))
                    elif kind == "segment":  # one end far, the other near or far beyond y
                        other = far * rng.uniform(0.5, 2) if rng.random() < 0.5 else rng.uniform(0.1, 2)
                        pieces.append((y - sign * far * d, y + sign * other * d))
                    else:  # a ray's origin behind y; a line's on either side
                        pieces.append((y - (1.0 if kind == "ray" else sign) * far * d, d))
                out.append((f"far origin {far:g} angle {angle:g}", ka, pieces[0], kb, pieces[1]))
        if "segment" not in (ka, kb) and "point" not in (ka, kb):
            for angle in (1e-9, 1e-13):  # nearly parallel, passing 1e-9 apart 1/angle from both origins
                u = rng.normal(size=3)
                v = rotate(u, np.cross(u, rng.normal(size=3)), angle)
                pa = rng.normal(size=3)
                normal = np.cross(u, v)
                normal /= np.linalg.norm(normal)
                across = np.cross(normal, u)  # in the pieces' plane: the lines meet 1e-3 / angle away
                pb = pa + 1e-3 * across / np.linalg.norm(across) + 1e-9 * normal
                out.append((f"far meeting angle {angle:g}", ka, (pa, u), kb, (pb, v)))
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
    # Found by the differential test (linear_far_origin/1/290, /235): a point 6e-9 from a segment
    # whose ends lie 1e11 and 1e8 away answered 1.7e-5; a ray and a segment 5e-17 rad apart, their
    # origin and far end 3e10 and 9e9 from where they pass 3.7e-7 apart, answered 3.5e-8.
    out.append(
        (
            "found: point by a long far segment",
            "point",
            ([0.8001554157507818, -0.3458700927461995, 0.13286317186295868], [0.0, 0.0, 0.0]),
            "segment",
            (
                [112221190684.01337, -61990910881.69316, -70779235551.27132],
                [-99936905.46298178, 55205080.01550244, 63031391.847861975],
            ),
        )
    )
    out.append(
        (
            "found: far ray and segment 5e-17 rad apart",
            "ray",
            (
                [10355145348.85256, -11762825922.486448, 29936564446.30502],
                [-0.0960963293781369, 0.10915968400308561, -0.2778129963567933],
            ),
            "segment",
            (
                [-0.7800725896139666, -0.9680412084446177, 1.9812839500368162],
                [-2881389669.7702622, 3273086367.5970874, -8330052798.097823],
            ),
        )
    )
    # Found by a random search: crossing segments 1e-5 rad apart answered 1.5e-11 for 5.8e-18.
    out.append(
        (
            "found: crossing segments",
            "segment",
            (
                [0.469088546821133, 0.026205966427920835, 1.8590472355014187],
                [-1.0934957465634532, 0.7561085485942733, 0.22038671559146072],
            ),
            "segment",
            (
                [1.9660258787094098, -0.6730321024438254, 3.428864695992459],
                [-0.3778505617265781, 0.4218217708477871, 0.9708739150794374],
            ),
        )
    )
    return [
        (name, ka, tuple(np.asarray(x, float) for x in a), kb, tuple(np.asarray(x, float) for x in b))
        for name, ka, a, kb, b in out
    ]


CASES = cases()


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES, ids=[f"{c[1]}-{c[3]}-{c[0]}-{i}" for i, c in enumerate(CASES)])
def test_linear_pairs_against_the_reference(case):
    name, ka, a, kb, b = case
    exact = reference(piece(ka, *a), piece(kb, *b))
    truth = float(exact)
    bar = 1e-12 * max(truth, floor(ka, a, kb, b))
    A, B = make(ka, *a), make(kb, *b)
    for first, second in ((A, B), (B, A)):  # long double: the same inputs, the 1e-15 bar
        d = cd.distance(first, second, precision="longdouble")
        assert abs(mp.mpf(repr(float(d))) + mp.mpf(repr(float(d - np.longdouble(float(d))))) - exact) <= 1e-15 * max(
            truth, floor(ka, a, kb, b)
        ), f"{name}: long double {d!r}"
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


def near_largest_cases():
    """Exact binary configurations near the largest doubles (review finding: a point 1 from a ray
    whose origin lies 1.5e308 away answered 0; the plain offset's rounding squared past the largest
    double, and the scene scaled down put the distance among the subnormals)."""
    out = []
    for x in (1e306, 1.5e308, 1.7e308):
        p = np.array([x, 0.0, 1.0])
        for kind, b in (
            ("ray", ([0.0, 0, 0], [1.9, 0, 0])),
            ("line", ([0.0, 0, 0], [1.9, 0, 0])),
            ("segment", ([0.0, 0, 0], [1.79e308, 0, 0])),
            ("segment", ([-x, 0, 0], [x, 0, 0])),
        ):
            out.append((f"point {x:g} from {kind}", "point", (p, p), kind, tuple(np.asarray(v) for v in b)))
            if kind != "segment" or b[0][0] == 0:  # (the line first: the reference's search runs along it)
                out.append(
                    (
                        f"a line across a {kind} at {x:g}",
                        "line",
                        (p, np.array([0.0, 1.0, 0.0])),
                        kind,
                        tuple(np.asarray(v) for v in b),
                    )
                )
    d, m = np.array([3.0, 4.0, 12.0]), np.array([4.0, -3.0, 0.0])  # d.m = 0
    for k in (1018, 1020):
        far = np.ldexp(1.0, k)
        for e in (-30, 0):
            p = np.ldexp(1.0, e) * m  # 5 h from the line through 0 along d
            for kind, b in (
                ("line", (-far * d, d)),
                ("ray", (-far * d, d)),
                ("segment", (-far * d, far / 2 * d)),
                ("segment", (-far * d, 0.25 * d)),
            ):
                out.append((f"point 2^{e} off a {kind} from 2^{k}", "point", (p, p), kind, b))
    return out


NEAR_LARGEST = near_largest_cases()


@pytest.mark.parametrize("case", NEAR_LARGEST, ids=[f"{c[1]}-{c[3]}-{i}" for i, c in enumerate(NEAR_LARGEST)])
def test_near_the_largest_doubles_held_to_the_distance(case):
    """These configurations are exact in binary, so the answer is held to 1e-12 of itself (the
    floor of the general bar, 1e-24 of the query's size, would allow anything here). The reference
    runs at 800 digits: the offsets cancel over more than 300 orders of magnitude; its search runs
    over A's parameter, whose minimum lies near A's origin here."""
    name, ka, a, kb, b = case
    with mp.workdps(800):
        truth = float(reference(piece(ka, *a), piece(kb, *b)))
    A, B = make(ka, *a), make(kb, *b)
    for first, second in ((A, B), (B, A)):
        for solver in ("bracketing", "companion"):
            d = float(cd.distance(first, second, solver=solver))
            assert abs(d - truth) <= 1e-12 * truth, f"{name}: distance {d!r}, truth {truth!r}"
            assert float(cd.closest_points(first, second, solver=solver).distance) == d
        d = float(cd.distance(first, second, precision="longdouble"))
        assert abs(d - truth) <= 1e-15 * truth, f"{name}: long double {d!r}, truth {truth!r}"
