"""Stability sweeps: one-parameter families that walk toward a degeneracy.

Shared by bench/accuracy_vs_time.py (error against k for every root policy, double, plotted into
docs/stability_sweeps.png) and tests/test_stability_sweeps.py (the default policy through the
Python API must stay within 1e-12 x max(distance, largest radius) for every k).

Families (the round shape is the unit circle / disk in its own frame unless said otherwise):
  axis-tilt     a line through (0, 0, 0.5) tilted from the axis by a = 10^-k rad, k = 0..16
  tangent-lift  the tangent line x = 1 (direction +y) lifted to height h = 10^-k, k = 0..16:
                its distance is exactly h (the float h) for the circle and the disk
  offset        fixed scenes translated by 10^k (1, -0.7, 0.4), k = 0..9
  circle-tilt   a circle (or disk) tilted from coplanar by a = 10^-k rad, k = 0..16
References: the analytic value where there is one (tangent-lift), else the 50-digit independent
reference of accuracy_vs_time.reference_distance (one-parameter minimisation, no polynomial roots),
always of the exact float inputs.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Optional

import numpy as np

import accuracy_vs_time as avt

FAMILIES = {
    "axis-tilt": ("line tilted from the axis by 10^-k rad", "k (tilt 10^-k rad)", tuple(range(17))),
    "tangent-lift": ("tangent line lifted by h = 10^-k", "k (height 10^-k)", tuple(range(17))),
    "offset": ("scene translated by 10^k (1, -0.7, 0.4)", "k (offset 10^k)", tuple(range(10))),
    "circle-tilt": ("circle / disk tilted from coplanar by 10^-k rad", "k (tilt 10^-k rad)", tuple(range(17))),
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


def _axis_tilt(k):
    a = 10.0 ** -k
    p = (0.0, 0.0, 0.5)
    d = (math.sin(a), 0.0, math.cos(a))
    p0 = tuple(pi - di for pi, di in zip(p, d))
    p1 = tuple(pi + 2 * di for pi, di in zip(p, d))
    return [
        ("line-circle", "line-circle", ("line", p, d), avt.UNIT_CIRCLE, "z"),
        ("line-disk", "line-disk", ("line", p, d), avt.UNIT_DISK, "z"),
        ("segment-circle", "segment-circle", ("segment", p0, p1), avt.UNIT_CIRCLE, "z"),
        ("line-circle, rotated", "line-circle", ("line", p, d), avt.UNIT_CIRCLE, "rot"),
    ]


def _tangent_lift(k):
    h = float(f"1e-{k}")
    return [
        ("line-circle", "line-circle", ("line", (1.0, 0.0, h), (0.0, 1.0, 0.0)), avt.UNIT_CIRCLE, "z"),
        ("line-disk", "line-disk", ("line", (1.0, 0.0, h), (0.0, 1.0, 0.0)), avt.UNIT_DISK, "z"),
        ("ray-circle", "ray-circle", ("ray", (1.0, -2.0, h), (0.0, 1.0, 0.0)), avt.UNIT_CIRCLE, "z"),
        ("segment-disk", "segment-disk", ("segment", (1.0, -1.0, h), (1.0, 1.0, h)), avt.UNIT_DISK, "z"),
        ("line-circle, rotated", "line-circle", ("line", (1.0, 0.0, h), (0.0, 1.0, 0.0)), avt.UNIT_CIRCLE, "rot"),
    ], h


_GENERIC_ROUND = ((0.0, 0.0, 0.0), (0.2, 0.3, 1.0), 1.0)
OFFSET_SCENES = [
    ("line-circle, generic", "line-circle", ("line", (0.3, 1.2, 0.4), (1.0, 0.2, -0.3)),
     ("circle",) + _GENERIC_ROUND),
    ("line-disk, tangent lifted 1e-6", "line-disk", ("line", (1.0, 0.0, 1e-6), (0.0, 1.0, 0.0)), avt.UNIT_DISK),
    ("circle-circle, linked", "circle-circle", ("circle", (0.6, 0.0, 0.0), (0.0, 1.0, 0.0), 0.6), avt.UNIT_CIRCLE),
    ("circle-disk, generic", "circle-disk", ("circle", (0.4, 1.3, 0.9), (0.5, -0.2, 0.7), 0.8),
     ("disk",) + _GENERIC_ROUND),
]


def _circle_tilt(k):
    a = 10.0 ** -k
    return [
        ("circle-circle, nested", "circle-circle", ("circle", (0.7, 0.2, 0.0), _tilted_z(a, "x"), 0.5),
         ("circle", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0)),
        ("circle-circle, concentric", "circle-circle", ("circle", (0.0, 0.0, 0.0), _tilted_z(a), 2.0),
         avt.UNIT_CIRCLE),
        ("circle-disk, outside", "circle-disk", ("circle", (2.5, 0.3, 0.0), _tilted_z(a, "x"), 0.5),
         ("disk", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0)),
        ("circle-disk, inside", "circle-disk", ("circle", (0.3, 0.2, 0.0), _tilted_z(a), 0.5),
         ("disk", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0)),
        ("disk-disk, outside", "disk-disk", ("disk", (2.5, 0.3, 0.0), _tilted_z(a, "x"), 0.5),
         ("disk", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 2.0)),
    ]


def sweep_cases(kinds=None):
    """Every sweep case, in family order; restricted to `kinds` when given."""
    out = []
    for k in FAMILIES["axis-tilt"][2]:
        for member, kind, a, b, orient in _axis_tilt(k):
            out.append(SweepCase("axis-tilt", member, kind, k, avt.scene_values(a, b, orient)))
    for k in FAMILIES["tangent-lift"][2]:
        members, h = _tangent_lift(k)
        for member, kind, a, b, orient in members:
            exact = h if orient == "z" else None
            out.append(SweepCase("tangent-lift", member, kind, k, avt.scene_values(a, b, orient), exact))
    for k in FAMILIES["offset"][2]:
        for member, kind, a, b in OFFSET_SCENES:
            out.append(SweepCase("offset", member, kind, k, avt.scene_values(a, b, "z", 10.0 ** k)))
    for k in FAMILIES["circle-tilt"][2]:
        for member, kind, a, b in _circle_tilt(k):
            out.append(SweepCase("circle-tilt", member, kind, k, avt.scene_values(a, b)))
    if kinds is not None:
        out = [c for c in out if c.kind in kinds]
    return out


@functools.lru_cache(maxsize=None)
def _mp_reference(kind, values):
    return avt.reference_distance(kind, values)


def reference(case):
    """(50-digit distance, largest radius) of a sweep case's exact float inputs."""
    radius = avt.largest_radius(case.kind, case.values)
    if case.exact is not None:
        return avt.mpf(case.exact), radius
    return _mp_reference(case.kind, case.values), radius


def relative_error(distance, case):
    ref, radius = reference(case)
    return avt.relative_error(repr(float(distance)), ref, radius), ref, radius


# ------------------------------------------------------------------------------------------------
# Python API shapes
# ------------------------------------------------------------------------------------------------
def make_shape(cd, shape, vals):
    v = np.asarray(vals, dtype=float)
    if shape == "point":
        return v[:3].copy()
    if shape == "line":
        return cd.Line(v[:3], v[3:6])
    if shape == "ray":
        return cd.Ray(v[:3], v[3:6])
    if shape == "segment":
        return cd.Segment(v[:3], v[3:6])
    if shape == "circle":
        return cd.Circle(v[:3], v[3:6], float(v[6]))
    if shape == "disk":
        return cd.Disk(v[:3], v[3:6], float(v[6]))
    if shape == "bezier":
        k = int(v[0])
        return cd.Bezier(v[1:1 + 3 * k].reshape(k, 3))
    raise ValueError(shape)


def make_shapes(cd, kind, values):
    (a, va), (b, vb) = avt.split_values(kind, values)
    return make_shape(cd, a, va), make_shape(cd, b, vb)


# ------------------------------------------------------------------------------------------------
# summaries and the plot (used by accuracy_vs_time.py)
# ------------------------------------------------------------------------------------------------
def _members(cases, family):
    seen = []
    for c in cases:
        if c.family == family and c.member not in seen:
            seen.append(c.member)
    return seen


def summarize_failures(cases, errors, policies, bar):
    """errors[(index into cases, policy)] -> relative error. Returns {'lines': [...], 'summary': str}."""
    lines, fails = [], []
    for family in FAMILIES:
        for member in _members(cases, family):
            idx = [i for i, c in enumerate(cases) if c.family == family and c.member == member]
            parts = []
            for pol in policies:
                errs = [(cases[i].k, errors[(i, pol)]) for i in idx]
                worst_k, worst = max(errs, key=lambda e: e[1])
                over = [k for k, e in errs if not e <= bar]
                parts.append(f"{pol} max {avt.fmt_e(worst)}" + (f" (k={worst_k})" if worst > 0 else "")
                             + (f" OVER at k={','.join(map(str, over))}" if over else ""))
                if over:
                    fails.append(f"{pol} on {family} / {member} at k = {','.join(map(str, over))} "
                                 f"(max {avt.fmt_e(worst)} at k={worst_k})")
            lines.append(f"{family} / {member}: " + "; ".join(parts))
    if fails:
        summary = "over the 1e-12 bar: " + "; ".join(fails) + "."
    else:
        summary = "every policy stays within the 1e-12 bar for every k of every family."
    return {"lines": lines, "summary": summary, "fails": fails}


MEMBER_STYLES = [("-", "o"), ("--", "s"), (":", "^"), ("-.", "D"), ((0, (5, 1, 1, 1, 1, 1)), "v")]


def plot_sweeps(path, cases, errors, policies, colors, bar):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    fams = [f for f in FAMILIES if any(c.family == f for c in cases)]
    ncol = 2
    nrow = (len(fams) + 1) // 2
    fig, axes = plt.subplots(nrow, ncol, figsize=(7.2 * ncol, 4.8 * nrow), squeeze=False)
    offsets = {p: (j - (len(policies) - 1) / 2) * 0.12 for j, p in enumerate(policies)}
    for ax, fam in zip(axes.flat, fams):
        members = _members(cases, fam)
        for m_i, member in enumerate(members):
            ls, mk = MEMBER_STYLES[m_i % len(MEMBER_STYLES)]
            idx = [i for i, c in enumerate(cases) if c.family == fam and c.member == member]
            for pol in policies:
                ks = [cases[i].k + offsets[pol] for i in idx]
                ys = [errors[(i, pol)] for i in idx]
                ys = [max(y, avt.ERROR_FLOOR) if math.isfinite(y) else 1.0 for y in ys]
                ax.plot(ks, ys, ls=ls, marker=mk, color=colors[pol], lw=1.2, ms=4.5, alpha=0.85)
        ax.axhline(bar, color="black", lw=1.0, ls="--")
        ax.text(0.01, bar * 2.5, "bar 1e-12", transform=ax.get_yaxis_transform(), fontsize=8)
        ax.set_yscale("log")
        ax.set_ylim(avt.ERROR_FLOOR / 3, 10.0)
        title, xlabel, ks = FAMILIES[fam]
        ax.set_xticks(list(ks))
        ax.set_xlabel(xlabel)
        ax.set_ylabel("relative error (double)")
        ax.set_title(f"{fam}: {title}", fontsize=11)
        ax.grid(True, alpha=0.3)
        handles = [Line2D([], [], color="0.25", ls=MEMBER_STYLES[i % len(MEMBER_STYLES)][0],
                          marker=MEMBER_STYLES[i % len(MEMBER_STYLES)][1], label=m) for i, m in enumerate(members)]
        handles += [Line2D([], [], color=colors[p], lw=3, label=p) for p in policies]
        ax.legend(handles=handles, fontsize=8, loc="upper left", ncol=2, framealpha=0.85)
    for ax in list(axes.flat)[len(fams):]:
        ax.axis("off")
    fig.suptitle("Stability sweeps toward degeneracies: |d - d_ref| / max(d_ref, largest radius), "
                 f"errors below {avt.ERROR_FLOOR:.0e} drawn at it", fontsize=12)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(path, dpi=110)
    plt.close(fig)
