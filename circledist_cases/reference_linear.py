"""50-digit reference for points, lines, rays and segments among themselves (no circledist).

Shared by tests/accuracy/test_linear_accuracy.py and the differential test (circledist_cases/differential/).
The reference minimizes over one parameter: s -> dist(A(s), B), the distance from a point of A
to the piece B (its projection clamped, in mpmath), is convex in s, so a bracket search
(sampling, then golden section) finds its minimum; s = tan(phi) maps an infinite interval onto a
finite one (a monotone change of variable keeps the function unimodal). Inputs are taken as the
exact binary64 values.

The search: 121 samples of phi, then 240 golden-section steps (interval reduction like a ternary
search, one new value per step) on the bracket around the best sample, down to 0.618^240 ~ 1e-50
of a sample step: a minimum far along a line (an origin 1e12 away, tan(phi) ~ 1e12, where one
unit of phi moves the point by 1e24) is still resolved to ~1e-26 of the direction's length.
(160 ternary steps, a bracket of ~1e-28 of a
step, would leave such a minimum ~4e-6 of the direction's length off: dphi / (pi/2 - phi)^2.)
"""

import mpmath as mp
import numpy as np

from .golden import golden_section
from .reference_store import stored

mp.mp.dps = 50
KINDS = ("point", "line", "ray", "segment")
INF = mp.inf
STEPS = 240
_INVPHI = (mp.sqrt(5) - 1) / 2


def interval(kind):
    return {"point": (0, 0), "line": (-INF, INF), "ray": (0, INF), "segment": (0, 1)}[kind]


def piece(kind, p, q=None):
    """(origin, direction, lo, hi) in mpmath (3-tuples of mpf); a segment's direction is q - p
    exactly; a point's q is ignored (None allowed)."""
    o = tuple(mp.mpf(float(x)) for x in p)
    if kind == "point":
        d = (mp.mpf(0),) * 3
    else:
        d = tuple(mp.mpf(float(x)) - (oi if kind == "segment" else 0) for x, oi in zip(q, o))
    lo, hi = interval(kind)
    return o, d, lo, hi


def _dot(u, v):
    return mp.fsum(a * b for a, b in zip(u, v))


def point_to_piece(x, b):
    """|x - (the point of b nearest x)| for a point x (any sequence of 3 numbers)."""
    o, d, lo, hi = b
    w = tuple(xi - oi for xi, oi in zip(x, o))
    dd = _dot(d, d)
    t = 0 if dd == 0 else min(max(_dot(w, d) / dd, lo), hi)
    return mp.sqrt(mp.fsum((wi - t * di) ** 2 for wi, di in zip(w, d)))


def reference(a, b):
    """The distance between two pieces (from piece()), as an mpf."""
    o, d, lo, hi = a
    if lo == hi:
        return point_to_piece(o, b)
    to_s = (lambda phi: phi) if (lo, hi) == (0, 1) else (lambda phi: mp.tan(phi))
    a_lo = 0 if (lo, hi) == (0, 1) or lo == 0 else -mp.pi / 2
    a_hi = 1 if (lo, hi) == (0, 1) else mp.pi / 2

    def f(phi):
        s = to_s(phi)
        return point_to_piece(tuple(oi + s * di for oi, di in zip(o, d)), b)

    grid = [a_lo + (a_hi - a_lo) * mp.mpf(i) / 120 for i in range(121)]
    values = [f(g) for g in grid]
    i = min(range(len(grid)), key=lambda k: values[k])
    left, right = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    # golden-section steps: the ternary search's bracket reduction, reusing one inner value per
    # step (a unimodal function keeps its minimum in the bracket either way)
    _, best = golden_section(f, left, right, _INVPHI, steps=STEPS)
    return min(values[i], best)


@stored
def linear_linear(ka, a_data, kb, b_data):
    """The reference for two pieces given as flat float data (point: 3 numbers; line / ray:
    origin, direction; segment: two ends)."""
    return reference(
        piece(ka, a_data[:3], a_data[3:6] if ka != "point" else None),
        piece(kb, b_data[:3], b_data[3:6] if kb != "point" else None),
    )


# The bars of the linear pairs: |error| <= bar x max(true distance, FLOOR x the query's size). The
# answers are held to their own size; only distances twelve orders below the query's size (pieces
# that touch or cross, within the inputs' rounding) are held to an absolute floor.
FLOOR = 1e-12


def bar_scale(ka, a_data, kb, b_data):
    """What the bar multiplies besides the true distance: FLOOR x query_size."""
    return FLOOR * query_size(ka, a_data, kb, b_data)


def query_size(ka, a_data, kb, b_data):
    """The query's size: the largest distance from A's first point to any point that defines the
    query (a point, the origins of lines and rays, segment ends).  Translating a scene does not
    change it."""
    pts = (
        [np.asarray(a_data[:3], float)]
        + ([np.asarray(a_data[3:6], float)] if ka == "segment" else [])
        + [np.asarray(b_data[:3], float)]
        + ([np.asarray(b_data[3:6], float)] if kb == "segment" else [])
    )
    return max(float(np.linalg.norm(x - pts[0])) for x in pts[1:])
