"""Building scenes: the command line's read, check and answer, and write_scene, on a
JSON file of n single entries of every kind (no batches); the command line end to end (a process
of its own, imports and output included); and Scene.add of single shapes, one by one, at a few
scene sizes, and Scene.extend of one large batch.

Prints the seconds of each step and the machine; writes nothing but temporary files.

    python -m bench.bench_scene_file [--n 200000] [--adds 1000 10000 100000] [--batch 1000000]

Each step prints its wall time and its CPU time (this process's and, for the command line, its
child's): on a shared machine the CPU time is the steadier figure.
"""

import argparse
import json
import os
import platform
import random
import resource
import subprocess
import sys
import tempfile
import time

if not __package__:  # run as a file: its sibling one_core would not import
    sys.exit("bench/bench_scene_file.py: run it from the repository's root as python -m bench.bench_scene_file")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread)

import numpy as np

import circledist as cd
from circledist._cli_answer import answer
from circledist._cli_present import table


def scene_document(n, seed=7):
    """n single shapes, the kinds in turn, in a cube whose side keeps the density fixed."""
    rng = random.Random(seed)
    side = 2.0 * n ** (1 / 3)

    def v():
        return [round(rng.uniform(-side / 2, side / 2), 6) for _ in range(3)]

    def direction():
        while True:
            x = [round(rng.gauss(0, 1), 6) for _ in range(3)]
            if any(x):
                return x

    shapes = []
    for i in range(n):
        name, p = f"s{i}", v()
        kind = ("circle", "disk", "segment", "point", "bezier", "line", "ray")[i % 7]
        spec = {"name": name, "kind": kind}
        if kind in ("circle", "disk"):
            spec.update(center=p, normal=direction(), radius=round(rng.uniform(0.2, 1), 4))
        elif kind == "segment":
            spec.update(p0=p, p1=[x + rng.uniform(-1, 1) for x in p], sweep=0.01)
        elif kind == "point":
            spec.update(p=p, sweep=0.1)
        elif kind == "bezier":
            spec.update(control_points=[p, [x + 0.5 for x in p], [x + 1 for x in p]])
        else:
            spec.update(origin=p, direction=direction())
        shapes.append(spec)
    queries = [
        {"a": "s0", "effects": ["nearest"], "k": 3},
        {"a": "s1", "b": "s2", "effects": ["distance"]},
        {"a": "s0", "effects": ["within"], "d": 0.5},
        {"a": "s1", "effects": ["intersects"]},
    ]
    return {"format": "circledist-scene", "version": 1, "shapes": shapes, "queries": queries}


def clock():
    """(wall seconds, CPU seconds of this process and its finished children): on a shared machine
    the CPU seconds are the steadier figure."""
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.perf_counter(), time.process_time() + children.ru_utime + children.ru_stime


def report(label, start, per=1, unit="s"):
    """Prints the wall and CPU time since `start` (a clock()), divided by `per`, in s or us."""
    wall, cpu = (b - a for a, b in zip(start, clock()))
    scale = 1e6 if unit == "us" else 1.0
    print(f"{label:<58} {wall / per * scale:8.2f} {unit} wall {cpu / per * scale:8.2f} {unit} CPU")


def machine():
    try:
        with open("/proc/cpuinfo") as f:
            model = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        model = platform.processor() or platform.machine()
    return f"{model}, {os.cpu_count()} logical cores, Python {platform.python_version()}"


def scene_building(sizes, batch, seed=11):
    """Scene.add one by one (microseconds per call, and the hierarchy's first build after the
    adds) at each size, then Scene.extend of one batch of `batch` disks and its build."""
    rng = np.random.default_rng(seed)
    for n in sizes:
        side = 2.0 * n ** (1 / 3)
        centers, normals = rng.uniform(-side / 2, side / 2, (n, 3)), rng.normal(size=(n, 3))
        radii = rng.uniform(0.2, 1, n)
        disks = [cd.Disk(centers[i], normals[i], radii[i]) for i in range(n)]
        names = [f"d{i}" for i in range(n)]
        scene = cd.Scene()
        start = clock()
        for name, disk in zip(names, disks):
            scene.add(name, disk)
        report(f"Scene.add, {n:,} disks one by one, per add", start, per=n, unit="us")
        start = clock()
        scene._build()
        report("  then the first query's build (arrays, hierarchy)", start)
    if batch:
        side = 2.0 * batch ** (1 / 3)
        disks = cd.Disk(
            rng.uniform(-side / 2, side / 2, (batch, 3)), rng.normal(size=(batch, 3)), rng.uniform(0.2, 1, batch)
        )
        scene = cd.Scene()
        start = clock()
        scene.extend("d", disks)
        report(f"Scene.extend, a batch of {batch:,} disks", start)
        start = clock()
        scene._build()
        report("  then the first query's build (arrays, hierarchy)", start)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=200_000)
    ap.add_argument(
        "--adds",
        type=int,
        nargs="*",
        default=[1000, 10_000, 100_000],
        help="scene sizes at which to time Scene.add one by one",
    )
    ap.add_argument("--batch", type=int, default=1_000_000, help="the size of the Scene.extend batch (0: none)")
    args = ap.parse_args()
    print(f"circledist from {os.path.dirname(cd.__file__)}; {machine()}")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "scene.json")
        with open(path, "w") as f:
            json.dump(scene_document(args.n), f, indent=1)
        print(f"{args.n:,} single shapes, {os.path.getsize(path) / 1e6:.1f} MB of JSON")
        start = clock()
        run = subprocess.run([sys.executable, "-m", "circledist", path], capture_output=True, text=True)
        if run.returncode != 0:
            raise SystemExit(f"the command line failed: {run.stderr}")
        report("python -m circledist scene.json (a process of its own)", start)
        start = clock()
        scene = cd.read_scene(path)
        report("  in this process: read_scene (parse, schema, checks)", start)
        start = clock()
        table(scene, answer(scene))
        report("  in this process: answer (Scene built, queries), table", start)
        start = clock()
        shapes = scene.shapes
        report("SceneFile.shapes (a library shape per entry)", start)
        start = clock()
        cd.write_scene(os.path.join(tmp, "again.json"), shapes, scene.queries_as_written())
        report("write_scene of those shapes (JSON, checked)", start)
    scene_building(args.adds, args.batch)


if __name__ == "__main__":
    main()
