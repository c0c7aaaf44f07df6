"""Independent 50-digit reference for arcs: one, used by tests/pairs/test_arc.py and by the
differential test's confirmation (circledist_cases/differential/).

No circledist code.  An arc is built from its own definition, center + R (cos t u + sin t v),
t in [0, angle], u the unit projection of `start` onto the plane normal to `normal`, v = n x u
(an angle of at least float64's 2 pi is the whole circle, the library's convention).  A query
against an arc is the minimum over the arc's angle t of the other shape's closed-form point
distance (point, line, ray, segment: the clamped projection; circle, disk: note 000 / 001;
another arc: the point-arc closed form of ArcMP.point_distance, itself checked against sampling
in tests/pairs/test_arc.py), found by reference_kit.minimize_1d (dense samples, golden section on
every sampled local minimum; zoomed by Lipschitz bounds where two minima could share a sampling
step: an arc nearly tangent to a line or ring, or far larger than a round target).  Every value
is a genuine point's exact distance, an upper bound; the least is kept.  A Bezier curve against
an arc (bezier_arc, for the Arc-Bezier query to come): the curve's t against the point-arc closed
form, zoomed alike.

Shapes are plain tuples (kind, *fields), fields as tuples of floats: ("arc", center, normal,
radius, start, angle); shape(kind, data) converts the differential's flat lists.
"""

from __future__ import annotations

import functools
import math

from . import reference_kit as K
from . import reference_round as R
from .reference_store import stored

mpf, ctx = K.mpf, K.ctx
TWO_PI = 2 * math.pi  # float64's 2 pi: an angle >= this is the whole circle (docs/derivations/arc.md)
INTERVALS = 720


def _t(v):
    return tuple(float(x) for x in v)


def arc(center, normal, radius, start, angle):
    return ("arc", _t(center), _t(normal), float(radius), _t(start), float(angle))


def shape(kind, data):
    """The tuple of a shape given as the differential's flat data list."""
    d = [float(x) for x in data]
    if kind == "point":
        return ("point", _t(d[:3]))
    if kind in ("line", "ray", "segment"):
        return (kind, _t(d[:3]), _t(d[3:6]))
    if kind in ("circle", "disk"):
        return (kind, _t(d[:3]), _t(d[3:6]), d[6])
    assert kind == "arc", kind
    return arc(d[:3], d[3:6], d[6], d[7:10], d[10])


class ArcMP:
    """An arc at 50 digits: its basis from its own definition (not the library's frame)."""

    def __init__(self, shape):
        _, c, n, r, s, a = shape
        self.c, self.r, self.angle = K.vec(c), K.to_mp(r), K.to_mp(a)
        self.whole = float(a) >= TWO_PI
        self.n = K.normalize(K.vec(n))
        s = K.vec(s)
        self.u = K.normalize(K.sub(s, K.scale(K.dot(s, self.n), self.n)))
        self.v = K.cross(self.n, self.u)

    def at(self, t):
        return K.add(self.c, K.scale(self.r, K.add(K.scale(ctx.cos(t), self.u), K.scale(ctx.sin(t), self.v))))

    def point_distance(self, p):
        """Closed form (a point's distance along the circle rises with the angular gap from the
        angle of its projection): the ring's distance where that angle is on the arc, else the
        nearer end's; on the axis every point is as far."""
        w = K.sub(p, self.c)
        z, x, y = K.dot(w, self.n), K.dot(w, self.u), K.dot(w, self.v)
        rho = ctx.sqrt(x * x + y * y)
        if rho == 0:
            return ctx.sqrt(z * z + self.r * self.r)
        phi = ctx.atan2(y, x)
        if phi < 0:
            phi += 2 * ctx.pi
        if self.whole or phi <= self.angle:
            return ctx.sqrt(z * z + (rho - self.r) ** 2)
        return min(K.dist(p, self.at(mpf(0))), K.dist(p, self.at(self.angle)))


def point_distance_function(shape):
    """x (an mp 3-vector) -> the distance from x to `shape`, in closed form."""
    kind = shape[0]
    if kind == "point":
        p = K.vec(shape[1])
        return lambda x: K.dist(x, p)
    if kind in ("line", "ray", "segment"):
        o, d = K.vec(shape[1]), K.vec(shape[2])
        return lambda x: R.point_linear_closest(x, kind, o, d)[0]
    if kind in ("circle", "disk"):
        rnd = R.make_round(shape[1], shape[2], shape[3])
        f = R.point_circle if kind == "circle" else R.point_disk
        return lambda x: f(x, rnd)[0]
    assert kind == "arc"
    return ArcMP(shape).point_distance


def _target_radius(shape):
    return K.to_mp(shape[3]) if shape[0] in ("circle", "disk", "arc") else None


ZOOM_SAMPLES = 4000  # the zoom's cap on added samples per reference (lowest bounds first)


@functools.lru_cache(maxsize=4096)
@stored
def reference_mp(a, b, intervals=INTERVALS):
    """min over the arc a's angle t of the closed-form distance from a(t) to b (an mpf).

    Zoomed (reference_kit.minimize_1d's Lipschitz zoom; a's point moves by its radius per
    radian): every interval that could hold a value below the best sample is re-sampled until one
    step moves the point by at most 1/8 of a lower bound of the distance on it (the distance to
    a point, line, ray, segment or round is smooth on the scale of the distance itself away from
    a round's axis region), and, where a is far larger than a round target b, by at most b's
    radius / 8.  Why: an arc passing a line (or a ring) at a height h while nearly tangent to it
    crosses its neighbourhood twice, 2 sqrt(2 R delta) apart; two such near-tied minima 4e-4 rad
    apart shared one of the 720 steps (5.9e-3 rad) of the float32 scene of
    arc_far_origin/20261114/2, and golden section found the higher one (3.7478e-8 against
    3.7469e-8).  On a continuum of closest points every interval qualifies: the zoom then stops
    at ZOOM_SAMPLES (any sample there is a minimum)."""
    arc_a = ArcMP(a)
    hi = 2 * ctx.pi if arc_a.whole else arc_a.angle
    rt = _target_radius(b)
    big = rt is not None and rt > 0 and arc_a.r * hi / intervals > rt / K.ZOOM_FRACTION
    return _least(
        arc_a.at,
        point_distance_function(b),
        hi,
        intervals,
        arc_a.whole,
        lambda lo_, hi_: arc_a.r,
        max(arc_a.r, rt or 0),
        rt / K.ZOOM_FRACTION if big else None,
    )


def _least(point_at, other, hi, intervals, periodic, lipschitz, scale, round_res=None):
    """The least value of other(point_at(t)) over t in [0, hi], by minimize_1d zoomed as
    reference_mp says (round_res: the finer resolution a round's features ask for, or None)."""
    floor = mpf("1e-20") * scale
    seen = {}

    def f(t):
        v = other(point_at(t))
        seen[t._mpf_] = v
        return v

    def resolution(lo_, hi_, lh):
        res = max(min(seen[lo_._mpf_], seen[hi_._mpf_]) - lh / 2, floor) / K.ZOOM_FRACTION
        return res if round_res is None else min(res, round_res)

    minima = K.minimize_1d(
        f,
        mpf(0),
        hi,
        intervals,
        periodic=periodic,
        lipschitz=lipschitz,
        resolution=resolution,
        max_samples=ZOOM_SAMPLES,
    )
    return minima[0].value


@stored
def bezier_arc(ctrl, arc_shape):
    """A Bezier curve (control points) against an arc: min over the curve's t of the point-arc
    closed form, zoomed as above (the curve's speed bounded by its hodograph, reference_round's
    _speed_bound; the arc's features resolved to its radius / 8 where the curve is far larger)."""
    arc_b = ArcMP(arc_shape)
    pts = [K.vec(p) for p in ctrl]
    extent = max(float(K.norm(K.sub(p, pts[0]))) for p in pts)
    return _least(
        lambda t: R.bezier_point(ctrl, t),
        arc_b.point_distance,
        mpf(1),
        R.CURVE_SAMPLES,
        False,
        R._speed_bound(ctrl),
        max(arc_b.r, extent),
        arc_b.r / K.ZOOM_FRACTION,
    )


def reference(a, b, intervals=INTERVALS):
    """reference_mp as a float."""
    return float(reference_mp(a, b, intervals))


def case_reference(ka, a_data, kb, b_data):
    """The 50-digit distance of a differential case with an arc (canonical order: the arc second,
    or both arcs; a Bezier curve first: bezier_arc, ready for the Arc-Bezier query)."""
    assert kb == "arc", (ka, kb)
    if ka == "bezier":
        return bezier_arc([list(p) for p in a_data], shape(kb, b_data))
    return reference_mp(shape(kb, b_data), shape(ka, a_data))
