"""Rays and segments that end at, or within rounding of, a stationary point of their line's
distance to a circle.

A ray or segment whose line has one local minimum over the ring is answered from the slope of
the distance at an end point, before the line's root is solved (docs/derivations/line_circle.md, "Before the
root"): rising at the first end, that end answers; falling at a segment's second end, that one.
The slope is 0 where an end sits at the line's minimum, and undefined where it sits on the
circle's axis (the distance's cusp): these tests put ends exactly there and at offsets from
1e-15 to 1e-3 on both sides, for lines in general position, lines crossing the axis, and lines
near the axis (where the line has a second minimum, and the slope is not asked), under every
solver policy, in double and long double. The reference is the 50-digit minimization over the
piece's parameter (circledist_cases/reference_linear_round.py), which uses no library code.
"""

import numpy as np
import pytest

import circledist as cd
from circledist_cases import reference_linear_round as ref

SOLVERS = ("bracketing", "companion", "polished", "eigen")
BARS = {"float64": 1e-12, "longdouble": 1e-15}
OFFSETS = (0.0, 1e-15, -1e-15, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3)
LENGTH = 0.7  # of each piece, in units of the line's direction


def _unit(v):
    return v / np.linalg.norm(v)


def _lines():
    """(name, origin, direction, circle data, the stationary parameter t0 on the line)."""
    rng = np.random.default_rng(20261126)
    out = []
    for i in range(8):
        c, n, radius = rng.normal(0, 1, 3), rng.normal(0, 1, 3), float(rng.uniform(0.5, 2))
        o, d = rng.normal(0, 1.5, 3), rng.normal(0, 1, 3)
        circle = tuple(map(float, c)) + tuple(map(float, n)) + (radius,)
        line = ref.reference("line", tuple(map(float, o)) + tuple(map(float, d)), "circle", circle)
        # The line's minimum as its parameter, from the reference's closest point.
        foot = np.array([float(x) for x in line.point_lin])
        out.append((f"general{i}", o, d, circle, float(np.dot(foot - o, d) / np.dot(d, d))))
    for i in range(4):
        # Through the axis at height h: the distance has a cusp (a local maximum) there.
        c, n, radius = rng.normal(0, 1, 3), _unit(rng.normal(0, 1, 3)), float(rng.uniform(0.5, 2))
        o, d = c + float(rng.normal(0, 1)) * n, rng.normal(0, 1, 3)
        out.append((f"axis{i}", o, d, tuple(map(float, c)) + tuple(map(float, n)) + (radius,), 0.0))
    for i in range(4):
        # Near the axis, tilted by 0.3: inside the astroid, two local minima.
        c, n, radius = rng.normal(0, 1, 3), _unit(rng.normal(0, 1, 3)), float(rng.uniform(0.5, 2))
        across = rng.normal(0, 1, 3)
        across -= np.dot(across, n) * n
        o, d = c + 0.05 * radius * _unit(across), n + 0.3 * _unit(np.cross(n, across))
        circle = tuple(map(float, c)) + tuple(map(float, n)) + (radius,)
        line = ref.reference("line", tuple(map(float, o)) + tuple(map(float, d)), "circle", circle)
        foot = np.array([float(x) for x in line.point_lin])
        out.append((f"near_axis{i}", o, d, circle, float(np.dot(foot - o, d) / np.dot(d, d))))
    return out


def _pieces():
    """(id, kind, data, circle data): pieces starting or ending near each line's stationary point."""
    out = []
    for name, o, d, circle, t0 in _lines():
        for offset in OFFSETS:
            t = t0 + offset
            at = o + t * d
            ahead, behind = o + (t + LENGTH) * d, o + (t - LENGTH) * d
            tag = f"{name}:{offset:+g}"
            out.append((f"{tag}:starts", "segment", tuple(map(float, at)) + tuple(map(float, ahead)), circle))
            out.append((f"{tag}:ends", "segment", tuple(map(float, behind)) + tuple(map(float, at)), circle))
            out.append((f"{tag}:ray_on", "ray", tuple(map(float, at)) + tuple(map(float, d)), circle))
            out.append((f"{tag}:ray_back", "ray", tuple(map(float, at)) + tuple(map(float, -d)), circle))
    return out


PIECES = _pieces()


@pytest.fixture(scope="module")
def references():
    return {case[0]: ref.reference(case[1], case[2], "circle", case[3]) for case in PIECES}


def _shapes(kind, data, circle, dtype):
    a = np.array(data, dtype=dtype)
    piece = cd.Segment(a[:3], a[3:]) if kind == "segment" else cd.Ray(a[:3], a[3:])
    c = np.array(circle, dtype=dtype)
    return piece, cd.Circle(c[:3], c[3:6], c[6])


@pytest.mark.slow
@pytest.mark.parametrize("precision", sorted(BARS))
@pytest.mark.parametrize("solver", SOLVERS)
def test_pieces_ending_at_stationary_points(solver, precision, references):
    dtype = np.longdouble if precision == "longdouble" else np.float64
    failures = []
    for case_id, kind, data, circle in PIECES:
        piece, ring = _shapes(kind, data, circle, dtype)
        expected = references[case_id]
        bar = BARS[precision] * float(expected.scale)
        got = cd.distance(piece, ring, solver=solver, precision=precision)
        closest = cd.closest_points(piece, ring, solver=solver, precision=precision)
        error = abs(float(got) - float(expected.distance))
        separation = float(
            np.linalg.norm(np.asarray(closest.point_a, np.longdouble) - np.asarray(closest.point_b, np.longdouble))
        )
        if error > bar or closest.distance != got or abs(separation - float(got)) > bar:
            failures.append(
                f"{case_id}: got {float(got)!r}, reference {float(expected.distance)!r}, "
                f"closest {float(closest.distance)!r}, separation {separation!r}"
            )
    assert not failures, f"{len(failures)} of {len(PIECES)}:\n" + "\n".join(failures[:10])


def test_batch_equals_scalar():
    """The batch of all pieces of one kind answers as the scalar calls do, to the bit."""
    for kind in ("segment", "ray"):
        chosen = [case for case in PIECES if case[1] == kind]
        data = np.array([case[2] for case in chosen])
        circles = np.array([case[3] for case in chosen])
        pieces = cd.Segment(data[:, :3], data[:, 3:]) if kind == "segment" else cd.Ray(data[:, :3], data[:, 3:])
        rings = cd.Circle(circles[:, :3], circles[:, 3:6], circles[:, 6])
        batch = cd.distance(pieces, rings)
        scalar = [cd.distance(*_shapes(kind, case[2], case[3], np.float64)) for case in chosen]
        assert np.array_equal(batch, np.array(scalar))


# A ray or segment can be closest at its line's other local minimum over the ring, which exists
# only for a line near the circle's axis (docs/derivations/line_circle.md, the second minimum).
# Its ring point must lie in the circle's plane to rounding however far above the plane the line
# passes: small-integer scenes (exact inputs) keep the lines that pass within R / 2 of the axis.
PLANE_ULPS = 8  # of the scene's largest coordinate or radius


def _near_axis_scenes(count=4000, seed=11):
    rng = np.random.default_rng(seed)
    n = 12 * count
    center = rng.integers(-3, 4, (n, 3)).astype(float)
    normal = rng.integers(-2, 3, (n, 3)).astype(float)
    radius = rng.integers(1, 4, n).astype(float)
    p, q = rng.integers(-3, 4, (n, 3)).astype(float), rng.integers(-3, 4, (n, 3)).astype(float)
    direction = q - p
    keep = np.any(normal != 0, axis=1) & np.any(direction != 0, axis=1)
    # the distance between the line and the axis (0 where they are parallel: kept out)
    across = np.cross(direction, normal)
    size = np.linalg.norm(across, axis=1)
    keep &= size > 0
    gap = np.abs(np.einsum("ij,ij->i", p - center, across)) / np.where(size > 0, size, 1)
    keep &= gap < radius / 2
    idx = np.flatnonzero(keep)[:count]
    return center[idx], normal[idx], radius[idx], p[idx], q[idx]


def _off_plane_in_ulps(points, center, normal, scale, precision):
    """|(X - C) . N| / |N| in long double (the inputs are exact in it), in ulps of `scale`."""
    ld = np.longdouble
    x, c, w = np.asarray(points, dtype=ld), center.astype(ld), normal.astype(ld)
    height = np.einsum("ij,ij->i", x - c, w) / np.sqrt(np.einsum("ij,ij->i", w, w))
    eps = np.finfo(ld if precision == "longdouble" else np.float64).eps
    return (np.abs(height) / (ld(eps) * scale.astype(ld))).astype(float)


@pytest.mark.parametrize("precision", ["float64", "longdouble"])
@pytest.mark.parametrize("target", ["circle", "annulus", "arc"])
@pytest.mark.parametrize("piece", ["ray", "segment"])
def test_rim_point_of_a_piece_near_the_axis_lies_in_the_plane(piece, target, precision):
    center, normal, radius, p, q = _near_axis_scenes()
    start = np.cross(normal, np.where(np.abs(normal[:, :1]) > 0, [[0.0, 1.0, 0.0]], [[1.0, 0.0, 0.0]]))
    shape = {
        "circle": lambda: cd.Circle(center, normal, radius),
        "annulus": lambda: cd.Annulus(center, normal, radius / 2, radius),
        "arc": lambda: cd.Arc(center, normal, radius, start, 4.0),
    }[target]()
    line = cd.Ray(p, q - p) if piece == "ray" else cd.Segment(p, q)
    scale = np.maximum(np.abs(np.concatenate([center, p, q], axis=1)).max(axis=1), radius)
    for solver in SOLVERS:
        ab = cd.closest_points(line, shape, solver=solver, precision=precision)
        ba = cd.closest_points(shape, line, solver=solver, precision=precision)
        for name, points in (("ab", ab.point_b), ("ba", ba.point_a)):
            off = _off_plane_in_ulps(points, center, normal, scale, precision)
            worst = int(np.argmax(off))
            assert off[worst] <= PLANE_ULPS, (
                solver,
                name,
                off[worst],
                center[worst],
                normal[worst],
                p[worst],
                q[worst],
            )
