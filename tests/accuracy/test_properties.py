"""Property-based tests (hypothesis) for circledist; no reference values needed.

Scenes are drawn relative to the circle/disk so that the interesting regimes occur often:
generic placement, (near-)axial lines, lines parallel to the plane, lines through a rim
point, zero-length segments, radius 0.

Properties, for every pair kind (point/line/ray/segment vs circle/disk):
* symmetry: distance(a, b) == distance(b, a) exactly; closest_points(b, a) is
  closest_points(a, b) with the points swapped;
* invariance under a rigid motion: rotating and translating every input changes the floats
  (each coordinate is rounded again), so the distance is compared with tolerance
  1e-10 * scene size, not bit-for-bit;
* the returned points lie on their shapes and are `distance` apart (1e-12*scale plus the
  binary64 representation limit of the coordinates);
* no pair among 200 sampled points on each shape (end points, rim and centre included) is
  closer than the returned distance minus 1e-12*scale (plus the rounding of the samples).
"""

import math

import numpy as np
import pytest
from hypothesis import given, note
from hypothesis import strategies as st

from circledist_cases import reference_linear_round as ref
from circledist_cases.shapes import make_shape

EPS = float(np.finfo(float).eps)
KIND_PAIRS = [(lk, rk) for rk in ("circle", "disk") for lk in ("point", "line", "ray", "segment")]
IDS = [f"{lk}-{rk}" for lk, rk in KIND_PAIRS]

coord = st.floats(min_value=-10, max_value=10, allow_nan=False, allow_infinity=False)
small = st.floats(min_value=-1, max_value=1, allow_nan=False, allow_infinity=False)
vec = st.tuples(coord, coord, coord)
nonzero_vec = vec.filter(lambda v: math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2) > 1e-2)
radius_st = st.one_of(st.floats(min_value=0.05, max_value=5.0), st.just(0.0), st.sampled_from([1.0, 2.5]))
tiny = st.sampled_from([0.0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3])


def _frame(n):
    n = np.asarray(n, float) / np.linalg.norm(n)
    e = np.zeros(3)
    e[np.argmin(np.abs(n))] = 1.0
    u = e - n.dot(e) * n
    u /= np.linalg.norm(u)
    return u, np.cross(n, u), n


@st.composite
def scene(draw, lin_kind, round_kind):
    """(lin_kind, lin_data, round_kind, round_data) as tuples of floats."""
    c = np.array(draw(vec))
    nrm = np.array(draw(nonzero_vec))
    R = draw(radius_st)
    u, v, n = _frame(nrm)
    style = draw(st.sampled_from(["generic", "axis", "parallel", "rim", "generic"]))
    if style == "generic":
        o = c + np.array(draw(st.tuples(small, small, small))) * 3 * max(R, 1.0)
        dvec = np.array(draw(nonzero_vec))
    elif style == "axis":
        o = c + draw(small) * 2 * n + draw(tiny) * u
        dvec = n + draw(tiny) * v
    elif style == "parallel":
        a, b, h = draw(small), draw(small), draw(tiny)
        o = c + 1.5 * R * (a * u + b * v) + h * draw(st.sampled_from([1, -1, 1000])) * n
        phi = draw(st.floats(0, 2 * math.pi))
        dvec = math.cos(phi) * u + math.sin(phi) * v + draw(tiny) * n
    else:  # through a rim point
        phi = draw(st.floats(0, 2 * math.pi))
        o = c + R * (math.cos(phi) * u + math.sin(phi) * v)
        dvec = np.array(draw(nonzero_vec))
    if lin_kind == "point":
        lin = tuple(float(x) for x in o)
    elif lin_kind in ("line", "ray"):
        lin = tuple(float(x) for x in o) + tuple(float(x) for x in dvec)
    else:
        k = draw(st.sampled_from([0.0, 0.5, 1.0, 3.0]))
        shift = draw(st.sampled_from([0.0, -0.5, -1.0]))
        p0 = o + shift * k * dvec
        lin = tuple(float(x) for x in p0) + tuple(float(x) for x in p0 + k * dvec)
    rnd = tuple(float(x) for x in c) + tuple(float(x) for x in nrm) + (float(R),)
    return lin_kind, lin, round_kind, rnd


def _scene_size(sc):
    lk, ld, rk, rd = sc
    c = np.asarray(rd[:3])
    pts = [np.asarray(ld[:3])]
    if lk == "segment":
        pts.append(np.asarray(ld[3:6]))
    return max([rd[6]] + [float(np.linalg.norm(p - c)) for p in pts] + [1e-3])


@pytest.fixture(scope="module")
def lib(cd):
    return cd


@pytest.mark.parametrize("kinds", KIND_PAIRS, ids=IDS)
def test_symmetry(lib, kinds):
    @given(scene(*kinds))
    def check(sc):
        lk, ld, rk, rd = sc
        a, b = make_shape(lib, lk, ld), make_shape(lib, rk, rd)
        d_ab, d_ba = lib.distance(a, b), lib.distance(b, a)
        assert d_ab == d_ba, f"distance(a, b) = {d_ab!r} != distance(b, a) = {d_ba!r}"
        r1, r2 = lib.closest_points(a, b), lib.closest_points(b, a)
        assert r1.distance == r2.distance
        assert np.array_equal(np.asarray(r1.point_a), np.asarray(r2.point_b))
        assert np.array_equal(np.asarray(r1.point_b), np.asarray(r2.point_a))
        assert bool(r1.unique) == bool(r2.unique)

    check()


def _random_rotation(q):
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q)
    w, x, y, z = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def _move(sc, Q, T):
    lk, ld, rk, rd = sc
    ld = np.asarray(ld, float)
    if lk == "point":
        ld2 = Q @ ld + T
    elif lk in ("line", "ray"):
        ld2 = np.concatenate([Q @ ld[:3] + T, Q @ ld[3:6]])
    else:
        ld2 = np.concatenate([Q @ ld[:3] + T, Q @ ld[3:6] + T])
    rd = np.asarray(rd, float)
    rd2 = np.concatenate([Q @ rd[:3] + T, Q @ rd[3:6], rd[6:]])
    return lk, tuple(ld2), rk, tuple(rd2)


quaternion = st.tuples(small, small, small, small).filter(lambda q: sum(x * x for x in q) > 0.1)


@pytest.mark.parametrize("kinds", KIND_PAIRS, ids=IDS)
def test_rigid_motion_invariance(lib, kinds):
    @given(scene(*kinds), quaternion, vec)
    def check(sc, q, t):
        Q = _random_rotation(q)
        sc2 = _move(sc, Q, np.asarray(t, float))
        d1 = lib.distance(make_shape(lib, sc[0], sc[1]), make_shape(lib, sc[2], sc[3]))
        d2 = lib.distance(make_shape(lib, sc2[0], sc2[1]), make_shape(lib, sc2[2], sc2[3]))
        size = _scene_size(sc)
        note(f"d1={d1!r} d2={d2!r} size={size}")
        assert abs(d1 - d2) <= 1e-10 * size

    check()


@pytest.mark.parametrize("kinds", KIND_PAIRS, ids=IDS)
def test_points_on_shapes(lib, kinds):
    @given(scene(*kinds), st.booleans())
    def check(sc, swap):
        lk, ld, rk, rd = sc
        a, b = make_shape(lib, lk, ld), make_shape(lib, rk, rd)
        res = lib.closest_points(b, a) if swap else lib.closest_points(a, b)
        p_lin = np.asarray(res.point_b if swap else res.point_a, float)
        p_rnd = np.asarray(res.point_a if swap else res.point_b, float)
        d = res.distance
        tol = 1e-12 * max(d, rd[6], 1e-300)
        sl_lin = 2 * EPS * float(np.linalg.norm(p_lin))
        sl_rnd = 2 * EPS * float(np.linalg.norm(p_rnd))
        off_lin = float(ref.distance_to_shape(p_lin, lk, ld))
        off_rnd = float(ref.distance_to_shape(p_rnd, rk, rd))
        sep = float(ref.mp_distance(p_lin, p_rnd))
        note(f"d={d!r} off_lin={off_lin:.3e} off_round={off_rnd:.3e} sep={sep!r}")
        assert off_lin <= tol + sl_lin
        assert off_rnd <= tol + sl_rnd
        assert abs(sep - d) <= tol + sl_lin + sl_rnd

    check()


@pytest.mark.parametrize("round_kind", ["circle", "disk"])
@pytest.mark.parametrize("precision", ["float64", "longdouble"])
def test_point_distance_is_closest_points_distance(lib, round_kind, precision):
    """A point's distance() and closest_points().distance come from the same height and radial
    offset: equal to the bit, and the closest point lies in the shape's plane."""

    @given(scene("point", round_kind))
    def check(sc):
        _, ld, rk, rd = sc
        a, b = make_shape(lib, "point", ld), make_shape(lib, rk, rd)
        for x, y in ((a, b), (b, a)):
            res = lib.closest_points(x, y, precision=precision)
            assert res.distance == lib.distance(x, y, precision=precision)
        res = lib.closest_points(a, b)
        u, v, n = _frame(rd[3:6])
        height = abs(float(np.dot(np.asarray(res.point_b, float) - np.asarray(rd[:3]), n)))
        assert height <= 8 * EPS * max(float(np.linalg.norm(np.asarray(ld[:3]) - np.asarray(rd[:3]))), rd[6], 1.0)

    check()


def _samples_linear(lk, ld, center, reach, rng, n=200):
    ld = np.asarray(ld, float)
    if lk == "point":
        return ld[None, :3]
    if lk == "segment":
        p0, p1 = ld[:3], ld[3:6]
        ts = np.concatenate([[0.0, 1.0], rng.uniform(0, 1, n - 2)])
        return p0 + ts[:, None] * (p1 - p0)
    o, m = ld[:3], ld[3:6]
    tc = float((center - o) @ m / (m @ m))
    half = reach / math.sqrt(m @ m)
    lo = tc - half if lk == "line" else max(0.0, tc - half)
    hi = max(tc + half, lo)
    ts = np.concatenate([[lo, hi, min(max(tc, lo), hi)], rng.uniform(lo, hi, n - 3)])
    if lk == "ray":
        ts = np.concatenate([[0.0], ts[:-1]])
    return o + ts[:, None] * m


def _samples_round(rk, rd, rng, n=200):
    rd = np.asarray(rd, float)
    c, R = rd[:3], rd[6]
    u, v, _ = _frame(rd[3:6])
    th = rng.uniform(0, 2 * math.pi, n)
    if rk == "circle":
        rr = np.full(n, R)
    else:
        rr = R * np.sqrt(rng.uniform(0, 1, n))
        rr[:40] = R  # rim points
        rr[40] = 0.0  # centre
    return c + (rr * np.cos(th))[:, None] * u + (rr * np.sin(th))[:, None] * v


@pytest.mark.parametrize("kinds", KIND_PAIRS, ids=IDS)
def test_no_sampled_pair_is_closer(lib, kinds):
    @given(scene(*kinds), st.integers(0, 2**32 - 1))
    def check(sc, seed):
        lk, ld, rk, rd = sc
        d = lib.distance(make_shape(lib, lk, ld), make_shape(lib, rk, rd))
        rng = np.random.default_rng(seed)
        c = np.asarray(rd[:3], float)
        reach = d + 2 * rd[6] + 1.0
        P = _samples_linear(lk, ld, c, reach, rng)
        Q = _samples_round(rk, rd, rng)
        diff = P[:, None, :] - Q[None, :, :]
        best = float(np.sqrt(np.min(np.einsum("ijk,ijk->ij", diff, diff))))
        mag = float(max(np.max(np.abs(P)), np.max(np.abs(Q))))
        # samples are rounded binary64 points: allow a few ulps of their magnitude
        allowed = d - 1e-12 * max(d, rd[6]) - 8 * EPS * mag
        note(f"d={d!r} best sampled pair={best!r}")
        assert best >= allowed, f"sampled pair at {best!r} < distance {d!r}"

    check()
