"""Stability sweeps toward each degeneracy, through the Python API with the default root policy.

The families live in circledist_cases/sweeps.py (shared with bench/accuracy_vs_time.py, which
plots every policy into docs/reports/stability_sweeps.png):
  axis-tilt     a line tilted from the circle's axis by 10^-k rad, k = 0..16
  tangent-lift  the tangent line lifted by h = 10^-k, k = 0..16 (distance exactly h)
  offset        fixed scenes translated by 10^k (1, -0.7, 0.4), k = 0..9
  circle-tilt   a circle / disk tilted from coplanar by 10^-k rad, k = 0..16
Bar (never loosened): |d - d_ref| <= 1e-12 * max(d_ref, largest radius of the query), in double.
References are of the exact float inputs: the analytic distance where there is one, else a
50-digit one-parameter minimisation of a closed form (circledist_cases/reference_linear_round.py,
reference_round.py).
"""

import pytest
from mpmath import mp, mpf

from circledist_cases import sweeps

BAR = 1e-12
CASES = sweeps.sweep_cases()


def test_every_family_is_swept():
    assert {c.family for c in CASES} == set(sweeps.FAMILIES)
    for family, (_, _, ks) in sweeps.FAMILIES.items():
        assert sorted({c.k for c in CASES if c.family == family}) == list(ks)


def test_tangent_lift_reference_is_the_height():
    """The analytic tangent-lift distance agrees with the independent mpmath reference."""
    for c in CASES:
        if c.family == "tangent-lift" and c.exact is not None and c.k in (0, 6, 16):
            ref = sweeps._mp_reference(c.kind, c.values)
            assert abs(ref - mpf(c.exact)) <= mpf("1e-30") * max(ref, 1)


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES, ids=[c.label.replace(" ", "_") for c in CASES])
def test_default_policy_within_bar(cd, case):
    a, b = sweeps.make_shapes(cd, case.kind, case.values)
    d = float(cd.distance(a, b))
    err, ref, radius = sweeps.relative_error(d, case)
    assert err <= BAR, (
        f"{case.label}: distance {d!r}, reference {mp.nstr(ref, 20)}, largest radius {radius}, "
        f"relative error {err:.3e} > {BAR:.0e}"
    )
