"""Threads: one Scene shared by threads that add and query it at once (``--threads``)."""

from __future__ import annotations

import sys
import tempfile

import numpy as np

from .runner import _run_chunk
from .cases import _shape


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
THREAD_OPS = (
    "add",
    "extend",
    "pairs",
    "nearest",
    "within",
    "nearest_name",
    "within_name",
    "matrix",
    "shape",
    "pickle",
    "duplicate",
)
# Outcomes a valid query may have: an answer, or one of these errors (the serial scene must agree).
THREAD_ERRORS = ("TypeError", "ValueError", "KeyError", "MemoryError")


def generate_threads(seed: int, count: int):
    rng = np.random.default_rng(seed)
    for index in range(count):
        yield {
            "index": index,
            "seed": int(rng.integers(0, 2**63 - 1)),
            "shapes": int(rng.integers(8, 120)),
            "threads": int(rng.integers(3, 6)),
            "ops": int(rng.integers(10, 60)),
        }


def _scene_shapes(cd, rng, count):
    """count single shapes (fields as arrays), in runs of one layout (kind, dtype, sweep, control
    point count) that extend can add as one batch; a tenth far away or huge."""
    shapes, layout = [], None
    while len(shapes) < count:
        if layout is None or rng.random() < 0.6:
            layout = (
                THREAD_KINDS[rng.integers(0, len(THREAD_KINDS))],
                np.float32 if rng.random() < 0.15 else np.float64,
                rng.random() < 0.25,
            )
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
    if any(
        s.kind != shapes[0].kind
        or a.keys() != first.keys()
        or any(a[k].shape != first[k].shape or a[k].dtype != first[k].dtype for k in a)
        for s, a in zip(shapes, arrays)
    ):
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
    queries = (
        [cd.Point(rng.uniform(0, 10, 3))]
        + _scene_shapes(cd, rng, 3)
        + [cd.Line(rng.uniform(0, 10, 3), rng.normal(size=3)), cd.Point([1e12, -3e14, 2.0])]
    )
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
                        args = (
                            tuple(pick() for _ in range(int(r.integers(0, 4)))),
                            tuple(pick() for _ in range(int(r.integers(0, 4)))),
                        )
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
                return {
                    "finding": "pairs_within with max_pairs: an error no serial scene gives",
                    "detail": f"{op} with {before}..{after} shapes: {got}, serial: {expected}",
                }
            continue
        if not any(serial_answer(op, m) == got for m in range(before, after + 1)):
            return {
                "finding": f"{op[0]}: an answer no serial scene gives",
                "detail": f"{op} with {before}..{after} shapes: {str(got)[:500]}; serial: "
                f"{str(serial_answer(op, before))[:500]}",
            }
    final = [
        ("pairs", 1.0, 1, None),
        ("nearest", 0, 3),
        ("within", 1, 2.0),
        ("pickle", 0.5, "pickle"),
        ("pickle", 0.5, "deepcopy"),
        ("shape", n - 1),
    ]
    for op in final:
        got, expected = _outcome(_query(scene, op, names, queries)), serial_answer(op, n)
        if got != expected:
            return {
                "finding": f"the scene's end state: {op[0]} differs from the serial scene's",
                "detail": f"{op}: {str(got)[:500]}; serial: {str(expected)[:500]}",
            }
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
                print(
                    f"  {summary['cases']} scenarios, {summary['crashes']} crashes, {summary['hangs']} hangs, "
                    f"{summary['findings']} findings",
                    file=sys.stderr,
                    flush=True,
                )
    return summary
