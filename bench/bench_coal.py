"""Disk-disk against coal's GJK (the PyPI package coal, pip install ".[compare]"): the same seeded
random disk pairs, per call from Python and in C++, in one run. Prints the tables and writes
docs/reports/coal.md.

    python -m bench.bench_coal [--n 4000] [--repeats 7] [--no-cpp] [--no-write]

A disk in coal is a coal.Cylinder of height 0 (coal accepts it: radius r, half-length 0), placed
by a Transform3s whose rotation takes z to the disk's normal. Before anything is timed, coal's
distances at tolerance 1e-9 are checked to be those of disks: against circledist's on the same
pairs (the largest difference is printed; the check fails the run past 1e-6).

Rows, each a per-pair time over the same n pairs (thread CPU time, the least over the repeats of
a full pass; the rows' passes alternate within each repeat, so that a load that comes and goes
on a shared machine weighs on all alike):
  circledist scalar   cd.distance(a, b) on single Disk objects, in a Python loop
  circledist batch    one cd.distance(A, B) on Disk batches holding every pair, divided by n
  coal, tolerance T   coal.distance(s1, t1, s2, t2, request, result) in a Python loop, at the
                      DistanceRequest's default gjk_tolerance and at 1e-9 and 1e-12
and, for coal, the largest |coal - circledist| over the pairs (circledist's answers are exact
to 1e-12 of the scale: docs/derivations/disk_disk.md), and the calls that say colliding where
circledist's distance is positive, or separated where it is 0 (a negative coal distance is
its penetration depth, counted as colliding). Both sides pay a Python call per pair; the
batched row is circledist without it.

In C++ (bench/bench_coal.cpp, compiled here with the C++ compiler, -O3 -DNDEBUG as the package
is built, against circledist's headers and the headers and library that coal's wheel ships in
its cmeel prefix; build/bench_coal/, rebuilt when a source is newer): circledist::distance
against coal::distance on the same pairs, the same rows without Python, alternating passes in
one process. The target (circledist at most 0.7x coal's time at its default tolerance) is
judged there, where neither side's time is a Python call's.
"""

from __future__ import annotations

import argparse
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

if not __package__:  # run as a file: its sibling one_core would not import
    sys.exit("bench/bench_coal.py: run it from the repository's root as python -m bench.bench_coal")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread)

import numpy as np

import circledist as cd

ROOT = Path(__file__).resolve().parent.parent
REPORT = ROOT / "docs" / "reports" / "coal.md"
CPP_SOURCE = ROOT / "bench" / "bench_coal.cpp"
CPP_BINARY = ROOT / "build" / "bench_coal" / "bench_coal"
SEED = 20261129
TARGET = 0.7  # circledist's disk-disk time over coal's at its default tolerance
TOLERANCES = (None, 1e-9, 1e-12)  # None: the DistanceRequest's default
MODEL_TOLERANCE = 1e-9  # where coal's distances are checked to be the disks'; its 1e-12 runs are worse


def import_coal():
    try:
        import coal
    except ImportError:
        sys.exit('bench/bench_coal.py needs coal: pip install ".[compare]"')
    return coal


def disk_pairs(n, rng):
    """n pairs of disks: centers in [-2, 2]^3, random normals, radii in [0.2, 1.5] (about one
    pair in five intersects)."""

    def disks():
        return rng.uniform(-2, 2, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.2, 1.5, n)

    return disks(), disks()


def rotation_to(normal):
    """A rotation matrix whose third column is the unit normal (a disk's plane is coal's
    Cylinder's z = 0)."""
    w = normal / np.linalg.norm(normal)
    helper = np.array([1.0, 0.0, 0.0]) if abs(w[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(helper, w)
    u /= np.linalg.norm(u)
    return np.column_stack([u, np.cross(w, u), w])


def coal_shapes(coal, disks):
    centers, normals, radii = disks
    shapes = [coal.Cylinder(float(r), 0.0) for r in radii]
    placements = [coal.Transform3s(rotation_to(w), c.astype(float)) for c, w in zip(centers, normals)]
    return shapes, placements


def request_at(coal, tolerance):
    request = coal.DistanceRequest()
    if tolerance is not None:
        request.gjk_tolerance = tolerance
    return request


def thread_time():
    return time.thread_time()


def coal_prefix(coal):
    """The cmeel prefix of coal's wheel (include/coal, lib/libcoal.so), or None."""
    path = Path(coal.__file__).resolve()
    for parent in path.parents:
        if parent.name == "cmeel.prefix":
            return parent if (parent / "include" / "coal").is_dir() else None
    return None


def build_cpp(prefix):
    """bench_coal.cpp compiled against circledist's headers and coal's prefix (reused while no
    source is newer); the path, or None with the reason printed."""
    compiler = os.environ.get("CXX") or shutil.which("c++") or shutil.which("g++")
    if compiler is None:
        print("bench_coal: no C++ compiler: the C++ rows are left out")
        return None
    headers = list((ROOT / "cpp" / "include" / "circledist").rglob("*.hpp"))
    newest = max(p.stat().st_mtime for p in [CPP_SOURCE, *headers])
    if CPP_BINARY.exists() and CPP_BINARY.stat().st_mtime >= newest:
        return CPP_BINARY
    CPP_BINARY.parent.mkdir(parents=True, exist_ok=True)
    eigen = prefix / "include" / "eigen3"
    command = [
        compiler, "-std=c++17", "-O3", "-DNDEBUG", str(CPP_SOURCE), "-o", str(CPP_BINARY),
        "-I", str(ROOT / "cpp" / "include"), "-isystem", str(eigen), "-isystem", str(prefix / "include"),
        "-L", str(prefix / "lib"), "-lcoal", f"-Wl,-rpath,{prefix / 'lib'}",
    ]  # fmt: skip
    print("bench_coal: compiling bench/bench_coal.cpp (about a minute)")
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        print("bench_coal: the C++ comparison did not compile; its rows are left out:\n" + done.stderr[-2000:])
        return None
    return CPP_BINARY


def run_cpp(binary, a, b, repeats):
    """The C++ rows: {name: ns per pair} and {name: distances}, and coal's default tolerance."""
    n = len(a[2])
    values = np.concatenate([a[0], a[1], a[2][:, None], b[0], b[1], b[2][:, None]], axis=1).astype(float)
    with tempfile.TemporaryDirectory() as tmp:
        source, target = Path(tmp) / "pairs.bin", Path(tmp) / "distances.bin"
        source.write_bytes(struct.pack("<Q", n) + np.ascontiguousarray(values).tobytes())
        tolerances = ["0" if t is None else repr(t) for t in TOLERANCES]
        command = [str(binary), str(source), str(target), str(repeats), *tolerances]
        done = subprocess.run(command, capture_output=True, text=True, check=True)
        distances = np.fromfile(target, dtype="<f8").reshape(1 + len(TOLERANCES), n)
    lines = [line.split() for line in done.stdout.splitlines()]
    default_tolerance = float(lines[-1][1])
    names = ["circledist"] + [coal_label(t, default_tolerance) for t in TOLERANCES]
    ns = {name: float(line[1]) for name, line in zip(names, lines)}
    return ns, dict(zip(names, distances)), default_tolerance


def judged(answers, ours):
    """Per row: (max error against circledist's exact distances, wrongly colliding, wrongly
    separated)."""
    touching = ours == 0
    out = {}
    for name, d in answers.items():
        error = float(np.max(np.abs(np.maximum(d, 0) - ours)))
        out[name] = (error, int(np.count_nonzero((d <= 0) & ~touching)), int(np.count_nonzero((d > 0) & touching)))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=4000, help="disk pairs")
    parser.add_argument("--repeats", type=int, default=7, help="passes per row (the least is kept)")
    parser.add_argument("--no-cpp", action="store_true", help="leave out the C++ comparison")
    parser.add_argument("--no-write", action="store_true", help=f"do not write {REPORT.relative_to(ROOT)}")
    args = parser.parse_args(argv)
    coal = import_coal()

    rng = np.random.default_rng(SEED)
    a, b = disk_pairs(args.n, rng)
    batch_a, batch_b = cd.Disk(*a), cd.Disk(*b)
    ours = np.asarray(cd.distance(batch_a, batch_b), dtype=float)
    singles_a = [cd.Disk(a[0][i], a[1][i], float(a[2][i])) for i in range(args.n)]
    singles_b = [cd.Disk(b[0][i], b[1][i], float(b[2][i])) for i in range(args.n)]
    shapes_a, places_a = coal_shapes(coal, a)
    shapes_b, places_b = coal_shapes(coal, b)
    pairs = list(zip(shapes_a, places_a, shapes_b, places_b))
    default_tolerance = coal.DistanceRequest().gjk_tolerance

    def coal_pass(tolerance):
        request, result = request_at(coal, tolerance), coal.DistanceResult()
        out = np.empty(args.n)
        for i, (s1, t1, s2, t2) in enumerate(pairs):
            result.clear()
            out[i] = coal.distance(s1, t1, s2, t2, request, result)
        return out

    # coal's Cylinder of height 0 is the disk: at a tight tolerance its distances are ours.
    tight = coal_pass(MODEL_TOLERANCE)
    model_gap = float(np.max(np.abs(np.maximum(tight, 0) - ours)))
    if not model_gap <= 1e-6:
        sys.exit(f"bench_coal: coal's zero-height cylinders are {model_gap:.3g} off circledist's disks")

    def ours_scalar():
        out = np.empty(args.n)
        for i, (x, y) in enumerate(zip(singles_a, singles_b)):
            out[i] = cd.distance(x, y)
        return out

    def ours_batch():
        return np.asarray(cd.distance(batch_a, batch_b), dtype=float)

    rows = {"circledist scalar": ours_scalar, "circledist batch": ours_batch}
    for tolerance in TOLERANCES:
        rows[coal_label(tolerance, default_tolerance)] = lambda tolerance=tolerance: coal_pass(tolerance)
    best = {name: float("inf") for name in rows}
    answers = {}
    for _ in range(args.repeats):
        for name, fn in rows.items():
            t0 = thread_time()
            answers[name] = fn()
            best[name] = min(best[name], thread_time() - t0)
    ns = {name: 1e9 * t / args.n for name, t in best.items()}

    errors = judged(answers, ours)
    table = [(name, ns[name], *errors[name]) for name in rows]
    default_name = coal_label(None, default_tolerance)
    ratio_scalar = ns["circledist scalar"] / ns[default_name]
    ratio_batch = ns["circledist batch"] / ns[default_name]

    cpp = None
    prefix = None if args.no_cpp else coal_prefix(coal)
    if prefix is None and not args.no_cpp:
        print("bench_coal: coal's wheel has no C++ headers here: the C++ rows are left out")
    binary = build_cpp(prefix) if prefix is not None else None
    if binary is not None:
        cpp_ns, cpp_answers, _ = run_cpp(binary, a, b, args.repeats)
        if not np.array_equal(cpp_answers["circledist"], ours):
            sys.exit("bench_coal: circledist's C++ distances differ from its Python batch's")
        cpp_errors = judged(cpp_answers, ours)
        cpp_rows = [(name, cpp_ns[name], *cpp_errors[name]) for name in cpp_ns]
        cpp = (cpp_rows, cpp_ns["circledist"] / cpp_ns[default_name])

    text = report(args, table, ratio_scalar, ratio_batch, model_gap, int((ours == 0).sum()), cpp)
    print(text)
    if not args.no_write:
        REPORT.write_text(text)
        print(f"wrote {REPORT.relative_to(ROOT)}")
    return 0


def coal_label(tolerance, default_tolerance):
    if tolerance is None:
        return f"coal, default tolerance ({default_tolerance:g})"
    return f"coal, tolerance {tolerance:g}"


def table_lines(rows):
    lines = [
        "| call | ns per pair | max error | colliding, wrongly | separated, wrongly |",
        "| --- | ---: | ---: | ---: | ---: |",
    ]
    for name, ns, error, wrong_colliding, wrong_separated in rows:
        lines.append(f"| {name} | {ns:,.0f} | {error:.1e} | {wrong_colliding} | {wrong_separated} |")
    return lines


def report(args, table, ratio_scalar, ratio_batch, model_gap, touching, cpp):
    from importlib.metadata import version

    from bench.bench_queries import _busy, machine

    info = machine()

    lines = [
        "# Disk–disk against coal's GJK",
        "",
        "Written by `python -m bench.bench_coal` (bench/bench_coal.py and bench_coal.cpp; coal from the "
        f"`compare` extra). {args.n} seeded random disk pairs ({touching} of them touching or intersecting), "
        "every row on the same pairs in one run, per pair: thread CPU time, the least of "
        f"{args.repeats} passes, the rows' passes alternating.",
        "",
        "A disk in coal is a `coal.Cylinder(radius, 0)` (height 0, which coal accepts) placed by a "
        f"`Transform3s` taking z to the disk's normal. At tolerance {MODEL_TOLERANCE:g} coal's distances are "
        f"those of the disks: the largest difference from circledist's is {model_gap:.1e}.",
        "",
        "Error: the largest |coal − circledist| over the pairs, a negative coal distance (penetration) "
        "counted as 0; circledist's distances are exact to 1e-12 of the scene's scale "
        "([disk_disk.md](../derivations/disk_disk.md)). Wrong calls: pairs called colliding "
        "(distance ≤ 0) that are apart, and pairs called apart that touch.",
        "",
    ]
    if cpp is not None:
        cpp_rows, cpp_ratio = cpp
        verdict = "met" if cpp_ratio <= TARGET else "not met"
        lines += [
            "## In C++",
            "",
            "`circledist::distance(a, b)` against `coal::distance` (bench_coal.cpp, -O3 -DNDEBUG, coal's "
            "library from its wheel), each in a loop over the pairs.",
            "",
            *table_lines(cpp_rows),
            "",
            f"circledist over coal at its default tolerance: **{cpp_ratio:.2f}×** (target ≤ {TARGET}×: {verdict}).",
            "",
        ]
    lines += [
        "## From Python",
        "",
        "Both libraries called once per pair from a Python loop (the scalar rows: each pays a Python "
        "call); the batch row is one circledist call over every pair.",
        "",
        *table_lines(table),
        "",
        f"circledist's scalar call over coal's at its default tolerance: **{ratio_scalar:.2f}×**; "
        f"the batched call: **{ratio_batch:.2f}×**.",
        "",
        f"Machine: {info['model']}, {info['cores']} cores ({info['usable']} usable)"
        + (", shared with other work during the run" if _busy(info["load"], info["usable"]) else "")
        + f"; Python {info['python']}, NumPy {info['numpy']}, coal {version('coal')}, "
        f"circledist {version('circledist')}.",
        "",
    ]
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main())
