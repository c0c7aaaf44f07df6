"""Bezier curves against points, lines, rays and segments (bezier_point.hpp, bezier_linear.hpp).

References: circledist_cases/reference_round.py `bezier_other`, mpmath at 50 digits, the minimum
over the curve's t of the closed-form distance from B(t) to the point or to the piece (its
projection clamped to the interval), by dense sampling zoomed on the curve's speed bound and
golden section on every sampled local minimum: no polynomial roots and nothing from circledist.

Accuracy rule: |d - d_ref| <= 1e-12 * max(d_ref, scale) in double, 1e-15 * max(d_ref, scale) in
long double, where `scale` is the largest length in the query: the control polygon's extent (and a
segment's length). Cases whose answer hinges on the pieces of a far-reaching curve (a control
point 1e10 away) are held to a scale of their own, the size of the curve near the answer (1),
not to its 1e10 extent. Every solver, both argument orders, closest_points (points on their
shapes, separation == distance, distance bit-identical to distance()), within / intersects, swept
shapes and batches (bit-identical to single calls).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Optional

import numpy as np
import pytest

import circledist as cd
from circledist_cases import reference_round as R
from circledist_cases.effect_checks import assert_effects_and_sweeps, assert_other_order_swapped

SOLVERS = ("bracketing", "companion", "polished", "eigen")
TOL = {"float64": 1e-12, "longdouble": 1e-15}
MAX_POINTS = cd._core._max_control_points


@dataclass(frozen=True)
class Case:
    name: str
    ctrl: tuple
    kind: str  # point, line, ray, segment
    data: tuple
    scale: Optional[float] = None  # the bar's scale when not the query's largest length
    unique: Optional[bool] = None  # expected `unique` when clear-cut


def _t(v):
    return tuple(float(x) for x in v)


def case(name, ctrl, kind, *data, scale=None, unique=None):
    return Case(name, tuple(_t(p) for p in ctrl), kind, tuple(_t(d) for d in data), scale, unique)


def _random_cases():
    rng = np.random.default_rng(1919)
    out = []
    for kind in ("point", "line", "ray", "segment"):
        for k in range(1, MAX_POINTS):  # degree 1 to the largest
            ctrl = rng.uniform(-2, 2, (k + 1, 3))
            a = rng.uniform(-2, 2, 3)
            if kind == "point":
                data = (a,)
            elif kind == "segment":
                data = (a, a + rng.uniform(-2, 2, 3))
            else:
                data = (a, rng.normal(size=3))
            out.append(case(f"random_{kind}_deg{k}", ctrl, kind, *data))
    return out


ARCH = ((-1, 0, 0), (0, 2, 0), (1, 0, 0))  # B(t) = (2t - 1, 4t(1 - t), 0): apex (0, 1), curvature radius 1/2
CUBIC = ((0, 0, 0), (1, 1, 0), (2, 1, 0), (3, 0, 0))
WAVY = ((0, 0, 0), (1, 2, 0.5), (2, -1, -0.3), (3, 1.5, 0.2), (4, -0.5, 0))
FAR = ((0, 0, 0), (1e10, 0, 0), (1, 1, 1))  # passes (1, 2.5e-21, 2.5e-21) at t = 5e-11
STRAIGHT = ((0, 0, 0), (1, 0, 0), (3, 0, 0))
SHIFT = np.array([1e6, -1e6, 1e6])


def _shifted(ctrl, by):
    return tuple(tuple(np.array(p) + by) for p in ctrl)


def _hard_cases():
    on = tuple(float(x) for x in R.bezier_point(WAVY, 0.3))  # rounded: within 1e-16 of the curve
    big = tuple(tuple(1e5 * np.array(p)) for p in WAVY)
    return [
        # ---- point ----
        case("point_on_curve", WAVY, "point", on),
        case("point_at_start", WAVY, "point", WAVY[0]),
        case("point_at_end", WAVY, "point", WAVY[-1]),
        case("point_center_of_curvature", ARCH, "point", (0, 0.5, 0)),
        case("point_two_ends_tied", ARCH, "point", (0, -1, 0), unique=False),
        case("point_off_plane", CUBIC, "point", (1.5, 0.5, 2.0)),
        case("point_far_control", FAR, "point", (1, 0, 0), scale=1.0),
        case("point_far_control_off", FAR, "point", (2, 3, -1), scale=1.0),
        case("point_translated", _shifted(WAVY, SHIFT), "point", np.array((1.5, 0.3, 0.2)) + SHIFT),
        case("point_large_curve", big, "point", (1.5e5, 0.4e5, 1.0)),
        case("point_degenerate_curve", ((1, 2, 3),) * 4, "point", (0, 0, 0)),
        case("point_collinear_curve", STRAIGHT, "point", (1.5, 1, 0)),
        case("point_collinear_beyond", STRAIGHT, "point", (5, 0, 0)),
        # ---- line ----
        case("line_through_control_point", WAVY, "line", WAVY[1], (0.3, -1, 0.7)),
        case("line_tangent_apex", ARCH, "line", (0, 1, 0), (1, 0, 0)),
        case("line_tangent_apex_offset", ARCH, "line", (5, 1.25, 0), (1, 0, 0)),
        case("line_along_axis", ARCH, "line", (0, 0, 0), (0, 1, 0)),
        case("line_crossing_plane", CUBIC, "line", (1.5, 0.75, -1), (0, 0, 1)),
        case("line_collinear", STRAIGHT, "line", (7, 0, 0), (-2, 0, 0), unique=False),
        case("line_parallel_offset", STRAIGHT, "line", (0, 1, 0), (1, 0, 0), unique=False),
        case("line_far_origin", CUBIC, "line", (1e6, 2, 0), (1, 0, 0)),
        case("line_far_control", FAR, "line", (1, 0, 0), (0, 0, 1), scale=1.0),
        case("line_translated", _shifted(WAVY, SHIFT), "line", np.array((1, 0.5, -1)) + SHIFT, (0.2, 0.1, 1)),
        case("line_large_curve", big, "line", (2e5, 1e5, 0), (0, 0.1, 1)),
        case("line_short_direction", CUBIC, "line", (1, 2, 0), (1e-9, 1e-9, 0)),
        # ---- ray ----
        case("ray_start_nearest", ARCH, "ray", (0, 2, 0), (0, 1, 0)),
        case("ray_through_curve", ARCH, "ray", (0, 2, 0), (0, -1, 0)),
        case("ray_tangent", ARCH, "ray", (-3, 1, 0), (1, 0, 0)),
        case("ray_through_control_point", WAVY, "ray", (2, -1, -0.3), (1, 1, 1)),
        case("ray_collinear", STRAIGHT, "ray", (1, 0, 0), (1, 0, 0), unique=False),
        case("ray_far_control", FAR, "ray", (1, 0, -1), (0, 0, 1), scale=1.0),
        case("ray_translated", _shifted(CUBIC, SHIFT), "ray", np.array((1.5, 2, 0.5)) + SHIFT, (0, -1, -0.5)),
        # ---- segment ----
        case("segment_collinear_overlap", STRAIGHT, "segment", (1, 0, 0), (5, 0, 0), unique=False),
        case("segment_collinear_inside", STRAIGHT, "segment", (0.5, 0, 0), (1, 0, 0), unique=False),
        case("segment_collinear_apart", STRAIGHT, "segment", (4, 0, 0), (5, 0, 0)),
        case("segment_crossing", CUBIC, "segment", (1.5, 0, 0), (1.5, 2, 0)),
        case("segment_end_nearest", CUBIC, "segment", (1.5, 2, 0), (1.5, 3, 0)),
        case("segment_curve_end_nearest", CUBIC, "segment", (-1, -1, 0.5), (-1, 1, 0.5)),
        case("segment_degenerate", CUBIC, "segment", (1.5, 2, 0), (1.5, 2, 0)),
        case("segment_tangent", ARCH, "segment", (-0.5, 1, 0), (0.5, 1, 0)),
        case("segment_through_control_point", WAVY, "segment", (1, 2, 0.5), (1, 2, 2.5)),
        case("segment_large_curve", big, "segment", (2e5, 0.4e5, -1), (2e5, 0.4e5, 1)),
        case("segment_far_control", FAR, "segment", (1, 0, -1), (1, 0, 1), scale=1.0),
        # a straight curve nearly along the piece (from a random search): every piece of the
        # curve survived the branch and bound and the cap of pieces was spent next to t = 0
        case(
            "segment_nearly_along_straight_curve",
            (
                (0.469088546821133, 0.026205966427920835, 1.8590472355014187),
                (-1.0934957465634532, 0.7561085485942733, 0.22038671559146072),
            ),
            "segment",
            (1.9660258787094098, -0.6730321024438254, 3.428864695992459),
            (-0.3778505617265781, 0.4218217708477871, 0.9708739150794374),
        ),
        case(
            "ray_nearly_along_straight_curve",
            (
                (-0.9657236606277491, 1.6991824952754198, 1.5083294665863227),
                (-0.1909397366488217, 0.19917479281428063, 0.8024648344382479),
            ),
            "ray",
            (-0.6547856173686233, 1.0971959987048914, 1.2250502697758192),
            (7.747839236849074e-08, -1.5000077013826996e-07, -7.058646311897121e-08),
        ),
        # a straight curve's end point against a segment 1e6 away (from a random search): the
        # closed form in world coordinates erred by 6.6e-12 (1.01e-12 of the query's size)
        case(
            "segment_translated_curve_end",
            (
                (1000000.0079412854, -2000001.2940920747, 299999.72433899983),
                (999999.8538955955, -2000001.360227488, 299998.9743287738),
            ),
            "segment",
            (1000003.4983533251, -2000000.1162210216, 300000.34578803234),
            (999997.8895753128, -1999996.7627101275, 300000.6542917533),
        ),
        case(
            "segment_translated",
            _shifted(CUBIC, SHIFT),
            "segment",
            np.array((1.5, 0, 1)) + SHIFT,
            np.array((1.5, 2, -1)) + SHIFT,
        ),
    ]


CASES = _random_cases() + _hard_cases()
IDS = [c.name for c in CASES]
BY_NAME = {c.name: c for c in CASES}


@functools.lru_cache(maxsize=None)
def reference(name):
    c = BY_NAME[name]
    return R.bezier_other(c.ctrl, c.kind, *c.data)


def bar_scale(c: Case, ref) -> float:
    return max(float(ref.distance), c.scale if c.scale is not None else float(ref.scale), 1e-300)


def shapes(c: Case, sweeps=(None, None)):
    a = cd.Bezier(np.array(c.ctrl), sweep=sweeps[0])
    cls = {"point": cd.Point, "line": cd.Line, "ray": cd.Ray, "segment": cd.Segment}[c.kind]
    b = cls(*[np.array(d) for d in c.data], sweep=sweeps[1])
    return a, b


def curve_point(c: Case, t):
    return R.bezier_point(c.ctrl, float(t))


def on_other(c: Case, q, s):
    """|q - (the other shape's point at parameter s)| in mpmath, and whether s is in the interval."""
    q = R.vec(q)
    if c.kind == "point":
        return R.dist(q, R.vec(c.data[0])), s == 0
    o = R.vec(c.data[0])
    d = R.sub(R.vec(c.data[1]), o) if c.kind == "segment" else R.vec(c.data[1])
    inside = c.kind == "line" or (s >= 0 and (c.kind == "ray" or s <= 1))
    return R.dist(q, R.add(o, R.scale(R.to_mp(float(s)), d))), inside


# ------------------------------------------------------------------------------------------------
# the references themselves (no circledist)
# ------------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_reference_known_answers():
    """Answers known in closed form: the far curve passes (1, t^2, t^2) with 2e10 t (1 - t) + t^2 = 1;
    the arch's apex is 1/2 from its center of curvature; a straight curve lies on its line."""
    far = reference("point_far_control")
    assert abs(far.distance / R.mpf("3.5355339062862910e-21") - 1) < 1e-15
    assert abs(reference("point_center_of_curvature").distance - R.mpf("0.5")) < R.mpf("1e-30")
    assert reference("line_collinear").distance == 0
    assert abs(reference("line_tangent_apex_offset").distance - R.mpf("0.25")) < R.mpf("1e-30")


# ------------------------------------------------------------------------------------------------
# the library against them
# ------------------------------------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("precision", list(TOL))
@pytest.mark.parametrize("name", IDS)
def test_distance(name, precision, solver):
    c = BY_NAME[name]
    ref = reference(name)
    a, b = shapes(c)
    opts = dict(precision=precision, solver=solver)
    d = cd.distance(a, b, **opts)
    assert d == cd.distance(b, a, **opts)  # both orders, to the bit
    dtype = np.longdouble if precision == "longdouble" else np.float64
    err = (
        abs(R.to_mp(d) - ref.distance)
        if precision == "float64"
        else abs(R.mpf(np.format_float_scientific(np.longdouble(d), unique=True)) - ref.distance)
    )
    assert float(err) <= TOL[precision] * bar_scale(c, ref), (d, ref)
    assert np.asarray(d).dtype == dtype


@pytest.mark.slow
@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("name", IDS)
def test_closest_points(name, solver):
    c = BY_NAME[name]
    ref = reference(name)
    a, b = shapes(c)
    tol = 1e-12 * bar_scale(c, ref)
    # Points are world coordinates: within rounding of their own size (a scene 1e6 away), and a
    # curve's point is the curve's at its t as computed, whose rounding moves it along the curve
    # by up to its speed x ulp(t) (1e10 x 1e-16 on the far curve).
    ctrl = np.array(c.ctrl)
    size = max(np.abs(ctrl).max(), max(np.abs(np.array(d)).max() for d in c.data))
    speed = (len(ctrl) - 1) * np.linalg.norm(np.diff(ctrl, axis=0), axis=1).max()
    on = 8 * tol + 16 * np.finfo(float).eps * (size + speed)
    r = cd.closest_points(a, b, solver=solver)
    assert r.distance == cd.distance(a, b, solver=solver)
    t, s = float(r.param_a[0]), float(r.param_b[0])
    assert 0 <= t <= 1 and r.param_a[1] == 0 and r.param_b[1] == 0
    assert float(R.dist(R.vec(r.point_a), curve_point(c, t))) <= on
    off, inside = on_other(c, r.point_b, s)
    assert inside and float(off) <= on
    assert abs(float(R.dist(R.vec(r.point_a), R.vec(r.point_b))) - r.distance) <= on
    assert abs(float(R.to_mp(r.distance) - ref.distance)) <= tol
    if c.unique is not None:
        assert r.unique == c.unique
    assert_other_order_swapped(a, b, r, solver)


@pytest.mark.parametrize("name", IDS)
def test_effects_and_sweeps(name):
    c = BY_NAME[name]
    ref = reference(name)
    scale = bar_scale(c, ref)
    a, b = shapes(c)
    d_ref = float(ref.distance)
    # within()'s tolerance is 64 eps x the pair's size from its bounding balls (effects.hpp):
    # 1e10 for the far curve, whatever the answer's own scale.
    size = max(np.abs(np.array(c.ctrl)).max(), max(np.abs(np.array(d)).max() for d in c.data))
    assert_effects_and_sweeps(a, b, lambda ra, rb: shapes(c, (ra, rb)), d_ref, scale, size)


@pytest.mark.parametrize("kind", ["point", "line", "ray", "segment"])
def test_batch_matches_single(kind):
    """Batches of each kind (curves of one degree per batch), both orders, bit for bit."""
    for points in range(1, MAX_POINTS + 1):
        group = [c for c in CASES if c.kind == kind and len(c.ctrl) == points]
        if not group:
            continue
        ctrl = np.array([c.ctrl for c in group])
        fields = [np.array([c.data[i] for c in group]) for i in range(len(group[0].data))]
        cls = {"point": cd.Point, "line": cd.Line, "ray": cd.Ray, "segment": cd.Segment}[kind]
        A, B = cd.Bezier(ctrl), cls(*fields)
        for solver in ("bracketing", "companion"):
            d = cd.distance(A, B, solver=solver)
            assert np.array_equal(d, cd.distance(B, A, solver=solver))
            r = cd.closest_points(A, B, solver=solver)
            w = cd.within(A, B, d)
            for i, c in enumerate(group):
                a, b = shapes(c)
                assert d[i] == cd.distance(a, b, solver=solver), c.name
                single = cd.closest_points(a, b, solver=solver)
                assert r.distance[i] == single.distance
                assert np.array_equal(r.point_a[i], single.point_a) and np.array_equal(r.point_b[i], single.point_b)
                assert np.array_equal(r.param_a[i], single.param_a) and np.array_equal(r.param_b[i], single.param_b)
                assert r.unique[i] == single.unique
                assert w[i]


def test_float32_runs():
    c = BY_NAME["segment_crossing"]
    a, b = shapes(c)
    assert abs(cd.distance(a, b, precision="float32") - float(reference(c.name).distance)) <= 1e-6


def test_far_control_point_is_pieces_accurate():
    """The far curve's answer to the last digits (the pieces in double-double), not only to the
    1e-12 x 1e10 its extent would allow."""
    ref = reference("point_far_control")
    a, b = shapes(BY_NAME["point_far_control"])
    for solver in SOLVERS:
        d = cd.distance(a, b, solver=solver)
        assert abs(R.to_mp(d) / ref.distance - 1) <= 1e-12
        r = cd.closest_points(b, a, solver=solver)
        assert abs(r.param_b[0] - 5e-11) <= 1e-20


def test_scene_accepts_curves_with_linear_shapes():
    scene = cd.Scene()
    scene.add("curve", cd.Bezier(np.array(CUBIC)))
    scene.add("seg", cd.Segment([1.5, 0, 0], [1.5, 2, 0]))
    scene.add("pt", cd.Point([5.0, 5.0, 5.0]))
    scene.add("ray", cd.Ray([10.0, 0, 0], [1.0, 0, 0]))
    assert scene.pairs_within(0.0) == [("curve", "seg")]
    near = scene.nearest(cd.Point([1.5, 0.5, 0]), 1)
    assert [n for n, _ in near] == ["curve"] or [n for n, _ in near] == ["seg"]
    a = cd.Bezier(np.array([CUBIC, CUBIC]) + np.array([0, 0, 0.5]))
    pairs = cd.pairs_within(a, cd.Point(np.array([[1.5, 0.75, 0.0], [9.0, 9.0, 9.0]])), 0.6)
    assert [(int(i), int(j)) for i, j in zip(pairs[0], pairs[1])] == [(0, 0), (1, 0)]
