"""The rule that decides closest_points().unique where exact symmetry or a closed form does
(``expected_unique``).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from .base import LINEAR, _key


# ---- closest_points().unique ------------------------------------------------------------------
# The rule (independent of the library; exact rational tests on the inputs as given, or closed
# forms in float64 with a margin far above their rounding):
#   unique must be False where the inputs are EXACTLY (in rationals) a configuration with a
#   continuum of closest pairs, by symmetry:
#     - a point, line, ray, segment or Bezier curve (every control point: the curve lies in their
#       hull), or a round of radius 0 (the point at its centre), lying on the axis of a circle or
#       an arc (angle >= 1e-3) of radius > 0 or an annulus with a hole (inner > 0): every rim
#       (inner rim) point is as far from each point of the axis, so the closest pairs of any
#       closest axis point form a circle (an arc);
#     - two coaxial shapes of radius > 0 among circle, disk, annulus and arc (not two arcs; an
#       arc's angle >= 1e-3): common axis (normals parallel, the centres' offset along it).  The set of closest
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
#   point had no margin: docs/reports/differential.md).  Not
#   checked: two regions (disk-disk, disk-annulus, annulus-annulus beyond the coaxial cases),
#   a point against an arc or annulus where the closed form is too close to call, a Bezier curve
#   against a Bezier curve (no kind pair of the cases), a linear pair within 1e-3 rad of
#   parallel; never False from sampling.
UNIQUE_MARGIN = 1e-6
UNIQUE_MIN_ARC = 1e-3


def _fr(v):
    return [Fraction(float(x)) for x in v]


def _fcross_zero(a, b):
    return a[1] * b[2] - a[2] * b[1] == 0 and a[2] * b[0] - a[0] * b[2] == 0 and a[0] * b[1] - a[1] * b[0] == 0


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
    a circle or an arc (of angle >= UNIQUE_MIN_ARC) of radius > 0, an annulus with a hole. A
    round of radius 0 is a single point: its axis carries no continuum."""
    if kind == "circle":
        return data[6] > 0
    if kind == "arc":
        return data[6] > 0 and data[10] >= UNIQUE_MIN_ARC
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
            return None  # the point's angle at an end: the in-span point is the end
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
        # a round of radius 0 is the point at its centre
        k1, d1 = ("point", d1[:3]) if k1 in _SYM and d1[6] == 0 else (k1, d1)
        if (k1 in LINEAR or k1 == "bezier") and k2 in _SYM and _continuum_round(k2, d2):
            if _on_axis(k1, d1, _fr(d2[:3]), _fr(d2[3:6])):
                return False, f"the {k1} lies on the {k2}'s axis"
    # coaxial rounds of radius > 0 (a round of radius 0 is a point: the rule above)
    if ka in _SYM and kb in _SYM and not (ka == "arc" and kb == "arc") and a[6] > 0 and b[6] > 0:
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
