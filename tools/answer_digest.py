"""Fingerprints of the library's answers, to show that a change which should not move an answer
moves none: every kind pair of the accuracy cases (random, hard and the differential families'
hard cases, circledist_cases/accuracy.py), in both orders, through every entry point
(distance, closest_points with its points, parameters and `unique`, within, distance_if_within,
intersects), every solver policy and precision, plus random batches through the batched calls.

    python tools/answer_digest.py --save-cases build/digest_cases.npz --out build/digest_before.json
    ... change the code, rebuild ...
    python tools/answer_digest.py --cases build/digest_cases.npz --out build/digest_after.json
    python tools/answer_digest.py --compare build/digest_before.json build/digest_after.json

Each group's fingerprint is the SHA-256 of the answers' bytes (NaN kept bitwise). The cases are
saved once and read back, so a change in how the case generators draw does not pass for a change
in the answers.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys

import numpy as np

sys.path.insert(0, str(__import__("pathlib").Path(__file__).resolve().parents[1]))  # circledist_cases

SOLVERS = ("bracketing", "companion", "polished", "eigen")
PRECISIONS = ("float32", "float64", "longdouble")


def _cases(n_random: int):
    from circledist_cases import accuracy as A

    out = {}
    for case in A.generate_cases(n_random, A.KINDS):
        out.setdefault(case.kind, []).append(np.asarray(case.values, dtype=float))
    return out


def _save(path, cases):
    arrays = {}
    for kind, rows in cases.items():
        width = max(len(r) for r in rows)
        block = np.full((len(rows), width), np.nan)
        for i, r in enumerate(rows):
            block[i, : len(r)] = r
        arrays[kind] = block
    np.savez_compressed(path, **arrays)


def _load(path):
    with np.load(path) as data:
        return {kind: [row[~np.isnan(row)] for row in data[kind]] for kind in data.files}


class Digest:
    def __init__(self):
        self.groups = {}

    def add(self, group, *answers):
        h = self.groups.setdefault(group, hashlib.sha256())
        for x in answers:
            x = np.ascontiguousarray(x)
            h.update(str(x.dtype).encode())
            raw = x.reshape(-1).view(np.uint8).reshape(x.size, x.itemsize) if x.size else np.zeros((0, 1), np.uint8)
            if x.dtype == np.longdouble and np.finfo(np.longdouble).nmant == 63:
                raw = raw[:, :10]  # x87's 80 bits: the rest of the element is padding, not the value
            h.update(raw.tobytes())

    def result(self):
        out = {g: h.hexdigest() for g, h in sorted(self.groups.items())}
        total = hashlib.sha256("".join(out.values()).encode()).hexdigest()
        return {"total": total, "groups": out}


def _answers(cd, a, b, solver, precision, limit):
    kw = {"solver": solver, "precision": precision}
    cp = cd.closest_points(a, b, **kw)
    return (
        cd.distance(a, b, **kw),
        cp.distance,
        cp.point_a,
        cp.point_b,
        cp.param_a,
        cp.param_b,
        cp.unique,
        cd.within(a, b, limit, **kw),
        cd.distance_if_within(a, b, limit, **kw),
        cd.intersects(a, b, **kw),
    )


def _scalar(cd, cases, digest):
    from circledist_cases import accuracy as A
    from circledist_cases import shapes as S

    for kind, rows in sorted(cases.items()):
        for values in rows:
            (ka, va), (kb, vb) = A.split_values(kind, values)
            a, b = S.make_shape(cd, ka, va), S.make_shape(cd, kb, vb)
            limit = 1.0
            for solver in SOLVERS:
                for precision in PRECISIONS:
                    group = f"scalar {kind} {solver} {precision}"
                    try:
                        digest.add(group, *_answers(cd, a, b, solver, precision, limit))
                        digest.add(group, *_answers(cd, b, a, solver, precision, limit))
                    except (ValueError, OverflowError) as error:  # float32 beyond range: the error is the answer
                        digest.add(group, np.frombuffer(type(error).__name__.encode(), np.uint8))


def _batched(cd, digest, n=64):
    from circledist_cases import batches as B

    rng = np.random.default_rng(39)
    kinds = ["Point", "Line", "Ray", "Segment", "Circle", "Disk", "Arc", "Annulus", "Bezier"]
    for ka in kinds:
        for kb in kinds:
            if (ka.lower(), kb.lower()) not in B.SUPPORTED:
                continue
            a, b = B.random_batch(ka, n, rng), B.random_batch(kb, n, rng)
            limit = rng.uniform(0, 2, n)
            for solver in SOLVERS:
                for precision in PRECISIONS:
                    digest.add(f"batch {ka}-{kb} {solver} {precision}", *_answers(cd, a, b, solver, precision, limit))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--random", type=int, default=20, help="random cases per kind pair (default 20)")
    p.add_argument("--save-cases", help="draw the cases and save them here (.npz)")
    p.add_argument("--cases", help="read the cases saved by --save-cases")
    p.add_argument("--out", help="write the fingerprints here (JSON)")
    p.add_argument("--compare", nargs=2, metavar=("BEFORE", "AFTER"), help="compare two fingerprint files")
    args = p.parse_args(argv)
    if args.compare:
        before, after = (json.load(open(f)) for f in args.compare)
        moved = sorted(
            g for g in set(before["groups"]) | set(after["groups"]) if before["groups"].get(g) != after["groups"].get(g)
        )
        for g in moved:
            print("moved:", g)
        print(f"{len(before['groups'])} groups; {len(moved)} moved; total {'same' if not moved else 'differs'}")
        return 1 if moved else 0
    import circledist as cd

    if args.cases:
        cases = _load(args.cases)
    else:
        cases = _cases(args.random)
        if args.save_cases:
            _save(args.save_cases, cases)
    digest = Digest()
    _scalar(cd, cases, digest)
    _batched(cd, digest)
    result = digest.result()
    result["cases"] = {k: len(v) for k, v in cases.items()}
    text = json.dumps(result, indent=1)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text + "\n")
    print(f"{sum(result['cases'].values())} cases, {len(result['groups'])} groups, total {result['total']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
