"""Cases of every kind pair, entry point, precision and solver, run and checked in the child, and
``fuzz``, the default mode.
"""

from __future__ import annotations

import math
import sys
import tempfile

import numpy as np

from .common import ENTRY_POINTS, KINDS, PRECISIONS, ROUNDS, SOLVERS
from .runner import _run_chunk


# ----------------------------------------------------------------------------------------------
# cases: plain JSON-able dicts (floats as repr strings, so that the reproducer is exact)
# ----------------------------------------------------------------------------------------------
def _magnitude(rng):
    """A length scale: mostly moderate, often extreme."""
    r = rng.random()
    if r < 0.5:
        return float(10 ** rng.uniform(-2, 2))
    if r < 0.75:
        return float(10 ** rng.uniform(-300, 300))
    # float32's edges too (3.4e38 and 1.4e-45): answers past float32's range from inputs inside it
    # (a closest point at 5.2e38).
    return float(
        10.0 ** int(rng.choice([-300, -200, -155, -100, -45, -38, 38, 100, 155, 200, 300])) * rng.uniform(1, 9)
    )


def _vector(rng, scale):
    v = rng.normal(size=3) * scale
    mode = rng.random()
    if mode < 0.1:
        v[rng.integers(0, 3)] = 0.0
    elif mode < 0.15:
        v[:] = 0.0
        v[rng.integers(0, 3)] = scale
    return [float(x) for x in v]


def _direction(rng):
    v = _vector(rng, _magnitude(rng))
    if not any(v):
        v[2] = 1.0
    return v


def _arc_start(rng, normal):
    """An arc's start direction: any, often nearly or exactly along the normal (its projection
    onto the plane tiny, or zero: a clear error), of any length."""
    r = rng.random()
    if r < 0.1:
        return list(normal)  # parallel: the constructor's error
    if r < 0.25:  # a projection 1e-300..1e-8 of the start's length
        tilt = _vector(rng, 10.0 ** rng.uniform(-300, -8))
        return [n + t * abs(n) for n, t in zip(normal, tilt)]
    return _direction(rng)


def _arc_angle(rng):
    """An arc's angle: the whole circle, tiny (down to 1e-300), a hair short of 2 pi, random in
    (0, 2 pi], or now and then outside (0, 2 pi] (the constructor's error)."""
    r = rng.random()
    if r < 0.15:
        return 2 * math.pi
    if r < 0.3:
        return float(10.0 ** rng.uniform(-300, -1))
    if r < 0.4:
        return 2 * math.pi - float(10.0 ** rng.uniform(-16, -3))
    if r < 0.45:
        return float(rng.choice([0.0, -1.0, 7.0, math.inf, math.nan]))
    return float(rng.uniform(0, 2 * math.pi)) or math.pi


def _shape(rng, kind, scale, center):
    def near():
        return [c + x for c, x in zip(center, _vector(rng, scale))]

    if kind == "point":
        return {"p": near()}
    if kind in ("line", "ray"):
        return {"origin": near(), "direction": _direction(rng)}
    if kind == "segment":
        p0 = near()
        return {"p0": p0, "p1": list(p0) if rng.random() < 0.1 else near()}
    if (
        kind == "annulus"
    ):  # inner radius 0 (the disk), equal to the outer one (the circle), tiny, or now and then past it
        outer = 0.0 if rng.random() < 0.05 else abs(scale * rng.uniform(0.1, 3))
        r = rng.random()
        inner = (
            0.0
            if r < 0.1
            else outer
            if r < 0.2
            else outer * 10.0 ** rng.uniform(-300, -1)
            if r < 0.3
            else (outer * rng.uniform(1, 2) if r < 0.35 else outer * rng.uniform(0, 1))
        )
        return {"center": near(), "normal": _direction(rng), "inner_radius": inner, "outer_radius": outer}
    if kind in ("circle", "disk", "arc"):
        radius = 0.0 if rng.random() < 0.05 else abs(scale * rng.uniform(0.1, 3))
        round_fields = {"center": near(), "normal": _direction(rng), "radius": radius}
        if kind == "arc":
            round_fields.update(start=_arc_start(rng, round_fields["normal"]), angle=_arc_angle(rng))
        return round_fields
    count = int(rng.integers(2, 9))
    points = [near() for _ in range(count)]
    if rng.random() < 0.3:  # one dominant control point
        points[int(rng.integers(0, count))] = [float(x) for x in rng.normal(size=3) * scale * 10 ** rng.uniform(2, 200)]
    return {"control_points": points}


def generate(seed: int, count: int):
    rng = np.random.default_rng(seed)
    for index in range(count):
        scale = _magnitude(rng)
        center = _vector(rng, scale * (10 ** rng.uniform(0, 8) if rng.random() < 0.2 else 1))
        ka, kb = KINDS[rng.integers(0, len(KINDS))], KINDS[rng.integers(0, len(KINDS))]
        a, b = _shape(rng, ka, scale, center), _shape(rng, kb, scale, center)
        if rng.random() < 0.2:
            a["sweep"] = abs(_magnitude(rng) * rng.random())
        if ka in ROUNDS and kb in ROUNDS and rng.random() < 0.3:
            b["center"] = list(a["center"])  # concentric
        yield {
            "index": index,
            "a": [ka, a],
            "b": [kb, b],
            "entry": ENTRY_POINTS[rng.integers(0, len(ENTRY_POINTS))],
            "precision": PRECISIONS[rng.integers(0, len(PRECISIONS))],
            "solver": SOLVERS[rng.integers(0, len(SOLVERS))],
            "d": abs(_magnitude(rng)),
            "batch": int(rng.integers(0, 4)),  # 0: scalar; 1: C batch; 2: Fortran; 3: strided, read-only
        }


# ----------------------------------------------------------------------------------------------
# the child: run cases, check answers
# ----------------------------------------------------------------------------------------------
def _build(cd, kind, fields, batch):
    cls = getattr(cd, kind.capitalize())
    args = {k: v for k, v in fields.items()}
    if batch:
        out = {}
        for k, v in args.items():
            arr = np.asarray(v, dtype=float)
            stacked = np.stack([arr, arr, arr])
            if batch == 2:
                stacked = np.asfortranarray(stacked)
            elif batch == 3:
                wide = np.stack([stacked, stacked], axis=-1)
                stacked = wide[..., 0]
                stacked.setflags(write=False)
            out[k] = stacked
        args = out
    sweep = args.pop("sweep", None)
    positional = list(args.values())
    return cls(*positional, sweep=sweep) if sweep is not None else cls(*positional)


def _finite_array(x):
    return bool(np.all(np.isfinite(np.asarray(x, dtype=np.longdouble))))


def run_case(cd, case):
    """Returns None when all is well, else a finding (a short string). Exceptions from the
    constructors or the queries are answers (a clear error), not findings."""
    kw = {"precision": case["precision"], "solver": case["solver"]}
    try:
        a = _build(cd, *case["a"], case["batch"])
        b = _build(cd, *case["b"], case["batch"])
    except (ValueError, TypeError, OverflowError):
        return None
    entry = case["entry"]
    try:
        if entry == "distance":
            d = np.asarray(cd.distance(a, b, **kw), dtype=np.longdouble)
            if np.any(np.isnan(d)):
                return "NaN distance"
            if np.any(d < 0):
                return "negative distance"
        elif entry == "closest_points":
            r = cd.closest_points(a, b, **kw)
            d = np.asarray(r.distance, dtype=np.longdouble)
            if np.any(np.isnan(d)):
                return "NaN distance"
            finite = np.isfinite(d)
            pa = np.asarray(r.point_a, dtype=np.longdouble).reshape(-1, 3)
            pb = np.asarray(r.point_b, dtype=np.longdouble).reshape(-1, 3)
            if not (np.all(np.isfinite(pa[finite.ravel()])) and np.all(np.isfinite(pb[finite.ravel()]))):
                return "non-finite closest points for a finite distance"
            d2 = np.asarray(cd.distance(a, b, **kw), dtype=np.longdouble)
            if not np.array_equal(d2, d):
                return "distance() and closest_points().distance disagree"
        elif entry in ("within", "intersects"):
            out = cd.within(a, b, case["d"], **kw) if entry == "within" else cd.intersects(a, b, **kw)
            np.asarray(out, dtype=bool)
        else:
            d = np.asarray(cd.distance_if_within(a, b, case["d"], **kw), dtype=np.longdouble)
            if np.any(np.isnan(d)):
                return "NaN distance_if_within"
    except (ValueError, TypeError, OverflowError):
        return None
    return None


def _group_key(case):
    """Cases that can run as one batched call: the same kinds, field layout and query."""

    def layout(kind, fields):
        return (kind, tuple(sorted(fields)), len(fields.get("control_points", ())))

    return (layout(*case["a"]), layout(*case["b"]), case["entry"], case["precision"], case["solver"])


def _batch_shape(cd, kind, fields_list):
    cls = getattr(cd, kind.capitalize())
    names = [k for k in fields_list[0] if k != "sweep"]
    columns = [np.array([f[k] for f in fields_list], dtype=float) for k in names]
    sweep = np.array([f.get("sweep", 0.0) for f in fields_list], dtype=float)
    return cls(*columns, sweep=sweep)


def run_batch(cd, cases):
    """One batched call for cases of one group; None when every element is fine (or the whole
    call raised a clear error: then each case is run alone to see which), else the index of the
    first bad element and the finding."""
    case = cases[0]
    kw = {"precision": case["precision"], "solver": case["solver"]}
    try:
        a = _batch_shape(cd, case["a"][0], [c["a"][1] for c in cases])
        b = _batch_shape(cd, case["b"][0], [c["b"][1] for c in cases])
        d_limit = np.array([c["d"] for c in cases])
        entry = case["entry"]
        if entry == "distance":
            d = np.asarray(cd.distance(a, b, **kw), dtype=np.longdouble)
            bad = np.isnan(d) | (d < 0)
            return (int(np.argmax(bad)), "NaN or negative distance (batch)") if bad.any() else None
        if entry == "closest_points":
            r = cd.closest_points(a, b, **kw)
            d = np.asarray(r.distance, dtype=np.longdouble)
            pa = np.asarray(r.point_a, dtype=np.longdouble)
            pb = np.asarray(r.point_b, dtype=np.longdouble)
            finite = np.isfinite(d)
            bad = np.isnan(d) | (finite & ~(np.isfinite(pa).all(-1) & np.isfinite(pb).all(-1)))
            bad |= np.asarray(cd.distance(a, b, **kw), dtype=np.longdouble) != d
            return (
                (
                    int(np.argmax(bad)),
                    "NaN distance, non-finite points, or distance() and " "closest_points().distance disagree (batch)",
                )
                if bad.any()
                else None
            )
        if entry in ("within", "intersects"):
            out = cd.within(a, b, d_limit, **kw) if entry == "within" else cd.intersects(a, b, **kw)
            np.asarray(out, dtype=bool)
            return None
        d = np.asarray(cd.distance_if_within(a, b, d_limit, **kw), dtype=np.longdouble)
        bad = np.isnan(d)
        return (int(np.argmax(bad)), "NaN distance_if_within (batch)") if bad.any() else None
    except (ValueError, TypeError, OverflowError):
        return "error"


def fuzz(count, seed, chunk, timeout, python=sys.executable, progress=False, batched=False):
    summary = {"cases": 0, "crashes": 0, "hangs": 0, "findings": 0, "examples": []}
    cases = generate(seed, count)
    with tempfile.TemporaryDirectory() as tmp:
        while True:
            todo = [c for _, c in zip(range(chunk), cases)]
            if not todo:
                break
            _run_chunk(todo, "1" if batched else "0", python, timeout, tmp, summary)
            if progress:
                print(
                    f"  {summary['cases']} cases, {summary['crashes']} crashes, {summary['hangs']} hangs, "
                    f"{summary['findings']} findings",
                    file=sys.stderr,
                    flush=True,
                )
    return summary
