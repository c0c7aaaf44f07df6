"""Crash-isolating fuzz of circledist's Python API (issue 15).

Cases cover every kind pair in both orders, every entry point (distance, closest_points, within,
intersects, distance_if_within), precision and solver, magnitudes from 1e-300 to 1e300, degenerate
shapes (zero radius, zero-length segments, points on axes, coplanar and concentric rounds), sweeps,
batches in several memory layouts (C, Fortran, strided, read-only) and dtypes.

Each chunk of cases runs in a child process. The child writes the case it is about to run to a file
first, so when it dies (a signal: a crash) or stops answering (a hang), the parent names the input.
The child also checks every answer: no NaN for inputs the constructors accepted, distances >= 0,
closest points finite whenever the distance is finite, and distance() == closest_points().distance.

    python tools/fuzz_crash.py [--cases N] [--seed S] [--chunk K] [--timeout T] [--report FILE]
    python tools/fuzz_crash.py --files N [--seed S] [--report FILE]
    python tools/fuzz_crash.py --threads N [--seed S] [--timeout T] [--report FILE]
    python tools/fuzz_crash.py --arguments N [--seed S] [--chunk K] [--timeout T] [--report FILE]

--files: the command line on hostile files instead (FIFOs and devices, zip bombs, .npy headers
that lie about their shape, JSON nested near the recursion limit, lone surrogates, counts beyond
memory, unsupported compression, members that are no .npy, truncated and byte-flipped files),
each in its own process held to 1 GiB of address space and 60 s: a finding is anything but one
"circledist: error: FILE: ..." line and exit status 2 (a truncated or flipped file may still be
valid: exit 0).

--threads: N scenarios of one Scene shared by 3-5 threads (each scenario in its own child, held
to --timeout seconds, at most 120): random shapes (points, circles, disks, segments, arcs, annuli,
Bezier curves; some far or huge outliers, some float32, some swept), and in every thread a random
mix of adds (single and batched), pairs_within, nearest, within, queries by a shape's name,
distance_matrix, pickling or deep-copying the scene mid-run and adding a name already taken. A
finding: a crash, a hang, an exception other than the documented ones, or an answer that no
serial scene of the first m shapes gives for any m between the counts at the query's start and
end.

--arguments: N calls of every entry point (distance, closest_points, within, intersects,
distance_if_within, nearest, pairs_within, Scene.nearest/within/pairs_within, the shape
constructors, batch indexing, circledist.dask.pairs_within where dask is installed), each with one
hostile scalar argument (huge integers, bools, NumPy integers and bools, floats where integers are
expected, NaN, inf, strings, None) over small, empty, one-element, outer 10^5 x 10^5 and 10^15-row
broadcast batches, --chunk calls per child held to 2 GiB of address space. A finding: a crash, a
hang, an exception other than TypeError, ValueError, MemoryError and IndexError (KeyError for a
scene shape's name), pybind11's "Unable to cast" or "incompatible function arguments", or a
MemoryError raised after the process grew by 256 MiB (memory really allocated) or in C++'s words.

Exit status 0 when nothing was found, 1 otherwise; the summary (counts, and one reproducer per
finding) is printed and, with --report, written as JSON.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

KINDS = ("point", "line", "ray", "segment", "circle", "disk", "bezier", "arc", "annulus")
ROUNDS = ("circle", "disk", "arc", "annulus")  # the kinds with a center: concentric pairs
ENTRY_POINTS = ("distance", "closest_points", "within", "intersects", "distance_if_within")
PRECISIONS = (None, "float32", "float64", "longdouble")
SOLVERS = (None, "bracketing", "companion", "polished", "eigen")


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
    # (the 10^7 run's finding: a closest point at 5.2e38).
    return float(10.0 ** int(rng.choice([-300, -200, -155, -100, -45, -38, 38, 100, 155, 200, 300])) * rng.uniform(1, 9))


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
    if kind == "annulus":  # inner radius 0 (the disk), equal to the outer one (the circle), tiny, or now and then past it
        outer = 0.0 if rng.random() < 0.05 else abs(scale * rng.uniform(0.1, 3))
        r = rng.random()
        inner = 0.0 if r < 0.1 else outer if r < 0.2 else outer * 10.0 ** rng.uniform(-300, -1) if r < 0.3 else (
            outer * rng.uniform(1, 2) if r < 0.35 else outer * rng.uniform(0, 1))
        return {"center": near(), "normal": _direction(rng), "inner_radius": inner, "outer_radius": outer}
    if kind in ("circle", "disk", "arc"):
        radius = 0.0 if rng.random() < 0.05 else abs(scale * rng.uniform(0.1, 3))
        round_fields = {"center": near(), "normal": _direction(rng), "radius": radius}
        if kind == "arc":
            round_fields.update(start=_arc_start(rng, round_fields["normal"]), angle=_arc_angle(rng))
        return round_fields
    count = int(rng.integers(2, 9))
    points = [near() for _ in range(count)]
    if rng.random() < 0.3:  # one dominant control point (issue 15 item 1)
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
            return (int(np.argmax(bad)), "NaN distance, non-finite points, or distance() and "
                    "closest_points().distance disagree (batch)") if bad.any() else None
        if entry in ("within", "intersects"):
            out = cd.within(a, b, d_limit, **kw) if entry == "within" else cd.intersects(a, b, **kw)
            np.asarray(out, dtype=bool)
            return None
        d = np.asarray(cd.distance_if_within(a, b, d_limit, **kw), dtype=np.longdouble)
        bad = np.isnan(d)
        return (int(np.argmax(bad)), "NaN distance_if_within (batch)") if bad.any() else None
    except (ValueError, TypeError, OverflowError):
        return "error"


def child(cases_file, current_file, results_file, mode="0"):
    """Runs the cases of cases_file: mode "0" one by one, "1" batched, "threads" the thread
    scenarios, "arguments" the hostile argument calls."""
    import faulthandler

    import circledist as cd

    faulthandler.enable()  # a crash's stderr names the threads' Python stacks
    cases = json.load(open(cases_file))
    findings = []
    run_one = {"threads": run_thread_case, "arguments": run_argument_case}.get(mode, run_case)

    def note(case):
        current.seek(0)
        current.write(json.dumps(case))
        current.truncate()
        current.flush()

    with open(current_file, "w") as current:
        if mode == "1":
            groups = {}
            for case in cases:
                groups.setdefault(_group_key(case), []).append(case)
            for group in groups.values():
                note({"batch_of": [c["index"] for c in group], **group[0]})
                result = run_batch(cd, group)
                if result is None:
                    continue
                # A clear error somewhere in the batch, or a bad element: each case alone.
                alone = 0
                for case in group:
                    note(case)
                    finding = run_case(cd, dict(case, batch=0))
                    if finding:
                        findings.append({"finding": finding, "case": case})
                        alone += 1
                if result != "error" and alone == 0:  # bad in the batch only
                    findings.append({"finding": result[1], "case": group[result[0]]})
        else:
            for case in cases:
                note(case)
                finding = run_one(cd, case)
                if isinstance(finding, dict):  # a finding with its detail
                    findings.append({**finding, "case": case})
                elif finding:
                    findings.append({"finding": finding, "case": case})
    json.dump({"ran": len(cases), "findings": findings}, open(results_file, "w"))


# ----------------------------------------------------------------------------------------------
# the parent: chunks in child processes
# ----------------------------------------------------------------------------------------------
def _run_child(todo, mode, python, timeout, tmp, memory=None):
    """Runs the cases in a child (mode: as child()'s; memory: a bound on its address space, in
    bytes); returns (result or None, last case started, crash/hang text)."""
    cases_file, current_file, results_file = (os.path.join(tmp, n) for n in ("cases", "current", "results"))
    json.dump(todo, open(cases_file, "w"))
    for f in (current_file, results_file):
        if os.path.exists(f):
            os.remove(f)
    try:
        proc = subprocess.run([python, os.path.abspath(__file__), "--child", cases_file, current_file, results_file,
                               mode], timeout=timeout, capture_output=True, text=True, stdin=subprocess.DEVNULL,
                              preexec_fn=None if memory is None else lambda: _limit_memory(memory))
        if proc.returncode == 0 and os.path.exists(results_file):
            return json.load(open(results_file)), None, None
        what = f"crash (exit {proc.returncode})", proc.stderr[-2000:]
    except subprocess.TimeoutExpired:
        what = "hang", ""
    last = json.load(open(current_file)) if os.path.exists(current_file) else None
    return None, last, what


def _run_chunk(todo, mode, python, timeout, tmp, summary, memory=None):
    """Adds the chunk's counts to summary. A batched chunk that stops its child is run again case
    by case; a case that stops its child is recorded with its input, and the rest run on."""
    while todo:
        result, last, what = _run_child(todo, mode, python, timeout, tmp, memory)
        if result is not None:
            summary["cases"] += result["ran"]
            summary["findings"] += len(result["findings"])
            seen = {e["finding"] for e in summary["examples"]}
            for f in result["findings"]:
                if f["finding"] not in seen:
                    summary["examples"].append(f)
                    seen.add(f["finding"])
            return
        if mode == "1":
            mode = "0"
            continue
        summary["hangs" if what[0] == "hang" else "crashes"] += 1
        summary["examples"].append({"finding": what[0], "case": last, "stderr": what[1]})
        done = next((i + 1 for i, c in enumerate(todo) if last and c["index"] == last["index"]), len(todo))
        summary["cases"] += done
        todo = todo[done:]


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
                print(f"  {summary['cases']} cases, {summary['crashes']} crashes, {summary['hangs']} hangs, "
                      f"{summary['findings']} findings", file=sys.stderr, flush=True)
    return summary


# ----------------------------------------------------------------------------------------------
# hostile files: the command line on files made to break a reader
# ----------------------------------------------------------------------------------------------
# Files a reader must refuse: each run as `python -m circledist FILE --no-plot` in a process held to
# FILE_MEMORY bytes of address space and FILE_TIMEOUT seconds; a finding is anything but exit
# status 2 with one line "circledist: error: FILE: ..." on stderr and nothing on stdout (the
# mutated classes may also be valid: exit 0 then).
FILE_CLASSES = ("fifo", "device", "zip_bomb", "lying_header", "deep_json", "deep_queries", "surrogate",
                "huge_count", "compression", "foreign_member", "truncated", "flipped")
MUST_REFUSE = set(FILE_CLASSES) - {"truncated", "flipped"}
FILE_MEMORY = 1 << 30
FILE_TIMEOUT = 60.0
_FILE_SCENE = {"format": "circledist-scene", "version": 3, "description": "hostile",
               "shapes": [{"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1},
                          {"name": "dust", "kind": "point", "count": 3, "p": [[0, 0, 2], [1, 0, 2], [2, 0, 2]]},
                          {"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]}],
               "queries": [{"a": "rail", "b": "ring", "effects": ["distance"]},
                           {"a": "dust[1]", "effects": ["nearest"], "k": 2}]}
_NPZ_ROLES = {"format": ("<U", ()), "version": ("<i8", ()), "shapes": ("<U", (3,)), "queries": ("<U", ()),
              "ring/kind": ("<U", ()), "ring/center": ("<f8", (3,)), "ring/radius": ("<f8", ()),
              "dust/count": ("<i8", ()), "dust/p": ("<f8", (3, 3)), "rail/direction": ("<f8", (3,))}


def _npz_arrays():
    arrays = {"format": np.array("circledist-scene"), "version": np.array(3), "description": np.array("hostile"),
              "shapes": np.array(["ring", "dust", "rail"]), "queries": np.array(json.dumps(_FILE_SCENE["queries"]))}
    for spec in _FILE_SCENE["shapes"]:
        name = spec["name"]
        arrays[f"{name}/kind"] = np.array(spec["kind"])
        if "count" in spec:
            arrays[f"{name}/count"] = np.array(spec["count"])
        for field, value in spec.items():
            if field not in ("name", "kind", "count"):
                arrays[f"{name}/{field}"] = np.array(value, dtype=np.float64)
    return arrays


def _write_npz(path, members, method=None):
    """An .npz member by member: name -> array, raw bytes, or a callable writing the member."""
    import zipfile

    with zipfile.ZipFile(path, "w", compression=method or zipfile.ZIP_STORED) as z:
        for name, value in members.items():
            with z.open(name, "w", force_zip64=True) as f:
                if callable(value):
                    value(f)
                elif isinstance(value, bytes):
                    f.write(value)
                else:
                    np.lib.format.write_array(f, value, allow_pickle=False)


def _npy_header(descr, shape):
    def write(f, zeros=0):
        np.lib.format.write_array_header_1_0(f, {"descr": descr, "fortran_order": False, "shape": shape})
        piece = bytes(1 << 20)
        for _ in range(zeros >> 20):
            f.write(piece)
        f.write(bytes(zeros & ((1 << 20) - 1)))
    return write


def _hostile_file(rng, kind, folder, index):
    """Makes case `index` of class `kind` in folder; returns (path, description)."""
    import zipfile

    base = os.path.join(folder, f"case{index}")
    members = {f"{k}.npy": v for k, v in _npz_arrays().items()}
    if kind == "fifo":
        path = base + rng.choice([".json", ".npz", ""])
        os.mkfifo(path)
        return path, "a FIFO"
    if kind == "device":
        path = str(rng.choice(["/dev/zero", "/dev/urandom", "/dev/null"]))
        return path, path
    if kind in ("zip_bomb", "lying_header"):
        key = str(rng.choice(sorted(_NPZ_ROLES)))
        descr, shape = _NPZ_ROLES[key]
        descr = descr + "4096" if descr == "<U" else descr
        size = 32 << 20
        if kind == "zip_bomb":  # data of 32 MiB under a header of another dtype or shape
            item = np.dtype(str(rng.choice(["<f8", "<i8", "<U8", "<f4"])))
            claim = (size // item.itemsize,) if rng.random() < 0.7 else ()
            header = _npy_header(item.str, claim)
            zeros = size if claim else item.itemsize
            if rng.random() < 0.3:  # a small header over all the data
                header, zeros = _npy_header(descr, shape), size
            members[f"{key}.npy"] = lambda f: header(f, zeros)
            what = f"{key}: {item.str} {claim}, {zeros} bytes"
        else:  # a header claiming up to 10^15 elements over a few bytes
            claim = tuple(int(10 ** rng.uniform(0, 15)) for _ in range(int(rng.integers(1, 3))))
            header = _npy_header(descr if rng.random() < 0.5 else "<f8", claim)
            members[f"{key}.npy"] = lambda f: header(f, int(rng.integers(0, 64)))
            what = f"{key}: header of shape {claim}"
        path = base + ".npz"
        _write_npz(path, members, zipfile.ZIP_DEFLATED)
        return path, what
    if kind in ("deep_json", "deep_queries"):
        depth = int(rng.choice([int(rng.integers(900, 1100)), int(10 ** rng.uniform(2, 5))]))
        deep = "[" * depth + "]" * depth if rng.random() < 0.7 else '{"a":' * depth + "1" + "}" * depth
        if kind == "deep_queries":
            text = json.dumps([{"a": "rail", "effects": ["nearest"], "k": "@"}]).replace('"@"', deep)
            members["queries.npy"] = np.array(text)
            path = base + ".npz"
            _write_npz(path, members)
            return path, f"queries nested {depth} deep"
        place = str(rng.choice(["shapes", "description", "center", "p", "queries", "effects", "top"]))
        doc = json.loads(json.dumps(_FILE_SCENE))
        target = {"shapes": (doc, "shapes"), "description": (doc, "description"), "center": (doc["shapes"][0], "center"),
                  "p": (doc["shapes"][1], "p"), "queries": (doc, "queries"),
                  "effects": (doc["queries"][0], "effects")}.get(place)
        if target is None:
            text = deep
        else:
            target[0][target[1]] = "@DEEP@"
            text = json.dumps(doc).replace('"@DEEP@"', deep)
        path = base + ".json"
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        return path, f"{place} nested {depth} deep"
    if kind == "surrogate":
        bad = chr(int(rng.integers(0xD800, 0xE000)))
        place = str(rng.choice(["name", "description", "query name", "npz name", "npz description"]))
        if place.startswith("npz"):
            if place == "npz name":
                members["shapes.npy"] = np.array(["ring", "dust", "rail" + bad])
            else:
                members["description.npy"] = np.array("x" + bad)
            path = base + ".npz"
            _write_npz(path, members)
            return path, place
        doc = json.loads(json.dumps(_FILE_SCENE))
        if place == "name":
            doc["shapes"][0]["name"] = "ring" + bad
        elif place == "description":
            doc["description"] = bad
        else:
            doc["queries"][0]["name"] = "q" + bad
        path = base + ".json"
        with open(path, "w", encoding="ascii") as f:
            f.write(json.dumps(doc))  # the surrogate as an escape: valid JSON
        return path, f"{place}: U+{ord(bad):04X}"
    if kind == "huge_count":
        count = int(10 ** rng.uniform(8, 30))
        if rng.random() < 0.5:
            doc = json.loads(json.dumps(_FILE_SCENE))
            doc["shapes"][1].update(count=count, p=[0, 0, 2])
            path = base + ".json"
            with open(path, "w", encoding="utf-8") as f:
                f.write(json.dumps(doc))
            return path, f"JSON count {count}"
        members["dust/count.npy"] = np.array(min(count, 2**63 - 1))
        members["dust/p.npy"] = np.zeros(3)
        path = base + ".npz"
        _write_npz(path, members)
        return path, f"npz count {min(count, 2**63 - 1)}"
    if kind == "compression":
        path = base + ".npz"
        _write_npz(path, members)
        method = int(rng.choice([9, 10, 18, 19, 97, 98, 99]))
        data = bytearray(open(path, "rb").read())
        for signature, offset in ((b"PK\x03\x04", 8), (b"PK\x01\x02", 10)):
            at = data.find(signature)
            while at >= 0:
                data[at + offset:at + offset + 2] = method.to_bytes(2, "little")
                at = data.find(signature, at + 4)
        with open(path, "wb") as f:
            f.write(data)
        return path, f"method {method}"
    if kind == "foreign_member":
        key = str(rng.choice(sorted(_NPZ_ROLES)))
        junk = bytes(rng.integers(0, 256, int(rng.integers(0, 200)), dtype=np.uint8))
        if rng.random() < 0.5:
            members[f"{key}.npy"] = junk
        else:
            members.pop(f"{key}.npy")
            members[key] = junk
        path = base + ".npz"
        _write_npz(path, members)
        return path, f"{key}: {len(junk)} bytes of no .npy"
    # truncated or flipped: a valid file, cut short or with bytes changed
    path = base + str(rng.choice([".json", ".npz"]))
    if path.endswith(".npz"):
        _write_npz(path, members, zipfile.ZIP_DEFLATED if rng.random() < 0.5 else None)
    else:
        with open(path, "w", encoding="utf-8") as f:
            f.write(json.dumps(_FILE_SCENE))
    data = bytearray(open(path, "rb").read())
    if kind == "truncated":
        cut = int(rng.integers(0, len(data)))
        data = data[:cut]
        what = f"cut at byte {cut}"
    else:
        at = rng.integers(0, len(data), int(rng.integers(1, 8)))
        for i in at:
            data[i] = int(rng.integers(0, 256))
        what = f"bytes {sorted(int(i) for i in at)} changed"
    with open(path, "wb") as f:
        f.write(data)
    return path, what


def _limit_memory(limit=FILE_MEMORY):
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_file_case(path, kind, python=sys.executable):
    """None, or what is wrong with the command line's answer to the file."""
    try:
        proc = subprocess.run([python, "-m", "circledist", path, "--no-plot"], capture_output=True, text=True,
                              timeout=FILE_TIMEOUT, preexec_fn=_limit_memory, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return "hang", ""
    err = proc.stderr
    if proc.returncode == 0 and kind not in MUST_REFUSE:
        return None
    if proc.returncode != 2:
        return f"exit {proc.returncode}", err[-2000:]
    if not err.startswith(f"circledist: error: {path}: ") or err.count("\n") != 1 or "Traceback" in err \
            or proc.stdout:
        return "not one clean error line", err[-2000:]
    return None


def fuzz_files(count, seed, python=sys.executable, progress=False):
    """count hostile files, the classes in turn; a summary as fuzz()'s."""
    summary = {"cases": 0, "crashes": 0, "hangs": 0, "findings": 0, "examples": [], "classes": {}}
    rng = np.random.default_rng(seed)
    with tempfile.TemporaryDirectory() as folder:
        for index in range(count):
            kind = FILE_CLASSES[index % len(FILE_CLASSES)]
            path, what = _hostile_file(rng, kind, folder, index)
            start = time.time()
            found = run_file_case(path, kind, python)
            summary["cases"] += 1
            summary["classes"][kind] = summary["classes"].get(kind, 0) + 1
            if found is not None:
                key = "hangs" if found[0] == "hang" else "crashes" if found[0].startswith("exit -") else "findings"
                summary[key] += 1
                summary["examples"].append({"finding": found[0], "case": {"index": index, "class": kind, "file": what},
                                            "stderr": found[1]})
            if progress:
                print(f"  {index} {kind} ({what[:60]}): {found[0] if found else 'ok'} {time.time() - start:.1f} s",
                      file=sys.stderr, flush=True)
    return summary


# ----------------------------------------------------------------------------------------------
# threads: one Scene shared by threads that add and query it at once
# ----------------------------------------------------------------------------------------------
# Each scenario runs in its own child (THREAD_TIMEOUT seconds): a Scene of random shapes (the kinds
# below, some far or huge outliers, some float32, some swept) shared by 3-5 threads, each doing a
# random mix of adds (single, and batched with extend), pairs_within, nearest, within (of a shape
# and of a scene shape by name), distance_matrix and shape lookups by name, pickling or deep-copying
# the scene, and adding a name already taken. The shapes are added in one order (a thread claims the next ones
# under a lock of its own), so the scene is always a prefix of that order; every answer must be the
# answer of a serial scene of the first m shapes for some m between the counts at the query's start
# and its end (tests/api/test_scene.py's threaded test), and the scene must end as the serial one. A
# finding: a crash, a hang, an exception other than the documented ones, or an answer no serial
# scene gives.
THREAD_KINDS = ("point", "circle", "disk", "segment", "arc", "annulus", "bezier")
THREAD_TIMEOUT = 120.0
THREAD_OPS = ("add", "extend", "pairs", "nearest", "within", "nearest_name", "within_name", "matrix", "shape",
              "pickle", "duplicate")
# Outcomes a valid query may have: an answer, or one of these errors (the serial scene must agree).
THREAD_ERRORS = ("TypeError", "ValueError", "KeyError", "MemoryError")


def generate_threads(seed: int, count: int):
    rng = np.random.default_rng(seed)
    for index in range(count):
        yield {"index": index, "seed": int(rng.integers(0, 2**63 - 1)), "shapes": int(rng.integers(8, 120)),
               "threads": int(rng.integers(3, 6)), "ops": int(rng.integers(10, 60))}


def _scene_shapes(cd, rng, count):
    """count single shapes (fields as arrays), in runs of one layout (kind, dtype, sweep, control
    point count) that extend can add as one batch; a tenth far away or huge."""
    shapes, layout = [], None
    while len(shapes) < count:
        if layout is None or rng.random() < 0.6:
            layout = (THREAD_KINDS[rng.integers(0, len(THREAD_KINDS))],
                      np.float32 if rng.random() < 0.15 else np.float64, rng.random() < 0.25)
        kind, dtype, swept = layout
        outlier = rng.random() < 0.1
        scale = float(10 ** rng.uniform(6, 15)) if outlier and rng.random() < 0.5 else float(rng.uniform(0.1, 2))
        center = rng.uniform(0, 10, 3) + (rng.choice([-1, 1], 3) * 10 ** rng.uniform(6, 15) if outlier else 0)
        fields = _shape(rng, kind, scale, [float(c) for c in center])
        if swept:
            fields["sweep"] = float(rng.uniform(0, 0.5) * scale)
        try:
            shape = _single_shape(cd, kind, fields, dtype)
        except (ValueError, TypeError, OverflowError):
            layout = None
            continue
        shapes.append(shape)
    return shapes


def _single_shape(cd, kind, fields, dtype=np.float64):
    cls = getattr(cd, kind.capitalize())
    with np.errstate(over="ignore"):  # float32 fields past its range: the constructor's error
        args = {k: np.asarray(v, dtype=dtype) for k, v in fields.items()}
    sweep = args.pop("sweep", None)
    return cls(*args.values(), sweep=sweep) if sweep is not None else cls(*args.values())


def _stacked(cd, shapes):
    """The shapes (of one layout) as one batch, or None when their layouts differ."""
    arrays = [s.to_arrays() for s in shapes]
    first = arrays[0]
    if any(s.kind != shapes[0].kind or a.keys() != first.keys()
           or any(a[k].shape != first[k].shape or a[k].dtype != first[k].dtype for k in a)
           for s, a in zip(shapes, arrays)):
        return None
    return type(shapes[0]).from_arrays({k: np.stack([a[k] for a in arrays]) for k in first})


def _outcome(call):
    """("ok", answer as text) or ("error", exception type): what serial and threaded runs compare."""
    try:
        answer = call()
    except Exception as error:  # noqa: BLE001 (compared, and checked against THREAD_ERRORS)
        return ("error", type(error).__name__, str(error)[:200])
    if isinstance(answer, np.ndarray):
        return ("ok", answer.dtype.str, answer.shape, answer.tobytes().hex())
    return ("ok", repr(answer))


def _query(scene, op, names, queries):
    """The call of a reading op on scene (a thread's scene or a serial one)."""
    name, args = op[0], op[1:]
    if name == "pairs":
        d, workers, max_pairs = args
        return lambda: scene.pairs_within(d, workers=workers, max_pairs=max_pairs)
    if name == "nearest":
        return lambda: scene.nearest(queries[args[0]], k=args[1])
    if name == "within":
        return lambda: scene.within(queries[args[0]], args[1])
    if name == "nearest_name":
        return lambda: scene.nearest(names[args[0]], k=args[1], exclude=[names[i] for i in args[2]])
    if name == "within_name":
        return lambda: scene.within(names[args[0]], args[1])
    if name == "matrix":
        return lambda: scene.distance_matrix([names[i] for i in args[0]], [names[i] for i in args[1]])
    if name == "shape":
        return lambda: sorted((k, v.dtype.str, v.tobytes().hex()) for k, v in scene[names[args[0]]].to_arrays().items())
    if name == "pickle":  # pickled and loaded, or deep-copied
        def copied():
            import copy
            import pickle

            twin = pickle.loads(pickle.dumps(scene)) if args[1] == "pickle" else copy.deepcopy(scene)
            return twin.names, twin.pairs_within(args[0]), twin.nearest(queries[0], k=3)
        return copied
    raise AssertionError(op)


def run_thread_case(cd, case):
    """None, or a finding (a dict with its detail) for one scenario."""
    import threading
    import traceback

    rng = np.random.default_rng(case["seed"])
    n = case["shapes"]
    shapes = _scene_shapes(cd, rng, n)
    names = [f"s{i}" for i in range(n)]
    queries = [cd.Point(rng.uniform(0, 10, 3))] + _scene_shapes(cd, rng, 3) + [
        cd.Line(rng.uniform(0, 10, 3), rng.normal(size=3)), cd.Point([1e12, -3e14, 2.0])]
    first = int(rng.integers(0, n // 2))
    scene = cd.Scene()
    for i in range(first):
        scene.add(names[i], shapes[i])
    claim = threading.Lock()
    added = [first]  # shapes claimed and added, in order (under claim)
    seen, failures = [], []

    def distance_limit(r):
        x = r.random()
        return 0.0 if x < 0.1 else 1e30 if x < 0.15 else float(10 ** r.uniform(-3, 1))

    def worker(t):
        r = np.random.default_rng([case["seed"], t])
        try:
            for _ in range(case["ops"]):
                op = THREAD_OPS[r.integers(0, len(THREAD_OPS))]
                present = len(scene)
                if op in ("add", "extend"):
                    with claim:
                        at = added[0]
                        if at >= n:
                            continue
                        if op == "extend":
                            stop = min(n, at + int(r.integers(1, 6)))
                            while stop > at + 1 and _stacked(cd, shapes[at:stop]) is None:
                                stop -= 1
                            scene.extend(names[at:stop], _stacked(cd, shapes[at:stop]))
                        else:
                            stop = at + 1
                            scene.add(names[at], shapes[at])
                        added[0] = stop
                    continue
                if op == "duplicate":
                    if present == 0:
                        continue
                    before = len(scene)
                    got = _outcome(lambda: scene.add(names[int(r.integers(0, present))], shapes[0]))
                    seen.append((("duplicate",), before, len(scene), got))
                    continue
                if op == "pairs":
                    max_pairs = None if r.random() < 0.5 else int(r.integers(0, 40))
                    args = (distance_limit(r), int(r.choice([1, 2, -1])), max_pairs)
                elif op == "nearest":
                    args = (int(r.integers(0, len(queries))), int(r.choice([1, 3, 7, 2**62])))
                elif op == "within":
                    args = (int(r.integers(0, len(queries))), distance_limit(r))
                elif op == "pickle":
                    args = (distance_limit(r), str(r.choice(["pickle", "deepcopy"])))
                else:  # by name: only names present now (the scene only grows)
                    if present == 0:
                        continue
                    pick = lambda: int(r.integers(0, present))  # noqa: E731
                    if op == "nearest_name":
                        args = (pick(), int(r.choice([1, 2, 5])), tuple(pick() for _ in range(int(r.integers(0, 3)))))
                    elif op == "within_name":
                        args = (pick(), distance_limit(r))
                    elif op == "matrix":
                        args = (tuple(pick() for _ in range(int(r.integers(0, 4)))),
                                tuple(pick() for _ in range(int(r.integers(0, 4)))))
                    else:
                        args = (pick(),)
                before = len(scene)
                got = _outcome(_query(scene, (op, *args), names, queries))
                seen.append(((op, *args), before, len(scene), got))
        except BaseException:  # noqa: BLE001 (an add that raised: reported by the main thread)
            failures.append(traceback.format_exc()[-2000:])

    threads = [threading.Thread(target=worker, args=(t,)) for t in range(case["threads"])]
    switch = sys.getswitchinterval()
    sys.setswitchinterval(1e-5)  # the GIL changes hands often: more interleavings of the threads
    try:
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(switch)
    if failures:
        return {"finding": "an add raised in a thread", "detail": failures[0]}
    for i in range(added[0], n):  # the rest, so that the end state is the whole serial scene
        scene.add(names[i], shapes[i])

    serial_scenes, serial_answers = {}, {}

    def serial(m):
        if m not in serial_scenes:
            s = cd.Scene()
            for i in range(m):
                s.add(names[i], shapes[i])
            serial_scenes[m] = s
        return serial_scenes[m]

    def serial_answer(op, m):
        if (op, m) not in serial_answers:
            serial_answers[op, m] = _outcome(_query(serial(m), op, names, queries))
        return serial_answers[op, m]

    for op, before, after, got in seen:
        if got[0] == "error" and got[1] not in THREAD_ERRORS:
            return {"finding": f"{op[0]}: {got[1]}", "detail": f"{op} with {before}..{after} shapes: {got}"}
        if op[0] == "duplicate":
            if got[:2] != ("error", "ValueError"):
                return {"finding": "adding a name taken did not raise ValueError", "detail": f"{got}"}
            continue
        if op[0] == "pairs" and got[0] == "error" and op[3] is not None:
            # max_pairs: the count at which the search stops may follow the workers' order
            expected = [serial_answer(op, m)[:2] for m in range(before, after + 1)]
            if got[:2] not in expected:
                return {"finding": "pairs_within with max_pairs: an error no serial scene gives",
                        "detail": f"{op} with {before}..{after} shapes: {got}, serial: {expected}"}
            continue
        if not any(serial_answer(op, m) == got for m in range(before, after + 1)):
            return {"finding": f"{op[0]}: an answer no serial scene gives",
                    "detail": f"{op} with {before}..{after} shapes: {str(got)[:500]}; serial: "
                              f"{str(serial_answer(op, before))[:500]}"}
    final = [("pairs", 1.0, 1, None), ("nearest", 0, 3), ("within", 1, 2.0), ("pickle", 0.5, "pickle"),
             ("pickle", 0.5, "deepcopy"), ("shape", n - 1)]
    for op in final:
        got, expected = _outcome(_query(scene, op, names, queries)), serial_answer(op, n)
        if got != expected:
            return {"finding": f"the scene's end state: {op[0]} differs from the serial scene's",
                    "detail": f"{op}: {str(got)[:500]}; serial: {str(expected)[:500]}"}
    if scene.names != names:
        return {"finding": "the scene's end state: names differ from the serial order", "detail": ""}
    return None


def fuzz_threads(count, seed, python=sys.executable, progress=False, timeout=THREAD_TIMEOUT):
    """count thread scenarios, each in its own child held to timeout seconds; a summary as fuzz()'s."""
    summary = {"cases": 0, "crashes": 0, "hangs": 0, "findings": 0, "examples": []}
    with tempfile.TemporaryDirectory() as tmp:
        for case in generate_threads(seed, count):
            _run_chunk([case], "threads", python, timeout, tmp, summary)
            if progress and (case["index"] + 1) % 10 == 0:
                print(f"  {summary['cases']} scenarios, {summary['crashes']} crashes, {summary['hangs']} hangs, "
                      f"{summary['findings']} findings", file=sys.stderr, flush=True)
    return summary


# ----------------------------------------------------------------------------------------------
# arguments: every entry point called with hostile scalar arguments
# ----------------------------------------------------------------------------------------------
# Each call puts one hostile value (HOSTILE: huge and negative integers, bools, NumPy integers and
# bools, floats where integers are expected, NaN and inf, strings, None, odd objects; and a few
# valid values, so that the valid paths run too) into one argument of one entry point, over a
# small, an empty or a one-element batch, an outer pair of 10^5-element batches (10^10 answers), or
# a huge one (np.broadcast_to 10^15 rows: a view that must never be copied); the calls over the last
# two are stopped by a progress callback once the work starts. The calls run
# in children of ARGUMENT_MEMORY bytes of address space. A finding: a crash, a hang, an exception
# other than TypeError, ValueError, MemoryError and IndexError (KeyError where the argument is a
# scene shape's name), a message with pybind11's "Unable to cast" or "incompatible function
# arguments", or a MemoryError not in the library's words (std::bad_alloc, NumPy's "Unable to
# allocate": memory really asked for) or after the process really grew by ARGUMENT_GROWTH bytes.
HOSTILE = ("2**62", "2**63", "2**64+1", "10**30", "-2**63-1", "-1", "0", "1", "3", "True", "False",
           "np.int64(2**62)", "np.uint64(2**64-1)", "np.int8(-1)", "np.intc(2)", "np.bool_(True)", "np.bool_(False)",
           "1.5", "2.0", "1e300", "-0.0", "nan", "inf", "-inf", "np.float64(3.0)", "np.float32('nan')",
           "np.longdouble('1e4000')", "'3'", "''", "'float64'", "None", "b'1'", "[1]", "[]", "(2, 3)",
           "np.array(2**62)", "np.array([1, 2])", "np.zeros((0,))", "1+0j", "fractions.Fraction(1, 3)",
           "decimal.Decimal('1e400')", "object()")
BATCHES = ("small", "empty", "one", "outer", "huge")
HUGE = 10**15
POSITIONS = ("p", "p0", "p1", "origin", "center", "control_points")  # the fields a translation moves
# entry point -> the arguments hostile values go into
ARGUMENTS = {
    "distance": ("a", "workers", "precision", "solver", "progress"),
    "closest_points": ("b", "workers", "precision"),
    "within": ("d", "workers", "solver"),
    "intersects": ("workers", "progress"),
    "distance_if_within": ("d", "workers"),
    "nearest": ("k", "workers", "a", "precision"),
    "pairs_within": ("d", "workers", "max_pairs", "b"),
    "Scene.nearest": ("k", "shape"),
    "Scene.within": ("d", "shape"),
    "Scene.pairs_within": ("d", "workers", "max_pairs"),
    "constructor": ("field", "sweep", "copy"),
    "indexing": ("key", "slice", "tuple"),
    "dask.pairs_within": ("d", "tiles", "workers"),
}
ARGUMENT_MEMORY = 2 << 30
ARGUMENT_GROWTH = 256 << 20
ALLOWED_ERRORS = (TypeError, ValueError, MemoryError, IndexError)


def generate_arguments(seed: int, count: int):
    rng = np.random.default_rng(seed)
    entries = sorted(ARGUMENTS)
    for index in range(count):
        entry = entries[rng.integers(0, len(entries))]
        slot = ARGUMENTS[entry][rng.integers(0, len(ARGUMENTS[entry]))]
        yield {"index": index, "entry": entry, "argument": slot, "value": HOSTILE[rng.integers(0, len(HOSTILE))],
               "batch": BATCHES[rng.integers(0, len(BATCHES))],
               "kind": THREAD_KINDS[rng.integers(0, len(THREAD_KINDS))]}


class _Stopped(Exception):
    """Raised by the progress callback of the calls over huge batches: the work had begun."""


def _stop(done, total):
    raise _Stopped


def _hostile(text):
    """The value HOSTILE's text names (evaluated: the text is the reproducer)."""
    import decimal
    import fractions

    return eval(text, {"np": np, "decimal": decimal, "fractions": fractions, "nan": math.nan, "inf": math.inf})


def _argument_batch(cd, kind, batch, column=False):
    """A batch of kind: 3 elements, none, one, 10^5 (as a column (10^5, 1) or a row (1, 10^5): an
    outer pair of them asks for 10^10 answers), or 10^15 (broadcast views, which copy=False must
    refuse without copying; a point batch as the bare view, which a query converts)."""
    fields = _shape(np.random.default_rng(1), kind, 1.0, [0.0, 0.0, 0.0])
    if kind == "arc":
        fields.update(normal=[0.0, 0.0, 1.0], start=[1.0, 0.0, 0.0], angle=1.0)
    if kind == "annulus":
        fields.update(inner_radius=0.5, outer_radius=1.0)
    if kind in ("circle", "disk", "arc"):
        fields.update(radius=1.0)
    fields.pop("sweep", None)
    rows = {"small": (3,), "empty": (0,), "one": None, "outer": (10**5, 1) if column else (1, 10**5),
            "huge": (HUGE,)}[batch]
    arrays = {k: np.asarray(v, dtype=float) for k, v in fields.items()}
    if rows is not None:
        arrays = {k: np.broadcast_to(v, (*rows, *v.shape)) for k, v in arrays.items()}
    if batch == "huge" and kind == "point":
        return arrays["p"]
    if batch not in ("huge", "one"):
        # Elements spread over a box of side 1000 (coincident ones would tie in every query)
        offset = np.random.default_rng(2 + column).uniform(0, 1000, (*rows, 3))
        arrays = {k: np.ascontiguousarray(v + (offset if v.ndim == len(rows) + 1 else offset[..., None, :])
                                          if k in POSITIONS else v) for k, v in arrays.items()}
    return getattr(cd, kind.capitalize())(*arrays.values(), copy=False)


def _argument_call(cd, case):
    """The call of one case (a function of no arguments, which builds its batches too), or None
    when the case cannot be stopped (a huge batch without the progress callback)."""
    value = _hostile(case["value"])
    entry, slot, batch = case["entry"], case["argument"], case["batch"]
    big = batch in ("huge", "outer")
    if big and (entry.startswith("Scene.") or entry.startswith("dask.") or slot == "progress"):
        return None  # no callback stops these: a huge batch would run for days
    if big and entry == "pairs_within" and slot == "max_pairs":
        return None  # the memory a large max_pairs lets pairs_within hold is what the caller asked for
    progress = _stop if big else None
    if entry in ("distance", "closest_points", "within", "intersects", "distance_if_within", "nearest", "pairs_within"):
        def call():
            fn = getattr(cd, entry)
            args = {"a": _argument_batch(cd, case["kind"], batch, column=True),
                    "b": _argument_batch(cd, "point", "small" if batch == "huge" else batch)}
            if entry in ("within", "distance_if_within", "pairs_within"):
                args["d"] = 1.0
            if entry == "nearest":
                args["k"] = 2
            kw = {"progress": progress}
            if entry == "pairs_within" and big:
                kw["max_pairs"] = 10**6  # the default (10^8 pairs, 1.6 GB) fills the child's memory
            if slot in args:
                args[slot] = value
            else:
                kw[slot] = value
            return fn(*args.values(), **kw)
        return call
    if entry.startswith("Scene."):
        def call():
            a = _argument_batch(cd, case["kind"], batch)
            b = _argument_batch(cd, "point", batch)
            scene = cd.Scene()
            if batch != "empty":
                for i, shape in enumerate([a[0], a[-1], b[0]] if batch != "one" else [a, b]):
                    scene.add(f"s{i}", shape)
            query = b[0] if batch not in ("one", "empty") else cd.Point([0.0, 0.0, 0.0])
            args = {"shape": query, "k": 2} if entry == "Scene.nearest" else {"shape": query, "d": 1.0} \
                if entry == "Scene.within" else {"d": 1.0}
            kw = {}
            if slot in args:
                args[slot] = value
            else:
                kw[slot] = value
            return getattr(scene, entry.split(".")[1])(*args.values(), **kw)
        return call
    if entry == "constructor":
        def call():
            a = _argument_batch(cd, case["kind"], "small" if big else batch)
            arrays = {k: np.asarray(v) for k, v in a.to_arrays().items() if k != "sweep"}
            if big:  # every field a broadcast view of 10^15 rows: refused, never copied
                arrays = {k: np.broadcast_to(v[0], (HUGE, *v.shape[1:])) for k, v in arrays.items()}
            kw = {"copy": bool(rng_choice(case, 2))}
            if slot == "field":
                arrays[sorted(arrays)[rng_choice(case, len(arrays))]] = value
            else:
                kw[slot] = value
            return type(a)(*arrays.values(), **kw)
        return call
    if entry == "indexing":
        def call():
            a = _argument_batch(cd, case["kind"], "small" if batch == "huge" else batch, column=True)
            key = value if slot == "key" else slice(value) if slot == "slice" else (value, Ellipsis)
            return a[key]
        return call

    def call():
        import circledist.dask as cdd  # dask.pairs_within: generated only where dask is installed

        fields = _argument_batch(cd, case["kind"], batch).to_arrays()
        sweep = fields.pop("sweep", None)
        args = {"a": getattr(cdd, case["kind"].capitalize())(*fields.values(), sweep=sweep),
                "b": np.asarray(_argument_batch(cd, "point", batch).to_arrays()["p"]), "d": 1.0}
        kw = {"tiles": 2} if slot != "tiles" else {}
        if slot in args:
            args[slot] = value
        else:
            kw[slot] = value
        import dask

        return dask.compute(*cdd.pairs_within(*args.values(), **kw))
    return call


def rng_choice(case, n):
    """A choice among n made from the case's index (the case stays a plain record)."""
    return case["index"] * 2654435761 % (2**32) % n


def _peak_bytes(reset=False):
    """The process's peak resident size; with reset, the peak is first set back to the current
    size where the system allows it (Linux: /proc/self/clear_refs), so that growth is measured
    from now even in a process that peaked higher before (a test suite's)."""
    try:
        if reset:
            with open("/proc/self/clear_refs", "w") as f:
                f.write("5")
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def run_argument_case(cd, case):
    """None, or a finding (a dict with its detail) for one hostile call."""
    call = _argument_call(cd, case)
    if call is None:
        return None
    where = f"{case['entry']}({case['argument']})"
    peak = _peak_bytes(reset=True)
    try:
        call()
    except _Stopped:
        return None
    except ALLOWED_ERRORS + (KeyError,) as error:
        text = str(error)
        if isinstance(error, KeyError) and not (case["entry"].startswith("Scene.") and case["argument"] == "shape"
                                                and isinstance(_hostile(case["value"]), str)):
            return {"finding": f"{where}: KeyError", "detail": text[:500]}
        if "Unable to cast" in text or "incompatible function arguments" in text:
            return {"finding": f"{where}: pybind11's words", "detail": f"{type(error).__name__}: {text[:500]}"}
        if isinstance(error, MemoryError):
            grown = _peak_bytes() - peak
            if grown > ARGUMENT_GROWTH:
                return {"finding": f"{where}: MemoryError after growing {grown >> 20} MiB", "detail": text[:500]}
            if not text or "bad_alloc" in text:
                return {"finding": f"{where}: MemoryError in C++'s words", "detail": text[:500]}
        return None
    except Exception as error:  # noqa: BLE001 (the finding)
        return {"finding": f"{where}: {type(error).__name__}", "detail": f"{error!s}"[:500]}
    return None


def fuzz_arguments(count, seed, chunk, timeout, python=sys.executable, progress=False):
    """count hostile calls, chunk by chunk in children held to ARGUMENT_MEMORY; a summary as
    fuzz()'s, with the calls per entry point."""
    import importlib.util

    summary = {"cases": 0, "crashes": 0, "hangs": 0, "findings": 0, "examples": [], "classes": {}}
    dask = importlib.util.find_spec("dask") is not None
    cases = (c for c in generate_arguments(seed, count) if dask or not c["entry"].startswith("dask."))
    with tempfile.TemporaryDirectory() as tmp:
        while True:
            todo = [c for _, c in zip(range(chunk), cases)]
            if not todo:
                break
            for c in todo:
                summary["classes"][c["entry"]] = summary["classes"].get(c["entry"], 0) + 1
            _run_chunk(todo, "arguments", python, timeout, tmp, summary, memory=ARGUMENT_MEMORY)
            if progress:
                print(f"  {summary['cases']} calls, {summary['crashes']} crashes, {summary['hangs']} hangs, "
                      f"{summary['findings']} findings", file=sys.stderr, flush=True)
    return summary


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "--child":
        child(*argv[1:5])
        return 0
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=15)
    parser.add_argument("--chunk", type=int, default=2000)
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--report")
    parser.add_argument("--batched", action="store_true",
                        help="run each chunk's cases of one kind pair and query as one batched call (the long mode)")
    parser.add_argument("--files", type=int, metavar="N",
                        help="instead: the command line on N hostile files (FIFOs, devices, zip bombs, lying .npy "
                             "headers, deep nesting, surrogates, huge counts, odd compression, foreign members, "
                             "truncated and flipped files), each in a process held to 1 GiB and 60 s")
    parser.add_argument("--threads", type=int, metavar="N",
                        help="instead: N scenarios of a Scene shared by 3-5 threads that add and query it at "
                             "once, each in its own child held to --timeout seconds (at most 120), every answer "
                             "checked against serial scenes")
    parser.add_argument("--arguments", type=int, metavar="N",
                        help="instead: N calls of the entry points with hostile scalar arguments (huge integers, "
                             "bools, NumPy scalars, floats, NaN, strings, None; small, empty and 10^15-row "
                             "broadcast batches), --chunk calls per child held to 2 GiB")
    args = parser.parse_args(argv)
    t0 = time.time()
    if args.threads is not None:
        summary = fuzz_threads(args.threads, args.seed, progress=True, timeout=min(args.timeout, THREAD_TIMEOUT))
    elif args.arguments is not None:
        summary = fuzz_arguments(args.arguments, args.seed, args.chunk, args.timeout, progress=True)
    elif args.files is not None:
        summary = fuzz_files(args.files, args.seed, progress=True)
    else:
        summary = fuzz(args.cases, args.seed, args.chunk, args.timeout, progress=True, batched=args.batched)
    summary["seconds"] = round(time.time() - t0, 1)
    text = json.dumps(summary, indent=1)
    print(text)
    if args.report:
        open(args.report, "w").write(text)
    return 0 if summary["crashes"] == summary["hangs"] == summary["findings"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
