"""The references of cpp/tests/test_bezier_linear.cpp: 50-digit mpmath minima over the curve's t
of the closed-form distance to a point, line, ray or segment (circledist_cases/reference_round.py
bezier_other: no polynomial roots, nothing from circledist). Run from the repository's root:
    python cpp/tests/bezier_linear_reference.py
and paste its lines into the test's table."""

from circledist_cases import reference_round as R

CUBIC = ((0, 0, 0), (1, 1, 0), (2, 1, 0), (3, 0, 0))
WAVY = ((0, 0, 0), (1, 2, 0.5), (2, -1, -0.3), (3, 1.5, 0.2), (4, -0.5, 0))
FAR = ((0, 0, 0), (1e10, 0, 0), (1, 1, 1))
CASES = [
    ("point", CUBIC, ((1.5, 0.3, 0.2),)),
    ("point", WAVY, ((2.5, 0.5, -1.0),)),
    ("point", FAR, ((1, 0, 0),)),
    ("line", WAVY, ((1, 2, 0.5), (0.3, -1, 0.7))),
    ("line", CUBIC, ((0, 2, 1), (1, 0.1, 0.3))),
    ("ray", CUBIC, ((1.5, 2, 0.5), (0, -1, -0.5))),
    ("ray", WAVY, ((5, 0, 0), (1, 1, 0))),
    ("segment", CUBIC, ((-1, -1, 0.5), (-1, 1, 0.5))),
    ("segment", WAVY, ((2, 0, -1), (2.5, 1, 1))),
]

if __name__ == "__main__":
    for kind, ctrl, data in CASES:
        print(f"  // {kind}: {R.ctx.nstr(R.bezier_other(ctrl, kind, *data).distance, 25)}")
        print(f'  "{R.ctx.nstr(R.bezier_other(ctrl, kind, *data).distance, 25)}",')
