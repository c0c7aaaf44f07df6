"""Finding classes, reproducers, and the direct comparison with the 50-digit references
(``reference_check``).
"""

from __future__ import annotations

import collections

import numpy as np

from .base import BARS, _load, combos
from .screen import screen
from .families import bar_scale, to_float32_case
from .unique import expected_unique
from .check import _call, _finding, _jsonable, make_shape
from .confirm import MISS_REL, _mp_num, mp_reference, mp_screen_value
from .unique_reference import reference_unique


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
    lines = [
        "import numpy as np, circledist as cd",
        f"a = {_ctor_text(ka, f['a_data'], f32)}",
        f"b = {_ctor_text(kb, f['b_data'], f32)}",
    ]
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
        entry = (
            "closest_points(a, b, %s).distance" % kw
            if f.get("entry") == "closest_points"
            else "distance(a, b, %s)" % kw
        )
        lines.append(f"print(repr(cd.{entry}))")
    note = {
        k: f[k]
        for k in (
            "library",
            "reference",
            "reference_screen",
            "error",
            "screen",
            "problems",
            "ab",
            "ba",
            "off_a",
            "off_b",
            "allowed",
            "separation",
            "distance",
            "closest_points",
            "error",
        )
        if k in f
    }
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
                diags.append(
                    dict(
                        case_id=case["id"],
                        family=case["family"],
                        pair=f"{case['a']}-{case['b']}",
                        problem="reference missed the minimum",
                        reference=float(ref),
                        screen_mp=float(scr_mp),
                        float32=f32,
                    )
                )
                best = scr_mp
            tol = (BARS["float32"] if f32 else 1e-15) * scale_ + float(scr.slack[0])
            if float(scr.value[0]) > float(best) + tol:
                diags.append(
                    dict(
                        case_id=case["id"],
                        family=case["family"],
                        pair=f"{case['a']}-{case['b']}",
                        problem="screen bound above the reference",
                        reference=float(best),
                        screen=float(scr.value[0]),
                        float32=f32,
                    )
                )
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
                            f = _finding(
                                "unique",
                                c,
                                solver,
                                precision,
                                order,
                                entry,
                                library=bool(v.unique),
                                expected=uexp[0],
                                why=uexp[1] + " (direct)",
                            )
                            f["confirmed"] = True
                            findings.append(f)
                        v = v if entry == "distance" else v.distance
                        e = abs(_mp_num(_jsonable(np.longdouble(v)) if precision == "longdouble" else float(v)) - best)
                        if e > bar:
                            f = _finding(
                                "reference",
                                c,
                                solver,
                                precision,
                                order,
                                entry,
                                library=np.longdouble(v) if precision == "longdouble" else float(v),
                                reference=float(best),
                                error=float(e) / scale_,
                            )
                            f["confirmed"] = True
                            findings.append(f)
    return findings, diags
