#!/usr/bin/env python3
"""Accuracy against time for every circledist query kind x root policy x precision.

    python -m bench.accuracy_vs_time [--quick] [--min-time S] [--jobs N] [--binary PATH]

(from the repository's root: a module run, so that the shared cases, circledist_cases, import.)

1. Generates the cases (circledist_cases/accuracy.py): seeded random ones and the hard families
   (tangent lines, lines on or near the axis, near-parallel lines, rim crossings, coplanar /
   concentric / linked / near-coplanar circles, curves grazing a disk, arc ends at tangency and on
   an axis, arcs of angle 2 pi - 1e-9 and 2 pi, lines, circles and disks in an annulus's hole,
   coplanar and concentric annuli, ...), each placed in the round shape's own
   frame, under a generic rotation, and translated by 1e6 and 1e8, plus radii 1e-9 and 1e9.
   The stability sweeps of circledist_cases/sweeps.py are appended (double only, not timed).
2. Computes 50-digit references by an independent method: circledist_cases/reference_linear_round.py (linear
   shapes against circles and disks), reference_round.py (circle, disk and Bezier kinds),
   reference_arc.py (every kind against an arc: the arc's angle) and reference_annulus.py (every
   kind against an annulus: the other shape's parameter, or both regions' rims)
   minimise a closed-form point-to-shape distance over ONE parameter (dense sampling, then
   golden-section refinement in mpmath); no polynomial, no root finding. Two Bezier curves:
   reference_bezier.py (the edges by reference_round, the interior by 50-digit descents from a
   grid, then one parameter along the valley). The float run gets the
   references of its own float-rounded inputs; the long double run's inputs are the doubles
   extended exactly, so it shares the double references. References are cached in
   build/accuracy_vs_time/references.json (keyed by the reference modules' contents).
3. Runs bench/accuracy_vs_time.cpp (the CMake target `accuracy_vs_time` in build/cpp, which
   this script has CMake configure and build when it is missing or stale), which computes every distance in
   float, double and long double with the three root policies, and times them.
4. Prints one table per kind x policy x precision (ns/query, max and median relative error on
   the random and on the hard cases), writes docs/reports/accuracy_vs_time.md with the recommended
   default policy, docs/reports/accuracy_vs_time.png (error against time) and
   docs/reports/stability_sweeps.png.

Relative error = |d - d_ref| / max(d_ref, largest radius of the query (an arc's radius, an
annulus's outer radius); for two Bezier curves the larger curve size). The bar is 1e-12 in
double; float and long double are judged against the same number of ulps (1e-12 eps_p / eps_d:
5.4e-4 for float, 4.9e-16 for long double).
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import json
import math
import multiprocessing
import os
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

if not __package__:  # run as a file: the shared cases (circledist_cases) would not import
    sys.exit("bench/accuracy_vs_time.py: run it from the repository's root as python -m bench.accuracy_vs_time")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread)

from circledist_cases import sweeps  # noqa: E402
from circledist_cases.accuracy import (
    KINDS,
    Case,
    generate_cases,
    bar_scale,
    reference_distance,  # noqa: E402
    relative_error,
    to_float32,
)
from mpmath import mpf  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

# ------------------------------------------------------------------------------------------------
# kinds, value layouts (shared with accuracy_vs_time.cpp) and the precisions / policies
# ------------------------------------------------------------------------------------------------
POLICIES = ["EigenCompanion", "EigenPolished", "Bracketing", "EigenPolynomialSolver"]
PRECISIONS = ["float", "double", "longdouble"]
EPS = {"float": 2.0**-23, "double": 2.0**-52, "longdouble": 2.0**-63}
DOUBLE_BAR = 1e-12
BAR = {p: DOUBLE_BAR * EPS[p] / EPS["double"] for p in PRECISIONS}
GROUPS = {"random": 0, "hard": 1, "sweep": 2}
ERROR_FLOOR = 1e-21  # zero errors are drawn here on log axes

BUILD = ROOT / "build" / "accuracy_vs_time"
DOCS = ROOT / "docs" / "reports"


def _reference_version():
    h = hashlib.sha256()
    for name in (
        "reference_kit.py",
        "reference_linear_round.py",
        "reference_round.py",
        "reference_bezier.py",
        "reference_arc.py",
        "reference_annulus.py",
    ):
        h.update((ROOT / "circledist_cases" / name).read_bytes())
    return h.hexdigest()[:16]


def _key(kind, values):
    return kind + "|" + ",".join(repr(float(v)) for v in values)


def _ref_job(item):
    kind, values = item
    return _key(kind, values), str(reference_distance(kind, values))


def compute_references(jobs_list, jobs, log=print):
    """{key: 50-digit string} for every (kind, values) pair, cached on disk."""
    BUILD.mkdir(parents=True, exist_ok=True)
    path = BUILD / "references.json"
    version = _reference_version()
    cache = {}
    if path.exists():
        try:
            data = json.loads(path.read_text())
            if data.get("version") == version:
                cache = data["references"]
        except (OSError, ValueError, KeyError):
            cache = {}
    todo = {}
    for kind, values in jobs_list:
        k = _key(kind, values)
        if k not in cache:
            todo[k] = (kind, tuple(values))
    if todo:
        log(f"== references: {len(todo)} to compute ({len(cache)} cached), {jobs} processes")
        t0 = time.time()
        items = list(todo.values())

        def save():  # every 500 references too: an interrupted run keeps what it computed
            tmp = path.with_suffix(".tmp")
            tmp.write_text(json.dumps({"version": version, "references": cache}))
            tmp.replace(path)

        with multiprocessing.Pool(jobs) if jobs > 1 else contextlib.nullcontext() as pool:
            results = pool.imap_unordered(_ref_job, items, chunksize=4) if pool else map(_ref_job, items)
            for i, (k, v) in enumerate(results):
                cache[k] = v
                if (i + 1) % 500 == 0:
                    log(f"   {i + 1}/{len(items)} ({time.time() - t0:.0f} s)")
                    save()
        log(f"   done in {time.time() - t0:.1f} s")
        save()
    return cache


# ------------------------------------------------------------------------------------------------
# the C++ program
# ------------------------------------------------------------------------------------------------
def _sources():
    src = ROOT / "bench" / "accuracy_vs_time.cpp"
    headers = sorted((ROOT / "cpp" / "include" / "circledist").rglob("*.hpp"))
    return src, headers


def _newest_source_time():
    src, headers = _sources()
    return max(p.stat().st_mtime for p in [src] + headers)


def ensure_binary(explicit=None, jobs=2, log=print):
    """The benchmark program: --binary, else the CMake target bench/accuracy_vs_time in build/cpp,
    configured and built first when it is missing or older than its sources (the one build
    system: the project's CMake, with the flags of bench/CMakeLists.txt)."""
    if explicit:
        return Path(explicit)
    build = ROOT / "build" / "cpp"
    binary = build / "bench" / "accuracy_vs_time"
    if binary.exists() and binary.stat().st_mtime >= _newest_source_time():
        return binary
    log(f"== building {binary.relative_to(ROOT)} with CMake ({jobs} jobs)")
    t0 = time.time()
    subprocess.run(
        [
            "cmake",
            "-S",
            str(ROOT),
            "-B",
            str(build),
            "-G",
            "Ninja",
            "-DCMAKE_BUILD_TYPE=Release",
            "-DCIRCLEDIST_BUILD_TESTS=ON",
            "-DCIRCLEDIST_BUILD_BENCH=ON",
        ],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    subprocess.run(
        ["cmake", "--build", str(build), "--target", "accuracy_vs_time", "-j", str(max(1, jobs))], check=True
    )
    log(f"   built in {time.time() - t0:.0f} s")
    return binary


def run_binary(binary, cases, min_time, log=print):
    BUILD.mkdir(parents=True, exist_ok=True)
    inp, out = BUILD / "cases.txt", BUILD / "results.txt"
    with open(inp, "w") as f:
        f.write("# kind group count values (written by bench/accuracy_vs_time.py)\n")
        for c in cases:
            f.write(f"{c.kind} {GROUPS[c.group]} {len(c.values)} " + " ".join(repr(float(v)) for v in c.values) + "\n")
    log(f"== running {binary} on {len(cases)} cases (min time {min_time} s per timing)")
    t0 = time.time()
    subprocess.run([str(binary), str(inp), str(out), "--min-time", str(min_time)], check=True)
    log(f"   done in {time.time() - t0:.1f} s")
    compiled, dist, timing = {}, {}, {}
    for line in out.read_text().splitlines():
        f = line.split()
        if f[0] == "K":
            compiled[f[1]] = f[2] == "1"
        elif f[0] == "D":
            dist[(int(f[1]), f[2], f[3])] = f[5] if len(f) > 5 else f[4]  # the exact hexfloat
        elif f[0] == "T":
            group = "random" if f[2] == "0" else "hard"
            timing[(f[1], group, f[3], f[4])] = float(f[6])
    return compiled, dist, timing


# ------------------------------------------------------------------------------------------------
# errors and the summary
# ------------------------------------------------------------------------------------------------
def case_inputs(case, precision):
    return to_float32(case.values) if precision == "float" else case.values


def evaluate(cases, refs, dist):
    """errors[(case index, policy, precision)] = relative error."""
    errors = {}
    for i, c in enumerate(cases):
        for prec in PRECISIONS:
            if c.group == "sweep" and prec != "double":
                continue
            vals = case_inputs(c, prec)
            ref = mpf(c.exact) if c.exact is not None else mpf(refs[_key(c.kind, vals)])
            radius = bar_scale(c.kind, vals)
            for pol in POLICIES:
                errors[(i, pol, prec)] = relative_error(dist.get((i, pol, prec)), ref, radius)
    return errors


@dataclass
class Row:
    kind: str
    policy: str
    precision: str
    ns_random: float
    ns_hard: float
    random_max: float
    random_median: float
    hard_max: float
    hard_median: float
    hard_over: int
    hard_count: int
    random_over: int
    worst: str


def summarize(cases, errors, timing, kinds):
    rows = []
    for kind in kinds:
        idx = {g: [i for i, c in enumerate(cases) if c.kind == kind and c.group == g] for g in ("random", "hard")}
        for prec in PRECISIONS:
            for pol in POLICIES:
                e = {g: [errors[(i, pol, prec)] for i in idx[g]] for g in idx}
                worst_i = max(idx["hard"], key=lambda i: errors[(i, pol, prec)]) if idx["hard"] else None
                rows.append(
                    Row(
                        kind,
                        pol,
                        prec,
                        timing.get((kind, "random", pol, prec), math.nan),
                        timing.get((kind, "hard", pol, prec), math.nan),
                        max(e["random"], default=math.nan),
                        statistics.median(e["random"]) if e["random"] else math.nan,
                        max(e["hard"], default=math.nan),
                        statistics.median(e["hard"]) if e["hard"] else math.nan,
                        sum(x > BAR[prec] for x in e["hard"]),
                        len(e["hard"]),
                        sum(x > BAR[prec] for x in e["random"]),
                        cases[worst_i].name if worst_i is not None else "",
                    )
                )
    return rows


def _geomean(xs):
    xs = [x for x in xs if x > 0 and math.isfinite(x)]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else math.nan


def policy_stats(rows, cases, errors, precision):
    stats = {}
    for pol in POLICIES:
        hard = [errors[(i, pol, precision)] for i, c in enumerate(cases) if c.group == "hard"]
        rnd = [errors[(i, pol, precision)] for i, c in enumerate(cases) if c.group == "random"]
        logs = [math.log10(max(x, ERROR_FLOOR)) if math.isfinite(x) else 0.0 for x in hard]
        pr = [r for r in rows if r.policy == pol and r.precision == precision]
        stats[pol] = {
            "hard_over": sum(not x <= BAR[precision] for x in hard),
            "hard_count": len(hard),
            "hard_max": max(hard),
            "hard_meanlog": sum(logs) / len(logs),
            "random_over": sum(not x <= BAR[precision] for x in rnd),
            "random_count": len(rnd),
            "random_max": max(rnd),
            "ns_random": _geomean([r.ns_random for r in pr]),
            "ns_hard": _geomean([r.ns_hard for r in pr]),
            "failing_kinds": sorted({r.kind for r in pr if r.hard_over or r.random_over}),
        }
    return stats


def recommend(rows, cases, errors):
    """The most accurate policy on the hard cases in double: fewest cases over the bar, then the
    smallest max error, then the smallest mean log10 error. Policies within a factor 2 of the best
    max error and 0.1 of its mean log10 error count as equally accurate; the cheapest of those
    (geometric mean of ns/query on the random cases) is recommended. Returns (policy, stats, tied)."""
    stats = policy_stats(rows, cases, errors, "double")
    over = {p: stats[p]["hard_over"] + stats[p]["random_over"] for p in POLICIES}
    cands = [p for p in POLICIES if over[p] == min(over.values())]
    best_max = min(stats[p]["hard_max"] for p in cands)
    cands = [p for p in cands if stats[p]["hard_max"] <= 2 * best_max]
    best_log = min(stats[p]["hard_meanlog"] for p in cands)
    tied = [p for p in cands if stats[p]["hard_meanlog"] <= best_log + 0.1]
    best = min(tied, key=lambda p: stats[p]["ns_random"])
    return best, stats, tied


def current_default():
    text = (ROOT / "cpp" / "include" / "circledist" / "roots.hpp").read_text()
    for line in text.splitlines():
        if line.strip().startswith("using DefaultRoots"):
            return line.split("=")[1].strip().rstrip(";").strip()
    return "?"


# ------------------------------------------------------------------------------------------------
# output: terminal table, markdown, plots
# ------------------------------------------------------------------------------------------------
def fmt_e(x):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if math.isinf(x):
        return "inf"
    if x == 0:
        return "0"
    return f"{x:.1e}"


def fmt_ns(x):
    if x is None or math.isnan(x):
        return "-"
    return f"{x:.0f}" if x >= 100 else f"{x:.1f}"


HEADER = [
    "kind",
    "policy",
    "precision",
    "ns random",
    "ns hard",
    "random max",
    "random median",
    "hard max",
    "hard median",
    "hard > bar",
    "worst hard case",
]


def row_cells(r):
    return [
        r.kind,
        r.policy,
        r.precision,
        fmt_ns(r.ns_random),
        fmt_ns(r.ns_hard),
        fmt_e(r.random_max),
        fmt_e(r.random_median),
        fmt_e(r.hard_max),
        fmt_e(r.hard_median),
        f"{r.hard_over}/{r.hard_count}",
        r.worst if r.hard_max > BAR[r.precision] else "",
    ]


def print_table(rows, out=sys.stdout):
    cells = [HEADER] + [row_cells(r) for r in rows]
    widths = [max(len(c[i]) for c in cells) for i in range(len(HEADER) - 1)]
    for i, c in enumerate(cells):
        if i > 1 and c[0] != cells[i - 1][0]:
            print("", file=out)
        print(
            "  ".join(x.ljust(w) if j < 3 else x.rjust(w) for j, (x, w) in enumerate(zip(c, widths)))
            + ("  " + c[-1] if c[-1] else ""),
            file=out,
        )


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


def write_markdown(
    path, rows, best, stats, tied, other_precisions, cases, sweep_summary, runtime, n_random, kinds, compiled, min_time
):
    default = current_default()
    dbl = {(r.kind, r.policy): r for r in rows if r.precision == "double"}
    n_hard = sum(c.group == "hard" for c in cases)
    n_rand = sum(c.group == "random" for c in cases)
    s = stats[best]
    others = [p for p in POLICIES if p != best]
    lines = [
        "# Accuracy against time: root policies and precisions",
        "",
        "Generated by `python -m bench.accuracy_vs_time` (also run by `bash tools/run.sh bench`); do not edit",
        "by hand. Every distance query kind of the headers, with each root policy (`EigenCompanion`,",
        "`EigenPolished`, `Bracketing`, and `EigenPolynomialSolver`: Eigen's own solver as it is) in "
        "float, double and long double, on "
        f"{n_rand} seeded random cases ({n_random} per kind) and {n_hard} hard cases.",
        "",
        "## Headline",
        "",
    ]
    verdict = "the current `DefaultRoots`" if best == default else f"**not** the current `DefaultRoots` (`{default}`)"
    if len(tied) > 1:
        why = (
            f"{', '.join(f'`{p}`' for p in tied)} are equally accurate on the hard cases in double "
            f"(same number over the bar, max error within x2, mean log10 error within 0.1); `{best}` is "
            "the cheapest of them"
        )
    else:
        why = f"`{best}` is the most accurate policy on the hard cases in double"
    lines += [
        f"- **Recommended default: `{best}`** ({verdict}). {why}.",
        "",
        "| policy (double) | hard cases over 1e-12 | hard max error | hard mean log10 error | random over | "
        "random max error | ns/query random (geomean) | ns/query hard (geomean) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for p in POLICIES:
        o = stats[p]
        lines.append(
            f"| `{p}` | {o['hard_over']}/{o['hard_count']} | {fmt_e(o['hard_max'])} | "
            f"{o['hard_meanlog']:.2f} | {o['random_over']}/{o['random_count']} | {fmt_e(o['random_max'])} | "
            f"{o['ns_random']:.0f} | {o['ns_hard']:.0f} |"
        )
    ratio = {p: stats[p]["ns_random"] / stats[best]["ns_random"] for p in POLICIES}
    lines += [
        "",
        f"- Cost of the others relative to `{best}` (random cases): "
        + ", ".join(f"`{p}` x{ratio[p]:.2f}" for p in others)
        + ".",
    ]
    for prec in ("float", "longdouble"):
        ps = other_precisions[prec]
        lines.append(
            f"- {prec if prec == 'float' else 'long double'} (bar {BAR[prec]:.1e}): cases over the bar "
            + ", ".join(
                f"`{p}` {ps[p]['hard_over']} hard / {ps[p]['random_over']} random "
                f"(max {fmt_e(max(ps[p]['hard_max'], ps[p]['random_max']))})"
                for p in POLICIES
            )
            + "."
        )
    if s["failing_kinds"]:
        lines.append(f"- Even `{best}` misses the bar on: {', '.join(s['failing_kinds'])} (see the tables).")
    if sweep_summary:
        lines.append("- Stability sweeps (double, [stability_sweeps.png](stability_sweeps.png)): " + sweep_summary)
    missing = [k for k in KINDS if not compiled.get(k, False)]
    if missing:
        lines.append(f"- Kinds whose header is missing (not measured): {', '.join(missing)}.")
    lines += [
        "",
        "Relative error = |d - d_ref| / max(d_ref, largest radius of the query, an annulus's outer radius; for two",
        "Bezier curves the larger curve size, their control polygons' extent). The bar is 1e-12 in double;",
        "float and long double are judged against the same number of ulps of their own precision,",
        f"1e-12 eps_p / eps_double: {BAR['float']:.1e} for float, {BAR['longdouble']:.1e} for long double.",
        "The float inputs are the double cases rounded to float, and their references are those of the",
        "rounded inputs (so the error measures the solver, not the input rounding); the long double",
        "inputs are the doubles extended exactly and share the double references.",
        "",
        "References: 50-digit mpmath, by an independent method (circledist_cases/reference_linear_round.py and",
        "circledist_cases/reference_round.py): the distance is minimised over ONE parameter (an angle of a circle or",
        "the curve/line parameter) of a closed-form point-to-shape distance, by dense sampling and",
        "golden-section refinement; no polynomial and no root finding. Two Bezier curves",
        "(circledist_cases/reference_bezier.py): the four edges that way, the interior by 50-digit Newton",
        "descents from a grid's local minima, the best of them then minimised in one parameter along their",
        "valley (min over s of the distance from A(s) to B). Arcs (circledist_cases/reference_arc.py): the arc's",
        "angle against the other shape's closed-form point distance (the point-arc closed form for two arcs",
        "and a Bezier curve's t). Annuli (circledist_cases/reference_annulus.py): the other shape's parameter",
        "against the closed-form point-annulus distance; a disk or annulus against an annulus, each region's",
        "rims against the other region.",
        "",
        f"Timing: ns/query is the median over repeated passes (each ~2 ms, at least {min_time} s per",
        "kind x policy x precision x case set) of one single-threaded loop of `circledist::distance<Policy>`",
        "over the cases, compiled -O3 -DNDEBUG without -march=native. Absolute numbers depend on the",
        f"machine and its load (measured on a {os.cpu_count()}-core machine shared with other jobs); compare",
        "policies within a kind and precision rather than absolute values.",
        "",
        "## Double: time and worst error per kind",
        "",
    ]
    header = ["kind"] + [f"{p} ns" for p in POLICIES] + [f"{p} max err (random / hard)" for p in POLICIES]
    body = []
    for k in kinds:
        if (k, POLICIES[0]) not in dbl:
            continue
        body.append(
            [k]
            + [fmt_ns(dbl[(k, p)].ns_random) for p in POLICIES]
            + [f"{fmt_e(dbl[(k, p)].random_max)} / {fmt_e(dbl[(k, p)].hard_max)}" for p in POLICIES]
        )
    lines += [
        md_table(header, body),
        "",
        "![error against time](accuracy_vs_time.png)",
        "",
        "## Every kind x policy x precision",
        "",
        "ns random / ns hard: ns/query on the random / hard cases. `hard > bar`: hard cases over the",
        "precision's bar. The worst hard case is named where it is over the bar.",
        "",
    ]
    lines.append(md_table(HEADER, [row_cells(r) for r in rows]))
    lines += [
        "",
        "## Hard cases",
        "",
        "Linear shapes against the unit circle / disk in its own frame: tangent in the plane; tangent",
        "line lifted by 1e-3, 1e-6, 1e-9; line on the axis, offset from it by 1e-8 / 1e-12, tilted from it",
        "by 1e-8 / 1e-12; near-parallel to the plane (1e-9) at height 1e-3 and over the rim at 1e-6;",
        "crossing the plane on the rim and 1e-9 inside / outside it; in-plane lines; rays and segments",
        "around and starting at each of those, plus their own (starting on the rim, zero length, ...);",
        "points on the axis, the rim, near both. Circle / disk kinds: coplanar (disjoint, nested,",
        "crossing, touching), concentric, coaxial, linked, near-coplanar (tilt 1e-9), parallel 1e-9 apart,",
        "perpendicular touching, radius ratios 1e-6 / 1e6. Bezier kinds: straight curves tangent to the",
        "rim (lifted by 1e-9), along the axis, parabolas touching the disk, a wavy quintic, a degree-7",
        "curve; two curves: crossing, nearly touching (1e-9, 1e-13), tangent, nearly parallel, parallel",
        "and identical (continua), a big curve against a small one, degenerate (point, collinear) curves",
        "(circledist_cases/bezier_cases.py). Arcs (the unit circle's from +x over 3 pi / 2): the circle's",
        "scenes (several tangent to or crossing at its start end, or on its axis), lines tangent at either",
        "end (lifted by 1e-9), tangent 1e-9 past an end (the circle's closest point just off the arc),",
        "through both ends and through the gap; circles, disks and arcs touching an end, with an end on",
        "their axis, concentric and coaxial, linked through the gap, two arcs of one circle 1e-9 apart;",
        "selected scenes also against arcs of angle 2 pi - 1e-9, 2 pi (the circle) and pi / 2. Annuli",
        "(radii 0.5 and 1): the circle's scenes, lines along the axis through the hole, 1e-9 inside, on and",
        "outside the inner rim, crossing the plane in the hole; circles, disks and arcs in the hole",
        "(coplanar, concentric, lifted, perpendicular, 1e-9 from the inner rim), covering it, coplanar",
        "overlapping, concentric and stacked annuli; selected scenes also against inner radius 0 (the",
        "disk), = outer (the circle) and 1e-9 of outer. Each scene is used in the round shape's frame, "
        "under a generic rotation, and translated",
        "by 1e6 and 1e8 (both orientations); selected linear scenes also with the scene scaled by",
        "1e-9 / 1e9 and with the radius alone 1e-9 / 1e9 (those not translated: a radius of 1e-9 at 1e8,",
        "where the ulp is 1.5e-8, would ask for an absolute error below the rounding of the line's own",
        "closest point to the center, in any policy).",
        "",
        f"Script runtime: {runtime:.0f} s (references cached in build/accuracy_vs_time/ after the first run).",
        "",
    ]
    path.write_text("\n".join(lines))


POLICY_COLORS = {
    "EigenCompanion": "#1f77b4",
    "EigenPolished": "#d62728",
    "Bracketing": "#2ca02c",
    "EigenPolynomialSolver": "#9467bd",
}
PRECISION_MARKERS = {"float": "v", "double": "o", "longdouble": "s"}


def plot_accuracy(path, rows, kinds):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    kinds = [k for k in kinds if any(r.kind == k for r in rows)]
    ncol = 4
    nrow = (len(kinds) + 1 + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.4 * nrow), squeeze=False)
    for ax, kind in zip(axes.flat, kinds):
        for r in rows:
            if r.kind != kind:
                continue
            col = POLICY_COLORS[r.policy]
            mk = PRECISION_MARKERS[r.precision]
            for ns, err, filled in ((r.ns_random, r.random_max, False), (r.ns_hard, r.hard_max, True)):
                if not math.isfinite(ns):
                    continue
                y = err if math.isfinite(err) else 1.0
                ax.scatter(
                    [ns],
                    [max(y, ERROR_FLOOR)],
                    s=46,
                    marker=mk,
                    edgecolors=col,
                    facecolors=col if filled else "none",
                    linewidths=1.4,
                    zorder=3,
                )
        for prec, ls in (("float", ":"), ("double", "--"), ("longdouble", "-.")):
            ax.axhline(BAR[prec], color="0.45", lw=0.9, ls=ls, zorder=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(ERROR_FLOOR / 3, 3.0)
        ax.set_title(kind, fontsize=11)
        ax.grid(True, which="major", alpha=0.3)
        ax.tick_params(labelsize=8)
        ax.set_xlabel("ns / query", fontsize=9)
        ax.set_ylabel("max relative error", fontsize=9)
    legend_ax = axes.flat[len(kinds)]
    for ax in list(axes.flat)[len(kinds) :]:
        ax.axis("off")
    handles = [Line2D([], [], ls="", marker="o", color=c, label=p, markersize=8) for p, c in POLICY_COLORS.items()]
    handles += [
        Line2D([], [], ls="", marker=m, color="0.3", label=p if p != "longdouble" else "long double", markersize=8)
        for p, m in PRECISION_MARKERS.items()
    ]
    handles += [
        Line2D([], [], ls="", marker="o", color="0.3", label="hard cases (filled)", markersize=8),
        Line2D(
            [], [], ls="", marker="o", markerfacecolor="none", color="0.3", label="random cases (hollow)", markersize=8
        ),
    ]
    handles += [
        Line2D([], [], color="0.45", ls=ls, label=f"bar {p}")
        for p, ls in (("float", ":"), ("double", "--"), ("long double", "-."))
    ]
    legend_ax.legend(
        handles=handles,
        loc="center",
        fontsize=10,
        frameon=False,
        title=f"errors below {ERROR_FLOOR:.0e} drawn at it",
        title_fontsize=9,
    )
    fig.suptitle("circledist: max relative error against time, per kind x root policy x precision", fontsize=13)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ------------------------------------------------------------------------------------------------
# the stability sweeps (circledist_cases/sweeps.py): summaries and the plot
# ------------------------------------------------------------------------------------------------
def _members(cases, family):
    seen = []
    for c in cases:
        if c.family == family and c.member not in seen:
            seen.append(c.member)
    return seen


def summarize_failures(cases, errors, policies, bar):
    """errors[(index into cases, policy)] -> relative error. Returns {'lines': [...], 'summary': str}."""
    lines, fails = [], []
    for family in sweeps.FAMILIES:
        for member in _members(cases, family):
            idx = [i for i, c in enumerate(cases) if c.family == family and c.member == member]
            parts = []
            for pol in policies:
                errs = [(cases[i].k, errors[(i, pol)]) for i in idx]
                worst_k, worst = max(errs, key=lambda e: e[1])
                over = [k for k, e in errs if not e <= bar]
                parts.append(
                    f"{pol} max {fmt_e(worst)}"
                    + (f" (k={worst_k})" if worst > 0 else "")
                    + (f" OVER at k={','.join(map(str, over))}" if over else "")
                )
                if over:
                    fails.append(
                        f"{pol} on {family} / {member} at k = {','.join(map(str, over))} "
                        f"(max {fmt_e(worst)} at k={worst_k})"
                    )
            lines.append(f"{family} / {member}: " + "; ".join(parts))
    if fails:
        summary = "over the 1e-12 bar: " + "; ".join(fails) + "."
    else:
        summary = "every policy stays within the 1e-12 bar for every k of every family."
    return {"lines": lines, "summary": summary, "fails": fails}


MEMBER_STYLES = [("-", "o"), ("--", "s"), (":", "^"), ("-.", "D"), ((0, (5, 1, 1, 1, 1, 1)), "v")]


def plot_sweeps(path, cases, errors, policies, colors, bar):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    fams = [f for f in sweeps.FAMILIES if any(c.family == f for c in cases)]
    ncol = 2
    nrow = (len(fams) + 1) // 2
    fig, axes = plt.subplots(nrow, ncol, figsize=(7.2 * ncol, 4.8 * nrow), squeeze=False)
    offsets = {p: (j - (len(policies) - 1) / 2) * 0.12 for j, p in enumerate(policies)}
    for ax, fam in zip(axes.flat, fams):
        members = _members(cases, fam)
        for m_i, member in enumerate(members):
            ls, mk = MEMBER_STYLES[m_i % len(MEMBER_STYLES)]
            idx = [i for i, c in enumerate(cases) if c.family == fam and c.member == member]
            for pol in policies:
                ks = [cases[i].k + offsets[pol] for i in idx]
                ys = [errors[(i, pol)] for i in idx]
                ys = [max(y, ERROR_FLOOR) if math.isfinite(y) else 1.0 for y in ys]
                ax.plot(ks, ys, ls=ls, marker=mk, color=colors[pol], lw=1.2, ms=4.5, alpha=0.85)
        ax.axhline(bar, color="black", lw=1.0, ls="--")
        ax.text(0.01, bar * 2.5, "bar 1e-12", transform=ax.get_yaxis_transform(), fontsize=8)
        ax.set_yscale("log")
        ax.set_ylim(ERROR_FLOOR / 3, 10.0)
        title, xlabel, ks = sweeps.FAMILIES[fam]
        ax.set_xticks(list(ks))
        ax.set_xlabel(xlabel)
        ax.set_ylabel("relative error (double)")
        ax.set_title(f"{fam}: {title}", fontsize=11)
        ax.grid(True, alpha=0.3)
        handles = [
            Line2D(
                [],
                [],
                color="0.25",
                ls=MEMBER_STYLES[i % len(MEMBER_STYLES)][0],
                marker=MEMBER_STYLES[i % len(MEMBER_STYLES)][1],
                label=m,
            )
            for i, m in enumerate(members)
        ]
        handles += [Line2D([], [], color=colors[p], lw=3, label=p) for p in policies]
        ax.legend(handles=handles, fontsize=8, loc="upper left", ncol=2, framealpha=0.85)
    for ax in list(axes.flat)[len(fams) :]:
        ax.axis("off")
    fig.suptitle(
        "Stability sweeps toward degeneracies: |d - d_ref| / max(d_ref, largest radius), "
        f"errors below {ERROR_FLOOR:.0e} drawn at it",
        fontsize=12,
    )
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ------------------------------------------------------------------------------------------------
def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--random", type=int, default=40, help="random cases per kind (default 40)")
    ap.add_argument(
        "--min-time", type=float, default=0.05, help="seconds of timing per kind x policy x precision x set"
    )
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="processes for the references / compiling")
    ap.add_argument("--binary", help="use this accuracy_vs_time executable")
    ap.add_argument("--kinds", help="comma-separated subset of the kinds")
    ap.add_argument("--quick", action="store_true", help="10 random cases per kind, 0.01 s timings")
    ap.add_argument("--no-docs", action="store_true", help="print the table only; write no docs/reports/ files")
    args = ap.parse_args(argv)
    if args.quick:
        args.random, args.min_time = 10, 0.01
    t_start = time.time()

    binary = ensure_binary(args.binary, args.jobs)
    kinds = KINDS if not args.kinds else [k for k in args.kinds.split(",") if k in KINDS]
    # Kinds the program does not compile (missing header) are dropped before any reference work.
    probe = BUILD / "probe.txt"
    BUILD.mkdir(parents=True, exist_ok=True)
    probe.write_text("")
    subprocess.run([str(binary), str(probe), str(BUILD / "probe_out.txt"), "--min-time", "0"], check=True)
    compiled = {
        ln.split()[1]: ln.split()[2] == "1"
        for ln in (BUILD / "probe_out.txt").read_text().splitlines()
        if ln.startswith("K ")
    }
    kinds = [k for k in kinds if compiled.get(k)]

    cases = generate_cases(args.random, kinds)
    sweep_cases = sweeps.sweep_cases(kinds)
    all_cases = cases + [Case(sc.kind, "sweep", sc.label, sc.values, sc.exact) for sc in sweep_cases]
    needed = []
    for c in all_cases:
        if c.exact is None:
            needed.append((c.kind, c.values))
        if c.group != "sweep":
            needed.append((c.kind, to_float32(c.values)))
    refs = compute_references(needed, args.jobs)
    compiled, dist, timing = run_binary(binary, all_cases, args.min_time)
    errors = evaluate(all_cases, refs, dist)
    rows = summarize(all_cases, errors, timing, kinds)
    print()
    print_table(rows)
    best, stats, tied = recommend(rows, all_cases, errors)
    other_precisions = {p: policy_stats(rows, all_cases, errors, p) for p in ("float", "longdouble")}

    # Stability sweeps: error against k per policy (double).
    offset = len(cases)
    sweep_err = {}
    for j, sc in enumerate(sweep_cases):
        for pol in POLICIES:
            sweep_err[(j, pol)] = errors[(offset + j, pol, "double")]
    sweep_fail = summarize_failures(sweep_cases, sweep_err, POLICIES, DOUBLE_BAR)
    print()
    print(
        f"Recommended default: {best} (current DefaultRoots: {current_default()}; "
        f"equally accurate in double: {', '.join(tied)})"
    )
    for p in POLICIES:
        s = stats[p]
        print(
            f"  {p:15s} hard over bar {s['hard_over']}/{s['hard_count']}  hard max {fmt_e(s['hard_max'])}  "
            f"random over bar {s['random_over']}  ns (geomean random) {s['ns_random']:.0f}  hard {s['ns_hard']:.0f}"
        )
    print("Stability sweeps (double, bar 1e-12):")
    for line in sweep_fail["lines"]:
        print("  " + line)
    runtime = time.time() - t_start
    if not args.no_docs:
        DOCS.mkdir(exist_ok=True)
        plot_sweeps(DOCS / "stability_sweeps.png", sweep_cases, sweep_err, POLICIES, POLICY_COLORS, DOUBLE_BAR)
        plot_accuracy(DOCS / "accuracy_vs_time.png", rows, kinds)
        runtime = time.time() - t_start
        write_markdown(
            DOCS / "accuracy_vs_time.md",
            rows,
            best,
            stats,
            tied,
            other_precisions,
            all_cases,
            sweep_fail["summary"],
            runtime,
            args.random,
            kinds,
            compiled,
            args.min_time,
        )
        print("wrote docs/reports/accuracy_vs_time.md, accuracy_vs_time.png, stability_sweeps.png")
    print(f"runtime {runtime:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
