#!/usr/bin/env python3
"""Batches on several threads: the time of one batched call with workers=1 and with every core
(workers=-1), for 10^5 random queries of each dearer kind, and the speedup. Runs alternate
(1, all, 1, all, ...) and the medians are compared, so a slow spell of the machine falls on both.
Prints a markdown table and writes it, with the machine's description, to docs/reports/workers.md.

    python -m bench.bench_workers [--n 100000] [--repeats 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
import sys
from pathlib import Path

if not __package__:  # run as a file: its sibling one_core would not import
    sys.exit("bench/bench_workers.py: run it from the repository's root as python -m bench.bench_workers")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread, none spinning beside the workers)

import numpy as np

import circledist as cd
from .bench_queries import machine

ROOT = Path(__file__).resolve().parent.parent
REPORT = ROOT / "docs" / "reports" / "workers.md"
TARGET = 1.8  # speedup on 2 cores, batches of >= 10^5 queries of line-circle and dearer kinds


def shapes(kind, n, rng):
    if kind in ("Line", "Segment"):
        return getattr(cd, kind)(rng.normal(size=(n, 3)), rng.normal(size=(n, 3)))
    if kind in ("Circle", "Disk"):
        return getattr(cd, kind)(rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.5, 2, n))
    return cd.Bezier(rng.normal(size=(n, 4, 3)))


PAIRS = [
    ("Line", "Circle"),
    ("Segment", "Disk"),
    ("Circle", "Circle"),
    ("Circle", "Disk"),
    ("Disk", "Disk"),
    ("Bezier", "Disk"),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=100_000)
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args()
    rng = np.random.default_rng(20261125)
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    rows = []
    for a_kind, b_kind in PAIRS:
        n = args.n if a_kind != "Bezier" else args.n // 4
        a, b = shapes(a_kind, n, rng), shapes(b_kind, n, rng)
        for entry in (cd.distance, cd.closest_points):
            times = {1: [], -1: []}
            for _ in range(args.repeats):
                for workers in (1, -1):
                    start = time.perf_counter()
                    entry(a, b, workers=workers)
                    times[workers].append(time.perf_counter() - start)
            one, every = statistics.median(times[1]), statistics.median(times[-1])
            rows.append(
                (f"{a_kind.lower()}-{b_kind.lower()}", entry.__name__, n, one / n * 1e9, every / n * 1e9, one / every)
            )
    m = machine()
    lines = [
        "# Batches on several threads (workers=)",
        "",
        f"{m['model']}, {cores} usable cores; Python {m['python']}, "
        f"NumPy {m['numpy']}. Median of {args.repeats} alternating runs "
        f"of one batched call; `python -m bench.bench_workers` regenerates this file.",
        "",
        "| pair | entry | queries | ns/query, workers=1 | ns/query, workers=-1 | speedup |",
        "|---|---|---|---|---|---|",
    ]
    for pair, entry, n, one, every, speedup in rows:
        lines.append(f"| {pair} | {entry} | {n:,} | {one:.0f} | {every:.0f} | {speedup:.2f}x |")
    worst = min(r[-1] for r in rows)
    lines += [
        "",
        f"Smallest speedup {worst:.2f}x on {cores} cores (target on 2 cores: {TARGET}x): "
        f"{'met' if cores != 2 or worst >= TARGET else 'missed'}.",
    ]
    text = "\n".join(lines) + "\n"
    print(text)
    REPORT.write_text(text)


if __name__ == "__main__":
    main()
