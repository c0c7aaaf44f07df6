"""Regressions of circles and disks against each other, each against an independent 50-digit
reference (mpmath geometry written here, no library code), under every solver policy, in both
argument orders: within() on nearly coaxial parallel rings, disks coplanar within rounding, rings
crossing near their common center, coplanar rings crossing next to a tangency.

The bar: |error| <= 1e-12 x max(true distance, largest radius in the query) in double, 1e-15 x in
long double (the inputs are float64 values, referenced exactly).
"""

from __future__ import annotations

import numpy as np
import pytest
from mpmath import mp, mpf

from regressions_common import BARS, EPS, SOLVERS, cd, make


# within() decided by bounds whose sample points had left their shape: parallel circles of equal
# radius nearly on one axis (in-plane offset 2.7e-17, planes 1.88e-7 apart). The point of A
# nearest B's center, scaled out to A's rim, was 1.7e-9 off A's plane, and in long double
# within(d) said True 1.75e-9 below the distance. The truth (the planes' separation) is computed
# here in mpmath.
PARALLEL_COAXIAL = (
    (
        -1.7049544532287482,
        -0.4196123492227376,
        -0.6174039345691138,
        4.669208110269334,
        -0.9104412238263111,
        -3.44955441916865,
        2.0775529896862657,
    ),
    (
        -1.7049546023051612,
        -0.41961232015457256,
        -0.6174038244332648,
        -4.669208110269334,
        0.9104412238263111,
        3.44955441916865,
        2.0775529896862657,
    ),
)


@pytest.mark.parametrize("precision", sorted(BARS))
@pytest.mark.parametrize("kinds", [("circle", "circle"), ("circle", "disk"), ("disk", "disk")])
def test_within_parallel_nearly_coaxial(kinds, precision):
    a, b = PARALLEL_COAXIAL
    mp.dps = 50
    n = [mpf(x) for x in a[3:6]]
    norm = mp.sqrt(sum(x * x for x in n))
    height = abs(sum((mpf(q) - mpf(p)) * x / norm for p, q, x in zip(a[:3], b[:3], n)))
    sa, sb = make(kinds[0], a), make(kinds[1], b)
    truth = float(height)
    bar = BARS[precision] * a[6]
    for x, y in ((sa, sb), (sb, sa)):
        assert abs(float(cd.distance(x, y, precision=precision)) - truth) <= bar
        assert cd.within(x, y, truth + 2 * bar, precision=precision)
        assert not cd.within(x, y, truth - 2 * bar, precision=precision)
        assert np.isinf(cd.distance_if_within(x, y, truth - 2 * bar, precision=precision))


# Disks coplanar within rounding but not exactly (one 6.3e-15 above the other's plane, centers
# 6.3e-15 apart along the normal): the contact point was put in B's plane, off A by 2 ulps of
# the radius, and reported at distance 0. Closest points lie on both disks to a few ulps.
@pytest.mark.parametrize("solver", SOLVERS)
def test_disks_coplanar_within_rounding_points_on_both(solver):
    a = (
        -1.4156594408668646,
        0.4715817383194796,
        -0.3749771405031259,
        -3.660440794139036,
        -4.569617412843425,
        0.22856891273652835,
        1.9878174268191156,
    )
    b = (
        -1.4156594408668686,
        0.4715817383194747,
        -0.3749771405031257,
        -3.660440794139036,
        -4.569617412843425,
        0.22856891273652835,
        1.9878174268191156,
    )
    mp.dps = 50
    n = [mpf(x) for x in a[3:6]]
    norm = mp.sqrt(sum(x * x for x in n))
    n = [x / norm for x in n]

    def off_disk(p, d):  # distance of p from disk d, in mpmath
        w = [mpf(float(x)) - mpf(c) for x, c in zip(p, d[:3])]
        h = sum(x * y for x, y in zip(w, n))
        radial = mp.sqrt(max(mpf(0), sum(x * x for x in w) - h * h))
        return mp.sqrt(h * h + max(mpf(0), radial - mpf(d[6])) ** 2)

    height = abs(sum((mpf(q) - mpf(p)) * x for p, q, x in zip(a[:3], b[:3], n)))
    sa, sb = make("disk", a), make("disk", b)
    for x, y, dx, dy in ((sa, sb, a, b), (sb, sa, b, a)):
        r = cd.closest_points(x, y, solver=solver)
        assert abs(r.distance - float(height)) <= 1e-12 * a[6]
        assert off_disk(r.point_a, dx) <= 8 * EPS * 2 and off_disk(r.point_b, dy) <= 8 * EPS * 2


# Two rings of equal radius whose centers differ by 1e-14 and whose planes are tilted cross at two
# points. The raw eigenvalue policies answered 0.505 (the rings' size): the octic's roots were too
# far off to lead the polish there; the points where one ring crosses the other's plane are now
# starts too. Reference: 50-digit mpmath minimization over the angle (the long differential
# run, docs/reports/differential.md), 1.0925491132860966e-14.
NEAR_CONCENTRIC_RINGS = (
    (
        [-0.6647478320178631, -0.1478456243803689, 0.5419060141101574],
        [1.2516289029374994, 1.918050346932966, -2.020965388079425],
        0.39345072874537984,
    ),
    (
        [-0.6647478320178529, -0.14784562438033882, 0.5419060141101185],
        [0.09078177042049894, 2.543035662455498, 1.689532903938856],
        0.39345072874537984,
    ),
)


@pytest.mark.parametrize("solver", ["companion", "polished", "bracketing", "eigen"])
@pytest.mark.parametrize("precision, bar", [("float64", 1e-12), ("longdouble", 1e-15)])
def test_near_concentric_crossing_rings(cd, solver, precision, bar):
    a, b = (cd.Circle(*x) for x in NEAR_CONCENTRIC_RINGS)
    reference, radius = 1.0925491132860966e-14, NEAR_CONCENTRIC_RINGS[0][2]
    for x, y in ((a, b), (b, a)):
        got = float(cd.distance(x, y, solver=solver, precision=precision))
        assert abs(got - reference) <= bar * radius, (got, reference)
        assert cd.within(x, y, 2 * reference, solver=solver, precision=precision)


# Coplanar rings that cross by a few ulps next to a tangency (internal or external), and a ring
# crossing a coplanar disk's rim the same way. The distance along the parametrized ring is a W:
# zeros about sqrt(overlap) rad either side of a bump as high as the overlap. The octic's roots
# there are lost to rounding (its values near the cluster are ~overlap^(3/2), below eps); in long
# double, bracketing answered 2.4e-15 for 0 (radii 1.5 and 0.5, overlap 13 ulps): the polish
# started on the bump's flank, where the squared distance is concave, and Brent's parabolas kept
# the bump (the long differential run). Newton's fallback now walks downhill first
# (minimize.hpp, downhill_bracket). Reference: the in-plane geometry in 50-digit mpmath: rings at
# center distance d are min(|d - (Ra + Rb)|, ...) apart, 0 when |Ra - Rb| <= d <= Ra + Rb; a ring
# and a disk 0 when |d - Ra| <= Rb, else |d - Ra| - Rb. Not from circledist.
def _coplanar_round_cases():
    rng = np.random.default_rng(14)
    cases = []
    # The finding itself and its neighbours (overlaps of 1 to 40 ulps of the center distance).
    for k in range(1, 41):
        cases.append(("circle", [-1.0, -0.5, -0.25], [k * EPS, -0.5, -0.25], [0.0, 0.0, 0.25], 1.5, 0.5))
    for i in range(48):
        axis = np.zeros(3)
        axis[i % 3] = (0.25, 1.0, -3.0)[i % 3]
        angle = rng.uniform(0, 2 * np.pi) if i % 4 else (i // 4 % 8) * np.pi / 4
        u = np.zeros(3)
        u[(i + 1) % 3], u[(i + 2) % 3] = np.cos(angle), np.sin(angle)
        ra = float(rng.choice([1.5, 1.0, rng.uniform(0.5, 2.0)]))
        rb = float(ra * rng.choice([1 / 3, rng.uniform(0.05, 0.95)]))
        center = rng.integers(-2, 3, size=3) * 0.25
        kind = "circle" if i % 3 else "disk"
        for precision_eps in (EPS, np.finfo(np.longdouble).eps):
            overlap = float(rng.integers(1, 300) * precision_eps)
            external = i % 2 == 0
            d = (ra + rb - overlap) if external else (ra - rb + overlap)
            if kind == "disk":  # the ring of radius ra crossing the rim of the disk of radius rb
                d = (ra + rb - overlap) if external else (ra - rb - overlap)
            cases.append((kind, list(center), list(center + d * u), list(axis), ra, rb))
    return cases


def _coplanar_round_reference(kind, ca, cb, ra, rb):
    d = mp.sqrt(sum((mpf(x) - mpf(y)) ** 2 for x, y in zip(ca, cb)))
    ra, rb = mpf(ra), mpf(rb)
    if kind == "disk":
        return max(mpf(0), abs(d - ra) - rb)
    return max(mpf(0), d - ra - rb, abs(ra - rb) - d)


@pytest.mark.parametrize("precision", sorted(BARS))
def test_coplanar_rings_crossing_near_tangency(cd, precision):
    mp.dps = 50
    failures = []
    for kind, ca, cb, axis, ra, rb in _coplanar_round_cases():
        ring = cd.Circle(ca, axis, ra)
        other = getattr(cd, kind.capitalize())(cb, axis, rb)
        truth = _coplanar_round_reference(kind, ca, cb, ra, rb)
        bar = BARS[precision] * max(float(truth), ra, rb)
        for solver in SOLVERS:
            for x, y in ((ring, other), (other, ring)):
                for got in (
                    cd.distance(x, y, solver=solver, precision=precision),
                    cd.closest_points(x, y, solver=solver, precision=precision).distance,
                ):
                    if not abs(mpf(str(got)) - truth) <= bar:
                        failures.append((kind, ca, cb, axis, ra, rb, solver, str(got), float(truth)))
    assert not failures, failures[:5]
