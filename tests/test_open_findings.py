"""Findings of the long differential run (tools/differential.py, 10^5 cases, seed 2026) that are
not fixed yet, kept as strict expected failures: each one turns into an error (XPASS) the day its
class is fixed, and must then move to test_regressions.py.

The references are the differential test's own: 50-digit mpmath minimization over one parameter
(tests/reference_round.py), agreeing with its dense-sampling screen; none comes from circledist.
The bar is the project's: |error| <= 1e-12 (double), 1e-15 (long double) times
max(true distance, largest radius); float32 answers are double answers rounded, so their bar is
the double one plus the rounding of the answer (4 float32 ulps).
"""

import numpy as np
import pytest

cd = pytest.importorskip("circledist")


def _bar(precision, reference, radius):
    scale = max(reference, radius)
    if precision == "longdouble":
        return 1e-15 * scale
    if precision == "float32":
        return 1e-12 * scale + 4 * np.spacing(np.float32(reference))
    return 1e-12 * scale


def _check(a, b, solver, precision, reference, radius):
    for x, y in ((a, b), (b, a)):
        got = float(cd.distance(x, y, solver=solver, precision=precision))
        assert abs(got - reference) <= _bar(precision, reference, radius), (got, reference)


# A degree-6 Bezier curve whose middle control point is the ring's center: the companion policy
# answers 0.1713 for 0.1601 (in float32 and float64).
_BEZIER = np.array([[-0.7396453022956848, -0.739128053188324, -1.4231096506118774],
                    [-0.35104236006736755, 0.1521882861852646, -1.4333250522613525],
                    [-1.105171799659729, -1.6972906589508057, -1.7876821756362915],
                    [-1.1054109334945679, -0.7729302644729614, -1.427234172821045],
                    [-1.1056499481201172, 0.15143021941184998, -1.0667861700057983],
                    [-1.8597793579101562, -1.698048710823059, -1.4211431741714478],
                    [-1.4711765050888062, -0.8067324161529541, -1.4313586950302124]], np.float32)
CONCENTRIC_BEZIER = (
    cd.Bezier(_BEZIER),
    cd.Circle(np.array([-1.1054109334945679, -0.7729302644729614, -1.427234172821045], np.float32),
              np.array([-0.37762004137039185, -0.29596588015556335, 1.6394959688186646], np.float32),
              np.float32(0.5424387454986572)),
    0.1601137907534006, 0.5424387454986572)


@pytest.mark.xfail(strict=True, reason="issue 14: Bezier through the ring's center, companion policy")
@pytest.mark.parametrize("precision", ["float32", "float64"])
def test_bezier_through_the_center_companion(precision):
    _check(*CONCENTRIC_BEZIER[:2], "companion", precision, *CONCENTRIC_BEZIER[2:])
