"""All-pairs queries on the C++ broadphase: cd.pairs_within and Scene.pairs_within over 10^5
rings and 10^5 segments, against the NumPy Scene they replace (commit 9ae4333's scene.py, run on
this build's module) and against brute force; one and two workers; Scene build times.

Prints the numbers and writes docs/reports/pairs.md.

    python -m bench.bench_pairs [--n 100000] [--side 17] [--repeats 3] [--large 1000000] [--no-old] [--no-write]
"""

import argparse
import os
import platform
import resource
import subprocess
import sys
import time
import types

if not __package__:  # run as a file: its sibling one_core would not import
    sys.exit("bench/bench_pairs.py: run it from the repository's root as python -m bench.bench_pairs")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread)

import numpy as np

import circledist as cd

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
DOCS = os.path.join(ROOT, "docs", "reports")
OLD_COMMIT = "9ae4333"  # the last commit with the NumPy Scene


def rings_and_segments(n, side, rng):
    """n rings (radius 0.05 to 0.3, random normals) and n segments (each coordinate of p1 - p0
    normal with deviation 0.3) in a cube of the given side."""
    rings = cd.Circle(rng.uniform(0, side, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.05, 0.3, n))
    p0 = rng.uniform(0, side, (n, 3))
    segments = cd.Segment(p0, p0 + rng.normal(scale=0.3, size=(n, 3)))
    return rings, segments


def timed(fn, repeats):
    """(median time, the last result, stats of the last run)."""
    times, result, counters = [], None, None
    for _ in range(repeats):
        cd.reset_stats()
        t = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t)
        counters = cd.stats()
    return float(np.median(times)), result, counters


def old_scene_module():
    """The Scene of commit 9ae4333 (a NumPy bounding-volume hierarchy), on this build's _core."""
    try:
        text = subprocess.run(
            ["git", "show", f"{OLD_COMMIT}:python/circledist/scene.py"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
        ).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    module = types.ModuleType("circledist_old_scene")
    exec(
        compile(text.replace("from . import _core", "from circledist import _core"), "old_scene.py", "exec"),
        module.__dict__,
    )
    return module


def scene_of(cls, rings, segments):
    s = cls()
    s.extend("ring", rings)
    s.extend("seg", segments)
    return s


def single_adds(cls, n, rng):
    """Seconds for n single Scene.add calls, then for the first query (the hierarchy's build)."""
    centers = rng.uniform(0, 100, (n, 3))
    shapes = [cd.Circle(centers[i], [0, 0, 1], 0.5) for i in range(n)]
    names = [f"ring{i}" for i in range(n)]
    scene = cls()
    t = time.perf_counter()
    for name, shape in zip(names, shapes):
        scene.add(name, shape)
    adds = time.perf_counter() - t
    t = time.perf_counter()
    scene.nearest([50.0, 50.0, 50.0])
    first = time.perf_counter() - t
    return adds, first


def large_run(n, side, d):
    """One cd.pairs_within over n rings x n segments in a process of its own: (time, pairs, peak
    memory in MB, memory of the inputs in MB)."""
    out = subprocess.run(
        [sys.executable, "-m", "bench.bench_pairs", "--pairs-only", "--n", str(n), "--side", str(side), "--d", str(d)],
        capture_output=True,
        text=True,
        check=True,
        cwd=ROOT,
    ).stdout.split()
    return float(out[0]), int(out[1]), float(out[2]), float(out[3])


def peak_mb():
    """This process's peak resident memory (VmHWM: ru_maxrss would carry the parent's peak over
    from before the exec)."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def pairs_only(n, side, d):
    rings, segments = rings_and_segments(n, side, np.random.default_rng(2026))
    inputs = peak_mb()
    t = time.perf_counter()
    i, _, _ = cd.pairs_within(rings, segments, d)
    t = time.perf_counter() - t
    print(t, len(i), peak_mb(), inputs)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=100_000, help="rings, and segments")
    ap.add_argument("--side", type=float, default=17.0, help="the cube's side (17: about 10^5 pairs at d = 0.05)")
    ap.add_argument("--d", type=float, default=0.05)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--adds", type=int, nargs="+", default=[10_000, 100_000, 1_000_000])
    ap.add_argument("--large", type=int, default=1_000_000, help="rings and segments of the large run (0: none)")
    ap.add_argument("--pairs-only", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--no-old", action="store_true", help="skip the old NumPy Scene")
    ap.add_argument("--no-write", action="store_true", help="print only")
    args = ap.parse_args()
    if args.pairs_only:
        return pairs_only(args.n, args.side, args.d)
    load = os.getloadavg()
    rng = np.random.default_rng(2026)
    rings, segments = rings_and_segments(args.n, args.side, rng)
    lines = []

    def say(text=""):
        print(text, flush=True)
        lines.append(text)

    # 1. cd.pairs_within(rings, segments, d) on 1 and 2 workers.
    say(f"## cd.pairs_within: {args.n:,} rings x {args.n:,} segments, d = {args.d:g}, cube side {args.side:g}")
    say()
    say("| call | workers | time | pairs found | distances evaluated | polynomial solves |")
    say("|---|---|---|---|---|---|")
    runs = {}
    for workers in (1, 2):
        t, (i, j, dist), s = timed(lambda: cd.pairs_within(rings, segments, args.d, workers=workers), args.repeats)
        runs[workers] = (t, i, j, dist)
        say(
            f"| `cd.pairs_within(rings, segments, {args.d:g})` | {workers} | {t:.3f} s | {len(i):,} | "
            f"{s['distances']:,} | {s['solves']:,} |"
        )
    same = all(np.array_equal(a, b) for a, b in zip(runs[1][1:], runs[2][1:]))
    say()
    say(
        f"Speed-up on 2 workers: {runs[1][0] / runs[2][0]:.2f}x; the answers of 1 and 2 workers are "
        f"{'identical' if same else 'DIFFERENT'}. Brute force would evaluate {args.n * args.n:,} distances."
    )
    say()
    # A control for what the machine gives a second thread right now: one batched distance call
    # (docs/reports/workers.md), and the process's CPU time against wall time.
    control_a = cd.Circle(rings.center[:, None][:1000], rings.normal[:1000, None], rings.radius[:1000, None])
    control_b = cd.Segment(segments.p0[:1000], segments.p1[:1000])
    control = {}
    for workers in (1, 2):
        c0 = time.process_time()
        t, _, _ = timed(lambda: cd.distance(control_a, control_b, workers=workers), args.repeats)
        control[workers] = (t, (time.process_time() - c0) / args.repeats / t)
    say(
        f"Control, the machine's second core at the time: `cd.distance` over 10^6 ring-segment pairs took "
        f"{control[1][0]:.3f} s on 1 worker and {control[2][0]:.3f} s on 2 ({control[1][0] / control[2][0]:.2f}x; "
        f"CPU time / wall time {control[2][1]:.2f} on 2 workers)."
    )
    say()

    # 1b. cd.nearest(rings, segments) on 1 and 2 workers.
    say(f"## cd.nearest: the nearest of {args.n:,} segments to each of {args.n:,} rings")
    say()
    say("| call | workers | time | distances evaluated |")
    say("|---|---|---|---|")
    near = {}
    for workers in (1, 2):
        t, (idx, dist), s = timed(lambda: cd.nearest(rings, segments, k=1, workers=workers), args.repeats)
        near[workers] = (t, idx, dist)
        say(f"| `cd.nearest(rings, segments, k=1)` | {workers} | {t:.3f} s | {s['distances']:,} |")
    same = all(np.array_equal(a, b) for a, b in zip(near[1][1:], near[2][1:]))
    say()
    say(
        f"Speed-up on 2 workers: {near[1][0] / near[2][0]:.2f}x; the answers of 1 and 2 workers are "
        f"{'identical' if same else 'DIFFERENT'}."
    )
    say()

    # 2. Scene.pairs_within over all 2n shapes (ring-ring, segment-segment and ring-segment pairs,
    #    decided by cd.within): the new Scene, then the old one.
    say(f"## Scene.pairs_within({args.d:g}) over the same {2 * args.n:,} shapes")
    say()
    say("| Scene | workers | extend (2 batches) | pairs_within (hierarchy built on the first) | pairs |")
    say("|---|---|---|---|---|")
    new = {}
    for workers in (1, 2):
        # A scene of its own for each count: its first query builds the hierarchy on its workers.
        t_build, scene, _ = timed(lambda: scene_of(cd.Scene, rings, segments), 1)
        t, pairs, _ = timed(lambda s=scene: s.pairs_within(args.d, workers=workers), 1)
        new[workers] = (t, pairs)
        say(f"| C++ broadphase (this commit) | {workers} | {t_build:.3f} s | {t:.3f} s | {len(pairs):,} |")
        del scene
    old_module = None if args.no_old else old_scene_module()
    if old_module is not None:
        t_old_build, old_scene, _ = timed(lambda: scene_of(old_module.Scene, rings, segments), 1)
        t_old, old_pairs, _ = timed(lambda: old_scene.pairs_within(args.d), 1)
        say(f"| NumPy ({OLD_COMMIT}) | 1 | {t_old_build:.3f} s | {t_old:.3f} s | {len(old_pairs):,} |")
        say()
        say(
            f"Same pairs as the NumPy Scene: {'yes' if old_pairs == new[1][1] else 'NO'}. "
            f"Speed-up on one core: {t_old / new[1][0]:.1f}x; on two workers: {t_old / new[2][0]:.1f}x. "
            f"Speed-up of 2 workers over 1: {new[1][0] / new[2][0]:.2f}x; their pairs are "
            f"{'identical' if new[1][1] == new[2][1] else 'DIFFERENT'}."
        )
    else:
        say()
        say(
            f"Speed-up on 2 workers: {new[1][0] / new[2][0]:.2f}x; the pairs of 1 and 2 workers are "
            f"{'identical' if new[1][1] == new[2][1] else 'DIFFERENT'}."
        )
        say()
        say(
            "The NumPy Scene was not run (--no-old, or no git history): its documented figure for this query "
            "is 4 to 5.5 s (measured on a scene of its own)."
        )
    say()

    # 2b. Large: the same density of pairs with 10x the shapes, in a process of its own.
    if args.large:
        side = args.side * (args.large / args.n) ** (1 / 3)  # 10x the shapes, 10x the pairs
        t, found, peak, inputs = large_run(args.large, round(side, 2), args.d)
        say(f"## cd.pairs_within: {args.large:,} rings x {args.large:,} segments (cube side {side:.2f}), one worker")
        say()
        say(
            f"{found:,} pairs in {t:.2f} s; peak memory {peak:,.0f} MB, of which the inputs (the two batches and "
            f"the interpreter) {inputs:,.0f} MB."
        )
        say()

    # 3. Where pairs_within beats the full distance matrix.
    say("## cd.pairs_within against brute force (the full distance matrix, then `<= d`), one worker")
    say()
    say("| rings x segments | brute force | pairs_within | speed-up |")
    say("|---|---|---|---|")
    for m in (100, 300, 1000, 3000):
        side = args.side * (m / args.n) ** (1 / 3)  # the same density
        r, s_ = rings_and_segments(m, side, np.random.default_rng(m))
        column = cd.Circle(r.center[:, None], r.normal[:, None], r.radius[:, None])

        def brute():
            matrix = cd.distance(column, s_)
            i, j = np.nonzero(matrix <= args.d)
            return i, j, matrix[i, j]

        t_b, ref, _ = timed(brute, args.repeats)
        t_p, got, _ = timed(lambda: cd.pairs_within(r, s_, args.d), args.repeats)
        assert all(np.array_equal(a, b) for a, b in zip(ref, got))
        say(f"| {m:,} x {m:,} | {t_b * 1e3:.2f} ms | {t_p * 1e3:.2f} ms | {t_b / t_p:.1f}x |")
    say()

    # 4. Building a scene by single adds.
    say("## Scene build: n single `Scene.add` calls, then the first query (which builds the hierarchy)")
    say()
    say("| adds | Scene.add, all | per add | first query |")
    say("|---|---|---|---|")
    for n in args.adds:
        adds, first = single_adds(cd.Scene, n, np.random.default_rng(n))
        say(f"| {n:,} | {adds:.2f} s | {adds / n * 1e6:.1f} us | {first:.2f} s |")
    if old_module is not None:
        n = 10_000
        adds, first = single_adds(old_module.Scene, n, np.random.default_rng(n))
        say(f"| {n:,} (NumPy Scene, {OLD_COMMIT}) | {adds:.2f} s | {adds / n * 1e6:.1f} us | {first:.2f} s |")
    say()
    peak = peak_mb()
    say("Peak memory of the whole run (the NumPy Scene's pairs_within and the 10^6 single shapes made for")
    say(f"the adds among it): {peak:,.0f} MB.")

    if args.no_write:
        return
    machine = (
        f"AMD EPYC, 2 cores ({platform.processor() or platform.machine()}, {os.cpu_count()} logical), "
        f"Python {platform.python_version()}, NumPy {np.__version__}"
    )
    md = (
        [
            "# All-pairs queries: measurements",
            "",
            "Generated by `python -m bench.bench_pairs` (re-run it to refresh this page).",
            "",
            f"Machine: {machine}."
            + (
                " The machine was **shared with other builds and test runs** while this ran: times are those of"
                if load[0] > 0.5 * (os.cpu_count() or 1)
                else " Times on an otherwise idle machine;"
            ),
            "a busy machine, and the 2-worker rows say little about two idle cores (the"
            if load[0] > 0.5 * (os.cpu_count() or 1)
            else "the 2-worker rows show what a second core gives (the",
            "control row below shows what a second thread got at the time). Median of",
            f"{args.repeats} runs where a table does not say otherwise; the Scene rows are one run. The NumPy Scene is",
            f"the code of {OLD_COMMIT} run on this build's module, on the same machine at the same time (4 to",
            "5.5 s were measured for its query on a scene of its own).",
            "",
            "`cd.pairs_within` returns the pairs with `distance <= d` (the distances to the bit);",
            "`Scene.pairs_within` the pairs for which `cd.within` holds, over every pair of the scene's shapes",
            "(ring-ring and segment-segment pairs too), so the two counts differ.",
            "",
        ]
        + lines
        + [""]
    )
    with open(os.path.join(DOCS, "pairs.md"), "w") as f:
        f.write("\n".join(md))
    print("wrote docs/reports/pairs.md")


if __name__ == "__main__":
    main()
