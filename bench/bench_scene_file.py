"""Scene files of many single shapes: the command line's read, check and answer, and
write_scene, on a JSON file of n single entries of every kind (no batches).

Prints the seconds of each step; writes nothing but a temporary file.

    python bench/bench_scene_file.py [--n 200000]
"""

import argparse
import json
import os
import random
import tempfile
import time

import one_core  # noqa: F401  (before NumPy: one BLAS thread)

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
    queries = [{"a": "s0", "effects": ["nearest"], "k": 3}, {"a": "s1", "b": "s2", "effects": ["distance"]},
               {"a": "s0", "effects": ["within"], "d": 0.5}, {"a": "s1", "effects": ["intersects"]}]
    return {"format": "circledist-scene", "version": 1, "shapes": shapes, "queries": queries}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=200_000)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "scene.json")
        with open(path, "w") as f:
            json.dump(scene_document(args.n), f, indent=1)
        print(f"{args.n} single shapes, {os.path.getsize(path) / 1e6:.1f} MB of JSON")
        t0 = time.perf_counter()
        scene = cd.read_scene(path)
        t1 = time.perf_counter()
        queries = answer(scene)
        table(scene, queries)
        t2 = time.perf_counter()
        print(f"read_scene (parse, schema, checks): {t1 - t0:6.2f} s")
        print(f"answer (Scene built, queries):      {t2 - t1:6.2f} s")
        print(f"the command line's work in all:     {t2 - t0:6.2f} s")
        shapes = scene.shapes
        t3 = time.perf_counter()
        cd.write_scene(os.path.join(tmp, "again.json"), shapes, scene.queries_as_written())
        print(f"write_scene (JSON, checked back):   {time.perf_counter() - t3:6.2f} s")


if __name__ == "__main__":
    main()
