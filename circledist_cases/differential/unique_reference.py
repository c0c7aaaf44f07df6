"""closest_points().unique against the 50-digit references' own local minima
(``reference_unique``) where expected_unique's rule leaves it open.
"""

from __future__ import annotations

import collections

import numpy as np

from .base import _key, _load, combos
from .families import bar_scale
from .unique import expected_unique
from .check import _call, _finding, make_shape
from .confirm import _CURVE_MINIMA, _REF_CACHE, ann_shape, mp_reference
from ..reference_store import stored


REF_UNIQUE_REL = "1e-6"  # the second-best distinct local minimum must be worse by this x max(d, scale)
REF_UNIQUE_RISE = "1e-12"  # and the minimum not flat: d(x* +- 1e-4) - d > this x max(d, scale)
REF_UNIQUE_STEP = "1e-4"  # that step: in radians of a rim, in t of a Bezier curve
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
    """The rule of _reference_unique (below) for the case's shapes."""
    ka, a, kb, b = _key(case)
    return _reference_unique(ka, a, kb, b)


@stored(also=("differential/base.py", "differential/confirm.py", "differential/families.py"))
def _reference_unique(ka, a, kb, b):
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

    def data(d):
        return [list(p) for p in d] if d and isinstance(d[0], tuple) else list(d)

    case = {"a": ka, "a_data": data(a), "b": kb, "b_data": data(b)}
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
        minima = R.minimize_1d(
            f,
            R.mpf(0),
            hi,
            intervals,
            periodic=periodic,
            lipschitz=lipschitz,
            resolution=resolution,
            max_samples=A.ZOOM_SAMPLES,
        )
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
        sides = [
            min(best.x + delta, hi) if best.x < hi else None,
            max(best.x - delta, R.mpf(0)) if best.x > 0 else None,
        ]
        sides = [x for x in sides if x is not None]
    if not sides or any(f(x) - best.value <= R.mpf(REF_UNIQUE_RISE) * scale for x in sides):
        return None, ""
    if not _target_point_unique(at(best.x), tk, td, R.mpf(REF_UNIQUE_REL) * scale):
        return None, ""
    name = {
        "circle": "the circle's angle",
        "arc": "the arc's angle",
        "bezier": "the curve's t",
        "line": "the line",
        "ray": "the ray",
        "segment": "the segment",
    }[mk]
    return True, (
        f"the 50-digit minimum over {name} of the distance to the {tk} is single and strict, "
        f"and the {tk}'s nearest point to it unique"
    )


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
                    f = _finding(
                        "unique",
                        c,
                        solver,
                        precision,
                        order,
                        "closest_points",
                        library=bool(v.unique),
                        expected=uexp[0],
                        why=uexp[1] + " (direct)",
                        distance=v.distance,
                    )
                    f["confirmed"] = True
                    findings.append(f)
    return findings
