"""The case families (``FAMILIES``), the effect family, case generation and scales.

Case families.  ``generate(family, n, seed)`` returns ``n`` JSON-able cases
``{"family", "id", "a", "a_data", "b", "b_data"}`` (kind names and plain floats; a Bezier's
data is a list of [x, y, z] control points) for the kind pairs the family applies to, cycling
through them.  Pairs are written in a canonical order (point/line/ray/segment/bezier before
circle/disk, circle before disk; among linear pieces point, line, ray, segment in that order;
a Bezier curve before a linear piece); the checker runs both argument orders.  ``FAMILIES``
lists them: plain random cases and the adversarial ones (tangencies, lines on and
near the axis, lines whose shadow on the plane crosses the centre, coplanar and (nearly)
concentric rounds, far-translated scenes, far line origins, extreme radius ratios, nearly
touching disks, a circle parallel to a disk at tiny heights,
large / far-controlled / in-plane Bezier curves, a huge circle passing a small disk); then
the families of the pairs without a round, every pair among point/line/ray/segment and a
Bezier curve against each (random, far-translated, nearly parallel pieces crossing or a hair
apart or collinear, far origins and ends, zero-length segments, points and ends on the other
piece, a line tangent to a curve or parallel to its end tangent, a curve crossing a piece,
curves with a far control point or 1e2..1e5 times larger than the piece).  Arcs:
an arc against a point, line, ray, segment, circle, disk or arc, the arc second (after the
other kind, as a circle or disk comes after the pieces; ARC_PAIRS), in the "arc_" families:
the circle families applied to arcs (_arc_variant: the base family's case with the arcs drawn
as circles, each then cut to an arc whose span is placed relative to the circle's point
nearest the other shape or the other round's axis -- an end exactly there or 1e-16..1e-6 rad
beside it, the point inside the span, or beyond both ends), and the arcs' own: ends at the
features (arc_ends), a round's axis through an arc end (arc_end_on_axis), concentric coplanar
spans overlapping, disjoint or touching at an end (arc_spans), tiny angles, 2 pi - tiny and
2 pi exactly (arc_angles).  Annuli: an annulus against every kind, the annulus
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
"""

from __future__ import annotations

import math

import numpy as np

from .base import (
    ANN_PAIRS,
    ANN_RR,
    ARC_PAIRS,
    ARC_RR,
    BL,
    BR,
    FAMILIES,
    KIND_PAIRS,
    LL,
    LL3,
    LLZ,
    LR,
    LR3,
    RIMS,
    ROUND,
    ROUND_PAIRS,
    RR,
    _key,
    _load,
    _piece_points,
    _plain,
)
from .families_round import (
    _fam_axis,
    _fam_bezier_far_control,
    _fam_bezier_large,
    _fam_bezier_plane,
    _fam_concentric,
    _fam_coplanar,
    _fam_far_origin,
    _fam_far_translated,
    _fam_huge_circle,
    _fam_near_concentric,
    _fam_near_touching,
    _fam_parallel_height,
    _fam_piece_near_plane,
    _fam_radius_ratio,
    _fam_random,
    _fam_shadow_center,
    _fam_tangent,
)
from .families_linear import (
    _fam_bezier_crossing,
    _fam_bezier_far_control_linear,
    _fam_bezier_large_linear,
    _fam_bezier_tangent_line,
    _fam_linear_far_origin,
    _fam_linear_far_translated,
    _fam_linear_random,
    _fam_near_parallel,
    _fam_on_piece,
    _fam_zero_length,
)
from .families_arc import (
    _arc_pairs,
    _arc_variant,
    _fam_arc_angles,
    _fam_arc_end_on_axis,
    _fam_arc_ends,
    _fam_arc_far_translated,
    _fam_arc_spans,
)
from .families_annulus import (
    _ann_pairs,
    _ann_variant,
    _fam_ann_degenerate,
    _fam_ann_far_translated,
    _fam_ann_hole,
    _fam_ann_inner_tangent,
    _fam_ann_overlap,
)


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
    small integer data: a round's radius 0, 1 or 2 (0: a point), an annulus's inner radius
    0..outer (0: the disk, = outer: the circle), a segment of length 0 sometimes."""

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


# name: (kind pairs, generator); the dict is base.FAMILIES, which the generators read
FAMILIES.update(
    {
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
)
# arcs: the circle families applied to arcs (arc_<base>: the base family's cases with
# their arcs cut from circles, _arc_variant), then the arcs' own
for _base in (
    "random",
    "tangent",
    "axis",
    "shadow_center",
    "piece_near_plane",
    "coplanar",
    "concentric",
    "near_concentric",
    "far_origin",
    "radius_ratio",
    "near_touching",
    "parallel_height",
    "huge_circle",
):
    FAMILIES["arc_" + _base] = (_arc_pairs(FAMILIES[_base][0]), _arc_variant(_base))
FAMILIES.update(
    {
        "arc_ends": (ARC_PAIRS, _fam_arc_ends),
        "arc_end_on_axis": (ARC_RR, _fam_arc_end_on_axis),
        "arc_spans": (ARC_RR, _fam_arc_spans),
        "arc_angles": (ARC_PAIRS, _fam_arc_angles),
        "arc_far_translated": (ARC_PAIRS, _fam_arc_far_translated),
    }
)
# annuli: the disk families applied to annuli (ann_<base>: the base family's cases with
# their annuli holed from disks and their arcs cut from circles, _ann_variant), then the annuli's own
for _base in (
    "random",
    "tangent",
    "axis",
    "shadow_center",
    "piece_near_plane",
    "coplanar",
    "concentric",
    "near_concentric",
    "far_origin",
    "radius_ratio",
    "near_touching",
    "parallel_height",
    "huge_circle",
):
    FAMILIES["ann_" + _base] = (_ann_pairs(FAMILIES[_base][0]), _ann_variant(_base))
FAMILIES.update(
    {
        "ann_hole": (ANN_PAIRS, _fam_ann_hole),
        "ann_overlap": (ANN_RR, _fam_ann_overlap),
        "ann_degenerate": (ANN_PAIRS, _fam_ann_degenerate),
        "ann_inner_tangent": (ANN_PAIRS, _fam_ann_inner_tangent),
        "ann_far_translated": (ANN_PAIRS, _fam_ann_far_translated),
    }
)
# every kind pair: within() / intersects() / distance_if_within() / Scene.within /
# Scene.pairs_within against their definition on degenerate small-integer configurations
FAMILIES["effect_degenerate"] = (KIND_PAIRS, _fam_effect_degenerate)
EFFECT_FAMILIES = ("effect_degenerate",)


def has_round(family):
    """Whether a family's kind pairs include a circle or disk (the sixteen first families and piece_near_plane) or
    not (the pairs among points, lines, rays and segments and Bezier curves against them); the
    arc families (is_arc) and the annulus families (is_annulus) count as neither."""
    return not is_arc(family) and not is_annulus(family) and any(set(ROUND) & set(pair) for pair in FAMILIES[family][0])


def is_arc(family):
    """Whether a family is one of the arcs' (its kind pairs have an arc, and no annulus)."""
    return not is_annulus(family) and any("arc" in pair for pair in FAMILIES[family][0])


def is_annulus(family):
    """Whether a family is one of the annuli's (its kind pairs have an annulus)."""
    return any("annulus" in pair for pair in FAMILIES[family][0])


def generate_one(family, seed, i):
    """Case i of a family: kind pair i mod (number of pairs), drawn from
    np.random.default_rng([seed, family index, i]) -- reproducible from its id alone."""
    fam_pairs, gen = FAMILIES[family]
    ka, kb = fam_pairs[i % len(fam_pairs)]
    rng = np.random.default_rng([seed, list(FAMILIES).index(family), i])
    a, b = gen(rng, ka, kb)
    return {"family": family, "id": f"{family}/{seed}/{i}", "a": ka, "a_data": _plain(a), "b": kb, "b_data": _plain(b)}


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
    query, pieces that touch within the inputs' rounding, fall back to that floor); for a Bezier curve
    against one of them the largest length in the query, the
    control polygon's extent and a segment's length (reference_round.bezier_other_scale, as
    tests/pairs/test_bezier_point_linear.py).  Both are translation invariant; points a hair apart
    (zero-length segments) are held to the distance between them."""
    ka, kb = case["a"], case["b"]
    if ka in RIMS or kb in RIMS:
        return largest_radius(case)
    key = _key(case)
    if key not in _SCALE_CACHE:
        if ka == "bezier":
            _SCALE_CACHE[key] = _load("reference_round").bezier_other_scale(
                case["a_data"], kb, *_piece_points(kb, case["b_data"])
            )
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
