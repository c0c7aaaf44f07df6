"""Findings of the long differential run (tools/differential.py, 10^5 cases, seed 2026) that are
not fixed yet, kept as strict expected failures: each one turns into an error (XPASS) the day its
class is fixed, and must then move to test_regressions.py.

The references are the differential test's own: 50-digit mpmath minimization over one parameter
(circledist_cases/reference_round.py), agreeing with its dense-sampling screen; none comes from circledist.
The bar is the project's: |error| <= 1e-12 (double), 1e-15 (long double) times
max(true distance, largest radius); float32 answers are double answers rounded, so their bar is
the double one plus the rounding of the answer (4 float32 ulps).
"""

# None open. The last two of the round pairs (a degree-6 Bezier point-symmetric about a ring's
# center, companion policy; internally tangent coplanar rings, bracketing in long double) are fixed
# and kept in test_regressions.py, and so is the first class of the pairs without a round (the
# bracketing policy on Bezier curves with a control point 1e9..1e11 away against a point, line,
# ray or segment: test_bezier_far_control_against_linear). A new one goes here as a strict xfail
# with its 50-digit reference.
