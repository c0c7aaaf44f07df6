"""Bezier curves against Bezier curves (bezier_bezier.hpp).

References: circledist_cases/reference_bezier.py, mpmath at 50 digits and nothing from
circledist: the four edges (an end point against the other curve) by one-parameter minimisation
(reference_round.bezier_other: dense sampling and golden section), the interior by 50-digit
Newton descents with a line search from the local minima of a dense grid of the squared distance.

Accuracy rule: |d - d_ref| <= 1e-12 * max(d_ref, scale) in double, 1e-15 * max(d_ref, scale) in
long double, `scale` the largest curve size in the query (the larger control polygon extent).
Every solver, both argument orders, closest_points (points on their curves, separation ==
distance, distance bit-identical to distance()), `unique` where clear-cut (continua of closest
pairs: false), within / intersects, swept curves, batches with broadcasting (bit-identical to
single calls), and the degenerate curves against the point and segment queries.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Optional

import numpy as np
import pytest

import circledist as cd
from circledist_cases import reference_bezier as RB
from circledist_cases import bezier_cases as BB
from circledist_cases.bezier_cases import ARCH, CROSS, CUBIC_A, CUBIC_B, LINE, shifted
from circledist_cases import reference_round as R
from circledist_cases.effect_checks import assert_effects_and_sweeps, assert_other_order_swapped

SOLVERS = ("bracketing", "companion", "polished", "eigen")
TOL = {"float64": 1e-12, "longdouble": 1e-15}
MAX_POINTS = cd._core._max_control_points


@dataclass(frozen=True)
class Case:
    name: str
    a: tuple
    b: tuple
    unique: Optional[bool] = None  # expected `unique` when clear-cut


def _t(v):
    return tuple(float(x) for x in v)


def case(name, a, b, unique=None):
    return Case(name, tuple(_t(p) for p in a), tuple(_t(p) for p in b), unique)


def _random_cases():
    rng = np.random.default_rng(2019)
    out = []
    for na, nb in (
        (2, 2),
        (2, 2),
        (3, 3),
        (3, 3),
        (3, 3),
        (3, 2),
        (1, 3),
        (1, 1),
        (4, 5),
        (5, 3),
        (7, 2),
        (6, 7),
        (7, 7),
    ):
        a = rng.uniform(-2, 2, (na + 1, 3))
        b = rng.uniform(-2, 2, (nb + 1, 3)) + rng.uniform(-1, 1, 3)
        out.append(case(f"random_deg{na}_deg{nb}_{len(out)}", a, b))
    return out


def _hard_cases():
    return [case(*scene) for scene in BB.hard_scenes()]


CASES = _random_cases() + _hard_cases()
IDS = [c.name for c in CASES]
BY_NAME = {c.name: c for c in CASES}


@functools.lru_cache(maxsize=None)
def reference(name):
    c = BY_NAME[name]
    return RB.bezier_bezier(c.a, c.b)


def bar_scale(ref) -> float:
    return max(float(ref.distance), float(ref.scale), 1e-300)


def shapes(c: Case, sweeps=(None, None)):
    return cd.Bezier(np.array(c.a), sweep=sweeps[0]), cd.Bezier(np.array(c.b), sweep=sweeps[1])


def error(d, ref, precision):
    x = R.to_mp(d) if precision == "float64" else R.mpf(np.format_float_scientific(np.longdouble(d), unique=True))
    return float(abs(x - ref.distance))


# ------------------------------------------------------------------------------------------------
# the references themselves (no circledist)
# ------------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_reference_known_answers():
    """The crossing is at the arch's apex; the shifted straight curves are as far apart all along
    as their offset across them (0.5, 0.625); identical curves meet everywhere; the arches touch at
    the apex (the second is the first mirrored through y = 1); the near crossing passes the apex
    at the rounded 1e-9 offset."""
    assert reference("crossing").distance == 0
    assert abs(reference("parallel_offset").distance - R.mpf("0.5")) < R.mpf("1e-40")
    assert abs(reference("parallel_offset_overlap").distance - R.mpf("0.625")) < R.mpf("1e-40")
    assert reference("identical").distance == 0
    assert abs(reference("nearly_touching_1e-9").distance - R.mpf(1 + 1e-9) + 1) < R.mpf("1e-25")
    assert reference("tangent_arches").distance < R.mpf("1e-20")


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
    assert error(d, ref, precision) <= TOL[precision] * bar_scale(ref), (d, ref)
    assert np.asarray(d).dtype == (np.longdouble if precision == "longdouble" else np.float64)


@pytest.mark.slow
@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("name", IDS)
def test_closest_points(name, solver):
    c = BY_NAME[name]
    ref = reference(name)
    a, b = shapes(c)
    tol = 1e-12 * bar_scale(ref)
    # Points are world coordinates: within rounding of their own size (a scene 1e6 away).
    size = max(np.abs(np.array(c.a)).max(), np.abs(np.array(c.b)).max())
    on = 8 * tol + 16 * np.finfo(float).eps * size
    r = cd.closest_points(a, b, solver=solver)
    assert r.distance == cd.distance(a, b, solver=solver)
    s, t = float(r.param_a[0]), float(r.param_b[0])
    assert 0 <= s <= 1 and 0 <= t <= 1 and r.param_a[1] == 0 and r.param_b[1] == 0
    assert float(R.dist(R.vec(r.point_a), R.bezier_point(c.a, s))) <= on
    assert float(R.dist(R.vec(r.point_b), R.bezier_point(c.b, t))) <= on
    assert abs(float(R.dist(R.vec(r.point_a), R.vec(r.point_b))) - r.distance) <= on
    assert abs(float(R.to_mp(r.distance) - ref.distance)) <= tol
    if c.unique is not None:
        assert r.unique == c.unique
    assert_other_order_swapped(a, b, r, solver)


@pytest.mark.parametrize("name", IDS)
def test_effects_and_sweeps(name):
    c = BY_NAME[name]
    ref = reference(name)
    scale = bar_scale(ref)
    a, b = shapes(c)
    d_ref = float(ref.distance)
    size = max(np.abs(np.array(c.a)).max(), np.abs(np.array(c.b)).max())
    assert_effects_and_sweeps(a, b, lambda ra, rb: shapes(c, (ra, rb)), d_ref, scale, size)


def _single(c, solver):
    a, b = shapes(c)
    return cd.distance(a, b, solver=solver), cd.closest_points(a, b, solver=solver)


@pytest.mark.parametrize("solver", ("bracketing", "companion"))
def test_batch_matches_single(solver):
    """Batches of curves of one degree pair, both orders, with broadcasting (a batch against one
    curve; a column against a row), bit for bit against single calls."""
    groups = {}
    for c in CASES:
        groups.setdefault((len(c.a), len(c.b)), []).append(c)
    for group in groups.values():
        A = cd.Bezier(np.array([c.a for c in group]))
        B = cd.Bezier(np.array([c.b for c in group]))
        d = cd.distance(A, B, solver=solver)
        assert np.array_equal(d, cd.distance(B, A, solver=solver))
        r = cd.closest_points(A, B, solver=solver)
        w = cd.within(A, B, d)
        for i, c in enumerate(group):
            ds, single = _single(c, solver)
            assert d[i] == ds, c.name
            assert r.distance[i] == single.distance
            assert np.array_equal(r.point_a[i], single.point_a) and np.array_equal(r.point_b[i], single.point_b)
            assert np.array_equal(r.param_a[i], single.param_a) and np.array_equal(r.param_b[i], single.param_b)
            assert r.unique[i] == single.unique
            assert w[i]
    # broadcasting: cubics (n, 1) against cubics (m,), and a batch against one curve
    cubics = [c for c in CASES if len(c.a) == 4 and len(c.b) == 4]
    A = np.array([c.a for c in cubics])
    B = np.array([c.b for c in cubics])
    m = cd.distance(cd.Bezier(A[:, None]), cd.Bezier(B), solver=solver)
    assert m.shape == (len(cubics), len(cubics))
    for i in range(len(cubics)):
        for j in range(len(cubics)):
            assert m[i, j] == cd.distance(cd.Bezier(A[i]), cd.Bezier(B[j]), solver=solver)
    one = cd.distance(cd.Bezier(A), cd.Bezier(B[0]), solver=solver)
    assert np.array_equal(one, m[:, 0])


def test_degenerate_curves_agree_with_point_and_segment_queries():
    """A curve whose control points are equal is a point; collinear control points traversed once
    are a segment: the answers agree with the point and segment queries (to rounding)."""
    dot = cd.Bezier(np.array(BY_NAME["point_curve"].a))
    p = cd.Point(BY_NAME["point_curve"].a[0])
    cubic = cd.Bezier(np.array(CUBIC_A))
    assert abs(cd.distance(dot, cubic) - cd.distance(p, cubic)) <= 1e-15
    c = BY_NAME["collinear_collinear"]
    sa, sb = cd.Segment(c.a[0], c.a[-1]), cd.Segment(c.b[0], c.b[-1])
    a, b = shapes(c)
    assert abs(cd.distance(a, b) - cd.distance(sa, sb)) <= 1e-15
    assert abs(cd.distance(a, cd.Bezier(np.array(CUBIC_B))) - cd.distance(sa, cd.Bezier(np.array(CUBIC_B)))) <= 1e-15
    line = cd.Bezier(np.array(LINE))
    assert (
        abs(
            cd.distance(line, cd.Bezier(np.array(CUBIC_B)))
            - cd.distance(cd.Segment(LINE[0], LINE[-1]), cd.Bezier(np.array(CUBIC_B)))
        )
        <= 1e-15
    )
    # an empty batch
    assert cd.distance(cd.Bezier(np.zeros((0, 3, 3))), cubic).shape == (0,)


def test_float32_runs():
    a, b = shapes(BY_NAME["random_deg3_deg3_2"])
    ref = reference("random_deg3_deg3_2")
    a32 = cd.Bezier(np.array(BY_NAME["random_deg3_deg3_2"].a, dtype=np.float32))
    b32 = cd.Bezier(np.array(BY_NAME["random_deg3_deg3_2"].b, dtype=np.float32))
    assert abs(cd.distance(a32, b32) - float(ref.distance)) <= 1e-5
    assert abs(cd.distance(a, b, precision="float32") - float(ref.distance)) <= 1e-5


def test_scene_and_pairs_with_curves():
    """Scenes of curves: nearest and pairs_within through the same kernels."""
    scene = cd.Scene()
    scene.add("arch", cd.Bezier(np.array(ARCH)))
    scene.add("cross", cd.Bezier(np.array(CROSS)))
    scene.add("far", cd.Bezier(np.array(shifted(CUBIC_A, (10, 0, 0)))))
    assert scene.nearest(cd.Bezier(np.array(shifted(CROSS, (0, 1e-3, 0)))))[0][0] in ("arch", "cross")
    assert ("arch", "cross") in [tuple(sorted(p)) for p in scene.pairs_within(1e-9)]
