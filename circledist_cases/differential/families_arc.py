"""Case families of the arcs: the circle families applied to arcs, and the arcs' own."""

from __future__ import annotations

import math

import numpy as np

from .base import ARC_PAIRS, FAMILIES, RIMS, ROUND, _plain
from .closed_forms import _diff_ld, _lin_dist, _round_dist
from .screen import _anchor
from .frames import EZ, _Frame, _in_plane, _logu, _perp, _radius, _rot, _tiny, _unit
from .families_round import _fam_far_translated
from .families_linear import EX


# ---- arcs: the circle families applied to arcs -----------------------------------------------
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
    return 2 * math.pi  # the library takes angles in (0, 2 pi]


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
        P = sum(
            math.comb(len(data) - 1, i) * (t**i * (1 - t) ** (len(data) - 1 - i))[:, None] * (np.asarray(q) - C)
            for i, q in enumerate(data)
        )
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
    if how == "touch_end":  # a starts where b ends
        s_a = b_end
    elif how == "touch_start":  # a ends where b starts
        s_a = _rot(r, na, -angle_a)
    elif how == "overlap":
        s_a = _rot(r, nb, rng.uniform(0, min(angle_b, 2 * math.pi)))
    else:  # starting after b's end, ending before b's start (if it can)
        gap = max(2 * math.pi - angle_b, 0.0)
        s_a = _rot(b_end, nb, gap * rng.uniform(0.1, 0.9))
        angle_a = min(angle_a, gap * rng.uniform(0.05, 0.5)) if gap > 0 else angle_a
    s_a = np.round(s_a) if ex and np.max(np.abs(s_a - np.round(s_a))) < 1e-12 else s_a
    return fr.round(np.zeros(3), na, Ra) + fr.dirv(s_a) + [angle_a], b


_ARC_TRANSLATED_BASES = (
    "arc_random",
    "arc_tangent",
    "arc_ends",
    "arc_coplanar",
    "arc_concentric",
    "arc_axis",
    "arc_near_touching",
    "arc_spans",
    "arc_angles",
    "arc_end_on_axis",
)


def _fam_arc_far_translated(rng, ka, kb):
    return _fam_far_translated(rng, ka, kb, bases=_ARC_TRANSLATED_BASES)


def _fam_arc_ends(rng, ka, kb):
    """An arc end (theta = 0 or theta = angle) exactly at, or 1e-16..1e-6 rad beside, the
    circle's point nearest the other shape (or the other round's axis), over the tangent,
    coplanar, random and (rounds) nearly touching cases."""
    bases = [
        f
        for f in ("tangent", "coplanar", "random", "near_touching", "shadow_center", "concentric")
        if (ka, kb) in _arc_pairs(FAMILIES[f][0])
    ]
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
    bases = [
        f for f in ("random", "tangent", "coplanar", "axis", "near_touching") if (ka, kb) in _arc_pairs(FAMILIES[f][0])
    ]
    return _arc_variant(str(rng.choice(bases)), extreme=True)(rng, ka, kb)
