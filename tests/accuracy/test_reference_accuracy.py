"""Accuracy of circledist against the independent 50-digit references (circledist_cases/reference_linear_round.py).

Kinds: point, line, ray and segment against circle and disk.  Each kind has 40 seeded
random cases and every hard scene of circledist_cases/scenes.py (tangent, near-tangent at heights
1e-3/1e-6/1e-9, along / near the axis, tilted through the centre, in-plane, near-parallel,
crossing or ending exactly on the rim, parallel above the disk, zero-length segments), in
two orientations, translated by 0, 1e6 and 1e8, plus radius 1e-9 / 1e9 (scene scaled or
not) and radius 0.  Every case runs in both argument orders.

Accuracy rule (never loosened):  |d - d_ref| <= 1e-12 * max(d_ref, R).

Closest points:
* both points lie on their shapes and are `distance` apart, to 1e-12*scale PLUS the
  binary64 representation limit of the returned coordinates (about eps*|point|: a point at
  1e8 cannot be written to better than ~1e-8, whatever the algorithm).  This slack applies
  to the points only, never to the distance.
* when the reference minimiser is bounded, the returned points must be near the reference
  ones: within max(1e-6*scale, r) where r is the reference's own bound on how far ANY pair
  that passes the checks above can be from the reference pair.  1e-6 rather than 1e-12
  because positions at a minimum are ill-conditioned: if the distance is tight to eta, a
  quadratic minimum only fixes the position to ~sqrt(eta) and a flat (quartic) one, e.g.
  a line parallel to the plane above a tangent, only to ~eta^(1/4).
* `unique` must be False wherever the reference minimiser is an exact tie or a continuum,
  and True for the random cases whose minimiser is clearly isolated.
"""

import math

import numpy as np
import pytest
from mpmath import mp, mpf

from circledist_cases import reference_linear_round as ref
from circledist_cases import scenes
from circledist_cases.shapes import make_shape

# A sweep of 8,912 cases: the test task runs it, the check task leaves it out.
pytestmark = pytest.mark.slow

REL = 1e-12
EPS = float(np.finfo(float).eps)
CASES = scenes.all_cases()
ORDERS = ["lin_first", "round_first"]


def in_both_orders(cases):
    """Parametrizes a test by every one of `cases` (named by its id) and both argument orders."""

    def parametrized(test):
        by_case = pytest.mark.parametrize("case", cases, ids=[c.id for c in cases])(test)
        return pytest.mark.parametrize("order", ORDERS)(by_case)

    return parametrized


def _refr(case):
    return ref.reference(case.lin_kind, case.lin_data, case.round_kind, case.round_data)


def _scale(r):
    return max(r.scale, mpf("1e-300"))


def _shapes(cd, case, order):
    lin = make_shape(cd, case.lin_kind, case.lin_data)
    rnd = make_shape(cd, case.round_kind, case.round_data)
    return (lin, rnd) if order == "lin_first" else (rnd, lin)


def _fmt(x):
    return mp.nstr(mpf(x), 17)


@in_both_orders(CASES)
def test_distance(cd, case, order):
    r = _refr(case)
    a, b = _shapes(cd, case, order)
    d = cd.distance(a, b)
    assert isinstance(d, float), f"single query returned {type(d)}"
    scale = _scale(r)
    err = abs(mpf(d) - r.distance)
    assert err <= REL * scale, (
        f"distance {d!r} vs reference {_fmt(r.distance)}: error {float(err):.3e} = "
        f"{float(err / scale):.3e} * scale (allowed 1e-12), scale {float(scale):.3e}"
    )


def _check_closest(case, order, res, r):
    """All closest-point checks; returns a list of problems (empty = pass)."""
    problems = []
    scale = _scale(r)
    tol = REL * scale
    d = res.distance
    if order == "lin_first":
        p_lin, p_round = np.asarray(res.point_a, float), np.asarray(res.point_b, float)
    else:
        p_lin, p_round = np.asarray(res.point_b, float), np.asarray(res.point_a, float)
    if p_lin.shape != (3,) or p_round.shape != (3,):
        return [f"point shapes {p_lin.shape}, {p_round.shape} instead of (3,)"]
    if not (np.all(np.isfinite(p_lin)) and np.all(np.isfinite(p_round))):
        return [f"non-finite points {p_lin}, {p_round}"]
    err = abs(mpf(d) - r.distance)
    if err > tol:
        problems.append(
            f"closest_points.distance {d!r} vs reference {_fmt(r.distance)}: " f"error {float(err / scale):.3e} * scale"
        )
    sl_lin = 2 * EPS * float(np.linalg.norm(p_lin))  # representation limit
    sl_round = 2 * EPS * float(np.linalg.norm(p_round))
    on_lin = ref.distance_to_shape(p_lin, case.lin_kind, case.lin_data)
    on_round = ref.distance_to_shape(p_round, case.round_kind, case.round_data)
    if on_lin > tol + sl_lin:
        problems.append(
            f"point on {case.lin_kind} is {float(on_lin):.3e} off it " f"(allowed {float(tol + sl_lin):.3e})"
        )
    if on_round > tol + sl_round:
        problems.append(
            f"point on {case.round_kind} is {float(on_round):.3e} off it " f"(allowed {float(tol + sl_round):.3e})"
        )
    sep = ref.mp_distance(p_lin, p_round)
    if abs(sep - mpf(d)) > tol + sl_lin + sl_round:
        problems.append(f"|point_a - point_b| = {_fmt(sep)} but distance = {d!r}")
    # any pair passing the checks above is eta-optimal with
    eta = 4 * float(tol) + 2 * sl_lin + 2 * sl_round
    # round eta up to a quarter decade (a larger eta only loosens the bound) so that both
    # argument orders share the cached sub-level computation
    eta = 10 ** (math.ceil(math.log10(eta) * 4) / 4)
    ra, rb = r.near_optimal_radius(eta)
    floor = 1e-6 * float(scale)
    for kind, point, reference_point, radius, slack in (
        (case.lin_kind, p_lin, r.point_lin, ra, sl_lin),
        (case.round_kind, p_round, r.point_round, rb, sl_round),
    ):
        if math.isfinite(radius):
            dev = float(ref.mp_vec_distance(point, reference_point))
            lim = max(floor, radius + float(tol) + slack)
            if dev > lim:
                problems.append(f"point on {kind} is {dev:.3e} from the reference point (allowed {lim:.3e})")
    unique = bool(res.unique)
    if r.degenerate and unique:
        problems.append("unique is True but the closest pairs are an exact tie or a continuum")
    if case.random and r.unique and not unique:
        if all(math.isfinite(x) for x in r.near_optimal_radius(1e-9 * float(scale))):
            problems.append("unique is False for a generic case with an isolated minimiser")
    return problems


@in_both_orders(CASES)
def test_closest_points(cd, case, order):
    r = _refr(case)
    a, b = _shapes(cd, case, order)
    res = cd.closest_points(a, b)
    problems = _check_closest(case, order, res, r)
    assert not problems, "; ".join(problems)


PARAM_CASES = [c for c in CASES if c.lin_kind != "point" and (c.random or c.offset == 0.0)]


@in_both_orders(PARAM_CASES)
def test_linear_parameter(cd, case, order):
    """For lines/rays/segments the parameter reported with a point (its first component,
    if a vector) is the t of the API:
    point = origin + t*direction (segment: p0 + t*(p1 - p0)), t >= 0 for rays, t in [0, 1]
    for segments."""
    a, b = _shapes(cd, case, order)
    res = cd.closest_points(a, b)
    point = np.asarray(res.point_a if order == "lin_first" else res.point_b, float)
    t = np.asarray(res.param_a if order == "lin_first" else res.param_b, float).reshape(-1)
    # the library may report every parameter as a fixed-length vector; t comes first
    assert t.size >= 1, f"empty parameter for a {case.lin_kind}"
    t = float(t[0])
    data = np.asarray(case.lin_data, float)
    base = data[:3]
    m = data[3:6] - base if case.lin_kind == "segment" else data[3:6]
    if case.lin_kind == "ray":
        assert t >= 0.0, f"ray parameter {t} < 0"
    if case.lin_kind == "segment":
        assert 0.0 <= t <= 1.0, f"segment parameter {t} outside [0, 1]"
    r = _refr(case)
    scale = float(_scale(r))
    rebuilt = [mpf(float(base[i])) + mpf(t) * mpf(float(m[i])) for i in range(3)]
    gap = float(ref.mp_vec_distance(point, tuple(rebuilt)))
    allowed = REL * scale + 4 * EPS * (float(np.linalg.norm(point)) + abs(t) * float(np.linalg.norm(m)))
    assert gap <= allowed, f"origin + t*direction is {gap:.3e} from the returned point (t={t!r})"
