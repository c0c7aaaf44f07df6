"""Effects held to their definition on the library's own distance
(``check_effects_definition``), and ``check_and_confirm``, the entry point of the CI slice and
the long mode.
"""

from __future__ import annotations

import numpy as np

from .base import EPS64
from .families import EFFECT_FAMILIES
from .check import _eq, _finding, _group, check_cases, make_shape, pair_scale
from .confirm import confirm_finding
from .report import finding_class


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
    shapes (unless `scenes` is False). float64, the default solver (the bounds are the same for every policy;
    check_cases
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
                            findings.append(
                                _effect_finding(group[j], order, sa, sb, "within", D[j], d[j], bool(w[j]), float(b[j]))
                            )
                    it = np.asarray(cd.intersects(x, y))
                    w0 = np.asarray(cd.within(x, y, np.zeros_like(D)))
                    for j in np.flatnonzero(it != w0):
                        findings.append(
                            _effect_finding(group[j], order, sa, sb, "intersects", D[j], 0.0, bool(it[j]), None)
                        )
                    for d in (0.5 * D, D + band):  # scalar calls give the batch's answers
                        w = np.asarray(cd.within(x, y, d))
                        for j in range(len(group)):
                            ws = bool(cd.within(x[j], y[j], float(d[j])))
                            if ws != bool(w[j]):
                                findings.append(
                                    _effect_finding(group[j], order, sa, sb, "scalar within", D[j], d[j], ws, None)
                                )
                    if order == "ba" or not scenes:
                        continue
                    for j in range(len(group)):
                        findings += _check_scene_effects(
                            cd, group[j], SA[j], SB[j], sa, sb, float(D[j]), float(s[j]), float(band[j])
                        )
    for f in findings:
        f["confirmed"] = True
    return findings


def _effect_finding(case, order, sa, sb, entry, D, d, got, got_distance):
    f = _finding(
        "effect_definition",
        case,
        "default",
        "float64",
        order,
        entry,
        library=float(D),
        d=float(d),
        answer=got,
        sweeps=[float(sa), float(sb)],
    )
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
        got = {
            "Scene.within(shape)": ("b" in scene.within(a, d)) == want,
            "Scene.within(name)": scene.within("a", d) == (["b"] if want else []),
            "Scene.pairs_within": scene.pairs_within(d) == ([("a", "b")] if want else []),
        }
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
