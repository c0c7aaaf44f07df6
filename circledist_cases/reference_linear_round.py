"""Independent 50-digit references for circledist.

Nothing in this module shares an algorithm with the library under test.  The
derivations the library implements reduce line/circle problems to
a quartic and disk problems to interval partitions plus polynomial roots.
Here there are NO polynomials and NO root finding: every distance is the
global minimum of a closed-form function of ONE parameter, found by dense
sampling followed by golden-section refinement in mpmath at 50 digits.

Shapes and parameters
---------------------
"Linear" shapes S are the point, the line, the ray and the segment, all written
as  S(t) = B + t*m  with t restricted to a closed parameter set T:
point (m = 0, T = {0}), line (T = R), ray (T = [0, inf)), segment
(m = p1 - p0, T = [0, 1]; p0 == p1 is allowed and is a point).
"Round" shapes are the circle (ring) and the filled disk with centre C, normal
N (normalised here in mpmath) and radius R.  The circle frame {U, V, N} is
built here (U from the coordinate axis least aligned with N); the distance does
not depend on that choice.

Every input is taken as the EXACT binary64 values that the library receives:
the floats are converted to mpmath numbers without rounding, so a scene
translated by 1e8 is referenced exactly as the translated floats describe it.

Circle references (point/line/ray/segment against a circle)
-----------------------------------------------------------
    dist(S, circle) = min over theta in [0, 2*pi) of g(theta),
    g(theta) = dist(X(theta), S),  X(theta) = C + R (cos theta U + sin theta V),
and dist(X, S) has the closed form |X - S(t*)| with t* the orthogonal projection
parameter of X on the line through S clamped to T (S is convex, so the clamped
projection is its nearest point).  This is an identity, so the reference is
complete as soon as the global minimum of g is found.  To avoid cancellation,
the objective is evaluated in coordinates relative to C with the origin of S
moved to its point nearest C (a re-parametrisation t -> t - t_c).

Disk references
---------------
See ``_ref_disk`` for the candidate set and the proof that it is complete.  The
point-disk distance uses the closed form of the second note (written as
(rho - R)^2 + z^2 to avoid cancellation).  A second, unrelated disk reference
(``reference_by_line_parameter``) minimises the convex function
t -> dist(S(t), disk) and is used in the self-validation tests.

Global minimisation in one variable
-----------------------------------
``reference_kit.bracketed_min_1d``: 2048 samples of the squared objective in binary64 (cheap
numpy, used ONLY to place brackets); every sampled local minimum (runs of equal
samples merged; brackets that a Lipschitz bound shows cannot reach the best
sample are dropped) is refined in mpmath by recursive re-sampling
with 13 points per level, following the best and, when present, a second
distinct local minimum (this finds two minima closer than any fixed step, e.g.
a line grazing the rim), down to a bracket of 1e-7, then golden-section search
to a bracket of 1e-20 rad (1e-22 of the interval for line parameters).  The
squared distance is smooth in theta, so at a quadratic minimum the value error
is ~1e-40*scale^2 in g^2; where the minimum is degenerate ("flat") the abscissa
is ill-conditioned but the value still converges.  At a simple zero of g the
error of g itself is ~1e-20*scale, far below the 1e-12 test tolerance.

Closest points and uniqueness
-----------------------------
Each result carries reference closest points and ``near_optimal_radius(eta)``:
an upper bound on how far ANY pair whose separation is within ``eta`` of the
minimum can be from the reference pair (or inf when the eta-optimal pairs form
several separate groups, i.e. near-ties).  ``unique`` is True when that radius
is tiny for a squared-distance level d^2 + (1e-19*scale)^2, i.e. the minimiser
is a single pair in exact arithmetic on the given floats; ``degenerate`` when
it is an exact tie or a continuum of macroscopic extent.
"""

import functools
import math

import numpy as np
from mpmath import mp, mpf

# the shared 50-digit toolkit: vector operations (on the numbers' own operators, so in this
# module's global context), frames, and the minimiser this module was validated with
from .reference_kit import BRACKET_SAMPLES, bracket_golden, bracketed_min_1d, in_plane_axes
from .reference_store import stored
from .reference_kit import add as _add, cross as _cross, dot as _dot, scale as _mul, sub as _sub  # noqa: F401

DPS = 50
mp.dps = DPS

LINEAR_KINDS = ("point", "line", "ray", "segment")
ROUND_KINDS = ("circle", "disk")

_THETA_TOL = mpf("1e-20")
_T_REL_TOL = mpf("1e-22")
_TINY_REL = mpf("1e-19")  # see RefResult._tiny_radius
_UNIQUE_REL = 1e-8  # minimiser sets narrower than this * scale count as one pair
_DEGENERATE_REL = 1e-3  # minimiser sets wider than this * scale are exact continua/ties


# ----------------------------------------------------------------------------
# small vector helpers on 3-tuples of mpf (mpmath's global context, at DPS digits)
# ----------------------------------------------------------------------------
def _v(xs):
    """Exact conversion of three binary64 numbers to mpf."""
    return tuple(mpf(float(x)) for x in xs)


def _norm(a):
    return mp.sqrt(_dot(a, a))


def to_numpy(a):
    return np.array([float(x) for x in a])


# ----------------------------------------------------------------------------
# shapes
# ----------------------------------------------------------------------------
class Linear:
    """S(t) = B + t*m, t in [lo, hi] (None = unbounded), built from exact floats."""

    def __init__(self, kind, data):
        data = tuple(float(x) for x in data)
        zero = mpf(0)
        if kind == "point":
            self.B, self.m, self.lo, self.hi = _v(data[:3]), (zero, zero, zero), zero, zero
        elif kind == "line":
            self.B, self.m, self.lo, self.hi = _v(data[:3]), _v(data[3:6]), None, None
        elif kind == "ray":
            self.B, self.m, self.lo, self.hi = _v(data[:3]), _v(data[3:6]), zero, None
        elif kind == "segment":
            p0, p1 = _v(data[:3]), _v(data[3:6])
            self.B, self.m, self.lo, self.hi = p0, _sub(p1, p0), zero, mpf(1)
        else:
            raise ValueError(kind)
        self.kind = kind
        self.mm = _dot(self.m, self.m)

    def clamp(self, t):
        if self.lo is not None and t < self.lo:
            return self.lo
        if self.hi is not None and t > self.hi:
            return self.hi
        return t

    def point(self, t):
        return _add(self.B, _mul(t, self.m))

    def closest_param(self, p):
        if self.mm == 0:
            return self.lo if self.lo is not None else mpf(0)
        return self.clamp(_dot(_sub(p, self.B), self.m) / self.mm)

    def distance_to_point(self, p):
        return _norm(_sub(p, self.point(self.closest_param(p))))

    def endpoint_params(self):
        out = []
        if self.lo is not None:
            out.append(self.lo)
        if self.hi is not None and self.hi != self.lo:
            out.append(self.hi)
        return out


class Round:
    """Circle or disk; unit normal and an independent orthonormal frame in mpmath."""

    def __init__(self, kind, data):
        data = tuple(float(x) for x in data)
        if kind not in ROUND_KINDS:
            raise ValueError(kind)
        self.kind = kind
        self.C = _v(data[0:3])
        self.nraw = _v(data[3:6])
        self.R = mpf(data[6])
        self.n = _mul(1 / _norm(self.nraw), self.nraw)
        self.U, self.V = in_plane_axes(self.n, mp)

    def coords(self, p):
        d = _sub(p, self.C)
        return _dot(d, self.U), _dot(d, self.V), _dot(d, self.n)

    def rim(self, theta):
        c, s = mp.cos_sin(theta)
        return _add(self.C, _mul(self.R, _add(_mul(c, self.U), _mul(s, self.V))))


def point_circle_closest(p, rnd):
    """Closed-form nearest circle point (any rim point when p is on the axis)."""
    x, y, z = rnd.coords(p)
    rho = mp.sqrt(x * x + y * y)
    if rho == 0:
        q = _add(rnd.C, _mul(rnd.R, rnd.U))
    else:
        q = _add(rnd.C, _mul(rnd.R / rho, _add(_mul(x, rnd.U), _mul(y, rnd.V))))
    return mp.sqrt((rho - rnd.R) ** 2 + z * z), q


def point_disk_closest(p, rnd):
    """Point-disk closed form of the second note, in the disk frame (x, y, z):
    delta = |z| if x^2 + y^2 <= R^2, else sqrt((rho - R)^2 + z^2) with rho = sqrt(x^2+y^2)
    (identical to x^2+y^2+z^2+R^2-2R*rho, written without cancellation)."""
    x, y, z = rnd.coords(p)
    rho2 = x * x + y * y
    if rho2 <= rnd.R * rnd.R:
        return abs(z), _add(rnd.C, _add(_mul(x, rnd.U), _mul(y, rnd.V)))
    rho = mp.sqrt(rho2)
    q = _add(rnd.C, _mul(rnd.R / rho, _add(_mul(x, rnd.U), _mul(y, rnd.V))))
    return mp.sqrt((rho - rnd.R) ** 2 + z * z), q


def point_round_closest(p, rnd):
    return point_circle_closest(p, rnd) if rnd.kind == "circle" else point_disk_closest(p, rnd)


def point_round_distance(p, rnd):
    return point_round_closest(p, rnd)[0]


# ----------------------------------------------------------------------------
# the rim objective g(theta)^2 = dist(X(theta), S)^2
# ----------------------------------------------------------------------------
class _RimObjective:
    def __init__(self, lin, rnd):
        self.lin, self.rnd = lin, rnd
        b = _sub(lin.B, rnd.C)
        m = lin.m
        if lin.mm > 0:
            tc = -_dot(b, m) / lin.mm
            self.b0 = _add(b, _mul(tc, m))
            self.lo = None if lin.lo is None else lin.lo - tc
            self.hi = None if lin.hi is None else lin.hi - tc
        else:
            tc = mpf(0)
            self.b0 = b
            self.lo = self.hi = mpf(0)
        self.tc = tc
        self.m, self.mm = m, lin.mm
        self.a = _mul(rnd.R, rnd.U)
        self.bv = _mul(rnd.R, rnd.V)
        # binary64 copies (relative to C), only for bracket placement
        self.f_b0, self.f_m = to_numpy(self.b0), to_numpy(m)
        self.f_mm = float(self.mm)
        self.f_a, self.f_bv = to_numpy(self.a), to_numpy(self.bv)
        self.f_lo = -np.inf if self.lo is None else float(self.lo)
        self.f_hi = np.inf if self.hi is None else float(self.hi)

    def _eval(self, theta):
        c, s = mp.cos_sin(theta)
        a, bv, b0, m = self.a, self.bv, self.b0, self.m
        x = (c * a[0] + s * bv[0], c * a[1] + s * bv[1], c * a[2] + s * bv[2])
        w = (x[0] - b0[0], x[1] - b0[1], x[2] - b0[2])
        if self.mm > 0:
            t = (w[0] * m[0] + w[1] * m[1] + w[2] * m[2]) / self.mm
            if self.lo is not None and t < self.lo:
                t = self.lo
            if self.hi is not None and t > self.hi:
                t = self.hi
            r = (w[0] - t * m[0], w[1] - t * m[1], w[2] - t * m[2])
        else:
            t = mpf(0)
            r = w
        return r[0] * r[0] + r[1] * r[1] + r[2] * r[2], x, t

    def g2(self, theta):
        return self._eval(theta)[0]

    def g2_np(self, thetas):
        x = np.cos(thetas)[:, None] * self.f_a + np.sin(thetas)[:, None] * self.f_bv
        w = x - self.f_b0
        if self.f_mm > 0:
            t = np.clip(w @ self.f_m / self.f_mm, self.f_lo, self.f_hi)
            w = w - t[:, None] * self.f_m
        return np.einsum("ij,ij->i", w, w)

    def pair(self, theta):
        """(point on S, point on the circle) for the rim angle theta."""
        _, x, t = self._eval(theta)
        return self.lin.point(t + self.tc), _add(self.rnd.C, x)


def _level_crossing(below, inside, outside, steps):
    """Bisection between an offset `inside` the sub-level set (below(inside) true) and one
    `outside` it: the outer end after `steps` halvings (an upper bound of the crossing)."""
    for _ in range(steps):
        mid = (inside + outside) / 2
        if below(mid):
            inside = mid
        else:
            outside = mid
    return outside


class _RimMin:
    """Global minimum of g over the rim, plus the data needed for sub-level analysis."""

    def __init__(self, lin, rnd):
        self.obj = _RimObjective(lin, rnd)
        self.minima = bracketed_min_1d(
            self.obj.g2, self.obj.g2_np, mpf(0), 2 * mp.pi, True, _THETA_TOL, lipschitz=float(rnd.R)
        )
        self.theta, g2 = self.minima[0]
        self.value = mp.sqrt(g2)
        self.point_lin, self.point_round = self.obj.pair(self.theta)

    def theta_radius(self, level2):
        """Max angular distance from theta* of its connected component of {g^2 <= level2};
        "whole" if the component is the whole rim, "tie" if another part of the sub-level
        set exists (a tie or near-tie with a separate minimiser)."""
        g2, th = self.obj.g2, self.theta
        sides = []
        for sgn in (1, -1):
            delta = mpf("1e-30")
            while delta < mp.pi and g2(th + sgn * delta) <= level2:
                delta *= 8
            if delta >= mp.pi:
                return "whole"
            sides.append(_level_crossing(lambda x: g2(th + sgn * x) <= level2, delta / 8, delta, 24))
        dr, dl = sides

        def in_component(x):
            d = (x - th) % (2 * mp.pi)
            return d <= dr * (1 + mpf("1e-6")) or (2 * mp.pi - d) <= dl * (1 + mpf("1e-6"))

        for x, v in self.minima[1:]:
            if v <= level2 and not in_component(x):
                return "tie"
        # binary64 samples that might lie in another part of the sub-level set
        n = BRACKET_SAMPLES
        xs = 2 * np.pi / n * np.arange(n)
        fv = self.obj.g2_np(xs)
        slack = 1e-15 * float(np.max(fv)) + 1e-300
        suspects = np.flatnonzero(fv <= float(level2) + slack)
        for i in suspects:
            x = mpf(float(xs[i]))
            if not in_component(x) and g2(x) <= level2:
                return "tie"
        return max(dr, dl)


# ----------------------------------------------------------------------------
# results
# ----------------------------------------------------------------------------
class RefResult:
    """Reference answer for (linear shape, round shape).

    distance     mpf, 50 digits
    point_lin    reference closest point on the linear shape (mpf 3-tuple)
    point_round  reference closest point on the circle/disk
    scale        max(distance, R): the scale used for tolerances
    near_optimal_radius(eta) -> (r_lin, r_round) as floats (inf if unbounded)
    unique       the minimising pair is unique (exact arithmetic on the inputs)
    degenerate   the minimising pairs are an exact tie or a macroscopic continuum
    """

    def __init__(self, distance, point_lin, point_round, R, radius_fn, via):
        self.distance = distance
        self.point_lin = point_lin
        self.point_round = point_round
        self.R = R
        self.scale = max(distance, R)
        self._radius_fn = radius_fn
        self.via = via
        self._cache = {}

    @property
    def distance_float(self):
        return float(self.distance)

    def near_optimal_radius(self, eta):
        """Upper bounds (r_lin, r_round): every pair (p on S, q on round shape) with
        |p - q| <= distance + eta satisfies |p - point_lin| <= r_lin and
        |q - point_round| <= r_round, unless a radius is inf (near-ties/continuum)."""
        return self._radius_at_level(self.distance + mpf(eta))[:2]

    def _radius_at_level(self, level):
        if level not in self._cache:
            # a pair (p, q) with |p - q| <= level whose p (or q) is the nearest point to
            # the other one at distance >= d: the partner is within slack of that
            # nearest point (Pythagoras at a nearest point of a convex set)
            slack = mp.sqrt(max(level * level - self.distance**2, mpf(0)))
            res = self._radius_fn(level, slack)
            if isinstance(res, str):
                self._cache[level] = (math.inf, math.inf, res)
            else:
                self._cache[level] = tuple(float(r) for r in res) + (None,)
        return self._cache[level]

    @functools.cached_property
    def _tiny_radius(self):
        # level chosen on the SQUARED distance: d^2 + (1e-19*scale)^2.  The refined minima
        # are accurate to ~1e-40*scale^2 in g^2 (golden bracket 1e-20 rad), so exact ties
        # are recognised even between simple zeros of g, where g itself is only good to
        # ~1e-20*scale.
        level = mp.sqrt(self.distance**2 + (_TINY_REL * self._eff_scale) ** 2)
        ra, rb, reason = self._radius_at_level(level)
        return max(ra, rb), reason

    @property
    def _eff_scale(self):
        # scale = 0 means d = R = 0: S passes through the single point C, and any positive
        # length serves to tell an isolated pair from a continuum
        return self.scale if self.scale > 0 else mpf(1)

    @property
    def unique(self):
        """The minimising pair is a single pair: the pairs whose squared separation is
        within (1e-19*scale)^2 of the minimum all lie within 1e-8*scale of the reference
        pair."""
        return self._tiny_radius[0] <= _UNIQUE_REL * float(self._eff_scale)

    @property
    def degenerate(self):
        """Exactly (not just numerically) non-unique: a continuum of minimisers of
        macroscopic extent (> 1e-3*scale, or the whole rim), or a tie between separate
        minimisers when d >= 1e-6*scale (for smaller d a "tie" within the reference's
        resolution, ~1e-38*scale^2/d, can be a rounding-level near-tie, e.g. a tangent
        line made to cross the circle by 1e-17 by rounding).  Cases that are neither
        unique nor degenerate are ill-conditioned; the tests make no claim about the
        library's `unique` flag for them."""
        radius, reason = self._tiny_radius
        eff = self._eff_scale
        if reason == "tie":
            return self.distance >= mpf("1e-6") * eff
        return reason == "whole" or radius > _DEGENERATE_REL * float(eff)


def _t_radius(lin, rnd, t_star, level):
    """Half-width (in |m|*t units) of the sub-level interval {t : dist(S(t), disk) <= level}
    around t_star.  dist(S(t), disk) is convex in t (distance to a convex set along a line),
    so this interval is connected and the outward search below is exact."""
    if lin.mm == 0:
        return mpf(0)
    f = lambda t: point_disk_closest(lin.point(t), rnd)[0]
    norm_m = mp.sqrt(lin.mm)
    scale = max(level, rnd.R, mpf("1e-300"))
    level = max(level, f(t_star))
    out = []
    for sgn, bound in ((1, lin.hi), (-1, lin.lo)):
        room = None if bound is None else abs(bound - t_star)
        delta = mpf("1e-30") * scale / norm_m
        hit_end = False
        for _ in range(400):
            if room is not None and delta >= room:
                delta, hit_end = room, True
                break
            if f(t_star + sgn * delta) > level:
                break
            delta *= 8
        if hit_end and f(t_star + sgn * delta) <= level:
            out.append(delta)
            continue
        inside = delta / 8 if not hit_end else mpf(0)
        out.append(_level_crossing(lambda x: f(t_star + sgn * x) <= level, inside, delta, 30))
    return max(out) * norm_m


# ----------------------------------------------------------------------------
# references
# ----------------------------------------------------------------------------
def _ref_circle(lin, rnd):
    """dist(S, circle) = min_theta dist(X(theta), S): an identity, see module docstring."""
    rm = _RimMin(lin, rnd)
    d = rm.value

    def radius(level, slack):
        th = rm.theta_radius(level**2)
        if isinstance(th, str):
            return th
        r_round = rnd.R * th  # chord <= R * angle
        # the nearest point of the convex S to a rim point is 1-Lipschitz in that point;
        # a near-optimal partner may further be off that nearest point by <= slack
        return r_round + slack, r_round

    return RefResult(d, rm.point_lin, rm.point_round, rnd.R, radius, "rim")


def _ref_disk(lin, rnd):
    """Distance from S (point/line/ray/segment) to the closed disk D.

    Candidates (each is the separation of an actual pair (p in S, q in D), so each is
    >= the true distance d):
      (I) 0, if S meets D: S crosses the plane at a parameter in T at a point with
          in-plane radius <= R, or S lies in the plane and its nearest point to C is
          within R of C;
      (R) min over theta of dist(X(theta), S)  (rim points);
      (E) for each finite end point E of S (ray origin, segment ends, the point
          itself) whose projection onto the plane lies in the closed disk: |height(E)|.
    Completeness (one candidate equals d).  Let (p*, q*) be a closest pair, p* = S(t*).
    If d = 0, S meets D and (I) gives 0.  Let d > 0.  If q* is on the rim, (R) <= d.
    Otherwise q* is in the open disk, so q* is the orthogonal projection of p* and
    d = |h(p*)| (h = signed height).  Let I = {t in T : projection of S(t) in the closed
    disk} (a closed interval: preimage of a convex set under an affine map).  On I,
    dist(S(t), D) = |h(S(t))|, and h(S(t)) is affine in t and never 0 on I (d > 0), so
    by continuity it has a constant sign and |h| is affine on I.  Hence its minimum d on I
    is attained at an end point of I (if |h| were constant and I unbounded, m would be
    parallel to the plane with a bounded projection, i.e. m = 0, a point: then I = T = {0}).
    An end point of I is either an end point of T -> candidate (E), or a parameter where
    the projection of S(t) is on the rim -> then the distance of S(t) to the rim point
    below it equals |h|, so (R) <= d.  In every case min(candidates) = d.
    """
    cands = []
    # (I) intersection
    if lin.mm > 0:
        b = _sub(lin.B, rnd.C)
        hb = _dot(b, rnd.nraw)  # exact-ish: products of binary64 numbers, 166-bit sums
        mn = _dot(lin.m, rnd.nraw)
        if mn != 0:
            t0 = -hb / mn
            if lin.clamp(t0) == t0:
                p = lin.point(t0)
                x, y, _ = rnd.coords(p)
                if x * x + y * y <= rnd.R * rnd.R:
                    cands.append((mpf(0), p, p, "cross"))
        elif hb == 0:
            t = lin.closest_param(rnd.C)
            q = lin.point(t)
            if _dot(_sub(q, rnd.C), _sub(q, rnd.C)) <= rnd.R * rnd.R:
                cands.append((mpf(0), q, q, "in-plane"))
    # (R) rim
    if rnd.R == 0:
        # the rim is the single point C: g(theta) is constant, no search needed
        q = lin.point(lin.closest_param(rnd.C))
        cands.append((_norm(_sub(q, rnd.C)), q, rnd.C, "rim"))
    else:
        rm = _RimMin(lin, rnd)
        cands.append((rm.value, rm.point_lin, rm.point_round, "rim"))
    # (E) end points
    for t in lin.endpoint_params():
        e = lin.point(t)
        x, y, z = rnd.coords(e)
        if x * x + y * y <= rnd.R * rnd.R:
            cands.append((abs(z), e, _add(rnd.C, _add(_mul(x, rnd.U), _mul(y, rnd.V))), "end"))
    d, pa, pb, via = min(cands, key=lambda c: c[0])
    t_star = lin.closest_param(pa)

    def radius(level, slack):
        ra = _t_radius(lin, rnd, t_star, level)
        # nearest-point map onto the convex disk is 1-Lipschitz; partner off by <= slack
        return ra, ra + slack

    return RefResult(d, pa, pb, rnd.R, radius, via)


def _ref_point_disk(lin, rnd):
    """Point-disk: the closed form (second note).  Validated against the rim/end-point
    route and brute force in test_reference_validation."""
    d, q = point_disk_closest(lin.B, rnd)

    def radius(level, slack):
        # disk convex: |q' - q|^2 <= |p - q'|^2 - d^2 <= level^2 - d^2
        return mpf(0), slack

    return RefResult(d, lin.B, q, rnd.R, radius, "closed-form")


@functools.lru_cache(maxsize=None)
def reference(lin_kind, lin_data, round_kind, round_data):
    """Reference for the pair (linear shape, round shape); inputs are tuples of floats:
    point (x,y,z); line/ray (ox,oy,oz,dx,dy,dz); segment (p0..., p1...);
    round (cx,cy,cz,nx,ny,nz,R). Its numbers and its near-optimal radii are recorded
    (reference_store): the search runs only for what is not."""
    case = (lin_kind, lin_data, round_kind, round_data)
    distance, point_lin, point_round, radius, via = _reference_values(*case)
    return RefResult(distance, point_lin, point_round, radius, functools.partial(_radius_at, *case), via)


@stored
def _reference_values(lin_kind, lin_data, round_kind, round_data):
    r = _computed(lin_kind, lin_data, round_kind, round_data)
    return r.distance, r.point_lin, r.point_round, r.R, r.via


@stored
def _radius_at(lin_kind, lin_data, round_kind, round_data, level, slack):
    """RefResult's radius function at (level, slack), of the search's own result."""
    return _computed(lin_kind, lin_data, round_kind, round_data)._radius_fn(level, slack)


@functools.lru_cache(maxsize=None)
def _computed(lin_kind, lin_data, round_kind, round_data):
    """The search itself (reference's RefResult, with its radius function)."""
    lin = Linear(lin_kind, lin_data)
    rnd = Round(round_kind, round_data)
    if rnd.R == 0 or round_kind == "disk":
        # R == 0: circle and disk are both the single point C, the disk code is exact
        if lin.mm == 0:
            return _ref_point_disk(lin, rnd)
        return _ref_disk(lin, rnd)
    return _ref_circle(lin, rnd)


@functools.lru_cache(maxsize=None)
def reference_disk_by_candidates(lin_kind, lin_data, round_data):
    """The candidate route of _ref_disk even for points (cross-check of the closed form)."""
    return _ref_disk(Linear(lin_kind, lin_data), Round("disk", round_data))


# ----------------------------------------------------------------------------
# an unrelated second formulation, used only to validate the references
# ----------------------------------------------------------------------------
def _line_window(lin, rnd):
    """Parameter interval (within T) that contains every minimiser of t -> dist(S(t), shape).

    With t_r the clamped projection of C, any minimiser satisfies
    |S(t) - C| - R <= dist <= |S(t_r) - C| + R, so |S(t) - C| <= |S(t_r) - C| + 2R."""
    b = _sub(lin.B, rnd.C)
    tc = -_dot(b, lin.m) / lin.mm
    dc2 = _dot(_add(b, _mul(tc, lin.m)), _add(b, _mul(tc, lin.m)))
    dref = _norm(_sub(lin.point(lin.clamp(tc)), rnd.C))
    half = mp.sqrt(max((dref + 2 * rnd.R) ** 2 - dc2, mpf(0)) / lin.mm) * mpf("1.001") + mpf("1e-30") * (1 + abs(tc))
    lo, hi = tc - half, tc + half
    if lin.lo is not None:
        lo = max(lo, lin.lo)
    if lin.hi is not None:
        hi = min(hi, lin.hi)
    return lo, max(lo, hi)


@functools.lru_cache(maxsize=None)
def reference_by_line_parameter(lin_kind, lin_data, round_kind, round_data):
    """dist(S, shape) = min over t in T of dist(S(t), shape) with the closed-form
    point-circle / point-disk distance.  For the disk the objective is convex in t
    (distance to a convex set restricted to a line), so plain golden-section on the
    whole window is a complete global method; for the circle the generic sampler is used
    (R = 0: the circle is a point, convex again).
    Shares no step with the rim (theta) formulation."""
    lin = Linear(lin_kind, lin_data)
    rnd = Round(round_kind, round_data)
    if lin.mm == 0:
        return point_round_distance(lin.B, rnd)
    lo, hi = _line_window(lin, rnd)
    f2 = lambda t: point_round_distance(lin.point(t), rnd) ** 2
    if hi <= lo:
        return mp.sqrt(f2(lo))
    tol = (hi - lo) * _T_REL_TOL
    if round_kind == "disk" or rnd.R == 0:
        _, v = bracket_golden(f2, lo, hi, tol)
        return mp.sqrt(min(v, f2(lo), f2(hi)))
    # binary64 version for bracket placement, relative to C
    B = to_numpy(_sub(lin.B, rnd.C))
    m = to_numpy(lin.m)
    U, V, n = to_numpy(rnd.U), to_numpy(rnd.V), to_numpy(rnd.n)
    R = float(rnd.R)

    def f2_np(ts):
        p = B + ts[:, None] * m
        x, y, z = p @ U, p @ V, p @ n
        return (np.hypot(x, y) - R) ** 2 + z * z

    res = bracketed_min_1d(f2, f2_np, lo, hi, False, tol, lipschitz=float(mp.sqrt(lin.mm)))
    return mp.sqrt(res[0][1])


def brute_force(lin_kind, lin_data, round_kind, round_data, n_lin=500, n_theta=720, n_rad=16):
    """Plain binary64 sampling of both shapes (no projections at all).

    Returns (smallest sampled pair distance, bound) where bound is an upper bound on
    how much the sampled minimum can exceed the true one (half the sampling gaps).
    Meant for untranslated scenes only (coordinates relative to C in binary64)."""
    lin = Linear(lin_kind, lin_data)
    rnd = Round(round_kind, round_data)
    C = to_numpy(rnd.C)
    U, V = to_numpy(rnd.U), to_numpy(rnd.V)
    R = float(rnd.R)
    B, m = to_numpy(lin.B) - C, to_numpy(lin.m)
    if lin.mm > 0:
        lo, hi = (float(x) for x in _line_window(lin, rnd))
        ts = np.linspace(lo, hi, n_lin)
        gap_lin = (hi - lo) / (n_lin - 1) / 2 * float(mp.sqrt(lin.mm))
    else:
        ts = np.zeros(1)
        gap_lin = 0.0
    P = B + ts[:, None] * m
    th = 2 * np.pi * np.arange(n_theta) / n_theta
    ring = np.cos(th)[:, None] * U + np.sin(th)[:, None] * V
    if round_kind == "circle":
        Q = R * ring
        gap_round = R * np.pi / n_theta
    else:
        th = th[::2]
        ring = ring[::2]
        radii = R * np.arange(n_rad + 1) / n_rad
        Q = (radii[:, None, None] * ring[None, :, :]).reshape(-1, 3)
        gap_round = math.hypot(2 * R * np.pi / n_theta, R / n_rad / 2)
    best = np.inf
    for k in range(0, len(Q), 512):
        diff = P[:, None, :] - Q[None, k : k + 512, :]
        best = min(best, float(np.sqrt(np.min(np.einsum("ijk,ijk->ij", diff, diff)))))
    return best, gap_lin + gap_round


# ----------------------------------------------------------------------------
# residual helpers for the tests (exact on the float inputs)
# ----------------------------------------------------------------------------
def distance_to_shape(point, kind, data):
    """mpf distance from a point (binary64 array-like or mpf 3-tuple) to the shape."""
    p = point if isinstance(point, tuple) and isinstance(point[0], type(mpf(0))) else _v(point)
    if kind in LINEAR_KINDS:
        return Linear(kind, data).distance_to_point(p)
    return point_round_distance(p, Round(kind, data))


def mp_distance(p, q):
    return _norm(_sub(_v(p), _v(q)))


def mp_vec_distance(p, q_mp):
    """Distance between a binary64 3-vector and an mpf 3-tuple."""
    return _norm(_sub(_v(p), q_mp))
