#!/usr/bin/env python3
"""Moving shapes: distance evaluations per first_contact and per closest_approach, and their cost
relative to one static distance, for random moving pairs of every kind. Each query is run alone
to count its evaluations (cd.stats()); the cost is the time of one batched call over all the
pairs against a batched static distance of the same pairs, run alternately (median of the
repeats), so that a slow spell of the machine falls on both. Writes docs/reports/motion.md whole.

    python -m bench.bench_motion [--n 60] [--repeats 3]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

if not __package__:  # run as a file: its sibling one_core would not import
    sys.exit("bench/bench_motion.py: run it from the repository's root as python -m bench.bench_motion")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread)

import numpy as np

import circledist as cd
from circledist_cases.shapes import random_fields
from .bench_queries import machine

ROOT = Path(__file__).resolve().parent.parent
REPORT = ROOT / "docs" / "reports" / "motion.md"
TARGET = 20  # static distances per first_contact on the median random pair (the aim)


def kinds():
    return sorted({k for pair in cd._core._query_kinds() for k in pair})


def moving_pairs(first, second, n, rng):
    """n random pairs of the two kinds (unit-sized: fields standard normal, radii in [0.2, 2)),
    the second moved 5 along x; each turning (lines and rays only translate) and the first aimed
    at the second (its first point field meets the other's about mid-way, give or take 0.3), so
    that many touch."""
    a = getattr(cd, first)(**random_fields(cd, first, rng, batch=(n,)))
    b = getattr(cd, second)(**random_fields(cd, second, rng, batch=(n,)))
    b = b.moved(cd.Motion(translation=[5, 0, 0]), 1.0)

    def rotation(kind):
        return np.zeros((n, 3)) if kind in ("Line", "Ray") else rng.normal(size=(n, 3)) * 2

    def a_point(shape):
        return np.asarray(next(iter(shape.to_arrays().values())), dtype=float).reshape(n, -1, 3)[:, 0]

    turn_a = cd.Motion(rotation=rotation(first), center=rng.normal(size=(n, 3)))
    mb = cd.Motion(rotation=rotation(second), center=rng.normal(size=(n, 3)))
    aim = 2 * (a_point(b.moved(mb, 0.5)) - a_point(a.moved(turn_a, 0.5))) + rng.normal(size=(n, 3)) * 0.3
    ma = cd.Motion(translation=aim, rotation=turn_a.rotation, center=turn_a.center)
    return a, b, ma, mb


def one(shape, i):
    """Element i of a batch (batch shape (n,), n > 3), as a single shape."""
    n = shape.batch_shape[0]
    arrays = {k: (v[i] if np.ndim(v) and np.shape(v)[0] == n else v) for k, v in shape.to_arrays().items()}
    return type(shape)(**arrays)


def one_motion(m, i):
    """Element i of a batch of motions (a field of one motion serves every element)."""
    fields = {k: np.asarray(v).reshape(-1, 3) for k, v in m.to_arrays().items()}
    return cd.Motion(**{k: v[i % len(v)] for k, v in fields.items()})


def counts(query, a, b, ma, mb, n):
    out = []
    for i in range(n):
        cd.reset_stats()
        query(one(a, i), one(b, i), one_motion(ma, i), one_motion(mb, i))
        out.append(cd.stats()["distances"])
    return np.array(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=60)
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    rng = np.random.default_rng(20261129)
    names = kinds()
    rows = []
    pooled = ([], [])  # every pair's evaluations, first_contact and closest_approach
    for i, first in enumerate(names):
        for second in names[i:]:
            a, b, ma, mb = moving_pairs(first, second, args.n, rng)
            still_a, still_b = a.moved(ma, 0.0), b.moved(mb, 0.0)
            contact = counts(cd.first_contact, a, b, ma, mb, args.n)
            approach = counts(cd.closest_approach, a, b, ma, mb, args.n)
            pooled[0].extend(contact)
            pooled[1].extend(approach)
            touched = float(np.isfinite(cd.first_contact(a, b, ma, mb).time).mean())
            times = {"static": [], "contact": [], "approach": []}
            for _ in range(args.repeats):
                for name, call in (
                    ("static", lambda: cd.distance(still_a, still_b)),
                    ("contact", lambda: cd.first_contact(a, b, ma, mb)),
                    ("static", lambda: cd.distance(still_a, still_b)),
                    ("approach", lambda: cd.closest_approach(a, b, ma, mb)),
                ):
                    start = time.perf_counter()
                    call()
                    times[name].append(time.perf_counter() - start)
            static = statistics.median(times["static"])
            rows.append(
                (
                    f"{first.lower()}-{second.lower()}",
                    touched,
                    float(np.median(contact)),
                    int(contact.max()),
                    statistics.median(times["contact"]) / static,
                    float(np.median(approach)),
                    int(approach.max()),
                    statistics.median(times["approach"]) / static,
                )
            )
    m = machine()
    contact_costs = [r[4] for r in rows]
    median_cost = float(np.median(contact_costs))
    lines = [
        "# Moving shapes: first_contact and closest_approach",
        "",
        f"{m['model']}; Python {m['python']}, NumPy {m['numpy']}. For each pair of kinds, {args.n} random "
        "moving pairs (unit-sized shapes, each turning about a random center at up to a few "
        "radians, the first's first point field (a center, an origin, an end) aimed at the "
        "second's, so that many touch, as the contacts column counts; lines and rays translate "
        "only). Evaluations: the exact distances one query evaluates, run alone (median and "
        "largest over the pairs). Cost: one batched call over the pairs against a batched static "
        "distance of the same pairs (at t = 0), median of "
        f"{args.repeats} alternating runs: the query's price in static distances, evaluations "
        "and the closest points at the answer included. `python -m bench.bench_motion` "
        "regenerates this file.",
        "",
        "| pair | contacts | first_contact evaluations, median | largest | cost (static distances) "
        "| closest_approach evaluations, median | largest | cost (static distances) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for pair, touched, cm, cx, cc, am, ax, ac in rows:
        lines.append(f"| {pair} | {touched:.0%} | {cm:.0f} | {cx} | {cc:.1f} | {am:.0f} | {ax} | {ac:.1f} |")
    worst_contact = sorted(rows, key=lambda r: -r[4])[:3]
    worst_approach = sorted(rows, key=lambda r: -r[7])[:3]
    lines += [
        "",
        f"first_contact on the median pair of kinds: {median_cost:.1f} static distances (aim: at most "
        f"{TARGET}): {'met' if median_cost <= TARGET else 'missed'}. Dearest families: "
        + ", ".join(f"{r[0]} ({r[4]:.1f})" for r in worst_contact)
        + ". closest_approach dearest: "
        + ", ".join(f"{r[0]} ({r[7]:.0f})" for r in worst_approach)
        + f"; on the median pair of kinds {float(np.median([r[7] for r in rows])):.0f} static distances.",
        "",
        f"Over all {len(pooled[0])} random pairs: the median first_contact evaluates "
        f"{float(np.median(pooled[0])):.0f} distances (the largest {int(np.max(pooled[0]))}), the median "
        f"closest_approach {float(np.median(pooled[1])):.0f} (the largest {int(np.max(pooled[1]))}). An "
        "evaluation costs more than a static distance by the moving of both shapes (a rotation "
        "each), which the cost columns include.",
    ]
    text = "\n".join(lines) + "\n"
    print(text)
    REPORT.write_text(text)


if __name__ == "__main__":
    main()
