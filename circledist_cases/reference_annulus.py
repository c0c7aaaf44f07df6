"""Independent 50-digit reference for annuli: one, used by tests/pairs/test_annulus.py, the
differential test and the accuracy report (circledist_cases/accuracy.py).

No circledist code. The distance from a point to an annulus is a closed form (its projection's
distance rho from the center: |z| in the ring, else the nearer rim's sqrt(z^2 + (rho - r)^2)),
checked against dense sampling of the annulus in tests/pairs/test_annulus.py. Against a curve (circle,
arc, line, ray, segment: a line's parameter on the bounded stretch where a closest point can lie;
a Bezier curve's t) the reference is the minimum over the curve's parameter of that closed form, by
reference_kit.minimize_1d (dense samples, golden section on every sampled local minimum, zoomed
where two minima could share a sampling step). Two plane regions (a disk or an annulus against an
annulus) are as close as a rim of one is to the other: a closest pair with both points inside
their regions' rims has p - q normal to both planes, so the planes are parallel and the pair
slides to a rim, and a contact (distance 0) has a rim point of one region in the other; the
reference is the least of each rim's minimum against the other region (the closed forms of
point-disk and point-annulus).

Shapes are plain tuples (kind, *fields), fields as tuples of floats:
("annulus", center, normal, inner_radius, outer_radius); the other kinds as reference_arc's.
"""

from __future__ import annotations

import functools
import math

from . import reference_kit as K
from . import reference_round as R
from .reference_arc import ArcMP
from .reference_store import stored

mpf, ctx = K.mpf, K.ctx
TWO_PI = 2 * math.pi
INTERVALS = 400  # samples of a parameter per minimization (then golden section on every local minimum)


def _t(v):
    return tuple(float(x) for x in v)


def _radii(shape):
    """A shape's radius (a round's or an arc's; an annulus's outer one)."""
    if shape[0] in ("circle", "disk", "arc"):
        return [shape[3]]
    return [shape[4]] if shape[0] == "annulus" else []


# ------------------------------------------------------------------------------------------------
# shapes as plain tuples: (kind, *fields), fields as tuples of floats
# ------------------------------------------------------------------------------------------------
def annulus(center, normal, inner, outer):
    return ("annulus", _t(center), _t(normal), float(inner), float(outer))


# ------------------------------------------------------------------------------------------------
# the reference (50 digits)
# ------------------------------------------------------------------------------------------------
class AnnulusMP:
    """An annulus at 50 digits: center, unit normal, radii, and its rims (own frame)."""

    def __init__(self, shape):
        _, c, n, inner, outer = shape
        self.c, self.inner, self.outer = K.vec(c), K.to_mp(inner), K.to_mp(outer)
        self.u, self.v, self.n = K.frame(n)

    def point_distance(self, p):
        w = K.sub(p, self.c)
        z = K.dot(w, self.n)
        rho = K.norm(K.sub(w, K.scale(z, self.n)))
        if rho < self.inner:
            return ctx.sqrt(z * z + (self.inner - rho) ** 2)
        if rho > self.outer:
            return ctx.sqrt(z * z + (rho - self.outer) ** 2)
        return abs(z)

    def rims(self):
        """Its rims as curves (point at angle t, speed), the outer first."""
        return [rim_curve(self.c, self.u, self.v, r) for r in (self.outer, self.inner)]


def rim_curve(c, u, v, r):
    """The circle c + r (cos t u + sin t v): (point at t, |d point / dt|)."""
    return (lambda t: K.add(c, K.scale(r, K.add(K.scale(ctx.cos(t), u), K.scale(ctx.sin(t), v))))), r


def point_distance_function(shape):
    """x (an mp 3-vector) -> the distance from x to `shape` (a point, disk or annulus), in closed form."""
    kind = shape[0]
    if kind == "point":
        p = K.vec(shape[1])
        return lambda x: K.dist(x, p)
    if kind == "disk":
        rnd = R.make_round(shape[1], shape[2], shape[3])
        return lambda x: R.point_disk(x, rnd)[0]
    assert kind == "annulus"
    return AnnulusMP(shape).point_distance


def curves_of(shape, toward):
    """[(point at t, lo, hi, periodic, speed)]: the curves whose minimum against the annulus `toward`
    is the distance (a curve's own points; a disk's or an annulus's rims, see the module docstring)."""
    kind = shape[0]
    if kind in ("circle", "disk"):
        u, v, _ = K.frame(shape[2])
        at, speed = rim_curve(K.vec(shape[1]), u, v, K.to_mp(shape[3]))
        return [(at, mpf(0), 2 * ctx.pi, True, speed)]
    if kind == "arc":  # the arc's own definition (reference_arc.ArcMP)
        arc_mp = ArcMP(shape)
        if shape[5] < TWO_PI:
            return [(arc_mp.at, mpf(0), arc_mp.angle, False, arc_mp.r)]
        return [(arc_mp.at, mpf(0), 2 * ctx.pi, True, arc_mp.r)]
    if kind == "annulus":
        return [(at, mpf(0), 2 * ctx.pi, True, speed) for at, speed in AnnulusMP(shape).rims()]
    # a line, ray or segment: the stretch where a closest point can lie. A point of the line at
    # |P(t) - c| > |P(t*) - c| + 2 outer (t* nearest the center c) is farther from the annulus than P(t*).
    o, d = K.vec(shape[1]), K.vec(shape[2])
    if kind == "segment":
        d = K.sub(d, o)
    ring = AnnulusMP(toward)
    dd = K.dot(d, d)
    if dd == 0:  # a zero-length segment: its one point
        return [(lambda t: o, mpf(0), mpf(0), False, mpf(0))]
    t_star = K.dot(K.sub(ring.c, o), d) / dd
    reach = (K.dist(K.add(o, K.scale(t_star, d)), ring.c) + 2 * ring.outer + 1) / ctx.sqrt(dd)
    lo, hi = t_star - reach, t_star + reach
    if kind in ("ray", "segment"):
        lo = max(lo, mpf(0))
    if kind == "segment":
        hi = min(hi, mpf(1))
    if lo > hi:  # the stretch lies wholly past the piece's end: only that end can be closest
        lo = hi = mpf(0) if kind == "ray" or t_star < 0 else mpf(1)
    return [(lambda t: K.add(o, K.scale(t, d)), lo, hi, False, ctx.sqrt(dd))]


def _feature(a, b):
    """The smallest length either shape's features must be resolved to (a zoom's target)."""
    lengths = [x for x in _radii(a) + _radii(b) if x > 0]
    for s in (a, b):
        if s[0] == "annulus" and s[4] > s[3]:
            lengths += [s[4] - s[3]] + ([s[3]] if s[3] > 0 else [])
    # An annulus of radius 0 (a point) against a shape without a radius: no feature of its own;
    # the curve's or piece's distance to a point is resolved at the unit length.
    return mpf(min(lengths, default=1)) / 8


def minimum_along(curve, other, feature):
    """The least of other(point) along the curve. Two local minima can share a sample interval only
    where a step moves the point by more than the structure there: the target's features, or the
    distance itself (the scale on which the distance varies). Where a step is longer than both,
    the samples are zoomed (minimize_1d's lipschitz bound: the curve's speed) down to them."""
    at, lo, hi, periodic, speed = curve
    if lo == hi:
        return other(at(lo))
    f = lambda t: other(at(t))  # noqa: E731
    plain = K.minimize_1d(f, lo, hi, INTERVALS, periodic)[0].value
    resolution = max(feature, plain / 8)
    if speed * (hi - lo) / INTERVALS <= resolution:
        return plain
    return K.minimize_1d(
        f, lo, hi, INTERVALS, periodic, lipschitz=lambda x, y: speed, resolution=lambda x, y, step: resolution
    )[0].value


@functools.lru_cache(maxsize=None)
@stored
def reference_mp(a, b):
    """The distance between the annulus a and the shape b, at 50 digits (an mpf; module docstring)."""
    ring = AnnulusMP(a)
    feature = _feature(a, b)
    if b[0] == "point":
        return ring.point_distance(K.vec(b[1]))
    values = [minimum_along(c, ring.point_distance, feature) for c in curves_of(b, a)]
    if b[0] in ("disk", "annulus"):  # a's rims against the region b
        values += [minimum_along(c, point_distance_function(b), feature) for c in curves_of(a, a)]
    return min(values)


def reference(a, b):
    """reference_mp as a float."""
    return float(reference_mp(a, b))


@stored
def bezier_reference_mp(a, ctrl):
    """The distance between the annulus a and the Bezier curve `ctrl` at 50 digits (an mpf): the
    least of the point-annulus closed form over the curve's t (its speed bounded by
    n max |P_i+1 - P_i|)."""
    pts = [K.vec(p) for p in ctrl]
    speed = (len(pts) - 1) * max([K.norm(K.sub(q, p)) for p, q in zip(pts, pts[1:])] + [mpf(0)])
    curve = (lambda t: R.bezier_point(ctrl, t), mpf(0), mpf(1), False, speed)
    return minimum_along(curve, AnnulusMP(a).point_distance, _feature(a, ("bezier",)))


def bezier_reference(a, ctrl):
    """bezier_reference_mp as a float."""
    return float(bezier_reference_mp(a, ctrl))
