"""Differential accuracy testing of circledist (issue 14, "keep it closed"): a library module.

Nothing here is a test; tests/test_differential.py (the CI slice) and tools/differential.py (the
long mode, ``python -m tools.differential``) drive it.  Three parts:

1. Case families.  ``generate(family, n, seed)`` returns ``n`` JSON-able cases
   ``{"family", "id", "a", "a_data", "b", "b_data"}`` (kind names and plain floats; a Bezier's
   data is a list of [x, y, z] control points) for the kind pairs the family applies to, cycling
   through them.  Pairs are written in a canonical order (point/line/ray/segment/bezier before
   circle/disk, circle before disk; among linear pieces point, line, ray, segment in that order;
   a Bezier curve before a linear piece); the checker runs both argument orders.  ``FAMILIES``
   lists them: plain random cases and the adversarial ones of issue 14 (tangencies, lines on and
   near the axis, lines whose shadow on the plane crosses the centre, coplanar and (nearly)
   concentric rounds, far-translated scenes, far line origins, extreme radius ratios, nearly
   touching disks, a circle parallel to a disk at tiny heights,
   large / far-controlled / in-plane Bezier curves, a huge circle passing a small disk); then
   the families of the pairs without a round, every pair among point/line/ray/segment and a
   Bezier curve against each (random, far-translated, nearly parallel pieces crossing or a hair
   apart or collinear, far origins and ends, zero-length segments, points and ends on the other
   piece, a line tangent to a curve or parallel to its end tangent, a curve crossing a piece,
   curves with a far control point or 1e2..1e5 times larger than the piece).  Arcs (issue 19):
   an arc against a point, line, ray, segment, circle, disk or arc, the arc second (after the
   other kind, as a circle or disk comes after the pieces; ARC_PAIRS), in the "arc_" families:
   the circle families applied to arcs (_arc_variant: the base family's case with the arcs drawn
   as circles, each then cut to an arc whose span is placed relative to the circle's point
   nearest the other shape or the other round's axis -- an end exactly there or 1e-16..1e-6 rad
   beside it, the point inside the span, or beyond both ends), and the arcs' own: ends at the
   features (arc_ends), a round's axis through an arc end (arc_end_on_axis), concentric coplanar
   spans overlapping, disjoint or touching at an end (arc_spans), tiny angles, 2 pi - tiny and
   2 pi exactly (arc_angles).  Annuli (issue 19): an annulus against every kind, the annulus
   second (ANN_PAIRS; an annulus's data is centre, normal, OUTER radius, inner radius), in the
   "ann_" families: the disk families applied to annuli (_ann_variant: the base family's case
   with its annuli drawn as disks, each then holed -- inner radius 0, equal to the outer, 1e-9
   or 1e-9..1e-6 of it, a dyadic quarter / half / three quarters in exact frames, or any
   fraction -- and its arcs cut from circles as above; ann_axis is a line through the hole along
   or near the axis), and the annuli's own: pieces in the hole, coplanar or lifted 1e-9..1e-3
   (ann_hole: points, short segments inside the inner rim, lines through the hole, curves,
   circles, arcs, disks and annuli inside it, up to 1e-12 short of touching), coplanar rounds
   and annuli over the ring (ann_overlap), inner 0 / = outer / 1e-9 x outer (ann_degenerate;
   inner 0 must answer as the disk and inner = outer as the circle, to the bit, distance,
   points, parameters and `unique`: _check_hole), a
   piece tangent to or 1e-16..1e-4 off the inner rim (ann_inner_tangent), far-translated scenes
   (ann_far_translated).  The effect family (EFFECT_FAMILIES: effect_degenerate, every kind pair):
   small integer configurations with a center on the other's axis (either way), coaxial,
   coplanar, concentric, radius 0, inner radius 0 or = outer, where within()'s cheap bounds meet
   degenerate frames; besides every check below, check_effects_definition holds each effect to
   its definition on the library's own distance at several limits, swept too, and through the
   Scene's within and pairs_within.

2. The fast screen (``screen``): an independent one-parameter minimisation in NumPy.  Every
   distance is the minimum over one parameter of a closed form (point-circle, point-disk,
   point-line; point-arc: the circle's where the angle of the point's projection lies in the
   span, else the nearer end's): a circle's angle against the other shape (both ways round for
   two rounds), a line's parameter against the round and the round's angle against the line, an
   arc's angle over [0, angle] wherever a circle's runs over [0, 2 pi) and the arc's closed form
   wherever a round's is the target; an annulus as a target: the point-annulus closed form (|z|
   over the ring, the inner rim's distance over the hole, the outer's beyond), and as a moving
   shape both its rims (its inner rim is one more form: against a region, the rims of each
   region against the other's closed form are exact, see reference_annulus's docstring; against
   a curve the other's parameter against the closed form is exact, the rims only add genuine
   pairs), a Bezier curve's t against the round (each half from its
   own end, so parameters near an end keep their full precision).  Dense sampling, then a
   vectorised beam search (nested re-sampling around the
   best few sampled local minima) in float64, then long-double levels around the best.  Where
   the sampling step is long for the target round's features (a curve or a huge circle passing a
   much smaller round) a Lipschitz zoom (``_zoom``: hodograph or radius bounds on the point's
   speed) re-samples every interval that could hold a value below the best sample until a step
   moves the point by at most max(R, rho)/8 (rho: distance from the round's axis), and EVERY
   sampled local minimum it leaves is refined in long double on its own, the least kept: two
   near-tied minima (5.9e-13 apart on a curve 2e4 long, below float64's resolution there) are
   both refined, not one chosen by a float64 ranking.  Bezier curves' long-double stage works
   on pieces around each candidate whose control points are computed in double-double (a curve
   1e5 times larger than the round is resolved to ~1e-19 of the round).  Coordinates are taken relative to the round's centre;
   offsets between inputs (B - C, p1 - p0, P_i - C) and the anchoring of a line at its point
   nearest the centre are computed in double-double, so far-translated scenes and far line
   origins lose nothing.  Every value is the distance between two genuine points (up to the
   long-double rounding reported as ``slack``), hence an UPPER bound of the true distance.  The
   screen is a sampling method, not a proof: its misses show up as alarms the 50-digit
   reference refutes (counted as "refuted", never as findings).
   Pairs without a round: a linear piece's parameter against the other piece's closed form (the
   projection clamped; inside the other piece the parts perpendicular to it, in double-double),
   s = S0 sinh(x) over every magnitude of s, in long double, re-anchored pass by pass at the
   best point found (``_screen_linear``); a Bezier curve's halves against the
   piece's closed form, as against a round (``_screen_bezier_linear``); a point: the closed form.

3. The checker (``check_cases``): for every (solver, precision) combination and both argument
   orders it calls distance, closest_points, within, distance_if_within and intersects, batched
   and (for the chosen cases) scalar, and reports findings: answers above the screen's bound or
   below every verified bound (beyond the bar), closest points off their shapes, separations
   that differ from the reported distance, distance(a, b) != distance(b, a), batch != scalar,
   within / intersects inconsistent with the distance, non-finite answers or wrong dtypes, and
   an arc of angle 2 pi whose answers are not its circle's to the bit (distance, points,
   `unique`, the other side's parameter; docs/arc.md), and an annulus of inner 0 / inner = outer
   whose are not its disk's / circle's (docs/annulus.md).
   The bound an answer is held against is the screen's, or lower: the separation (plus the
   measured distances off their shapes) of any combination's closest points, a genuine pair too.
   ``confirm`` re-judges an accuracy finding against the 50-digit mpmath references of
   circledist_cases/reference.py, reference_round.py (Bezier curves, also against linear pieces:
   bezier_other), reference_arc.py (arcs: the arc's angle against the other's closed form) and
   reference_linear.py (linear pieces among themselves: the search of
   tests/test_linear_accuracy.py), reference_annulus.py (annuli: the other shape's parameter
   against the point-annulus closed form, rim by rim for regions), and evaluates the screen's own
   best pair at 50 digits, so a reference that missed the minimum is caught, not trusted.
   closest_points().unique is checked against an independent rule (expected_unique, the comment
   above it gives it in full) on every kind pair: it must be False where the inputs are exactly
   (rational arithmetic on the given floats) a configuration with a continuum of closest pairs
   by symmetry -- a point, line, ray or segment on the axis of a circle, an arc or an annulus
   with a hole; two coaxial shapes among circle, disk, annulus and arc (not two arcs) -- and True
   where a closed form or strict convexity proves one closest pair with a margin of 1e-6 (a
   point against a point, a linear piece or a disk; a point against a circle, an arc or an
   annulus, its nearest candidate better than the others by 1e-6 x max(d, R); two linear pieces
   at least 1e-3 rad from parallel).  Elsewhere (curve pairs, near-continua that rounding breaks)
   it is not checked by the screen-driven checker; the direct 50-digit comparison
   (reference_check, the CI slice's first case of each family and pair) adds True where the
   reference's own local minima show it for a circle or arc against a convex shape (line, ray,
   segment, disk: reference_unique -- a single strict minimum over the rim's angle, every other
   distinct local minimum worse by 1e-6 x max(d, R), not flat within 1e-4 rad).

Bars: |d - d_true| <= bar * max(d_true, scale), the scale being the largest radius (circle, disk
or arc) in the query
(for a query without a circle or disk: the scale of the pairs' own accuracy tests, see
``bar_scale``: for the linear pairs 1e-12 x the query's size), bar 1e-12 in float64,
1e-15 in long double (float64 inputs referenced exactly), 4 float32 ulps (4 * 2^-23) for float32
inputs (README: float32 queries are solved in double and rounded; referenced on the float32
values).  Closest points must lie on their shapes within 8 ulps (of the answer's precision) of
the scene scale (the largest input coordinate or radius; for a query without a round, of the
points' own size where that is larger: nearly parallel lines meet far outside the scene), and
their separation must equal the reported distance within the bar plus those ulps.
"""

from __future__ import annotations

import collections
import importlib
import math
from fractions import Fraction

import numpy as np

SOLVERS = ("bracketing", "companion", "polished", "eigen")
PRECISIONS = ("float64", "longdouble", "float32")
EPS32 = float(np.finfo(np.float32).eps)
EPS64 = float(np.finfo(np.float64).eps)
EPSLD = float(np.finfo(np.longdouble).eps)
BARS = {"float64": 1e-12, "longdouble": 1e-15, "float32": 4 * EPS32}
OUT_EPS = {"float64": EPS64, "longdouble": EPSLD, "float32": EPS32}
ULPS = 8          # closest points: ulps of the scene scale allowed off their shapes
LINEAR = ("point", "line", "ray", "segment")
ROUND = ("circle", "disk")
# kinds with a radius: the rounds and arcs (an arc is a circle restricted to an angle interval;
# its data: centre, normal, radius, start, angle -- 11 numbers)
RIMS = ROUND + ("arc", "annulus")
# an annulus's data: centre, normal, OUTER radius, inner radius (8 numbers: the outer radius at
# index 6, where a round's radius is, so scales, translations and frames read it alike); the
# library's constructor takes (centre, normal, inner, outer)
TARGET_REGION = ("disk", "annulus")   # closed forms with a face (a disk's |z|, an annulus's too)
# the pairs with a circle or disk (the families of the first version), then the pairs among
# points, lines, rays and segments (point before line before ray before segment) and a Bezier
# curve against each of them (the curve first)
ROUND_PAIRS = [(lk, rk) for lk in LINEAR for rk in ROUND] + [
    ("bezier", "circle"), ("bezier", "disk"), ("circle", "circle"), ("circle", "disk"), ("disk", "disk")]
LL = [(lk, rk) for i, lk in enumerate(LINEAR) for rk in LINEAR[i:]]
BL = [("bezier", lk) for lk in LINEAR]
# an arc against every kind with a query, the arc second (as a circle or disk comes after the
# pieces, and arc after disk), a Bezier curve too (after "segment", since Arc-Bezier has its query,
# bezier_arc.hpp): the screen, the families (_arc_variant, _feature), the reference
# (reference_arc.bezier_arc) and the checker take it as they are.  (Adding a pair re-maps the
# arc families' case ids: case i is pair i mod the number of pairs.)
ARC_OTHERS = ("point", "line", "ray", "segment", "bezier", "circle", "disk", "arc")
ARC_PAIRS = [(k, "arc") for k in ARC_OTHERS]
ARC_RR = [p for p in ARC_PAIRS if p[0] in ("circle", "disk", "arc")]   # a circle, disk or arc against an arc
# an annulus against every kind (issue 19), the annulus second (after the arc, and after another
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
    """A reference module of this package (reference, reference_round), imported on first use:
    mpmath is needed only to confirm findings."""
    return importlib.import_module(f"{__package__}.{name}")


# =============================================================================================
# 1. case families
# =============================================================================================
def _unit(rng):
    v = rng.normal(size=3)
    return v / np.linalg.norm(v)


def _perp(rng, n):
    """A random unit vector orthogonal to the unit vector n."""
    v = rng.normal(size=3)
    v = v - np.dot(v, n) * n
    return v / np.linalg.norm(v)


def _rot(v, axis, angle):
    """v rotated about the unit axis by angle (Rodrigues)."""
    v, axis = np.asarray(v, float), np.asarray(axis, float)
    return (v * math.cos(angle) + np.cross(axis, v) * math.sin(angle)
            + axis * np.dot(axis, v) * (1 - math.cos(angle)))


def _logu(rng, lo, hi):
    return float(10 ** rng.uniform(lo, hi))


def _tiny(rng, lo=-16, hi=-4, zero=0.3):
    """0 with probability `zero`, else +-10^U(lo, hi)."""
    if rng.random() < zero:
        return 0.0
    return float(rng.choice([-1.0, 1.0])) * _logu(rng, lo, hi)


EZ = np.array([0.0, 0.0, 1.0])


class _Frame:
    """Local coordinates (x, y, z) -> world C + x U + y V + z N.  Exact frames are signed axis
    permutations with dyadic centres (so special geometry stays exact in binary64); the others are
    random rotations (special geometry then holds up to rounding)."""

    def __init__(self, rng, exact=None, scale=1.0):
        self.rng = rng
        self.exact = bool(rng.random() < 0.5) if exact is None else exact
        if self.exact:
            perm = rng.permutation(3)
            signs = rng.choice([-1.0, 1.0], 3)
            M = np.zeros((3, 3))
            M[np.arange(3), perm] = signs
            self.Q = M.T                       # columns U, V, N
            self.C = rng.integers(-8, 9, 3) / 4.0 * scale
            self.nlen = 2.0 ** int(rng.integers(-3, 4))
        else:
            Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
            self.Q = Q
            self.C = rng.normal(size=3) * scale
            self.nlen = _logu(rng, -1, 1)

    def pos(self, p):
        return [float(x) for x in self.C + self.Q @ np.asarray(p, float)]

    def dirv(self, d, length=1.0):
        return [float(x) for x in (self.Q @ np.asarray(d, float)) * length]

    def dlen(self):
        return 2.0 ** int(self.rng.integers(-2, 3)) if self.exact else _logu(self.rng, -1, 1)

    def param(self, lo, hi):
        """A scalar in [lo, hi]: dyadic in exact frames."""
        if self.exact:
            return float(self.rng.integers(int(lo * 8), int(hi * 8) + 1)) / 8.0
        return float(self.rng.uniform(lo, hi))

    def round(self, c, n, r):
        return self.pos(c) + self.dirv(np.asarray(n, float) / np.linalg.norm(n), self.nlen) + [float(r)]

    def linear(self, kind, X, d, spread):
        """A point/line/ray/segment through the local point X with local unit direction d."""
        X, d = np.asarray(X, float), np.asarray(d, float)
        if kind == "point":
            return self.pos(X)
        if kind == "line":
            o = X + self.param(-2, 2) * spread * d
            return self.pos(o) + self.dirv(d, self.dlen())
        if kind == "ray":
            o = X - self.param(-0.5, 3) * spread * d
            return self.pos(o) + self.dirv(d, self.dlen())
        s0, s1 = self.param(-0.5, 3) * spread, self.param(-0.5, 3) * spread
        return self.pos(X - s0 * d) + self.pos(X + s1 * d)

    def bezier(self, ctrl):
        return [self.pos(p) for p in ctrl]


def _radius(rng, exact):
    return float(rng.choice([0.5, 0.75, 1.0, 1.5, 2.0])) if exact else _logu(rng, -0.5, 0.5)


def _in_plane(rng, exact, r=1.0):
    """(radial, tangent) in-plane unit vectors at a random (exact: axis) angle."""
    th = 0.0 if exact else rng.uniform(0, 2 * math.pi)
    return np.array([math.cos(th), math.sin(th), 0.0]), np.array([-math.sin(th), math.cos(th), 0.0])


def _elevate(ctrl, k_total):
    """Degree elevation of a Bezier control polygon to k_total control points (same curve up to
    rounding)."""
    P = [np.asarray(p, float) for p in ctrl]
    while len(P) < k_total:
        k = len(P)        # degree k-1 -> k
        Q = [P[0]]
        for i in range(1, k):
            Q.append(i / k * P[i - 1] + (1 - i / k) * P[i])
        Q.append(P[-1])
        P = Q
    return P


def _bezier_through(rng, X, size, npts, t0=None):
    """Random control points of extent `size` around X, shifted so that B(t0) = X."""
    P = [X + size * rng.normal(size=3) for _ in range(npts)]
    t0 = rng.uniform(0.1, 0.9) if t0 is None else t0
    k = npts - 1
    B = sum(math.comb(k, i) * t0 ** i * (1 - t0) ** (k - i) * P[i] for i in range(npts))
    return [p + (X - B) for p in P]


def _npts(rng):
    return int(rng.integers(2, 9))


# ---- round-round helpers (local frame of the first round: centre 0, normal +z) -------------
def _tangent_round(rng, Ra, Rb, exact, phi=None):
    """(centre, normal) of a round of radius Rb whose rim touches A's rim (centre 0, normal z,
    radius Ra) at one point with a common tangent; phi = 0 internal coplanar, pi external
    coplanar, pi/2 standing on the rim."""
    r, t = _in_plane(rng, exact)
    X = Ra * r
    if phi is None:
        phi = float(rng.choice([0.0, math.pi, math.pi / 2, rng.uniform(0, 2 * math.pi)]))
    w = math.cos(phi) * (-r) + math.sin(phi) * EZ
    return X + Rb * w, np.cross(t, w), w


# ---- families --------------------------------------------------------------------------------
def _fam_random(rng, ka, kb):
    fr = _Frame(rng, exact=False)
    Rb = _radius(rng, False)
    b = fr.round(np.zeros(3), EZ, Rb)
    if ka in ROUND:
        Ra = _radius(rng, False)
        a = fr.round(rng.normal(size=3) * 0.75 * (Ra + Rb), _unit(rng), Ra)
    elif ka == "bezier":
        a = fr.bezier([rng.normal(size=3) * 1.5 * Rb for _ in range(_npts(rng))])
    else:
        a = fr.linear(ka, rng.normal(size=3) * 1.5 * Rb, _unit(rng), Rb)
    return a, b


def _fam_tangent(rng, ka, kb):
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    if ka in ROUND:
        Ra = _radius(rng, ex)
        h = _tiny(rng, -16, -6) * max(Ra, Rb)
        mode = int(rng.integers(0, 3 if "disk" in (ka, kb) else 2))
        if mode == 2:
            # a rim touching the disk's face at an interior point (the disk is local, centre 0)
            disk_is_b = kb == "disk"
            Rd, Rr = (Rb, Ra) if disk_is_b else (Ra, Rb)
            r, t = _in_plane(rng, ex)
            P = r * Rd * fr.param(0, 0.875)
            e = _perp(rng, EZ) if not ex else np.array([1.0, 0.0, 0.0])
            c, n = P + (Rr + abs(h)) * EZ, np.cross(EZ, e)
            other = fr.round(c, n, Rr)
            disk = fr.round(np.zeros(3), EZ, Rd)
            return (other, disk) if disk_is_b else (disk, other)
        c, n, w = _tangent_round(rng, Ra, Rb, ex)
        return fr.round(np.zeros(3), EZ, Ra), fr.round(c + h * w, n, Rb)
    b = fr.round(np.zeros(3), EZ, Rb)
    r, t = _in_plane(rng, ex)
    X = Rb * r
    h = _tiny(rng) * Rb
    mode = int(rng.integers(0, 4 if kb == "disk" else 3))
    if ka == "point":
        return fr.pos(X + h * (_unit(rng) if not ex else r)), b
    if mode == 0:                               # in-plane tangent, moved radially by h
        X, d = X + h * r, t
    elif mode == 1:                             # tangent, lifted by |h|
        X, d = X + abs(h) * EZ, t
    elif mode == 2:                             # through the rim point, orthogonal to the radius
        psi = rng.uniform(0.1, 1.4)
        X, d = X + h * r, math.cos(psi) * t + math.sin(psi) * EZ
    else:                                       # touching the disk's face from above
        X = r * Rb * fr.param(0, 0.875) + abs(h) * EZ
        d = t
    if ka == "bezier":
        npts = max(3, _npts(rng))
        L = Rb * rng.uniform(0.3, 2)
        away = EZ if mode in (1, 3) else (r if mode != 2 else r)
        delta = away * Rb * rng.uniform(0.05, 1)
        ctrl = _elevate([X - L * d + delta, X - delta, X + L * d + delta], npts)
        return fr.bezier(ctrl), b
    return fr.linear(ka, X, d, Rb), b


_RHO_CHOICES = ("zero", "R", "R(1+e)", "inside", "outside", "tiny", "huge")


def _fam_axis(rng, ka, kb):
    """Lines, rays, segments on and nearly parallel to the axis (tilt 0 or 1e-16..1e-10 rad), at
    any offset from the axis, including exactly at the radius; points on / near the axis."""
    fr = _Frame(rng)
    ex = fr.exact
    R = _radius(rng, ex)
    b = fr.round(np.zeros(3), EZ, R)
    kind = rng.choice(_RHO_CHOICES)
    rho = {"zero": 0.0, "R": R, "R(1+e)": R * (1 + _tiny(rng, -16, -8, 0)),
           "inside": R * rng.uniform(0, 1), "outside": R * rng.uniform(1, 3),
           "tiny": R * _logu(rng, -12, -3), "huge": R * _logu(rng, 0, 3)}[kind]
    beta = 0.0 if ex else rng.uniform(0, 2 * math.pi)
    X = np.array([rho * math.cos(beta), rho * math.sin(beta), 0.0])
    if ka == "point":
        return fr.pos(X + fr.param(-2, 2) * R * EZ), b
    psi = 0.0 if rng.random() < 0.35 else _logu(rng, -16, -10)
    alpha = 0.0 if ex else rng.uniform(0, 2 * math.pi)
    d = np.array([math.sin(psi) * math.cos(alpha), math.sin(psi) * math.sin(alpha), math.cos(psi)])
    if rng.random() < 0.5:
        d = -d
    return fr.linear(ka, X, d, R), b



def _fam_shadow_center(rng, ka, kb):
    """Lines, rays and segments whose shadow on the round's plane crosses the centre (exactly, or
    1e-16..1e-12 radii beside it), tilted from the plane by 1e-4..1 rad, at heights 1e-6..2
    radii: the line's distance then has a second local minimum over the ring, mirroring the
    global one, which rays and segments starting between the two hold (a ray from within a
    radius of the centre's shadow, toward it or away)."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    b = fr.round(np.zeros(3), EZ, R)
    alpha = 0.0 if fr.exact else rng.uniform(0, 2 * math.pi)
    psi = _logu(rng, -4, 0) * float(rng.choice([-1.0, 1.0]))
    along = np.array([math.cos(alpha), math.sin(alpha), 0.0])
    across = np.array([-math.sin(alpha), math.cos(alpha), 0.0])
    d = math.cos(psi) * along + math.sin(psi) * EZ
    height = R * (rng.uniform(0.1, 2) if rng.random() < 0.7 else _logu(rng, -6, -1))
    X = height * EZ + _tiny(rng, -16, -12, 0.6) * R * across + fr.param(-1, 1) * R * d
    if rng.random() < 0.5:
        d = -d
    return fr.linear(ka, X, d, R / 4), b


def _fam_piece_near_plane(rng, ka, kb):
    """Lines, rays and segments nearly in the round's plane: at heights 1e-12..1e-6 radii,
    parallel to it or tilted by up to 1e-9. The line's minimum over the ring is then nearly tied
    with its mirror image, where closest_points takes its pair from the general path and must
    keep distance()'s value (7112 of 50,000 such segments disagreed by 1-2 ulps before)."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    b = fr.round(np.zeros(3), EZ, R)
    r, t = _in_plane(rng, fr.exact)
    height = _logu(rng, -12, -6) * R * float(rng.choice([-1.0, 1.0]))
    X = r * fr.param(0, 2) * R + height * EZ
    d = t + _tiny(rng, -12, -9, 0.5) * EZ
    return fr.linear(ka, X, d / np.linalg.norm(d), R), b


def _fam_coplanar(rng, ka, kb):
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    b = fr.round(np.zeros(3), EZ, Rb)
    r, t = _in_plane(rng, ex)
    if ka in ROUND:
        Ra = Rb * float(rng.choice([1.0, 0.5, 2.0])) if ex else Rb * rng.uniform(0.1, 3)
        c = r * fr.param(0, 1.5) * (Ra + Rb)
        n = EZ * float(rng.choice([-1.0, 1.0]))
        return fr.round(c, n, Ra), b
    X = r * fr.param(0, 2) * Rb
    if ka == "bezier":
        ctrl = [np.array([*(rng.normal(size=2) * 1.5 * Rb), 0.0]) for _ in range(_npts(rng))]
        return fr.bezier(ctrl), b
    return fr.linear(ka, X, t if rng.random() < 0.5 else _perp(rng, EZ), Rb), b


def _tilted_normal(rng, exact):
    psi = float(rng.choice([0.0, 1e-9, _logu(rng, -12, -1), rng.uniform(0, math.pi / 2), math.pi / 2]))
    axis = np.array([1.0, 0.0, 0.0]) if exact else _perp(rng, EZ)
    return _rot(EZ, axis, psi), psi


def _fam_concentric(rng, ka, kb, offset=0.0):
    fr = _Frame(rng)
    ex = fr.exact and offset == 0.0
    Rb = _radius(rng, ex)
    b = fr.round(np.zeros(3), EZ, Rb)
    off = offset * Rb * _unit(rng)
    if ka in ROUND:
        n, _ = _tilted_normal(rng, ex)
        Ra = Rb * float(rng.choice([1.0, 1.0 + _tiny(rng, -15, -6, 0), rng.uniform(0.2, 3)]))
        return fr.round(off, n, Ra), b
    if ka == "point":
        if not offset:
            off = np.zeros(3) if rng.random() < 0.7 else _tiny(rng, -15, -6, 0) * Rb * _unit(rng)
        return fr.pos(off), b
    if ka == "bezier":
        npts = _npts(rng)
        half = [rng.normal(size=3) * Rb for _ in range((npts + 1) // 2)]
        ctrl = half[: npts // 2] + ([np.zeros(3)] if npts % 2 else []) + [-p for p in reversed(half[: npts // 2])]
        return fr.bezier([p + off for p in ctrl]), b
    n, psi = _tilted_normal(rng, ex)
    d = _rot(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]), -psi) if ex else \
        math.cos(psi) * _perp(rng, EZ) + math.sin(psi) * EZ
    d = d / np.linalg.norm(d)
    return fr.linear(ka, off - np.dot(off, d) * d, d, Rb), b


def _fam_near_concentric(rng, ka, kb):
    return _fam_concentric(rng, ka, kb, offset=_logu(rng, -15, -6))


def _translate(kind, data, T):
    if kind == "bezier":
        return [[float(x) for x in np.asarray(p) + T] for p in data]
    data = list(data)
    npos = {"point": 3, "line": 3, "ray": 3, "segment": 6, "circle": 3, "disk": 3, "arc": 3, "annulus": 3}[kind]
    for i in range(npos):
        data[i] = float(data[i] + T[i % 3])
    return data


_TRANSLATED_BASES = ("random", "tangent", "coplanar", "concentric", "axis", "near_touching", "parallel_height")


def _fam_far_translated(rng, ka, kb, bases=_TRANSLATED_BASES):
    bases = [f for f in bases if (ka, kb) in FAMILIES[f][0]]
    base = str(rng.choice(bases))
    a, b = FAMILIES[base][1](rng, ka, kb)
    if rng.random() < 0.3:
        T = np.zeros(3)
        T[rng.integers(0, 3)] = float(rng.choice([-1.0, 1.0])) * _logu(rng, 6, 12)
    else:
        T = _unit(rng) * _logu(rng, 6, 12)
    return _translate(ka, a, T), _translate(kb, b, T)


def _interesting_line(rng, fr, R, kb):
    """A local (X, d) near the round: random, tangent, near the axis or in the plane."""
    mode = int(rng.integers(0, 4))
    r, t = _in_plane(rng, fr.exact)
    if mode == 0:
        return rng.normal(size=3) * R, _unit(rng)
    if mode == 1:
        return R * r + _tiny(rng) * R * r, t
    if mode == 2:
        psi = 0.0 if rng.random() < 0.3 else _logu(rng, -16, -10)
        return r * R * float(rng.choice([0.0, 1.0, rng.uniform(0, 2)])), _rot(EZ, t, psi)
    return r * R * rng.uniform(0, 2), _perp(rng, EZ)


def _fam_far_origin(rng, ka, kb):
    """Line origins / segment ends 1e6..1e12 radii along the line."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    b = fr.round(np.zeros(3), EZ, R)
    X, d = _interesting_line(rng, fr, R, kb)
    return _far_piece(rng, fr, ka, X, d, R), b


def _far_piece(rng, fr, kind, X, d, R):
    """A line, ray or segment through the local point X along d whose origin / one end (or both)
    lies 1e6..1e12 x R along it; a point stays at X."""
    if kind == "point":
        return fr.pos(X)
    d = d / np.linalg.norm(d)
    far = _logu(rng, 6, 12) * R
    sgn = float(rng.choice([-1.0, 1.0]))
    if kind == "line":
        return fr.pos(X - sgn * far * d) + fr.dirv(d, fr.dlen())
    if kind == "ray":
        if rng.random() < 0.8:
            return fr.pos(X - far * d) + fr.dirv(d, fr.dlen())
        return fr.pos(X + far * d) + fr.dirv(d, fr.dlen())
    far2 = _logu(rng, 6, 12) * R if rng.random() < 0.5 else rng.uniform(-0.5, 2) * R
    ends = [fr.pos(X - far * d), fr.pos(X + far2 * d)]
    if rng.random() < 0.5:
        ends.reverse()
    return ends[0] + ends[1]


def _fam_radius_ratio(rng, ka, kb):
    """Extreme radius ratios: 1e-9 and 1e9."""
    fr = _Frame(rng, exact=False)
    ratio = float(rng.choice([1e-9, 1e9]))
    if ka in ROUND:
        Ra = _logu(rng, -0.5, 0.5)
        Rb = Ra * ratio * (1.0 if rng.random() < 0.5 else rng.uniform(0.5, 2))
        big, small = max(Ra, Rb), min(Ra, Rb)
        mode = int(rng.integers(0, 3))
        nb = _unit(rng)
        if mode == 0:       # the small one near the big one's rim
            if Rb > Ra:
                u = _perp(rng, nb)
                cb = -Rb * u + small * rng.normal(size=3) * 2
            else:
                r, _ = _in_plane(rng, False)
                cb = Ra * r + small * rng.normal(size=3) * 2
        elif mode == 1:     # near the big one's centre
            cb = small * rng.normal(size=3) * 2
        else:               # anywhere at the big one's scale
            cb = big * rng.normal(size=3)
        return fr.round(np.zeros(3), EZ, Ra), fr.round(cb, nb, Rb)
    R = ratio * (1.0 if rng.random() < 0.5 else rng.uniform(0.5, 2))
    scale = R if rng.random() < 0.5 else 1.0
    b = fr.round(np.zeros(3), EZ, R)
    if ka == "bezier":
        return fr.bezier([rng.normal(size=3) * 1.5 * scale for _ in range(_npts(rng))]), b
    return fr.linear(ka, rng.normal(size=3) * scale, _unit(rng), scale), b


def _fam_near_touching(rng, ka, kb):
    """Rounds nearly touching: gap 1e-14..1e-9 x radius."""
    fr = _Frame(rng)
    ex = fr.exact
    Ra, Rb = _radius(rng, ex), _radius(rng, ex)
    g = _logu(rng, -14, -9) * max(Ra, Rb)
    modes = ["coplanar", "rims"] + (["face", "parallel"] if "disk" in (ka, kb) else [])
    mode = str(rng.choice(modes))
    A = fr.round(np.zeros(3), EZ, Ra)
    r, t = _in_plane(rng, ex)
    if mode == "coplanar":
        return A, fr.round((Ra + Rb + g) * r, EZ * float(rng.choice([-1.0, 1.0])), Rb)
    if mode == "rims":
        c, n, w = _tangent_round(rng, Ra, Rb, ex, phi=float(rng.choice([math.pi, math.pi / 2, rng.uniform(0.3, 5.9)])))
        return A, fr.round(c + g * w, n, Rb)
    disk_is_b = kb == "disk"
    Rd, Rr = (Rb, Ra) if disk_is_b else (Ra, Rb)
    D = fr.round(np.zeros(3), EZ, Rd)
    if mode == "face":
        P = r * Rd * fr.param(0, 0.875)
        e = np.array([1.0, 0.0, 0.0]) if ex else _perp(rng, EZ)
        O = fr.round(P + (Rr + g) * EZ, np.cross(EZ, e), Rr)
    else:
        c = r * (Rd + Rr) * fr.param(0, 0.875) + g * EZ
        O = fr.round(c, EZ, Rr)
    return (O, D) if disk_is_b else (D, O)


def _fam_parallel_height(rng, ka, kb):
    """A circle (or disk) parallel to a disk (or circle) at heights 0 or 1e-16..1e-6."""
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    B = fr.round(np.zeros(3), EZ, Rb)
    Ra = Rb * float(rng.choice([rng.uniform(0.1, 0.9), 1.0, 1.0 + _tiny(rng, -15, -6, 0), rng.uniform(1.1, 3)]))
    h = _tiny(rng, -16, -6, 0.15) * Rb
    r, _ = _in_plane(rng, ex)
    where = rng.choice(["centre", "inside", "rim", "outside"])
    off = {"centre": 0.0, "inside": rng.uniform(0, 1) * abs(Rb - Ra),
           "rim": Rb + rng.choice([-1.0, 1.0]) * Ra + _tiny(rng, -14, -6) * Rb,
           "outside": Rb + Ra + rng.uniform(0, 2) * Rb}[where]
    n = EZ * float(rng.choice([-1.0, 1.0]))
    return fr.round(off * r + h * EZ, n, Ra), B


def _fam_bezier_large(rng, ka, kb):
    """Bezier curves 1e2..1e5 times larger than the round, passing near it."""
    fr = _Frame(rng, exact=False)
    R = _radius(rng, False)
    b = fr.round(np.zeros(3), EZ, R)
    r, t = _in_plane(rng, False)
    X = [R * r, R * r * rng.uniform(0, 1) + _tiny(rng, -14, -6) * R * EZ, rng.normal(size=3) * 2 * R,
         np.zeros(3)][int(rng.integers(0, 4))]
    size = _logu(rng, 2, 5) * R
    return fr.bezier(_bezier_through(rng, X, size, _npts(rng))), b


def _fam_bezier_far_control(rng, ka, kb):
    """One control point 1e6..1e12 radii away."""
    fr = _Frame(rng, exact=False)
    R = _radius(rng, False)
    b = fr.round(np.zeros(3), EZ, R)
    ctrl = [rng.normal(size=3) * 1.5 * R for _ in range(_npts(rng))]
    ctrl[int(rng.integers(0, len(ctrl)))] = _unit(rng) * _logu(rng, 6, 12) * R
    return fr.bezier(ctrl), b


def _fam_bezier_plane(rng, ka, kb):
    """A Bezier curve in a plane parallel to the round's at height 1e-9 (x radius), translated by
    1e6."""
    fr = _Frame(rng)
    R = _radius(rng, fr.exact)
    h = 1e-9 * R * float(rng.choice([-1.0, 1.0]))
    b = fr.round(np.zeros(3), EZ, R)
    ctrl = [np.array([*(rng.normal(size=2) * 1.2 * R), h]) for _ in range(_npts(rng))]
    a = fr.bezier(ctrl)
    T = (_unit(rng) if rng.random() < 0.7 else np.array([1.0, 0.0, 0.0])) * 1e6
    return _translate("bezier", a, T), _translate(kb, b, T)


def _fam_huge_circle(rng, ka, kb):
    """A huge circle (radius 1e3..1e9) passing near a small disk or circle."""
    fr = _Frame(rng, exact=False)
    r_small = _logu(rng, -1, 0.3)
    Rh = _logu(rng, 3, 9)
    huge_is_a = not (ka == "circle" and kb == "disk" and rng.random() < 0.3)
    r, t = _in_plane(rng, False)
    mode = int(rng.integers(0, 4))
    g = _tiny(rng, -12, 0, 0.3) * r_small
    X = [r_small * r + g * _unit(rng), r * r_small * rng.uniform(0, 1) + abs(g) * EZ,
         rng.normal(size=3) * 2 * r_small, g * _unit(rng)][mode]
    nh = _unit(rng)
    uh = _perp(rng, nh)
    huge = fr.round(X - Rh * uh, nh, Rh)
    small = fr.round(np.zeros(3), EZ, r_small)
    return (huge, small) if huge_is_a else (small, huge)


# ---- families of the pairs without a round: points, lines, rays, segments and Bezier curves ----
# (S: the scene's size; the pieces' local geometry in a _Frame as above)
EX = np.array([1.0, 0.0, 0.0])
EY = np.array([0.0, 1.0, 0.0])


def _size(rng, exact):
    return _radius(rng, exact)


def _fam_linear_random(rng, ka, kb):
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    b = fr.linear(kb, rng.normal(size=3) * S, _unit(rng), S)
    if ka == "bezier":
        return fr.bezier([rng.normal(size=3) * 1.5 * S for _ in range(_npts(rng))]), b
    return fr.linear(ka, rng.normal(size=3) * S, _unit(rng), S), b


def _parallel_pair(rng, exact, S):
    """Local (X_a, d_a, X_b, d_b) of two nearly parallel pieces: directions 1e-12..1e-2 rad
    apart (or parallel), crossing, 1e-15..1e-9 x S apart (along their common normal) or
    collinear."""
    mode = str(rng.choice(["cross", "gap", "collinear", "parallel"]))
    angle = 0.0 if mode in ("collinear", "parallel") else _logu(rng, -12, -2)
    gap = {"cross": 0.0, "collinear": 0.0}.get(mode, _logu(rng, -15, -9) * S)
    sgn = float(rng.choice([-1.0, 1.0]))
    d_b = sgn * (math.cos(angle) * EX + math.sin(angle) * EY)
    # the crossing point (or the place of nearest approach) anywhere near the pieces
    X_b = (0.0 if exact else rng.uniform(-2, 2) * S) * EX + gap * EZ
    return np.zeros(3), EX, X_b, d_b


def _fam_near_parallel(rng, ka, kb):
    """Nearly parallel lines, rays and segments: crossing at 1e-12..1e-2 rad, passing
    1e-15..1e-9 apart, parallel a hair apart, collinear (overlapping or not)."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    X_a, d_a, X_b, d_b = _parallel_pair(rng, fr.exact, S)
    return fr.linear(ka, X_a, d_a, S), fr.linear(kb, X_b, d_b, S)


def _fam_linear_far_origin(rng, ka, kb):
    """Line origins / segment ends 1e6..1e12 x S along the pieces (one or both), on random or
    nearly parallel pieces; a Bezier curve against such a line, ray or segment."""
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    if ka == "bezier":
        X, d = rng.normal(size=3) * S, _unit(rng)
        ctrl = _bezier_through(rng, X + _tiny(rng, -15, -1) * S * _perp(rng, d), S, max(2, _npts(rng)))
        return fr.bezier(ctrl), _far_piece(rng, fr, kb, X, d, S)
    if rng.random() < 0.5:
        X_a, d_a, X_b, d_b = _parallel_pair(rng, False, S)
    else:
        X_a, d_a, X_b, d_b = rng.normal(size=3) * S, _unit(rng), rng.normal(size=3) * S, _unit(rng)
    which = int(rng.integers(0, 3))       # far: a, b or both
    a = _far_piece(rng, fr, ka, X_a, d_a, S) if which != 1 else fr.linear(ka, X_a, d_a, S)
    b = _far_piece(rng, fr, kb, X_b, d_b, S) if which != 0 else fr.linear(kb, X_b, d_b, S)
    return a, b


def _fam_zero_length(rng, ka, kb):
    """Zero-length segments (both ends equal) against a point, line, ray, segment (zero-length
    or not) or curve, at 0, tiny or ordinary distances."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    P = np.zeros(3)
    h = _tiny(rng, -16, 0, 0.3) * S
    Q = P + h * (EZ if fr.exact else _unit(rng))      # the other piece passes through Q
    zero = fr.pos(P)
    if ka == "bezier":
        return fr.bezier(_bezier_through(rng, Q, S, _npts(rng))), zero + zero
    if ka == "segment" and rng.random() < 0.5:        # both zero-length
        return fr.pos(Q) + fr.pos(Q), zero + zero
    if ka == "segment":                                # the first one zero-length, the other not
        return zero + zero, fr.linear(kb, Q, EX if fr.exact else _unit(rng), S)
    return fr.linear(ka, Q, EX if fr.exact else _unit(rng), S), zero + zero


def _fam_on_piece(rng, ka, kb):
    """A point of one piece as the other's point, ray origin or segment end (computed exactly in
    exact frames), and segment ends / ray origins exactly at, or 1e-16..1e-6 x S off, the other
    piece's closest point (the piece leaving it at a right or an oblique angle)."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    b = fr.linear(kb, np.zeros(3), EX, S)              # b along local x through 0
    c = fr.param(-1, 1) * S
    if kb == "segment" and rng.random() < 0.3:        # at b's end
        c = float(np.dot(np.asarray(b[3:6]) - fr.C, fr.Q[:, 0])) if fr.exact else c
    h = 0.0 if rng.random() < 0.5 else _tiny(rng, -16, -6, 0) * S
    E = c * EX + h * EZ
    side = EZ if h or fr.exact else _perp(rng, EX)
    d = side if rng.random() < 0.5 else _rot(side, np.cross(EX, side), -rng.uniform(0.2, 1.4))
    L = fr.dlen() * S
    if ka == "point":
        return fr.pos(E), b
    if ka == "segment":
        return fr.pos(E) + fr.pos(E + L * d), b
    if ka == "ray":
        return fr.pos(E) + fr.dirv(d, fr.dlen()), b
    return fr.pos(E) + fr.dirv(d, fr.dlen()), b


def _fam_bezier_tangent_line(rng, ka, kb):
    """A line, ray or segment tangent to a curve at an interior point (exactly or 1e-16..1e-4 x S
    off, on either side), or parallel to the curve's end tangent (through the end, or beside it)."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    h = _tiny(rng, -16, -4, 0.4) * S
    if rng.random() < 0.6:       # the apex of a symmetric arch (degree-elevated): tangent EX at X = 0
        L = S * rng.uniform(0.3, 2)
        delta = EY * S * rng.uniform(0.05, 1)
        ctrl = _elevate([-L * EX + delta, -delta, L * EX + delta], max(3, _npts(rng)))
        return fr.bezier(ctrl), fr.linear(kb, h * EY, EX, S)
    ctrl = [rng.normal(size=3) * S for _ in range(max(3, _npts(rng)))]
    d0 = ctrl[1] - ctrl[0]
    d0 = d0 / np.linalg.norm(d0)
    X = ctrl[0] + h * _perp(rng, d0)
    return fr.bezier(ctrl), fr.linear(kb, X, -d0 if rng.random() < 0.5 else d0, S)


def _fam_bezier_crossing(rng, ka, kb):
    """A line, ray or segment crossing a curve (exactly at a rounded curve point, or 1e-16..1e-6
    x S beside it), at any angle."""
    fr = _Frame(rng)
    S = _size(rng, fr.exact)
    X = np.zeros(3)
    ctrl = _bezier_through(rng, X, S, max(2, _npts(rng)))
    Y = X + _tiny(rng, -16, -6, 0.4) * S * _unit(rng)
    return fr.bezier(ctrl), fr.linear(kb, Y, _unit(rng), S)


def _fam_bezier_far_control_linear(rng, ka, kb):
    """A curve with one control point 1e6..1e12 x S away against a point, line, ray or segment
    near its other control points."""
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    ctrl = [rng.normal(size=3) * 1.5 * S for _ in range(_npts(rng))]
    ctrl[int(rng.integers(0, len(ctrl)))] = _unit(rng) * _logu(rng, 6, 12) * S
    return fr.bezier(ctrl), fr.linear(kb, rng.normal(size=3) * S, _unit(rng), S)


def _fam_bezier_large_linear(rng, ka, kb):
    """A curve 1e2..1e5 times larger than the other piece (a segment of length ~S, a point, a
    line or ray near it), passing through a point on, near or beside that piece."""
    fr = _Frame(rng, exact=False)
    S = _size(rng, False)
    d = _unit(rng)
    b = fr.linear(kb, np.zeros(3), d, S)
    X = [rng.uniform(0, 1) * S * d, rng.uniform(0, 1) * S * d + _tiny(rng, -14, -6) * S * _perp(rng, d),
         rng.normal(size=3) * 2 * S][int(rng.integers(0, 3))]
    return fr.bezier(_bezier_through(rng, X, _logu(rng, 2, 5) * S, _npts(rng))), b


_LINEAR_TRANSLATED_BASES = ("linear_random", "near_parallel", "zero_length", "on_piece", "bezier_tangent_line",
                            "bezier_crossing")


def _fam_linear_far_translated(rng, ka, kb):
    return _fam_far_translated(rng, ka, kb, bases=_LINEAR_TRANSLATED_BASES)


# ---- arcs: the circle families applied to arcs (issue 19) --------------------------------------
# An arc family takes a base family's case with every arc drawn as a circle (the base generator
# called with "circle" for "arc"; a disk stays a disk), then cuts each such circle to an arc
# (same centre, normal and radius; a start and an angle).  Where the span lies is chosen relative
# to a feature of the circle found by a float64 search (_feature): its point nearest the other
# shape (a tangency, a line's closest point, the touching point of nearly touching rounds) or
# nearest the other round's axis -- an arc END exactly there (theta = 0 or theta = angle), or
# 1e-16..1e-6 rad beside it; the feature inside the span; or outside it (the ends decide).  In
# exact frames (normals along the axes) a feature within 1e-5 rad of a coordinate axis is snapped
# onto it, so that the end sits exactly at the base family's exact touching point.
def _arc_angle(rng, extreme=False):
    """An arc's angle: ordinary, quarter / half / three-quarter turns, tiny (1e-12..1e-3 rad),
    2 pi - (1e-12..1e-3), or float64's 2 pi exactly (the whole circle)."""
    k = int(rng.integers(0, 8)) if not extreme else int(rng.integers(4, 8))
    if k <= 2:
        return float(rng.uniform(0.05, 2 * math.pi - 0.05))
    if k == 3:
        return float(rng.choice([0.5, 1.0, 1.5])) * math.pi
    if k in (4, 5):
        return _logu(rng, -12, -3)
    if k == 6:
        return 2 * math.pi - _logu(rng, -12, -3)
    return 2 * math.pi      # the library takes angles in (0, 2 pi]


def _unit_normal(data):
    N = np.asarray(data[3:6], float)
    return N / np.linalg.norm(N)


def _snap(e, n):
    """e snapped onto the coordinate axis it lies within 1e-5 rad of, when the normal n is a
    coordinate axis (an exact frame) and that axis lies in the plane."""
    k = int(np.argmax(np.abs(e)))
    if abs(e[k]) > 1 - 5e-11 and np.max(np.abs(n)) == 1.0 and n[k] == 0.0:
        out = np.zeros(3)
        out[k] = math.copysign(1.0, e[k])
        return out
    return e


def _feature(circle, kind, data):
    """The unit direction (world) from the circle's centre to its point nearest the shape
    (kind, data) -- a point, line, ray, segment, circle or disk; "axis": the line along a round's
    axis -- by a float64 scan of 720 angles and eight re-samplings around the best (a generator's
    hint, not a reference: its minimiser is good to ~1e-8 rad where the distance is quadratic)."""
    C, R = np.asarray(circle[:3], float), float(circle[6])
    n = _unit_normal(circle)
    u0 = _perp(np.random.default_rng(0), n)
    v0 = np.cross(n, u0)
    if kind == "axis":
        kind, data = "line", list(data[:6])
    D = np.asarray(data, float)[None]
    if kind == "bezier":
        # (a Bezier curve: the nearest of 401 of its points, relative to the circle's centre)
        t = np.linspace(0, 1, 401)
        P = sum(math.comb(len(data) - 1, i) * (t ** i * (1 - t) ** (len(data) - 1 - i))[:, None] * (np.asarray(q) - C)
                for i, q in enumerate(data))
        rel = np.zeros(3)

        def dist(w):
            return np.min(np.linalg.norm(w[:, None, :] - P[None], axis=2), axis=1)
    elif kind in ROUND:
        rel = _diff_ld(C[None], D[:, :3]).astype(float)[0]
        tn = _unit_normal(data)

        def dist(w):
            return _round_dist(w, tn, float(data[6]), kind == "disk")
    else:
        b0, m, lo, hi = (np.asarray(x, float) for x in _anchor(kind, D, C[None]))
        rel = -b0[0]

        def dist(w):
            return _lin_dist(w, m[0], float(np.dot(m[0], m[0])), lo[0], hi[0])

    def f(th):
        return dist(rel + R * (np.cos(th)[:, None] * u0 + np.sin(th)[:, None] * v0))

    th = np.arange(720) * (2 * math.pi / 720)
    best = th[int(np.argmin(f(th)))]
    h = 2 * math.pi / 720
    for _ in range(8):
        th = best + np.linspace(-2 * h, 2 * h, 65)
        best = th[int(np.argmin(f(th)))]
        h /= 16
    return _snap(math.cos(best) * u0 + math.sin(best) * v0, n)


def _offset(rng):
    """0, or +-1e-16..1e-6 rad: an end exactly at the feature or beside it."""
    return _tiny(rng, -16, -6, 0.4)


def _cut(rng, circle, e, mode, angle):
    """The arc of the circle (data: centre, normal, radius) with the angle `angle`, placed by
    mode relative to the feature direction e: "start" (theta = 0 at e, or beside it), "end"
    (theta = angle at e, or beside it), "inside" (e in the span), "outside" (e beyond both ends),
    "random"."""
    n = _unit_normal(circle)
    if mode == "start":
        start = _rot(e, n, _offset(rng))
    elif mode == "end":
        start = _rot(e, n, -angle + _offset(rng))
    elif mode == "inside":
        start = _rot(e, n, -angle * rng.uniform(0.05, 0.95))
    elif mode == "outside" and angle < 2 * math.pi - 1e-3:
        start = _rot(e, n, rng.uniform(0, 2 * math.pi - angle))
    else:
        start = _rot(_perp(rng, n), n, 0.0)
    if mode != "random":
        start = _snap(start / np.linalg.norm(start), n)
    return [float(x) for x in circle[:7]] + [float(x) for x in start] + [float(angle)]


_SPAN_MODES = ("start", "end", "inside", "outside", "random")


def _arc_of(rng, circle, other_kind, other, modes=_SPAN_MODES, extreme=False):
    """Cut a circle to an arc, the span placed by a mode drawn from `modes` relative to the
    circle's point nearest the other shape or (a round other, half the time) nearest its axis."""
    mode = str(rng.choice(modes))
    feature_of = "axis" if other_kind in RIMS and rng.random() < 0.5 else _arc_base_kind(other_kind)
    e = _feature(circle, feature_of, other[:7] if other_kind in RIMS else other)
    return _cut(rng, circle, e, mode, _arc_angle(rng, extreme))


def _arc_base_kind(kind):
    return "circle" if kind == "arc" else kind


def _arc_variant(base, modes=_SPAN_MODES, extreme=False):
    """The generator of an arc family: the base family's case, its arcs cut from circles."""
    def gen(rng, ka, kb):
        a, b = FAMILIES[base][1](rng, _arc_base_kind(ka), _arc_base_kind(kb))
        a, b = _plain(a), _plain(b)
        kinds = (_arc_base_kind(ka), _arc_base_kind(kb))
        a2 = _arc_of(rng, a, kinds[1], b, modes, extreme) if ka == "arc" else a
        b2 = _arc_of(rng, b, kinds[0], a, modes, extreme) if kb == "arc" else b
        return a2, b2
    return gen


def _arc_pairs(base_pairs):
    """The arc pairs whose circle version (arcs drawn as circles) the base family covers."""
    def covered(k):
        kk = _arc_base_kind(k)
        return (kk, "circle") in base_pairs or ("circle", kk) in base_pairs
    return [p for p in ARC_PAIRS if covered(p[0])]


def _fam_arc_spans(rng, ka, kb):
    """Concentric, coplanar circle / disk / arc against an arc: spans overlapping, disjoint or
    touching at an end (the other arc starting where this one ends, or ending where it starts,
    exactly in exact frames), radii equal, 1 + 1e-15..1e-6 or apart; normals equal or opposite
    (the other arc then runs the other way round)."""
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    Ra = Rb * float(rng.choice([1.0, 1.0 + _tiny(rng, -15, -6, 0), rng.uniform(0.2, 3)]))
    nb = EZ
    na = EZ * float(rng.choice([-1.0, 1.0]))
    angle_b = float(rng.choice([0.5, 1.0, 1.5])) * math.pi if ex else _arc_angle(rng)
    r, _ = _in_plane(rng, ex)
    b_end = _rot(r, nb, angle_b)
    b = fr.round(np.zeros(3), nb, Rb) + fr.dirv(r) + [angle_b]
    if ka != "arc":
        return fr.round(np.zeros(3), na, Ra), b
    angle_a = float(rng.choice([0.5, 1.0, 1.5])) * math.pi if ex else _arc_angle(rng)
    how = str(rng.choice(["touch_end", "touch_start", "overlap", "disjoint"]))
    # a's start s_a, its points at s_a rotated about na by [0, angle_a]
    if how == "touch_end":          # a starts where b ends
        s_a = b_end
    elif how == "touch_start":      # a ends where b starts
        s_a = _rot(r, na, -angle_a)
    elif how == "overlap":
        s_a = _rot(r, nb, rng.uniform(0, min(angle_b, 2 * math.pi)))
    else:                           # starting after b's end, ending before b's start (if it can)
        gap = max(2 * math.pi - angle_b, 0.0)
        s_a = _rot(b_end, nb, gap * rng.uniform(0.1, 0.9))
        angle_a = min(angle_a, gap * rng.uniform(0.05, 0.5)) if gap > 0 else angle_a
    s_a = np.round(s_a) if ex and np.max(np.abs(s_a - np.round(s_a))) < 1e-12 else s_a
    return fr.round(np.zeros(3), na, Ra) + fr.dirv(s_a) + [angle_a], b


_ARC_TRANSLATED_BASES = ("arc_random", "arc_tangent", "arc_ends", "arc_coplanar", "arc_concentric", "arc_axis",
                         "arc_near_touching", "arc_spans", "arc_angles", "arc_end_on_axis")


def _fam_arc_far_translated(rng, ka, kb):
    return _fam_far_translated(rng, ka, kb, bases=_ARC_TRANSLATED_BASES)


def _fam_arc_ends(rng, ka, kb):
    """An arc end (theta = 0 or theta = angle) exactly at, or 1e-16..1e-6 rad beside, the
    circle's point nearest the other shape (or the other round's axis), over the tangent,
    coplanar, random and (rounds) nearly touching cases."""
    bases = [f for f in ("tangent", "coplanar", "random", "near_touching", "shadow_center", "concentric")
             if (ka, kb) in _arc_pairs(FAMILIES[f][0])]
    return _arc_variant(str(rng.choice(bases)), modes=("start", "end"))(rng, ka, kb)


def _fam_arc_end_on_axis(rng, ka, kb):
    """A circle, disk or arc whose axis passes exactly through the arc's end (theta = 0 or
    theta = angle; in exact frames quarter turns, the end exact up to cos(pi/2)'s rounding) or
    1e-16..1e-6 radii beside it, at heights 0..2 radii along the axis: the distance from the end
    to the round is then the same for every point of its rim (a circle) or attained at the disk's
    centre region."""
    fr = _Frame(rng)
    ex = fr.exact
    Rb = _radius(rng, ex)
    r, _ = _in_plane(rng, ex)
    angle = float(rng.choice([0.5, 1.0, 1.5])) * math.pi if ex else _arc_angle(rng)
    at_end = rng.random() < 0.5
    E = Rb * (_snap(_rot(r, EZ, angle), EZ) if at_end else r)
    b = fr.round(np.zeros(3), EZ, Rb) + fr.dirv(r) + [angle]
    na = (EZ if rng.random() < 0.5 else EX) if ex else _unit(rng)
    off = _tiny(rng, -16, -6, 0.5) * Rb * _perp(rng, na)
    Ra = _radius(rng, ex) * float(rng.choice([1.0, 0.25, 4.0]))
    a = fr.round(E + off + fr.param(-2, 2) * Rb * na, na, Ra)
    if ka == "arc":
        a = _arc_of(rng, a, "arc", b)
    return a, b


def _fam_arc_angles(rng, ka, kb):
    """Tiny angles (1e-12..1e-3 rad), 2 pi - (1e-12..1e-3), float64's 2 pi exactly and above
    (the whole circle, which must answer as the circle: check_cases compares them to the bit)."""
    bases = [f for f in ("random", "tangent", "coplanar", "axis", "near_touching")
             if (ka, kb) in _arc_pairs(FAMILIES[f][0])]
    return _arc_variant(str(rng.choice(bases)), extreme=True)(rng, ka, kb)


# ---- annuli: the disk families applied to annuli, and the annuli's own (issue 19) -------------
# An annulus family takes a base family's case with every annulus drawn as a disk (and every arc
# as a circle, cut to an arc as the arc families do), then cuts a hole in each such disk: inner
# radius 0 (the disk), the outer radius (the circle), 1e-9..1e-6 of it, a quarter, half or three
# quarters (exact in exact frames) or any fraction.  Annulus data: centre, normal, OUTER radius,
# inner radius (RIMS).
def _ann_base_kind(kind):
    return {"arc": "circle", "annulus": "disk"}.get(kind, kind)


def _axis_normal(data):
    """Whether a round's normal is a coordinate axis (an exact frame's)."""
    return sum(1 for x in data[3:6] if x != 0.0) == 1


_HOLES = ("zero", "outer", "tiny", "fraction", "any")


def _hole(rng, disk, holes=_HOLES):
    """The disk's data with a hole: [centre, normal, outer, inner]."""
    R = float(disk[6])
    how = str(rng.choice(holes))
    if how == "zero":
        inner = 0.0
    elif how == "outer":
        inner = R
    elif how == "tiny":
        inner = R * (1e-9 if rng.random() < 0.5 else _logu(rng, -9, -6))
    elif how == "fraction" and _axis_normal(disk):
        inner = R * float(rng.choice([0.25, 0.5, 0.75]))
    else:
        inner = R * float(rng.uniform(0.05, 0.95))
    return [float(x) for x in disk[:7]] + [float(inner)]


def _ann_variant(base, holes=_HOLES):
    """The generator of an annulus family: the base family's case (annuli drawn as disks, arcs as
    circles), its arcs cut (_arc_of) and its annuli holed (_hole)."""
    def gen(rng, ka, kb):
        bka, bkb = _ann_base_kind(ka), _ann_base_kind(kb)
        a, b = FAMILIES[base][1](rng, bka, bkb)
        a, b = _plain(a), _plain(b)
        if ka == "arc":
            a = _arc_of(rng, a, bkb, b)
        if ka == "annulus":
            a = _hole(rng, a, holes)
        return a, _hole(rng, b, holes)
    return gen


def _ann_pairs(base_pairs):
    """The annulus pairs whose disk version (annuli drawn as disks, arcs as circles) the base
    family covers."""
    return [p for p in ANN_PAIRS if (_ann_base_kind(p[0]), "disk") in base_pairs]


def _ann_local(rng, fr, lo=0.3, hi=0.8):
    """The annulus of a local frame (centre 0, normal z): (data, outer, inner); in exact frames
    dyadic radii."""
    Ro = _radius(rng, fr.exact)
    Ri = Ro * (float(rng.choice([0.25, 0.5, 0.75])) if fr.exact else float(rng.uniform(lo, hi)))
    return fr.round(np.zeros(3), EZ, Ro) + [Ri], Ro, Ri


def _lift(rng, R):
    """0 (coplanar) or +-1e-9..1e-3 x R."""
    return _tiny(rng, -9, -3, 0.4) * R


def _inner_circle(b, fr, Ri):
    """The inner rim of the local annulus as a circle's data (world)."""
    return fr.round(np.zeros(3), EZ, Ri)


def _fam_ann_hole(rng, ka, kb):
    """Something in the hole: a point, a segment, a Bezier curve, a circle, arc, disk or annulus
    inside the inner rim, coplanar or lifted by 1e-9..1e-3 radii, concentric or not (a circle's
    radius up to 1e-12 short of touching the inner rim); lines and rays through the hole, in the
    plane (crossing the ring) or tilted through it."""
    fr = _Frame(rng)
    ex = fr.exact
    b, Ro, Ri = _ann_local(rng, fr)
    h = _lift(rng, Ro)
    r, t = _in_plane(rng, ex)
    if ka == "point":
        return fr.pos(r * Ri * fr.param(0, 0.875) + h * EZ), b
    if ka in ("line", "ray", "segment"):
        X = r * Ri * fr.param(0, 0.875) + h * EZ
        if ka == "segment" and rng.random() < 0.5:
            # a short segment wholly inside the hole
            room = math.sqrt(max(Ri * Ri - float(np.dot(X[:2], X[:2])), 0.0))
            s0, s1 = room * rng.uniform(-0.9, 0.9), room * rng.uniform(-0.9, 0.9)
            return fr.pos(X + s0 * t) + fr.pos(X + s1 * t), b
        psi = 0.0 if rng.random() < 0.5 else float(rng.uniform(0.1, 1.5))
        d = math.cos(psi) * t + math.sin(psi) * EZ
        return fr.linear(ka, X, d, Ri), b
    if ka == "bezier":
        ctrl = [np.array([*(rng.normal(size=2) * 0.3 * Ri), h]) for _ in range(_npts(rng))]
        return fr.bezier(ctrl), b
    off = 0.0 if rng.random() < 0.4 else fr.param(0, 0.375)
    c = r * Ri * off + h * EZ
    room = Ri * (1 - off)
    if rng.random() < 0.3:
        Rc = room * (1 - _logu(rng, -12, -3))
    else:
        Rc = room * (float(rng.choice([0.5, 0.75])) if ex else float(rng.uniform(0.1, 0.95)))
    n = EZ * float(rng.choice([-1.0, 1.0]))
    if rng.random() < 0.2 and not ex:
        n = _rot(n, _perp(rng, EZ), _logu(rng, -12, -3))
    a = fr.round(c, n, Rc)
    if ka == "arc":
        a = _arc_of(rng, a, "circle", _inner_circle(b, fr, Ri))
    elif ka == "annulus":
        a = _hole(rng, a, ("fraction", "any", "tiny"))
    return a, b


def _fam_ann_overlap(rng, ka, kb):
    """Coplanar (or parallel at heights 1e-16..1e-6) circles, arcs, disks and annuli over the
    ring: centres anywhere from concentric (exactly, in exact frames) to beyond the outer rim,
    the other's radii from inside the hole to beyond the outer rim."""
    fr = _Frame(rng)
    ex = fr.exact
    b, Ro, Ri = _ann_local(rng, fr)
    h = _tiny(rng, -16, -6, 0.5) * Ro
    r, _ = _in_plane(rng, ex)
    Ra = Ro * (float(rng.choice([0.25, 0.5, 0.75, 1.0, 1.5])) if ex else float(rng.uniform(0.1, 2)))
    off = 0.0 if rng.random() < 0.25 else fr.param(0, 1.5) * (Ra + Ro) / 2
    a = fr.round(off * r + h * EZ, EZ * float(rng.choice([-1.0, 1.0])), Ra)
    if ka == "arc":
        a = _arc_of(rng, a, "circle", _inner_circle(b, fr, Ri) if rng.random() < 0.5 else b[:7])
    elif ka == "annulus":
        a = _hole(rng, a, ("fraction", "any"))
    return a, b


def _fam_ann_degenerate(rng, ka, kb):
    """Annuli of inner radius 0 (the disk's answers, to the bit: _check_hole), equal to the outer
    one (the circle's) or 1e-9 of it, over the random, tangent, axis, coplanar, concentric and
    nearly touching cases."""
    bases = [f for f in ("random", "tangent", "axis", "coplanar", "concentric", "near_touching")
             if (ka, kb) in _ann_pairs(FAMILIES[f][0])]
    return _ann_variant(str(rng.choice(bases)), holes=("zero", "outer", "tiny"))(rng, ka, kb)


def _fam_ann_inner_tangent(rng, ka, kb):
    """A piece tangent to the inner rim, or 1e-16..1e-4 radii inside or outside it: points by the
    inner rim, lines, rays and segments through the hole grazing it (tilted from the plane by
    0.1..1.4 rad), a Bezier arch grazing it, circles, arcs, disks and annuli touching it from
    inside the hole (coplanar) or standing on it."""
    fr = _Frame(rng)
    ex = fr.exact
    b, Ro, Ri = _ann_local(rng, fr)
    r, t = _in_plane(rng, ex)
    X = Ri * r
    h = _tiny(rng, -16, -4, 0.3) * Ri
    if ka == "point":
        return fr.pos(X + h * (r if ex or rng.random() < 0.5 else _unit(rng))), b
    if ka in ("line", "ray", "segment", "bezier"):
        psi = float(rng.uniform(0.1, 1.4))
        d = math.cos(psi) * t + math.sin(psi) * EZ
        Y = X + h * r
        if ka == "bezier":
            L = Ri * rng.uniform(0.3, 2)
            delta = -r * Ri * rng.uniform(0.05, 0.5)        # bulging into the hole
            ctrl = _elevate([Y - L * d - delta, Y + delta, Y + L * d - delta], max(3, _npts(rng)))
            return fr.bezier(ctrl), b
        return fr.linear(ka, Y, d, Ri), b
    phi = float(rng.choice([0.0, math.pi / 2, rng.uniform(0, 2 * math.pi)]))
    Rc = Ri * (float(rng.choice([0.25, 0.5])) if ex else float(rng.uniform(0.1, 0.9))) if phi == 0.0 else \
        _radius(rng, ex) * Ri
    c, n, w = _tangent_round(rng, Ri, Rc, ex, phi=phi)
    a = fr.round(c + h * w, n, Rc)
    if ka == "arc":
        a = _arc_of(rng, a, "circle", _inner_circle(b, fr, Ri))
    elif ka == "annulus":
        a = _hole(rng, a, ("fraction", "any"))
    return a, b


_ANN_TRANSLATED_BASES = ("ann_random", "ann_tangent", "ann_axis", "ann_coplanar", "ann_concentric",
                         "ann_near_touching", "ann_parallel_height", "ann_hole", "ann_overlap", "ann_inner_tangent")


def _fam_ann_far_translated(rng, ka, kb):
    return _fam_far_translated(rng, ka, kb, bases=_ANN_TRANSLATED_BASES)


# ---- effects on degenerate configurations ----------------------------------------------------
_DEGENERATE_MODES = ("axis", "axis_of_a", "coaxial", "coplanar", "concentric", "random")
_DEGENERATE_WEIGHTS = (0.3, 0.3, 0.1, 0.1, 0.1, 0.1)
_DEGENERATE_ANGLES = (math.pi / 2, math.pi, 1.5 * math.pi, 2 * math.pi, 1.0)


def _small_int_vector(rng, nonzero=False, lo=-2, hi=2):
    while True:
        v = rng.integers(lo, hi + 1, size=3).astype(float)
        if not nonzero or np.any(v != 0):
            return v


def _oblique_normal(rng):
    """A small integer normal, mostly off the coordinate axes (two or three components nonzero:
    its unit vector is rounded, and a center on its axis leaves rounding noise in the plane)."""
    while True:
        v = _small_int_vector(rng, True)
        if np.count_nonzero(v) >= 2 or rng.random() < 0.2:
            return v


def _small_shape(rng, kind, c, n):
    """A shape of `kind` anchored at c (a round's center, a piece's origin or first point, a curve's
    first control point) along n (a round's normal, a piece's direction half the time), with
    small integer data: a circle's or disk's radius 0, 1 or 2, an arc's or annulus's 1 or 2, an
    annulus's inner radius 0..outer (0: the disk, = outer: the circle), a segment of length 0
    sometimes."""
    def along():
        return n * float(rng.choice([1, -1, 2])) if rng.random() < 0.5 else _small_int_vector(rng, True)
    if kind == "point":
        return list(c)
    if kind in ("line", "ray"):
        return list(c) + list(along())
    if kind == "segment":
        return list(c) + list(c + (along() if rng.random() < 0.9 else 0.0))
    if kind == "bezier":
        return [list(c)] + [list(c + _small_int_vector(rng)) for _ in range(int(rng.integers(1, 4)))]
    r = float(rng.integers(0, 3))
    if kind in ("circle", "disk"):
        return list(c) + list(n) + [r]
    r = max(r, 1.0)  # an arc or annulus of radius 0 is a point, on which the unique rules and
    # _check_hole (inner 0: the disk's answers, inner = outer: the circle's) disagree
    if kind == "arc":
        start = _small_int_vector(rng, True)
        while not np.any(np.cross(start, n)):
            start = _small_int_vector(rng, True)
        return list(c) + list(n) + [r] + list(start) + [float(rng.choice(_DEGENERATE_ANGLES))]
    if kind == "annulus":
        return list(c) + list(n) + [r, float(rng.integers(0, int(r) + 1))]
    raise ValueError(kind)


def _fam_effect_degenerate(rng, ka, kb):
    """Small integer configurations where the cheap bounds of within() / intersects()
    (bounds.hpp) meet degenerate frames: a's anchor on b's axis (k = +-1 or +-2 normals from its
    center), b's center on a's axis, both on one axis (coaxial), a in b's plane
    (coplanar), concentric, or random; radii 0..2, inner radius 0..outer. The effects must equal
    their definition on the distance (check_effects_definition)."""
    mode = str(rng.choice(_DEGENERATE_MODES, p=_DEGENERATE_WEIGHTS))
    cb, nb, na = _small_int_vector(rng), _oblique_normal(rng), _oblique_normal(rng)
    k = float(rng.choice([-2, -1, 1, 2]))
    if mode == "axis":
        ca = cb + k * nb
    elif mode == "axis_of_a":
        ca = cb - k * na
    elif mode == "coaxial":
        na, ca = nb * float(rng.choice([1, -1, 2])), cb + k * nb
    elif mode == "coplanar":
        na, ca = nb * float(rng.choice([1, -1])), cb + np.cross(nb, _small_int_vector(rng, lo=-1, hi=1))
    elif mode == "concentric":
        ca = cb.copy()
    else:
        ca = _small_int_vector(rng)
    return _small_shape(rng, ka, ca, na), _small_shape(rng, kb, cb, nb)


RR = [("circle", "circle"), ("circle", "disk"), ("disk", "disk")]
LR = [(lk, rk) for lk in LINEAR for rk in ROUND]
LR3 = [(lk, rk) for lk in ("line", "ray", "segment") for rk in ROUND]
BR = [("bezier", "circle"), ("bezier", "disk")]
LL3 = [p for p in LL if "point" not in p]                    # among lines, rays and segments
LLZ = [p for p in LL + BL if "segment" in p]                 # with a segment (made zero-length)

# name: (kind pairs, generator)
FAMILIES = {
    "random": (ROUND_PAIRS, _fam_random),
    "tangent": (ROUND_PAIRS, _fam_tangent),
    "axis": (LR, _fam_axis),
    "coplanar": (ROUND_PAIRS, _fam_coplanar),
    "concentric": (ROUND_PAIRS, _fam_concentric),
    "near_concentric": (ROUND_PAIRS, _fam_near_concentric),
    "far_translated": (ROUND_PAIRS, _fam_far_translated),
    "far_origin": (LR3, _fam_far_origin),
    "radius_ratio": (ROUND_PAIRS, _fam_radius_ratio),
    "near_touching": (RR, _fam_near_touching),
    "parallel_height": (RR, _fam_parallel_height),
    "bezier_large": (BR, _fam_bezier_large),
    "bezier_far_control": (BR, _fam_bezier_far_control),
    "bezier_plane": (BR, _fam_bezier_plane),
    "huge_circle": (RR, _fam_huge_circle),
    # Families found later come last: a case's id ("family/seed/i") seeds its generator with the
    # family's position here, so appending keeps every earlier id's case.
    "shadow_center": (LR3, _fam_shadow_center),
    # the pairs without a round (points, lines, rays, segments; Bezier curves against them)
    "linear_random": (LL + BL, _fam_linear_random),
    "linear_far_translated": (LL + BL, _fam_linear_far_translated),
    "near_parallel": (LL3, _fam_near_parallel),
    "linear_far_origin": (LL[1:] + BL[1:], _fam_linear_far_origin),
    "zero_length": (LLZ, _fam_zero_length),
    "on_piece": (LL[1:], _fam_on_piece),
    "bezier_tangent_line": (BL[1:], _fam_bezier_tangent_line),
    "bezier_crossing": (BL[1:], _fam_bezier_crossing),
    "bezier_far_control_linear": (BL, _fam_bezier_far_control_linear),
    "bezier_large_linear": (BL, _fam_bezier_large_linear),
    "piece_near_plane": (LR3, _fam_piece_near_plane),
}
# arcs (issue 19): the circle families applied to arcs (arc_<base>: the base family's cases with
# their arcs cut from circles, _arc_variant), then the arcs' own
for _base in ("random", "tangent", "axis", "shadow_center", "piece_near_plane", "coplanar", "concentric",
              "near_concentric", "far_origin", "radius_ratio", "near_touching", "parallel_height", "huge_circle"):
    FAMILIES["arc_" + _base] = (_arc_pairs(FAMILIES[_base][0]), _arc_variant(_base))
FAMILIES.update({
    "arc_ends": (ARC_PAIRS, _fam_arc_ends),
    "arc_end_on_axis": (ARC_RR, _fam_arc_end_on_axis),
    "arc_spans": (ARC_RR, _fam_arc_spans),
    "arc_angles": (ARC_PAIRS, _fam_arc_angles),
    "arc_far_translated": (ARC_PAIRS, _fam_arc_far_translated),
})
# annuli (issue 19): the disk families applied to annuli (ann_<base>: the base family's cases with
# their annuli holed from disks and their arcs cut from circles, _ann_variant), then the annuli's own
for _base in ("random", "tangent", "axis", "shadow_center", "piece_near_plane", "coplanar", "concentric",
              "near_concentric", "far_origin", "radius_ratio", "near_touching", "parallel_height", "huge_circle"):
    FAMILIES["ann_" + _base] = (_ann_pairs(FAMILIES[_base][0]), _ann_variant(_base))
FAMILIES.update({
    "ann_hole": (ANN_PAIRS, _fam_ann_hole),
    "ann_overlap": (ANN_RR, _fam_ann_overlap),
    "ann_degenerate": (ANN_PAIRS, _fam_ann_degenerate),
    "ann_inner_tangent": (ANN_PAIRS, _fam_ann_inner_tangent),
    "ann_far_translated": (ANN_PAIRS, _fam_ann_far_translated),
})
# every kind pair: within() / intersects() / distance_if_within() / Scene.within /
# Scene.pairs_within against their definition on degenerate small-integer configurations
FAMILIES["effect_degenerate"] = (KIND_PAIRS, _fam_effect_degenerate)
EFFECT_FAMILIES = ("effect_degenerate",)


def has_round(family):
    """Whether a family's kind pairs include a circle or disk (the sixteen first families and piece_near_plane) or
    not (the pairs among points, lines, rays and segments and Bezier curves against them); the
    arc families (is_arc) and the annulus families (is_annulus) count as neither."""
    return not is_arc(family) and not is_annulus(family) and any(set(ROUND) & set(pair)
                                                                 for pair in FAMILIES[family][0])


def is_arc(family):
    """Whether a family is one of the arcs' (its kind pairs have an arc, and no annulus)."""
    return not is_annulus(family) and any("arc" in pair for pair in FAMILIES[family][0])


def is_annulus(family):
    """Whether a family is one of the annuli's (its kind pairs have an annulus)."""
    return any("annulus" in pair for pair in FAMILIES[family][0])


def _plain(data):
    if isinstance(data, (list, tuple)) and data and isinstance(data[0], (list, tuple, np.ndarray)):
        return [[float(x) for x in p] for p in data]
    return [float(x) for x in data]


def generate_one(family, seed, i):
    """Case i of a family: kind pair i mod (number of pairs), drawn from
    np.random.default_rng([seed, family index, i]) -- reproducible from its id alone."""
    fam_pairs, gen = FAMILIES[family]
    ka, kb = fam_pairs[i % len(fam_pairs)]
    rng = np.random.default_rng([seed, list(FAMILIES).index(family), i])
    a, b = gen(rng, ka, kb)
    return {"family": family, "id": f"{family}/{seed}/{i}", "a": ka, "a_data": _plain(a), "b": kb,
            "b_data": _plain(b)}


def generate(family, n, seed, start=0):
    """Cases start .. start+n-1 of one family (cycling through its kind pairs)."""
    return [generate_one(family, seed, i) for i in range(start, start + n)]


def case_from_id(case_id):
    """The case named by an id "family/seed/i"."""
    family, seed, i = case_id.split("/")
    return generate_one(family, int(seed), int(i))


def to_float32_case(case):
    """The case with every input rounded to float32 (the scene a float32 query describes)."""
    def r(data):
        if data and isinstance(data[0], list):
            return [[float(np.float32(x)) for x in p] for p in data]
        return [float(np.float32(x)) for x in data]
    out = dict(case)
    out["a_data"], out["b_data"] = r(case["a_data"]), r(case["b_data"])
    return out


def largest_radius(case):
    return max([case[k + "_data"][6] for k in ("a", "b") if case[k] in RIMS] + [0.0])


def bar_scale(case):
    """The length the bars are relative to besides the true distance.  A query with a circle or
    disk: its largest radius (the rounds' features set the answer's scale, however far the other
    shape's origin or however large a curve).  Without one there is no radius, and the scale is
    the one the pairs' own 50-digit accuracy tests hold the library to: for two points / lines /
    rays / segments 1e-12 x the query's size (reference_linear.bar_scale: the answers are held to
    their own size, however far the origins and ends lie; only distances twelve orders below the
    query, pieces that touch within the inputs' rounding, fall back to that floor); for a Bezier curve against one of them the largest length in the query, the
    control polygon's extent and a segment's length (reference_round.bezier_other_scale, as
    tests/test_bezier_point_linear.py).  Both are translation invariant; points a hair apart
    (zero-length segments) are held to the distance between them."""
    ka, kb = case["a"], case["b"]
    if ka in RIMS or kb in RIMS:
        return largest_radius(case)
    key = _key(case)
    if key not in _SCALE_CACHE:
        if ka == "bezier":
            _SCALE_CACHE[key] = _load("reference_round").bezier_other_scale(case["a_data"], kb,
                                                                           *_piece_points(kb, case["b_data"]))
        else:
            _SCALE_CACHE[key] = _load("reference_linear").bar_scale(ka, case["a_data"], kb, case["b_data"])
    return _SCALE_CACHE[key]


_SCALE_CACHE = {}


def scene_scale(case):
    """The largest input coordinate of a position (centres, points, origins, ends, control
    points) or radius: the scale of the ulps the closest points may be off their shapes."""
    vals = [0.0]
    for k in ("a", "b"):
        kind, data = case[k], case[k + "_data"]
        if kind == "bezier":
            vals += [abs(x) for p in data for x in p]
        elif kind in RIMS:
            vals += [abs(x) for x in data[:3]] + [abs(data[6])]
        elif kind == "segment":
            vals += [abs(x) for x in data[:6]]
        else:
            vals += [abs(x) for x in data[:3]]
    return max(vals)


# =============================================================================================
# 2. the fast screen
# =============================================================================================
# ---- double-double helpers (float64 arrays), for offsets and the line anchor ------------------
def _two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _quick(a, b):
    s = a + b
    return s, b - (s - a)


def _split(a):
    t = 134217729.0 * a
    hi = t - (t - a)
    return hi, a - hi


def _two_prod(a, b):
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _dd_add(x, y):
    s, e = _two_sum(x[0], y[0])
    return _quick(s, e + x[1] + y[1])


def _dd_mul(x, y):
    p, e = _two_prod(x[0], y[0])
    return _quick(p, e + (x[0] * y[1] + x[1] * y[0]))


def _dd_neg(x):
    return -x[0], -x[1]


def _dd_div(x, y):
    q1 = x[0] / y[0]
    r = _dd_add(x, _dd_neg(_dd_mul((q1, np.zeros_like(q1)), y)))
    q2 = r[0] / y[0]
    r = _dd_add(r, _dd_neg(_dd_mul((q2, np.zeros_like(q2)), y)))
    q3 = r[0] / y[0]
    s = _quick(q1, q2)
    return _dd_add(s, (q3, np.zeros_like(q3)))


def _dd_dot(x, y):
    """x, y: (hi, lo) pairs of (n, 3) arrays."""
    acc = _dd_mul((x[0][:, 0], x[1][:, 0]), (y[0][:, 0], y[1][:, 0]))
    for i in (1, 2):
        acc = _dd_add(acc, _dd_mul((x[0][:, i], x[1][:, i]), (y[0][:, i], y[1][:, i])))
    return acc


def _ld(x):
    return x[0].astype(LD) + x[1].astype(LD)


def _diff_ld(p, q):
    """p - q (float64 arrays) as long double, via the exact double-double difference."""
    return _ld(_two_sum(np.asarray(p, float), -np.asarray(q, float)))


def _ld_frame(N):
    """Unit normal n and in-plane U, V (long double): U from the coordinate axis least aligned with
    n (Gram-Schmidt), V = n x U -- the construction of the references, built independently."""
    Nl = N.astype(LD)
    Nl = Nl / np.max(np.abs(Nl), axis=1, keepdims=True)
    n = Nl / np.sqrt(np.sum(Nl * Nl, axis=1, keepdims=True))
    k = np.argmin(np.abs(n), axis=1)
    e = np.zeros_like(n)
    e[np.arange(len(k)), k] = 1
    u = e - np.sum(e * n, axis=1, keepdims=True) * n
    u = u / np.sqrt(np.sum(u * u, axis=1, keepdims=True))
    return n, u, _cross(n, u)


def _cross(a, b):
    return np.stack([a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
                     a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
                     a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1)


def _dot(a, b):
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def _nrm(a):
    return np.sqrt(_dot(a, a))


# ---- closed forms (any float dtype; arrays broadcast (n, k, 3) against (n, 1, 3)) -------------
def _round_dist(w, n, R, disk, with_rho=False, span=None, inner=None):
    """Distance of the points w (relative to the centre) from the round; with_rho: also their
    distance rho from its axis.  span (an arc: its unit u, v = n x u, angle and whether it is
    the whole circle, broadcast like n, n, R, R): the circle restricted to the angles [0, angle]
    from u -- the ring's distance where the angle phi of w's projection lies in the span (or w is
    on the axis), else the nearer end's (the distance to the ring's point at theta grows with
    |theta - phi| up to pi, so the nearer end in angle is the nearer in distance; both are taken,
    each a genuine point's distance)."""
    z = _dot(w, n)
    a = w - z[..., None] * n
    rho = _nrm(a)
    e = rho - R
    d = np.sqrt(z * z + e * e)
    if disk:
        d = np.where(rho <= R, np.abs(z), d)
    if inner is not None:
        # an annulus (disk=True): over its hole the inner rim's distance (docs/annulus.md (1))
        d = np.where(rho < inner, np.sqrt(z * z + (inner - rho) * (inner - rho)), d)
    if span is not None:
        u, v, ang, whole = span
        phi = np.arctan2(_dot(w, v), _dot(w, u))
        two_pi = 2 * np.arctan2(phi.dtype.type(0), phi.dtype.type(-1))
        phi = np.where(phi < 0, phi + two_pi, phi)
        off = (whole == 0) & (phi > ang) & (rho > 0)
        e0 = _nrm(w - R[..., None] * u)
        e1 = _nrm(w - R[..., None] * (np.cos(ang)[..., None] * u + np.sin(ang)[..., None] * v))
        d = np.where(off, np.minimum(e0, e1), d)
    return (d, rho) if with_rho else d


def _span(P, x1=True):
    """The span parameters of an arc target in P (None for a circle or disk), shaped for
    (n, k) points (x1) or (n,) points."""
    if "tu" not in P:
        return None
    f = _x1 if x1 else (lambda v: v)
    return f(P["tu"]), f(P["tv"]), f(P["tang"]), f(P["twhole"])


def _tdist(X, P, kind, x1=True, with_rho=False):
    """The closed-form distance of the points X from a circle, disk, arc or annulus target whose
    parameters (_rim_parts' "target": n, R, an arc's span, an annulus's inner radius Rin) are in
    P, shaped (n, k) (x1) or (n,)."""
    f = _x1 if x1 else (lambda v: v)
    inner = f(P["Rin"]) if "Rin" in P else None
    return _round_dist(X, f(P["n"]), f(P["R"]), kind in TARGET_REGION, with_rho, span=_span(P, x1), inner=inner)


def _lin_dist(w, m, mm, lo, hi):
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.where(mm > 0, _dot(w, m) / np.where(mm > 0, mm, 1), 0)
    s = np.minimum(np.maximum(s, lo), hi)
    return _nrm(w - s[..., None] * m)


class _P:
    """Per-case parameters of one formulation, in float64 and long double."""

    def __init__(self, **arrays):
        self.ld = {k: (np.asarray(v).astype(LD) if isinstance(v, np.ndarray) else v) for k, v in arrays.items()}
        self.f64 = {k: (np.asarray(v).astype(np.float64) if isinstance(v, np.ndarray) else v)
                    for k, v in arrays.items()}

    def get(self, dtype):
        return self.ld if dtype == LD else self.f64

    def take(self, idx):
        """The parameters of cases idx (repeats allowed): one row per candidate of a flat batch."""
        out = _P.__new__(_P)
        out.ld = {k: (v[idx] if isinstance(v, np.ndarray) else v) for k, v in self.ld.items()}
        out.f64 = {k: (v[idx] if isinstance(v, np.ndarray) else v) for k, v in self.f64.items()}
        return out


def _x1(a):
    """(n, ...) -> (n, 1, ...) for broadcasting against (n, k) parameters."""
    return a[:, None]


class _Form:
    """One formulation: distance = min over a parameter x in [lo, hi] (periodic or not) of
    f(x), f evaluated as  target_closed_form(moving_point(x))."""

    def __init__(self, name, moving, target, params, lo, hi, periodic, grid):
        self.name, self.moving, self.target = name, moving, target
        self.p = params
        self.lo, self.hi, self.periodic, self.grid = lo, hi, periodic, grid

    def take(self, idx):
        """This formulation for cases idx (one row per candidate)."""
        return _Form(self.name, self.moving, self.target, self.p.take(idx), np.asarray(self.lo)[idx],
                     np.asarray(self.hi)[idx], self.periodic, self.grid)

    def points(self, x, P):
        if self.moving == "rim":
            c, s = np.cos(x), np.sin(x)
            return _x1(P["D"]) + _x1(P["Ra"])[..., None] * (c[..., None] * _x1(P["Ua"]) + s[..., None] * _x1(P["Va"]))
        if self.moving == "line":
            return _x1(P["b0"]) + self.line_s(x, P)[..., None] * _x1(P["m"])
        # bezier: Bernstein sum of control points relative to the target centre
        ctrl = P["ctrl"]                       # (n, K, 3)
        k = ctrl.shape[1] - 1
        t = x
        s = 1 - t
        tp, sp = [None, t], [None, s]
        for _ in range(2, k + 1):
            tp.append(tp[-1] * t)
            sp.append(sp[-1] * s)
        out = 0
        for i in range(k + 1):
            w = tp[i] if k == i else (sp[k - i] if i == 0 else tp[i] * sp[k - i])
            c = math.comb(k, i)
            out = out + ((w * c) if c != 1 else w)[..., None] * ctrl[:, None, i, :]
        return out

    @staticmethod
    def line_s(x, P):
        """A line's parameter s at x: x itself, or S0 sinh(x) clamped to the piece's interval
        [slo, shi] (the pairs among linear pieces: uniform steps in x are steps by a constant
        ratio in s, every magnitude of s from S0 to the window's ends alike; the clamp keeps the
        rounding of sinh(asinh(lo / S0)) on the piece)."""
        if "S0" not in P:
            return x
        S0, lo, hi = (P[k] if np.ndim(x) == 1 else _x1(P[k]) for k in ("S0", "slo", "shi"))
        return np.minimum(np.maximum(S0 * np.sinh(x), lo), hi)

    def value(self, x, P):
        X = self.points(x, P)
        if self.target in RIMS:
            return _tdist(X, P, self.target)
        d = _lin_dist(X - _x1(P["tb0"]), _x1(P["tm"]), _x1(P["tmm"]), _x1(P["tlo"]), _x1(P["thi"]))
        if "mperp" not in P:
            return d
        inside, s = self.perp_inside(x, P)
        return np.where(inside, _nrm(_x1(P["cperp"]) + s[..., None] * _x1(P["mperp"])), d)

    def perp_inside(self, x, P):
        """(a line against a linear target with _perp_parts) whether the target's projection of
        the point lies inside the target by more than its rounding (there the perpendicular form
        holds), and the line's parameter s."""
        s = self.line_s(x, P)
        x1 = (lambda k: P[k]) if np.ndim(x) == 1 else (lambda k: _x1(P[k]))
        st = (x1("cu") + s * x1("mu")) / x1("uu")
        margin = 64 * EPSLD * (np.abs(x1("cu")) + np.abs(s * x1("mu"))) / x1("uu")
        return (st - margin >= x1("tlo")) & (st + margin <= x1("thi")), s

    def f(self, x):
        P = self.p.get(x.dtype.type)
        with np.errstate(invalid="ignore", over="ignore"):
            v = self.value(x, P)
        return np.where(np.isnan(v), np.inf, v)

    def f_rho(self, x):
        """f and the points' distance from the (round) target's axis, for the zoom."""
        P = self.p.get(x.dtype.type)
        if self.target not in RIMS:
            # a point or a linear piece: its local minima lie apart by about the distance itself
            # (see reference_round.bezier_other), which stands in for rho
            v = self.f(x)
            return v, v
        with np.errstate(invalid="ignore", over="ignore"):
            v, rho = _tdist(self.points(x, P), P, self.target, with_rho=True)
        return np.where(np.isnan(v), np.inf, v), rho

    def magnitude(self, x):
        """Size of the quantities that cancel at x (for the rounding slack)."""
        P = self.p.get(LD)
        X = self.points(x[:, None], P)[:, 0]
        mag = _nrm(X)
        if self.target in RIMS:
            mag = mag + P["R"]
        else:
            mag = mag + _nrm(P["tb0"])
        if "mperp" in P:
            # the perpendicular parts are double-double results (2^-100 of what they cancel:
            # |m_perp| = |m| sin(angle), 1e-17 |m| for pieces parallel within 1e-17)
            inside, s = self.perp_inside(x, P)
            full = _nrm(P["b0"]) + np.abs(s) * _nrm(P["m"])
            return np.where(inside, _nrm(P["cperp"]) + np.abs(s) * _nrm(P["mperp"])
                            + LD(2.0 ** -100 / (16 * EPSLD)) * (full + _nrm(P["tb0"])), mag + full)
        if self.moving == "rim":
            mag = mag + _nrm(P["D"]) + P["Ra"]
        elif self.moving == "line":
            mag = mag + _nrm(P["b0"]) + np.abs(self.line_s(x, P)) * _nrm(P["m"])
        else:
            ctrl = P["ctrl"]
            k = ctrl.shape[1] - 1
            t = x
            mag = mag + sum(math.comb(k, i) * t ** i * (1 - t) ** (k - i) * _nrm(ctrl[:, i, :]) for i in range(k + 1))
        return mag


_THETA_GRID = np.arange(512) / 512.0


def _bezier_grid():
    """Normalised samples of a half curve [0, 1/2] (the grid is scaled by the interval): uniform,
    plus samples clustered at the end the half is parametrised from."""
    u = np.linspace(0, 1, 385)
    ends = 10.0 ** -np.arange(1, 20.05, 0.1)
    return np.unique(np.concatenate([u, ends]))


_T_GRID = _bezier_grid()
_S_GRID = np.linspace(0, 1, 513)


def _beam(form, lo, hi, beam, levels, K, dtype, start=None):
    """Nested re-sampling: keep the `beam` best sampled local minima per case, re-sample each
    bracket at K+1 points per level.  start: (a, b) brackets (n, m) to begin from instead of the
    grid.  Returns (best value, best x, final bracket centres (n, beam), their values)."""
    n = lo.shape[0]
    lo, hi = lo.astype(dtype), hi.astype(dtype)
    w = hi - lo
    inf = dtype(np.inf)
    if start is None:
        g = form.grid.astype(dtype)
        X = lo[:, None] + g[None, :] * w[:, None]
        if not form.periodic:
            X[:, -1] = hi
        F = form.f(X)
        if form.periodic:
            Fl, Fr = np.roll(F, 1, 1), np.roll(F, -1, 1)
            Xl = np.concatenate([X[:, -1:] - w[:, None], X[:, :-1]], 1)
            Xr = np.concatenate([X[:, 1:], X[:, :1] + w[:, None]], 1)
        else:
            pad = np.full((n, 1), inf, dtype=dtype)
            Fl, Fr = np.concatenate([pad, F[:, :-1]], 1), np.concatenate([F[:, 1:], pad], 1)
            Xl = np.concatenate([X[:, :1], X[:, :-1]], 1)
            Xr = np.concatenate([X[:, 1:], X[:, -1:]], 1)
        # sampled local minima; a run of equal samples counts once (strict on the right), so that
        # plateaus (a curve's end point sampled at clustered parameters, a flat function) do not
        # fill the beam; a row without any (a flat periodic function) keeps its smallest sample
        lm = (F <= Fl) & (F < Fr)
        none = ~lm.any(axis=1)
        lm[none, np.argmin(F[none], axis=1)] = True
        Fm = np.where(lm, F, inf)
        idx = np.argsort(Fm, axis=1, kind="stable")[:, :beam]
        a = np.take_along_axis(Xl, idx, 1)
        b = np.take_along_axis(Xr, idx, 1)
        va = np.take_along_axis(Fm, idx, 1)
        j = np.argmin(F, axis=1)
        best_v = F[np.arange(n), j]
        best_x = X[np.arange(n), j]
        centres = np.take_along_axis(X, idx, 1)
    else:
        a, b = start
        a, b = a.astype(dtype), b.astype(dtype)
        va = np.zeros(a.shape, dtype=dtype)
        best_v = np.full(n, inf, dtype=dtype)
        best_x = a[:, 0].copy()
        centres = (a + b) / 2
    tt = np.linspace(0, 1, K + 1).astype(dtype)
    m = a.shape[1]
    for _ in range(levels):
        h = (b - a) / K
        P = a[..., None] + (b - a)[..., None] * tt
        if not form.periodic:
            P = np.minimum(np.maximum(P, lo[:, None, None]), hi[:, None, None])
        V = form.f(P.reshape(n, -1)).reshape(n, m, K + 1)
        V = np.where(np.isfinite(va)[..., None], V, inf)
        padc = np.full((n, m, 1), inf, dtype=dtype)
        lm = (V <= np.concatenate([padc, V[..., :-1]], 2)) & (V < np.concatenate([V[..., 1:], padc], 2))
        Vm = np.where(lm, V, inf).reshape(n, -1)
        flat = ~np.isfinite(Vm).any(axis=1)
        if flat.any():
            Vr = V.reshape(n, -1)
            Vm[flat, np.argmin(Vr[flat], axis=1)] = Vr[flat].min(axis=1)
        jj = np.argsort(Vm, axis=1, kind="stable")[:, :beam]
        bi, kk = np.divmod(jj, K + 1)
        Pf = P.reshape(n, -1)
        hb = np.take_along_axis(h, bi, 1)
        centres = np.take_along_axis(Pf, jj, 1)
        lo_i = np.where(kk > 0, np.take_along_axis(Pf, np.maximum(jj - 1, 0), 1), centres - hb)
        hi_i = np.where(kk < K, np.take_along_axis(Pf, np.minimum(jj + 1, Pf.shape[1] - 1), 1), centres + hb)
        a, b = lo_i, hi_i
        if not form.periodic:
            a = np.maximum(a, lo[:, None])
            b = np.minimum(b, hi[:, None])
        va = np.take_along_axis(Vm, jj, 1)
        m = a.shape[1]
        j = np.argmin(V.reshape(n, -1), axis=1)
        v = V.reshape(n, -1)[np.arange(n), j]
        better = v < best_v
        best_v = np.where(better, v, best_v)
        best_x = np.where(better, Pf[np.arange(n), j], best_x)
    return best_v, best_x, centres, va


# The zoom: a uniform scan of a shape far larger than the other one (a curve 2e4 long passing a
# ring of radius 0.8, a huge circle passing a small disk) has steps much longer than the other
# shape, so two local minima a fraction of its size apart fall between the same two samples and a
# search from the best sample finds one of them, possibly the higher (5.9e-13 higher for the far
# curve of tests/test_regressions.py::test_far_curve_near_tied_minima, below float64's resolution
# of a point 2e4 away, so no float64 ranking can choose between them).  The zoom re-samples, in
# float64, every interval that could hold a value below the best sample until one step moves the
# point by at most max(R, rho) / ZOOM_FRACTION (R the target round's radius, rho the distance from
# its axis: the scale on which the distance to the round can have distinct local minima, see
# reference_round._feature_scale), and hands EVERY sampled local minimum (the ZOOM_KEEP lowest
# per case) to the long-double stage, each refined on its own.
ZOOM_FRACTION = 8     # resolution: max(R, rho) / this
ZOOM_SPLIT = 8        # pieces per split interval and pass
ZOOM_PASSES = 24      # 8^24: from a grid step to ~1e-22 of it
ZOOM_CAP = 2048       # intervals split per case and pass (lowest bounds first; reached only by
                      # curves with a control point 1e6+ away, which the value-driven beam covers)
ZOOM_KEEP = 6         # sampled local minima per case refined in long double


def _zoom(form, lo, hi, lip, R):
    """Lipschitz zoom of form on [lo, hi] (float64 arrays (n,)).  lip(c, a, b): a bound on the
    point's speed |dX/dx| on the intervals [a, b] of cases c (flat arrays); R (n,): the target
    round's radius.  f is 1-Lipschitz in the moving point, so nothing on [a, b] lies below
    (f(a) + f(b))/2 - L (b - a)/2: intervals above the best sample are dropped, the others split
    until L (b - a) <= max(R, rho) / ZOOM_FRACTION (rho: a lower bound of the distance from the
    target's axis on [a, b]).  Returns flat candidates (case, x, half-width h, value): the
    ZOOM_KEEP lowest sampled local minima of each case (h: the step around it; the minimum lies
    in [x - h, x + h]), and zoomed (n,): whether a case needed any split."""
    n = lo.shape[0]
    w = hi - lo
    X = lo[:, None] + form.grid[None, :] * w[:, None]
    if form.periodic:  # the interval that wraps round, closed by the first sample one period on
        X = np.concatenate([X, X[:, :1] + w[:, None]], 1)
    else:
        X[:, -1] = hi
    F, RHO = form.f_rho(X)
    RHO = RHO.astype(float)
    best = F.min(axis=1)
    G = X.shape[1]
    c = np.repeat(np.arange(n), G - 1)
    a, b = X[:, :-1].ravel(), X[:, 1:].ravel()
    fa, fb = F[:, :-1].ravel(), F[:, 1:].ravel()
    ra, rb = RHO[:, :-1].ravel(), RHO[:, 1:].ravel()
    zoomed = np.zeros(n, dtype=bool)
    done = []
    tt = np.arange(1, ZOOM_SPLIT) / ZOOM_SPLIT
    for pass_ in range(ZOOM_PASSES + 1):
        lh = lip(c, a, b) * (b - a)
        lb = (fa + fb - lh) / 2
        alive = lb <= best[c]
        res = np.maximum(R[c], np.minimum(ra, rb) - lh / 2) / ZOOM_FRACTION
        split = alive & (lh > res) & (pass_ < ZOOM_PASSES)
        fin = alive & ~split
        done.append((c[fin], a[fin], b[fin], fa[fin], fb[fin], lb[fin]))
        if not split.any():
            break
        c, a, b, fa, fb, ra, rb, lb = (v[split] for v in (c, a, b, fa, fb, ra, rb, lb))
        zoomed[c] = True
        # at most ZOOM_CAP per case, the lowest bounds first (c is sorted: intervals stay in order)
        order = np.lexsort((lb, c))
        rank = np.empty(len(c), dtype=np.int64)
        rank[order] = np.arange(len(c)) - np.searchsorted(c[order], c[order])
        keep = rank < ZOOM_CAP
        c, a, b, fa, fb, ra, rb = (v[keep] for v in (c, a, b, fa, fb, ra, rb))
        P = a[:, None] + (b - a)[:, None] * tt
        V, RH = form.take(c).f_rho(P)
        np.minimum.at(best, c, V.min(axis=1))
        XX = np.concatenate([a[:, None], P, b[:, None]], 1)
        FF = np.concatenate([fa[:, None], V, fb[:, None]], 1)
        RR = np.concatenate([ra[:, None], RH.astype(float), rb[:, None]], 1)
        c = np.repeat(c, ZOOM_SPLIT)
        a, b = XX[:, :-1].ravel(), XX[:, 1:].ravel()
        fa, fb = FF[:, :-1].ravel(), FF[:, 1:].ravel()
        ra, rb = RR[:, :-1].ravel(), RR[:, 1:].ravel()
    c, a, b, fa, fb, lb = (np.concatenate(v) for v in zip(*done))
    live = lb <= best[c]       # the best sample kept falling: drop what it now excludes
    c, a, b, fa, fb = (v[live] for v in (c, a, b, fa, fb))
    # the samples (both ends of the intervals kept), in order per case, each with its step
    h = b - a
    cc, xx, ff, hh = np.concatenate([c, c]), np.concatenate([a, b]), np.concatenate([fa, fb]), np.concatenate([h, h])
    if form.periodic:
        xx = np.where(xx >= hi[cc], xx - w[cc], xx)
    order = np.lexsort((xx, cc))
    cc, xx, ff, hh = cc[order], xx[order], ff[order], hh[order]
    first = np.ones(len(cc), dtype=bool)
    first[1:] = (cc[1:] != cc[:-1]) | (xx[1:] != xx[:-1])
    starts = np.flatnonzero(first)
    hh = np.maximum.reduceat(hh, starts)      # a sample between a fine and a coarse interval: both sides
    cc, xx, ff = cc[starts], xx[starts], ff[starts]
    # sampled local minima; a run of equal samples counts once (strict on the right); at the ends
    # of a case's samples the neighbour is the other end (periodic) or nothing
    m = len(cc)
    gs = np.ones(m, dtype=bool)
    gs[1:] = cc[1:] != cc[:-1]
    ge = np.ones(m, dtype=bool)
    ge[:-1] = cc[1:] != cc[:-1]
    gstart = np.maximum.accumulate(np.where(gs, np.arange(m), 0))
    gend = np.minimum.accumulate(np.where(ge, np.arange(m), m)[::-1])[::-1]
    prev = np.where(gs, gend, np.arange(m) - 1)
    nxt = np.where(ge, gstart, np.arange(m) + 1)
    fprev = np.where(gs & (not form.periodic), np.inf, ff[prev])
    fnext = np.where(ge & (not form.periodic), np.inf, ff[nxt])
    lm = (ff <= fprev) & (ff < fnext)
    has = np.zeros(n, dtype=bool)
    has[cc[lm]] = True
    lm |= ~has[cc] & (ff == best[cc])           # a flat case: its best sample
    cc, xx, ff, hh = cc[lm], xx[lm], ff[lm], hh[lm]
    order = np.lexsort((ff, cc))
    cc, xx, ff, hh = cc[order], xx[order], ff[order], hh[order]
    rank = np.arange(len(cc)) - np.searchsorted(cc, cc)
    keep = rank < ZOOM_KEEP
    return (cc[keep], xx[keep], hh[keep], ff[keep]), zoomed


def _refine_ld(form, cc, a, b, ld_levels, K):
    """Long-double beam search of form on the brackets [a, b] of cases cc (flat: one row per
    candidate, each refined on its own).  Returns (value, x) per row."""
    sub = form.take(cc)
    lo, hi = np.asarray(sub.lo, dtype=LD), np.asarray(sub.hi, dtype=LD)
    vv, xx, _, _ = _beam(sub, lo, hi, 2, ld_levels, K, LD, start=(a[:, None], b[:, None]))
    return vv, xx


def _least(n, cc, v, *cols):
    """Per case (0..n-1) the row of cc with the least v: (has a row, v, cols...) per case."""
    order = np.lexsort((v, cc))
    cc_s = cc[order]
    first = np.ones(len(cc_s), dtype=bool)
    first[1:] = cc_s[1:] != cc_s[:-1]
    pick = order[first]
    has = np.zeros(n, dtype=bool)
    has[cc[pick]] = True
    outs = []
    for col in (v,) + cols:
        o = np.zeros(n, dtype=col.dtype)
        o[cc[pick]] = col[pick]
        outs.append(o)
    return (has, *outs)


def _minimize(form, lo, hi, beam=5, levels=14, ld_levels=30, K=8, use_ld=True, lip=None, R=None):
    """Float64 beam search from the grid, then (use_ld) long-double levels around the two best
    final brackets; with lip/R (see _zoom) the cases whose grid is too coarse for R are zoomed
    too and each of their sampled local minima is refined in long double on its own.  Returns
    (value (long double), x (long double))."""
    n = lo.shape[0]
    v64, x64, centres, vals = _beam(form, lo, hi, beam, levels, K, np.float64)
    zc = None
    if lip is not None:
        (zc, zx, zh, zf), zoomed = _zoom(form, lo.astype(float), hi.astype(float), lip, R)
        sel = zoomed[zc]
        zc, zx, zh, zf = zc[sel], zx[sel], zh[sel], zf[sel]
        if not use_ld and len(zc):
            has, zv, zxx = _least(n, zc, zf, zx)
            better = has & (zv < v64)
            v64, x64 = np.where(better, zv, v64), np.where(better, zxx, x64)
    xl = x64.astype(LD)
    vl = form.f(xl[:, None])[:, 0] if use_ld else v64.astype(LD)
    if not use_ld:
        return vl, xl
    width = (hi - lo).astype(LD)
    hw = np.maximum(width * LD(1e-7), LD(0))[:, None]
    order = np.argsort(vals, axis=1, kind="stable")[:, :2]
    cx = np.take_along_axis(centres, order, 1).astype(LD)
    a, b = cx - hw, cx + hw
    vv, xx, _, _ = _beam(form, lo.astype(LD), hi.astype(LD), 2, ld_levels, K, LD, start=(a, b))
    better = vv < vl
    vl, xl = np.where(better, vv, vl), np.where(better, xx, xl)
    if zc is not None and len(zc):
        zv, zxx = _refine_ld(form, zc, (zx - zh).astype(LD), (zx + zh).astype(LD), ld_levels, K)
        has, zv, zxx = _least(n, zc, zv, zxx)
        better = has & (zv < vl)
        vl, xl = np.where(better, zv, vl), np.where(better, zxx, xl)
    return vl, xl


def _sub_bezier_dd(ctrl_dd, a, b):
    """Control points (long double) of the piece of the curve on [a, b] (a, b: float64 arrays):
    Q_j = blossom(a, .., a, b, .., b) (k - j a's, j b's) by de Casteljau steps in double-double,
    so the piece is the same curve up to ~1e-32 of the control points' size."""
    hi, lo = ctrl_dd
    k = hi.shape[1] - 1
    out = []
    for j in range(k + 1):
        ph, pl = hi, lo
        for tau in [a] * (k - j) + [b] * j:
            t = np.broadcast_to(tau[:, None, None], ph[:, 1:].shape)
            d = _dd_add((ph[:, 1:], pl[:, 1:]), (-ph[:, :-1], -pl[:, :-1]))
            d = _dd_mul(d, (t, np.zeros(t.shape)))
            ph, pl = _dd_add((ph[:, :-1], pl[:, :-1]), d)
        out.append(_ld((ph[:, 0], pl[:, 0])))
    return np.stack(out, axis=1)


def _lipschitz(dP, a, b):
    """Bound on |B'(t)| for t in [a, b] (arrays (n, m)): B' = k sum_i b_{i,k-1}(t) (P_{i+1} - P_i),
    and each Bernstein basis function is unimodal with its maximum at i/(k-1), so
    |B'| <= k sum_i |P_{i+1} - P_i| max_[a,b] b_{i,k-1}."""
    k = dP.shape[1]
    if k == 1:
        return np.broadcast_to(dP[:, :1], a.shape)
    out = 0
    for i in range(k):
        t = np.clip(i / (k - 1), a, b)
        out = out + dP[:, i:i + 1] * (math.comb(k - 1, i) * t ** i * (1 - t) ** (k - 1 - i))
    return k * out * (1 + 1e-9)


def _minimize_bezier(form, ctrl_dd, target, res, ld_levels=30, K=8):
    """A half curve: float64 value-driven beam search and zoom (_zoom) on t in [0, 1/2], then a
    long-double search of every candidate on its own piece of the curve, re-parametrised on
    [0, 1] with its control points computed in double-double (a curve 1e5 times larger than the
    round is then resolved to ~1e-19 of the round, not of the curve): the pieces [t - h, t + h]
    around the zoom's sampled local minima (h its step there) and [t - 5e-8, t + 5e-8] around the
    beam's three best.  target: the target's parameters (n, R of a round; _linear_target's of a
    linear piece) per case; res: the zoom's resolution scale per case (a round's radius).
    Returns (value, a, b, u, magnitude) with the best point at t = a + u (b - a)."""
    n = ctrl_dd[0].shape[0]
    lo, hi = np.zeros(n), np.full(n, 0.5)
    P64 = ctrl_dd[0] + ctrl_dd[1]
    dP = np.linalg.norm(np.diff(P64, axis=1), axis=2)                   # (n, k) hodograph norms
    # two searches: a value-driven beam (follows the sampled minima: curves with a far control
    # point, whose Lipschitz bound is useless away from the ends) and the zoom (keeps every local
    # minimum: curves much larger than the round)
    # (several crossings of a rim by a curve in a plane just above it are near-ties: the beam is
    # wider, and keeps its three best)
    vb, xb, bcentres, bvals = _beam(form, lo, hi, 8, 14, K, np.float64)
    (zc, zx, zh, _), _ = _zoom(form, lo, hi, lambda c, a, b: _lipschitz(dP[c], a[:, None], b[:, None])[:, 0],
                               np.asarray(res, dtype=float))
    border = np.argsort(bvals, axis=1, kind="stable")
    beam_x = [xb] + [np.take_along_axis(bcentres, border[:, q:q + 1], 1)[:, 0] for q in (1, 2)
                     if q < border.shape[1]]
    cc = np.concatenate([zc] + [np.arange(n)] * len(beam_x))
    tc = np.concatenate([zx] + beam_x)
    hw = np.concatenate([np.maximum(zh, 5e-8)] + [np.full(n, 5e-8)] * len(beam_x))
    a = np.maximum(tc - hw, 0.0)
    b = np.minimum(tc + hw, 0.5)
    Q = _sub_bezier_dd((ctrl_dd[0][cc], ctrl_dd[1][cc]), a, b)
    m = len(cc)
    sub = _Form(form.name, "bezier", form.target, _P(ctrl=Q, **{k: v[cc] for k, v in target.items()}), np.zeros(m),
                np.ones(m), False, _S_GRID)
    vv, uu, _, _ = _beam(sub, np.zeros(m, dtype=LD), np.ones(m, dtype=LD), 2, ld_levels, K, LD,
                         start=(np.zeros((m, 1)), np.ones((m, 1))))
    # the candidate itself (a sampled end point can be the best point seen)
    u0 = ((tc - a) / np.where(b > a, b - a, 1)).astype(LD)
    v0 = sub.f(u0[:, None])[:, 0]
    take0 = v0 < vv
    vv, uu = np.where(take0, v0, vv), np.where(take0, u0, uu)
    mag = sub.magnitude(uu)
    _, best, ba, bb, bu, bm = _least(n, cc, vv, a, b, uu, mag)
    return best, ba, bb, bu, bm


def _stack(case_list, key):
    return np.array([c[key] for c in case_list], dtype=float)


def _anchor(kind, data, C, dd=False):
    """A linear shape relative to the centre C, anchored at its point nearest C (double-double):
    returns long-double b0, m, lo, hi with S = {b0 + s m : s in [lo, hi]} (dd: and b0, m as
    double-double pairs of (n, 3) arrays)."""
    n = data.shape[0]
    zeros = np.zeros((n, 3))
    b = _two_sum(data[:, :3], -C)
    if kind == "point":
        out = _ld(b), np.zeros((n, 3), dtype=LD), np.zeros(n, dtype=LD), np.zeros(n, dtype=LD)
        return out + (b, (zeros, zeros)) if dd else out
    if kind == "segment":
        m = _two_sum(data[:, 3:6], -data[:, :3])
    else:
        m = (data[:, 3:6].copy(), zeros)
    # scale m to moderate length exactly (a power of two) so that squares neither overflow nor underflow
    sc = 2.0 ** -np.floor(np.log2(np.maximum(np.max(np.abs(m[0]), axis=1), 1e-300)))
    m = (m[0] * sc[:, None], m[1] * sc[:, None])
    mm = _dd_dot(m, m)
    bm = _dd_dot(b, m)
    ok = mm[0] > 0
    safe = (np.where(ok, mm[0], 1.0), np.where(ok, mm[1], 0.0))
    tc = _dd_neg(_dd_div(bm, safe))
    tc = (np.where(ok, tc[0], 0.0), np.where(ok, tc[1], 0.0))
    b0 = tuple(np.stack(c, axis=1) for c in zip(*[
        _dd_add((b[0][:, i], b[1][:, i]), _dd_mul(tc, (m[0][:, i], m[1][:, i]))) for i in range(3)]))
    lo_raw = {"line": -np.inf, "ray": 0.0, "segment": 0.0}[kind]
    hi_raw = {"line": np.inf, "ray": np.inf, "segment": 1.0}[kind]
    tcl = _ld(tc)
    lo = (LD(lo_raw) / LD(1)) * np.ones(n, dtype=LD)
    hi = LD(hi_raw) * np.ones(n, dtype=LD)
    lo = lo - tcl
    if kind == "segment":
        # The far end's parameter from its own offset, (p1 - C).m / m.m in double-double: as
        # 1/sc - tc it cancelled to eps * 1e10 along a segment whose other end is 1e10 away.
        th = _dd_div(_dd_dot(_two_sum(data[:, 3:6], -C), m), safe)
        hi = np.where(ok, _ld(th), LD(0))
    else:
        hi = hi - tcl
    return (_ld(b0), _ld(m), lo, hi) + ((b0, m) if dd else ())


def _linear_target(kind, data, C):
    b0, m, lo, hi = _anchor(kind, data, C)
    return dict(tb0=b0, tm=m, tmm=np.sum(m * m, axis=1), tlo=lo, thi=hi)


def _window(b0, m, lo, hi, R):
    """Parameter window holding every minimiser of s -> dist(b0 + s m, round)."""
    mm = np.sum(m * m, axis=1)
    s0 = np.minimum(np.maximum(LD(0), lo), hi)
    dref = _nrm(b0 + s0[:, None] * m)
    b2 = np.sum(b0 * b0, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        W = np.sqrt(np.maximum((dref + 2 * R) ** 2 - b2, 0) / np.where(mm > 0, mm, 1)) * LD(1.001)
    W = np.where(mm > 0, W, 0) + LD(1e-30) * (1 + np.abs(s0))
    wlo = np.minimum(np.maximum(-W, lo), hi)
    whi = np.minimum(np.maximum(W, lo), hi)
    return wlo, whi


def _rim_parts(kind, data):
    """A circle's, disk's or arc's screen parameters (long double) from its data rows (n, 7; an
    arc's n, 11): the normal n; the moving rim's basis (U, V), interval [0, hi], periodicity and
    grid (a circle: the frame of _ld_frame, [0, 2 pi) periodic; an arc: u, the unit projection of
    its start, v = n x u, [0, angle] with both ends sampled, the whole [0, 2 pi] for an angle of
    at least float64's 2 pi); target: the parameters of its closed form (an arc's span too)."""
    n, U, V = _ld_frame(data[:, 3:6])
    Rl = data[:, 6].astype(LD)
    m = len(data)
    target = dict(n=n, R=Rl)
    if kind == "annulus":
        # (its inner rim moves too: "inner"; its features' scale, for the zooms: the least of its
        # positive radii and width)
        Rin = data[:, 7].astype(LD)
        target.update(Rin=Rin)
        width = data[:, 6] - data[:, 7]
        feat = np.min(np.where(np.stack([data[:, 7], width]) > 0, np.stack([data[:, 7], width]), np.inf), axis=0)
        return dict(n=n, U=U, V=V, R=Rl, inner=Rin, feature=np.minimum(data[:, 6], feat), hi=np.full(m, 2 * math.pi),
                    periodic=True, grid=_THETA_GRID, target=target)
    if kind != "arc":
        return dict(n=n, U=U, V=V, R=Rl, hi=np.full(m, 2 * math.pi), periodic=True, grid=_THETA_GRID,
                    target=target, feature=data[:, 6])
    S = data[:, 7:10].astype(LD)
    S = S / np.max(np.abs(S), axis=1, keepdims=True)
    u = S - _dot(S, n)[:, None] * n
    u = u / _nrm(u)[:, None]
    v = _cross(n, u)
    ang = data[:, 10]
    whole = ang >= 2 * math.pi
    target.update(tu=u, tv=v, tang=ang.astype(LD), twhole=whole.astype(float))
    return dict(n=n, U=u, V=v, R=Rl, hi=np.where(whole, 2 * math.pi, ang), periodic=False, grid=_S_GRID,
                target=target, feature=data[:, 6])


class ScreenResult:
    """value: long-double upper bound per case; slack: its rounding allowance; how: (form name,
    parameter as long double) of the best pair, for a 50-digit re-evaluation."""

    def __init__(self, value, slack, forms, params):
        self.value, self.slack, self.forms, self.params = value, slack, forms, params


def screen(cases, use_ld=True):
    """Screen upper bounds for cases of ONE kind pair (canonical order, same number of Bezier
    control points).  use_ld=False (float32 scenes, whose bar is far coarser) skips the
    long-double stage except for Bezier curves."""
    with np.errstate(all="ignore"):
        return _screen(cases, use_ld)


def _screen(cases, use_ld):
    ka, kb = cases[0]["a"], cases[0]["b"]
    if kb in LINEAR:
        return _screen_bezier_linear(cases) if ka == "bezier" else _screen_linear(cases, use_ld)
    n = len(cases)
    B = _stack(cases, "b_data")
    Cb, Rb = B[:, :3], B[:, 6]
    rb = _rim_parts(kb, B)
    nb, Ub, Vb, Rbl, tb = rb["n"], rb["U"], rb["V"], rb["R"], rb["target"]
    forms = []
    if ka == "point":
        A = _stack(cases, "a_data")
        w = _diff_ld(A[:, :3], Cb)
        v = _tdist(w[:, None], tb, kb)[:, 0]
        slack = 16 * EPSLD * (_nrm(w) + Rbl)
        return ScreenResult(v, slack.astype(float), ["point"] * n, [LD(0)] * n)
    if ka in ("line", "ray", "segment"):
        A = _stack(cases, "a_data")
        tgt = _linear_target(ka, A, Cb)
        # (1) the round's rim (an arc's: over its span) against the linear shape's closed form
        p1 = _P(D=np.zeros((n, 3), dtype=LD), Ra=Rbl, Ua=Ub, Va=Vb, **tgt)
        forms.append(_Form("rim|linear", "rim", "linear", p1, np.zeros(n), rb["hi"], rb["periodic"], rb["grid"]))
        zooms = [None]
        if "inner" in rb:
            # (1') an annulus's inner rim too (every form is an upper bound from genuine points)
            p1i = _P(D=np.zeros((n, 3), dtype=LD), Ra=rb["inner"], Ua=Ub, Va=Vb, **tgt)
            forms.append(_Form("rim_inner|linear", "rim", "linear", p1i, np.zeros(n), rb["hi"], True, rb["grid"]))
            zooms.append(None)
        # (2) the linear shape's parameter against the round's (the arc's) closed form
        wlo, whi = _window(tgt["tb0"], tgt["tm"], tgt["tlo"], tgt["thi"], Rbl)
        p2 = _P(b0=tgt["tb0"], m=tgt["tm"], **tb)
        forms.append(_Form("line|round", "line", kb, p2, wlo, whi, False, _S_GRID))
        # (the point moves by |m| per unit of s; the rim's own form is sampled at 1/80 of its radius)
        speed = np.sqrt(tgt["tmm"].astype(float))
        zooms.append((lambda c, a, b: speed[c], rb["feature"]))
    elif ka == "bezier":
        # two halves, each parametrised from its end (t on [0, 1/2], and s = 1 - t on [0, 1/2] with
        # the control points reversed): parameters near an end keep their full relative precision,
        # which a curve with a control point 1e12 away needs (there 1 ulp of t near 1 moves the
        # point by 1e-4)
        ctrl = np.array([c["a_data"] for c in cases], dtype=float)       # (n, K, 3)
        rel_dd = _two_sum(ctrl, -Cb[:, None, :])                          # exact
        best = np.full(n, LD(np.inf), dtype=LD)
        names, params = [None] * n, [None] * n
        slack = np.zeros(n)
        for name, order in (("bezier|round", slice(None)), ("bezier_reversed|round", slice(None, None, -1))):
            dd = (rel_dd[0][:, order, :].copy(), rel_dd[1][:, order, :].copy())
            form = _Form(name, "bezier", kb, _P(ctrl=_ld(dd), **tb), np.zeros(n), np.full(n, 0.5), False,
                         _T_GRID)
            # (always refined in long double: a float32 scene of a curve 1e5 times larger than the
            # round needs it for the float32 bar too)
            v, a, b, u, mag = _minimize_bezier(form, dd, tb, rb["feature"].astype(LD))
            for j in np.flatnonzero(v < best):
                best[j], names[j], params[j] = v[j], name, (float(a[j]), float(b[j]), LD(u[j]))
                slack[j] = 16 * EPSLD * float(mag[j])
        return ScreenResult(best, slack, names, params)
    else:
        # two rounds (or arcs): each one's rim (an arc's over its span) against the other's closed form
        A = _stack(cases, "a_data")
        Ca, Ra = A[:, :3], A[:, 6]
        ra = _rim_parts(ka, A)
        Dab = _diff_ld(Ca, Cb)
        pa = _P(D=Dab, Ra=ra["R"], Ua=ra["U"], Va=ra["V"], **tb)
        forms.append(_Form("rim_a|b", "rim", kb, pa, np.zeros(n), ra["hi"], ra["periodic"], ra["grid"]))
        pb = _P(D=-Dab, Ra=Rbl, Ua=Ub, Va=Vb, **ra["target"])
        forms.append(_Form("rim_b|a", "rim", ka, pb, np.zeros(n), rb["hi"], rb["periodic"], rb["grid"]))
        # a rim point moves by its radius per radian (a huge circle passing a small round)
        zooms = [(lambda c, a, b: Ra[c], rb["feature"]), (lambda c, a, b: Rb[c], ra["feature"])]
        # an annulus's inner rim against the other's closed form too
        if "inner" in ra:
            Ria = A[:, 7]
            pai = _P(D=Dab, Ra=ra["inner"], Ua=ra["U"], Va=ra["V"], **tb)
            forms.append(_Form("rim_a_inner|b", "rim", kb, pai, np.zeros(n), ra["hi"], True, ra["grid"]))
            zooms.append((lambda c, a, b: Ria[c], rb["feature"]))
        if "inner" in rb:
            Rib = B[:, 7]
            pbi = _P(D=-Dab, Ra=rb["inner"], Ua=Ub, Va=Vb, **ra["target"])
            forms.append(_Form("rim_b_inner|a", "rim", ka, pbi, np.zeros(n), rb["hi"], True, rb["grid"]))
            zooms.append((lambda c, a, b: Rib[c], ra["feature"]))
    best = np.full(n, LD(np.inf), dtype=LD)
    best_x = np.zeros(n, dtype=LD)
    best_f = np.zeros(n, dtype=int)
    slack = np.zeros(n)
    for fi, form in enumerate(forms):
        lip, R = zooms[fi] or (None, None)
        v, x = _minimize(form, np.asarray(form.lo, dtype=LD), np.asarray(form.hi, dtype=LD), use_ld=use_ld,
                         lip=lip, R=R)
        better = v < best
        best = np.where(better, v, best)
        best_x = np.where(better, x, best_x)
        best_f = np.where(better, fi, best_f)
    for fi, form in enumerate(forms):
        sel = best_f == fi
        if sel.any():
            mag = form.magnitude(best_x)
            slack = np.where(sel, (16 * EPSLD if use_ld else 16 * EPS64) * mag.astype(float), slack)
    return ScreenResult(best, slack, [forms[i].name for i in best_f], list(best_x))


# ---- pairs without a round: linear pieces among themselves, Bezier curves against them ---------
_SINH_SPAN = LD(1e22)    # the line parameter's window: S0 = r / (|m| _SINH_SPAN) .. r _SINH_SPAN / |m|
LINEAR_PASSES = 5        # re-anchored searches of a linear pair (see _screen_linear)


def _segment_extent(tgt):
    """The linear target's finite extent |m| (hi - lo) (0 for points, lines and rays)."""
    ext = np.sqrt(tgt["tmm"]) * (tgt["thi"] - tgt["tlo"])
    return np.where(np.isfinite(ext), ext, LD(0))


def _screen_linear(cases, use_ld):
    """Two linear pieces (a the earlier kind).  A point: the closed form against b, anchored at
    its point nearest the point in double-double.  Otherwise a's parameter against b's closed
    form, s = S0 sinh(x) (every magnitude of s alike: a convex function of s, unimodal in x; the
    window +-1e22 r / |m|, r the size of the anchors' offsets, holds the minimiser unless the
    directions are parallel within 1e-22, where the function is flat), searched in long double
    (a beam in x), in LINEAR_PASSES passes: relative to b's first point, then each time relative
    to the best point found so far (rounded to float64), both pieces anchored at their points
    nearest that reference point in double-double.  Each pass leaves offsets of the size of the
    distance from the reference point to the minimiser, so the rounding shrinks pass by pass:
    far origins, far ends, far-translated scenes and pieces parallel within 1e-17 whose
    minimiser lies 1e10 along them (where a long-double point is rounded by 1e-9) are resolved.
    The parameter reported is (reference point, s).  use_ld is not used: the search is cheap."""
    ka, kb = cases[0]["a"], cases[0]["b"]
    n = len(cases)
    A, B = _stack(cases, "a_data"), _stack(cases, "b_data")
    eps = 16 * EPSLD
    if ka == "point":
        tgt = _linear_target(kb, B, A[:, :3])
        w = -tgt["tb0"]
        v = _lin_dist(w[:, None], tgt["tm"][:, None], tgt["tmm"][:, None], tgt["tlo"][:, None],
                      tgt["thi"][:, None])[:, 0]
        slack = (eps * _nrm(w)).astype(float) + _anchor_error(kb, B, A[:, :3])
        return ScreenResult(v, slack, ["point|linear"] * n, [LD(0)] * n)
    C = B[:, :3].copy()
    best = np.full(n, LD(np.inf), dtype=LD)
    slack = np.zeros(n)
    params = [None] * n
    todo = np.arange(n)
    for _ in range(LINEAR_PASSES):
        v, mag, s, nxt = _linear_pass(ka, kb, A[todo], B[todo], C[todo])
        mag = mag + (_anchor_error(ka, A[todo], C[todo]) + _anchor_error(kb, B[todo], C[todo])) / eps
        # passes compared by their certified bounds (value + rounding slack)
        for q in np.flatnonzero(v + eps * mag < best[todo] + slack[todo]):
            j = todo[q]
            best[j], params[j] = v[q], (tuple(float(c) for c in C[j]), LD(s[q]))
            slack[j] = eps * float(mag[q])
        # the next pass where the best point moved the reference point (else it would repeat)
        moved = np.isfinite(nxt).all(axis=1) & (nxt != C[todo]).any(axis=1)
        C[todo[moved]] = nxt[moved]
        todo = todo[moved]
        if not len(todo):
            break
    return ScreenResult(best, slack, ["line|linear"] * n, params)


def _anchor_error(kind, data, C):
    """A bound on the error of _anchor's double-double anchor of a piece relative to C: 2^-100 of
    the offsets it cancels (an origin 1e10 from C anchored within 1e-7 of it: 1e-20)."""
    off = np.linalg.norm(data[:, :3] - C, axis=1)
    if kind == "segment":
        off = off + np.linalg.norm(data[:, 3:6] - C, axis=1)
    return 2.0 ** -100 * off


def _dd_vec(v, i):
    return v[0][:, i], v[1][:, i]


def _dd_vsub(x, y):
    """x - y for double-double (n, 3) vectors."""
    return tuple(np.stack(c, axis=1) for c in zip(*[_dd_add(_dd_vec(x, i), _dd_neg(_dd_vec(y, i))) for i in range(3)]))


def _perp_parts(ka, kb, A, B, C):
    """The moving piece a against the target piece b, both anchored at their points nearest C:
    the target's parameters (_linear_target's) and, in double-double rounded to long double, the
    parts of c = b0 - tb0 and of m perpendicular to b's direction u, with c.u, m.u and u.u: where
    b's projection of a(s) lies inside b, the distance is |c_perp + s m_perp|, free of the
    cancellation of |w - (w.u / u.u) u| for w = c + s m (1e7 long: 1e-12 of rounding, against a
    distance that varies by 1e-14 over 1e7 along two lines parallel within 1e-17)."""
    b0, m, lo, hi, b0_dd, m_dd = _anchor(ka, A, C, dd=True)
    tb0, tm, tlo, thi, tb0_dd, u = _anchor(kb, B, C, dd=True)
    uu = _dd_dot(u, u)
    ok = uu[0] > 0
    uu_safe = (np.where(ok, uu[0], 1.0), np.where(ok, uu[1], 0.0))

    def perp(v):
        k = _dd_div(_dd_dot(v, u), uu_safe)
        k = (np.where(ok, k[0], 0.0), np.where(ok, k[1], 0.0))
        return tuple(np.stack(c, axis=1) for c in zip(*[
            _dd_add(_dd_vec(v, i), _dd_neg(_dd_mul(k, _dd_vec(u, i)))) for i in range(3)]))
    c_dd = _dd_vsub(b0_dd, tb0_dd)
    tgt = dict(tb0=tb0, tm=tm, tmm=np.sum(tm * tm, axis=1), tlo=tlo, thi=thi)
    extra = dict(cperp=_ld(perp(c_dd)), mperp=_ld(perp(m_dd)), cu=_ld(_dd_dot(c_dd, u)), mu=_ld(_dd_dot(m_dd, u)),
                 uu=_ld(uu_safe))
    return b0, m, lo, hi, tgt, extra


def _linear_pass(ka, kb, A, B, C):
    """One pass of _screen_linear relative to the reference points C: (value, magnitude of the
    cancelling quantities, parameter s, the best point rounded to float64) per case."""
    eps = 16 * EPSLD
    b0, m, lo, hi, tgt, extra = _perp_parts(ka, kb, A, B, C)
    mn = _nrm(m)
    r = np.maximum(_nrm(b0) + _nrm(tgt["tb0"]) + _segment_extent(tgt), LD(1e-280))
    ok = mn > 0
    S0 = np.where(ok, r / np.where(ok, mn, 1) / _SINH_SPAN, LD(1))
    Smax = S0 * _SINH_SPAN * _SINH_SPAN
    xlo = np.where(ok, np.arcsinh(np.maximum(lo, -Smax) / S0), LD(0))
    xhi = np.where(ok, np.arcsinh(np.minimum(hi, Smax) / S0), LD(0))
    form = _Form("line|linear", "line", "linear", _P(b0=b0, m=m, S0=S0, slo=lo, shi=hi, **tgt, **extra), xlo, xhi,
                 False, _S_GRID)
    v, x, _, _ = _beam(form, xlo, xhi, 3, 40, 8, LD)
    mag = form.magnitude(x)
    s = form.line_s(x, form.p.ld)
    nxt = (C.astype(LD) + b0 + s[:, None] * m).astype(float)
    # the anchor itself (x = 0) where it is as good up to the rounding: on a flat function
    # (parallel pieces) the search may stop anywhere, 1e8 away where the rounding is large
    x0 = np.minimum(np.maximum(LD(0), xlo), xhi)
    v0, mag0 = form.f(x0[:, None])[:, 0], form.magnitude(x0)
    take0 = v0 + eps * mag0 <= v + eps * mag
    return (np.where(take0, v0, v), np.where(take0, mag0, mag), np.where(take0, form.line_s(x0, form.p.ld), s),
            nxt)


def _bezier_eval64(ctrl, t):
    """B(t) (float64, de Casteljau) of curves (n, K, 3) at t (n,)."""
    P = ctrl.copy()
    while P.shape[1] > 1:
        P = P[:, :-1] + t[:, None, None] * (P[:, 1:] - P[:, :-1])
    return P[:, 0]


def _screen_bezier_linear(cases):
    """A Bezier curve against a point, line, ray or segment: the curve's t against the piece's
    closed form, by the halves of the Bezier-round screen (_minimize_bezier; the zoom resolves
    1e-4 of the query's size, or the distance itself where larger, as reference_round.bezier_other
    does), twice: relative to the control point nearest the piece, then relative to the best
    point found (rounded to float64); the piece anchored at its point nearest that reference point
    in double-double, the control points taken relative to it exactly."""
    kb = cases[0]["b"]
    n = len(cases)
    ctrl = np.array([c["a_data"] for c in cases], dtype=float)        # (n, K, 3)
    B = _stack(cases, "b_data")
    ext = np.max(np.linalg.norm(ctrl - ctrl[:, :1], axis=2), axis=1)
    if kb == "segment":
        ext = np.maximum(ext, np.linalg.norm(B[:, 3:6] - B[:, :3], axis=1))
    res = np.maximum(1e-4 * ext, 1e-300)
    o = B[:, :3]
    m = np.zeros((n, 3)) if kb == "point" else (B[:, 3:6] - o if kb == "segment" else B[:, 3:6])
    lo, hi = {"point": (0.0, 0.0), "line": (-np.inf, np.inf), "ray": (0.0, np.inf), "segment": (0.0, 1.0)}[kb]
    near = _lin_dist(ctrl - o[:, None], m[:, None], np.sum(m * m, axis=1)[:, None], lo, hi)
    C = ctrl[np.arange(n), np.argmin(np.where(np.isfinite(near), near, np.inf), axis=1)]
    best = np.full(n, LD(np.inf), dtype=LD)
    names, params = [None] * n, [None] * n
    slack = np.zeros(n)
    t_best = np.zeros(n)
    todo = np.arange(n)
    for pass_ in range(2):
        sub = [ctrl[todo], B[todo], C[todo], res[todo]]
        for name, v, a, b, u, mag in _bezier_linear_pass(kb, *sub):
            mag = mag + _anchor_error(kb, B[todo], C[todo]) / (16 * EPSLD)
            # halves and passes compared by their certified bounds (value + rounding slack)
            for q in np.flatnonzero(v + 16 * EPSLD * mag < best[todo] + slack[todo]):
                j = todo[q]
                best[j], names[j], params[j] = v[q], name, (float(a[q]), float(b[q]), LD(u[q]))
                slack[j] = 16 * EPSLD * float(mag[q])
                t = float(a[q]) + float(u[q]) * (float(b[q]) - float(a[q]))
                t_best[j] = t if name == "bezier|linear" else 1 - t
        # the second pass where the rounding slack is not negligible against the long-double bar
        # (1e-15 of the query's size): the reference point far from the minimum
        todo = np.flatnonzero(slack > 1e-17 * np.maximum(best.astype(float), ext))
        if pass_ == 1 or not len(todo):
            break
        nxt = _bezier_eval64(ctrl[todo], t_best[todo])
        keep = np.isfinite(nxt).all(axis=1)
        todo = todo[keep]
        C[todo] = nxt[keep]
    return ScreenResult(best, slack, names, params)


def _bezier_linear_pass(kb, ctrl, B, C, res):
    """Both halves of _screen_bezier_linear relative to the reference points C: yields (form
    name, value, a, b, u, magnitude) per half."""
    n = len(ctrl)
    rel_dd = _two_sum(ctrl, -C[:, None, :])
    tgt = _linear_target(kb, B, C)
    for name, order in (("bezier|linear", slice(None)), ("bezier_reversed|linear", slice(None, None, -1))):
        dd = (rel_dd[0][:, order, :].copy(), rel_dd[1][:, order, :].copy())
        form = _Form(name, "bezier", "linear", _P(ctrl=_ld(dd), **tgt), np.zeros(n), np.full(n, 0.5), False, _T_GRID)
        yield (name,) + tuple(_minimize_bezier(form, dd, tgt, res))

# ---- residuals: how far a point is from a shape (long double, offsets in double-double) -------
def residuals(kind, data, pts, params=None):
    """(distance of each point (n, 3) (float64 or long double) from its shape (n cases of `kind`),
    a bound on the long-double evaluation error of that distance).  A Bezier point p is measured
    against B(param) (its own parameter, which must lie in [0, 1]) as |sum_i b_i(t) (p - P_i)|,
    error ~eps sum_i b_i |p - P_i|: small wherever p is near the curve, even for a control point
    1e12 away or a curve translated by 1e12."""
    pts = np.asarray(pts)
    P = pts.astype(LD)
    if kind == "bezier":
        ctrl = np.asarray(data, dtype=float)
        t = np.asarray(params, dtype=LD)
        k = ctrl.shape[1] - 1
        s = 1 - t
        w, mag = 0, 0
        for i in range(k + 1):
            b = math.comb(k, i) * t ** i * s ** (k - i)
            d = _pt_minus(P, ctrl[:, i, :])
            w = w + b[:, None] * d
            mag = mag + b * _nrm(d)
        bad = ~((t >= 0) & (t <= 1))
        return np.where(bad, LD(np.inf), _nrm(w)), 16 * LD(EPSLD) * mag
    data = np.asarray(data, dtype=float)
    if kind in RIMS:
        parts = _rim_parts(kind, data)
        n, tgt = parts["n"], parts["target"]
        w = _pt_minus(P, data[:, :3])
        R = data[:, 6].astype(LD)
        d = _tdist(w[:, None], tgt, kind)[:, 0]
        return d, 16 * LD(EPSLD) * (_nrm(w) + R)
    C0 = data[:, :3]
    w = _pt_minus(P, C0)
    if kind == "point":
        return _nrm(w), 16 * LD(EPSLD) * _nrm(w)
    tgt = _linear_target(kind, data, C0)
    d = _lin_dist(w[:, None] - tgt["tb0"][:, None], tgt["tm"][:, None], tgt["tmm"][:, None],
                  tgt["tlo"][:, None], tgt["thi"][:, None])[:, 0]
    return d, 16 * LD(EPSLD) * (_nrm(w) + _nrm(tgt["tb0"]))


def _pt_minus(P, C):
    """P (long double or float64 points) - C (float64), accurately."""
    if P.dtype == LD:
        hi = P.astype(np.float64)
        lo = (P - hi.astype(LD)).astype(np.float64)
        d = _two_sum(hi, -C)
        return d[0].astype(LD) + (d[1].astype(LD) + lo.astype(LD))
    return _diff_ld(P, C)


# =============================================================================================
# 3. the checker
# =============================================================================================
def _dtype(precision):
    return {"float32": np.float32, "float64": np.float64, "longdouble": np.float64}[precision]


def make_shape(cd, kind, data, dtype=np.float64):
    """A circledist shape (scalar, or a batch when data has a leading batch axis)."""
    arr = np.asarray(data, dtype=dtype)
    if kind == "bezier":
        return cd.Bezier(arr)
    if kind == "point":
        return cd.Point(arr[..., :3])
    if kind in ("line", "ray"):
        return getattr(cd, kind.capitalize())(arr[..., :3], arr[..., 3:6])
    if kind == "segment":
        return cd.Segment(arr[..., :3], arr[..., 3:6])
    if kind == "arc":
        return cd.Arc(arr[..., :3], arr[..., 3:6], arr[..., 6], arr[..., 7:10], arr[..., 10])
    if kind == "annulus":
        return cd.Annulus(arr[..., :3], arr[..., 3:6], arr[..., 7], arr[..., 6])
    return getattr(cd, kind.capitalize())(arr[..., :3], arr[..., 3:6], arr[..., 6])


def pair_scale(case):
    """The pair's length scale of within()'s documented tolerance 64 eps (s + d) (bounds.hpp
    pair_scale: the sizes and separation of the bounding balls; a line or ray counts by its
    distance from the other's centre, two of them by the separation of their origins)."""
    def ball(kind, data):
        d = np.asarray(data, float)
        if kind == "point":
            return d[:3], 0.0
        if kind in ("line", "ray"):
            return d[:3], math.inf
        if kind == "segment":
            return (d[:3] + d[3:6]) / 2, float(np.linalg.norm(d[3:6] - d[:3])) / 2
        if kind in RIMS:
            return d[:3], float(d[6])
        lo, hi = d.min(axis=0), d.max(axis=0)
        c = (lo + hi) / 2
        return c, float(max(np.linalg.norm(p - c) for p in d))
    def from_line(kind, data, c):
        # in exact rationals: a ray's origin 3e8 away cancels to 0 in doubles
        o, u, cc = ([Fraction(float(x)) for x in v] for v in (data[:3], data[3:6], c))
        t = sum((ci - oi) * ui for ci, oi, ui in zip(cc, o, u)) / sum(ui * ui for ui in u)
        if kind == "ray":
            t = max(t, Fraction(0))
        return math.sqrt(float(sum((oi + t * ui - ci) ** 2 for oi, ui, ci in zip(o, u, cc))))
    ka, kb = case["a"], case["b"]
    ca, ra = ball(ka, case["a_data"])
    cb, rb = ball(kb, case["b_data"])
    if math.isfinite(ra) and math.isfinite(rb):
        s = max(ra, rb, float(np.linalg.norm(ca - cb)))
    elif math.isfinite(rb):
        s = max(rb, from_line(ka, case["a_data"], cb))
    elif math.isfinite(ra):
        s = max(ra, from_line(kb, case["b_data"], ca))
    else:
        s = float(np.linalg.norm(ca - cb))
    return s if s > 0 else 1.0


def _eq(x, y):
    """Bitwise-equal answers (NaN equal to NaN)."""
    x, y = np.asarray(x), np.asarray(y)
    return (x == y) | (np.isnan(x.astype(float)) & np.isnan(y.astype(float)))


def _finding(check, case, solver, precision, order, entry, **info):
    ka, kb = (case["a"], case["b"]) if order == "ab" else (case["b"], case["a"])
    f = dict(check=check, family=case["family"], case_id=case["id"], pair=f"{case['a']}-{case['b']}",
                kinds=[ka, kb], solver=solver, precision=precision, order=order, entry=entry)
    f["a_data"] = case["a_data"] if order == "ab" else case["b_data"]
    f["b_data"] = case["b_data"] if order == "ab" else case["a_data"]
    for k, v in info.items():
        f[k] = _jsonable(v)
    return f


def _jsonable(v):
    if isinstance(v, np.longdouble) and np.finfo(np.longdouble).nmant > 52:
        # full long-double digits (25 significant: exact to far below one ulp)
        return np.format_float_scientific(v, unique=False, precision=24) if np.isfinite(v) else str(v)
    if isinstance(v, (np.floating, float)):
        return float(v) if np.isfinite(float(v)) else str(float(v))
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.bool_,)):
        return bool(v)
    if isinstance(v, np.ndarray):
        return [_jsonable(x) for x in v]
    if isinstance(v, (list, tuple)):
        return [_jsonable(x) for x in v]
    return v


def _group(cases):
    groups = {}
    for i, c in enumerate(cases):
        key = (c["a"], c["b"], len(c["a_data"]) if c["a"] == "bezier" else 0)
        groups.setdefault(key, []).append(i)
    return groups


def _call(fn, *args, **kw):
    try:
        return fn(*args, **kw), None
    except Exception as e:  # noqa: BLE001 - any exception is a finding
        return None, f"{type(e).__name__}: {e}"


def _run_batch(cd, ka, kb, A, Bd, solver, precision, n):
    dt = _dtype(precision)
    SA, SB = make_shape(cd, ka, A, dt), make_shape(cd, kb, Bd, dt)
    kw = dict(solver=solver, precision=precision)
    out = {}
    for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
        d, err = _call(cd.distance, x, y, **kw)
        r, err2 = _call(cd.closest_points, x, y, **kw)
        out[order] = dict(d=d, r=r, err=err or err2)
    return out, SA, SB


def _within_limits(D, s, eps, bar_abs):
    """Limits just above and below D that the documented tolerance 64 eps (s + d) cannot blur."""
    band = 4 * 64 * eps * (s + D)
    hi = D + np.maximum(band, bar_abs)
    lo = D - np.maximum(band, bar_abs)
    return lo, hi, band


def check_cases(cd, cases, combo_list=None, scalar=None, screens=None, within=True):
    """Run every combination on `cases` (any mix of families and kinds), both orders, and return
    (findings, stats).  scalar: indices of cases that also get scalar calls (default all);
    screens: {case index: (value, slack, f32 value, f32 slack)} to reuse."""
    combo_list = combo_list or combos()
    if scalar is None:
        scalar = set(range(len(cases)))
    scalar = set(scalar)
    findings = []
    # answers: every value the library returned for one query, per entry point (a batched call of
    # n cases gives n; each within / distance_if_within probe is one)
    stats = {"cases": len(cases), "answers": collections.Counter(), "unique_checked": collections.Counter()}
    screens = {} if screens is None else screens
    for (ka, kb, _), idx in _group(cases).items():
        group = [cases[i] for i in idx]
        need64 = [j for j, i in enumerate(idx) if i not in screens]
        if need64:
            s64 = screen([group[j] for j in need64])
            precs = {p for _, p in combo_list}
            if "float32" in precs:
                s32 = screen([to_float32_case(group[j]) for j in need64], use_ld=False)
            for q, j in enumerate(need64):
                screens[idx[j]] = dict(
                    value=s64.value[q], slack=s64.slack[q], form=s64.forms[q], param=s64.params[q],
                    value32=s32.value[q] if "float32" in precs else None,
                    slack32=s32.slack[q] if "float32" in precs else None,
                    form32=s32.forms[q] if "float32" in precs else None,
                    param32=s32.params[q] if "float32" in precs else None)
        findings += _check_group(cd, ka, kb, idx, group, combo_list, scalar, screens, within, stats)
    return findings, stats


def _check_group(cd, ka, kb, idx, group, combo_list, scalar, screens, within, stats):
    findings = []
    n = len(group)
    data = {"f64": (np.array([c["a_data"] for c in group], dtype=float),
                    np.array([c["b_data"] for c in group], dtype=float))}
    g32 = [to_float32_case(c) for c in group]
    data["f32"] = (np.array([c["a_data"] for c in g32], dtype=float), np.array([c["b_data"] for c in g32], dtype=float))
    radius = {"f64": np.array([bar_scale(c) for c in group]), "f32": np.array([bar_scale(c) for c in g32])}
    sscale = {"f64": np.array([scene_scale(c) for c in group]), "f32": np.array([scene_scale(c) for c in g32])}
    pscale = {"f64": np.array([pair_scale(c) for c in group]), "f32": np.array([pair_scale(c) for c in g32])}
    U = {"f64": np.array([screens[i]["value"] for i in idx], dtype=LD),
         "f32": np.array([screens[i]["value32"] if screens[i]["value32"] is not None else np.nan for i in idx],
                         dtype=LD)}
    slack = {"f64": np.array([screens[i]["slack"] for i in idx]),
             "f32": np.array([screens[i]["slack32"] if screens[i]["slack32"] is not None else 0 for i in idx])}
    runs = {}
    # ---- batched calls and per-answer checks -----------------------------------------------
    for solver, precision in combo_list:
        scene = "f32" if precision == "float32" else "f64"
        A, Bd = data[scene]
        if ka == "bezier":
            A = A.reshape(n, -1, 3)
        res, SA, SB = _run_batch(cd, ka, kb, A, Bd, solver, precision, n)
        for order in res.values():
            stats["answers"]["distance"] += n if order["d"] is not None else 0
            stats["answers"]["closest_points"] += n if order["r"] is not None else 0
        runs[(solver, precision)] = (res, SA, SB)
    # verified pairs: upper bounds from every combination's closest points (per input scene)
    upair = {"f64": np.full(n, LD(np.inf), dtype=LD), "f32": np.full(n, LD(np.inf), dtype=LD)}
    resid = {}
    for (solver, precision), (res, SA, SB) in runs.items():
        scene = "f32" if precision == "float32" else "f64"
        A, Bd = data[scene]
        if ka == "bezier":
            A = A.reshape(n, -1, 3)
        for order in ("ab", "ba"):
            r = res[order]["r"]
            if r is None:
                continue
            pa, pb = np.asarray(r.point_a), np.asarray(r.point_b)
            qa, qb = (pa, pb) if order == "ab" else (pb, pa)   # qa on shape a, qb on shape b
            par = np.asarray(r.param_a if order == "ab" else r.param_b)
            with np.errstate(all="ignore"):
                ra_, ea = residuals(ka, A, qa, par[:, 0] if ka == "bezier" else None)
                rb_, eb = residuals(kb, Bd, qb)
                sep = _nrm(qa.astype(LD) - qb.astype(LD))
            resid[(solver, precision, order)] = (ra_, rb_, sep)
            # a genuine pair: the truth is at most its separation plus both points' distances off
            # their shapes (each rounded up by its evaluation error, and the separation's)
            bound = sep + ra_ + rb_ + ea + eb + 16 * LD(EPSLD) * sep
            ok = np.isfinite(bound)
            upair[scene] = np.where(ok, np.minimum(upair[scene], bound), upair[scene])
    for (solver, precision), (res, SA, SB) in runs.items():
        scene = "f32" if precision == "float32" else "f64"
        bar = BARS[precision]
        eps_out = OUT_EPS[precision]
        Us, sl = U[scene], slack[scene]
        Ub = np.minimum(Us, upair[scene])
        scale_ = np.maximum(Ub.astype(float), radius[scene])
        bar_abs = bar * scale_
        ulps = ULPS * eps_out * sscale[scene]
        gcases = g32 if scene == "f32" else group
        d_orders = {}
        inaccurate = {}
        for order in ("ab", "ba"):
            rr = res[order]
            if rr["err"] is not None:
                for j in range(n):
                    findings.append(_finding("exception", gcases[j], solver, precision, order,
                                             "distance/closest_points", error=rr["err"]))
                continue
            d = np.asarray(rr["d"])
            r = rr["r"]
            cdist = np.asarray(r.distance)
            d_orders[order] = d
            want = {"float32": np.float32, "float64": np.float64, "longdouble": np.longdouble}[precision]
            if d.dtype != want or cdist.dtype != want:
                findings.append(_finding("dtype", gcases[0], solver, precision, order, "distance",
                                         got=str(d.dtype), expected=np.dtype(want).name))
            dl, cl = d.astype(LD), cdist.astype(LD)
            ra_, rb_, sep = resid[(solver, precision, order)]
            ulps_o = ulps
            if ka not in RIMS and kb not in RIMS:
                # without a round the closest points can lie far outside the scene (1e5 along two
                # lines 1e-5 rad apart): each is rounded by ulps of its own size
                with np.errstate(invalid="ignore"):
                    pmag = np.maximum(np.abs(np.asarray(r.point_a, dtype=float)).max(axis=1),
                                      np.abs(np.asarray(r.point_b, dtype=float)).max(axis=1))
                ulps_o = ULPS * eps_out * np.maximum(sscale[scene], pmag)
            acc_bad = inaccurate.setdefault(order, set())
            for j in range(n):
                c = gcases[j]
                info = dict(screen=Us[j], screen_slack=sl[j], verified_pair_bound=upair[scene][j],
                            bar_abs=bar_abs[j], bar_scale=radius[scene][j])
                for entry, val in (("distance", dl[j]), ("closest_points", cl[j])):
                    if not np.isfinite(val) or val < 0:
                        findings.append(_finding("non_finite", c, solver, precision, order, entry, library=val))
                        continue
                    if val > Ub[j] + bar_abs[j] + sl[j]:
                        findings.append(_finding("above_bound", c, solver, precision, order, entry, library=val,
                                                 excess=(val - Ub[j]) / scale_[j], **info))
                        acc_bad.add(j)
                    elif val < Us[j] - bar_abs[j] - sl[j] and val < upair[scene][j] - bar_abs[j] - sl[j]:
                        findings.append(_finding("below_bound", c, solver, precision, order, entry, library=val,
                                                 excess=(val - Ub[j]) / scale_[j], **info))
                        acc_bad.add(j)
                # closest points on their shapes; separation equals the reported distance
                if not (ra_[j] <= ulps_o[j] and rb_[j] <= ulps_o[j]):
                    findings.append(_finding("point_off_shape", c, solver, precision, order, "closest_points",
                                             off_a=ra_[j], off_b=rb_[j], allowed=ulps_o[j],
                                             point_a=np.asarray(r.point_a)[j],
                                             point_b=np.asarray(r.point_b)[j]))
                if not abs(sep[j] - cl[j]) <= bar_abs[j] + ulps_o[j]:
                    findings.append(_finding("separation", c, solver, precision, order, "closest_points",
                                             separation=sep[j], library=cl[j], allowed=bar_abs[j] + ulps_o[j],
                                             point_a=np.asarray(r.point_a)[j], point_b=np.asarray(r.point_b)[j]))
                # the same number, to the bit (README: the two never disagree)
                if not (dl[j] == cl[j] or (np.isnan(dl[j]) and np.isnan(cl[j]))):
                    findings.append(_finding("distance_vs_closest_points", c, solver, precision, order, "both",
                                             distance=dl[j], closest_points=cl[j], allowed=0.0))
                if precision == "float32" and float(np.float32(d[j])) != float(d[j]):
                    findings.append(_finding("float32_value", c, solver, precision, order, "distance", library=d[j]))
        # symmetry: distance(a, b) == distance(b, a) (README; the closest points of a non-unique
        # pair may legitimately differ between the orders, so only the distances are compared)
        if len(d_orders) == 2:
            r1, r2 = res["ab"]["r"], res["ba"]["r"]
            same = _eq(d_orders["ab"], d_orders["ba"]) & _eq(np.asarray(r1.distance), np.asarray(r2.distance))
            for j in np.flatnonzero(~same):
                findings.append(_finding("asymmetric", gcases[j], solver, precision, "ab", "distance",
                                         ab=d_orders["ab"][j], ba=d_orders["ba"][j],
                                         cp_ab=np.asarray(r1.distance)[j], cp_ba=np.asarray(r2.distance)[j]))
        # within / distance_if_within / intersects, batched
        wres = {}
        if within and d_orders:
            fw, wres = _check_within(cd, res, SA, SB, d_orders, solver, precision, gcases, pscale[scene], bar_abs,
                                     inaccurate, stats)
            findings += fw
        # an arc of angle 2 pi is the whole circle, answered by the circle's query (docs/arc.md)
        if "arc" in (ka, kb) and d_orders:
            A, Bd = data[scene]
            findings += _check_whole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats)
        # an annulus of inner radius 0 is the disk, of inner radius = outer the circle: the disk's
        # or circle's query answers it (docs/annulus.md), to the bit
        if "annulus" in (ka, kb) and d_orders:
            A, Bd = data[scene]
            findings += _check_hole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats)
        # closest_points().unique against the independent rule (expected_unique)
        if d_orders:
            findings += _check_unique(res, d_orders, solver, precision, gcases, stats)
        # batched == scalar
        sel = [j for j, i in enumerate(idx) if i in scalar]
        if sel:
            findings += _check_scalar(cd, ka, kb, res, d_orders, wres, sel, gcases, solver, precision, stats)
    return findings


def _check_whole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats):
    """Cases whose arcs all have angle 2 pi (as given: float32's 2 pi rounds above float64's)
    must give the answers of the same query with each arc replaced by its circle, to the bit
    (arc.hpp: the circle's query is called): distance, closest_points' distance, points,
    `unique` and the parameter of a side that is not an arc.  An arc's own parameter is its
    t = theta - theta0, the circle's angle moved to the arc's start (ArcSpan::param_of): not the
    circle's number (tests/test_arc.py checks that t gives the arc's point)."""
    rows = np.ones(len(gcases), dtype=bool)
    for kind, X in ((ka, A), (kb, Bd)):
        if kind == "arc":
            rows &= X[:, 10] >= 2 * math.pi
    sel = np.flatnonzero(rows)
    if not len(sel):
        return []
    kinds = ["circle" if k == "arc" else k for k in (ka, kb)]
    dt = _dtype(precision)
    SA = make_shape(cd, kinds[0], A[sel, :7] if ka == "arc" else A[sel], dt)
    SB = make_shape(cd, kinds[1], Bd[sel, :7] if kb == "arc" else Bd[sel], dt)
    same = (ka != "arc", kb != "arc")   # which side's parameter must be the circle query's
    return _compare_replaced(cd, (ka, kb), SA, SB, sel, res, d_orders, solver, precision, gcases, stats,
                             "whole_arc_vs_circle", "whole arc as circle", same)


def _check_hole(cd, ka, kb, A, Bd, res, d_orders, solver, precision, gcases, stats):
    """Cases with an annulus of inner radius 0 or inner = outer (as given: float32 scenes keep
    both) must give the answers of the same query with that annulus replaced by its disk or its
    outer circle, to the bit (docs/annulus.md: the disk's / circle's query is called): distance,
    closest_points' distance, points, parameters and `unique`; the circle's parameter (theta, 0)
    on the annulus's side reported as (outer radius, theta).  An annulus-annulus case with only
    one degenerate annulus is compared with the disk-annulus or circle-annulus query."""
    out = []
    for which, kind, X in (("a", ka, A), ("b", kb, Bd)):
        if kind != "annulus":
            continue
        for as_kind, rows in (("disk", X[:, 7] == 0), ("circle", X[:, 7] == X[:, 6])):
            sel = np.flatnonzero(rows)
            if not len(sel):
                continue
            dt = _dtype(precision)
            if which == "a":
                SA, SB = make_shape(cd, as_kind, A[sel, :7], dt), make_shape(cd, kb, Bd[sel], dt)
            else:
                SA, SB = make_shape(cd, ka, A[sel], dt), make_shape(cd, as_kind, Bd[sel, :7], dt)
            rim = None if as_kind == "disk" else (which, X[sel, 6])
            out += _compare_replaced(cd, (ka, kb), SA, SB, sel, res, d_orders, solver, precision, gcases, stats,
                                     "degenerate_annulus_vs_" + as_kind, f"annulus as {as_kind}", (True, True),
                                     rim=rim)
    return out


def _compare_replaced(cd, kinds, SA, SB, sel, res, d_orders, solver, precision, gcases, stats, check, what, same,
                      rim=None):
    """The rows `sel` of the batch's answers `res` (case kinds `kinds`) against the same query on
    the replaced shapes SA, SB (both orders), to the bit: distance(); closest_points()' distance,
    points and `unique`; the parameter of case side a / b where same[0] / same[1].  rim = (side,
    outer radii) of an annulus replaced by its circle: an annulus side answered by a circle has
    its (theta, 0) expected as (radius, theta), a circle side answered by an annulus (theta, 0).
    Where the two replaced shapes are the same set (_identical_rows) the answer may also be the
    replaced one with its two sides exchanged: a query between a shape and itself may report
    either point first."""
    out = []
    for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
        if order not in d_orders:
            continue
        d, err = _call(cd.distance, x, y, solver=solver, precision=precision)
        r, err2 = _call(cd.closest_points, x, y, solver=solver, precision=precision)
        if err or err2:
            out.append(_finding("exception", gcases[sel[0]], solver, precision, order, what, error=err or err2))
            continue
        stats["answers"][f"distance ({what})"] += len(sel)
        stats["answers"][f"closest_points ({what})"] += len(sel)
        d = np.asarray(d)
        for q in np.flatnonzero(~_eq(d, d_orders[order][sel])):
            out.append(_finding(check, gcases[sel[q]], solver, precision, order, "distance",
                                library=d_orders[order][sel[q]], replaced=d[q]))
        mine = res[order]["r"]
        if mine is None:
            continue
        # the answer's first / second field is case side a / b in order "ab", b / a in "ba"
        sides = ("a", "b") if order == "ab" else ("b", "a")

        def expected(swap):
            """The replaced answer's fields, as the case's answer must show them; swap: with its two
            sides exchanged (for two identical shapes either side's point may be reported first)."""
            fields = [("distance", np.asarray(r.distance)), ("unique", np.asarray(r.unique))]
            replaced_kinds = (x.kind.lower(), y.kind.lower())
            for k, side in enumerate(sides):
                j = 1 - k if swap else k  # the replaced answer's side that gives this one
                fields.append((("point_a", "point_b")[k], np.asarray(getattr(r, ("point_a", "point_b")[j]))))
                if not same["ab".index(side)]:
                    continue
                theirs = np.array(np.asarray(getattr(r, ("param_a", "param_b")[j])), copy=True)
                mine_kind = kinds["ab".index(side)]
                if rim is not None and mine_kind == "annulus" and replaced_kinds[j] == "circle":
                    theirs = np.stack([np.asarray(rim[1], dtype=theirs.dtype), theirs[:, 0]], axis=1)  # (R, theta)
                elif mine_kind == "circle" and replaced_kinds[j] == "annulus":
                    theirs = np.stack([theirs[:, 1], np.zeros_like(theirs[:, 1])], axis=1)  # (theta, 0)
                fields.append((("param_a", "param_b")[k], theirs))
            return fields

        def mismatches(fields):
            out_ = []
            for name, rep in fields:
                bad = ~_eq(np.asarray(getattr(mine, name))[sel], rep)
                if bad.ndim > 1:
                    bad = bad.any(axis=tuple(range(1, bad.ndim)))
                out_.append((name, rep, bad))
            return out_

        direct = mismatches(expected(False))
        failed = np.zeros(len(sel), dtype=bool)
        for _, _, bad in direct:
            failed |= bad
        twins = _identical_rows(x, y, len(sel))
        if (failed & twins).any():
            swapped_bad = np.zeros(len(sel), dtype=bool)
            for _, _, bad in mismatches(expected(True)):
                swapped_bad |= bad
            failed &= ~(twins & ~swapped_bad)
        for name, rep, bad in direct:
            for q in np.flatnonzero(bad & failed):
                out.append(_finding(check, gcases[sel[q]], solver, precision, order, f"closest_points {name}",
                                    library=np.asarray(getattr(mine, name))[sel][q], replaced=rep[q]))
    return out


def _identical_rows(x, y, n):
    """Which of the n elements of the batched shapes x and y are the same set (every field equal;
    an annulus of inner radius 0 is its disk, of inner = outer its circle): their closest pairs
    are symmetric, so a query may name either point first."""
    fx, fy = _round_fields(x, n), _round_fields(y, n)
    if fx is None or fy is None:
        return np.zeros(n, dtype=bool)
    same = np.ones(n, dtype=bool)
    for field in ("kind", "center", "normal", "radius", "inner", "start", "angle"):
        eq = fx[field] == fy[field]
        same &= eq if eq.ndim == 1 else eq.all(axis=1)
    return same


def _round_fields(shape, n):
    """A batch of circles, disks, annuli or arcs as comparable per-element arrays (kind code,
    center, normal, radius, inner radius, start, angle), an annulus of inner 0 as its disk and of
    inner = outer as its circle; None for other kinds."""
    codes = {"Circle": 0, "Disk": 1, "Annulus": 2, "Arc": 3}
    if shape.kind not in codes:
        return None
    f = shape.to_arrays()
    vec = lambda v: np.broadcast_to(np.asarray(v, dtype=float), (n, 3))  # noqa: E731
    num = lambda v: np.broadcast_to(np.asarray(v, dtype=float), (n,))  # noqa: E731
    out = dict(kind=np.full(n, codes[shape.kind]), center=vec(f["center"]), normal=vec(f["normal"]),
               inner=np.zeros(n), start=np.zeros((n, 3)), angle=np.zeros(n))
    if shape.kind == "Annulus":
        inner, outer = num(f["inner_radius"]), num(f["outer_radius"])
        out["radius"] = outer
        out["kind"] = np.where(inner == 0, codes["Disk"], np.where(inner == outer, codes["Circle"], codes["Annulus"]))
        out["inner"] = np.where(out["kind"] == codes["Annulus"], inner, 0.0)
    else:
        out["radius"] = num(f["radius"])
    if shape.kind == "Arc":
        out["start"], out["angle"] = vec(f["start"]), num(f["angle"])
    return out


# ---- closest_points().unique ------------------------------------------------------------------
# The rule (independent of the library; exact rational tests on the inputs as given, or closed
# forms in float64 with a margin far above their rounding):
#   unique must be False where the inputs are EXACTLY (in rationals) a configuration with a
#   continuum of closest pairs, by symmetry:
#     - a point, line, ray, segment or Bezier curve (every control point: the curve lies in their
#       hull) lying on the axis of a circle, an arc (angle >= 1e-3) or an annulus with a hole
#       (inner > 0): every rim (inner rim) point is as far from each point of the axis, so the
#       closest pairs of any closest axis point form a circle (an arc);
#     - two coaxial shapes among circle, disk, annulus and arc (not two arcs; an arc's angle
#       >= 1e-3): common axis (normals parallel, the centres' offset along it).  The set of closest
#       pairs is invariant under the rotations about the axis (for an arc: every arc point is as
#       far from the other shape); a pair off the axis has distinct rotated copies, and a pair on
#       the axis needs both shapes to meet the axis (two disks), whose every vertical pair over
#       the smaller one (coplanar: the overlap) is as close.
#   unique must be True where a closed form or strict convexity proves a single closest pair with a
#   clear margin:
#     - a point against a point, line, ray, segment or disk (a convex set: one nearest point);
#     - a point against a circle, or an annulus's hole (the inner rim), at distance rho from the
#       axis: the nearest rim point is unique, and the farthest (the only other critical point)
#       is worse by sqrt(z^2 + (R + rho)^2) - sqrt(z^2 + (R - rho)^2) > UNIQUE_MARGIN x max(d, R);
#       an annulus over its ring or beyond: the clamped projection (unique);
#     - a point against an arc: the nearer of the in-span rim point and the two ends (the arc
#       point at angle theta is farther the larger the angular gap to the point's own angle, up
#       to pi) better than the other candidates by that margin;
#     - two lines, rays or segments whose directions are at least 1e-3 rad from parallel: the
#       squared distance between their points is strictly convex in the two parameters.
#   Elsewhere the screen's checker does not check unique (curve pairs: the screen does not certify
#   that a minimum is single, nor that the other shape's closest point is unique).  The direct
#   50-digit comparison (reference_check, float64 scenes) adds True from a 50-digit search over
#   one parameter (reference_unique): a circle or arc against a line, ray, segment, disk, circle,
#   arc or annulus, a Bezier curve against a point, line, ray, segment, disk, circle, arc or
#   annulus, and a line, ray or segment against a disk or annulus.  A closest pair is (P(x), Q):
#   x minimises the distance from the moving shape's point P(x) (a rim's angle, a curve's t, a
#   line's length) to the target, Q is a nearest target point of P(x).  So the pair is unique
#   where the best local minimum of the 50-digit search is single (every other distinct one worse
#   by REF_UNIQUE_REL x max(d, scale)) and strict (rises by REF_UNIQUE_RISE x max(d, scale) within
#   REF_UNIQUE_STEP on each side in range; at an end of an open arc or of a curve on its inner
#   side only) and Q is unique with that same margin (a convex target's always; a circle's,
#   arc's or annulus's where the point-round closed forms' other candidates at P(x) are worse by
#   it and the rim holding Q is not flat: _target_point_unique).  The margin is the scene's
#   (max(d, scale)), not the target's own radius: a small rim far away in a large scene, or a
#   point within the scene's rounding of a rim's axis, is as close to a stretch of the rim as the
#   library's tie tolerance (64 eps x scale) can tell (two such cases, found when the annulus's
#   point had no margin: docs/differential_report.md).  Not
#   checked: two regions (disk-disk, disk-annulus, annulus-annulus beyond the coaxial cases),
#   a point against an arc or annulus where the closed form is too close to call, a Bezier curve
#   against a Bezier curve (no kind pair of the cases), a linear pair within 1e-3 rad of
#   parallel; never False from sampling.
UNIQUE_MARGIN = 1e-6
UNIQUE_MIN_ARC = 1e-3


def _fr(v):
    return [Fraction(float(x)) for x in v]


def _fcross_zero(a, b):
    return (a[1] * b[2] - a[2] * b[1] == 0 and a[2] * b[0] - a[0] * b[2] == 0
            and a[0] * b[1] - a[1] * b[0] == 0)


def _fsub(a, b):
    return [x - y for x, y in zip(a, b)]


def _on_axis(kind, data, C, N):
    """Whether a point, line, ray, segment or Bezier curve (every control point: the curve lies in
    their convex hull) lies exactly on the axis (C, N)."""
    if kind == "bezier":
        return all(_fcross_zero(_fsub(_fr(p), C), N) for p in data)
    if kind == "point":
        return _fcross_zero(_fsub(_fr(data[:3]), C), N)
    if kind == "segment":
        return _fcross_zero(_fsub(_fr(data[:3]), C), N) and _fcross_zero(_fsub(_fr(data[3:6]), C), N)
    return _fcross_zero(_fsub(_fr(data[:3]), C), N) and _fcross_zero(_fr(data[3:6]), N)


def _continuum_round(kind, data):
    """Whether a round-like shape has every one of its (rim) points as far from each axis point:
    a circle, an arc of angle >= UNIQUE_MIN_ARC, an annulus with a hole."""
    if kind == "circle":
        return True
    if kind == "arc":
        return data[10] >= UNIQUE_MIN_ARC
    if kind == "annulus":
        return data[7] > 0
    return False


def _np(v):
    return np.asarray(v, dtype=float)


def _point_round_unique(p, kind, data):
    """unique for a point against a circle, disk, arc or annulus (see the rule above): True,
    False or None (too close to call)."""
    C, N = _np(data[:3]), _np(data[3:6])
    N = N / np.linalg.norm(N)
    w = _np(p) - C
    z = float(np.dot(w, N))
    a = w - z * N
    rho = float(np.linalg.norm(a))
    R = float(data[6])
    if kind == "disk":
        return True
    if kind == "annulus":
        if rho >= data[7]:
            return True
        R = float(data[7])
    near, far = math.hypot(z, R - rho), math.hypot(z, R + rho)
    margin = UNIQUE_MARGIN * max(near, float(data[6]))
    if kind in ("circle", "annulus"):
        return True if far - near > margin else None
    # an arc: the in-span point (if the point's angle is in the span) and both ends
    u = _np(data[7:10])
    u = u - np.dot(u, N) * N
    u = u / np.linalg.norm(u)
    v = np.cross(N, u)
    ang = float(data[10])
    whole = ang >= 2 * math.pi
    phi = math.atan2(float(np.dot(w, v)), float(np.dot(w, u))) % (2 * math.pi)
    ends = [float(np.linalg.norm(w - R * u)), float(np.linalg.norm(w - R * (math.cos(ang) * u + math.sin(ang) * v)))]
    if whole:
        return True if far - near > margin else None
    if rho > 0 and (phi <= ang or abs(phi - ang) < 1e-9 or abs(phi - 2 * math.pi) < 1e-9):
        if abs(phi - ang) < 1e-9 or phi < 1e-9 or abs(phi - 2 * math.pi) < 1e-9:
            return None          # the point's angle at an end: the in-span point is the end
        cands = sorted([near] + ends)
    else:
        cands = sorted(ends)
    return True if cands[1] - cands[0] > margin and far - near > margin else None


def expected_unique(case):
    """(expected unique, why) for a case (its own inputs: float32 scenes are passed rounded), by
    the rule above; (None, "") where it says nothing."""
    key = _key(case)
    if key in _UNIQUE_CACHE:
        return _UNIQUE_CACHE[key]
    out = _expected_unique(case)
    _UNIQUE_CACHE[key] = out
    return out


_UNIQUE_CACHE = {}
_SYM = ("circle", "disk", "annulus", "arc")


def _expected_unique(case):
    ka, kb = case["a"], case["b"]
    a, b = case["a_data"], case["b_data"]
    # continua by symmetry (exact)
    for (k1, d1), (k2, d2) in (((ka, a), (kb, b)), ((kb, b), (ka, a))):
        if (k1 in LINEAR or k1 == "bezier") and k2 in _SYM and _continuum_round(k2, d2):
            if _on_axis(k1, d1, _fr(d2[:3]), _fr(d2[3:6])):
                return False, f"the {k1} lies on the {k2}'s axis"
    if ka in _SYM and kb in _SYM and not (ka == "arc" and kb == "arc"):
        arcs_ok = all(d[10] >= UNIQUE_MIN_ARC for k, d in ((ka, a), (kb, b)) if k == "arc")
        Na, Nb = _fr(a[3:6]), _fr(b[3:6])
        if arcs_ok and _fcross_zero(Na, Nb) and _fcross_zero(_fsub(_fr(b[:3]), _fr(a[:3])), Na):
            return False, "coaxial rounds"
    # single pairs with a margin
    if ka == "point" and kb in ("point", "line", "ray", "segment"):
        return True, "a point against a convex set"
    if ka == "point" and kb in _SYM:
        u = _point_round_unique(a[:3], kb, b)
        return (u, "point against a round, closed form") if u else (None, "")
    if ka in LINEAR and kb in LINEAR:
        def direction(kind, d):
            m = _np(d[3:6]) - (_np(d[:3]) if kind == "segment" else 0)
            return m
        ma, mb = direction(ka, a), direction(kb, b)
        na, nb = np.linalg.norm(ma), np.linalg.norm(mb)
        if na == 0 or nb == 0:
            return True, "a zero-length segment (a point) against a convex set"
        if not (np.isfinite(na) and np.isfinite(nb)):
            return None, ""
        sin = np.linalg.norm(np.cross(ma / na, mb / nb))
        if sin > UNIQUE_MIN_ARC:
            return True, "two linear pieces 1e-3 rad or more from parallel (strictly convex)"
    return None, ""


REF_UNIQUE_REL = "1e-6"      # the second-best distinct local minimum must be worse by this x max(d, scale)
REF_UNIQUE_RISE = "1e-12"    # and the minimum not flat: d(x* +- 1e-4) - d > this x max(d, scale)
REF_UNIQUE_STEP = "1e-4"     # that step: in radians of a rim, in t of a Bezier curve
_CONVEX = ("point", "line", "ray", "segment", "disk")


def _unique_roles(case):
    """(mover kind, mover data, target kind, target data) for reference_unique, or None: the
    mover is a shape of one bounded parameter (a circle's or arc's angle, a Bezier curve's t), the
    target any shape with a closed-form point distance (canonical order as the cases have it)."""
    ka, kb = case["a"], case["b"]
    a, b = case["a_data"], case["b_data"]
    if ka == "bezier" and kb != "bezier":
        return "bezier", a, kb, b
    if ka in ("line", "ray", "segment", "disk") and kb in ("circle", "arc"):
        return kb, b, ka, a
    if ka == "circle" and kb in ("disk", "circle", "annulus"):
        return ka, a, kb, b
    if (ka, kb) == ("circle", "arc"):
        return kb, b, ka, a
    if ka == "arc" and kb in ("arc", "annulus"):
        return ka, a, kb, b
    if ka in ("line", "ray", "segment") and kb in ("disk", "annulus"):
        return ka, a, kb, b
    return None


def _target_point_unique(p, kind, data, margin):
    """Whether the target's nearest point to the mp point p is unique with `margin` (an mpf: the
    direct rule's REF_UNIQUE_REL x max(d, scale), the scene's scale, not the target's own size):
    a convex target's always; a circle's, an arc's or an annulus's (the point-round rule's closed
    forms, _point_round_unique's, at 50 digits) where every other candidate for the nearest
    point is worse by the margin, and the rim holding it is not flat -- its farthest point, the
    other critical point, worse by the margin too (a point near the axis, or a small rim seen
    from far in a large scene, is as far from a stretch of the rim as double can tell: found
    with the margin relative to the target's own radius, a huge arc's end 9.6e7 from an annulus
    of outer radius 0.16, and a huge circle crossing a tiny-holed annulus 8e-8 from its axis).
    Candidates: a circle's nearest point; an arc's in-span point and ends (the in-span point
    only where the point's angle lies in the span); an annulus's projection (over the ring),
    its outer rim's nearest point and its inner rim's nearest and farthest points (the farthest
    is a local minimum over the annulus: the hole's boundary opposite the point)."""
    if kind in _CONVEX:
        return True
    R = _load("reference_round")
    ctx = R.ctx
    if kind == "arc":
        A = _load("reference_arc")
        arc = A.ArcMP(A.shape(kind, data))
        w = R.sub(p, arc.c)
        z, x, y = R.dot(w, arc.n), R.dot(w, arc.u), R.dot(w, arc.v)
        rho, r = ctx.sqrt(x * x + y * y), arc.r
    else:
        rnd = R.make_round(data[:3], data[3:6], data[6])
        w = R.sub(p, rnd.center)
        z = R.dot(w, rnd.n)
        rho, r = R.norm(R.sub(w, R.scale(z, rnd.n))), rnd.radius
    near, far = ctx.sqrt(z * z + (rho - r) ** 2), ctx.sqrt(z * z + (rho + r) ** 2)
    if kind == "circle" or (kind == "arc" and arc.whole):
        return far - near > margin
    if kind == "arc":
        phi = ctx.atan2(y, x)
        if phi < 0:
            phi += 2 * ctx.pi
        ends = [R.dist(p, arc.at(R.mpf(0))), R.dist(p, arc.at(arc.angle))]
        cands = sorted(([near] if rho > 0 and phi <= arc.angle else []) + ends)
        return cands[1] - cands[0] > margin and far - near > margin
    # an annulus: (distance, whether its point is clear) per candidate; inner 0 is the disk (convex),
    # inner = outer the circle
    ri = R.to_mp(data[7])
    if ri == 0:
        return True
    if ri == r:
        return far - near > margin
    cands = [(near, far - near > margin)]
    if ri <= rho <= r:
        cands.append((abs(z), True))
    near_i, far_i = ctx.sqrt(z * z + (rho - ri) ** 2), ctx.sqrt(z * z + (rho + ri) ** 2)
    cands += [(near_i, far_i - near_i > margin), (far_i, True)]
    cands.sort(key=lambda c: c[0])
    return cands[0][1] and cands[1][0] - cands[0][0] > margin


def reference_unique(case):
    """(True, why) or (None, "") from a 50-digit one-parameter search, for the pairs of
    _unique_roles: a circle or arc against a line, ray, segment, disk, circle, arc or annulus, a
    Bezier curve against any of those and a point, a line, ray or segment against a disk or
    annulus (not two disks, a disk or annulus against an annulus: regions on both sides).

    The mover's parameter x (a rim's angle, a curve's t, a linear piece's length over the
    stretch that holds its closest points) is searched for the least distance from the mover's
    point P(x) to the target (the target's closed form: reference_arc's, reference_annulus's) by
    reference_round.minimize_1d, zoomed as reference_arc's (Lipschitz: the radius, the curve's
    hodograph bound, 1; resolution: the distance, and a round target's radius, ring width and
    hole / 8); a Bezier curve against a point, line, ray, segment, circle or disk reuses the
    distance reference's own minima (mp_reference: bezier_other, bezier_circle, bezier_disk).
    A closest pair is (P(x), Q) with x a global minimiser and Q a nearest target point of P(x),
    so it is unique where (1) the best local minimum beats every other distinct one (parameters
    1e-9 apart) by REF_UNIQUE_REL x max(d, s) (s: bar_scale, the largest radius, or a
    Bezier-linear query's size), (2) it is strict: the distance rises by REF_UNIQUE_RISE x
    max(d, s) within REF_UNIQUE_STEP (a linear piece: that x the target's radius) on each side
    inside the parameter's range (a minimum at an end of an open arc, a curve or a piece on its
    inner side only; a minimum short of an end against the end itself) -- not a flat run of
    minima (a circle over a disk's face, a curve along a line) -- and (3) the target's nearest
    point to P(x) is unique with the margin of (1) (_target_point_unique: a convex target's
    always; a circle's, arc's or annulus's where the point-round rule's other candidates, at 50
    digits, are worse by it and the rim holding the point is not flat).  Otherwise
    None: the rule never says False from sampling (expected_unique's exact continua do).  Used
    by reference_check (the direct 50-digit comparison of a few cases) and unique_direct_check
    (the long mode's sample), not by the screen."""
    roles = _unique_roles(case)
    if roles is None:
        return None, ""
    mk, md, tk, td = roles
    A, R = _load("reference_arc"), _load("reference_round")
    if tk == "annulus":
        target = _load("reference_annulus").AnnulusMP(ann_shape(tk, td)).point_distance
    else:
        target = A.point_distance_function(A.shape(tk, td))
    if mk == "circle":
        rad = R.to_mp(md[6])
        at, hi, periodic = R.make_round(md[:3], md[3:6], md[6]).rim_point, 2 * R.ctx.pi, True
        lipschitz, intervals = (lambda a_, b_: rad), A.INTERVALS
    elif mk == "arc":
        arc = A.ArcMP(A.shape(mk, md))
        rad = arc.r
        at, periodic = arc.at, arc.whole
        hi = 2 * R.ctx.pi if arc.whole else arc.angle
        lipschitz, intervals = (lambda a_, b_: rad), A.INTERVALS
    elif mk == "bezier":
        pts = [R.vec(p) for p in md]
        if len(pts) < 2:
            return None, ""
        at, hi, periodic = (lambda t: R.bezier_point(pts, t)), R.mpf(1), False
        lipschitz, intervals = R._speed_bound(md), R.CURVE_SAMPLES
    else:
        # a line, ray or segment by its arc length x from x0 (the start of its stretch): a point
        # with |x - s*| > |P(s*) - C| + 2 R (s*: nearest the target's centre C, R: its radius) is
        # farther from the target than P(s*), so the stretch within that of s* holds every
        # closest point (reference_annulus.curves_of alike)
        o, d = R.vec(md[:3]), R.vec(md[3:6])
        if mk == "segment":
            d = R.sub(d, o)
        length = R.norm(d)
        if length == 0:
            return None, ""
        u = R.scale(1 / length, d)
        C = R.vec(td[:3])
        s_star = R.dot(R.sub(C, o), u)
        reach = (R.dist(R.add(o, R.scale(s_star, u)), C) + 2 * R.to_mp(td[6])) * (1 + R.mpf("1e-6")) + R.mpf("1e-300")
        x0, x1 = s_star - reach, s_star + reach
        if mk in ("ray", "segment"):
            x0 = max(x0, R.mpf(0))
        if mk == "segment":
            x1 = min(x1, length)
        if x0 >= x1:  # the stretch past the piece's end: only the end can be closest
            return None, ""
        at, hi, periodic = (lambda x: R.add(o, R.scale(x0 + x, u))), x1 - x0, False
        lipschitz, intervals = (lambda a_, b_: R.mpf(1)), A.INTERVALS
    scale0 = R.mpf(max(bar_scale(case), 1e-300))
    # a round target's features (its radius; an annulus's ring width and hole) resolved to / 8
    feats = []
    if tk in ("circle", "arc"):
        feats = [float(td[6])]
    elif tk == "annulus":
        feats = [x for x in (float(td[6]), float(td[6]) - float(td[7]), float(td[7])) if x > 0]
    round_res = R.mpf(min(feats)) / R.ZOOM_FRACTION if feats else None
    seen = {}
    floor = R.mpf("1e-20") * scale0

    def f(t):
        v = target(at(t))
        seen[t._mpf_] = v
        return v

    def resolution(lo_, hi_, lh):
        res = max(min(seen[lo_._mpf_], seen[hi_._mpf_]) - lh / 2, floor) / R.ZOOM_FRACTION
        return res if round_res is None else min(res, round_res)

    if mk == "bezier" and tk in ("point", "line", "ray", "segment", "circle", "disk"):
        # the distance reference's own search (mp_reference: reference_round.bezier_other,
        # bezier_circle, bezier_disk), its refined local minima over t
        key = _key(case)
        if key not in _CURVE_MINIMA:
            _REF_CACHE.pop(key, None)
            mp_reference(case)
        minima = [R.LocalMin(v, t, None) for v, t in _CURVE_MINIMA[key]]
    else:
        minima = R.minimize_1d(f, R.mpf(0), hi, intervals, periodic=periodic, lipschitz=lipschitz,
                               resolution=resolution, max_samples=A.ZOOM_SAMPLES)
    if not minima:
        return None, ""
    best = minima[0]
    scale = max(best.value, scale0)
    period = hi if periodic else None
    for m in minima[1:]:
        gap = abs(m.x - best.x)
        if period is not None:
            gap = min(gap, abs(period - gap))
        if gap > R.mpf("1e-9") and m.value - best.value <= R.mpf(REF_UNIQUE_REL) * scale:
            return None, ""
    # the step: in radians of a rim, in t of a curve, in radii of the target along a line
    delta = R.mpf(REF_UNIQUE_STEP) * (R.to_mp(td[6]) if mk in ("line", "ray", "segment") else 1)
    if periodic:
        sides = [best.x + delta, best.x - delta]
    else:
        # clamped to the range: a minimum at an end rises on its inner side only; one short of an
        # end must rise towards it too (the end itself, at most delta away, is that side)
        sides = [min(best.x + delta, hi) if best.x < hi else None, max(best.x - delta, R.mpf(0)) if best.x > 0 else None]
        sides = [x for x in sides if x is not None]
    if not sides or any(f(x) - best.value <= R.mpf(REF_UNIQUE_RISE) * scale for x in sides):
        return None, ""
    if not _target_point_unique(at(best.x), tk, td, R.mpf(REF_UNIQUE_REL) * scale):
        return None, ""
    name = {"circle": "the circle's angle", "arc": "the arc's angle", "bezier": "the curve's t",
            "line": "the line", "ray": "the ray", "segment": "the segment"}[mk]
    return True, (f"the 50-digit minimum over {name} of the distance to the {tk} is single and strict, "
                  f"and the {tk}'s nearest point to it unique")


def unique_direct_check(cd, cases, combo_list=None, stats=None):
    """closest_points().unique against reference_unique for the cases (float64 scenes; the
    float64 and long double combinations, both orders) where expected_unique says nothing and
    reference_unique says True: the long mode's sample of the direct check (reference_check does
    the same on its cases).  Returns the findings (confirmed: the rule is a 50-digit search of
    its own); stats (optional) receives "unique_checked_direct" as reference_check's."""
    combo_list = [(s_, p_) for s_, p_ in (combo_list or combos()) if p_ != "float32"]
    counts = collections.Counter()
    if stats is not None:
        stats.setdefault("unique_checked_direct", collections.Counter())
        counts = stats["unique_checked_direct"]
    findings = []
    for c in cases:
        if expected_unique(c)[0] is not None or _unique_roles(c) is None:
            continue
        uexp = reference_unique(c)
        if uexp[0] is None:
            continue
        sa, sb = make_shape(cd, c["a"], c["a_data"], np.float64), make_shape(cd, c["b"], c["b_data"], np.float64)
        for solver, precision in combo_list:
            for order, (x, y) in (("ab", (sa, sb)), ("ba", (sb, sa))):
                v, err = _call(cd.closest_points, x, y, solver=solver, precision=precision)
                if err:
                    findings.append(_finding("exception", c, solver, precision, order, "closest_points", error=err))
                    continue
                counts[f"{c['a']}-{c['b']} {uexp[0]} (reference)"] += 1
                if bool(v.unique) != uexp[0]:
                    f = _finding("unique", c, solver, precision, order, "closest_points", library=bool(v.unique),
                                 expected=uexp[0], why=uexp[1] + " (direct)", distance=v.distance)
                    f["confirmed"] = True
                    findings.append(f)
    return findings


def _check_unique(res, d_orders, solver, precision, gcases, stats):
    """closest_points().unique against expected_unique, both orders."""
    out = []
    exp = [expected_unique(c) for c in gcases]
    rows = [j for j, (e, _) in enumerate(exp) if e is not None]
    if not rows:
        return out
    for order in d_orders:
        u = np.asarray(res[order]["r"].unique)
        # (not library answers of their own: counted apart, by expectation)
        for j in rows:
            stats["unique_checked"][str(exp[j][0])] += 1
        for j in rows:
            if bool(u[j]) != exp[j][0]:
                out.append(_finding("unique", gcases[j], solver, precision, order, "closest_points",
                                    library=bool(u[j]), expected=exp[j][0], why=exp[j][1],
                                    distance=np.asarray(res[order]["r"].distance)[j]))
    return out


def _d_array(x, precision):
    return np.asarray(x, dtype={"float32": np.float32, "float64": np.float64, "longdouble": np.longdouble}[precision])


def _check_within(cd, res, SA, SB, d_orders, solver, precision, gcases, ps, bar_abs, inaccurate, stats):
    """within / distance_if_within / intersects against the library's own distance D and the
    documented rule  within(a, b, d) == (D <= d + 64 eps (s + d)):  probed at D +- 4x that
    tolerance (at least the bar), where the rule leaves no latitude.  Where D itself failed the
    accuracy check the finding is filed as "within_vs_inaccurate_distance" (a symptom)."""
    out = []
    wres = {}
    kw = dict(solver=solver, precision=precision)
    eps = OUT_EPS[precision]
    for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
        if order not in d_orders:
            continue
        dd = d_orders[order]
        Df = dd.astype(float)
        lo, hi, band = _within_limits(Df, ps, eps, bar_abs)
        lo = np.maximum(lo, 0.0)
        hi_a, lo_a = _d_array(hi, precision), _d_array(lo, precision)
        w_hi, e1 = _call(cd.within, x, y, hi_a, **kw)
        w_lo, e2 = _call(cd.within, x, y, lo_a, **kw)
        b_hi, e3 = _call(cd.distance_if_within, x, y, hi_a, **kw)
        b_lo, e4 = _call(cd.distance_if_within, x, y, lo_a, **kw)
        it, e5 = _call(cd.intersects, x, y, **kw)
        n = len(gcases)
        for entry, v in (("within", w_hi), ("within", w_lo), ("distance_if_within", b_hi),
                         ("distance_if_within", b_lo), ("intersects", it)):
            stats["answers"][entry] += n if v is not None else 0
        err = e1 or e2 or e3 or e4 or e5
        if err:
            out.append(_finding("exception", gcases[0], solver, precision, order, "within", error=err))
            continue
        w_hi, w_lo, it = np.asarray(w_hi), np.asarray(w_lo), np.asarray(it)
        b_hi, b_lo = np.asarray(b_hi), np.asarray(b_lo)
        wres[order] = (hi_a, lo_a, w_hi, w_lo, it)
        for j in range(len(gcases)):
            bad = []
            if not w_hi[j]:
                bad.append(f"within(d={float(hi[j])!r}) is False")
            if lo[j] > 0 and w_lo[j]:
                bad.append(f"within(d={float(lo[j])!r}) is True")
            if not _eq(b_hi[j], dd[j]):
                bad.append(f"distance_if_within(d={float(hi[j])!r}) = {b_hi[j]!r}")
            if lo[j] > 0 and not np.isinf(b_lo[j]):
                bad.append(f"distance_if_within(d={float(lo[j])!r}) = {b_lo[j]!r}")
            if Df[j] == 0 and not it[j]:
                bad.append("intersects is False at distance 0")
            if Df[j] > 4 * 64 * eps * ps[j] and Df[j] > bar_abs[j] and it[j]:
                bad.append("intersects is True")
            if bad:
                check = "within_vs_inaccurate_distance" if j in inaccurate.get(order, ()) else "within"
                out.append(_finding(check, gcases[j], solver, precision, order, "within/intersects",
                                    library=dd[j], problems=bad, pair_scale=ps[j]))
    return out, wres


def _check_scalar(cd, ka, kb, res, d_orders, wres, sel, gcases, solver, precision, stats):
    """Scalar calls must give exactly the batch's answers (distance, closest points, within at
    the batch's probe limits, intersects)."""
    out = []
    kw = dict(solver=solver, precision=precision)
    dt = _dtype(precision)
    for j in sel:
        c = gcases[j]
        sa = make_shape(cd, ka, c["a_data"], dt)
        sb = make_shape(cd, kb, c["b_data"], dt)
        for order, (x, y) in (("ab", (sa, sb)), ("ba", (sb, sa))):
            if order not in d_orders:
                continue
            d, e1 = _call(cd.distance, x, y, **kw)
            r, e2 = _call(cd.closest_points, x, y, **kw)
            stats["answers"]["scalar distance"] += not e1
            stats["answers"]["scalar closest_points"] += not e2
            if e1 or e2:
                out.append(_finding("exception", c, solver, precision, order, "scalar", error=e1 or e2))
                continue
            rb = res[order]["r"]
            problems = []
            if not _eq(d, d_orders[order][j]):
                problems.append(f"distance: scalar {d!r} batch {d_orders[order][j]!r}")
            if not _eq(r.distance, np.asarray(rb.distance)[j]):
                problems.append(f"closest_points.distance: scalar {r.distance!r} batch {np.asarray(rb.distance)[j]!r}")
            if not (np.all(_eq(np.asarray(r.point_a), np.asarray(rb.point_a)[j]))
                    and np.all(_eq(np.asarray(r.point_b), np.asarray(rb.point_b)[j]))):
                problems.append("closest points differ: scalar %r %r batch %r %r" % (
                    np.asarray(r.point_a), np.asarray(r.point_b), np.asarray(rb.point_a)[j], np.asarray(rb.point_b)[j]))
            if order in wres:
                hi_a, lo_a, w_hi, w_lo, it = wres[order]
                for lim, wb in ((hi_a[j], w_hi[j]), (lo_a[j], w_lo[j])):
                    ws, e3 = _call(cd.within, x, y, lim, **kw)
                    stats["answers"]["scalar within"] += not e3
                    if e3:
                        problems.append(f"within raised {e3}")
                    elif bool(ws) != bool(wb):
                        problems.append(f"within(d={lim!r}): scalar {ws} batch {wb}")
                its, e4 = _call(cd.intersects, x, y, **kw)
                stats["answers"]["scalar intersects"] += not e4
                if e4 or bool(its) != bool(it[j]):
                    problems.append(f"intersects: scalar {its} batch {it[j]} {e4 or ''}")
            if problems:
                out.append(_finding("batch_scalar", c, solver, precision, order, "scalar", problems=problems))
    return out


# =============================================================================================
# 4. confirmation with the 50-digit references
# =============================================================================================
_REF_CACHE = {}
# a Bezier curve against a point, line, ray, segment, circle or disk: the reference's refined local
# minima over the curve's t, [(distance, t)] lowest first (reused by reference_unique)
_CURVE_MINIMA = {}


def _key(case):
    def t(d):
        return tuple(tuple(p) for p in d) if d and isinstance(d[0], list) else tuple(d)
    return (case["a"], t(case["a_data"]), case["b"], t(case["b_data"]))


def mp_reference(case):
    """The 50-digit reference distance (mpf) of a case (canonical order), cached."""
    key = _key(case)
    if key in _REF_CACHE:
        return _REF_CACHE[key]
    L, R = _load("reference"), _load("reference_round")
    ka, a, kb, b = key
    if kb == "annulus":
        ref = _ann_reference(ka, a, b)
    elif kb == "arc":
        ref = _load("reference_arc").case_reference(ka, list(a), kb, list(b))
    elif kb in LINEAR and ka in LINEAR:
        ref = _load("reference_linear").linear_linear(ka, a, kb, b)
    elif kb in LINEAR:
        full = R.bezier_other([list(p) for p in a], kb, *_piece_points(kb, b))
        _CURVE_MINIMA[key] = [(p.value, p.t) for p in full.pairs]
        ref = full.distance
    elif ka in LINEAR:
        ref = L.reference(ka, a, kb, b).distance
    elif ka == "bezier":
        f = R.bezier_disk if kb == "disk" else R.bezier_circle
        full = f([list(p) for p in a], b[:3], b[3:6], b[6])
        _CURVE_MINIMA[key] = [(p.value, p.t) for p in full.pairs]
        ref = full.distance
    else:
        f = {("circle", "circle"): R.circle_circle, ("circle", "disk"): R.circle_disk,
             ("disk", "disk"): R.disk_disk}[(ka, kb)]
        ref = f(a[:3], a[3:6], a[6], b[:3], b[3:6], b[6]).distance
    _REF_CACHE[key] = ref
    return ref


def ann_shape(kind, data):
    """reference_annulus's tuple of a shape given as the differential's flat data list (an
    annulus: centre, normal, outer, inner here; (center, normal, inner, outer) there)."""
    if kind == "annulus":
        d = [float(x) for x in data]
        return _load("reference_annulus").annulus(d[:3], d[3:6], d[7], d[6])
    return _load("reference_arc").shape(kind, data)


def _ann_reference(ka, a, b):
    """The 50-digit distance of a case with an annulus (canonical order: the annulus second):
    reference_annulus's minimum of closed forms over the other shape's parameter, and rim by
    rim for regions (its docstring says why that is exact); a Bezier curve: over its t."""
    RA = _load("reference_annulus")
    if ka == "bezier":
        return RA.bezier_reference_mp(ann_shape("annulus", b), [list(p) for p in a])
    return RA.reference_mp(ann_shape("annulus", b), ann_shape(ka, a))


def _piece_points(kind, data):
    """A point's (p,), a line's or ray's (origin, direction), a segment's (p0, p1)."""
    return (data[:3],) if kind == "point" else (data[:3], data[3:6])


def _mp_piece_distance(p, kind, data):
    """The 50-digit distance (reference_round's context) from the mp point p to a linear piece."""
    R = _load("reference_round")
    if kind == "point":
        return R.dist(p, R.vec(data[:3]))
    return R.point_linear_closest(p, kind, R.vec(data[:3]), R.vec(data[3:6]))[0]


def _mp_line_point(ka, a, C, x):
    """The point (reference_round's context) of the line, ray or segment a at the screen's
    parameter x: relative to the anchor (a's point nearest C), in units of the direction scaled
    by the power of two sc of _anchor: t = tc + x sc."""
    L, R = _load("reference"), _load("reference_round")
    lin = L.Linear(ka, a)
    if lin.mm == 0:
        t = L.mpf(0)
    else:
        m = np.asarray(a[3:6], float)
        if ka == "segment":
            m = _two_sum(m, -np.asarray(a[:3], float))[0]
        sc = 2.0 ** -math.floor(math.log2(max(float(np.max(np.abs(m))), 1e-300)))
        tc = -L._dot(L._sub(lin.B, L._v(C)), lin.m) / lin.mm
        t = lin.clamp(tc + L.mpf(R.ctx.nstr(x, 60)) * L.mpf(sc))
    return tuple(R.mpf(L.mp.nstr(c, 60)) for c in lin.point(t))


def _mpf_ld(x):
    R = _load("reference_round")
    p, q = np.longdouble(x).as_integer_ratio()
    return R.mpf(p) / q


def mp_screen_value(case, form, param):
    """The screen's best pair re-evaluated at 50 digits: the exact distance between the genuine
    point the screen's parameter names and the other shape (an upper bound of the truth)."""
    L, R = _load("reference"), _load("reference_round")
    ka, kb = case["a"], case["b"]
    a, b = case["a_data"], case["b_data"]
    x = _mpf_ld(param) if not isinstance(param, tuple) else None
    ctx = R.ctx
    if form == "point":
        return _mp_rim_distance(R.vec(a[:3]), kb, b)
    if form in ("rim|linear", "rim_inner|linear"):
        p = _mp_rim(kb, b, x, inner=form == "rim_inner|linear")
        return L.Linear(ka, a).distance_to_point(tuple(L.mpf(ctx.nstr(c, 60)) for c in p))
    if form == "line|round":
        return _mp_rim_distance(_mp_line_point(ka, a, b[:3], x), kb, b)
    if form == "point|linear":
        return _mp_piece_distance(R.vec(a[:3]), kb, b)
    if form == "line|linear":
        C, s = param
        return _mp_piece_distance(_mp_line_point(ka, a, C, _mpf_ld(s)), kb, b)
    if form in ("bezier|linear", "bezier_reversed|linear"):
        lo_, hi_, u = param
        t = R.mpf(lo_) + _mpf_ld(u) * (R.mpf(hi_) - R.mpf(lo_))
        return _mp_piece_distance(R.bezier_point(a, t if form == "bezier|linear" else 1 - t), kb, b)
    if form in ("bezier|round", "bezier_reversed|round"):
        lo_, hi_, u = param
        t = R.mpf(lo_) + _mpf_ld(u) * (R.mpf(hi_) - R.mpf(lo_))
        return _mp_rim_distance(R.bezier_point(a, t if form == "bezier|round" else 1 - t), kb, b)
    if form in ("rim_a|b", "rim_a_inner|b"):
        return _mp_rim_distance(_mp_rim(ka, a, x, inner=form == "rim_a_inner|b"), kb, b)
    return _mp_rim_distance(_mp_rim(kb, b, x, inner=form == "rim_b_inner|a"), ka, a)


def _mp_rim(kind, data, x, inner=False):
    """The point (reference_round's context) at the screen's angle x of a circle or disk's rim
    (the frame of _ld_frame, which the references build alike), of an annulus's outer or (inner)
    inner rim (the same frame) or of an arc (from its start)."""
    if kind == "arc":
        A = _load("reference_arc")
        return A.ArcMP(A.shape(kind, data)).at(x)
    return _load("reference_round").make_round(data[:3], data[3:6], data[7] if inner else data[6]).rim_point(x)


def _mp_rim_distance(p, kind, data):
    """The 50-digit distance from the mp point p to a circle, disk, arc or annulus (closed forms)."""
    if kind == "annulus":
        return _load("reference_annulus").AnnulusMP(ann_shape(kind, data)).point_distance(p)
    A = _load("reference_arc")
    return A.point_distance_function(A.shape(kind, data))(p)


def confirm(finding, case, screen_info):
    """Judge an accuracy finding (above_bound / below_bound / distance_vs_closest_points) against
    the 50-digit reference.  Adds reference, reference_screen (the screen's pair at 50 digits),
    reference_missed (the screen's pair beats the reference: the reference is wrong there),
    error (relative) and confirmed."""
    f32 = finding["precision"] == "float32"
    c = to_float32_case(case) if f32 else case
    ref = mp_reference(c)
    form = screen_info["form32" if f32 else "form"]
    param = screen_info["param32" if f32 else "param"]
    try:
        scr = mp_screen_value(c, form, param)
    except Exception as e:  # noqa: BLE001
        scr = None
        finding["reference_screen_error"] = str(e)
    best = ref
    finding["basis"] = "mpmath reference"
    if scr is not None:
        finding["reference_screen"] = float(scr)
        R = _load("reference_round")
        scale_ = max(abs(ref), R.mpf(bar_scale(c)), R.mpf("1e-300"))
        if scr < ref - R.mpf(MISS_REL) * scale_:
            finding["reference_missed"] = True
            finding["basis"] = "the screen's pair at 50 digits (the mpmath reference missed the minimum)"
            best = scr
    finding["reference"] = float(best)
    scale_ = max(float(best), bar_scale(c))
    bar = BARS[finding["precision"]] * scale_
    vals = [finding[k] for k in ("library", "distance", "closest_points") if k in finding]
    # long-double answers are stored as 25-digit text (exact far below their ulp)
    errs = [abs(_mp_num(v) - best) for v in vals if not (isinstance(v, str) and v in ("nan", "inf"))]
    finding["error"] = float(max(errs) / scale_) if errs and scale_ > 0 else None
    finding["confirmed"] = bool(errs) and bool(max(errs) > bar)
    return finding


def confirm_point(finding, case):
    """Re-measure point_off_shape at 50 digits (closed forms; Bezier: the 50-digit point-curve
    distance by the reference's one-parameter minimisation)."""
    L, R = _load("reference"), _load("reference_round")
    ka, kb = finding["kinds"]
    a, b = finding["a_data"], finding["b_data"]
    offs = []
    for kind, data, p in ((ka, a, finding["point_a"]), (kb, b, finding["point_b"])):
        # points are stored exactly (long-double ones as 25-digit text)
        if kind == "bezier":
            offs.append(float(R.bezier_disk(data, list(p), (0.0, 0.0, 1.0), 0.0).distance))
        elif kind == "arc":
            A = _load("reference_arc")
            offs.append(float(A.ArcMP(A.shape(kind, data)).point_distance(tuple(_mp_num(x) for x in p))))
        elif kind == "annulus":
            offs.append(float(_mp_rim_distance(tuple(_mp_num(x) for x in p), kind, data)))
        else:
            offs.append(float(L.distance_to_shape(tuple(L.mpf(x) for x in p), kind, tuple(data))))
    finding["off_a_mp"], finding["off_b_mp"] = offs
    finding["confirmed"] = max(offs) > finding["allowed"]
    return finding


ACCURACY_CHECKS = ("above_bound", "below_bound", "distance_vs_closest_points")
# a genuine pair (the screen's, at 50 digits) below the reference by more than this (relative to
# max(reference, largest radius)) means the reference missed the minimum: 1e-3 of the tightest bar
MISS_REL = "1e-18"


EXACT_CHECKS = ("within", "within_vs_inaccurate_distance", "asymmetric", "batch_scalar", "dtype", "float32_value",
                "whole_arc_vs_circle", "degenerate_annulus_vs_disk", "degenerate_annulus_vs_circle", "unique",
                "exception", "non_finite")


def _mp_num(v):
    R = _load("reference_round")
    return R.mpf(v) if isinstance(v, str) else R.mpf(float(v))


def confirm_separation(finding):
    """Re-measure a separation mismatch at 50 digits from the stored points."""
    R = _load("reference_round")
    pa = [_mp_num(x) for x in finding["point_a"]]
    pb = [_mp_num(x) for x in finding["point_b"]]
    sep = R.norm(R.sub(tuple(pa), tuple(pb)))
    finding["separation_mp"] = float(sep)
    finding["confirmed"] = bool(abs(sep - _mp_num(finding["library"])) > _mp_num(finding["allowed"]))
    return finding


def confirm_finding(finding, case, screen_info):
    """Confirm one finding: accuracy findings against the 50-digit reference, point findings by
    50-digit residuals; the exact consistency checks (within, symmetry, batch == scalar, dtypes,
    exceptions) need no reference and are confirmed as they stand."""
    check = finding["check"]
    if check in ACCURACY_CHECKS:
        return confirm(finding, case, screen_info)
    if check == "point_off_shape":
        return confirm_point(finding, case)
    if check == "separation":
        return confirm_separation(finding)
    finding["confirmed"] = True
    return finding


def finding_class(f):
    """The class a finding is counted and reproduced under."""
    return (f["check"], f["family"], f["pair"])


def _lit(x):
    return repr(float(x)) if not isinstance(x, str) else x


def _ctor_text(kind, data, f32):
    def vec(v):
        body = ", ".join(_lit(x) for x in v)
        return f"np.array([{body}], np.float32)" if f32 else f"[{body}]"
    def scal(x):
        return f"np.float32({_lit(x)})" if f32 else _lit(x)
    if kind == "bezier":
        rows = ", ".join("[" + ", ".join(_lit(x) for x in p) + "]" for p in data)
        return f"cd.Bezier(np.array([{rows}]{', np.float32' if f32 else ''}))"
    if kind == "point":
        return f"cd.Point({vec(data[:3])})"
    if kind == "segment":
        return f"cd.Segment({vec(data[:3])}, {vec(data[3:6])})"
    if kind in ("line", "ray"):
        return f"cd.{kind.capitalize()}({vec(data[:3])}, {vec(data[3:6])})"
    if kind == "arc":
        return f"cd.Arc({vec(data[:3])}, {vec(data[3:6])}, {scal(data[6])}, {vec(data[7:10])}, {scal(data[10])})"
    if kind == "annulus":
        return f"cd.Annulus({vec(data[:3])}, {vec(data[3:6])}, {scal(data[7])}, {scal(data[6])})"
    return f"cd.{kind.capitalize()}({vec(data[:3])}, {vec(data[3:6])}, {scal(data[6])})"


def reproducer(f):
    """A self-contained Python snippet reproducing one finding (exact float inputs)."""
    f32 = f["precision"] == "float32"
    ka, kb = f["kinds"]
    kw = f'solver="{f["solver"]}", precision="{f["precision"]}"'
    lines = ["import numpy as np, circledist as cd",
             f"a = {_ctor_text(ka, f['a_data'], f32)}",
             f"b = {_ctor_text(kb, f['b_data'], f32)}"]
    check = f["check"]
    if check in ("within", "within_vs_inaccurate_distance"):
        lines.append(f"print(repr(cd.distance(a, b, {kw})))   # library {f.get('library')}")
        for p in f.get("problems", []):
            lines.append(f"# {p}")
        lines.append(f"print(cd.within(a, b, d, {kw}), cd.intersects(a, b, {kw}))  # d from the lines above")
    elif check == "unique":
        lines.append(f"r = cd.closest_points(a, b, {kw})")
        lines.append(f"print(r.unique, repr(r.distance))   # expected {f.get('expected')}: {f.get('why')}")
    elif check in ("point_off_shape", "separation"):
        lines.append(f"r = cd.closest_points(a, b, {kw})")
        lines.append("print(repr(r.distance), r.point_a, r.point_b)")
    else:
        entry = "closest_points(a, b, %s).distance" % kw if f.get("entry") == "closest_points" else \
            "distance(a, b, %s)" % kw
        lines.append(f"print(repr(cd.{entry}))")
    note = {k: f[k] for k in ("library", "reference", "reference_screen", "error", "screen", "problems", "ab", "ba",
                              "off_a", "off_b", "allowed", "separation", "distance", "closest_points", "error")
            if k in f}
    lines.append("# " + ", ".join(f"{k}={v}" for k, v in note.items()))
    return "\n".join(lines)


def reference_check(cd, cases, combo_list=None, stats=None):
    """Direct 50-digit comparison for a (small) set of cases: every combination, both orders,
    distance() and closest_points().distance against mp_reference, and closest_points().unique
    against expected_unique or (float64 scenes) reference_unique.  Returns (findings,
    diagnostics) where diagnostics lists screen-vs-reference disagreements (a reference that
    misses a pair the screen found, or a screen bound above the reference).  stats (a dict,
    optional) receives "unique_checked_direct": a Counter of the unique answers checked, keyed
    "a-b expected (rule)" (rule: "exact" for expected_unique, "reference" for reference_unique)."""
    combo_list = combo_list or combos()
    counts = collections.Counter()
    if stats is not None:
        stats["unique_checked_direct"] = counts
    findings, diags = [], []
    for case in cases:
        for f32 in sorted({p == "float32" for _, p in combo_list}):
            c = to_float32_case(case) if f32 else case
            ref = mp_reference(c)
            scr = screen([c], use_ld=not f32)
            try:
                scr_mp = mp_screen_value(c, scr.forms[0], scr.params[0])
            except Exception as e:  # noqa: BLE001
                scr_mp = None
                diags.append(dict(case_id=case["id"], problem=f"screen point not re-evaluable: {e}"))
            R = _load("reference_round")
            best = ref
            scale_ = max(float(ref), bar_scale(c))
            if scr_mp is not None and scr_mp < ref - R.mpf(MISS_REL) * R.mpf(max(scale_, 1e-300)):
                diags.append(dict(case_id=case["id"], family=case["family"], pair=f"{case['a']}-{case['b']}",
                                  problem="reference missed the minimum", reference=float(ref),
                                  screen_mp=float(scr_mp), float32=f32))
                best = scr_mp
            tol = (BARS["float32"] if f32 else 1e-15) * scale_ + float(scr.slack[0])
            if float(scr.value[0]) > float(best) + tol:
                diags.append(dict(case_id=case["id"], family=case["family"], pair=f"{case['a']}-{case['b']}",
                                  problem="screen bound above the reference", reference=float(best),
                                  screen=float(scr.value[0]), float32=f32))
            sa = make_shape(cd, c["a"], c["a_data"], np.float32 if f32 else np.float64)
            sb = make_shape(cd, c["b"], c["b_data"], np.float32 if f32 else np.float64)
            uexp, rule = expected_unique(c), "exact"
            if uexp[0] is None and not f32:
                # (the float64 scene only: ~0.2 s of 50-digit sampling a case; a Bezier curve
                # against a point, line, ray, segment, circle or disk reuses mp_reference's minima)
                uexp, rule = reference_unique(c), "reference"
            for solver, precision in combo_list:
                if (precision == "float32") != f32:
                    continue
                bar = BARS[precision] * scale_
                for order, (x, y) in (("ab", (sa, sb)), ("ba", (sb, sa))):
                    for entry in ("distance", "closest_points"):
                        fn = cd.distance if entry == "distance" else cd.closest_points
                        v, err = _call(fn, x, y, solver=solver, precision=precision)
                        if err:
                            findings.append(_finding("exception", c, solver, precision, order, entry, error=err))
                            continue
                        if entry == "closest_points" and uexp[0] is not None:
                            counts[f"{c['a']}-{c['b']} {uexp[0]} ({rule})"] += 1
                        if entry == "closest_points" and uexp[0] is not None and bool(v.unique) != uexp[0]:
                            f = _finding("unique", c, solver, precision, order, entry, library=bool(v.unique),
                                         expected=uexp[0], why=uexp[1] + " (direct)")
                            f["confirmed"] = True
                            findings.append(f)
                        v = v if entry == "distance" else v.distance
                        e = abs(_mp_num(_jsonable(np.longdouble(v)) if precision == "longdouble" else float(v)) - best)
                        if e > bar:
                            f = _finding("reference", c, solver, precision, order, entry, library=np.longdouble(v)
                                         if precision == "longdouble" else float(v), reference=float(best),
                                         error=float(e) / scale_)
                            f["confirmed"] = True
                            findings.append(f)
    return findings, diags


# within(a, b, d) at these multiples of the distance D (0 is intersects), besides the limits
# D -+ 4x the tolerance that check_cases probes for every case: a bound that decides wrongly
# shows at one of them whatever its size (the reported upper bound of 2 - sqrt 2 for a distance
# of sqrt 6 said yes at 0.24 D).
EFFECT_PROBES = (0.0, 0.25, 0.5, 0.9, 1.1, 2.0)
EFFECT_SWEEPS = (0.0, 0.5)  # each shape swept by this (a swept shape's distance is max(0, D - sweeps))


def _with_sweep(shape, sweep):
    arrays = {name: value for name, value in shape.to_arrays().items() if name != "sweep"}
    return type(shape)(**arrays, sweep=sweep)


def check_effects_definition(cd, cases, sweeps=EFFECT_SWEEPS, scenes=True):
    """Every effect against its definition on the library's own distance D (effects.hpp):
    within(a, b, d) == (D <= d + 64 eps (s + d)) and intersects(a, b) == within(a, b, 0),
    distance_if_within(a, b, d) == (D if within else inf), for both argument orders, at d = D x
    EFFECT_PROBES and D -+ 4x the tolerance, batched and scalar, the shapes plain and swept
    (each by every value of `sweeps`); and the scene's paths to the same test:
    Scene.within(shape, d), Scene.within(name, d) and Scene.pairs_within(d) on a scene of the two
    shapes (unless `scenes` is False). float64, the default solver (the bounds are the same for every policy; check_cases
    probes the limits for every combination). Returns findings ("effect_definition"), confirmed as
    they stand (no reference: the rule is consistency between entry points)."""
    findings = []
    eps = EPS64
    for (ka, kb, _), idx in _group(cases).items():
        group = [cases[i] for i in idx]
        A = make_shape(cd, ka, [c["a_data"] for c in group])
        B = make_shape(cd, kb, [c["b_data"] for c in group])
        ps = np.array([pair_scale(c) for c in group])
        for sa in sweeps:
            for sb in sweeps:
                SA, SB = (_with_sweep(A, sa) if sa else A), (_with_sweep(B, sb) if sb else B)
                # the sweeps grow the pair's scale (bounds.hpp distance_bounds)
                s = ps + sa + sb
                for order, (x, y) in (("ab", (SA, SB)), ("ba", (SB, SA))):
                    D = np.asarray(cd.distance(x, y), float)
                    band = 4 * 64 * eps * (s + D)
                    limits = [D * f for f in EFFECT_PROBES] + [np.maximum(D - band, 0.0), D + band]
                    for d in limits:
                        want = D <= d + 64 * eps * (s + d)
                        clear = np.abs(D - d) > band / 2
                        w = np.asarray(cd.within(x, y, d))
                        b = np.asarray(cd.distance_if_within(x, y, d))
                        got_b = np.where(want, D, np.inf)
                        for j in np.flatnonzero(clear & ((w != want) | ~_eq(b, got_b))):
                            findings.append(_effect_finding(group[j], order, sa, sb, "within", D[j], d[j],
                                                            bool(w[j]), float(b[j])))
                    it = np.asarray(cd.intersects(x, y))
                    w0 = np.asarray(cd.within(x, y, np.zeros_like(D)))
                    for j in np.flatnonzero(it != w0):
                        findings.append(_effect_finding(group[j], order, sa, sb, "intersects", D[j], 0.0,
                                                        bool(it[j]), None))
                    for d in (0.5 * D, D + band):  # scalar calls give the batch's answers
                        w = np.asarray(cd.within(x, y, d))
                        for j in range(len(group)):
                            ws = bool(cd.within(x[j], y[j], float(d[j])))
                            if ws != bool(w[j]):
                                findings.append(_effect_finding(group[j], order, sa, sb, "scalar within", D[j], d[j],
                                                                ws, None))
                    if order == "ba" or not scenes:
                        continue
                    for j in range(len(group)):
                        findings += _check_scene_effects(cd, group[j], SA[j], SB[j], sa, sb, float(D[j]),
                                                         float(s[j]), float(band[j]))
    for f in findings:
        f["confirmed"] = True
    return findings


def _effect_finding(case, order, sa, sb, entry, D, d, got, got_distance):
    f = _finding("effect_definition", case, "default", "float64", order, entry, library=float(D), d=float(d),
                 answer=got, sweeps=[float(sa), float(sb)])
    if got_distance is not None:
        f["distance_if_within"] = got_distance
    return f


def _check_scene_effects(cd, case, a, b, sa, sb, D, s, band):
    """Scene.within (by shape and by name) and Scene.pairs_within on the scene {a, b} against
    the definition, at d = D x EFFECT_PROBES and D -+ band."""
    out = []
    scene = cd.Scene()
    scene.add("a", a)
    scene.add("b", b)
    for d in [D * f for f in EFFECT_PROBES] + [max(D - band, 0.0), D + band]:
        if abs(D - d) <= band / 2:
            continue
        want = D <= d + 64 * EPS64 * (s + d)
        got = {"Scene.within(shape)": ("b" in scene.within(a, d)) == want,
               "Scene.within(name)": scene.within("a", d) == (["b"] if want else []),
               "Scene.pairs_within": scene.pairs_within(d) == ([("a", "b")] if want else [])}
        for entry, ok in got.items():
            if not ok:
                out.append(_effect_finding(case, "ab", sa, sb, entry, D, d, not want, None))
    return out


def check_and_confirm(cd, cases, combo_list=None, scalar=None, max_confirm=None, within=True):
    """check_cases, then confirm_finding on the findings: all of them, or at most `max_confirm`
    per (class, solver, precision) (the rest keep confirmed = None).  Returns (findings, stats)."""
    screens = {}
    findings, stats = check_cases(cd, cases, combo_list, scalar, screens, within)
    effect_cases = [c for c in cases if c["family"] in EFFECT_FAMILIES]
    if within and effect_cases:
        findings += check_effects_definition(cd, effect_cases)
    index = {c["id"]: i for i, c in enumerate(cases)}
    done = {}
    for f in findings:
        key = finding_class(f) + (f["solver"], f["precision"])
        if max_confirm is not None and done.get(key, 0) >= max_confirm:
            f["confirmed"] = None
            continue
        i = index[f["case_id"]]
        confirm_finding(f, cases[i], screens[i])
        done[key] = done.get(key, 0) + 1
    stats["screens"] = screens
    return findings, stats


def check_case(cd, case, solver, precision, confirm_findings=True):
    """One case, one (solver, precision) combination: both orders, every entry point, batch of one
    and scalar; returns the findings (confirmed against the 50-digit references if asked)."""
    if confirm_findings:
        return check_and_confirm(cd, [case], [(solver, precision)])[0]
    return check_cases(cd, [case], [(solver, precision)])[0]
