"""The 50-digit toolkit the reference modules share: exact conversions, 3-vectors, frames, and
global minimisation over one parameter.

Nothing here uses circledist.  Arithmetic is mpmath at 50 significant digits: ``ctx`` is a
private context (the global mpmath context is not touched); float inputs are converted exactly
(an IEEE double is a dyadic rational), so a reference describes exactly the float64 scene given
to the library.  The vector operations are written on the numbers' own operators, so they work
on the numbers of any mpmath context; ``norm``, ``normalize``, ``dist`` and ``frame`` compute in
``ctx``, and ``in_plane_axes`` in the context it is given.

Frames are built here, independently of the library: the in-plane unit vector U is the
Gram-Schmidt projection of the coordinate axis least aligned with N, and V = N x U.

Two minimisers, each the one its references were validated with:

* ``minimize_1d`` samples f in mpmath on a uniform grid (optionally zoomed where a Lipschitz
  bound says two minima could share a step) and refines every sampled local minimum by golden
  section to a bracket of PARAM_TOL (reference_round, reference_arc, reference_annulus,
  reference_bezier).
* ``bracketed_min_1d`` samples a binary64 version of f only to place brackets, then refines each
  in mpmath's global context by branching re-sampling and golden section (reference: a linear
  piece against a circle or disk).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, List, Optional, Sequence, Tuple

import numpy as np
from mpmath import mp
from mpmath.ctx_mp import MPContext

from .golden import golden_section

DPS = 50
ctx = MPContext()
ctx.dps = DPS
mpf = ctx.mpf

Vec = Tuple[object, object, object]


# ----------------------------------------------------------------------------------------------
# small vector helpers on tuples of mpf
# ----------------------------------------------------------------------------------------------
def to_mp(x) -> object:
    """Exact conversion of a float / int / numpy scalar; strings are parsed at 50 digits."""
    if isinstance(x, ctx.mpf):
        return x
    if isinstance(x, str):
        return mpf(x)
    if isinstance(x, int):
        return mpf(x)
    if hasattr(x, "as_integer_ratio") and math.isfinite(x):  # floats, NumPy's long double too: exactly
        p, q = x.as_integer_ratio()
        return mpf(p) / q
    return mpf(float(x))


def vec(x: Sequence) -> Vec:
    v = tuple(to_mp(c) for c in x)
    if len(v) != 3:
        raise ValueError("expected a 3-vector")
    return v


def add(a: Vec, b: Vec) -> Vec:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(s, a: Vec) -> Vec:
    return (s * a[0], s * a[1], s * a[2])


def dot(a: Vec, b: Vec):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a: Vec, b: Vec) -> Vec:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a: Vec):
    return ctx.sqrt(dot(a, a))


def normalize(a: Vec) -> Vec:
    n = norm(a)
    if n == 0:
        raise ValueError("zero vector")
    return scale(1 / n, a)


def dist(a: Vec, b: Vec):
    return norm(sub(a, b))


def in_plane_axes(n: Vec, context=ctx) -> Tuple[Vec, Vec]:
    """(U, V) completing the unit normal n to a right-handed orthonormal frame (U, V, n), in the
    given mpmath context: U is the unit projection of the coordinate axis least aligned with n
    onto the plane normal to n, V = n x U."""
    k = min(range(3), key=lambda i: (abs(n[i]), i))
    e = tuple(context.mpf(1) if i == k else context.mpf(0) for i in range(3))
    u = sub(e, scale(dot(e, n), n))
    u = scale(1 / context.sqrt(dot(u, u)), u)
    return u, cross(n, u)


def frame(normal: Sequence) -> Tuple[Vec, Vec, Vec]:
    """Right-handed orthonormal (U, V, N) with N = normal/|normal| (own construction)."""
    n = normalize(vec(normal))
    u, v = in_plane_axes(n)
    return u, v, n


# ----------------------------------------------------------------------------------------------
# minimize_1d: dense sampling in mpmath + golden section on every sampled local minimum
# ----------------------------------------------------------------------------------------------
PARAM_TOL = mpf("1e-40")  # golden-section bracket width at which refinement stops
TIE_TOL = mpf("1e-40")  # sampled values this close (relative) count as tied (see minimize_1d)
MAX_REFINED = 64  # safety cap on refinements per minimisation (never reached in the tests)
ZOOM_FRACTION = 8  # zoom: re-sample until one step moves the point by at most target radius / this
ZOOM_SPLIT = 8  # zoom: pieces an interval is cut into per pass
MAX_ZOOM_SAMPLES = 40000  # zoom: safety cap on added samples per minimisation (see minimize_1d)
_INVPHI = (ctx.sqrt(5) - 1) / 2


@dataclass
class LocalMin:
    value: object  # refined distance
    x: object  # parameter (angle or t)
    rise: object  # how much the sampled neighbours exceed the sampled minimum (flatness)


def _sample_grid(lo, hi, intervals: int, periodic: bool):
    """The sample abscissae of minimize_1d (shared so that cached values match exactly)."""
    lo, hi = to_mp(lo), to_mp(hi)
    h = (hi - lo) / intervals
    n = intervals if periodic else intervals + 1
    xs = [lo + i * h for i in range(n)]
    if not periodic:
        xs[-1] = hi
    return xs, h


def _lipschitz_zoom(
    f: Callable, pts: list, lipschitz: Callable, resolution: Callable, best, max_samples=MAX_ZOOM_SAMPLES
):
    """Re-sample, ZOOM_SPLIT pieces at a time, every interval between neighbouring samples that
    could hold a value below the best sample and on which one step can still move the point by
    more than resolution(a, b, L (b - a)).  f is L-Lipschitz on [a, b] (L = lipschitz(a, b)), so
    nothing on [a, b] lies below (f(a) + f(b))/2 - L (b - a)/2: intervals above the best sample
    are dropped.  pts: sorted [x, f(x)] lists, extended in place.  The intervals are taken
    lowest bound first, so a zoom stopped by MAX_ZOOM_SAMPLES has spent them where the minimum is."""
    added = 0
    while added < max_samples:
        todo = []
        for i, ((a, fa), (b, fb)) in enumerate(zip(pts, pts[1:])):
            lh = lipschitz(a, b) * (b - a)
            if (fa + fb - lh) / 2 <= best and lh > resolution(a, b, lh):
                todo.append(((fa + fb - lh) / 2, i))
        if not todo:
            break
        todo.sort(key=lambda x: x[0])
        new = {}
        for _, i in todo[: (max_samples - added) // (ZOOM_SPLIT - 1)]:
            (a, _fa), (b, _fb) = pts[i], pts[i + 1]
            step = (b - a) / ZOOM_SPLIT
            new[i] = [[a + j * step, None] for j in range(1, ZOOM_SPLIT)]
            for q in new[i]:
                q[1] = f(q[0])
                best = min(best, q[1])
            added += ZOOM_SPLIT - 1
        if not new:
            break
        out = []
        for i, q in enumerate(pts):
            out.append(q)
            out += new.get(i, [])
        pts[:] = out
    return pts


def minimize_1d(
    f: Callable,
    lo,
    hi,
    intervals: int,
    periodic: bool,
    lipschitz: Optional[Callable] = None,
    resolution=None,
    max_samples=MAX_ZOOM_SAMPLES,
) -> List[LocalMin]:
    """All refined local minima of f on [lo, hi] (periodic: [lo, hi) wraps), lowest first.

    lipschitz(a, b) (optional): a bound on |f'| over [a, b]; with resolution(a, b, step) (the
    length, in space, to which the target's features around [a, b] must be resolved) the uniform
    scan is zoomed (_lipschitz_zoom) until every interval that could hold a value below the best sample is
    sampled at steps moving the point by at most that much.  Why: a uniform scan of
    a shape far larger than the other one (a curve 2e4 long passing a ring of radius 0.8, a huge
    circle passing a small disk) has steps much longer than the other shape, so two local minima
    a fraction of its size apart fall between the same two samples, and golden section then finds
    only one of them, possibly the higher (5.9e-13 higher for the far curve of
    tests/accuracy/test_regressions.py::test_far_curve_near_tied_minima).  After the zoom each of them is
    a sampled local minimum of its own, and every one is refined."""
    xs, h = _sample_grid(lo, hi, intervals, periodic)
    fs = [f(x) for x in xs]
    if lipschitz is not None and resolution is not None:
        pts = [[x, v] for x, v in zip(xs, fs)]
        if periodic:  # the interval that wraps round, closed by the first sample one period on
            x_end = to_mp(hi) + (xs[0] - to_mp(lo))
            pts.append([x_end, f(x_end)])
        _lipschitz_zoom(f, pts, lipschitz, resolution, min(fs), max_samples)
        if periodic:
            pts.pop()
        xs, fs = [p[0] for p in pts], [p[1] for p in pts]
    n = len(xs)
    period = to_mp(hi) - to_mp(lo)
    cand = []
    for i in range(n):
        nb = []
        if periodic:
            nb = [fs[(i - 1) % n], fs[(i + 1) % n]]
        else:
            if i > 0:
                nb.append(fs[i - 1])
            if i < n - 1:
                nb.append(fs[i + 1])
        if all(fs[i] <= v for v in nb):
            cand.append((fs[i], i, min(nb) - fs[i]))
    cand.sort(key=lambda c: c[0])
    # Every sampled local minimum is refined, except exact ties: on a continuum of closest points
    # (concentric circles, a circle inside a disk's plane, ...) hundreds of samples tie to ~1e-50;
    # two of each tied value are refined (enough to see that the closest pair is not unique).
    tie = TIE_TOL * max(mpf(1), max(abs(v) for v in fs))
    chosen = []
    for c in cand:
        if sum(1 for v in chosen if abs(v[0] - c[0]) <= tie) < 2:
            chosen.append(c)
    out = []
    zoomed = n != len(_sample_grid(lo, hi, intervals, periodic)[0])
    for fi, i, rise in chosen[:MAX_REFINED]:
        if periodic and not zoomed:
            a, b = xs[i] - h, xs[i] + h
        elif periodic:
            # the neighbouring samples, across the wrap
            a = xs[i - 1] - (period if i == 0 else 0)
            b = xs[(i + 1) % n] + (period if i == n - 1 else 0)
        else:
            a = xs[i - 1] if i > 0 else xs[i]
            b = xs[i + 1] if i < n - 1 else xs[i]
        x, v = golden_section(f, a, b, _INVPHI, PARAM_TOL)
        if fi <= v:  # the sample itself (e.g. an end point) may be the best point seen
            v, x = fi, xs[i]
        out.append(LocalMin(v, x, rise))
    out.sort(key=lambda m: m.value)
    return out


# ----------------------------------------------------------------------------------------------


# ----------------------------------------------------------------------------------------------
# bracketed_min_1d: binary64 samples place brackets, mpmath (global context) refines them
# ----------------------------------------------------------------------------------------------
BRACKET_SAMPLES = 2048  # binary64 samples of the whole interval
BRANCH_SPLIT = 12  # pieces per level of the branching re-sampling
MAX_BRACKETS = 8  # sampled runs refined, lowest first
with mp.workdps(DPS):
    _INVPHI_GLOBAL = (mp.sqrt(5) - 1) / 2


def bracket_golden(f, a, b, tol):
    """Golden-section search for a minimum of f on [a, b] (mpmath), at most 400 steps."""
    return golden_section(f, a, b, _INVPHI_GLOBAL, tol, steps=400)


def _runs(mask, periodic):
    """Maximal runs of consecutive True indices as (first, last) (cyclic if periodic)."""
    n = len(mask)
    if mask.all():
        return [(0, n - 1)]
    idx = np.flatnonzero(mask)
    if len(idx) == 0:
        return []
    runs = []
    start = prev = idx[0]
    for i in idx[1:]:
        if i == prev + 1:
            prev = i
            continue
        runs.append((start, prev))
        start = prev = i
    runs.append((start, prev))
    if periodic and len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == n - 1:
        first = runs.pop(0)
        last = runs.pop()
        runs.append((last[0], first[1] + n))
    return runs


def _branching_zoom(f, xl, xr, tol, min_width, lipschitz):
    """Recursive re-sampling of [xl, xr] (mpmath): every level samples the bracket at
    BRANCH_SPLIT + 1 points and descends into the best sampled local minimum and, if there is
    one that could still be lower (Lipschitz bound on sqrt(f)), a second distinct local
    minimum, shrinking the bracket BRANCH_SPLIT/2-fold per level; brackets narrower than
    min_width are finished by golden-section search.  The branching is what finds two
    minima closer than any fixed sampling step (a line grazing the rim gives two minima
    ~1e-5 rad apart).  At most 24 brackets are opened: only flat functions (all samples
    equal) get there, and for them the sampled values are already the minimum."""
    stack = [(xl, xr)]
    leaves = []
    opened = 0
    while stack:
        a, b = stack.pop()
        if b - a <= min_width:
            leaves.append(bracket_golden(f, a, b, tol))
            continue
        if opened >= 24:
            continue
        opened += 1
        sx = [a + (b - a) * k / BRANCH_SPLIT for k in range(BRANCH_SPLIT + 1)]
        sv = [f(x) for x in sx]
        loc = []
        for k in range(BRANCH_SPLIT + 1):
            left = sv[k - 1] if k > 0 else None
            right = sv[k + 1] if k < BRANCH_SPLIT else None
            if (left is None or sv[k] <= left) and (right is None or sv[k] <= right):
                loc.append((sv[k], k))
        loc.sort()
        chosen = loc[:1]
        reach = lipschitz * (b - a) / BRANCH_SPLIT if lipschitz is not None else None
        for v, k in loc[1:]:
            if abs(k - chosen[0][1]) < 2:
                continue
            if reach is None or mp.sqrt(v) - reach <= mp.sqrt(chosen[0][0]):
                chosen.append((v, k))
                break
        for v, k in chosen:
            leaves.append((sx[k], v))
            stack.append((sx[max(k - 1, 0)], sx[min(k + 1, BRANCH_SPLIT)]))
    return leaves


def bracketed_min_1d(f_mp, f_np, a, b, periodic, tol, lipschitz=None):
    """All refined local minima of f on [a, b] (periodic: [a, b) with f(a) = f(b)).

    f_np is a binary64 version of f used only to place brackets; every value
    returned comes from f_mp.  Returns a list of (x, f(x)) sorted by value.
    """
    n = BRACKET_SAMPLES
    af, bf = float(a), float(b)
    h = (bf - af) / (n if periodic else n - 1)
    xs = af + h * np.arange(n)
    v = f_np(xs)
    finite = v[np.isfinite(v)]
    noise = 1e-13 * (float(np.max(np.abs(finite))) if finite.size else 1.0) + 1e-300
    if periodic:
        prev, nxt = np.roll(v, 1), np.roll(v, -1)
    else:
        prev = np.concatenate(([np.inf], v[:-1]))
        nxt = np.concatenate((v[1:], [np.inf]))
    cand = (v <= prev + noise) & (v <= nxt + noise)
    runs = _runs(cand, periodic)
    scored = []
    for first, last in runs:
        ids = np.arange(first, last + 1) % n
        scored.append((float(np.min(v[ids])), first, last))
    scored.sort()
    if lipschitz is not None and scored:
        # g = sqrt(f) is `lipschitz`-Lipschitz: a bracket (samples within h of every
        # point of it) whose best sample exceeds the best sample overall by more than
        # lipschitz*h cannot contain the global minimum nor a tie with it.
        best = math.sqrt(max(scored[0][0], 0.0))
        scored = [r for r in scored if math.sqrt(max(r[0], 0.0)) - 1.01 * lipschitz * h <= best]
    results = []

    def xpos(i):
        if not periodic:
            if i <= 0:
                return a
            if i >= n - 1:
                return b
        return mp.mpf(af) + mp.mpf(h) * i

    min_width = mp.mpf("1e-7") * (b - a) / (2 * mp.pi if periodic else 1)
    for _, first, last in scored[:MAX_BRACKETS]:
        if periodic and last - first + 1 >= n:
            xl, xr = mp.mpf(a), mp.mpf(a) + 2 * mp.pi
        else:
            xl, xr = xpos(first - 1), xpos(last + 1)
        if xr <= xl:
            results.append((xl, f_mp(xl)))
            continue
        results.extend(_branching_zoom(f_mp, xl, xr, tol, min_width, lipschitz))
    if not periodic:
        results.append((a, f_mp(a)))
        results.append((b, f_mp(b)))
    results.sort(key=lambda r: r[1])
    return results


# ----------------------------------------------------------------------------
# the rim objective g(theta)^2 = dist(X(theta), S)^2
