"""The references of cpp/tests/test_bezier_bezier.cpp: 50-digit distances between Bezier curves
(circledist_cases/reference_bezier.py: the edges by one-parameter minimisation, the interior by
50-digit Newton descents from a dense grid's local minima; nothing from circledist). Run from the
repository's root:
    python cpp/tests/bezier_bezier_reference.py
and paste its lines into the test's table (the cases are the test's CASES, in order)."""

from circledist_cases import reference_bezier as RB

ARCH = ((-1, 0, 0), (0, 2, 0), (1, 0, 0))
CROSS = ((0, 1, -1), (0.5, 1, -0.3), (-0.5, 1, 0.3), (0, 1, 1))  # B(1/2) = (0, 1, 0), ARCH's apex
NEAR = ((0, 1 + 1e-9, -1), (0.5, 1 + 1e-9, -0.3), (-0.5, 1 + 1e-9, 0.3), (0, 1 + 1e-9, 1))
CUBIC_A = ((0, 0, 0), (1, 2, 0.5), (2, -1, -0.3), (3, 1.5, 0.2))
CUBIC_B = ((0.5, 1, 1.5), (1.5, -1, 1), (2.5, 2, 0.7), (3.5, 0, 1.2))
QUAD_A = ((-1, 0.5, 0), (0.2, 2, -1), (1.3, -0.4, 0.6))
QUAD_B = ((0.8, 1.9, 0.7), (-0.6, 0.1, 1.4), (0.4, -1.2, -0.2))
WAVY = ((0, 0, 0), (1, 2, 0.5), (2, -1, -0.3), (3, 1.5, 0.2), (4, -0.5, 0), (5, 1, 1), (6, 0, -0.5), (7, 1, 0))
BIG = tuple(tuple(1e3 * x for x in p) for p in CUBIC_A)
SMALL = ((1109.5, 698.9, 152.6), (1110.2, 699.4, 153.1), (1110.9, 698.95, 152.9))  # 0.4 from BIG
SHIFT = (1e6, -1e6, 1e6)
CUBIC_A_FAR = tuple(tuple(x + s for x, s in zip(p, SHIFT)) for p in CUBIC_A)
CUBIC_B_FAR = tuple(tuple(x + s for x, s in zip(p, SHIFT)) for p in CUBIC_B)

from circledist_cases.bezier_cases import MISSED_A, MISSED_B, MISSED_C, MISSED_D  # noqa: E402

CASES = [
    ("cubics", CUBIC_A, CUBIC_B),
    ("quadratics", QUAD_A, QUAD_B),
    ("cubic_quadratic", CUBIC_A, QUAD_B),
    ("degree7_line", WAVY, ((1, -1, 0.3), (5, 2, -0.4))),
    ("crossing", ARCH, CROSS),
    ("nearly_touching", ARCH, NEAR),
    ("big_small", BIG, SMALL),
    ("translated", CUBIC_A_FAR, CUBIC_B_FAR),
    ("missed_basin_1", MISSED_A, MISSED_B),
    ("missed_basin_2", MISSED_C, MISSED_D),
]

if __name__ == "__main__":
    for name, a, b in CASES:
        print(f'  "{RB.ctx.nstr(RB.bezier_bezier(a, b).distance, 25)}",  // {name}')
