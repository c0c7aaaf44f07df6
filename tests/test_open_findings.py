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
# An arc lying on a circle or disk's rim (same centre, normals exactly parallel or opposite, same
# radius; a random frame): every arc point is on the other shape, a continuum of contact, so
# unique must be False.  The bracketing, companion and eigen policies say False; "polished" says
# True, in double and long double (distance ~1e-17 / ~1e-21, within the bar).  Exact inputs along
# the axes (Circle([0,0,0],[0,0,1],1) and a quarter arc) give False under every policy.  Found by
# the CI slice (arc_spans/20261114/3, float32 scene; here its float32 values as float64) and the
# quick runs (arc_spans/7/1, the disk).  No distance is wrong; the flag is.
import numpy as np  # noqa: E402
import pytest  # noqa: E402

cd = pytest.importorskip("circledist")

_ARC_ON_RIM = [
    ("circle", [0.3754752576351166, 0.041786301881074905, 0.8691385984420776],
     [-0.5726931691169739, 0.5593754649162292, 0.7319510579109192], 0.8811383843421936,
     [0.3754752576351166, 0.041786301881074905, 0.8691385984420776],
     [-0.5726931691169739, 0.5593754649162292, 0.7319510579109192], 0.8811383843421936,
     [-0.8095112442970276, -0.06531886011362076, -0.5834594964981079], 0.9098467826843262),
    ("disk", [-0.059277256740215334, 1.8470368353084892, 0.10379885584694382],
     [-3.0907616804010214, 4.546472063483862, -5.985165406879597], 0.521713543590457,
     [-0.059277256740215334, 1.8470368353084892, 0.10379885584694382],
     [3.0907616804010214, -4.546472063483862, 5.985165406879597], 0.521713543590457,
     [-0.22889874925302353, 0.7145959313793093, 0.6610280005011427], 1.5707963267948966),
]


def _same_rim(case):
    """Independent of the library: the arc's centre equals the other's, the normals are exactly
    parallel (rational cross product 0) and the radii are equal, so the arc lies on the rim."""
    from fractions import Fraction
    kind, c, n, r, ac, an, ar, start, angle = case
    f = [Fraction(x) for x in n]
    g = [Fraction(x) for x in an]
    cross = (f[1] * g[2] - f[2] * g[1], f[2] * g[0] - f[0] * g[2], f[0] * g[1] - f[1] * g[0])
    return c == ac and r == ar and cross == (0, 0, 0)


@pytest.mark.xfail(strict=True, reason="polished policy: unique=True for an arc lying on a coaxial circle's / disk's "
                                       "rim (a continuum of contact); the other policies say False")
@pytest.mark.parametrize("precision", ["float64", "longdouble"])
@pytest.mark.parametrize("case", _ARC_ON_RIM, ids=[c[0] for c in _ARC_ON_RIM])
def test_polished_unique_arc_on_rim(case, precision):
    assert _same_rim(case)
    kind, c, n, r, ac, an, ar, start, angle = case
    a = getattr(cd, kind.capitalize())(c, n, r)
    b = cd.Arc(ac, an, ar, start, angle)
    for x, y in ((a, b), (b, a)):
        res = cd.closest_points(x, y, solver="polished", precision=precision)
        assert res.distance <= 1e-12 * r
        assert not res.unique
