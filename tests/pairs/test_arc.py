"""The Arc kind in Python: cd.Arc against every kind that has a query, both argument
orders, scalar and batched, every solver and precision, against an independent reference.

Reference: 50-digit mpmath (circledist_cases/reference_arc.py, on reference_round.py's helpers,
no library code; the differential test confirms its arc findings with the same one). The arc is
sampled from its own definition, center + R (cos t u + sin t v), t in [0, angle], u the unit
projection of `start`, v = n x u; the other shape's distance from the arc's point is a closed form
(point, line, ray, segment, circle, disk; another arc: the point-arc closed form there, checked
against sampling below), and the minimum over t is found by
minimize_1d (dense samples, golden section on every sampled local minimum).

Accuracy rule (the project's, never loosened): |d - d_ref| <= 1e-12 x max(d_ref, largest radius
in the query) in double, 1e-15 x in long double; float32 answers within 4 float32 ulps of
max(d_ref, largest radius) of the exact answer for the float32 inputs (README). Arc-Bezier
(bezier_arc.hpp): the curve evaluated by de Casteljau at 50 digits, the arc's point-arc closed
form below, minimized over the curve's t in [0, 1]; its bar's size is the largest of the radius
and the curve's farthest control point from the arc's center.
"""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import circledist as cd
from circledist_cases import differential as D
from circledist_cases import reference_round as R

# the reference (50 digits), shared with the differential test
from circledist_cases.reference_arc import ArcMP, _t, arc, point_distance_function, reference
from circledist_cases.kind_checks import (
    assert_batched_equals_single,
    assert_broadphase_finds_points_on,
    assert_effects_agree_with_distance,
    assert_exact_and_unique,
    assert_float32,
    assert_long_double,
    assert_older_version_refused,
    assert_scene_equals_brute_force,
    assert_scene_file_round_trip,
    batch_of,
    both_orders,
    file_version,
    make,
    mixed_shapes,
    radii,
    random_shape,
    rounded,
    translated,
)
from circledist_cases.kind_checks import check as _check

mpf, ctx = R.mpf, R.ctx
SOLVERS = ("bracketing", "companion", "polished", "eigen")
OTHER_KINDS = ("point", "line", "ray", "segment", "circle", "disk", "arc")
TWO_PI = 2 * math.pi
REL = 1e-12
REL_LD = 1e-15


@pytest.mark.slow
def test_point_arc_closed_form_matches_sampling():
    """The reference's own point-arc closed form (used against arcs) against dense sampling."""
    rng = np.random.default_rng(5)
    for _ in range(6):
        a = arc(rng.normal(size=3), rng.normal(size=3), rng.uniform(0.3, 2), rng.normal(size=3), rng.uniform(0.3, 6.2))
        p = R.vec(rng.normal(size=3) * 2)
        arc_mp = ArcMP(a)
        sampled = min(R.dist(p, arc_mp.at(arc_mp.angle * k / 20000)) for k in range(20001))
        closed = arc_mp.point_distance(p)
        assert closed <= sampled + mpf("1e-40") and sampled - closed < 1e-7 * float(arc_mp.r)


# ------------------------------------------------------------------------------------------------
# cases
# ------------------------------------------------------------------------------------------------
def random_cases(kind, n, seed):
    rng = np.random.default_rng([seed, OTHER_KINDS.index(kind)])
    return [(random_shape("arc", rng), random_shape(kind, rng)) for _ in range(n)]


Z, X, Y, O = (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 0.0)
QUARTER = arc(O, Z, 1.0, X, math.pi / 2)  # from (1, 0, 0) to (0, 1, 0)


# (name, arc, other, exact distance or None, unique: True / False / None)
HARD = [
    # tangent ends: a line touching the circle at the arc's start / end, or just missing it
    ("line-tangent-at-start", QUARTER, ("line", (1.0, -5.0, 0.0), Y), 0.0, None),
    ("line-tangent-at-end", QUARTER, ("line", (-5.0, 1.0, 0.0), X), 0.0, None),
    ("line-tangent-at-end-1e-9-above", QUARTER, ("line", (-5.0, 1.0, 1e-9), X), 1e-9, True),
    ("line-tangent-off-the-arc", QUARTER, ("line", (-5.0, -1.0, 0.0), X), 1.0, True),  # at the start
    ("segment-tangent-at-start", QUARTER, ("segment", (1.0, -2.0, 0.0), (1.0, 0.0, 0.0)), 0.0, None),
    ("circle-tangent-at-end", QUARTER, ("circle", (0.0, 2.0, 0.0), Z, 1.0), 0.0, None),
    ("disk-tangent-at-start", QUARTER, ("disk", (1.0, 0.0, 1.0), X, 1.0), 0.0, None),
    ("arc-tangent-at-ends", QUARTER, arc((0.0, 2.0, 0.0), Z, 1.0, (0.0, -1.0, 0.0), 1.0), 0.0, None),
    # arc ends on the other shape's axis
    ("circle-axis-through-start", QUARTER, ("circle", (1.0, 0.0, 2.0), Z, 0.5), None, None),
    ("disk-axis-through-end", QUARTER, ("disk", (0.0, 1.0, -1.5), Z, 0.3), 1.5, False),  # over the disk
    ("arc-axis-through-start", QUARTER, arc((1.0, 0.0, 2.0), Z, 0.5, X, 2.0), None, None),
    ("line-along-the-axis", QUARTER, ("line", (0.0, 0.0, 3.0), Z), 1.0, False),
    ("point-on-the-axis", QUARTER, ("point", (0.0, 0.0, 0.75)), 1.25, False),
    # concentric coplanar continua
    ("concentric-coplanar-circle", QUARTER, ("circle", O, Z, 2.0), 1.0, False),
    ("concentric-coplanar-arcs-overlapping", QUARTER, arc(O, Z, 1.5, (1.0, 1.0, 0.0), 1.0), 0.5, False),
    ("inside-a-coplanar-disk", QUARTER, ("disk", (0.2, 0.1, 0.0), Z, 3.0), 0.0, False),
    ("coaxial-circle-above", QUARTER, ("circle", (0.0, 0.0, 0.5), Z, 1.0), 0.5, False),
    # an arc that misses the other's near side: the ends decide
    ("point-beyond-the-ends", QUARTER, ("point", (-2.0, -0.5, 0.0)), None, None),
    ("arc-arc-ends", QUARTER, arc((-1.0, -1.0, 0.3), Z, 0.5, (-1.0, 0.0, 0.0), 1.0), None, None),
    # extreme radius ratios
    ("tiny-arc-big-circle", arc((0.3, 0.2, 0.1), (0.3, 1.0, 0.2), 1e-6, X, 2.0), ("circle", O, Z, 1.0), None, None),
    ("big-arc-small-disk", arc(O, (0.1, 0.2, 1.0), 1e4, X, 0.5), ("disk", (9990.0, 300.0, 2.0), Y, 0.01), None, None),
    ("big-arc-small-circle", arc(O, Z, 1e3, X, 1.0), ("circle", (995.0, 5.0, 0.5), (0.2, 0.1, 1.0), 1e-3), None, None),
    (
        "small-arc-segment",
        arc((0.5, 0.5, 0.5), (1.0, 1.0, 0.0), 1e-5, Z, 3.0),
        ("segment", O, (1.0, 1.0, 1.0)),
        None,
        None,
    ),
]
# Translated by 1e6 and 1e8: every random kind and a few of the hard ones.
FAR = []
for _shift in (1e6, 1e8):
    _by = (_shift, -0.5 * _shift, 0.25 * _shift)
    for _kind in OTHER_KINDS:
        for _i, (_a, _b) in enumerate(random_cases(_kind, 2, 11)):
            FAR.append((f"{_kind}-{_i}-translated-{_shift:g}", translated(_a, _by), translated(_b, _by), None, None))
    for _name, _a, _b, _exact, _unique in HARD[:8]:
        FAR.append((f"{_name}-translated-{_shift:g}", translated(_a, _by), translated(_b, _by), None, None))


def check(a, b, d):
    return _check(a, b, d, reference(a, b), REL)


def check_closest(a, b, r, ref):
    """closest_points: the distance is distance()'s, the points lie on their shapes, apart by the
    distance, and the arc's parameter t gives its point."""
    pa, pb = np.asarray(r.point_a, float), np.asarray(r.point_b, float)
    # Points are world coordinates: they carry the rounding of their coordinates (1.5e-8 at 1e8).
    tol = 1e-9 * max([ref] + radii(a) + radii(b)) + 16 * np.finfo(float).eps * float(np.abs([pa, pb]).max())
    assert abs(float(np.linalg.norm(pa - pb)) - ref) <= tol
    arc_mp = ArcMP(a)
    assert float(arc_mp.point_distance(R.vec(pa))) <= tol
    assert float(point_distance_function(b)(R.vec(pb))) <= tol
    t = float(r.param_a[0])
    assert 0 <= t <= a[5] + 1e-15 and r.param_a[1] == 0
    assert float(R.dist(arc_mp.at(R.to_mp(t)), R.vec(pa))) <= tol


# ------------------------------------------------------------------------------------------------
# accuracy: random and hard cases, both orders
# ------------------------------------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_random_against_the_reference(kind):
    for a, b in random_cases(kind, 10, 1):
        d, r = both_orders(a, b)
        ref = check(a, b, d)
        check_closest(a, b, r, ref)


@pytest.mark.slow
@pytest.mark.parametrize("case", HARD + FAR, ids=lambda c: c[0])
def test_hard_cases(case):
    name, a, b, exact, unique = case
    d, r = both_orders(a, b)
    ref = check(a, b, d)
    assert_exact_and_unique(name, a, b, d, r, ref, exact, unique, REL)
    check_closest(a, b, r, ref)


@pytest.mark.parametrize("kind", OTHER_KINDS)
@pytest.mark.parametrize("solver", SOLVERS)
def test_every_solver(kind, solver):
    for a, b in random_cases(kind, 4, 2) + [c[1:3] for c in HARD if c[2][0] == kind]:
        d, _ = both_orders(a, b, solver=solver)
        check(a, b, d)


@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_long_double(kind):
    """precision='longdouble' on float64 inputs (which it reads exactly): the bar is 1e-15."""
    cases = random_cases(kind, 4, 3) + [c[1:3] for c in HARD if c[2][0] == kind]
    assert_long_double(cases, reference, SOLVERS, REL_LD)


@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_float32(kind):
    """float32 inputs: within 4 float32 ulps of max(d, radius) of the exact answer for them."""
    assert_float32(random_cases(kind, 4, 4), reference)


# ------------------------------------------------------------------------------------------------
# the whole circle: angle 2 pi answers as the circle, bit for bit
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_angle_two_pi_is_the_circle_bit_for_bit(kind):
    for a, b in random_cases(kind, 6, 6) + [(QUARTER, c[2]) for c in HARD if c[2][0] == kind]:
        whole = a[:5] + (TWO_PI,)
        circle = ("circle",) + a[1:4]
        if b[0] == "arc":
            continue  # arc-arc: against the circle's arc-circle answer below
        for precision in ("float64", "longdouble"):
            x, c, y = make(whole), make(circle), make(b)
            assert cd.distance(x, y, precision=precision) == cd.distance(c, y, precision=precision)
            rx, rc = cd.closest_points(x, y, precision=precision), cd.closest_points(c, y, precision=precision)
            assert rx.distance == rc.distance and np.array_equal(rx.point_a, rc.point_a)
            assert np.array_equal(rx.point_b, rc.point_b) and rx.unique == rc.unique
    # an arc against a whole arc: the arc against the circle
    for a, b in random_cases("arc", 6, 7):
        whole = b[:5] + (TWO_PI,)
        circle = ("circle",) + b[1:4]
        assert cd.distance(make(a), make(whole)) == cd.distance(make(a), make(circle))


def test_angle_two_pi_given_as_float64_is_whole_in_long_double():
    """float64's 2 pi is 2.4e-16 below long double's: it still means the whole circle."""
    a = arc((0.1, 0.2, 0.3), (0.3, -0.2, 1.0), 1.3, (1.0, 2.0, 0.5), TWO_PI)
    for b in [("point", (2.0, 1.0, 0.5)), ("line", (0.0, -3.0, 0.2), (1.0, 1.0, 0.1)), ("disk", O, Y, 0.8)]:
        c = ("circle",) + a[1:4]
        ld = dict(precision="longdouble")
        assert cd.distance(make(a), make(b), **ld) == cd.distance(make(c), make(b), **ld)


# ------------------------------------------------------------------------------------------------
# batches: scalar == batched, broadcasting, dtypes
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_batched_equals_scalar_and_broadcasts(kind):
    arcs, others = assert_batched_equals_single(random_cases(kind, 12, 8), 12)
    # (N, 1) against (M,): an N x M matrix of the single answers
    column = cd.Arc.from_arrays(
        {
            k: np.expand_dims(v, 1) if v.ndim > (1 if k in ("center", "normal", "start") else 0) else v
            for k, v in arcs[:5].to_arrays().items()
        }
    )
    m = cd.distance(column, others[:7])
    assert m.shape == (5, 7)
    for i in range(5):
        for j in range(7):
            assert m[i, j] == cd.distance(arcs[i], others[j])
    # one arc against the batch; fields broadcast within the arc (one angle for all)
    one = cd.Arc([0, 0, 0], [0, 0, 1], [0.5, 1.0, 1.5], [1, 0, 0], 2.0)
    assert one.batch_shape == (3,)
    d = cd.distance(one, others[:3])
    for i in range(3):
        assert d[i] == cd.distance(cd.Arc([0, 0, 0], [0, 0, 1], [0.5, 1.0, 1.5][i], [1, 0, 0], 2.0), others[i])


def test_precision_follows_the_dtypes():
    a32 = cd.Arc(np.float32([0, 0, 0]), np.float32([0, 0, 1]), np.float32(1), np.float32([1, 0, 0]), np.float32(2))
    assert cd.distance(a32, np.float32([[2, 0, 0]])).dtype == np.float32
    ald = cd.Arc([0, 0, 0], [0, 0, 1], np.longdouble(1), [1, 0, 0], 2.0)
    assert isinstance(cd.distance(ald, [2, 0, 0]), np.longdouble)
    assert isinstance(cd.distance(cd.Arc([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], 2.0), [2, 0, 0]), float)
    # float32's rounding of 2 pi (just above 2 pi) is 2 pi given as float32: the whole circle
    whole32 = cd.Arc(
        np.float32([0, 0, 0]), np.float32([0, 0, 1]), np.float32(1), np.float32([1, 0, 0]), np.float32(TWO_PI)
    )
    assert cd.distance(whole32, np.float32([-2, 0, 0])) == 1.0


# ------------------------------------------------------------------------------------------------
# Arc-Bezier (bezier_arc.hpp, docs/derivations/arc.md "A Bezier curve")
# ------------------------------------------------------------------------------------------------
def curve_reference(a, ctrl):
    """min over the curve's t in [0, 1] of the arc's closed-form distance from its point (50 digits)."""
    arc_a = ArcMP(a)
    return float(
        R.minimize_1d(lambda t: arc_a.point_distance(R.bezier_point(ctrl, t)), mpf(0), mpf(1), 720, periodic=False)[
            0
        ].value
    )


def curve_scale(a, ctrl, ref):
    return max([ref, a[3]] + [float(np.linalg.norm(np.subtract(p, a[1]))) for p in ctrl])


def random_curve_cases(n, seed):
    rng = np.random.default_rng([seed, 19])
    out = []
    for k in range(n):
        a = random_shape("arc", rng)
        around = np.asarray(a[1]) + rng.normal(size=3) * 0.7
        out.append((a, tuple(_t(around + rng.normal(size=3)) for _ in range(2 + k % 7))))  # degree 1..7
    return out


E1 = (0.0, 1.0, 0.0)  # QUARTER's end
CURVE_HARD = [
    # (name, arc, control points, exact distance or None, unique)
    ("curve-end-at-the-arc-end", QUARTER, (E1, (0.0, 1.5, 0.3), (-0.2, 2.0, -0.2)), 0.0, None),
    ("curve-end-at-a-tangency", QUARTER, ((0.6, 0.8, 0.0), (0.2, 1.1, 0.0), (-0.3, 1.2, 0.4)), 0.0, None),
    ("arc-end-on-the-curve", QUARTER, ((0.5, 1.5, 0.5), (0.0, 1.0, 0.0), (-0.5, 0.5, -0.5)), 0.0, None),
    ("arc-end-below-the-curve", QUARTER, ((0.5, 1.5, 0.55), (0.0, 1.0, 0.05), (-0.5, 0.5, -0.45)), None, True),
    ("along-the-axis", QUARTER, ((0.0, 0.0, -1.0), (0.0, 0.0, 0.5), (0.0, 0.0, 1.0)), 1.0, False),
    ("coplanar-across", QUARTER, ((0.0, 0.0, 0.0), (1.0, 0.4, 0.0), (2.0, 1.5, 0.0)), 0.0, None),
    ("coplanar-off-the-arc", QUARTER, ((-2.0, -0.5, 0.0), (-1.0, -2.0, 0.0), (0.5, -1.5, 0.0)), None, None),
    (
        "degree-7-wave",
        QUARTER,
        tuple((math.cos(k / 2), math.sin(k / 2), 0.3 * (-1) ** k) for k in range(8)),
        None,
        None,
    ),
    (
        "tiny-arc",
        arc((0.3, 0.2, 0.1), (0.3, 1.0, 0.2), 1e-6, X, 2.0),
        ((-1.0, 0.5, 0.2), (0.3, -1.0, 0.4), (1.0, 1.0, -0.3)),
        None,
        None,
    ),
    (
        "huge-arc",
        arc(O, Z, 1e6, X, 0.2),
        ((1e6 - 0.5, -0.3, 0.2), (1e6 + 0.2, 0.4, -0.3), (1e6 + 0.7, 0.1, 0.5)),
        None,
        None,
    ),
]
for _shift in (1e6, 1e8):
    _by = (_shift, -0.5 * _shift, 0.25 * _shift)
    for _name, _a, _c, _exact, _unique in CURVE_HARD[:4] + [
        (f"random-{i}", a, c, None, None) for i, (a, c) in enumerate(random_curve_cases(2, 12))
    ]:
        CURVE_HARD.append(
            (
                f"{_name}-translated-{_shift:g}",
                translated(_a, _by),
                tuple(tuple(x + y for x, y in zip(p, _by)) for p in _c),
                None,
                None,
            )
        )


def curve_both_orders(a, ctrl, **kw):
    x, y = make(a), cd.Bezier(np.asarray(ctrl))
    d_ab, d_ba = cd.distance(x, y, **kw), cd.distance(y, x, **kw)
    assert d_ab == d_ba
    r_ab, r_ba = cd.closest_points(x, y, **kw), cd.closest_points(y, x, **kw)
    assert r_ab.distance == d_ab and r_ba.distance == d_ba
    assert np.array_equal(r_ab.point_a, r_ba.point_b) and np.array_equal(r_ab.param_a, r_ba.param_b)
    assert r_ab.unique == r_ba.unique
    return d_ab, r_ab


def check_curve_closest(a, ctrl, r, ref):
    """The arc's point on the arc at its parameter t, the curve's at its parameter, apart by the distance."""
    pa, pb = np.asarray(r.point_a, float), np.asarray(r.point_b, float)
    tol = 1e-9 * curve_scale(a, ctrl, ref) + 16 * np.finfo(float).eps * float(np.abs([pa, pb]).max())
    assert abs(float(np.linalg.norm(pa - pb)) - ref) <= tol
    arc_mp = ArcMP(a)
    t = float(r.param_a[0])
    assert 0 <= t <= a[5] + 1e-15 and r.param_a[1] == 0
    assert float(R.dist(arc_mp.at(R.to_mp(t)), R.vec(pa))) <= tol
    s = float(r.param_b[0])
    assert 0 <= s <= 1 and float(R.dist(R.bezier_point(ctrl, s), R.vec(pb))) <= tol


@pytest.mark.slow
def test_arc_bezier_random_against_the_reference():
    for a, ctrl in random_curve_cases(14, 1):
        d, r = curve_both_orders(a, ctrl)
        ref = curve_reference(a, ctrl)
        assert abs(d - ref) <= REL * curve_scale(a, ctrl, ref), (a, ctrl, d, ref)
        check_curve_closest(a, ctrl, r, ref)


@pytest.mark.parametrize("case", CURVE_HARD, ids=lambda c: c[0])
def test_arc_bezier_hard_cases(case):
    name, a, ctrl, exact, unique = case
    d, r = curve_both_orders(a, ctrl)
    ref = curve_reference(a, ctrl)
    scale = curve_scale(a, ctrl, ref)
    if exact is not None:
        assert abs(ref - exact) <= 1e-14 * scale
    assert abs(d - ref) <= REL * scale, (name, d, ref)
    check_curve_closest(a, ctrl, r, ref)
    if unique is not None:
        assert bool(r.unique) is unique, name


@pytest.mark.slow
@pytest.mark.parametrize("solver", SOLVERS)
def test_arc_bezier_every_solver_and_long_double(solver):
    for a, ctrl in random_curve_cases(4, 2) + [c[1:3] for c in CURVE_HARD[:8]]:
        ref = curve_reference(a, ctrl)
        scale = curve_scale(a, ctrl, ref)
        d, _ = curve_both_orders(a, ctrl, solver=solver)
        assert abs(d - ref) <= REL * scale, (solver, a, ctrl, d, ref)
        d_ld, _ = curve_both_orders(a, ctrl, solver=solver, precision="longdouble")
        assert isinstance(d_ld, np.longdouble)
        assert abs(float(d_ld - np.longdouble(ref))) <= REL_LD * scale, (solver, a, ctrl, float(d_ld), ref)


def test_arc_bezier_float32():
    """float32 inputs: within 4 float32 ulps of max(d, size) of the exact answer for them."""
    for a, ctrl in random_curve_cases(4, 4):
        a32 = rounded(a, np.float32)
        c32 = tuple(_t(np.asarray(p, np.float32)) for p in ctrl)
        x, y = make(a32, np.float32), cd.Bezier(np.asarray(c32, np.float32))
        d = cd.distance(x, y)  # a single float32 answer comes back as a Python float of a float32
        assert float(np.float32(d)) == d and cd.distance(y, x) == d
        ref = curve_reference(a32, c32)
        assert abs(float(d) - ref) <= 4 * float(np.spacing(np.float32(curve_scale(a32, c32, ref)))), (float(d), ref)


def test_arc_bezier_whole_arc_is_the_circle_bit_for_bit():
    for a, ctrl in random_curve_cases(6, 5):
        whole = arc(a[1], a[2], a[3], a[4], TWO_PI)
        circle = cd.Circle(a[1], a[2], a[3])
        curve = cd.Bezier(np.asarray(ctrl))
        assert cd.distance(make(whole), curve) == cd.distance(circle, curve)
        r_arc, r_circle = cd.closest_points(curve, make(whole)), cd.closest_points(curve, circle)
        assert np.array_equal(r_arc.point_a, r_circle.point_a) and np.array_equal(r_arc.point_b, r_circle.point_b)


def test_arc_bezier_batches_and_effects():
    """A batch of arcs against one curve: the single answers, to the bit; within / intersects /
    distance_if_within agree with the distance."""
    cases = random_curve_cases(7, 6)
    ctrl = cases[0][1]
    curve = cd.Bezier(np.asarray(ctrl))
    arcs = batch_of([a for a, _ in cases])
    d = cd.distance(arcs, curve)
    r = cd.closest_points(curve, arcs)
    assert np.array_equal(d, cd.distance(curve, arcs)) and np.array_equal(r.distance, d)
    for i, (a, _) in enumerate(cases):
        assert d[i] == cd.distance(make(a), curve)
        assert bool(cd.within(make(a), curve, float(d[i]) * (1 + 1e-9) + 1e-12))
        assert not cd.within(curve, make(a), float(d[i]) * (1 - 1e-6)) or d[i] == 0
        assert bool(cd.intersects(make(a), curve)) == (d[i] == 0)
        assert cd.distance_if_within(make(a), curve, 2 * float(d[i]) + 1) == d[i]


# ------------------------------------------------------------------------------------------------
# bad input: the argument and the index named
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "args,message",
    [
        (([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], 0.0), r"Arc: angle must be in \(0, 2 pi\], got 0"),
        (([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], [1.0, -0.5]), r"Arc: angle\[1\] must be in \(0, 2 pi\], got -0.5"),
        (([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], [1.0, 2.0, 7.0]), r"Arc: angle\[2\] must be in \(0, 2 pi\]"),
        (([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], TWO_PI * (1 + 1e-15)), r"Arc: angle must be in \(0, 2 pi\]"),
        (([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], [1.0, np.nan]), r"Arc: angle\[1\] contains NaN or inf"),
        (([0, 0, 0], [0, 0, 1], 1.0, [[1, 0, 0], [0, 0, -3]], 1.0), r"Arc: start\[1\] is parallel to normal\[1\]"),
        (([0, 0, 0], [[0, 0, 1], [0, 1, 0]], 1.0, [0, 2, 0], 1.0), r"Arc: start\[1\] is parallel to normal\[1\]"),
        (([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], 1.0), r"Arc: start has zero length"),
        (([0, 0, 0], [0, 0, 1], 1.0, [1, np.inf, 0], 1.0), r"Arc: start contains NaN or inf"),
        (([0, 0, 0], [0, 0, 1], -1.0, [1, 0, 0], 1.0), r"Arc: radius is negative"),
        (([0, 0, 0], [0, 0, 0], 1.0, [1, 0, 0], 1.0), r"Arc: normal has zero length"),
        (([0, 0, np.nan], [0, 0, 1], 1.0, [1, 0, 0], 1.0), r"Arc: center contains NaN or inf"),
        (([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], [[1.0], [2.0]]), None),  # fine: broadcasts
        (([0, 0, 0], [0, 0, 1], [1.0, 2.0], [1, 0, 0], [1.0, 2.0, 3.0]), r"does not broadcast"),
    ],
)
def test_bad_input_names_the_argument_and_index(args, message):
    if message is None:
        assert cd.Arc(*args).batch_shape == (2, 1)
        return
    with pytest.raises(ValueError, match=message):
        cd.Arc(*args)


def test_angle_two_pi_and_tiny_angles_are_accepted():
    cd.Arc([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], TWO_PI)
    cd.Arc([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], 1e-300)
    cd.Arc([0, 0, 0], [0, 0, 1], 1.0, [1, 1e-12, 1], 1.0)  # nearly along the normal is still an arc


# ------------------------------------------------------------------------------------------------
# values: pickle, to_arrays, indexing, sweeps
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.longdouble])
def test_pickle_to_arrays_and_indexing_keep_values_and_dtypes(dtype):
    cases = random_cases("circle", 4, 9)
    arcs = batch_of([a for a, _ in cases], dtype)
    swept = cd.Arc.from_arrays({**arcs.to_arrays(), "sweep": np.asarray([0.1, 0.0, 0.2, 0.3], dtype)})
    for shape in (arcs, swept, arcs[2]):
        back = pickle.loads(pickle.dumps(shape))
        assert type(back) is cd.Arc and back.kind == "Arc" and back.batch_shape == shape.batch_shape
        for name, value in shape.to_arrays().items():
            got = back.to_arrays()[name]
            assert got.dtype == value.dtype and np.array_equal(got, value), name
    assert list(arcs.to_arrays()) == ["center", "normal", "radius", "start", "angle"]
    assert arcs.to_arrays()["angle"].dtype == dtype
    other = make(cases[0][1])
    d = cd.distance(arcs, other)
    for i in range(4):
        assert cd.distance(arcs[i], other) == d[i]
    assert np.array_equal(cd.distance(arcs[[3, 1]], other), d[[3, 1]])
    assert len(arcs) == 4 and [x.batch_shape for x in arcs] == [()] * 4
    assert repr(arcs[0]).startswith("Arc(center=")


def test_sweep_grows_the_arc():
    a = cd.Arc([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], math.pi / 2, sweep=0.25)
    assert cd.distance(a, [0, 0, 3]) == pytest.approx(math.sqrt(10) - 0.25, abs=1e-14)
    assert cd.distance(a, [-3, 0, 0]) == pytest.approx(math.sqrt(10) - 0.25, abs=1e-14)


# ------------------------------------------------------------------------------------------------
# effects and Scene with arcs among other shapes, against brute force
# ------------------------------------------------------------------------------------------------
def test_effects_on_arcs_agree_with_distance():
    shapes = mixed_shapes(OTHER_KINDS, 12, 6)
    assert_effects_agree_with_distance([s for name, s in shapes.items() if name.startswith("arc")], shapes.values())
    # touching: an arc through a disk, an arc ending on a line
    assert cd.intersects(make(QUARTER), cd.Disk([0.7, 0.7, 0], [1, 1, 0], 0.5))
    assert cd.intersects(make(QUARTER), cd.Line([1, -5, 0], [0, 1, 0]))
    assert not cd.intersects(make(QUARTER), cd.Circle([-1, -1, 0], [0, 0, 1], 0.5))
    # batched effects equal single ones
    cases = random_cases("disk", 8, 13)
    arcs_b, disks = batch_of([a for a, _ in cases]), batch_of([b for _, b in cases])
    flags = cd.within(arcs_b, disks, 0.5)
    for i in range(8):
        assert flags[i] == cd.within(arcs_b[i], disks[i], 0.5)


def test_scene_queries_with_arcs_equal_brute_force():
    probes = (cd.Arc([0.5, -0.5, 0.2], [0.3, 0.2, 1.0], 1.5, [1, 0, 0], 4.0), "arc2", "circle1", [0.5, 0.5, 0.5])
    assert_scene_equals_brute_force(mixed_shapes(OTHER_KINDS, 14, 6), probes, "arc")


def test_broadphase_boxes_hold_the_arcs():
    """The broadphase's box of an arc is tight (its ends and the circle's extremes on it), not the
    circle's: points on the arcs, and points just off them, must all be found by pairs_within and
    nearest exactly as brute force finds them (a box missing part of its arc would lose pairs)."""
    rng = np.random.default_rng(21)
    n = 300
    centers = rng.uniform(-20, 20, (n, 3))
    normals, starts = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    radii_, angles = rng.uniform(0.5, 3, n), rng.uniform(0.05, TWO_PI, n)
    arcs = cd.Arc(centers, normals, radii_, starts, angles)
    # a point on each arc at a random t (from the arc's own u, v), and one 1e-3 off it
    nn = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    u = starts - np.sum(starts * nn, axis=1, keepdims=True) * nn
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    v = np.cross(nn, u)
    t = rng.uniform(0, 1, n) * angles
    on = centers + radii_[:, None] * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)
    assert_broadphase_finds_points_on(arcs, on, rng)


# ------------------------------------------------------------------------------------------------
# scene files and the command line
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("suffix", [".json", ".npz"])
def test_scene_file_round_trip_and_version(tmp_path, suffix):
    """Arcs (single, batched, float32 and swept) write and read back to the bit; a file holding an
    arc is format version 2, one without stays version 1 (older readers read it), and an arc in a
    version 1 file is refused."""
    cases = random_cases("disk", 3, 17)
    shapes = {
        "hook": make(QUARTER),
        "hooks": batch_of([a for a, _ in cases]),
        "bent": cd.Arc([0, 0, 1], [0, 1, 1], 0.5, [1, 0, 0], 5.0, sweep=0.1),
        "coin": make(cases[0][1]),
    }
    queries = [
        {"a": "hook", "b": "coin", "effects": ["distance", "closest_points"]},
        {"a": "hooks[1]", "effects": ["nearest"], "k": 2},
    ]
    path = tmp_path / f"arcs{suffix}"
    assert_scene_file_round_trip(path, shapes, queries, "coin")
    assert_older_version_refused(path, 2, "hook", "arc")
    plain = tmp_path / f"plain{suffix}"
    cd.write_scene(plain, {"coin": shapes["coin"]})
    assert file_version(plain) == 1


def test_command_line_answers_and_draws_an_arc(tmp_path):
    import importlib.util
    import json

    from circledist import cli

    doc = {
        "format": "circledist-scene",
        "version": 2,
        "shapes": [
            {
                "name": "hook",
                "kind": "arc",
                "center": [0, 0, 0],
                "normal": [0, 0, 1],
                "radius": 1,
                "start": [1, 0, 0],
                "angle": 1.5707963267948966,
            },
            {"name": "rail", "kind": "line", "origin": [-5, -1, 0], "direction": [1, 0, 0]},
        ],
        "queries": [{"a": "hook", "b": "rail", "effects": ["distance", "closest_points"]}],
    }
    path, answers = tmp_path / "arc.json", tmp_path / "answers.json"
    path.write_text(json.dumps(doc))
    argv = [str(path), "--json", str(answers)]
    picture = tmp_path / "arc.png"
    if importlib.util.find_spec("matplotlib") is not None:
        argv += ["--plot", str(picture)]
    assert cli.main(argv) == 0
    got = json.loads(answers.read_text())["answers"][0]
    assert got["distance"] == 1.0  # the start (1, 0, 0) above the line y = -1
    assert got["closest_points"]["point_b"] == [1.0, -1.0, 0.0]
    if importlib.util.find_spec("matplotlib") is not None:
        assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_scene_with_arcs_and_bezier_curves_answers_that_pair():
    """Arc-Bezier has a query (bezier_arc.hpp): a Scene holding both answers it as brute force does."""
    hook, cable = make(QUARTER), cd.Bezier([[0, 0, 0], [1, 1, 1]])
    s = cd.Scene({"hook": hook, "cable": cable, "ring": cd.Circle([0, 0, 0], [0, 0, 1], 2.0)})
    assert s.nearest("ring", k=1) == [("hook", 1.0)]
    near = dict(s.nearest("hook", k=2))
    assert near["cable"] == cd.distance(hook, cable)
    got = {tuple(sorted(p)) for p in s.pairs_within(1.0)}
    assert ("cable", "hook") in got


def test_bounds_decide_separated_arc_pairs_without_a_solve():
    """within() against circles and disks tries the bounds first (bounds.hpp: the arc's ball, its
    height range over the round's plane, points on it): arcs far from a ring, or lying across a
    disk, are decided with no polynomial solved."""
    rng = np.random.default_rng(30)
    n = 200
    far = cd.Arc(
        rng.uniform(-1, 1, (n, 3)) + [0, 0, 10],
        rng.normal(size=(n, 3)),
        rng.uniform(0.2, 1, n),
        rng.normal(size=(n, 3)),
        rng.uniform(0.3, 6, n),
    )
    for target in (cd.Circle([0, 0, 0], [0, 0, 1], 1.0), cd.Disk([0, 0, 0], [0, 0, 1], 1.0)):
        cd.reset_stats()
        assert not np.any(cd.within(far, target, 1.0))
        s = cd.stats()
        assert s["decided_by_bounds"] == n and s["solves"] == 0, s
    # a quarter arc over a disk's plane, just above it: the height range decides "no" at d = 0
    above = cd.Arc([0, 0, 0.5], [0, 0, 1], 0.5, [1, 0, 0], 1.0)
    cd.reset_stats()
    assert not cd.intersects(above, cd.Disk([0, 0, 0], [0, 0, 1], 1.0))
    assert cd.stats()["decided_by_bounds"] == 1
    # an arc through a disk: its end points lie on both sides, a point on it inside: "yes" by bounds
    through = cd.Arc([0, 0, 0], [1, 0, 0], 0.5, [0, 0, 1], np.pi)
    cd.reset_stats()
    assert cd.within(through, cd.Disk([0, 0, 0], [0, 0, 1], 1.0), 0.0)


# ------------------------------------------------------------------------------------------------
# the normal's and the start's scales: only their directions count (README: any finite nonzero
# normal). A line, ray or segment against an arc forms the arc's end directions from products of
# the normal (|W|^2 S - (S.W) W, |W|^3 |S| for v) whose squares, from the raw normal of 1e-80 and
# a unit start, lie in the subnormals: answers 9-20% off. Every kind against an arc, both orders,
# every solver and precision: the same arc with its normal and start rescaled to unit length is
# the same set (a metamorphic reference independent of the code), and on a subset the 50-digit one.
# ------------------------------------------------------------------------------------------------
SCALE_KINDS = ("point", "line", "ray", "segment", "circle", "disk", "arc", "annulus", "bezier")
NORMAL_SCALES = (1e-300, 1e-150, 1e-100, 1e-90, 1e-80, 1e-75, 1e-70, 1e-50, 1.0, 1e50, 1e150, 1e300)
START_SCALES = (1e-300, 1e-60, 1e-20, 1.0, 1e60, 1e300)
F32_SCALES = (2.0**-100, 2.0**-50, 1.0, 2.0**50, 2.0**100)  # float32's range, exact


def scale_cases(kind, n, seed):
    """(unit arc, other) in the differential layout: the arc's normal and start of unit length,
    the start at an angle from the arc's plane (not in it: its projection counts)."""
    rng = np.random.default_rng([seed, SCALE_KINDS.index(kind)])
    out = []
    for _ in range(n):
        normal = rng.normal(size=3)
        normal /= np.linalg.norm(normal)
        start = rng.normal(size=3)
        start /= np.linalg.norm(start)
        unit = (
            list(rng.uniform(-1.5, 1.5, 3))
            + list(normal)
            + [float(rng.uniform(0.3, 2))]
            + list(start)
            + [float(rng.uniform(0.3, 2 * np.pi))]
        )
        if kind == "bezier":
            at = rng.uniform(-1.5, 1.5, 3)
            other = [list(at + rng.uniform(-1.5, 1.5, 3)) for _ in range(4)]
        else:
            other = _other_data(kind, rng)
        out.append((unit, other))
    return out


def _other_data(kind, rng):
    """A random shape of `kind` in the differential layout (an annulus: outer, then inner radius)."""
    s = random_shape(kind, rng)
    if kind == "annulus":
        return list(s[1]) + list(s[2]) + [s[4], s[3]]
    return [x for f in s[1:] for x in (f if isinstance(f, tuple) else (f,))]


def scale_case(kind, other, unit):
    """The pair as a differential case, in its canonical order (an arc before an annulus)."""
    if kind == "annulus":
        return dict(family="scale", id="scale", a="arc", a_data=unit, b=kind, b_data=other)
    return dict(family="scale", id="scale", a=kind, a_data=other, b="arc", b_data=unit)


def scaled_arcs(unit, normal_scales, start_scales):
    """Every (normal scale, start scale) version of the arc, as one batch of the layout's rows."""
    u = np.asarray(unit, float)
    rows = []
    for ns in normal_scales:
        for ss in start_scales:
            r = u.copy()
            r[3:6] *= ns
            r[7:10] *= ss
            rows.append(r)
    return np.array(rows)


@pytest.mark.parametrize("kind", SCALE_KINDS)
def test_normal_and_start_scales_do_not_change_the_answer(kind):
    combos = [(s, p) for s in SOLVERS for p in ("float64", "longdouble", "float32")]
    for unit, other in scale_cases(kind, 3, 12):
        scale = D.bar_scale(scale_case(kind, other, unit))
        for solver, precision in combos:
            f32 = precision == "float32"
            dtype = np.float32 if f32 else (np.longdouble if precision == "longdouble" else np.float64)
            rows = scaled_arcs(unit, F32_SCALES if f32 else NORMAL_SCALES, F32_SCALES if f32 else START_SCALES)
            unit_row = np.asarray(rows[0], float).copy()  # the unit arc in the inputs' precision
            unit_row[3:6], unit_row[7:10] = unit[3:6], unit[7:10]
            arcs = D.make_shape(cd, "arc", rows, dtype)
            x, one = D.make_shape(cd, kind, other, dtype), D.make_shape(cd, "arc", unit_row, dtype)
            kw = dict(solver=solver, precision=precision)
            ref = float(cd.distance(x, one, **kw))
            bar = (4 * float(np.finfo(np.float32).eps) if f32 else REL) * max(ref, scale)
            for order in ("ab", "ba"):
                d = np.asarray(cd.distance(x, arcs, **kw) if order == "ab" else cd.distance(arcs, x, **kw), float)
                bad = np.flatnonzero(~(np.abs(d - ref) <= bar))
                assert not len(bad), (
                    kind,
                    solver,
                    precision,
                    order,
                    [(rows[i][3], rows[i][7], d[i], ref) for i in bad[:4]],
                )
                r = cd.closest_points(x, arcs, **kw) if order == "ab" else cd.closest_points(arcs, x, **kw)
                pa, pb = np.asarray(r.point_a, float), np.asarray(r.point_b, float)
                on_arc, on_other = (pb, pa) if order == "ab" else (pa, pb)
                assert np.all(np.abs(np.asarray(r.distance, float) - ref) <= bar), (kind, solver, precision, order)
                # the points (rounded to the answer's precision) apart by the distance, the arc's on
                # the unit arc and the other's on the other shape (closed forms)
                on = (64 * float(np.finfo(np.float32).eps) if f32 else 1e-9) * scale
                assert np.all(np.abs(np.linalg.norm(pa - pb, axis=-1) - ref) <= bar + on)
                assert float(np.max(cd.distance(cd.Point(on_arc), D.make_shape(cd, "arc", unit)))) <= on
                assert float(np.max(cd.distance(cd.Point(on_other), D.make_shape(cd, kind, other)))) <= on


@pytest.mark.parametrize("kind", SCALE_KINDS)
def test_tiny_and_huge_normals_against_the_reference(kind):
    """The scaled arcs of the band that failed (normal 1e-80 .. 1e-70, start 1 .. 1e-20) and the
    extremes, against the 50-digit reference of the unit arc (the same set)."""
    for unit, other in scale_cases(kind, 2, 13):
        case = scale_case(kind, other, unit)
        ref = float(D.mp_reference(case))
        bar = REL * max(ref, D.bar_scale(case))
        rows = scaled_arcs(unit, (1e-300, 1e-80, 1e-75, 1e-70, 1e300), (1e-20, 1.0, 1e60))
        x, arcs = D.make_shape(cd, kind, other), D.make_shape(cd, "arc", rows)
        for d in (cd.distance(x, arcs), cd.distance(arcs, x), cd.closest_points(x, arcs).distance):
            assert np.all(np.abs(np.asarray(d) - ref) <= bar), (kind, np.asarray(d), ref)
