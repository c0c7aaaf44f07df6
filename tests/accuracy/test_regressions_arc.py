"""Regressions of arcs, each against an independent 50-digit reference
(circledist_cases/reference_arc.py: minimization over the arc's angle in mpmath) or an exact
symmetry checked in rationals, under every solver policy, in both argument orders: an arc whose
circle passes through the other round's axis, and closest_points().unique of an arc coaxial with
a circle, disk or annulus (a continuum of closest pairs).

The bar: |error| <= 1e-12 x max(true distance, largest radius in the query) in double, 1e-15 x in
long double (the inputs are float64 values, referenced exactly).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from circledist_cases import reference_arc as A
from circledist_cases import reference_round as R
from circledist_cases.kind_checks import make as make_shape
from regressions_common import BARS, SOLVERS, cd


# ---- an arc whose circle passes through the other round's axis (the arc runs of the
# differential test: the long arc runs, family arc_end_on_axis) ----------------
# The circle-circle octic of such a pair, e.g. (u^2 - 1)^2 (9 u^4 - 22 u^2 + 9) / 729, has a
# balanced companion matrix on which Eigen's real Schur iteration does not converge: the
# companion and eigen policies had no roots at all, and an arc whose span holds the interior
# minimum was answered at its end or another local minimum, 1.3-18 % too far (float64; one case
# in long double). Roots now come from isolation where the iteration fails (roots.hpp,
# roots_without_eigenvalues; C++ test_roots stalling_companion). Minimised from
# arc_end_on_axis/1/69, /694, /1571 and arc_end_on_axis/2/458, /611.
PAST_PI = math.pi + 1e-3
ARC_THROUGH_AXIS = [
    # (name, other shape, arc, exact distance (a function giving it at 50 digits) or None,
    # precisions that fail): shapes as the tuples reference_arc takes
    (
        "circle-arc",
        ("circle", (0.0, 1.5, 0.0), (0.0, 1.0, 0.0), 0.5),
        A.arc((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), 0.5, (0.0, -1.0, 0.0), PAST_PI),
        lambda: A.ctx.sqrt(10) / 2 - A.mpf(1) / 2,
        ("float64",),
    ),  # companion, eigen: 1.1178106951014877 (the end)
    (
        "disk-arc",
        ("disk", (-0.75, 0.0, 0.0), (1.0, 0.0, 0.0), 0.25),
        A.arc((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.5, (1.0, 0.0, 0.0), PAST_PI),
        lambda: A.mpf(3) / 2 - A.ctx.sqrt(10) / 4,
        ("float64",),
    ),  # companion, eigen: 0.7287707068690193
    (
        "arc-arc",
        A.arc(
            (1.5000000378657594, -3.5, -0.7499999870388022),
            (0.0, -8.0, 0.0),
            1.0,
            (0.09235596786032592, 0.0, -0.9957260542943438),
            6.283184750066664,
        ),
        A.arc((1.5, -0.75, -0.75), (-8.0, 0.0, 0.0), 1.0, (0.0, -1.0, 0.0), math.pi),
        None,
        ("float64",),
    ),  # companion, eigen: 2.0150689259397274; reference 1.926174982109305
    (
        "circle-arc-axis-3e-13-beside",
        ("circle", (-1.25, -2.125, 0.4999999999996971), (0.0, -1.0, 0.0), 1.5),
        A.arc((-1.25, 0.5, 0.5), (1.0, 0.0, 0.0), 1.0, (0.0, -1.0, 0.0), math.pi / 2),
        None,
        ("float64",),
    ),  # companion, eigen: 2.21148...; reference 2.0233466556121065
    (
        "circle-arc-long-double",
        ("circle", (-2.125, -0.2500000000804208, -4.352557640837963e-11), (-0.25, 0.0, 0.0), 1.0),
        A.arc((-0.25, -0.25, 0.0), (0.0, 0.25, 0.0), 1.0, (-1.0, 0.0, 0.0), 4.71238898038469),
        None,
        ("longdouble",),
    ),  # companion, eigen: 1.3280161426903714; reference 1.1249999999795174
]


@pytest.fixture(scope="module")
def arc_through_axis_references():
    return {case[0]: A.reference_mp(case[2], case[1]) for case in ARC_THROUGH_AXIS}


def test_circle_through_ring_axis_arc_references(arc_through_axis_references):
    """The 50-digit references agree with the closed forms where the scene has one (the distance
    from the other ring's rim point to the arc's circle, in the plane they share)."""
    for name, _, _, exact, _ in ARC_THROUGH_AXIS:
        if exact is not None:
            assert abs(arc_through_axis_references[name] - exact()) < A.mpf("1e-40"), name


@pytest.mark.parametrize("precision", ["float64", "longdouble"])
@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("case", ARC_THROUGH_AXIS, ids=lambda c: c[0])
def test_circle_through_ring_axis_arc(case, solver, precision, arc_through_axis_references):
    name, other, arc, _, _ = case
    ref = arc_through_axis_references[name]
    bar = BARS[precision] * max(float(ref), other[3], arc[3])
    for x, y in ((make_shape(other), make_shape(arc)), (make_shape(arc), make_shape(other))):
        d = cd.distance(x, y, solver=solver, precision=precision)
        assert abs(R.to_mp(d) - ref) <= bar, (name, solver, precision)  # the answer exactly, against 50 digits
        r = cd.closest_points(x, y, solver=solver, precision=precision)
        assert r.distance == d
        separation = np.linalg.norm(np.asarray(r.point_a, np.longdouble) - np.asarray(r.point_b, np.longdouble))
        # the points round by an ulp or so of their coordinates (the scenes reach 4): 8 ulps of 4
        ulp = np.finfo(np.longdouble if precision == "longdouble" else np.float64).eps
        assert abs(separation - np.longdouble(d)) <= bar + 8 * ulp * 4, (name, solver, precision)


# ---- closest_points().unique of an arc coaxial with a round ------------------------------------
# Found by the differential's unique rule (circledist_cases/differential.py, expected_unique,
# "coaxial rounds"): the scenes below said unique = True under some policies (listed with each).
# Cause: where the distance is flat along the arc, polishing took every start (the arc's ends and
# the circle's candidates on it) to one point (a Newton step on rounding noise runs to the
# interval's end), so the polished minima showed one pair; the arc's ends now count for ties
# (arc.hpp, add_ends_for_ties).
# An arc coaxial with a circle, disk or annulus (same centre, normals exactly parallel or
# opposite; random frames) in the same plane: every arc point is as far from the other shape --
# lying on its rim or face (distance 0 along the whole arc) or inside the hole at one gap -- a
# continuum of closest pairs, so unique must be False (differential.expected_unique: "coaxial
# rounds").  Which policies say True varies with the scene: "polished" only in the CI slice's
# arc_spans cases, every policy, or every policy but "polished", in others.  Exact inputs along
# the axes (Circle([0,0,0],[0,0,1],1) and a quarter arc) give False under every policy.  The long
# annulus run found them in float32 scenes (float32 rounding makes the scenes exactly coaxial);
# here those float32 values are given as float64.  No distance is wrong; the flag is.
# name: (other kind, other's data (an annulus: centre, normal, OUTER, inner, as the differential's),
#        arc data (centre, normal, radius, start, angle), failing solvers, failing precisions)
_COAXIAL_ARCS = {
    # CI slice arc_spans/20261114/3 (float32 scene): the arc on the circle's rim
    "circle_rim": (
        "circle",
        [
            0.3754752576351166,
            0.041786301881074905,
            0.8691385984420776,
            -0.5726931691169739,
            0.5593754649162292,
            0.7319510579109192,
            0.8811383843421936,
        ],
        [
            0.3754752576351166,
            0.041786301881074905,
            0.8691385984420776,
            -0.5726931691169739,
            0.5593754649162292,
            0.7319510579109192,
            0.8811383843421936,
            -0.8095112442970276,
            -0.06531886011362076,
            -0.5834594964981079,
            0.9098467826843262,
        ],
        ("polished",),
        ("float64", "longdouble"),
    ),
    # arc_spans/7/1: the arc on the disk's rim (opposite normals)
    "disk_rim": (
        "disk",
        [
            -0.059277256740215334,
            1.8470368353084892,
            0.10379885584694382,
            -3.0907616804010214,
            4.546472063483862,
            -5.985165406879597,
            0.521713543590457,
        ],
        [
            -0.059277256740215334,
            1.8470368353084892,
            0.10379885584694382,
            3.0907616804010214,
            -4.546472063483862,
            5.985165406879597,
            0.521713543590457,
            -0.22889874925302353,
            0.7145959313793093,
            0.6610280005011427,
            1.5707963267948966,
        ],
        ("polished",),
        ("float64", "longdouble"),
    ),
    # long run ann_parallel_height/1/154: an annulus of inner = outer (the circle), the arc on it
    "annulus_as_circle": (
        "annulus",
        [
            0.8247418999671936,
            -0.3103605806827545,
            -1.2652921676635742,
            -1.204155683517456,
            -5.464598178863525,
            4.803603649139404,
            1.6804858446121216,
            1.6804858446121216,
        ],
        [
            0.8247418999671936,
            -0.3103605806827545,
            -1.2652921676635742,
            1.204155683517456,
            5.464598178863525,
            -4.803603649139404,
            1.6804858446121216,
            0.11864553391933441,
            0.6406819820404053,
            0.7585840821266174,
            0.5085752010345459,
        ],
        ("bracketing", "companion", "polished", "eigen"),
        ("float64",),
    ),
    # ann_parallel_height/1/254: an annulus of inner 0 (the disk), the arc on its rim
    "annulus_as_disk": (
        "annulus",
        [
            -0.4618120789527893,
            0.48371386528015137,
            -0.5567301511764526,
            -0.05153070017695427,
            0.16629648208618164,
            0.3010227084159851,
            1.0204261541366577,
            0.0,
        ],
        [
            -0.4618120789527893,
            0.48371386528015137,
            -0.5567301511764526,
            0.05153070017695427,
            -0.16629648208618164,
            -0.3010227084159851,
            1.0204261541366577,
            0.3025674819946289,
            -0.8114180564880371,
            0.5000535845756531,
            1.0640931129455566,
        ],
        ("bracketing", "companion", "polished", "eigen"),
        ("float64",),
    ),
    # ann_far_translated/1/331: the arc inside the hole, 7.45e-9 from the inner rim all along
    "in_hole": (
        "annulus",
        [
            35322096.0,
            -74047784.0,
            -19948296.0,
            -4.212611675262451,
            -1.4199488162994385,
            2.3996176719665527,
            0.3228744566440582,
            0.09953676164150238,
        ],
        [
            35322096.0,
            -74047784.0,
            -19948296.0,
            -4.212611675262451,
            -1.4199488162994385,
            2.3996176719665527,
            0.09953675419092178,
            0.21371813118457794,
            -0.9579126238822937,
            -0.1916453093290329,
            0.6517081260681152,
        ],
        ("bracketing", "companion", "eigen"),
        ("float64",),
    ),
    # ann_near_concentric/1/844: the arc on the outer rim of an annulus with a 4.5e-7 hole
    "outer_rim": (
        "annulus",
        [
            -1.0637127161026,
            0.3427371382713318,
            0.38309207558631897,
            -0.09201692789793015,
            -0.009696000255644321,
            0.9183531999588013,
            0.9733959436416626,
            4.5047869434711174e-07,
        ],
        [
            -1.0637127161026,
            0.3427371382713318,
            0.38309207558631897,
            -0.09201692789793015,
            -0.009696000255644321,
            0.9183531999588013,
            0.9733959436416626,
            -0.7781444191932678,
            0.6240161657333374,
            -0.07137994468212128,
            1.5707963705062866,
        ],
        ("polished",),
        ("float64",),
    ),
    # seed 2's ann_far_translated/2/952 (float64 scene, translated by 1e11): the arc inside the hole,
    # 0.207 from the inner rim all along; long double only
    "in_hole_far": (
        "annulus",
        [
            56352424623.11552,
            92282982952.53368,
            -69984351500.61127,
            -3.944493218390809,
            3.170623902328786,
            0.15660873819560903,
            0.5960259175039737,
            0.29082514344868654,
        ],
        [
            56352424623.11552,
            92282982952.53368,
            -69984351500.61127,
            -3.944493218390809,
            3.170623902328786,
            0.15660873819560903,
            0.08363334738015628,
            0.5235957996734671,
            0.6769434646327138,
            -0.5172958382351053,
            0.1565287527326864,
        ],
        ("bracketing", "companion", "eigen"),
        ("longdouble",),
    ),
}


def _coaxial(other, arc):
    """Independent of the library: the same centre and exactly parallel normals (rational cross
    product 0), so each arc point is as far from the other shape (rotational symmetry)."""
    from fractions import Fraction

    f = [Fraction(x) for x in other[3:6]]
    g = [Fraction(x) for x in arc[3:6]]
    cross = (f[1] * g[2] - f[2] * g[1], f[2] * g[0] - f[0] * g[2], f[0] * g[1] - f[1] * g[0])
    return other[:3] == arc[:3] and cross == (0, 0, 0)


def _shape(kind, d):
    if kind == "annulus":
        return cd.Annulus(d[:3], d[3:6], d[7], d[6])
    return getattr(cd, kind.capitalize())(d[:3], d[3:6], d[6])


@pytest.mark.parametrize("precision", ["float64", "longdouble"])
@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("name", sorted(_COAXIAL_ARCS))
def test_unique_coaxial_arc(name, solver, precision):
    """Each scene under every policy and precision (not only the ones that said True)."""
    kind, other, arc, _, _ = _COAXIAL_ARCS[name]
    assert _coaxial(other, arc)
    a, b = _shape(kind, other), cd.Arc(arc[:3], arc[3:6], arc[6], arc[7:10], arc[10])
    for x, y in ((a, b), (b, a)):
        assert not cd.closest_points(x, y, solver=solver, precision=precision).unique


def _coaxial_family():
    """Random arcs coaxial with a random circle, disk or annulus: the same centre, the normal
    exactly parallel or opposite (scaled by a power of two, negated), in the plane or at a height
    along the axis (then every arc point is as far by rotation about the axis), the arc's radius on
    a rim, on the face, in the hole or beyond, its angle in [0.2, 2 pi), centres near the origin or
    translated by up to 1e11."""
    rng = np.random.default_rng(20261127)
    out = []
    for i in range(48):
        kind = ("circle", "disk", "annulus")[i % 3]
        c = rng.normal(size=3) * (10.0 ** rng.choice([0, 6, 11]))
        n = rng.normal(size=3)
        outer = rng.uniform(0.5, 2)
        inner = outer * rng.uniform(0.1, 0.9)
        radius = {
            0: outer,
            1: inner,
            2: rng.uniform(0.05, 1) * inner,
            3: rng.uniform(inner, outer),
            4: outer * rng.uniform(1.1, 3),
        }[int(rng.integers(0, 5))]
        height = 0.0 if i % 2 else rng.uniform(-1, 1)
        arc_normal = n * 2.0 ** int(rng.integers(-3, 4)) * (-1) ** int(rng.integers(0, 2))
        unit = n / np.linalg.norm(n)
        arc_center = c + height * unit if height else c
        other = list(c) + list(n) + ([outer, inner] if kind == "annulus" else [outer])
        arc = list(arc_center) + list(arc_normal) + [radius] + list(rng.normal(size=3)) + [rng.uniform(0.2, 6.2)]
        out.append((f"{kind}-{i}", kind, other, arc, height))
    return out


@pytest.mark.parametrize("precision", ["float64", "longdouble"])
@pytest.mark.parametrize("solver", SOLVERS)
def test_unique_coaxial_arc_family(solver, precision):
    """Every arc point is as far from the other shape (rotation about the common axis): unique is
    False in both orders, under every policy and precision. (Where the arc's centre is lifted along
    the axis, the lifted centre is rounded: the family keeps only scenes whose centre is on the
    axis exactly, checked in rationals, as _coaxial does.)"""
    checked = 0
    for name, kind, other, arc, height in _coaxial_family():
        if height and not _on_axis(other, arc):
            continue
        a = _shape(kind, other[:6] + ([other[6], other[7]] if kind == "annulus" else [other[6]]))
        b = cd.Arc(arc[:3], arc[3:6], arc[6], arc[7:10], arc[10])
        for x, y in ((a, b), (b, a)):
            assert not cd.closest_points(x, y, solver=solver, precision=precision).unique, name
        checked += 1
    assert checked >= 24


def _near_equal_coaxial_family():
    """Arcs coaxial with a circle whose radius differs from the arc's by a few ulps up to 1e-9 of
    it, either way (the differential test's arc_concentric/4/309: a circle 4.4e-14 smaller than the
    arc, polished in double, reported unique): the circle smaller than the arc is parametrized whole
    against the arc (arc.hpp ArcArcQuery), where polishing on a distance flat to rounding took every
    start to one point. In the plane, or lifted along the axis where the lifted centre stays on it
    exactly; centres near the origin or translated by 1e6."""
    rng = np.random.default_rng(20261128)
    out = []
    for i in range(40):
        c = rng.normal(size=3) * (10.0 ** rng.choice([0, 6]))
        n = rng.normal(size=3)
        r = rng.uniform(0.5, 3)
        rel = (-1) ** i * 10.0 ** rng.uniform(-15.5, -9)
        radius = r * (1 + rel)
        height = 0.0 if i % 4 < 2 else rng.uniform(-1, 1)
        unit = n / np.linalg.norm(n)
        arc_center = c + height * unit if height else c
        arc = (
            list(arc_center)
            + list(n * 2.0 ** int(rng.integers(-2, 3)))
            + [radius]
            + list(rng.normal(size=3))
            + [rng.uniform(0.2, 6.2)]
        )
        out.append((f"circle-{i}", list(c) + list(n) + [r], arc, height))
    return out


@pytest.mark.parametrize("precision", ["float64", "longdouble"])
@pytest.mark.parametrize("solver", SOLVERS)
def test_unique_coaxial_near_equal_radii(solver, precision):
    """A circle and a coaxial arc of nearly its radius: every arc point is as far (rotation about
    the axis), so unique is False in both orders under every policy and precision."""
    checked = 0
    for name, circle, arc, height in _near_equal_coaxial_family():
        if height and not _on_axis(circle, arc):
            continue
        a = cd.Circle(circle[:3], circle[3:6], circle[6])
        b = cd.Arc(arc[:3], arc[3:6], arc[6], arc[7:10], arc[10])
        for x, y in ((a, b), (b, a)):
            assert not cd.closest_points(x, y, solver=solver, precision=precision).unique, name
        checked += 1
    assert checked >= 20


def _on_axis(other, arc):
    """The arc's centre exactly on the other shape's axis (rational cross product of the offset and
    the normal 0), its normal exactly parallel."""
    from fractions import Fraction

    d = [Fraction(x) - Fraction(y) for x, y in zip(arc[:3], other[:3])]
    f = [Fraction(x) for x in other[3:6]]
    cross = (d[1] * f[2] - d[2] * f[1], d[2] * f[0] - d[0] * f[2], d[0] * f[1] - d[1] * f[0])
    g = [Fraction(x) for x in arc[3:6]]
    normal_cross = (f[1] * g[2] - f[2] * g[1], f[2] * g[0] - f[0] * g[2], f[0] * g[1] - f[1] * g[0])
    return cross == (0, 0, 0) and normal_cross == (0, 0, 0)
