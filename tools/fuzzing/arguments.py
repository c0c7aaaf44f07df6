"""Arguments: every entry point called with hostile scalar arguments (``--arguments``)."""

from __future__ import annotations

import math
import sys
import tempfile

import numpy as np

from .runner import _run_chunk
from .cases import _shape
from .threads import THREAD_KINDS


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
HOSTILE = (
    "2**62",
    "2**63",
    "2**64+1",
    "10**30",
    "-2**63-1",
    "-1",
    "0",
    "1",
    "3",
    "True",
    "False",
    "np.int64(2**62)",
    "np.uint64(2**64-1)",
    "np.int8(-1)",
    "np.intc(2)",
    "np.bool_(True)",
    "np.bool_(False)",
    "1.5",
    "2.0",
    "1e300",
    "-0.0",
    "nan",
    "inf",
    "-inf",
    "np.float64(3.0)",
    "np.float32('nan')",
    "np.longdouble('1e4000')",
    "'3'",
    "''",
    "'float64'",
    "None",
    "b'1'",
    "[1]",
    "[]",
    "(2, 3)",
    "np.array(2**62)",
    "np.array([1, 2])",
    "np.zeros((0,))",
    "1+0j",
    "fractions.Fraction(1, 3)",
    "decimal.Decimal('1e400')",
    "object()",
)
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
        yield {
            "index": index,
            "entry": entry,
            "argument": slot,
            "value": HOSTILE[rng.integers(0, len(HOSTILE))],
            "batch": BATCHES[rng.integers(0, len(BATCHES))],
            "kind": THREAD_KINDS[rng.integers(0, len(THREAD_KINDS))],
        }


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
    rows = {"small": (3,), "empty": (0,), "one": None, "outer": (10**5, 1) if column else (1, 10**5), "huge": (HUGE,)}[
        batch
    ]
    arrays = {k: np.asarray(v, dtype=float) for k, v in fields.items()}
    if rows is not None:
        arrays = {k: np.broadcast_to(v, (*rows, *v.shape)) for k, v in arrays.items()}
    if batch == "huge" and kind == "point":
        return arrays["p"]
    if batch not in ("huge", "one"):
        # Elements spread over a box of side 1000 (coincident ones would tie in every query)
        offset = np.random.default_rng(2 + column).uniform(0, 1000, (*rows, 3))
        arrays = {
            k: np.ascontiguousarray(
                v + (offset if v.ndim == len(rows) + 1 else offset[..., None, :]) if k in POSITIONS else v
            )
            for k, v in arrays.items()
        }
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
            args = {
                "a": _argument_batch(cd, case["kind"], batch, column=True),
                "b": _argument_batch(cd, "point", "small" if batch == "huge" else batch),
            }
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
            args = (
                {"shape": query, "k": 2}
                if entry == "Scene.nearest"
                else {"shape": query, "d": 1.0}
                if entry == "Scene.within"
                else {"d": 1.0}
            )
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
        args = {
            "a": getattr(cdd, case["kind"].capitalize())(*fields.values(), sweep=sweep),
            "b": np.asarray(_argument_batch(cd, "point", batch).to_arrays()["p"]),
            "d": 1.0,
        }
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
        if isinstance(error, KeyError) and not (
            case["entry"].startswith("Scene.")
            and case["argument"] == "shape"
            and isinstance(_hostile(case["value"]), str)
        ):
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
                print(
                    f"  {summary['cases']} calls, {summary['crashes']} crashes, {summary['hangs']} hangs, "
                    f"{summary['findings']} findings",
                    file=sys.stderr,
                    flush=True,
                )
    return summary
