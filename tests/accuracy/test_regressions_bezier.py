"""Regressions of Bezier curves, each against an independent 50-digit reference
(circledist_cases/reference_round.py, reference_annulus.py: one-parameter minimization in mpmath,
or a crossing certified in rational arithmetic), under every solver policy, in both argument
orders: far-reaching curves near tied minima, a curve through a ring's center, curves with a far
control point against points, lines, rays and segments, curves through an annulus's ring.

The bar: |error| <= 1e-12 x max(true distance, largest radius in the query) in double, 1e-15 x in
long double (the inputs are float64 values, referenced exactly).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from mpmath import mpf

from circledist_cases import reference_round as R
from circledist_cases.scenes import FAR_CURVE_CONTROL, FAR_CURVE_DISTANCE, FAR_CURVE_RING
from regressions_common import BARS, SOLVERS, cd, make


# A far-reaching degree-1 curve passing a ring with two local minima 2.5e-5 apart in t whose
# values differ by 5.9e-13 (the long differential run's false finding; circledist_cases/scenes.py).
@pytest.mark.parametrize("precision, bar", [("float64", 1e-12), ("longdouble", 1e-15)])
@pytest.mark.parametrize("kind", ["Bezier", "Segment"])
def test_far_curve_near_tied_minima(cd, kind, precision, bar):
    shape = cd.Bezier(FAR_CURVE_CONTROL) if kind == "Bezier" else cd.Segment(*FAR_CURVE_CONTROL)
    ring = cd.Circle(*FAR_CURVE_RING)
    for solver in ("companion", "polished", "bracketing", "eigen"):
        for got in (
            cd.distance(shape, ring, precision=precision, solver=solver),
            cd.closest_points(ring, shape, precision=precision, solver=solver).distance,
        ):
            assert abs(mpf(str(got)) - FAR_CURVE_DISTANCE) <= bar * FAR_CURVE_RING[2], (solver, got)


def _bar32(precision, reference, radius):
    """The bar, and for float32 answers (double answers rounded) 4 float32 ulps more."""
    scale = max(reference, radius)
    if precision == "float32":
        return 1e-12 * scale + 4 * np.spacing(np.float32(reference))
    return BARS[precision] * scale


def _check_open(a, b, solver, precision, reference, radius):
    for x, y in ((a, b), (b, a)):
        for got in (
            cd.distance(x, y, solver=solver, precision=precision),
            cd.closest_points(x, y, solver=solver, precision=precision).distance,
        ):
            assert abs(float(got) - reference) <= _bar32(precision, reference, radius), (solver, got, reference)


# A degree-6 Bezier curve point-symmetric about the ring's center (the long differential run's
# concentric family): its w^6 coefficient cancels to float32 rounding, the stationary polynomial
# gets one root near -2e7, and Eigen's QR on the balanced companion matrix then returned the roots
# in [-1, 1] as complex pairs: the companion policy answered 0.1713 for 0.1601 (float32 and
# float64). The far root is now divided out first (detail/curve_roots.hpp, without_far_roots);
# the family is cpp/tests/test_bezier_center.cpp. Reference: the differential run's 50-digit
# minimization.
_BEZIER = np.array(
    [
        [-0.7396453022956848, -0.739128053188324, -1.4231096506118774],
        [-0.35104236006736755, 0.1521882861852646, -1.4333250522613525],
        [-1.105171799659729, -1.6972906589508057, -1.7876821756362915],
        [-1.1054109334945679, -0.7729302644729614, -1.427234172821045],
        [-1.1056499481201172, 0.15143021941184998, -1.0667861700057983],
        [-1.8597793579101562, -1.698048710823059, -1.4211431741714478],
        [-1.4711765050888062, -0.8067324161529541, -1.4313586950302124],
    ],
    np.float32,
)
CONCENTRIC_BEZIER = (
    cd.Bezier(_BEZIER),
    cd.Circle(
        np.array([-1.1054109334945679, -0.7729302644729614, -1.427234172821045], np.float32),
        np.array([-0.37762004137039185, -0.29596588015556335, 1.6394959688186646], np.float32),
        np.float32(0.5424387454986572),
    ),
    0.1601137907534006,
    0.5424387454986572,
)


@pytest.mark.parametrize("precision", ["float32", "float64", "longdouble"])
def test_bezier_through_the_center(precision):
    for solver in SOLVERS:
        _check_open(*CONCENTRIC_BEZIER[:2], solver, precision, *CONCENTRIC_BEZIER[2:])


# Found by the differential families of the pairs without a round (family
# bezier_far_control_linear; docs/reports/differential.md): the bracketing policy on a Bezier curve
# with one control point 1e9..1e11 away answered the distance at a wrong parameter, off by up to
# 1e-3 in t (the root of an ill-conditioned polynomial), against
#  - a point (bezier_far_control_linear/20261114/0, the CI slice's case): 0.22785 for 0.22186 in
#    double (the only local minimum at t = 0.98501), 3.9e-12 of the curve's extent 1.5e9;
#  - a line (seed 1, cases 73 and 25): 0.60423 for 0.14937 in double; 0.067303 for 0.038455 in
#    long double (5.4e-13 of the extent 5.3e10, against the 1e-15 bar);
#  - a ray and a segment (seed 2, cases 166 and 559): 1.86340 for 1.81322 in double; 6.31175
#    (double) and 6.30991 (long double) for 6.24982.
# The fix (minimize.hpp: polish_newton goes on when its minimum is at an inner end of the
# bracket) answers them all. The bar is that of the
# Bezier-point/line pairs (tests/pairs/test_bezier_point_linear.py): the curve's extent.
FAR_CONTROL = {  # name: (control points, kind, the piece's data, precision)
    "point-double": (
        [
            [-798380750.5368731, -996066137.8019059, -853819246.0773492],
            [-0.34295007467759336, -1.3676697302814493, -1.3191024517654566],
            [0.017748406903181024, -1.2136245313816203, -0.8443267743707685],
            [1.4917719384991985, -2.1638068968554562, 0.47652795031376005],
            [0.12812070654574825, -0.5694194217831143, -0.7736516081182655],
            [0.03495903220114921, -0.7145210841297922, -0.09622166640438767],
        ],
        "point",
        ([-0.4006278449844352, -1.4541097235775402, -0.943626614802488],),
        "float64",
    ),
    "line-double": (
        [
            [-237051799.8855189, -399268632.3605501, -3016979706.461595],
            [-4.49109954989037, -1.574408950014667, 0.42084258644539874],
            [6.043374969599573, -1.7354933705487365, -2.4192848333338484],
            [1.0329081913470768, -5.1364089625427924, -2.7659594598710244],
            [-2.2301643954484014, -1.331864058588449, -3.268935088354538],
            [2.911124373720737, 0.8894682722489453, -0.1324751685781892],
        ],
        "line",
        (
            [-0.3652975927269513, -1.5077880694841528, 0.38085032284279785],
            [2.530300096078537, 1.6656827792893936, -2.034250691777488],
        ),
        "float64",
    ),
    "line-longdouble": (
        [
            [-0.31880956770331625, -0.39559093752493063, -0.4879409224867094],
            [0.3478001656862905, -0.2049724504712177, -0.26054557880821577],
            [-0.9193278759292147, -1.1831790778445872, -0.3112676758597071],
            [-0.6300132819021825, 0.8640752100712643, -1.1978736240727363],
            [0.0756337437482471, 0.1317395452957128, -0.5138105532045715],
            [-0.7198668229997431, 0.3944259221547405, -0.8344441094383297],
            [-41522456731.10714, -14599723381.596434, 30360101158.089157],
        ],
        "line",
        (
            [-0.3632620245250649, 0.23686449653832142, 0.3933610909309045],
            [0.015800260166894738, 0.32400911731506515, 0.4195232510127244],
        ),
        "longdouble",
    ),
    "ray-double": (
        [
            [-29295702.7043048, -196011889.42437443, 63691077.39854266],
            [0.3459309924825159, -0.39308164629852504, 1.2407504657533395],
            [0.7657300910420815, -0.22677575437678818, 1.5886233434925923],
            [0.6267701533440968, 0.2869862771820726, 0.7132102341230505],
            [0.5938569014026924, 0.852676058229136, 0.638025443103922],
            [0.7412236416215497, -0.9738452621328715, 1.1894499348571776],
        ],
        "ray",
        (
            [1.546138070103962, 0.6753541018617785, 0.8087822944305171],
            [1.5045569030131807, 0.3669565003373606, -1.0514491764915928],
        ),
        "float64",
    ),
    "segment-double": (
        [
            [-13755101356.669321, -4174633111.857974, 4073763212.481567],
            [1.2243871928079346, -3.711659326044454, 0.9321776177391667],
            [0.6278279571809471, 0.06430145565233147, -1.1599210703157856],
            [-0.238906545131921, -0.14126418042379507, -1.1101200228375712],
            [3.666065649072498, 3.466693761942905, 0.17855117375500884],
            [-1.4932411700543402, -2.0269035822104553, 1.1117905318429067],
        ],
        "segment",
        (
            [2.7543733480232473, -0.6521013480673424, -4.0062633951094115],
            [2.560358607420274, -0.8622983584303611, -3.617530216935663],
        ),
        "float64",
    ),
}
FAR_CONTROL["segment-longdouble"] = FAR_CONTROL["segment-double"][:3] + ("longdouble",)


_FAR_CONTROL_REFS = {}


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("name", list(FAR_CONTROL))
def test_bezier_far_control_against_linear(name, solver):
    ctrl, kind, data, precision = FAR_CONTROL[name]
    if name not in _FAR_CONTROL_REFS:
        _FAR_CONTROL_REFS[name] = R.bezier_other(ctrl, kind, *data)
    ref = _FAR_CONTROL_REFS[name]
    bar = BARS[precision] * max(float(ref.distance), R.bezier_other_scale(ctrl, kind, *data))
    a, b = cd.Bezier(np.array(ctrl)), make(kind, np.concatenate(data))
    for x, y in ((a, b), (b, a)):
        for got in (
            cd.distance(x, y, solver=solver, precision=precision),
            cd.closest_points(x, y, solver=solver, precision=precision).distance,
        ):
            p, q = np.longdouble(got).as_integer_ratio()
            assert abs(R.mpf(p) / q - ref.distance) <= bar, (got, ref)


# ---- a Bezier curve through an annulus's ring -----------------------------------------------
# Found by the long annulus run (seed 1: 7 of 29,762 cases; seed 2: 8 more, ann_inner_tangent and
# ann_tangent): the companion and eigen policies in long double answered a Bezier curve that
# crosses an annulus's face inside the ring (true distance 0; 50 digits) with 1e-15..2e-14,
# 1.2e-15..7.4e-15 x the outer radius, while bracketing and polished answered ~1e-21, and every
# policy the same curve against the disk (inner radius 0) ~1e-21.  The annulus's interior
# candidates (the roots of the height z and of z', annulus.hpp) were used as the root policy gave
# them, never polished; the curves were degree-elevated arches whose height is linear in t, so
# the height polynomial's higher coefficients are rounding noise, its companion matrix has
# eigenvalues near 1e5, and the QR's backward error put the crossing's small root 1e-14 off.
# They are now refined on the curve itself (bezier.hpp, push_refined_curve_height_roots).
BEZIER_RING = {  # name: (control points, annulus centre, normal, inner, outer)
    # ann_inner_tangent/1/166: crossing 6e-12 outside the hole at t = 0.5; was 9.665594605072491685e-16
    "by_the_hole": (
        [
            [-0.7101942833985928, -0.39068014472128004, -0.32302582640059707],
            [-0.6991227002034476, -0.480351626562345, -0.07555890804429077],
            [-0.7760518042453024, -0.56429297580268, 0.08499566795781921],
            [-0.9409815955241572, -0.642504192442285, 0.15863790160573277],
            [-1.193912074040012, -0.7149852764811601, 0.14536779289944998],
        ],
        [-0.5042840475030932, -0.5819890339998373, 0.35340234813746907],
        [-0.33713368487841255, 0.04617337810703753, 0.3443995953674146],
        0.44428672172024514,
        0.796808950921382,
    ),
    # ann_tangent/1/760: a 1e-6 hole; was 2.121065367614860531e-14 (6.9e-15 x the outer radius)
    "tiny_hole": (
        [
            [1.9410124537551017, 3.753351541927369, 1.546877829541188],
            [1.5903067891120657, 1.9164191936285198, 1.148426524700254],
            [1.204019489879799, 0.8481093996068911, 1.4815797077809183],
            [0.7821505560583013, 0.548422159862483, 2.5463373787831807],
            [0.32469998764757324, 1.0173574743952956, 4.342699537707042],
        ],
        [1.2892608342819993, -0.9932455752506648, -0.27109272677878005],
        [0.17834981144890788, -3.126647222115497, 3.2935248372402555],
        1.0466447969211326e-06,
        3.0744569231399432,
    ),
}


@pytest.fixture(scope="module")
def bezier_ring_references():
    from circledist_cases import reference_annulus as RA

    return {
        name: RA.bezier_reference_mp(RA.annulus(c, n, inner, outer), ctrl)
        for name, (ctrl, c, n, inner, outer) in BEZIER_RING.items()
    }


def _check_through_ring(curve, annulus, ref, outer, solver, precision, scale):
    """Both orders, distance() and closest_points(): the answer exactly against `ref` (an mpf),
    closest_points().distance == distance() to the bit, the points that far apart (up to their
    coordinates' rounding, 8 ulps of the scene's `scale`)."""
    bar = BARS[precision] * max(float(ref), outer)
    ulp = np.finfo(np.longdouble if precision == "longdouble" else np.float64).eps
    for x, y in ((curve, annulus), (annulus, curve)):
        d = cd.distance(x, y, solver=solver, precision=precision)
        assert abs(R.to_mp(d) - ref) <= bar, (solver, precision, float(d))
        r = cd.closest_points(x, y, solver=solver, precision=precision)
        assert r.distance == d
        separation = np.linalg.norm(np.asarray(r.point_a, np.longdouble) - np.asarray(r.point_b, np.longdouble))
        assert abs(separation - np.longdouble(d)) <= bar + 8 * ulp * scale, (solver, precision)


@pytest.mark.parametrize("precision", sorted(BARS))
@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("name", list(BEZIER_RING))
def test_bezier_through_ring(name, solver, precision, bezier_ring_references):
    ctrl, c, n, inner, outer = BEZIER_RING[name]
    ref = bezier_ring_references[name]
    assert ref < mpf("1e-30")
    scale = max(np.abs(np.array(ctrl)).max(), np.abs(np.array(c)).max())
    _check_through_ring(cd.Bezier(np.array(ctrl)), cd.Annulus(c, n, inner, outer), ref, outer, solver, precision, scale)


def _ring_crossings(count, seed):
    """`count` Bezier curves (degree 1..7) each crossing a random annulus's face at a chosen point
    of its ring, transversally (0.1..1.4 rad from the plane), as (control points, centre, normal,
    inner, outer): half of them arches of degree 2 elevated to degree 2..7 (their height linear in
    t, so the height polynomial's higher coefficients are rounding noise: the eigenvalue
    policies' hard case), half random curves moved so that t = 1/2 lands on the point; the point
    anywhere in the ring, or 1e-10..1e-4 x outer from the inner or the outer rim; holes of
    0.05..0.9 x outer or 1e-6 x outer.  The true distance is 0 exactly: certified in rational
    arithmetic (no library code): the height over the plane changes sign between t = 1/2 -+ 1e-12,
    and the whole stretch's projection lies in the ring, its distance from the axis within the
    curve's speed bound x 2e-12 of that at 1/2 - 1e-12."""
    from fractions import Fraction as F

    rng = np.random.default_rng(seed)

    def casteljau(points, t):
        p = list(points)
        for k in range(len(p) - 1, 0, -1):
            p = [tuple((1 - t) * a + t * b for a, b in zip(p[i], p[i + 1])) for i in range(k)]
        return p[0]

    def elevate(points):
        n = len(points) - 1
        return (
            [points[0]]
            + [(i / (n + 1)) * points[i - 1] + (1 - i / (n + 1)) * points[i] for i in range(1, n + 1)]
            + [points[n]]
        )

    out = []
    while len(out) < count:
        k = len(out)
        c = rng.normal(size=3)
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        outer = float(rng.uniform(0.2, 3))
        inner = outer * (1e-6 if k % 5 == 0 else float(rng.uniform(0.05, 0.9)))
        u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
        u /= np.linalg.norm(u)
        v = np.cross(n, u)
        phi = rng.uniform(0, 2 * np.pi)
        r, t = np.cos(phi) * u + np.sin(phi) * v, -np.sin(phi) * u + np.cos(phi) * v
        where = k % 4
        margin = outer * 10.0 ** rng.uniform(-10, -4)
        rho = {0: rng.uniform(inner, outer), 1: inner + margin, 2: outer - margin, 3: inner + margin}[where]
        y = c + rho * r
        psi = rng.uniform(0.1, 1.4)
        d = np.cos(psi) * t + np.sin(psi) * n
        degree = 1 + k % 7
        if k % 2 == 0:
            length = rng.uniform(0.2, 1.5) * outer
            bulge = -r * rho * rng.uniform(0.05, 0.5)
            ctrl = [y - length * d - bulge, y + bulge, y + length * d - bulge]
            while len(ctrl) - 1 < max(degree, 2):
                ctrl = elevate(ctrl)
        else:
            spread = rng.uniform(0.2, 1.5) * outer
            ctrl = [y + spread * rng.normal(size=3) for _ in range(degree + 1)]
            mid = np.array([float(x) for x in casteljau([tuple(map(F, p)) for p in ctrl], F(1, 2))])
            ctrl = [p + (y - mid) for p in ctrl]
        ctrl = np.array(ctrl, dtype=float)
        # The certificate, exactly.
        P = [tuple(map(F, p)) for p in ctrl]
        C, N = tuple(map(F, c)), tuple(map(F, n))
        nn = sum(x * x for x in N)

        def height_rho2(t_):
            q = [a - b for a, b in zip(casteljau(P, t_), C)]
            h = sum(a * b for a, b in zip(q, N))
            return h, sum(a * a for a in q) - h * h / nn

        eps = F(1, 10**12)
        h0, rho2 = height_rho2(F(1, 2) - eps)
        h1, _ = height_rho2(F(1, 2) + eps)
        speed = len(ctrl) * max([np.linalg.norm(b - a) for a, b in zip(ctrl, ctrl[1:])] + [0.0]) * 1.01
        slack = F(speed) * 2 * eps
        rho_lo = F(math.sqrt(float(rho2)) * (1 - 1e-15))  # bounds on rho at 1/2 - 1e-12, wide of rounding
        rho_hi = F(math.sqrt(float(rho2)) * (1 + 1e-15))
        if not (
            h0 * h1 < 0 and rho_lo**2 <= rho2 <= rho_hi**2 and rho_lo - slack >= F(inner) and rho_hi + slack <= F(outer)
        ):
            continue  # not certified (a random curve crossing too steeply near a rim): drawn again
        out.append((ctrl, c, n, inner, outer))
    return out


RING_CROSSINGS = _ring_crossings(140, 20261127)


@pytest.mark.parametrize("precision", sorted(BARS))
@pytest.mark.parametrize("solver", SOLVERS)
def test_bezier_crossing_ring_family(solver, precision):
    """Every curve of _ring_crossings (true distance 0): |d| <= bar x outer radius, both orders,
    distance() and closest_points() (to the bit), the points that far apart."""
    worst = 0.0
    for ctrl, c, n, inner, outer in RING_CROSSINGS:
        scale = max(np.abs(ctrl).max(), np.abs(c).max())
        curve, annulus = cd.Bezier(ctrl), cd.Annulus(c, n, inner, outer)
        _check_through_ring(curve, annulus, mpf(0), outer, solver, precision, scale)
        worst = max(worst, float(cd.distance(curve, annulus, solver=solver, precision=precision)) / outer)
    assert worst <= BARS[precision]
