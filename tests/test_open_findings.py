"""Findings of the long differential runs (tools/differential.py) that are not fixed yet, kept as
strict expected failures: each one turns into an error (XPASS) the day its class is fixed, and
must then move to test_regressions.py.

The references are the differential test's own: 50-digit mpmath minimization over one parameter
(circledist_cases/reference_round.py, reference_arc.py), agreeing with its dense-sampling screen;
none comes from circledist.  The bar is the project's: |error| <= 1e-12 (double), 1e-15 (long
double) times max(true distance, largest radius); float32 answers are double answers rounded, so
their bar is the double one plus the rounding of the answer (4 float32 ulps).
"""

# The round pairs: none open. The last two (a degree-6 Bezier point-symmetric about a ring's
# center, companion policy; internally tangent coplanar rings, bracketing in long double) are
# fixed and kept in test_regressions.py, and so is the first class of the pairs without a round
# (the bracketing policy on Bezier curves with a control point 1e9..1e11 away against a point,
# line, ray or segment: test_bezier_far_control_against_linear).

# None open. The arc cases of the long arc runs (family arc_end_on_axis: the companion and eigen
# policies answering an arc at its end where its interior held the minimum) were Eigen's real
# Schur iteration stalling on the octic's companion matrix (roots.hpp, roots_without_eigenvalues):
# fixed, and kept in test_regressions.py (test_circle_through_ring_axis_arc). A new finding goes
# here as a strict xfail with its 50-digit reference.


# ---- closest_points().unique (the differential's unique rule, 2026-11-27) ---------------------
# An arc coaxial with a circle, disk or annulus (same centre, normals exactly parallel or
# opposite; random frames) in the same plane: every arc point is as far from the other shape --
# lying on its rim or face (distance 0 along the whole arc) or inside the hole at one gap -- a
# continuum of closest pairs, so unique must be False (differential.expected_unique: "coaxial
# rounds").  Which policies say True varies with the scene: "polished" only in the CI slice's
# arc_spans cases, every policy, or every policy but "polished", in others.  Exact inputs along
# the axes (Circle([0,0,0],[0,0,1],1) and a quarter arc) give False under every policy.  The long
# annulus run found them in float32 scenes (float32 rounding makes the scenes exactly coaxial);
# here those float32 values are given as float64.  No distance is wrong; the flag is.
import numpy as np  # noqa: E402
import pytest  # noqa: E402

cd = pytest.importorskip("circledist")

# name: (other kind, other's data (an annulus: centre, normal, OUTER, inner, as the differential's),
#        arc data (centre, normal, radius, start, angle), failing solvers, failing precisions)
_COAXIAL_ARCS = {
    # CI slice arc_spans/20261114/3 (float32 scene): the arc on the circle's rim
    "circle_rim": ("circle", [0.3754752576351166, 0.041786301881074905, 0.8691385984420776,
                              -0.5726931691169739, 0.5593754649162292, 0.7319510579109192, 0.8811383843421936],
                   [0.3754752576351166, 0.041786301881074905, 0.8691385984420776, -0.5726931691169739,
                    0.5593754649162292, 0.7319510579109192, 0.8811383843421936, -0.8095112442970276,
                    -0.06531886011362076, -0.5834594964981079, 0.9098467826843262],
                   ("polished",), ("float64", "longdouble")),
    # arc_spans/7/1: the arc on the disk's rim (opposite normals)
    "disk_rim": ("disk", [-0.059277256740215334, 1.8470368353084892, 0.10379885584694382, -3.0907616804010214,
                          4.546472063483862, -5.985165406879597, 0.521713543590457],
                 [-0.059277256740215334, 1.8470368353084892, 0.10379885584694382, 3.0907616804010214,
                  -4.546472063483862, 5.985165406879597, 0.521713543590457, -0.22889874925302353,
                  0.7145959313793093, 0.6610280005011427, 1.5707963267948966],
                 ("polished",), ("float64", "longdouble")),
    # long run ann_parallel_height/1/154: an annulus of inner = outer (the circle), the arc on it
    "annulus_as_circle": ("annulus", [0.8247418999671936, -0.3103605806827545, -1.2652921676635742,
                                      -1.204155683517456, -5.464598178863525, 4.803603649139404,
                                      1.6804858446121216, 1.6804858446121216],
                          [0.8247418999671936, -0.3103605806827545, -1.2652921676635742, 1.204155683517456,
                           5.464598178863525, -4.803603649139404, 1.6804858446121216, 0.11864553391933441,
                           0.6406819820404053, 0.7585840821266174, 0.5085752010345459],
                          ("bracketing", "companion", "polished", "eigen"), ("float64",)),
    # ann_parallel_height/1/254: an annulus of inner 0 (the disk), the arc on its rim
    "annulus_as_disk": ("annulus", [-0.4618120789527893, 0.48371386528015137, -0.5567301511764526,
                                    -0.05153070017695427, 0.16629648208618164, 0.3010227084159851,
                                    1.0204261541366577, 0.0],
                        [-0.4618120789527893, 0.48371386528015137, -0.5567301511764526, 0.05153070017695427,
                         -0.16629648208618164, -0.3010227084159851, 1.0204261541366577, 0.3025674819946289,
                         -0.8114180564880371, 0.5000535845756531, 1.0640931129455566],
                        ("bracketing", "companion", "polished", "eigen"), ("float64",)),
    # ann_far_translated/1/331: the arc inside the hole, 7.45e-9 from the inner rim all along
    "in_hole": ("annulus", [35322096.0, -74047784.0, -19948296.0, -4.212611675262451, -1.4199488162994385,
                            2.3996176719665527, 0.3228744566440582, 0.09953676164150238],
                [35322096.0, -74047784.0, -19948296.0, -4.212611675262451, -1.4199488162994385,
                 2.3996176719665527, 0.09953675419092178, 0.21371813118457794, -0.9579126238822937,
                 -0.1916453093290329, 0.6517081260681152],
                ("bracketing", "companion", "eigen"), ("float64",)),
    # ann_near_concentric/1/844: the arc on the outer rim of an annulus with a 4.5e-7 hole
    "outer_rim": ("annulus", [-1.0637127161026, 0.3427371382713318, 0.38309207558631897, -0.09201692789793015,
                              -0.009696000255644321, 0.9183531999588013, 0.9733959436416626, 4.5047869434711174e-07],
                  [-1.0637127161026, 0.3427371382713318, 0.38309207558631897, -0.09201692789793015,
                   -0.009696000255644321, 0.9183531999588013, 0.9733959436416626, -0.7781444191932678,
                   0.6240161657333374, -0.07137994468212128, 1.5707963705062866],
                  ("polished",), ("float64",)),
    # seed 2's ann_far_translated/2/952 (float64 scene, translated by 1e11): the arc inside the hole,
    # 0.207 from the inner rim all along; long double only
    "in_hole_far": ("annulus", [56352424623.11552, 92282982952.53368, -69984351500.61127, -3.944493218390809,
                                3.170623902328786, 0.15660873819560903, 0.5960259175039737, 0.29082514344868654],
                    [56352424623.11552, 92282982952.53368, -69984351500.61127, -3.944493218390809,
                     3.170623902328786, 0.15660873819560903, 0.08363334738015628, 0.5235957996734671,
                     0.6769434646327138, -0.5172958382351053, 0.1565287527326864],
                    ("bracketing", "companion", "eigen"), ("longdouble",)),
}
_COAXIAL_FAILS = [(name, s, p) for name, case in _COAXIAL_ARCS.items() for s in case[3] for p in case[4]]


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


@pytest.mark.xfail(strict=True, reason="unique=True for an arc coaxial and coplanar with a circle, disk or annulus "
                                       "(every arc point as close: a continuum)")
@pytest.mark.parametrize("name, solver, precision", _COAXIAL_FAILS)
def test_unique_coaxial_arc(name, solver, precision):
    kind, other, arc, _, _ = _COAXIAL_ARCS[name]
    assert _coaxial(other, arc)
    a, b = _shape(kind, other), cd.Arc(arc[:3], arc[3:6], arc[6], arc[7:10], arc[10])
    for x, y in ((a, b), (b, a)):
        assert not cd.closest_points(x, y, solver=solver, precision=precision).unique


# ---- a Bezier curve through an annulus's ring (2026-11-27): fixed --------------------------
# The companion and eigen policies in long double answered a Bezier curve crossing an annulus's
# face inside the ring (truth 0) with 1e-15..2e-14: the interior height candidates were never
# polished.  Fixed (bezier.hpp, push_refined_curve_height_roots) and kept in test_regressions.py
# (test_bezier_through_ring, test_bezier_crossing_ring_family).
