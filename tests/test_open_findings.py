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


# closest_points().unique for an arc coaxial with a circle, disk or annulus (every arc point as
# close: a continuum; found by the differential's unique rule, 2026-11-27): fixed (arc.hpp,
# add_ends_for_ties), kept in test_regressions.py (test_unique_coaxial_arc and its family).


# ---- a Bezier curve through an annulus's ring (2026-11-27): fixed --------------------------
# The companion and eigen policies in long double answered a Bezier curve crossing an annulus's
# face inside the ring (truth 0) with 1e-15..2e-14: the interior height candidates were never
# polished.  Fixed (bezier.hpp, push_refined_curve_height_roots) and kept in test_regressions.py
# (test_bezier_through_ring, test_bezier_crossing_ring_family).
