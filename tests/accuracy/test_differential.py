"""The CI slice of the standing differential accuracy test.

A fixed seed; every case family of circledist_cases/differential.py with every kind pair it applies to
(every pair of kinds: a circle or disk with any kind, points / lines / rays / segments among
themselves, a Bezier curve against each of those, an arc against a point, line, ray, segment,
circle, disk or arc, an annulus against every kind);
every solver ("bracketing", "companion", "polished", "eigen") x precision (float64, long double,
float32); both argument orders; distance(), closest_points(), within(), distance_if_within() and
intersects(), batched and scalar.  Each answer is judged by the fast NumPy screen (an independent
one-parameter minimisation, an upper bound from genuine points) and by the closest points the
library returns (on their shapes, separation == distance); every accuracy finding is confirmed
against the 50-digit mpmath references of circledist_cases/reference_linear_round.py, reference_round.py,
reference_arc.py, reference_annulus.py and reference_linear.py before it counts; closest_points().unique is
checked where differential.expected_unique's independent rule decides it (exact continua by symmetry:
False; closed forms and strict convexity with a margin: True), and in the direct comparisons (float64
scenes) also where a 50-digit search over one shape's parameter shows a single strict minimum whose
nearest point on the other shape is unique (differential.reference_unique: a circle or arc against a
line, ray, segment, disk, circle, arc or annulus; a Bezier curve against a point, line, ray, segment,
disk, circle, arc or annulus; a line, ray or segment against a disk or annulus).  The first case of every (family, kind
pair) is also compared with those references directly, for every combination (a Bezier curve
against a linear piece: one family per pair, DIRECT_BEZIER_LINEAR; the arc and annulus families: every third
pair, DIRECT_ARC_EVERY).

Bars (never loosened here): |d - d_true| <= bar * max(d_true, scale), bar 1e-12 in float64, 1e-15
in long double, 4 float32 ulps (4 * 2^-23) for float32 inputs; the scale is the largest radius,
or without a circle or disk the scale of the pairs' own accuracy tests (differential.bar_scale).

Two cases per family and kind pair; the first case of each is also compared with the 50-digit
references directly, and the slice's size and cost are printed by the slice itself (the fixture's
summary). A failure lists one reproducer per finding class; `python -m tools.differential` runs the
same checks on millions of cases.

The effect family (effect_degenerate: every kind pair in small integer configurations with a
center on the other's axis, coaxial, coplanar, concentric, radius 0, inner radius 0 or = outer)
also goes through differential.check_effects_definition: within at d = 0, D/4, D/2, 0.9 D,
D -+ 4x the tolerance, 1.1 D and 2 D, distance_if_within, intersects, batched and scalar, plain
and swept, and Scene.within / Scene.pairs_within on the pair, against the documented definition on
the library's own distance.
"""

from __future__ import annotations

import collections
import time

import pytest

from circledist_cases import differential as D

cd = pytest.importorskip("circledist")

SEED = 20261114
PER_PAIR = 4  # cases per (family, kind pair) ...
MIN_PER_FAMILY = 40  # ... and at least this many per family
PER_PAIR_NO_ROUND = 2  # cases per (family, kind pair) of the families without a circle or disk
PER_PAIR_ARC = 2  # cases per (family, kind pair) of the arc families
PER_PAIR_ANN = 2  # ... and of the annulus families
PER_PAIR_EFFECT = 4  # ... and of the effect families (every kind pair; check_effects_definition too)
# The arc families' direct 50-digit comparison (~0.2 s a case with every combination) takes the
# first case of every third (family, kind pair): the pair whose index in the family's list is the
# family's index mod 3, so every arc pair is compared directly in some families.
DIRECT_ARC_EVERY = 3  # (the annulus families alike)
SCALAR_EVERY = 4  # scalar calls on every 4th case
# The direct 50-digit comparison takes the first case of every (family, kind pair), except for a
# Bezier curve against a point, line, ray or segment (whose reference costs ~0.5 s a case): one
# (family, pair) each, an adversarial one.  Their other families' findings are confirmed against
# the same references all the same, and tests/pairs/test_bezier_point_linear.py compares them directly.
DIRECT_BEZIER_LINEAR = {
    ("bezier", "point"): "bezier_large_linear",
    ("bezier", "line"): "bezier_tangent_line",
    ("bezier", "ray"): "bezier_crossing",
    ("bezier", "segment"): "bezier_far_control_linear",
}


def slice_cases():
    out = []
    for family, (pairs, _) in D.FAMILIES.items():
        if family in D.EFFECT_FAMILIES:
            n = PER_PAIR_EFFECT * len(pairs)
        elif D.is_arc(family):
            n = PER_PAIR_ARC * len(pairs)
        elif D.is_annulus(family):
            n = PER_PAIR_ANN * len(pairs)
        elif D.has_round(family):
            n = max(PER_PAIR * len(pairs), MIN_PER_FAMILY)
        else:
            n = PER_PAIR_NO_ROUND * len(pairs)
        out += D.generate(family, n, SEED)
    return out


@pytest.fixture(scope="module")
def results():
    t0 = time.perf_counter()
    cases = slice_cases()
    # Scalar calls (batch == scalar, to the bit) on every 4th case, and on the first case of every
    # (family, kind pair) of the families without a round (two cases per pair, which every 4th
    # case would miss for some); test_bindings.py checks single queries against batch elements for
    # every pair, solver and precision besides.
    scalar = set(range(0, len(cases), SCALAR_EVERY))
    seen = set()
    for i, c in enumerate(cases):
        if not D.has_round(c["family"]) and (c["family"], c["a"], c["b"]) not in seen:
            seen.add((c["family"], c["a"], c["b"]))
            scalar.add(i)
    findings, stats = D.check_and_confirm(cd, cases, scalar=scalar)
    t1 = time.perf_counter()
    firsts = {}
    for c in cases:
        pair = (c["a"], c["b"])
        if D.is_arc(c["family"]) or D.is_annulus(c["family"]):
            fam_pairs = D.FAMILIES[c["family"]][0]
            if fam_pairs.index(pair) % DIRECT_ARC_EVERY != list(D.FAMILIES).index(c["family"]) % DIRECT_ARC_EVERY:
                continue
        if DIRECT_BEZIER_LINEAR.get(pair, c["family"]) == c["family"]:
            firsts.setdefault((c["family"], c["a"], c["b"]), c)
    direct = {}
    ref_findings, diags = D.reference_check(cd, list(firsts.values()), stats=direct)
    t2 = time.perf_counter()
    print(
        f"\ndifferential slice: {len(cases)} cases, {sum(stats['answers'].values())} library answers, "
        f"{t1 - t0:.1f} s checks; "
        f"{len(firsts)} direct 50-digit references, {t2 - t1:.1f} s; unique checked "
        f"(screen) {dict(stats['unique_checked'])}, (direct) {dict(sorted(direct['unique_checked_direct'].items()))}"
    )
    return dict(cases=cases, findings=findings + ref_findings, diags=diags, firsts=list(firsts.values()))


def describe(findings, limit=12):
    classes = collections.OrderedDict()
    for f in findings:
        classes.setdefault(D.finding_class(f), []).append(f)
    lines = [f"{len(findings)} confirmed findings in {len(classes)} classes"]
    for (check, family, pair), fs in list(classes.items())[:limit]:
        combos = collections.Counter((f["solver"], f["precision"]) for f in fs)
        errors = [f["error"] for f in fs if isinstance(f.get("error"), float)]
        worst = max(fs, key=lambda f: f.get("error") or 0) if errors else fs[0]
        lines.append(
            f"\n[{check}] family={family} pair={pair}: {len(fs)} answers, "
            f"cases {sorted({f['case_id'] for f in fs})[:4]}, combos {dict(combos)}"
            + (f", worst relative error {max(errors):.3g}" if errors else "")
        )
        lines.append(D.reproducer(worst))
    return "\n".join(lines)


@pytest.mark.slow
def test_slice_covers_every_family_and_kind_pair(results):
    seen = collections.Counter((c["family"], (c["a"], c["b"])) for c in results["cases"])
    for family, (pairs, _) in D.FAMILIES.items():
        for pair in pairs:
            assert seen[(family, pair)] >= 1, (family, pair)
    assert {p for _, p in seen} == set(D.KIND_PAIRS)


# Classes that still fail, each with its note in the tracker. Any other finding in the family
# fails the test, and so does a known class that stops failing (remove it here then).
# None: the last (the polished policy's unique=True for an arc lying on a coaxial circle's rim) is
# fixed and kept in tests/accuracy/test_regressions_arc.py::test_unique_coaxial_arc.
KNOWN_FAILURES: dict = {}


@pytest.mark.slow
@pytest.mark.parametrize("family", list(D.FAMILIES))
def test_no_confirmed_findings(results, family):
    bad = [f for f in results["findings"] if f["family"] == family and f.get("confirmed")]
    unknown = [f for f in bad if (family, D.finding_class(f)[2]) not in KNOWN_FAILURES]
    assert not unknown, describe(unknown)
    known = {pair: why for (fam, pair), why in KNOWN_FAILURES.items() if fam == family}
    for pair in known:
        assert any(
            D.finding_class(f)[2] == pair for f in bad
        ), f"{family}/{pair} no longer fails: remove it from KNOWN_FAILURES"
    if known:
        pytest.xfail("; ".join(f"{family} {pair}: {why}" for pair, why in known.items()))


@pytest.mark.slow
def test_screen_false_alarms_and_reference_misses(results):
    """The tools themselves: no screen alarm that the 50-digit reference refutes, no reference
    that misses a pair the screen found (a reference above a genuine pair is wrong), no screen
    bound above a reference (a screen that misses minima would hide findings)."""
    refuted = [f for f in results["findings"] if f["check"] in D.ACCURACY_CHECKS and f.get("confirmed") is False]
    missed = [f for f in results["findings"] if f.get("reference_missed")]
    problems = []
    if refuted:
        problems.append(
            f"{len(refuted)} screen alarms refuted by the reference: "
            + "; ".join(
                f"{f['case_id']} {f['solver']}/{f['precision']} {f['check']} lib {f.get('library')} "
                f"screen {f.get('screen')} ref {f.get('reference')}"
                for f in refuted[:5]
            )
        )
    if missed:
        problems.append(
            f"{len(missed)} findings where the reference missed the minimum the screen found: "
            + "; ".join(f"{f['case_id']} ref {f['reference']} screen {f.get('reference_screen')}" for f in missed[:5])
        )
    problems += [str(d) for d in results["diags"]]
    assert not problems, "\n".join(problems)


# ---- the tools on their own (no library call) ------------------------------------------------
def far_curve_case():
    """The long run's false bezier_large finding (circledist_cases/scenes.py,
    tests/accuracy/test_regressions_bezier.py): a degree-1 curve 2e4
    long passing a ring of radius 0.78, with two local minima 2.5e-5 apart in t whose values
    differ by 5.9e-13; both tools used to refine only the higher one."""
    from circledist_cases.scenes import FAR_CURVE_CONTROL, FAR_CURVE_DISTANCE, FAR_CURVE_RING

    center, normal, radius = FAR_CURVE_RING
    case = dict(
        family="bezier_large",
        id="far_curve",
        a="bezier",
        a_data=FAR_CURVE_CONTROL.tolist(),
        b="circle",
        b_data=list(center) + list(normal) + [radius],
    )
    return case, FAR_CURVE_DISTANCE, radius


def test_screen_and_reference_keep_near_tied_minima():
    """Both independent references of the differential give the distance of the far curve: the
    screen (long double: within 1e-15 of the radius, and its best pair re-evaluated at 50 digits
    too) and the 50-digit reference (to the 25 digits FAR_CURVE_DISTANCE is stated to), which also
    reports both local minima."""
    R = D._load("reference_round")
    case, truth, radius = far_curve_case()
    scr = D.screen([case])
    value = D._mpf_ld(scr.value[0])
    assert abs(value - truth) <= 1e-15 * radius, (value, truth)
    assert value >= truth - R.mpf(float(scr.slack[0])), "the screen's value is a genuine pair's, an upper bound"
    pair = D.mp_screen_value(case, scr.forms[0], scr.params[0])
    assert abs(pair - truth) <= 1e-15 * radius, (pair, truth)
    D._REF_CACHE.pop(D._key(case), None)
    ref = D.mp_reference(case)
    assert abs(ref - truth) <= R.mpf("1e-24") * radius, (ref, truth)
    minima = R.bezier_circle(case["a_data"], case["b_data"][:3], case["b_data"][3:6], case["b_data"][6]).pairs
    assert len(minima) >= 2 and abs(minima[1].value - truth - R.mpf("5.899e-13")) <= R.mpf("1e-15"), minima[:2]


def _hand_case(ka, a, kb, b):
    return dict(family="hand", id=f"hand/{ka}-{kb}", a=ka, a_data=a, b=kb, b_data=b)


CIRCLE = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0]


@pytest.mark.parametrize(
    "ka, a, kb, b, want",
    [
        # a straight curve at height 2 across the circle, symmetric about its axis: x = +-1 tie
        ("bezier", [[-2.0, 0.0, 2.0], [0.0, 0.0, 2.0], [2.0, 0.0, 2.0]], "circle", CIRCLE, None),
        # the same, one side only: x = 1
        ("bezier", [[0.2, 0.0, 2.0], [1.1, 0.0, 2.0], [2.0, 0.0, 2.0]], "circle", CIRCLE, True),
        # a curve on the circle's axis (every control point): every rim point as close
        ("bezier", [[0.0, 0.0, 1.0], [0.0, 0.0, 3.0], [0.0, 0.0, 2.0]], "circle", CIRCLE, False),
        # a curve ending at the circle's plane, short of its rim: the minimum at the end t = 1
        ("bezier", [[0.3, 0.0, 2.0], [0.3, 0.5, 1.0], [0.5, 0.0, 0.0]], "disk", CIRCLE, True),
        # a curve along a line (a flat run of minima)
        ("bezier", [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [2.0, 0.0, 1.0]], "line", [0.0, 0.0, 0.0, 1.0, 0.0, 0.0], None),
        # two coplanar circles apart: one pair
        ("circle", CIRCLE, "circle", [3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0], True),
        # a circle tangent to the other's axis at its centre, nearest there (a strict minimum over its
        # angle): every rim point of the other is as close (distance 1), the target's nearest point is
        # not unique there
        ("circle", [1.2, 0.0, 0.0, 0.0, 1.0, 0.0, 1.2], "circle", CIRCLE, None),
        # an arc in a vertical plane from beyond an annulus's outer rim up over its ring, nearest at
        # its start (0, 3, 1)
        (
            "arc",
            [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 3.0, 0.0, 1.0, 0.0, 1.0],
            "annulus",
            [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.5, 1.0],
            True,
        ),
        # a huge circle through a tiny-holed annulus 8e-8 from its axis, in a scene of scale 3.7e8
        # (ann_huge_circle/21/216): within the scene's rounding of the inner rim's axis, not called
        (
            "circle",
            [
                120582553.34208253,
                -148834309.91328016,
                -317319889.41030097,
                -0.06949600391428644,
                -0.7651446695945717,
                0.3324713521195893,
                370653091.7178497,
            ],
            "annulus",
            [
                0.6756174095537185,
                -1.6265741399653666,
                -1.8059190432074093,
                0.11639810755213308,
                0.2329988340881641,
                0.7955980667529972,
                1.65122495808562,
                1.6512249580856201e-09,
            ],
            None,
        ),
        # a line over an annulus's ring, parallel to its plane (a flat run) and tilted (one pair)
        ("line", [0.0, 0.0, 1.0, 1.0, 0.0, 0.0], "annulus", [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 1.0], None),
        ("line", [0.0, 0.0, 1.0, 1.0, 0.0, 0.25], "annulus", [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 1.0], True),
    ],
)
def test_unique_rule_by_hand(ka, a, kb, b, want):
    """The unique rules on hand-made cases whose answer is plain (differential.expected_unique's
    exact continua, else differential.reference_unique's 50-digit search), and the library's
    unique agrees where they decide."""
    case = _hand_case(ka, a, kb, b)
    got = D.expected_unique(case)[0]
    if got is None:
        got = D.reference_unique(case)[0]
    assert got is want
    if want is not None:
        x, y = D.make_shape(cd, ka, a), D.make_shape(cd, kb, b)
        assert cd.closest_points(x, y).unique is want
        assert cd.closest_points(y, x).unique is want


# A round of radius 0 is the point at its centre: its axis carries no continuum of closest pairs,
# and a point-like round on another round's axis is a point there. Each round kind at radius 0,
# tilted, centred at Z0 on the axis (N0 through the origin) that the other shape shares.
N0 = [1.0, 2.0, 2.0]
Z0 = [2.0, 4.0, 4.0]
ZERO_ROUNDS = {
    "circle": Z0 + N0 + [0.0],
    "disk": Z0 + N0 + [0.0],
    "annulus": Z0 + N0 + [0.0, 0.0],
    "arc": Z0 + N0 + [0.0, 2.0, -1.0, 0.0, 2.0],
}
AXIS_SHAPES = [
    ("point", [-1.0, -2.0, -2.0], True),  # a point on the axis: point to point
    ("line", [0.0, 0.0, 0.0] + N0, True),  # the axis itself, through the round's centre
    ("segment", [0.0, 0.0, 0.0, -1.0, -2.0, -2.0], True),  # a piece of the axis short of it
    ("circle", [0.0, 0.0, 0.0] + N0 + [1.5], False),  # a coaxial ring: every rim point as far
    ("disk", [0.0, 0.0, 0.0] + N0 + [1.5], True),  # a coaxial disk: its centre is nearest
    ("annulus", [0.0, 0.0, 0.0] + N0 + [1.5, 0.5], False),  # the hole's rim, all as far
    ("annulus", [0.0, 0.0, 0.0] + N0 + [1.5, 0.0], True),  # no hole: a disk
    ("arc", [0.0, 0.0, 0.0] + N0 + [1.5, 2.0, -1.0, 0.0, 2.0], False),  # every arc point as far
]


@pytest.mark.parametrize("kind", sorted(ZERO_ROUNDS))
@pytest.mark.parametrize("kb, b, want", AXIS_SHAPES, ids=[f"{k}-{i}" for i, (k, _, _) in enumerate(AXIS_SHAPES)])
def test_unique_rule_rounds_of_radius_zero(kind, kb, b, want):
    """A round of radius 0 against shapes on its axis, in both orders: unique is what the point
    at its centre would have (the exact rule says False only where the other shape's rim is a
    continuum about the axis; elsewhere it says True or nothing, never False), and the library
    agrees."""
    a = ZERO_ROUNDS[kind]
    for case in (_hand_case(kind, a, kb, b), _hand_case(kb, b, kind, a)):
        got = D.expected_unique(case)[0]
        assert got is want or (want is True and got is None), (case, got)
    x, y = D.make_shape(cd, kind, a), D.make_shape(cd, kb, b)
    assert cd.closest_points(x, y).unique is want
    assert cd.closest_points(y, x).unique is want
