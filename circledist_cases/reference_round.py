"""Independent 50-digit references for the round-shape queries of circledist.

Nothing here uses circledist or polynomial root finding.  Every reference reduces the query to the
minimisation of a *closed-form* point-to-shape distance over one real parameter:

* point-circle (circle centre C, unit normal N, radius R): with w = P - C, z = N.w and
  rho = |w - z N| (distance of P from the circle's axis),  dist^2 = z^2 + (rho - R)^2.
* point-disk (note 001 section 2): dist^2 = z^2 if rho <= R, else z^2 + (rho - R)^2.

Both are exact, so minimising them over a compact one-parameter shape (a circle's angle, a Bezier
curve's t) gives the exact shape-to-shape distance: the minimiser exists and is found by dense
sampling followed by golden-section refinement of every sampled local minimum (exactly tied
samples on a continuum of minimisers excepted, see minimize_1d).  Where the moving shape is far
larger than the target round, the scan is first zoomed (Lipschitz bounds on the moving point's
speed) until every interval that could hold the minimum is sampled finely for the round's
features, so that near-tied local minima closer than the uniform step are refined each.  Every value ever
evaluated is the distance between a genuine point of one shape and the genuine closest point of the
other, hence an upper bound of the true distance; the reference keeps the smallest.

Arithmetic, exact conversions, vectors, frames and the minimisation (minimize_1d) are the shared
50-digit toolkit's (reference_kit): mpmath at 50 significant digits in a private context, float
inputs converted exactly, so the references describe exactly the float64 scene given to the
library, e.g. after a translation by 1e8 the reference is that of the rounded, translated
coordinates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, List, Optional, Sequence

import mpmath.libmp as _lm

# the shared 50-digit toolkit; its names stay reachable here as reference_round.NAME
from .reference_kit import (  # noqa: F401
    DPS,
    MAX_REFINED,
    MAX_ZOOM_SAMPLES,
    PARAM_TOL,
    TIE_TOL,
    ZOOM_FRACTION,
    ZOOM_SPLIT,
    LocalMin,
    Vec,
    _sample_grid,
    add,
    cross,
    ctx,
    dist,
    dot,
    frame,
    minimize_1d,
    mpf,
    norm,
    normalize,
    scale,
    sub,
    to_mp,
    vec,
)
from .reference_store import stored

CIRCLE_SAMPLES = 720  # samples of an angle over [0, 2 pi)
CURVE_SAMPLES = 600  # intervals of a Bezier parameter over [0, 1] (end points included)
_TWO_PI = 2 * ctx.pi
_RN = _lm.round_nearest
_add, _mul = _lm.mpf_add, _lm.mpf_mul


# ----------------------------------------------------------------------------------------------
# shapes
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Round:
    """A circle or disk: centre, orthonormal frame (u, v, n), radius; plus the raw float input."""

    center: Vec
    u: Vec
    v: Vec
    n: Vec
    radius: object
    raw_center: tuple
    raw_normal: tuple
    raw_radius: float

    def rim_point(self, theta) -> Vec:
        c, s = ctx.cos_sin(theta)
        return add(self.center, add(scale(self.radius * c, self.u), scale(self.radius * s, self.v)))


def make_round(center, normal, radius) -> Round:
    u, v, n = frame(normal)
    r = to_mp(radius)
    if r < 0:
        raise ValueError("negative radius")
    return Round(vec(center), u, v, n, r, tuple(center), tuple(normal), radius)


# ----------------------------------------------------------------------------------------------
# closed-form point distances
# ----------------------------------------------------------------------------------------------
def _local(p: Vec, rnd: Round):
    w = sub(p, rnd.center)
    z = dot(rnd.n, w)
    a = sub(w, scale(z, rnd.n))
    return z, a


def _round_from_local(z, a, radius, disk: bool):
    rho = norm(a)
    if disk and rho <= radius:
        return abs(z), rho
    return ctx.sqrt(z * z + (rho - radius) ** 2), rho


def point_circle(p: Sequence, rnd: Round):
    """(distance, closest point, degenerate) with degenerate True when p is on the axis."""
    p = vec(p)
    z, a = _local(p, rnd)
    d, rho = _round_from_local(z, a, rnd.radius, disk=False)
    if rho == 0:
        q = add(rnd.center, scale(rnd.radius, rnd.u))
    else:
        q = add(rnd.center, scale(rnd.radius / rho, a))
    return d, q, rho == 0


def point_disk(p: Sequence, rnd: Round):
    """(distance, closest point): note 001 section 2."""
    p = vec(p)
    z, a = _local(p, rnd)
    d, rho = _round_from_local(z, a, rnd.radius, disk=True)
    if rho <= rnd.radius:
        q = add(rnd.center, a)
    else:
        q = add(rnd.center, scale(rnd.radius / rho, a))
    return d, q


def point_segment(p: Vec, p0: Vec, p1: Vec):
    """Closed-form distance from a point to a segment (clamped projection)."""
    d = sub(p1, p0)
    dd = dot(d, d)
    t = mpf(0) if dd == 0 else dot(sub(p, p0), d) / dd
    t = min(max(t, mpf(0)), mpf(1))
    return dist(p, add(p0, scale(t, d)))


# ----------------------------------------------------------------------------------------------
# Bezier curves
# ----------------------------------------------------------------------------------------------
def bernstein(k: int, t) -> List[object]:
    s = 1 - t
    tp = [mpf(1)]
    sp = [mpf(1)]
    for _ in range(k):
        tp.append(tp[-1] * t)
        sp.append(sp[-1] * s)
    return [math.comb(k, i) * tp[i] * sp[k - i] for i in range(k + 1)]


def bezier_point(ctrl: Sequence[Sequence], t) -> Vec:
    """de Casteljau evaluation in 50-digit arithmetic."""
    pts = [vec(p) for p in ctrl]
    t = to_mp(t)
    while len(pts) > 1:
        pts = [add(pts[i], scale(t, sub(pts[i + 1], pts[i]))) for i in range(len(pts) - 1)]
    return pts[0]


# ----------------------------------------------------------------------------------------------
# a moving point (circle rim or Bezier curve) measured against a fixed circle or disk
# ----------------------------------------------------------------------------------------------
class _Against:
    """Distance from the affine combination sum_j coef_j * W_j (+ target centre) to a round target.

    W_j are vectors relative to the target's centre; their axial parts z_j = N.W_j and in-plane
    parts a_j = W_j - z_j N are precomputed, so the closed form needs few operations per point.
    The evaluation works on mpmath's raw mantissa/exponent tuples (libmp) at the context's
    precision: the same arithmetic as mpf operators, without the object overhead.
    """

    def __init__(self, rel_vectors: Sequence[Vec], target: Round, disk: bool):
        self.target = target
        self.disk = disk
        z = [dot(target.n, w) for w in rel_vectors]
        a = [sub(w, scale(zj, target.n)) for w, zj in zip(rel_vectors, z)]
        self.terms = [(zj._mpf_, aj[0]._mpf_, aj[1]._mpf_, aj[2]._mpf_) for zj, aj in zip(z, a)]
        self.r = target.radius._mpf_

    def raw(self, coefs, axis=None):
        """coefs: raw libmp values, or None for an exact 1.  Returns the raw distance; axis (a
        list, optional) receives the point's distance from the target's axis (raw)."""
        P, RN = ctx.prec, _RN
        z = ax = ay = az = _lm.fzero
        for c, (zj, a0, a1, a2) in zip(coefs, self.terms):
            if c is None:
                z, ax, ay, az = _add(z, zj, P, RN), _add(ax, a0, P, RN), _add(ay, a1, P, RN), _add(az, a2, P, RN)
            else:
                z = _add(z, _mul(c, zj, P, RN), P, RN)
                ax = _add(ax, _mul(c, a0, P, RN), P, RN)
                ay = _add(ay, _mul(c, a1, P, RN), P, RN)
                az = _add(az, _mul(c, a2, P, RN), P, RN)
        rho2 = _add(_add(_mul(ax, ax, P, RN), _mul(ay, ay, P, RN), P, RN), _mul(az, az, P, RN), P, RN)
        rho = _lm.mpf_sqrt(rho2, P, RN)
        if axis is not None:
            axis.append(rho)
        if self.disk and _lm.mpf_le(rho, self.r):
            return _lm.mpf_abs(z)
        e = _lm.mpf_sub(rho, self.r, P, RN)
        return _lm.mpf_sqrt(_add(_mul(z, z, P, RN), _mul(e, e, P, RN), P, RN), P, RN)

    def __call__(self, coefs):
        return ctx.make_mpf(self.raw([None if c is None else to_mp(c)._mpf_ for c in coefs]))


def _raw_bernstein(k: int, t_raw):
    P, RN = ctx.prec, _RN
    s_raw = _lm.mpf_sub(_lm.fone, t_raw, P, RN)
    tp, sp = [_lm.fone], [_lm.fone]
    for _ in range(k):
        tp.append(_mul(tp[-1], t_raw, P, RN))
        sp.append(_mul(sp[-1], s_raw, P, RN))
    return [_lm.mpf_mul_int(_mul(tp[i], sp[k - i], P, RN), math.comb(k, i), P, RN) for i in range(k + 1)]


@dataclass
class Pair:
    value: object
    pa: Vec
    pb: Vec
    rise: object
    degenerate: bool  # the closest point on the other shape is not unique (point on an axis)
    t: object = None  # a Bezier curve's parameter at the pair (bezier_disk, bezier_circle, bezier_other)


@dataclass(repr=False)
class Reference:
    distance: object
    pairs: List[Pair] = field(default_factory=list)
    scale: float = 1.0  # largest radius in the query
    intersect: Optional[bool] = None  # disk-disk only
    overlap: object = None  # disk-disk only: length of the common chord (or None)
    coplanar_overlap: bool = False  # disk-disk only: same plane, centres closer than rA+rB

    def __float__(self):
        return float(self.distance)

    def __repr__(self):  # short: pytest --showlocals prints it on failures
        return (
            f"Reference(distance={ctx.nstr(self.distance, 20)}, pairs={len(self.pairs)}, "
            f"scale={self.scale}, intersect={self.intersect})"
        )


# cos and sin of the angle samples, computed once (every circle is sampled at the same angles)
_GRID_COS_SIN = {
    x._mpf_: _lm.mpf_cos_sin(x._mpf_, ctx.prec, _RN) for x in _sample_grid(0, _TWO_PI, CIRCLE_SAMPLES, True)[0]
}


def _feature_scale(target: Round, axis: dict) -> Callable:
    """The zoom's resolution around [a, b]: 1/ZOOM_FRACTION of the scale on which the distance to
    the target can have distinct local minima.  The distance to a circle is smooth on the scale of
    the point's distance rho from the circle's axis (its focal set; the distance to a disk is
    smooth there too, and its kinks at rho = R and on its plane lie within R of the axis), so it
    is max(R, rho) (a lower bound of rho on [a, b] from the samples, rho being 1-Lipschitz): R near
    the round (two crossings of a ring's axis region R apart, the far curve's minima 1.4 R apart),
    coarser far from it (a round 1e-9 the size of the curve is zoomed only where the curve passes
    its axis).  axis: the samples' rho (f records it); None for a point target (R = 0: the
    uniform scan, no zoom)."""
    R = target.radius

    def res(a, b, lh):
        rho = min(axis[a._mpf_], axis[b._mpf_]) - lh / 2
        return max(R, rho) / ZOOM_FRACTION

    return res if R > 0 else None


def _rim_minima(a: Round, target: Round, disk: bool) -> List[LocalMin]:
    rel = [sub(a.center, target.center), scale(a.radius, a.u), scale(a.radius, a.v)]
    g = _Against(rel, target, disk)
    axis = {}

    def f(theta):
        cs = _GRID_COS_SIN.get(theta._mpf_)
        if cs is None:
            cs = _lm.mpf_cos_sin(theta._mpf_, ctx.prec, _RN)
        rho = []
        v = ctx.make_mpf(g.raw((None,) + cs, rho))
        axis[theta._mpf_] = ctx.make_mpf(rho[0])
        return v

    # the rim point moves by a.radius per radian; zoomed where one step is long for the target's
    # features (a huge circle passing a small disk)
    return minimize_1d(
        f,
        0,
        _TWO_PI,
        CIRCLE_SAMPLES,
        periodic=True,
        lipschitz=lambda lo, hi: a.radius,
        resolution=_feature_scale(target, axis),
    )


def _target_point(p, target, disk, scale):
    """The target round's point closest to p, and whether p lies on a circle target's axis
    (within 1e-9 of `scale`: every rim point is then as close, a degenerate pair)."""
    if disk:
        _, q = point_disk(p, target)
        return q, False
    _, q, _ = point_circle(p, target)
    _, a_vec = _local(p, target)
    return q, norm(a_vec) <= mpf("1e-9") * scale


def _pairs_from_rim(a: Round, target: Round, disk: bool, swap: bool) -> List[Pair]:
    out = []
    for m in _rim_minima(a, target, disk):
        p = a.rim_point(m.x)
        q, deg = _target_point(p, target, disk, max(target.radius, a.radius))
        out.append(Pair(m.value, q if swap else p, p if swap else q, m.rise, deg))
    return out


def _scale_of(*radii) -> float:
    return float(max(abs(to_mp(r)) for r in radii))


@stored
def circle_circle(ca, na, ra, cb, nb, rb, formulations: str = "ab") -> Reference:
    """Circle-circle: min over the angle of one circle of the point-circle distance to the other.

    formulations "a": parametrise circle A; "b": parametrise circle B; "ab": both, keep the lower
    (each is complete on its own; both together make near-degenerate cases robust, e.g. a huge
    circle against a tiny one)."""
    A, B = make_round(ca, na, ra), make_round(cb, nb, rb)
    pairs: List[Pair] = []
    if "a" in formulations:
        pairs += _pairs_from_rim(A, B, disk=False, swap=False)
    if "b" in formulations:
        pairs += _pairs_from_rim(B, A, disk=False, swap=True)
    pairs.sort(key=lambda p: p.value)
    return Reference(pairs[0].value, pairs, _scale_of(ra, rb))


@stored
def circle_disk(ca, na, ra, cb, nb, rb) -> Reference:
    """Circle A against disk B: min over A's angle of the closed-form point-disk distance."""
    A, B = make_round(ca, na, ra), make_round(cb, nb, rb)
    pairs = _pairs_from_rim(A, B, disk=True, swap=False)
    return Reference(pairs[0].value, pairs, _scale_of(ra, rb))


def disks_intersect(ca, na, ra, cb, nb, rb):
    """Decide whether two disks share a point; returns (intersect, overlap_length, coplanar).

    Proof.  A disk D with centre C, unit normal N, radius R is D = {x in plane P : |x - C| <= R},
    a convex set of its plane P.  A common point of disks A and B lies in both planes.
      * Planes not parallel (NA x NB != 0): PA and PB meet in the line L = {X0 + s M}, M = NA x NB.
        Since L lies in PA, A cap L = {x in L : |x - CA| <= RA} is the chord [sA-, sA+] (empty when
        the distance hA from CA to L exceeds RA), likewise B cap L.  A cap B = (A cap L) cap
        (B cap L), so the disks meet iff the two chords overlap.
      * Parallel, distinct planes: no common point.
      * Same plane: if |CA - CB| <= RA + RB the point CA + RA (CB - CA)/|CB - CA| (or CA if the
        centres coincide) is within RA of CA and, by the triangle inequality, within RB of CB, so it
        is common; if |CA - CB| > RA + RB no point x can have |x - CA| <= RA and |x - CB| <= RB.
    Parallelism and coplanarity are decided exactly in rational arithmetic on the float inputs;
    the chord computation is done at 50 digits (ambiguous only within ~1e-45 of tangency, where
    the distance is that small anyway).
    """
    fa = [Fraction(float(x)) for x in na]
    fb = [Fraction(float(x)) for x in nb]
    m_exact = (fa[1] * fb[2] - fa[2] * fb[1], fa[2] * fb[0] - fa[0] * fb[2], fa[0] * fb[1] - fa[1] * fb[0])
    if all(c == 0 for c in m_exact):
        dcen = [Fraction(float(y)) - Fraction(float(x)) for x, y in zip(ca, cb)]
        height = sum(n * d for n, d in zip(fa, dcen))
        if height != 0:
            return False, None, False
        sumr = Fraction(float(ra)) + Fraction(float(rb))
        d2 = sum(d * d for d in dcen)
        return d2 <= sumr * sumr, None, d2 < sumr * sumr
    A, B = make_round(ca, na, ra), make_round(cb, nb, rb)
    m = cross(A.n, B.n)
    mm = dot(m, m)
    dA, dB = dot(A.n, A.center), dot(B.n, B.center)
    x0 = scale(1 / mm, add(scale(dA, cross(B.n, m)), scale(dB, cross(m, A.n))))
    chords = []
    for D in (A, B):
        rel = sub(D.center, x0)
        sc = dot(m, rel) / mm
        perp = sub(rel, scale(sc, m))
        h2 = dot(perp, perp)
        r2 = D.radius**2
        if h2 > r2:
            return False, None, False
        half = ctx.sqrt(r2 - h2) / ctx.sqrt(mm)
        chords.append((sc - half, sc + half))
    lo = max(chords[0][0], chords[1][0])
    hi = min(chords[0][1], chords[1][1])
    if lo > hi:
        return False, None, False
    return True, (hi - lo) * ctx.sqrt(mm), False


def disk_disk_rims(ca, na, ra, cb, nb, rb) -> List[Pair]:
    """min(rim(A)-disk(B), rim(B)-disk(A)) as sorted pairs (valid also when the disks meet)."""
    A, B = make_round(ca, na, ra), make_round(cb, nb, rb)
    pairs = _pairs_from_rim(A, B, disk=True, swap=False) + _pairs_from_rim(B, A, disk=True, swap=True)
    pairs.sort(key=lambda p: p.value)
    return pairs


@stored
def disk_disk(ca, na, ra, cb, nb, rb) -> Reference:
    """Disk-disk distance: 0 when they meet (see disks_intersect), else the rim formula.

    Why the rim formula is complete for disjoint disks: let (p, q) be a closest pair, p in A, q in
    B, p != q.  If p is in the relative interior of A, first-order optimality of p for |x - q| over
    A's plane forces q - p to be parallel to NA; likewise q interior to B forces q - p parallel to
    NB.  If both were interior and the normals not parallel, q - p = 0: contradiction.  If the
    normals are parallel, q - p is the plane separation; translating p and q by the same in-plane
    vector keeps |p - q| (the lower bound) until one of them reaches its rim.  So some closest
    pair has p on rim(A) or q on rim(B), i.e. the distance is min over rim(A) of point-disk(B) and
    over rim(B) of point-disk(A), both closed forms minimised over one angle.
    """
    inter, overlap, coplanar = disks_intersect(ca, na, ra, cb, nb, rb)
    scl = _scale_of(ra, rb)
    if inter:
        return Reference(mpf(0), [], scl, True, overlap, coplanar)
    pairs = disk_disk_rims(ca, na, ra, cb, nb, rb)
    return Reference(pairs[0].value, pairs, scl, False, None, False)


def _speed_bound(ctrl) -> Callable:
    """lipschitz(a, b) >= max |B'(t)| over [a, b].  B' = k sum_i b_{i,k-1}(t) (P_{i+1} - P_i) and
    each Bernstein function b_{i,k-1} is unimodal with its peak at i/(k-1), so
    |B'| <= k sum_i |P_{i+1} - P_i| max_[a,b] b_{i,k-1}.  Evaluated in binary64 on [a, b] widened
    by a rounding of each end, the sum enlarged by 1e-9 for the rounding of the terms: an upper
    bound.  (Far tighter than the global k max |P_{i+1} - P_i| near the ends of a curve with a
    far control point, where that bound would keep every interval alive.)"""
    pts = [vec(p) for p in ctrl]
    k = len(pts) - 1
    legs = [float(norm(sub(pts[i + 1], pts[i]))) for i in range(k)]
    if k <= 1:
        speed = (legs[0] if legs else 0.0) * (1 + 1e-9)
        return lambda a, b: speed

    def bound(a, b):
        lo, hi = float(a), float(b)
        lo, hi = lo - 2.3e-16 * abs(lo), hi + 2.3e-16 * abs(hi)
        s = 0.0
        for i, leg in enumerate(legs):
            t = min(max(i / (k - 1), lo), hi)
            s += leg * math.comb(k - 1, i) * t**i * (1 - t) ** (k - 1 - i)
        return mpf(k * s * (1 + 1e-9))

    return bound


def _curve_minima(ctrl, target: Round, disk: bool) -> List[LocalMin]:
    pts = [vec(p) for p in ctrl]
    k = len(pts) - 1
    rel = [sub(p, target.center) for p in pts]
    g = _Against(rel, target, disk)
    axis = {}

    def f(t):
        rho = []
        v = ctx.make_mpf(g.raw(_raw_bernstein(k, t._mpf_), rho))
        axis[t._mpf_] = ctx.make_mpf(rho[0])
        return v

    # zoomed where one step is long for the target's features: a curve far larger than the round
    return minimize_1d(
        f, 0, 1, CURVE_SAMPLES, periodic=False, lipschitz=_speed_bound(ctrl), resolution=_feature_scale(target, axis)
    )


def _bezier_round(ctrl, center, normal, radius, disk: bool) -> Reference:
    T = make_round(center, normal, radius)
    pairs = []
    for m in _curve_minima(ctrl, T, disk):
        p = bezier_point(ctrl, m.x)
        q, deg = _target_point(p, T, disk, T.radius)
        pairs.append(Pair(m.value, p, q, m.rise, deg))
        pairs[-1].t = m.x  # the curve's parameter (as bezier_other's pairs)
    return Reference(pairs[0].value, pairs, _scale_of(radius))


@stored
def bezier_disk(ctrl, center, normal, radius) -> Reference:
    """Bezier B(t), t in [0, 1], against a disk: min over t of the point-disk closed form."""
    return _bezier_round(ctrl, center, normal, radius, disk=True)


@stored
def bezier_circle(ctrl, center, normal, radius) -> Reference:
    """Bezier B(t), t in [0, 1], against a circle: min over t of the point-circle closed form."""
    return _bezier_round(ctrl, center, normal, radius, disk=False)


# ----------------------------------------------------------------------------------------------
# alternative computations, used only to validate the references above
# ----------------------------------------------------------------------------------------------
def segment_circle_alt(p0, p1, center, normal, radius):
    """Segment-circle by the other parametrisation: min over the circle's angle of the
    closed-form point-segment distance."""
    C = make_round(center, normal, radius)
    q0, q1 = vec(p0), vec(p1)
    ms = minimize_1d(lambda th: point_segment(C.rim_point(th), q0, q1), 0, _TWO_PI, CIRCLE_SAMPLES, periodic=True)
    return ms[0].value


def segment_disk_alt(p0, p1, center, normal, radius):
    """Segment-disk without parametrising the segment.

    For a closest pair (p, q): either q is on the rim (min over the rim angle of point-segment),
    or q is interior, then p - q is parallel to N and p minimises |z| over the part of the segment
    whose projection is inside the disk: p is an end point there, or the segment crosses the plane
    inside the disk (distance 0), or the segment is parallel to the plane (constant |z|, and the
    pair can slide to an end point or to the rim)."""
    D = make_round(center, normal, radius)
    q0, q1 = vec(p0), vec(p1)
    best = minimize_1d(lambda th: point_segment(D.rim_point(th), q0, q1), 0, _TWO_PI, CIRCLE_SAMPLES, periodic=True)[
        0
    ].value
    for p in (q0, q1):
        z, a = _local(p, D)
        if norm(a) <= D.radius:
            best = min(best, abs(z))
    z0, _ = _local(q0, D)
    z1, _ = _local(q1, D)
    if (z0 <= 0 <= z1 or z1 <= 0 <= z0) and z0 != z1:
        t = z0 / (z0 - z1)
        x = add(q0, scale(t, sub(q1, q0)))
        _, a = _local(x, D)
        if norm(a) <= D.radius:
            best = mpf(0)
    return best


def expected_unique(ref: Reference, rel: float = 1e-6) -> Optional[bool]:
    """True when the reference shows one clearly isolated closest pair, None when undecided.

    Conditions: the best pair's other point is unique (not on an axis), the distance rises
    around it by more than 1e-9 * scale between samples, and no other local minimum within
    rel * scale of the distance belongs to a different pair."""
    s = mpf(ref.scale)
    if ref.intersect:
        # a common chord of positive length, or two overlapping disks of one plane: a continuum
        if ref.coplanar_overlap or (ref.overlap is not None and ref.overlap > mpf("1e-9") * s):
            return False
        return None
    if not ref.pairs:
        return None
    best = ref.pairs[0]
    if best.degenerate or best.rise <= mpf("1e-9") * s:
        return None
    for p in ref.pairs[1:]:
        if p.value <= best.value + rel * s:
            if dist(p.pa, best.pa) + dist(p.pb, best.pb) > rel * s:
                return None
            if p.degenerate:
                return None
    return True


# ----------------------------------------------------------------------------------------------
# a Bezier curve against a point, line, ray or segment
# ----------------------------------------------------------------------------------------------
def point_linear_closest(p: Vec, kind: str, origin: Vec, other: Vec):
    """(distance, closest point, parameter) from p to a line / ray (origin, direction) or a
    segment (p0, p1): the projection's parameter clamped to the piece's interval (closed form)."""
    d = sub(other, origin) if kind == "segment" else other
    dd = dot(d, d)
    s = mpf(0) if dd == 0 else dot(sub(p, origin), d) / dd
    if kind == "ray":
        s = max(s, mpf(0))
    elif kind == "segment":
        s = min(max(s, mpf(0)), mpf(1))
    q = add(origin, scale(s, d))
    return dist(p, q), q, s


def bezier_other_scale(ctrl, kind: str, *data) -> float:
    """The largest length in a Bezier-point/line/ray/segment query: the control polygon's extent
    (the largest distance of a control point from the first) and a segment's length."""
    pts = [vec(p) for p in ctrl]
    extent = max(float(norm(sub(p, pts[0]))) for p in pts)
    if kind == "segment":
        extent = max(extent, float(dist(vec(data[0]), vec(data[1]))))
    return extent


@stored
def bezier_other(ctrl, kind: str, *data) -> Reference:
    """Bezier B(t), t in [0, 1], against a point (kind "point", data (p,)), a line or ray
    (origin, direction) or a segment (p0, p1): min over t of the closed-form distance from B(t)
    to the other shape (its projection clamped to the piece), by minimize_1d (dense sampling,
    zoomed by the curve's speed bound where a step is long for the distance there, and golden
    section on every sampled local minimum).  `scale` is the largest length in the query: the
    control polygon's extent (and a segment's length)."""
    pts = [vec(p) for p in ctrl]
    k = len(pts) - 1
    if kind == "point":
        target = vec(data[0])

        def closest(x):
            return dist(x, target), target, mpf(0)
    else:
        origin, other = vec(data[0]), vec(data[1])

        def closest(x):
            return point_linear_closest(x, kind, origin, other)

    def f(t):
        return closest(bezier_point(pts, t))[0]

    extent = bezier_other_scale(ctrl, kind, *data)
    size = max(extent, 1e-300)

    def resolution(a, b, lh):
        # local minima of the distance to a point or line lie apart by at least about the
        # distance itself (the focal set): resolve to that, or 1e-4 of the query's size
        fa, fb = f_cache.get(a._mpf_, mpf(size)), f_cache.get(b._mpf_, mpf(size))
        if fa == 0 or fb == 0:  # an exact zero sampled (a curve along the line): nothing is lower
            return ctx.inf
        return max(min(fa, fb) - lh / 2, mpf(size) * mpf("1e-4")) / ZOOM_FRACTION

    f_cache = {}

    def fc(t):
        v = f(t)
        f_cache[t._mpf_] = v
        return v

    if k == 0:
        ms = [LocalMin(fc(mpf(0)), mpf(0), mpf(0))]
    else:
        ms = minimize_1d(fc, 0, 1, CURVE_SAMPLES, periodic=False, lipschitz=_speed_bound(ctrl), resolution=resolution)
    pairs = []
    for m in ms:
        pa = bezier_point(pts, m.x)
        v, pb, s = closest(pa)
        pairs.append(Pair(m.value, pa, pb, m.rise, False))
        pairs[-1].t = m.x
        pairs[-1].s = s
    pairs.sort(key=lambda q: q.value)
    return Reference(pairs[0].value, pairs, extent)
