"""Stability sweeps: one-parameter families that walk toward a degeneracy.

Shared by bench/accuracy_vs_time.py (error against k for every root policy, double, plotted into
docs/reports/stability_sweeps.png) and tests/accuracy/test_stability_sweeps.py (the default policy through the
Python API must stay within 1e-12 x max(distance, largest radius) for every k).

Families (the round shape is the unit circle / disk in its own frame unless said otherwise):
  axis-tilt     a line through (0, 0, 0.5) tilted from the axis by a = 10^-k rad, k = 0..16
  tangent-lift  the tangent line x = 1 (direction +y) lifted to height h = 10^-k, k = 0..16:
                its distance is exactly h (the float h) for the circle and the disk
  offset        fixed scenes translated by 10^k (1, -0.7, 0.4), k = 0..9
  circle-tilt   a circle (or disk) tilted from coplanar by a = 10^-k rad, k = 0..16
  shadow-offset a ray 1e-3 rad from the plane, at height 1 over the centre, its shadow passing
                10^-k beside the centre, k = 0..16, starting between the line's two local minima
                over the ring (it holds the second one, near the ring point (1, 0, 0))
References: the analytic value where there is one (tangent-lift), else the 50-digit independent
reference of accuracy.reference_distance (one-parameter minimisation, no polynomial roots),
always of the exact float inputs.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Optional

from . import accuracy
from .shapes import make_shape

FAMILIES = {
    "axis-tilt": ("line tilted from the axis by 10^-k rad", "k (tilt 10^-k rad)", tuple(range(17))),
    "tangent-lift": ("tangent line lifted by h = 10^-k", "k (height 10^-k)", tuple(range(17))),
    "offset": ("scene translated by 10^k (1, -0.7, 0.4)", "k (offset 10^k)", tuple(range(10))),
    "circle-tilt": ("circle / disk tilted from coplanar by 10^-k rad", "k (tilt 10^-k rad)", tuple(range(17))),
    "shadow-offset": ("ray whose shadow passes 10^-k beside the centre", "k (offset 10^-k)", tuple(range(17))),
}


@dataclass(frozen=True)
class SweepCase:
    family: str
    member: str
    kind: str
    k: int
    values: tuple
    exact: Optional[float] = None  # analytic distance of the float inputs

    @property
    def label(self):
        return f"{self.family}: {self.member}, k={self.k}"


def _tilted_z(a, axis="y"):
    """+z tilted by a rad about the y (or x) axis."""
    s, c = math.sin(a), math.cos(a)
    return (s, 0.0, c) if axis == "y" else (0.0, s, c)


def _member(shape, round_kind, orient):
    """One sweep member on the unit circle or disk: (member, kind, shape, round, orient), the
    member named by its kind ("line-circle"), ", rotated" added for the rotated frame."""
    kind = f"{shape[0]}-{round_kind}"
    rnd = accuracy.UNIT_CIRCLE if round_kind == "circle" else accuracy.UNIT_DISK
    return (kind + (", rotated" if orient == "rot" else ""), kind, shape, rnd, orient)


def _axis_tilt(k):
    a = 10.0**-k
    p = (0.0, 0.0, 0.5)
    d = (math.sin(a), 0.0, math.cos(a))
    p0 = tuple(pi - di for pi, di in zip(p, d))
    p1 = tuple(pi + 2 * di for pi, di in zip(p, d))
    line = ("line", p, d)
    return [
        _member(line, "circle", "z"),
        _member(line, "disk", "z"),
        _member(("segment", p0, p1), "circle", "z"),
        _member(line, "circle", "rot"),
    ]


def _tangent_lift(k):
    h = float(f"1e-{k}")
    return [
        ("line-circle", "line-circle", ("line", (1.0, 0.0, h), (0.0, 1.0, 0.0)), accuracy.UNIT_CIRCLE, "z"),
        ("line-disk", "line-disk", ("line", (1.0, 0.0, h), (0.0, 1.0, 0.0)), accuracy.UNIT_DISK, "z"),
        ("ray-circle", "ray-circle", ("ray", (1.0, -2.0, h), (0.0, 1.0, 0.0)), accuracy.UNIT_CIRCLE, "z"),
        ("segment-disk", "segment-disk", ("segment", (1.0, -1.0, h), (1.0, 1.0, h)), accuracy.UNIT_DISK, "z"),
        ("line-circle, rotated", "line-circle", ("line", (1.0, 0.0, h), (0.0, 1.0, 0.0)), accuracy.UNIT_CIRCLE, "rot"),
    ], h


_GENERIC_ROUND = ((0.0, 0.0, 0.0), (0.2, 0.3, 1.0), 1.0)
OFFSET_SCENES = [
    ("line-circle, generic", "line-circle", ("line", (0.3, 1.2, 0.4), (1.0, 0.2, -0.3)), ("circle",) + _GENERIC_ROUND),
    ("line-disk, tangent lifted 1e-6", "line-disk", ("line", (1.0, 0.0, 1e-6), (0.0, 1.0, 0.0)), accuracy.UNIT_DISK),
    ("circle-circle, linked", "circle-circle", ("circle", (0.6, 0.0, 0.0), (0.0, 1.0, 0.0), 0.6), accuracy.UNIT_CIRCLE),
    (
        "circle-disk, generic",
        "circle-disk",
        ("circle", (0.4, 1.3, 0.9), (0.5, -0.2, 0.7), 0.8),
        ("disk",) + _GENERIC_ROUND,
    ),
]


def _circle_tilt(k):
    a = 10.0**-k
    return [
        (
            "circle-circle, nested",
            "circle-circle",
            ("circle", (0.7, 0.2, 0.0), _tilted_z(a, "x"), 0.5),
            ("circle", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0),
        ),
        (
            "circle-circle, concentric",
            "circle-circle",
            ("circle", (0.0, 0.0, 0.0), _tilted_z(a), 2.0),
            accuracy.UNIT_CIRCLE,
        ),
        (
            "circle-disk, outside",
            "circle-disk",
            ("circle", (2.5, 0.3, 0.0), _tilted_z(a, "x"), 0.5),
            ("disk", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0),
        ),
        (
            "circle-disk, inside",
            "circle-disk",
            ("circle", (0.3, 0.2, 0.0), _tilted_z(a), 0.5),
            ("disk", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0),
        ),
        (
            "disk-disk, outside",
            "disk-disk",
            ("disk", (2.5, 0.3, 0.0), _tilted_z(a, "x"), 0.5),
            ("disk", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0),
        ),
    ]


def _shadow_offset(k):
    a, offset = 1e-3, 10.0**-k
    d = (math.cos(a), 0.0, math.sin(a))
    origin = (0.4, offset, 1.0 + 0.4 * math.tan(a))
    end = tuple(o + 1.5 * di for o, di in zip(origin, d))
    ray = ("ray", origin, d)
    return [
        _member(ray, "circle", "z"),
        _member(ray, "circle", "rot"),
        _member(("segment", origin, end), "circle", "rot"),
        _member(ray, "disk", "rot"),
    ]


def sweep_cases(kinds=None):
    """Every sweep case, in family order; restricted to `kinds` when given."""
    out = []
    for k in FAMILIES["axis-tilt"][2]:
        for member, kind, a, b, orient in _axis_tilt(k):
            out.append(SweepCase("axis-tilt", member, kind, k, accuracy.scene_values(a, b, orient)))
    for k in FAMILIES["tangent-lift"][2]:
        members, h = _tangent_lift(k)
        for member, kind, a, b, orient in members:
            exact = h if orient == "z" else None
            out.append(SweepCase("tangent-lift", member, kind, k, accuracy.scene_values(a, b, orient), exact))
    for k in FAMILIES["offset"][2]:
        for member, kind, a, b in OFFSET_SCENES:
            out.append(SweepCase("offset", member, kind, k, accuracy.scene_values(a, b, "z", 10.0**k)))
    for k in FAMILIES["circle-tilt"][2]:
        for member, kind, a, b in _circle_tilt(k):
            out.append(SweepCase("circle-tilt", member, kind, k, accuracy.scene_values(a, b)))
    for k in FAMILIES["shadow-offset"][2]:
        for member, kind, a, b, orient in _shadow_offset(k):
            out.append(SweepCase("shadow-offset", member, kind, k, accuracy.scene_values(a, b, orient)))
    if kinds is not None:
        out = [c for c in out if c.kind in kinds]
    return out


@functools.lru_cache(maxsize=None)
def _mp_reference(kind, values):
    return accuracy.reference_distance(kind, values)


def reference(case):
    """(50-digit distance, largest radius) of a sweep case's exact float inputs."""
    radius = accuracy.bar_scale(case.kind, case.values)
    if case.exact is not None:
        return accuracy.mpf(case.exact), radius
    return _mp_reference(case.kind, case.values), radius


def relative_error(distance, case):
    ref, radius = reference(case)
    return accuracy.relative_error(repr(float(distance)), ref, radius), ref, radius


# ------------------------------------------------------------------------------------------------
# Python API shapes
# ------------------------------------------------------------------------------------------------
def make_shapes(cd, kind, values):
    """The library shapes of a case's two value layouts."""
    (a, va), (b, vb) = accuracy.split_values(kind, values)
    return make_shape(cd, a, va), make_shape(cd, b, vb)
