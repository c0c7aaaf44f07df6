"""Findings of the long differential run (tools/differential.py, 10^5 cases, seed 2026) that are
not fixed yet, kept as strict expected failures: each one turns into an error (XPASS) the day its
class is fixed, and must then move to test_regressions.py.

The references are the differential test's own: 50-digit mpmath minimization over one parameter
(circledist_cases/reference_round.py), agreeing with its dense-sampling screen; none comes from circledist.
The bar is the project's: |error| <= 1e-12 (double), 1e-15 (long double) times
max(true distance, largest radius); float32 answers are double answers rounded, so their bar is
the double one plus the rounding of the answer (4 float32 ulps).
"""

# The last two of the round pairs (a degree-6 Bezier point-symmetric about a ring's center,
# companion policy; internally tangent coplanar rings, bracketing in long double) are fixed and kept
# in test_regressions.py. A new one goes here as a strict xfail with its 50-digit reference.

import numpy as np
import pytest

import circledist as cd
from circledist_cases import reference_round as R

# Found by the differential family bezier_far_control_linear (case bezier_far_control_linear/20261114/0,
# in the CI slice): a degree-5 curve whose first control point is 1.5e9 away, against a point near
# its other control points. The bracketing policy in double answers 0.22785 (t = 0.98515) for the
# true 0.22186 (t = 0.98501, the only local minimum): 6.0e-3 off, 3.9e-12 of the curve's extent (the bar of the Bezier-point
# pairs, tests/test_bezier_point_linear.py); companion, polished and eigen in double, every policy in
# long double and float32 answer 0.2218628054840761.
FAR_CONTROL_CURVE = [[-798380750.5368731, -996066137.8019059, -853819246.0773492],
                     [-0.34295007467759336, -1.3676697302814493, -1.3191024517654566],
                     [0.017748406903181024, -1.2136245313816203, -0.8443267743707685],
                     [1.4917719384991985, -2.1638068968554562, 0.47652795031376005],
                     [0.12812070654574825, -0.5694194217831143, -0.7736516081182655],
                     [0.03495903220114921, -0.7145210841297922, -0.09622166640438767]]
FAR_CONTROL_POINT = [-0.4006278449844352, -1.4541097235775402, -0.943626614802488]


@pytest.mark.xfail(strict=True, reason="bracketing policy, double: a curve with a control point 1.5e9 away "
                   "against a point answers 0.22785 for 0.22186 (at t = 0.98515, not a local minimum)")
def test_bezier_far_control_point_bracketing_double():
    ref = R.bezier_other(FAR_CONTROL_CURVE, "point", FAR_CONTROL_POINT)
    bar = 1e-12 * max(float(ref.distance), R.bezier_other_scale(FAR_CONTROL_CURVE, "point", FAR_CONTROL_POINT))
    a, b = cd.Bezier(np.array(FAR_CONTROL_CURVE)), cd.Point(FAR_CONTROL_POINT)
    for x, y in ((a, b), (b, a)):
        d = cd.distance(x, y, solver="bracketing", precision="float64")
        assert abs(R.to_mp(d) - ref.distance) <= bar, (d, ref)
