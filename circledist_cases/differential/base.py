"""Kinds, kind pairs, solver and precision combinations, the bars, and case keys.

Bars: |d - d_true| <= bar * max(d_true, scale), the scale being the largest radius (circle, disk
or arc) in the query (for a query without a circle or disk: the scale of the pairs' own accuracy tests, see
``bar_scale``: for the linear pairs 1e-12 x the query's size), bar 1e-12 in float64,
1e-15 in long double (float64 inputs referenced exactly), 4 float32 ulps (4 * 2^-23) for float32
inputs (README: float32 queries are solved in double and rounded; referenced on the float32
values).  Closest points must lie on their shapes within 8 ulps (of the answer's precision) of
the scene scale (the largest input coordinate or radius; for a query without a round, of the
points' own size where that is larger: nearly parallel lines meet far outside the scene), and
their separation must equal the reported distance within the bar plus those ulps.
"""

from __future__ import annotations

import importlib

import numpy as np


SOLVERS = ("bracketing", "companion", "polished", "eigen")
PRECISIONS = ("float64", "longdouble", "float32")
EPS32 = float(np.finfo(np.float32).eps)
EPS64 = float(np.finfo(np.float64).eps)
EPSLD = float(np.finfo(np.longdouble).eps)
BARS = {"float64": 1e-12, "longdouble": 1e-15, "float32": 4 * EPS32}
OUT_EPS = {"float64": EPS64, "longdouble": EPSLD, "float32": EPS32}
ULPS = 8  # closest points: ulps of the scene scale allowed off their shapes
LINEAR = ("point", "line", "ray", "segment")
ROUND = ("circle", "disk")
# kinds with a radius: the rounds and arcs (an arc is a circle restricted to an angle interval;
# its data: centre, normal, radius, start, angle -- 11 numbers)
RIMS = ROUND + ("arc", "annulus")
# an annulus's data: centre, normal, OUTER radius, inner radius (8 numbers: the outer radius at
# index 6, where a round's radius is, so scales, translations and frames read it alike); the
# library's constructor takes (centre, normal, inner, outer)
TARGET_REGION = ("disk", "annulus")  # closed forms with a face (a disk's |z|, an annulus's too)
# the pairs with a circle or disk, then the pairs among
# points, lines, rays and segments (point before line before ray before segment) and a Bezier
# curve against each of them (the curve first)
ROUND_PAIRS = [(lk, rk) for lk in LINEAR for rk in ROUND] + [
    ("bezier", "circle"),
    ("bezier", "disk"),
    ("circle", "circle"),
    ("circle", "disk"),
    ("disk", "disk"),
]
LL = [(lk, rk) for i, lk in enumerate(LINEAR) for rk in LINEAR[i:]]
BL = [("bezier", lk) for lk in LINEAR]
# an arc against every kind with a query, the arc second (as a circle or disk comes after the
# pieces, and arc after disk), a Bezier curve too (after "segment", since Arc-Bezier has its query,
# bezier_arc.hpp): the screen, the families (_arc_variant, _feature), the reference
# (reference_arc.bezier_arc) and the checker take it as they are.  (Adding a pair re-maps the
# arc families' case ids: case i is pair i mod the number of pairs.)
ARC_OTHERS = ("point", "line", "ray", "segment", "bezier", "circle", "disk", "arc")
ARC_PAIRS = [(k, "arc") for k in ARC_OTHERS]
ARC_RR = [p for p in ARC_PAIRS if p[0] in ("circle", "disk", "arc")]  # a circle, disk or arc against an arc
# an annulus against every kind, the annulus second (after the arc, and after another
# annulus: (annulus, annulus)); the "ann_" families (_ann_variant: the disk families with a hole
# cut in each annulus, arcs cut from circles as the arc families do; then the annuli's own)
ANN_OTHERS = ("point", "line", "ray", "segment", "bezier", "circle", "disk", "arc", "annulus")
ANN_PAIRS = [(k, "annulus") for k in ANN_OTHERS]
ANN_RR = [p for p in ANN_PAIRS if p[0] in ("circle", "disk", "arc", "annulus")]
KIND_PAIRS = ROUND_PAIRS + LL + BL + ARC_PAIRS + ANN_PAIRS
LD = np.longdouble


def combos(solvers=SOLVERS, precisions=PRECISIONS):
    return [(s, p) for p in precisions for s in solvers]


# library answers check_cases asks for per case, combination and argument order, batched:
# distance, closest_points, within and distance_if_within at two probes each, intersects
BATCH_ANSWERS = {"distance": 1, "closest_points": 1, "within": 2, "distance_if_within": 2, "intersects": 1}


def answers_per_case(n_combos, within=True):
    """Batched library answers per case (both orders); the scalar sample adds a few more."""
    per_order = sum(BATCH_ANSWERS.values()) if within else BATCH_ANSWERS["distance"] + BATCH_ANSWERS["closest_points"]
    return n_combos * 2 * per_order


def _load(name):
    """A reference module of circledist_cases (reference_linear_round, reference_round), imported on first use:
    mpmath is needed only to confirm findings."""
    return importlib.import_module(f"..{name}", __package__)


RR = [("circle", "circle"), ("circle", "disk"), ("disk", "disk")]
LR = [(lk, rk) for lk in LINEAR for rk in ROUND]
LR3 = [(lk, rk) for lk in ("line", "ray", "segment") for rk in ROUND]
BR = [("bezier", "circle"), ("bezier", "disk")]
LL3 = [p for p in LL if "point" not in p]  # among lines, rays and segments
LLZ = [p for p in LL + BL if "segment" in p]  # with a segment (made zero-length)


def _plain(data):
    if isinstance(data, (list, tuple)) and data and isinstance(data[0], (list, tuple, np.ndarray)):
        return [[float(x) for x in p] for p in data]
    return [float(x) for x in data]


def _key(case):
    def t(d):
        return tuple(tuple(p) for p in d) if d and isinstance(d[0], list) else tuple(d)

    return (case["a"], t(case["a_data"]), case["b"], t(case["b_data"]))


def _piece_points(kind, data):
    """A point's (p,), a line's or ray's (origin, direction), a segment's (p0, p1)."""
    return (data[:3],) if kind == "point" else (data[:3], data[3:6])


# The case families in case-id order, name: (kind pairs, generator).  Declared here, filled by
# the families module: the generators of the arc, annulus and far-translated families look their
# base families up in it.
FAMILIES = {}
