"""The Annulus kind in Python: cd.Annulus against every kind that has a query, both
argument orders, scalar and batched, every solver and precision, against an independent reference.

Reference: 50-digit mpmath (circledist_cases/reference_round.py's helpers, no library code). The
distance from a point to an annulus is a closed form written here (its projection's distance rho
from the center: |z| in the ring, else the nearer rim's sqrt(z^2 + (rho - r)^2)), itself checked
against dense sampling of the annulus. Against a curve (circle, arc, line, ray, segment: a line's
parameter on the bounded stretch where a closest point can lie) the reference is the minimum over
the curve's parameter of that closed form, by minimize_1d (dense samples, golden section on every
sampled local minimum). Two plane regions (a disk or an annulus against an annulus) are as close
as a rim of one is to the other: a closest pair with both points inside their regions' rims has
p - q normal to both planes, so the planes are parallel and the pair slides to a rim, and a
contact (distance 0) has a rim point of one region in the other; the reference is the least of
each rim's minimum against the other region (the closed forms of point-disk and point-annulus).

Accuracy rule (the project's, never loosened): |d - d_ref| <= 1e-12 x max(d_ref, largest radius
in the query) in double, 1e-15 x in long double; float32 answers within 4 float32 ulps of
max(d_ref, largest radius) of the exact answer for the float32 inputs (README), as for the arc.
Against a Bezier curve the reference is the minimum over the curve's t of the same closed form
(test_annulus_bezier_against_the_reference).
"""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import circledist as cd
from circledist_cases import reference_round as R
from circledist_cases.reference_annulus import (
    AnnulusMP,
    annulus,
    bezier_reference,
    curves_of,
    minimum_along,
    point_distance_function,
    reference,
    rim_curve,
)
from circledist_cases.reference_arc import arc
from circledist_cases.kind_checks import (
    as_floats as _t,
    assert_batched_equals_single,
    assert_broadphase_finds_points_on,
    assert_effects_agree_with_distance,
    assert_exact_and_unique,
    assert_float32,
    assert_long_double,
    assert_older_version_refused,
    assert_scene_file_round_trip,
    file_version,
    assert_scene_equals_brute_force,
    batch_of,
    both_orders,
    make,
    mixed_shapes,
    radii,
    random_shape,
    translated,
)
from circledist_cases.kind_checks import check as _check

mpf, ctx = R.mpf, R.ctx
SOLVERS = ("bracketing", "companion", "polished", "eigen")
OTHER_KINDS = ("point", "line", "ray", "segment", "circle", "disk", "arc", "annulus")
TWO_PI = 2 * math.pi
REL = 1e-12
REL_LD = 1e-15


@pytest.mark.slow
def test_point_annulus_closed_form_matches_sampling():
    """The reference's own point-annulus closed form against a dense polar grid of the annulus."""
    rng = np.random.default_rng(5)
    for _ in range(4):
        outer = rng.uniform(0.5, 2)
        a = annulus(rng.normal(size=3), rng.normal(size=3), outer * rng.uniform(0.2, 0.8), outer)
        ring = AnnulusMP(a)
        p = R.vec(ring.c[i] + mpf(x) for i, x in enumerate(rng.normal(size=3) * 2))
        rims = [
            rim_curve(ring.c, ring.u, ring.v, ring.inner + (ring.outer - ring.inner) * k / 60)[0] for k in range(61)
        ]
        sampled = min(R.dist(p, at(2 * ctx.pi * j / 720)) for at in rims for j in range(720))
        closed = ring.point_distance(p)
        assert closed <= sampled + mpf("1e-40") and sampled - closed < 2e-2 * float(ring.outer)


# ------------------------------------------------------------------------------------------------
# cases
# ------------------------------------------------------------------------------------------------
def random_cases(kind, n, seed):
    rng = np.random.default_rng([seed, OTHER_KINDS.index(kind)])
    return [(random_shape("annulus", rng), random_shape(kind, rng)) for _ in range(n)]


Z, X, Y, O = (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 0.0)
WASHER = annulus(O, Z, 1.0, 2.0)


# (name, annulus, other, exact distance or None, unique: True / False / None)
HARD = [
    # lines through the hole along the axis, and about it
    ("line-along-the-axis", WASHER, ("line", (0.0, 0.0, 3.0), Z), 1.0, False),
    ("segment-on-the-axis-above", WASHER, ("segment", (0.0, 0.0, 0.5), (0.0, 0.0, 3.0)), math.sqrt(1.25), False),
    ("ray-down-the-axis", WASHER, ("ray", (0.0, 0.0, 4.0), (0.0, 0.0, -1.0)), 1.0, False),
    ("ray-through-the-hole-slanted", WASHER, ("ray", (0.0, 0.0, 2.0), (0.1, 0.0, -1.0)), None, True),
    ("line-through-the-ring", WASHER, ("line", (1.5, 0.0, -1.0), Z), 0.0, None),
    ("line-parallel-over-the-ring", WASHER, ("line", (0.0, 1.5, 0.5), X), 0.5, False),
    ("line-in-the-plane-across", WASHER, ("line", O, X), 0.0, False),
    ("segment-in-the-hole", WASHER, ("segment", (-0.5, 0.0, 0.0), (0.5, 0.0, 0.0)), 0.5, False),
    ("point-at-the-center", WASHER, ("point", O), 1.0, False),
    ("point-above-the-ring", WASHER, ("point", (1.5, 0.0, 2.0)), 2.0, True),
    # a circle or arc in the hole, coplanar and concentric cases
    ("circle-in-the-hole", WASHER, ("circle", (0.1, 0.0, 0.0), Z, 0.5), 0.4, True),
    ("concentric-circle-in-the-hole", WASHER, ("circle", O, Z, 0.5), 0.5, False),
    ("concentric-circle-above", WASHER, ("circle", (0.0, 0.0, 1.0), Z, 1.5), 1.0, False),
    ("circle-outside-coplanar-tangent", WASHER, ("circle", (3.0, 0.0, 0.0), Z, 1.0), 0.0, None),
    ("circle-linking-the-ring", WASHER, ("circle", (2.0, 0.0, 0.0), Y, 1.5), None, None),
    ("circle-through-the-hole-tangent", WASHER, ("circle", (1.0, 0.0, 0.0), Y, 0.5), 0.0, None),
    ("arc-in-the-hole", WASHER, arc(O, Z, 0.5, X, 1.0), 0.5, False),
    ("arc-through-the-hole", WASHER, arc((2.0, 0.0, 0.0), Y, 1.5, (-1.0, 0.0, 0.0), 0.5), None, None),
    ("disk-in-the-hole", WASHER, ("disk", O, Z, 0.5), 0.5, False),
    ("disk-over-the-hole", WASHER, ("disk", (0.0, 0.0, 1.0), Z, 3.0), 1.0, False),
    ("disk-across-the-hole", WASHER, ("disk", O, X, 0.8), 0.2, False),
    ("annuli-concentric-coplanar-apart", WASHER, annulus(O, Z, 3.0, 4.0), 1.0, False),
    ("annuli-concentric-coplanar-overlapping", WASHER, annulus(O, Z, 1.5, 3.0), 0.0, False),
    ("annuli-concentric-parallel", WASHER, annulus((0.0, 0.0, 1.0), Z, 0.5, 1.5), 1.0, False),
    ("annuli-linked-touching", WASHER, annulus((2.0, 0.0, 0.0), Y, 1.0, 1.2), 0.0, None),
    ("annuli-linked-apart", WASHER, annulus((1.5, 0.0, 0.0), Y, 0.7, 0.9), None, None),
    ("annulus-in-the-hole-tilted", WASHER, annulus((0.0, 0.0, 0.1), (0.3, 0.1, 1.0), 0.2, 0.6), None, None),
    # extreme radius ratios
    ("pinhole-point-above", annulus(O, Z, 1e-6, 1.0), ("point", (0.0, 0.0, 1e-7)), math.sqrt(1e-14 + 1e-12), False),
    ("thin-big-ring-small-circle", annulus(O, Z, 9999.0, 1e4), ("circle", (9999.5, 0.0, 0.5), Y, 0.1), None, None),
    (
        "tiny-annulus-big-circle",
        annulus((0.3, 0.2, 0.1), (0.3, 1.0, 0.2), 1e-6, 2e-6),
        ("circle", O, Z, 1.0),
        None,
        None,
    ),
    (
        "big-annulus-small-disk",
        annulus(O, (0.1, 0.2, 1.0), 5e3, 1e4),
        ("disk", (300.0, 9000.0, 2.0), Y, 0.01),
        None,
        None,
    ),
    (
        "small-annulus-segment",
        annulus((0.5, 0.5, 0.5), (1.0, 1.0, 0.0), 1e-5, 3e-5),
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
        _a, _b = random_cases(_kind, 1, 11)[0]
        FAR.append((f"{_kind}-translated-{_shift:g}", translated(_a, _by), translated(_b, _by), None, None))
    for _name, _a, _b, _exact, _unique in HARD[:8:2] + HARD[10:26:3]:
        FAR.append((f"{_name}-translated-{_shift:g}", translated(_a, _by), translated(_b, _by), None, None))


def check(a, b, d):
    return _check(a, b, d, reference(a, b), REL)


def on_shape_distance(shape, p, toward):
    """The distance from the point p to `shape` (closed forms, or the minimum along a curve)."""
    x = R.vec(p)
    if shape[0] in ("point", "disk", "annulus"):
        return float(point_distance_function(shape)(x))
    if shape[0] in ("line", "ray", "segment"):
        return float(R.point_linear_closest(x, shape[0], R.vec(shape[1]), R.vec(shape[2]))[0])
    return float(min(minimum_along(c, lambda y: R.dist(x, y), mpf(1)) for c in curves_of(shape, toward)))


def check_closest(a, b, r, ref):
    """closest_points: the points lie on their shapes, apart by the distance, and the annulus's
    parameter (s, theta) is its point's distance from the center and the disk's angle of it."""
    pa, pb = np.asarray(r.point_a, float), np.asarray(r.point_b, float)
    # Points are world coordinates: they carry the rounding of their coordinates (1.5e-8 at 1e8).
    tol = 1e-9 * max([ref] + radii(a) + radii(b)) + 16 * np.finfo(float).eps * float(np.abs([pa, pb]).max())
    assert abs(float(np.linalg.norm(pa - pb)) - ref) <= tol
    assert on_shape_distance(a, pa, a) <= tol
    if b[0] in ("point", "line", "ray", "segment", "disk", "annulus"):
        assert on_shape_distance(b, pb, a) <= tol
    s, theta = (float(x) for x in r.param_a)
    assert a[3] - tol <= s <= a[4] + tol and abs(s - float(np.linalg.norm(pa - np.array(a[1])))) <= tol
    if s > tol:  # the disk's own angle of the point
        disk_param = cd.closest_points(cd.Disk(a[1], a[2], a[4]), pa).param_a
        assert abs(math.remainder(theta - float(disk_param[1]), TWO_PI)) * s <= tol


# ------------------------------------------------------------------------------------------------
# accuracy: random and hard cases, both orders
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_random_against_the_reference(kind):
    for a, b in random_cases(kind, 8, 1):
        d, r = both_orders(a, b)
        ref = check(a, b, d)
        check_closest(a, b, r, ref)


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
    for a, b in random_cases(kind, 3, 2) + [c[1:3] for c in HARD if c[2][0] == kind]:
        d, _ = both_orders(a, b, solver=solver)  # closest_points().distance == distance(), to the bit
        check(a, b, d)


@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_long_double(kind):
    """precision='longdouble' on float64 inputs (which it reads exactly): the bar is 1e-15."""
    cases = random_cases(kind, 3, 3) + [c[1:3] for c in HARD if c[2][0] == kind]
    assert_long_double(cases, reference, SOLVERS, REL_LD)


@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_float32(kind):
    """float32 inputs: within 4 float32 ulps of max(d, radius) of the exact answer for them."""
    assert_float32(random_cases(kind, 3, 4), reference)


# ------------------------------------------------------------------------------------------------
# inner radius 0 is the disk, inner = outer the circle: their answers, bit for bit
# ------------------------------------------------------------------------------------------------
def _same_answers(x, y, ref_x, precision, circle=False):
    assert cd.distance(x, y, precision=precision) == cd.distance(ref_x, y, precision=precision)
    rx, rr = cd.closest_points(x, y, precision=precision), cd.closest_points(ref_x, y, precision=precision)
    assert rx.distance == rr.distance and np.array_equal(rx.point_a, rr.point_a)
    assert np.array_equal(rx.point_b, rr.point_b) and rx.unique == rr.unique
    assert np.array_equal(rx.param_b, rr.param_b)
    # the annulus's (s, theta): the disk's own, or (R, theta) for the circle's (theta, 0)
    want = np.array([rr.param_a[...].dtype.type(x.outer_radius), rr.param_a[0]]) if circle else rr.param_a
    assert np.array_equal(rx.param_a, want)


@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_inner_zero_is_the_disk_and_inner_outer_the_circle_bit_for_bit(kind):
    for a, b in random_cases(kind, 5, 6) + [(WASHER, c[2]) for c in HARD if c[2][0] == kind]:
        _, c, n, _, outer = a
        for precision in ("float64", "longdouble"):
            y = make(b)
            _same_answers(make(annulus(c, n, 0.0, outer)), y, cd.Disk(c, n, outer), precision)
            _same_answers(make(annulus(c, n, outer, outer)), y, cd.Circle(c, n, outer), precision, circle=True)


# ------------------------------------------------------------------------------------------------
# batches: scalar == batched, broadcasting, dtypes
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", OTHER_KINDS)
def test_batched_equals_scalar_and_broadcasts(kind):
    rings, others = assert_batched_equals_single(random_cases(kind, 10, 8), 10)
    # (N, 1) against (M,): an N x M matrix of the single answers
    column = cd.Annulus.from_arrays(
        {
            k: np.expand_dims(v, 1) if v.ndim > (1 if k in ("center", "normal") else 0) else v
            for k, v in rings[:4].to_arrays().items()
        }
    )
    m = cd.distance(column, others[:6])
    assert m.shape == (4, 6)
    for i in range(4):
        for j in range(6):
            assert m[i, j] == cd.distance(rings[i], others[j])
    # fields broadcast within the annulus (one outer radius for three inner ones)
    one = cd.Annulus([0, 0, 0], [0, 0, 1], [0.0, 0.5, 1.0], 1.0)
    assert one.batch_shape == (3,)
    d = cd.distance(one, others[:3])
    for i in range(3):
        assert d[i] == cd.distance(cd.Annulus([0, 0, 0], [0, 0, 1], [0.0, 0.5, 1.0][i], 1.0), others[i])


def test_precision_follows_the_dtypes():
    f32 = np.float32
    a32 = cd.Annulus(f32([0, 0, 0]), f32([0, 0, 1]), f32(0.5), f32(1))
    assert cd.distance(a32, f32([[2, 0, 0]])).dtype == np.float32
    ald = cd.Annulus([0, 0, 0], [0, 0, 1], 0.5, np.longdouble(1))
    assert isinstance(cd.distance(ald, [2, 0, 0]), np.longdouble)
    assert isinstance(cd.distance(cd.Annulus([0, 0, 0], [0, 0, 1], 0.5, 1.0), [2, 0, 0]), float)


def _bezier_cases():
    """(name, annulus, control points): random curves of degree 1..5 about random annuli, and
    curves through the hole along the axis, lying in the plane across the ring and the hole, in
    the hole, touching the face, far larger than the annulus, and translated by 1e6."""
    rng = np.random.default_rng(20261126)
    out = []
    for i in range(12):
        a = random_shape("annulus", rng)
        k = 2 + i % 5
        at = np.asarray(a[1])
        out.append((f"random-{i}", a, tuple(_t(at + rng.uniform(-2, 2, 3)) for _ in range(k))))
    out += [
        ("down-the-axis", WASHER, ((0.0, 0.0, 3.0), (0.0, 0.0, 1.0), (0.0, 0.0, -0.5))),
        ("in-the-plane-across", WASHER, ((-3.0, 0.1, 0.0), (0.0, 0.5, 0.0), (3.0, 0.1, 0.0))),
        ("in-the-hole", WASHER, ((-0.5, 0.0, 0.0), (0.0, 0.6, 0.0), (0.5, 0.0, 0.0))),
        ("arch-over-the-ring", WASHER, ((1.5, -1.0, 1.0), (1.5, 0.0, -0.75), (1.5, 1.0, 1.0))),
        ("through-the-hole-slanted", WASHER, ((0.3, 0.0, 2.0), (0.0, 0.2, 0.0), (-0.3, 0.1, -2.0), (0.0, 0.0, -3.0))),
        ("large-passing-the-rim", WASHER, ((-500.0, 2.5, 0.3), (0.0, 2.0, 0.3), (500.0, 2.5, 0.3))),
    ]
    by = (1e6, -5e5, 2.5e5)
    for name, a, ctrl in out[12:15]:
        out.append((name + "-translated-1e6", translated(a, by), tuple(_t(np.add(p, by)) for p in ctrl)))
    return out


BEZIER_CASES = _bezier_cases()


@pytest.mark.parametrize("case", BEZIER_CASES, ids=lambda c: c[0])
def test_annulus_bezier_against_the_reference(case):
    """Every solver in double and long double, both orders: the distance against the 50-digit
    reference, closest_points().distance == distance() to the bit, the curve's point on the curve
    at its param and the annulus's point in the annulus, apart by the distance."""
    name, a, ctrl = case
    ref = bezier_reference(a, ctrl)
    curve = cd.Bezier(np.asarray(ctrl, float))
    ring = make(a)
    scale = max(ref, a[4])
    extent = float(np.abs(np.asarray(ctrl)).max())
    for solver in ("bracketing", "companion", "polished", "eigen"):
        for precision, rel in (("float64", REL), ("longdouble", REL_LD)):
            ulp = float(np.finfo(np.longdouble if precision == "longdouble" else np.float64).eps)
            d = cd.distance(ring, curve, solver=solver, precision=precision)
            assert d == cd.distance(curve, ring, solver=solver, precision=precision)
            assert abs(float(d) - ref) <= rel * scale + 4 * ulp * scale, (name, solver, precision, float(d), ref)
            r = cd.closest_points(curve, ring, solver=solver, precision=precision)
            assert r.distance == d
            tol = rel * scale + 16 * ulp * max(extent, scale)
            pa, pb = np.asarray(r.point_a, np.longdouble), np.asarray(r.point_b, np.longdouble)
            assert abs(float(np.linalg.norm(pa - pb)) - float(d)) <= tol
            assert float(R.dist(R.vec(pa), R.bezier_point(ctrl, R.to_mp(r.param_a[0])))) <= tol
            assert float(AnnulusMP(a).point_distance(R.vec(pb))) <= tol


def test_annulus_bezier_batched_equals_scalar():
    rings = batch_of([a for _, a, _ in BEZIER_CASES[:5]])
    curves = cd.Bezier(np.asarray([_t(p) for _, _, c in BEZIER_CASES[:5] for p in c[:2]], float).reshape(5, 2, 3))
    d = cd.distance(rings, curves)
    for i, (_, a, ctrl) in enumerate(BEZIER_CASES[:5]):
        assert d[i] == cd.distance(make(a), cd.Bezier(np.asarray(ctrl[:2], float)))


# ------------------------------------------------------------------------------------------------
# bad input: the argument and the index named
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "args,message",
    [
        (([0, 0, 0], [0, 0, 1], 2.0, 1.0), r"Annulus: inner_radius exceeds outer_radius \(2 > 1\)"),
        (([0, 0, 0], [0, 0, 1], [0.5, 1.5], 1.0), r"Annulus: inner_radius\[1\] exceeds outer_radius\[1\] \(1.5 > 1\)"),
        (([0, 0, 0], [0, 0, 1], 0.5, [[1.0], [0.25]]), r"Annulus: inner_radius\[1, 0\] exceeds outer_radius\[1, 0\]"),
        (([0, 0, 0], [0, 0, 1], -0.5, 1.0), r"Annulus: inner_radius is negative"),
        (([0, 0, 0], [0, 0, 1], 0.5, [1.0, -1.0]), r"Annulus: outer_radius\[1\] is negative"),
        (([0, 0, 0], [0, 0, 1], [0.5, np.nan], 1.0), r"Annulus: inner_radius\[1\] contains NaN or inf"),
        (([0, 0, 0], [0, 0, 1], 0.5, np.inf), r"Annulus: outer_radius contains NaN or inf"),
        (([0, 0, 0], [0, 0, 0], 0.5, 1.0), r"Annulus: normal has zero length"),
        (([0, 0, np.nan], [0, 0, 1], 0.5, 1.0), r"Annulus: center contains NaN or inf"),
        (([0, 0, 0], [0, 0, 1], [0.5, 0.7], [1.0, 2.0, 3.0]), r"does not broadcast"),
        (
            ([0, 0, 0], [0, 0, 1], np.longdouble(1) + np.finfo(np.longdouble).eps, np.longdouble(1)),
            r"Annulus: inner_radius exceeds outer_radius",
        ),  # compared as given (in long double)
    ],
)
def test_bad_input_names_the_argument_and_index(args, message):
    with pytest.raises(ValueError, match=message):
        cd.Annulus(*args)


def test_inner_zero_and_inner_equal_outer_are_accepted():
    assert cd.distance(cd.Annulus([0, 0, 0], [0, 0, 1], 0.0, 1.0), [0, 0, 1]) == 1.0
    assert cd.distance(cd.Annulus([0, 0, 0], [0, 0, 1], 1.0, 1.0), [0, 0, 0]) == 1.0
    assert cd.distance(cd.Annulus([0, 0, 0], [0, 0, 1], 0.0, 0.0), [0, 0, 2]) == 2.0  # a point


# ------------------------------------------------------------------------------------------------
# values: pickle, to_arrays, indexing, sweeps
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.longdouble])
def test_pickle_to_arrays_and_indexing_keep_values_and_dtypes(dtype):
    cases = random_cases("circle", 4, 9)
    rings = batch_of([a for a, _ in cases], dtype)
    swept = cd.Annulus.from_arrays({**rings.to_arrays(), "sweep": np.asarray([0.1, 0.0, 0.2, 0.3], dtype)})
    for shape in (rings, swept, rings[2]):
        back = pickle.loads(pickle.dumps(shape))
        assert type(back) is cd.Annulus and back.kind == "Annulus" and back.batch_shape == shape.batch_shape
        for name, value in shape.to_arrays().items():
            got = back.to_arrays()[name]
            assert got.dtype == value.dtype and np.array_equal(got, value), name
    assert list(rings.to_arrays()) == ["center", "normal", "inner_radius", "outer_radius"]
    assert rings.to_arrays()["inner_radius"].dtype == dtype
    other = make(cases[0][1])
    d = cd.distance(rings, other)
    for i in range(4):
        assert cd.distance(rings[i], other) == d[i]
    assert np.array_equal(cd.distance(rings[[3, 1]], other), d[[3, 1]])
    assert len(rings) == 4 and [x.batch_shape for x in rings] == [()] * 4
    assert repr(rings[0]).startswith("Annulus(center=")


def test_sweep_grows_the_annulus():
    a = cd.Annulus([0, 0, 0], [0, 0, 1], 1.0, 2.0, sweep=0.25)
    assert cd.distance(a, [0, 0, 0]) == 0.75
    assert cd.distance(a, [1.5, 0, 3]) == 2.75
    assert cd.distance(a, [0, 0, 1]) == pytest.approx(math.sqrt(2) - 0.25, abs=1e-15)
    swept, plain = make(WASHER, sweep=0.3), make(WASHER)
    for b in (cd.Circle([0, 0, 0.1], [0, 0, 1], 0.5), cd.Line([0, 0, 3], [0, 0, 1]), make(annulus(O, Z, 3, 4))):
        assert cd.distance(swept, b) == max(0.0, cd.distance(plain, b) - 0.3)


# ------------------------------------------------------------------------------------------------
# effects and Scene with annuli among other shapes, against brute force
# ------------------------------------------------------------------------------------------------
def test_effects_on_annuli_agree_with_distance():
    shapes = mixed_shapes(OTHER_KINDS, 12, 5)
    assert_effects_agree_with_distance([s for name, s in shapes.items() if name.startswith("annulus")], shapes.values())
    # touching: a line through the ring, a circle round the outer rim; not: a line through the hole
    assert cd.intersects(make(WASHER), cd.Line([1.5, 0, -1], [0, 0, 1]))
    assert cd.intersects(make(WASHER), cd.Circle([3, 0, 0], [0, 0, 1], 1.0))
    assert not cd.intersects(make(WASHER), cd.Line([0, 0, 3], [0, 0, 1]))
    assert not cd.intersects(make(WASHER), cd.Disk([0, 0, 0], [0, 0, 1], 0.5))
    # batched effects equal single ones
    cases = random_cases("disk", 8, 13)
    rings_b, disks = batch_of([a for a, _ in cases]), batch_of([b for _, b in cases])
    flags = cd.within(rings_b, disks, 0.5)
    for i in range(8):
        assert flags[i] == cd.within(rings_b[i], disks[i], 0.5)


def test_bounds_decide_separated_annulus_pairs_without_a_solve():
    """within() against circles and disks tries the bounds first (bounds.hpp: the annulus's outer
    disk's ball and height range, points on it): annuli far from a ring or a disk are decided with
    no polynomial solved."""
    rng = np.random.default_rng(30)
    n = 200
    outer = rng.uniform(0.2, 1, n)
    far = cd.Annulus(rng.uniform(-1, 1, (n, 3)) + [0, 0, 10], rng.normal(size=(n, 3)), outer * 0.5, outer)
    for target in (cd.Circle([0, 0, 0], [0, 0, 1], 1.0), cd.Disk([0, 0, 0], [0, 0, 1], 1.0)):
        cd.reset_stats()
        assert not np.any(cd.within(far, target, 1.0))
        s = cd.stats()
        assert s["decided_by_bounds"] == n and s["solves"] == 0, s
    # an annulus crossing a disk: a point of its ring lies on the disk, "yes" by bounds
    cd.reset_stats()
    assert cd.within(cd.Annulus([0, 0, 0], [1, 0, 0], 0.2, 0.5), cd.Disk([0, 0, 0], [0, 0, 1], 1.0), 0.0)
    assert cd.stats()["decided_by_bounds"] == 1


def test_scene_queries_with_annuli_equal_brute_force():
    probes = (cd.Annulus([0.5, -0.5, 0.2], [0.3, 0.2, 1.0], 0.7, 1.5), "annulus2", "circle1", [0.5, 0.5, 0.5])
    assert_scene_equals_brute_force(mixed_shapes(OTHER_KINDS, 14, 5), probes, "annulus")


def test_broadphase_boxes_hold_the_annuli():
    """The broadphase's box of an annulus is its outer disk's: points on the annuli (both rims and
    between), and points just off them, are all found by pairs_within and nearest as brute force
    finds them."""
    rng = np.random.default_rng(21)
    n = 300
    centers, normals = rng.uniform(-20, 20, (n, 3)), rng.normal(size=(n, 3))
    outer = rng.uniform(0.5, 3, n)
    inner = outer * rng.uniform(0, 1, n)
    rings = cd.Annulus(centers, normals, inner, outer)
    nn = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    helper = np.where(np.abs(nn[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]])
    u = np.cross(nn, helper)
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    v = np.cross(nn, u)
    t = rng.uniform(0, TWO_PI, n)
    s = np.choose(rng.integers(0, 3, n), [inner, outer, inner + (outer - inner) * rng.uniform(0, 1, n)])
    on = centers + s[:, None] * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)
    assert_broadphase_finds_points_on(rings, on, rng)


def test_scene_with_annuli_and_bezier_curves_answers_that_pair():
    shapes = {
        "washer": make(WASHER),
        "cable": cd.Bezier([[5, 0, 0], [6, 1, 1]]),
        "ring": cd.Circle([0, 0, 0], [0, 0, 1], 0.5),
    }
    s = cd.Scene(shapes)
    assert s.nearest("ring", k=1) == [("washer", 0.5)]
    assert s.nearest("washer", k=2) == sorted(
        ((n, cd.distance(shapes["washer"], x)) for n, x in shapes.items() if n != "washer"), key=lambda e: e[1]
    )
    assert abs(cd.distance(shapes["washer"], shapes["cable"]) - 3.0) <= 1e-12 * 3  # the cable's end to the rim
    assert ("cable", "washer") in {tuple(sorted(p[:2])) for p in s.pairs_within(3.0)}


# ------------------------------------------------------------------------------------------------
# scene files and the command line
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("suffix", [".json", ".npz"])
def test_scene_file_round_trip_and_version(tmp_path, suffix):
    """Annuli (single, batched, float32 and swept) write and read back to the bit; a file holding
    an annulus is format version 3, one with only an arc stays version 2 and one with neither
    version 1 (older readers read them), and an annulus in a version 2 file is refused."""
    cases = random_cases("disk", 3, 17)
    shapes = {
        "washer": make(WASHER),
        "washers": batch_of([a for a, _ in cases]),
        "thin": cd.Annulus(
            np.float32([0, 0, 1]), np.float32([0, 1, 1]), np.float32(0.4), np.float32(0.5), sweep=np.float32(0.1)
        ),
        "coin": make(cases[0][1]),
    }
    queries = [
        {"a": "washer", "b": "coin", "effects": ["distance", "closest_points"]},
        {"a": "washers[1]", "effects": ["nearest"], "k": 2},
    ]
    path = tmp_path / f"annuli{suffix}"
    assert_scene_file_round_trip(path, shapes, queries, "coin")
    assert_older_version_refused(path, 3, "washer", "annulus")
    for kept, version in (({"coin": shapes["coin"]}, 1), ({"hook": make(arc(O, Z, 1, X, 1))}, 2)):
        plain = tmp_path / f"plain{version}{suffix}"
        cd.write_scene(plain, kept)
        assert file_version(plain) == version


def test_command_line_answers_and_draws_an_annulus(tmp_path):
    import importlib.util
    import json

    from circledist import cli

    doc = {
        "format": "circledist-scene",
        "version": 3,
        "shapes": [
            {
                "name": "washer",
                "kind": "annulus",
                "center": [0, 0, 0],
                "normal": [0, 0, 1],
                "inner_radius": 1,
                "outer_radius": 2,
            },
            {"name": "pole", "kind": "line", "origin": [0, 0, 3], "direction": [0, 0, 1]},
        ],
        "queries": [{"a": "washer", "b": "pole", "effects": ["distance", "closest_points"]}],
    }
    path, answers = tmp_path / "annulus.json", tmp_path / "answers.json"
    path.write_text(json.dumps(doc))
    argv = [str(path), "--json", str(answers)]
    picture = tmp_path / "annulus.png"
    if importlib.util.find_spec("matplotlib") is not None:
        argv += ["--plot", str(picture)]
    assert cli.main(argv) == 0
    got = json.loads(answers.read_text())["answers"][0]
    assert got["distance"] == 1.0  # the pole runs down the axis, through the hole of radius 1
    assert got["closest_points"]["unique"] is False
    if importlib.util.find_spec("matplotlib") is not None:
        assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        from circledist import _cli_present

        curves = _cli_present._CURVES["annulus"]([np.zeros(3), np.array([0, 0, 1.0]), 1.0, 2.0], 16)
        assert [sorted({round(float(np.linalg.norm(p)), 12) for p in c}) for c in curves] == [[2.0], [1.0]]
