"""Accuracy of circledist's round-shape queries against independent 50-digit references.

Kinds: circle-circle (cc), circle-disk (cd), disk-disk (dd), Bezier-disk (bd), Bezier-circle (bc).
References come from circledist_cases/reference_round.py (mpmath, no polynomial roots).  Each kind has seeded
random cases plus the hard configurations (coplanar, concentric, coaxial, linked, touching,
near-coplanar, translated far away, extreme radius ratios, ...), each run in both argument orders.

Accuracy rule (never loosened): |d - d_ref| <= 1e-12 * max(d_ref, largest radius in the query).

The first group of tests validates the references themselves and runs without circledist; the
rest needs `import circledist` and fails (not skips) when the module or a shape kind is missing.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace
from typing import Optional, Tuple

import numpy as np
import pytest

from circledist_cases import reference_round as R

try:
    import circledist as cd

    _IMPORT_ERROR = None
except Exception as exc:  # noqa: BLE001 - reported by every library test
    cd = None
    _IMPORT_ERROR = exc

REL_TOL = 1e-12
AUTO = "auto"  # unique expectation read from the reference (asserted only when clear-cut)
KIND_SHAPES = {
    "cc": ("circle", "circle"),
    "cd": ("circle", "disk"),
    "dd": ("disk", "disk"),
    "bd": ("bezier", "disk"),
    "bc": ("bezier", "circle"),
}


# ------------------------------------------------------------------------------------------------
# cases
# ------------------------------------------------------------------------------------------------
def _t(v) -> Tuple[float, ...]:
    return tuple(float(x) for x in v)


def rnd(kind: str, center, normal, radius) -> tuple:
    return (kind, _t(center), _t(normal), float(radius))


def bez(*ctrl) -> tuple:
    return ("bezier", tuple(_t(p) for p in ctrl))


@dataclass(frozen=True)
class Case:
    kind: str
    name: str
    a: tuple
    b: tuple
    unique: object = AUTO  # True / False: known truth; None: not checked; AUTO: reference
    exact: Optional[float] = None  # analytic distance of the float inputs, when known
    exact_tol: float = 1e-30  # relative; looser only where an input is a rounded irrational
    robust: bool = True  # the unique truth survives ~1 ulp perturbations of the inputs
    #                                (tangencies do not: rounding may split one contact point into
    #                                two nearby crossings, so their variants assert nothing)
    straight: Optional[tuple] = None  # (p0, p1) when the Bezier is a straight segment

    @property
    def id(self) -> str:
        return f"{self.kind}-{self.name}"


SQ2 = math.sqrt(0.5)
EPS_TILT = 1e-9
TILT_X = (math.sin(EPS_TILT), 0.0, math.cos(EPS_TILT))  # z axis tilted by 1e-9 rad
TILT_Y = (0.0, math.sin(EPS_TILT), math.cos(EPS_TILT))
Z = (0.0, 0.0, 1.0)
Y = (0.0, 1.0, 0.0)
O = (0.0, 0.0, 0.0)

_QROT = np.linalg.qr(np.random.default_rng(7).normal(size=(3, 3)))[0]
_QROT = _QROT * np.sign(np.linalg.det(_QROT))  # a proper rotation


def _map_shape(s: tuple, fpoint, fdir) -> tuple:
    if s[0] in ("circle", "disk"):
        return rnd(s[0], fpoint(s[1]), fdir(s[2]), s[3])
    if s[0] == "bezier":
        return ("bezier", tuple(_t(fpoint(p)) for p in s[1]))
    raise ValueError(s[0])


def _variant(c: Case, suffix: str, fpoint, fdir) -> Case:
    return replace(
        c,
        name=f"{c.name}-{suffix}",
        a=_map_shape(c.a, fpoint, fdir),
        b=_map_shape(c.b, fpoint, fdir),
        exact=None,
        unique=c.unique if c.robust else None,
        straight=None,
    )


def rotated(c: Case) -> Case:
    """The same scene under a fixed rotation (float64 rounding of the rotated inputs)."""
    return _variant(c, "rot", lambda p: _QROT @ np.asarray(p), lambda n: _QROT @ np.asarray(n))


def translated(c: Case, s: float) -> Case:
    """The same scene translated by s * (1, -0.6, 0.8); the reference uses the rounded floats."""
    off = s * np.array([1.0, -0.6, 0.8])
    return _variant(c, f"tr{s:.0e}", lambda p: np.asarray(p, dtype=float) + off, lambda n: np.asarray(n))


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def _random_round(rng, kind, center_spread=1.5):
    c = rng.uniform(-center_spread, center_spread, 3)
    n = _unit(rng.normal(size=3)) * (1.0 if rng.random() < 0.5 else rng.uniform(0.1, 10.0))
    return rnd(kind, c, n, rng.uniform(0.2, 2.0))


def random_cases(kind: str, count: int = 30):
    rng = np.random.default_rng({"cc": 101, "cd": 202, "dd": 303, "bd": 404, "bc": 505}[kind])
    ka, kb = KIND_SHAPES[kind]
    out = []
    for i in range(count):
        b = _random_round(rng, kb, 0.5)
        if ka == "bezier":
            k = 1 + i % 5
            a = ("bezier", tuple(_t(p) for p in rng.uniform(-2.0, 2.0, (k + 1, 3))))
        else:
            a = _random_round(rng, ka, 2.0)
        out.append(Case(kind, f"random{i:02d}", a, b))
    return out


def _bern_from_power(a, n):
    a = list(a) + [0.0] * (n + 1 - len(a))
    return [sum(math.comb(i, j) / math.comb(n, j) * a[j] for j in range(i + 1)) for i in range(n + 1)]


# Degree-5 curves with several local minima: z(t) = 0.3 + 0.2 T5(2t - 1) -/+ 0.05 (2t - 1) (T5 the
# Chebyshev polynomial) has three local minima on [0, 1]; (x, y) is a straight path.
WAVY_Z_INTERIOR = (0.15, 2.13, -3.89, 4.49, -1.53, 0.45)  # global minimum inside (0, 1)
WAVY_Z_ENDPOINT = (0.05, 2.07, -3.91, 4.51, -1.47, 0.55)  # global minimum at t = 0


def _wavy(x0, x1, y0, y1, zs):
    xs = _bern_from_power([x0, x1 - x0], 5)
    ys = _bern_from_power([y0, y1 - y0], 5)
    return bez(*[(x, y, z) for x, y, z in zip(xs, ys, zs)])


def hard_cases():
    cc, cdk, dd, bd, bc = [], [], [], [], []
    C = lambda c, n, r: rnd("circle", c, n, r)  # noqa: E731
    D = lambda c, n, r: rnd("disk", c, n, r)  # noqa: E731

    # ---------------- circle-circle ----------------
    cc += [
        Case("cc", "concentric-coplanar", C(O, Z, 1), C(O, Z, 2), False, 1.0),
        Case("cc", "concentric-coplanar-flipped", C(O, Z, 1), C(O, (0, 0, -3), 2), False, 1.0),
        Case("cc", "coplanar-overlap", C(O, Z, 1), C((1, 0, 0), Z, 1), False, 0.0),
        Case("cc", "coplanar-nested", C(O, Z, 2), C((0.7, 0.2, 0), Z, 0.5), True, 2 - (math.sqrt(0.53) + 0.5), 1e-15),
        Case("cc", "coplanar-disjoint", C(O, Z, 1), C((3, 0, 0), Z, 0.5), True, 1.5),
        Case("cc", "coaxial-equal", C(O, Z, 1), C((0, 0, 0.75), Z, 1), False, 0.75),
        Case("cc", "coaxial-unequal", C(O, Z, 1), C((0, 0, 0.5), (0, 0, 2), 1.5), False, math.sqrt(0.5), 1e-15),
        # circle through the other's centre, orthogonal normals: every point of B is at distance 1
        Case("cc", "through-center-orthogonal", C(O, Z, 1), C((1, 0, 0), Y, 1), False, 1.0),
        # linked (B pierces A's disk at x = 0 and passes outside at x = 1.2): d^2 = 0.52 - 0.48 cos
        Case("cc", "linked", C(O, Z, 1), C((0.6, 0, 0), Y, 0.6), True, 0.2, 1e-15),
        # B crosses A at (+-1, 0, 0): distance 0, two tied pairs
        Case("cc", "crossing-twice", C(O, Z, 1), C((0, 0, 0.3), Y, math.sqrt(1.09)), False, 0.0, 1e-15),
        # linked and crossing A once at (1, 0, 0) (the other crossing of A's plane is inside A)
        Case("cc", "linked-crossing-once", C(O, Z, 1), C((0.8, 0, 0.3), Y, math.sqrt(0.13)), True, 0.0, 1e-15),
        Case("cc", "touching-external", C(O, Z, 1), C((2.5, 0, 0), Z, 1.5), True, 0.0, robust=False),
        Case("cc", "touching-internal", C(O, Z, 2), C((1, 0, 0), Z, 1), True, 0.0, robust=False),
        Case("cc", "touching-orthogonal", C(O, Z, 1), C((2, 0, 0), Y, 1), True, 0.0),
        Case("cc", "near-coplanar-concentric", C(O, Z, 1), C(O, TILT_X, 2), False),
        Case("cc", "near-coplanar-overlap", C(O, Z, 1), C((1, 0, 0), TILT_Y, 1), None),
        Case("cc", "near-coplanar-disjoint", C(O, Z, 1), C((3, 0, 0), TILT_Y, 0.5), True),
        Case("cc", "near-coplanar-nested", C(O, Z, 2), C((0.7, 0.2, 0), TILT_X, 0.5), True),
        Case("cc", "ratio-1e-6", C((0.3, 0.4, 0.2), (0.3, -0.5, 0.8), 1e-6), C(O, Z, 1)),
        Case("cc", "ratio-1e-6-near-rim", C((0.6, 0.8, 1e-3), (0.3, -0.5, 0.8), 1e-6), C(O, Z, 1)),
        Case("cc", "ratio-1e6", C(O, Z, 1e6), C((1e6 + 0.5, 0, 0.3), (0.3, 0.5, 0.8), 1)),
        Case("cc", "ratio-1e6-linked", C(O, Z, 1e6), C((1e6 - 0.25, 0.5, 0.1), (0.2, 1.0, 0.1), 1)),
        # same centre, orthogonal tilted normals: closest pairs (0,0,+-1)-(0,0,+-2), distance 1
        Case("cc", "same-center-orthogonal", C(O, (SQ2, SQ2, 0), 1), C(O, (SQ2, -SQ2, 0), 2), False, 1.0),
        Case("cc", "same-center-orthogonal-unnormalized", C(O, (1, 1, 0), 1), C(O, (3, -3, 0), 2), False, 1.0),
        Case("cc", "same-center-tilted", C(O, (0.3, 0.1, 1), 1), C(O, (1, -0.2, 0.4), 1.7), False),
    ]
    # ---------------- circle-disk (a = circle, b = disk) ----------------
    cdk += [
        Case("cd", "in-plane-inside", C((0.2, 0.1, 0), Z, 0.5), D(O, Z, 2), False, 0.0),
        Case("cd", "concentric-coplanar-outside", C(O, Z, 3), D(O, Z, 2), False, 1.0),
        Case("cd", "coplanar-crossing-rim", C((1.5, 0, 0), Z, 1), D(O, Z, 1), False, 0.0),
        Case("cd", "coplanar-disjoint", C((4, 0, 0), Z, 1), D(O, (0, 0, -1), 2), True, 1.0),
        Case("cd", "coaxial-smaller", C((0, 0, 0.7), Z, 1), D(O, Z, 2), False, 0.7),
        Case("cd", "coaxial-larger", C((0, 0, 0.5), Z, 3), D(O, Z, 2), False, math.sqrt(1.25), 1e-15),
        Case("cd", "through-center-orthogonal", C((1, 0, 0), Y, 1), D(O, Z, 1), True, 0.0),
        Case("cd", "crossing-twice", C((0, 0, 0.2), Y, 0.5), D(O, Z, 1), False, 0.0),
        Case("cd", "linked-with-rim", C((1, 0, 0), Y, 0.5), D(O, Z, 1), True, 0.0),
        Case("cd", "touching-face", C((0.3, 0, 0.5), Y, 0.5), D(O, Z, 1), True, 0.0, robust=False),
        Case("cd", "touching-rim-in-plane", C((3, 0, 0), Z, 2), D(O, Z, 1), True, 0.0, robust=False),
        Case("cd", "touching-rim-orthogonal", C((2, 0, 0), Y, 1), D(O, Z, 1), True, 0.0),
        Case("cd", "near-coplanar-inside", C((0.2, 0.1, 0), TILT_X, 0.5), D(O, Z, 2), False),
        Case("cd", "near-coplanar-concentric", C(O, TILT_Y, 3), D(O, Z, 2), False),
        Case("cd", "near-coplanar-disjoint", C((4, 0, 0), TILT_Y, 1), D(O, Z, 2), True),
        Case("cd", "above-face", C((0.1, 0.2, 0.8), (0.2, 0.3, 1.0), 0.4), D(O, Z, 1.5), True),
        Case("cd", "ratio-circle-1e-6", C((0.3, 0.2, 0.4), (0.3, -0.5, 0.8), 1e-6), D(O, Z, 1)),
        Case("cd", "ratio-circle-1e6", C(O, Z, 1e6), D((1e6 + 0.5, 0, 0.3), (0.2, 0.1, 1), 1)),
        Case("cd", "ratio-disk-1e6", C((1e6 - 0.3, 0.2, 0.6), (0.3, 0.1, 1), 1), D(O, Z, 1e6)),
        Case("cd", "ratio-disk-1e-6-concentric", C(O, Z, 1), D(O, Z, 1e-6), False, 1 - 1e-6, 1e-15),
        Case("cd", "ratio-disk-1e-6", C((0.2, 0.9, 0.4), (1, 0.3, 0.2), 1), D(O, Z, 1e-6)),
        Case("cd", "same-center-orthogonal", C(O, (SQ2, SQ2, 0), 1), D(O, (SQ2, -SQ2, 0), 2), False, 0.0),
        Case("cd", "same-center-orthogonal-big-circle", C(O, (SQ2, SQ2, 0), 2), D(O, (SQ2, -SQ2, 0), 1), False),
    ]
    # ---------------- disk-disk ----------------
    dd += [
        Case("dd", "coplanar-overlap", D(O, Z, 1), D((1.5, 0, 0), Z, 1), False, 0.0),
        Case("dd", "coplanar-nested", D(O, Z, 2), D((0.5, 0.2, 0), (0, 0, -1), 0.5), False, 0.0),
        Case("dd", "coplanar-concentric", D(O, Z, 1), D(O, Z, 2), False, 0.0),
        Case("dd", "coplanar-disjoint", D(O, Z, 1), D((3, 0, 0), Z, 1.5), True, 0.5),
        Case("dd", "coaxial-parallel", D(O, Z, 1), D((0, 0, 0.6), Z, 2), False, 0.6),
        Case("dd", "parallel-offset-overlapping", D(O, Z, 1), D((1.2, 0.3, 0.8), (0, 0, -2), 1), False, 0.8),
        Case("dd", "parallel-disjoint", D(O, Z, 1), D((3, 0, 0.5), Z, 1), True, math.sqrt(1.25), 1e-15),
        Case("dd", "linked", D(O, Z, 1), D((0.5, 0, 0), Y, 1), False, 0.0),
        Case("dd", "through-center-orthogonal", D(O, Z, 1), D((1, 0, 0), Y, 1), False, 0.0),
        Case("dd", "touching-rims", D(O, Z, 1), D((2, 0, 0), Y, 1), True, 0.0, robust=False),
        Case("dd", "standing-on-face", D(O, Z, 1), D((0.2, 0, 1), Y, 1), True, 0.0, robust=False),
        Case("dd", "edge-over-face", D(O, Z, 1.5), D((0.1, 0.2, 1.5), (0, 0.6, 0.8), 0.8), True),
        Case("dd", "edge-over-edge", D(O, Z, 1), D((1.5, 0.3, 0.9), (0.7, 0.2, 0.5), 0.7), True),
        Case("dd", "near-coplanar-disjoint", D(O, Z, 1), D((3, 0, 0), TILT_Y, 1.5), True),
        Case("dd", "near-coplanar-overlap", D(O, Z, 1), D((1.5, 0, 0), TILT_Y, 1), False, 0.0),
        Case("dd", "near-parallel-offset", D(O, Z, 1), D((2.5, 0, 0.3), TILT_X, 1), None),
        Case("dd", "same-center-orthogonal", D(O, (SQ2, SQ2, 0), 1), D(O, (SQ2, -SQ2, 0), 2), False, 0.0),
        Case("dd", "ratio-1e-6", D((0.3, 0.2, 0.4), (0.3, -0.5, 0.8), 1e-6), D(O, Z, 1)),
        Case("dd", "ratio-1e-6-beyond-rim", D((1.3, 0.2, 0.4), (0.3, -0.5, 0.8), 1e-6), D(O, Z, 1)),
        Case("dd", "ratio-1e6", D(O, Z, 1e6), D((1e6 + 0.5, 0, 0.3), (0.3, 0.5, 0.8), 0.2)),
    ]
    # ---------------- Bezier-disk (a = Bezier, b = disk) ----------------
    P0, P1 = (-2.0, 0.25, 1.0), (1.0, -0.5, 0.25)
    bd += [
        Case("bd", "straight-deg1", bez(P0, P1), D(O, (0.1, 0.2, 1), 1), AUTO, straight=(P0, P1)),
        Case(
            "bd",
            "straight-deg3",
            bez(P0, (-1, 0, 0.75), (0, -0.25, 0.5), P1),
            D(O, (0.1, 0.2, 1), 1),
            AUTO,
            straight=(P0, P1),
        ),
        Case(
            "bd",
            "straight-piercing",
            bez((0.3, 0.2, -1), (0.1, 0.3, 1)),
            D(O, Z, 1),
            True,
            0.0,
            straight=((0.3, 0.2, -1), (0.1, 0.3, 1)),
        ),
        Case(
            "bd",
            "straight-in-plane-crossing",
            bez((-2, 0.5, 0), (2, 0.25, 0)),
            D(O, Z, 1),
            False,
            0.0,
            straight=((-2, 0.5, 0), (2, 0.25, 0)),
        ),
        Case(
            "bd",
            "straight-over-rim-tangent",
            bez((-2, 1, 0.5), (2, 1, 0.5)),
            D(O, Z, 1),
            None,
            0.5,
            straight=((-2, 1, 0.5), (2, 1, 0.5)),
        ),  # unique but quartic-flat: not asserted
        Case(
            "bd",
            "straight-crossing-rim",
            bez((1, 0, -1), (1, 0, 1)),
            D(O, Z, 1),
            True,
            0.0,
            straight=((1, 0, -1), (1, 0, 1)),
        ),
        Case(
            "bd",
            "tangent-to-rim-in-plane",
            bez((-1, 1.25, 0), (0, 0.75, 0), (1, 1.25, 0)),
            D(O, Z, 1),
            True,
            0.0,
            robust=False,
        ),
        Case("bd", "tangent-to-rim-above", bez((-1, 1.25, 0.3), (0, 0.75, 0.3), (1, 1.25, 0.3)), D(O, Z, 1), None, 0.3),
        Case(
            "bd",
            "in-plane-inside",
            bez((-0.5, 0, 0), (0, 0.8, 0), (0.5, -0.2, 0), (0.3, 0.3, 0)),
            D(O, Z, 1),
            False,
            0.0,
        ),
        Case("bd", "in-plane-outside", bez((1.5, -1, 0), (0.9, 0.2, 0), (1.6, 1.4, 0)), D(O, Z, 1), True),
        Case("bd", "crossing-rim-above", bez((0, 0, 0.5), (0.8, 0, 0.2), (1.3, 0.1, 0.3), (2, 0, 0.1)), D(O, Z, 1)),
        Case("bd", "crossing-plane-twice", bez((-0.8, 0, 0.5), (0, 0.2, -0.8), (0.7, 0.1, 0.6)), D(O, Z, 1), False),
        Case("bd", "wavy-deg5-interior-min", _wavy(-0.6, 0.6, 0.1, 0.3, WAVY_Z_INTERIOR), D(O, Z, 1), True),
        Case("bd", "wavy-deg5-endpoint-min", _wavy(-0.6, 0.6, 0.1, 0.3, WAVY_Z_ENDPOINT), D(O, Z, 1), True),
        Case("bd", "wavy-deg5-across-rim", _wavy(0.7, 1.3, -0.3, 0.2, WAVY_Z_INTERIOR), D(O, Z, 1)),
        Case("bd", "endpoint-min", bez((0.2, 0.1, 0.4), (0.5, 0.5, 1.0), (1.5, -0.5, 2)), D(O, Z, 1), True),
        Case(
            "bd",
            "deg4-tilted-disk",
            bez((-1, -1, 1), (0, 2, -1), (1, 0, 2), (2, 1, -1), (0, 1, 1)),
            D((0.2, 0.1, 0.3), (1, 1, 1), 1.2),
        ),
        Case("bd", "ratio-disk-1e-6", bez((-1, 0.1, 0.3), (0, -0.2, 0.2), (1, 0.3, 0.4)), D(O, Z, 1e-6)),
        Case("bd", "ratio-disk-1e6", bez((-1, 0.1, 0.3), (0, -0.2, 0.2), (1, 0.3, 0.4)), D(O, Z, 1e6), None),
        Case(
            "bd",
            "ratio-disk-1e6-near-rim",
            bez((1e6 - 1, 0.1, 0.3), (1e6 + 1, -0.2, -0.2), (1e6 + 2, 0.3, 0.4)),
            D(O, Z, 1e6),
        ),
    ]
    # ---------------- Bezier-circle (a = Bezier, b = circle) ----------------
    Q0, Q1 = (-1.5, 0.5, 0.75), (1.5, -0.5, -0.25)
    bc += [
        Case(
            "bc",
            "straight-along-axis",
            bez((0, 0, -1), (0, 0, 1)),
            C(O, Z, 1),
            False,
            1.0,
            straight=((0, 0, -1), (0, 0, 1)),
        ),
        Case(
            "bc",
            "straight-in-plane-crossing",
            bez((-2, 0, 0), (2, 0, 0)),
            C(O, Z, 1),
            False,
            0.0,
            straight=((-2, 0, 0), (2, 0, 0)),
        ),
        Case(
            "bc",
            "straight-piercing",
            bez((1, 0, -1), (1, 0, 1)),
            C(O, Z, 1),
            True,
            0.0,
            straight=((1, 0, -1), (1, 0, 1)),
        ),
        Case("bc", "straight-deg1", bez(Q0, Q1), C((0.1, 0.2, 0), (0.2, 0.1, 1), 1.1), AUTO, straight=(Q0, Q1)),
        # collinear control points, non-uniform speed: B(t) = Q0 + (Q1 - Q0)(t + t^2)/2
        Case(
            "bc",
            "straight-deg2-nonuniform",
            bez(Q0, (-0.75, 0.25, 0.5), Q1),
            C((0.1, 0.2, 0), (0.2, 0.1, 1), 1.1),
            AUTO,
            straight=(Q0, Q1),
        ),
        Case(
            "bc",
            "tangent-in-plane",
            bez((-1, 1.25, 0), (0, 0.75, 0), (1, 1.25, 0)),
            C(O, Z, 1),
            True,
            0.0,
            robust=False,
        ),
        Case("bc", "inside-in-plane", bez((-0.3, 0, 0), (0, 0.5, 0), (0.4, 0.1, 0)), C(O, Z, 1), True),
        Case("bc", "through-center-orthogonal", bez((0, 0, 0), (1, 0, 1), (2, 0, 0)), C(O, Z, 1)),
        Case("bc", "wavy-deg5-interior-min", _wavy(-0.6, 0.6, 0.1, 0.3, WAVY_Z_INTERIOR), C(O, Z, 1)),
        Case("bc", "wavy-deg5-across-rim", _wavy(0.7, 1.3, -0.3, 0.2, WAVY_Z_INTERIOR), C(O, Z, 1), True),
        Case(
            "bc",
            "deg4-tilted",
            bez((-1, -1, 1), (0, 2, -1), (1, 0, 2), (2, 1, -1), (0, 1, 1)),
            C((0.2, 0.1, 0.3), (1, 1, 1), 1.2),
        ),
        Case("bc", "ratio-circle-1e-6", bez((-1, 0.1, 0.3), (0, -0.2, 0.2), (1, 0.3, 0.4)), C(O, Z, 1e-6)),
        Case("bc", "ratio-circle-1e6", bez((1e6 - 1, -1, 0.5), (1e6 + 1, 0, -0.2), (1e6 - 0.5, 1, 0.4)), C(O, Z, 1e6)),
    ]

    def by_name(lst, name):
        return next(c for c in lst if c.name == name)

    variants = []
    for lst, names in (
        (
            cc,
            [
                "concentric-coplanar",
                "coplanar-nested",
                "coplanar-disjoint",
                "coaxial-equal",
                "through-center-orthogonal",
                "linked",
                "touching-external",
                "same-center-orthogonal",
            ],
        ),
        (
            cdk,
            [
                "in-plane-inside",
                "coaxial-smaller",
                "coplanar-disjoint",
                "linked-with-rim",
                "touching-face",
                "above-face",
            ],
        ),
        (dd, ["coplanar-overlap", "coaxial-parallel", "parallel-disjoint", "edge-over-face", "linked"]),
        (bd, ["straight-deg1", "wavy-deg5-interior-min", "in-plane-inside"]),
        (bc, ["straight-along-axis", "wavy-deg5-interior-min"]),
    ):
        variants += [rotated(by_name(lst, n)) for n in names]
    for lst, names in (
        (cc, ["concentric-coplanar", "coaxial-equal", "linked", "coplanar-disjoint", "same-center-tilted"]),
        (cdk, ["in-plane-inside", "coaxial-smaller", "linked-with-rim", "above-face"]),
        (dd, ["coaxial-parallel", "edge-over-face", "coplanar-disjoint", "linked"]),
        (bd, ["straight-deg1", "wavy-deg5-interior-min"]),
        (bc, ["wavy-deg5-interior-min", "straight-piercing"]),
    ):
        for n in names:
            variants += [translated(by_name(lst, n), 1e6), translated(by_name(lst, n), 1e8)]
    return cc + cdk + dd + bd + bc + variants


HARD = hard_cases()
RANDOM = [c for k in ("cc", "cd", "dd", "bd", "bc") for c in random_cases(k)]
ALL = HARD + RANDOM
_ids = [c.id for c in ALL]
assert len(set(_ids)) == len(_ids), "duplicate case ids"


# ------------------------------------------------------------------------------------------------
# references (cached) and helpers
# ------------------------------------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def reference(kind: str, a: tuple, b: tuple) -> R.Reference:
    if kind == "cc":
        return R.circle_circle(*a[1:], *b[1:])
    if kind == "cd":
        return R.circle_disk(*a[1:], *b[1:])
    if kind == "dd":
        return R.disk_disk(*a[1:], *b[1:])
    if kind == "bd":
        return R.bezier_disk(a[1], *b[1:])
    if kind == "bc":
        return R.bezier_circle(a[1], *b[1:])
    raise ValueError(kind)


def ref_of(c: Case) -> R.Reference:
    return reference(c.kind, c.a, c.b)


def radius_scale(*shapes) -> float:
    """Largest radius in the query (Bezier curves and segments have none)."""
    return max([s[3] for s in shapes if s[0] in ("circle", "disk")] + [0.0])


def expected_unique(c: Case) -> Optional[bool]:
    if c.unique == AUTO:
        return R.expected_unique(ref_of(c))
    return c.unique


def input_magnitude(*shapes) -> float:
    vals = [0.0]
    for s in shapes:
        if s[0] in ("circle", "disk"):
            vals += [abs(x) for x in s[1]]
        elif s[0] == "bezier":
            vals += [abs(x) for p in s[1] for x in p]
        elif s[0] == "segment":
            vals += [abs(x) for x in s[1] + s[2]]
    return max(vals)


def on_shape_distance(s: tuple, p, param) -> float:
    """Exact (50-digit) distance from the float point p to the shape s."""
    if s[0] == "circle":
        return float(R.point_circle(p, R.make_round(*s[1:]))[0])
    if s[0] == "disk":
        return float(R.point_disk(p, R.make_round(*s[1:]))[0])
    if s[0] == "bezier":
        t = float(np.asarray(param, dtype=float).ravel()[0])
        assert 0.0 <= t <= 1.0, f"Bezier parameter {t} outside [0, 1]"
        return float(R.dist(R.vec(p), R.bezier_point(s[1], t)))
    raise ValueError(s[0])


def require(*names):
    if cd is None:
        pytest.fail(f"circledist is not importable: {_IMPORT_ERROR!r}")
    missing = [n for n in names if not hasattr(cd, n)]
    if missing:
        pytest.fail(f"circledist.{', circledist.'.join(missing)} not bound yet")


_CLASS = {"circle": "Circle", "disk": "Disk", "bezier": "Bezier", "segment": "Segment"}


def make(s: tuple):
    require(_CLASS[s[0]])
    if s[0] == "circle":
        return cd.Circle(np.array(s[1]), np.array(s[2]), s[3])
    if s[0] == "disk":
        return cd.Disk(np.array(s[1]), np.array(s[2]), s[3])
    if s[0] == "bezier":
        return cd.Bezier(np.array(s[1], dtype=float))
    if s[0] == "segment":
        return cd.Segment(np.array(s[1], dtype=float), np.array(s[2], dtype=float))
    raise ValueError(s[0])


def ordered(c: Case, order: str):
    return (c.a, c.b) if order == "ab" else (c.b, c.a)


# ------------------------------------------------------------------------------------------------
# 1. validation of the references (no circledist needed)
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("case", [c for c in HARD if c.exact is not None], ids=lambda c: c.id)
def test_reference_matches_analytic(case):
    ref = ref_of(case)
    scale = max(abs(case.exact), radius_scale(case.a, case.b), 1.0)
    assert (
        abs(float(ref.distance - R.mpf(case.exact))) <= case.exact_tol * scale
    ), f"reference {R.ctx.nstr(ref.distance, 25)} vs analytic {case.exact!r}"


def test_reference_basic_analytic():
    """The listed analytic sanity cases, computed directly."""
    assert abs(R.circle_circle(O, Z, 1, O, Z, 2).distance - 1) <= R.mpf("1e-45")
    for h in (0.5, 1.25, 3.0):
        assert abs(R.circle_circle(O, Z, 1.5, (0, 0, h), Z, 1.5).distance - h) <= R.mpf("1e-40")
    assert R.circle_disk((0.1, -0.2, 0), Z, 0.6, O, Z, 1).distance == 0
    # point-disk and point-circle closed forms at a few hand-checked points
    d0 = R.make_round(O, Z, 1)
    assert R.point_disk((0.5, 0, 2), d0)[0] == 2
    assert abs(R.point_disk((4, 0, 4), d0)[0] - 5) <= R.mpf("1e-45")
    assert abs(R.point_circle((0, 0, 1), d0)[0] - R.ctx.sqrt(2)) <= R.mpf("1e-45")
    assert R.point_circle((0, 0, 1), d0)[2]  # on the axis: degenerate
    # frames are right-handed and orthonormal
    for n in [(0, 0, 1), (1, 1, 0), (0.3, -2, 7), (-1e-9, 1, 0)]:
        u, v, w = R.frame(n)
        for x, y, e in ((u, u, 1), (v, v, 1), (w, w, 1), (u, v, 0), (u, w, 0), (v, w, 0)):
            assert abs(R.dot(x, y) - e) <= R.mpf("1e-45")
        assert R.dist(R.cross(u, v), w) <= R.mpf("1e-45")


@pytest.mark.parametrize("case", [c for c in HARD if c.straight is not None], ids=lambda c: c.id)
def test_reference_straight_bezier_matches_segment(case):
    """A straight Bezier's reference equals the segment distance computed another way
    (parametrising the circle / disk rim instead of the curve)."""
    p0, p1 = case.straight
    alt = (R.segment_disk_alt if case.kind == "bd" else R.segment_circle_alt)(p0, p1, *case.b[1:])
    ref = ref_of(case)
    assert abs(ref.distance - alt) <= R.mpf("1e-30") * max(1, case.b[3])


def test_reference_circle_formulations_agree():
    """Circle-circle over A's angle and over B's angle are independent; they must agree."""
    for c in [c for c in RANDOM if c.kind == "cc"][:6] + [c for c in HARD if c.name in ("linked", "ratio-1e-6")]:
        fa = R.circle_circle(*c.a[1:], *c.b[1:], formulations="a").distance
        fb = R.circle_circle(*c.a[1:], *c.b[1:], formulations="b").distance
        assert abs(fa - fb) <= R.mpf("1e-30") * max(1, c.a[3], c.b[3]), c.id


@pytest.mark.slow
def test_reference_disk_intersection_consistent():
    """The chord-overlap intersection test agrees with the rim formula (which is valid for meeting
    disks too: an end point of the common chord lies on one rim and in the other disk)."""
    for c in [c for c in ALL if c.kind == "dd"]:
        ref = ref_of(c)
        if not ref.intersect or max(c.a[3], c.b[3]) > 10:
            continue
        rims = R.disk_disk_rims(*c.a[1:], *c.b[1:])[0].value
        assert rims <= R.mpf("1e-30"), (c.id, rims)
    # and a non-meeting case is positive under both
    r = R.disk_disk(O, Z, 1, (0, 0, 0.5), (0, 1, 0.1), 0.4)
    assert r.intersect is False and r.distance > 0


def test_reference_pairs_are_consistent():
    """Every reported closest pair lies on the shapes and realises the distance."""
    for c in [c for c in RANDOM if c.name in ("random00", "random01", "random07")]:
        ref = ref_of(c)
        if not ref.pairs:
            continue
        p = ref.pairs[0]
        assert abs(R.dist(p.pa, p.pb) - ref.distance) <= R.mpf("1e-35"), c.id


def test_reference_degree5_has_many_minima():
    """The degree-5 'wavy' cases do exercise several separated local minima."""
    names = {"bd-wavy-deg5-interior-min", "bd-wavy-deg5-endpoint-min", "bc-wavy-deg5-across-rim"}
    for c in [c for c in HARD if c.id in names]:
        values = {round(float(m.value), 6) for m in ref_of(c).pairs}
        assert len(values) >= 3, (c.id, values)


@pytest.mark.slow
@pytest.mark.parametrize("case", [c for c in HARD if c.unique in (True, False)], ids=lambda c: c.id)
def test_reference_agrees_with_stated_unique(case):
    """Stated unique flags never contradict what the reference can see (it may be undecided)."""
    seen = R.expected_unique(ref_of(case))
    assert seen is None or seen == case.unique, (seen, case.unique)


def test_reference_inclusions():
    """disk-disk <= circle-disk <= circle-circle for the same geometry (the disk contains its rim)."""
    for c in [c for c in RANDOM if c.kind == "cd"][:4]:
        cdist = ref_of(c).distance
        ccd = reference("cc", c.a, ("circle",) + c.b[1:]).distance
        ddd = reference("dd", ("disk",) + c.a[1:], c.b).distance
        assert ddd <= cdist + R.mpf("1e-40") and cdist <= ccd + R.mpf("1e-40"), c.id


# ------------------------------------------------------------------------------------------------
# 2. the library against the references
# ------------------------------------------------------------------------------------------------
ORDERS = ["ab", "ba"]


@pytest.mark.slow
@pytest.mark.parametrize("order", ORDERS)
@pytest.mark.parametrize("case", ALL, ids=lambda c: c.id)
def test_distance(case, order):
    sa, sb = ordered(case, order)
    A, B = make(sa), make(sb)
    d = float(cd.distance(A, B))
    dref = float(ref_of(case).distance)
    tol = REL_TOL * max(dref, radius_scale(sa, sb))
    assert abs(d - dref) <= tol, f"distance {d!r} vs reference {dref!r}: error {abs(d - dref):.3e} > {tol:.3e}"


@pytest.mark.slow
@pytest.mark.parametrize("order", ORDERS)
@pytest.mark.parametrize("case", ALL, ids=lambda c: c.id)
def test_closest_points(case, order):
    sa, sb = ordered(case, order)
    A, B = make(sa), make(sb)
    r = cd.closest_points(A, B)
    d = float(r.distance)
    dref = float(ref_of(case).distance)
    tol = REL_TOL * max(dref, radius_scale(sa, sb))
    assert abs(d - dref) <= tol, f"distance {d!r} vs reference {dref!r}: error {abs(d - dref):.3e} > {tol:.3e}"
    pa = np.asarray(r.point_a, dtype=float)
    pb = np.asarray(r.point_b, dtype=float)
    assert pa.shape == (3,) and pb.shape == (3,)
    # Points are float64 vectors: far from the origin (scenes translated by 1e6 or 1e8) the nearest
    # representable point to an exact closest point is up to half an ulp of the coordinate
    # magnitude away per coordinate (sqrt(3)/2 ulp in length), and the library's own rounding adds
    # a few more ulps.  So the point checks allow 1e-12 * scale plus 8 ulps of the largest
    # coordinate; the distance itself (a difference) is held to the plain 1e-12 rule above.
    mag = max(input_magnitude(sa, sb), float(np.max(np.abs(pa))), float(np.max(np.abs(pb))))
    tol_pt = tol + 8 * float(np.spacing(mag))
    for s, p, prm, label in ((sa, pa, r.param_a, "point_a"), (sb, pb, r.param_b, "point_b")):
        off = on_shape_distance(s, p, prm)
        assert off <= tol_pt, f"{label} {p.tolist()} is {off:.3e} off its shape (> {tol_pt:.3e})"
    sep = float(R.dist(R.vec(pa), R.vec(pb)))
    assert abs(sep - d) <= tol_pt, f"|point_a - point_b| = {sep!r} but distance = {d!r}"
    want = expected_unique(case)
    if want is not None:
        assert bool(r.unique) == want, f"unique = {r.unique}, expected {want}"


@pytest.mark.slow
@pytest.mark.parametrize("case", ALL, ids=lambda c: c.id)
def test_symmetric(case):
    A, B = make(case.a), make(case.b)
    dab, dba = float(cd.distance(A, B)), float(cd.distance(B, A))
    assert dab == dba, f"distance(a, b) = {dab!r} != distance(b, a) = {dba!r}"


@pytest.mark.parametrize("case", [c for c in HARD if c.straight is not None], ids=lambda c: c.id)
def test_straight_bezier_matches_segment(case):
    require("Segment", "Bezier")
    p0, p1 = case.straight
    seg = ("segment", _t(p0), _t(p1))
    B = make(case.b)
    dref = float(ref_of(case).distance)
    tol = REL_TOL * max(dref, radius_scale(case.b))
    for order in ORDERS:
        x, y = (make(seg), B) if order == "ab" else (B, make(seg))
        ds = float(cd.distance(x, y))
        assert abs(ds - dref) <= tol, f"segment ({order}): {ds!r} vs reference {dref!r}"
    db = float(cd.distance(make(case.a), B))
    assert abs(db - ds) <= tol, f"Bezier {db!r} vs Segment {ds!r}"


def _batch_cases(n=16):
    return [c for c in RANDOM if c.kind == "cd"][:n]


def _stack(cases, which):
    shapes = [getattr(c, which) for c in cases]
    return (np.array([s[1] for s in shapes]), np.array([s[2] for s in shapes]), np.array([s[3] for s in shapes]))


@pytest.mark.parametrize("order", ORDERS)
def test_batch_circle_disk_equals_scalar(order):
    require("Circle", "Disk")
    cases = _batch_cases()
    circles = cd.Circle(*_stack(cases, "a"))
    disks = cd.Disk(*_stack(cases, "b"))
    x, y = (circles, disks) if order == "ab" else (disks, circles)
    d = np.asarray(cd.distance(x, y))
    assert d.shape == (len(cases),)
    scalar = []
    for c in cases:
        sa, sb = ordered(c, order)
        scalar.append(float(cd.distance(make(sa), make(sb))))
    np.testing.assert_array_equal(d, np.array(scalar))
    for c, di in zip(cases, d):
        dref = float(ref_of(c).distance)
        assert abs(di - dref) <= REL_TOL * max(dref, radius_scale(c.a, c.b)), c.id
    r = cd.closest_points(x, y)
    # The distance alone takes a shorter path (docs/derivations/circle_disk.md, "The distance alone"): the
    # same value up to rounding, not to the bit.
    for c, di, ri in zip(cases, d, np.asarray(r.distance)):
        assert abs(ri - di) <= 1e-13 * max(di, radius_scale(c.a, c.b)), c.id
    assert np.asarray(r.point_a).shape == (len(cases), 3)
    for i, c in enumerate(cases):
        sa, sb = ordered(c, order)
        ri = cd.closest_points(make(sa), make(sb))
        np.testing.assert_array_equal(np.asarray(r.point_a)[i], np.asarray(ri.point_a))
        np.testing.assert_array_equal(np.asarray(r.point_b)[i], np.asarray(ri.point_b))
        assert bool(np.asarray(r.unique)[i]) == bool(ri.unique)


def test_batch_broadcast_one_disk_many_circles():
    require("Circle", "Disk")
    cases = _batch_cases(8)
    circles = cd.Circle(*_stack(cases, "a"))
    disk_spec = cases[0].b
    d = np.asarray(cd.distance(circles, make(disk_spec)))
    assert d.shape == (len(cases),)
    for i, c in enumerate(cases):
        assert d[i] == float(cd.distance(make(c.a), make(disk_spec)))
