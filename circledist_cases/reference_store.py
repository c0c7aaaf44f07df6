"""A recorded copy of the 50-digit references the tests use, so that a test run reads them instead
of recomputing them; they are written and checked by ``python -m tools.references``.

A reference function decorated with ``@stored`` is looked up by its name and the exact value of
its arguments (floats to the bit) in ``tests/references/NAME.json``. Each file records the hash
of the sources that computed it (``circledist_cases``'s reference modules and the module of the
function): when those change, the file is stale, the function computes again, and
``tests/package/test_reference_store.py`` fails until the references are recorded again. A
value not in the file is computed as if there were no file.

``CIRCLEDIST_REFERENCES`` chooses the mode:

* unset: read the recorded value, else compute; every value whose key falls in the sample
  (one in SAMPLE_EVERY, by key) is computed as well and must agree with the recorded one
  (close(): far below any bar, not to the bit);
* ``record``: compute every value and write it (``tools.references record``);
* ``verify``: compute every value and compare it with the recorded one
  (``tools.references verify``, run by ``bash tools/run.sh fuzz``);
* ``off``: compute every value, read and write nothing.

Values are stored exactly: an mpf as its sign, mantissa, exponent and bit count, a float as its
hexadecimal form, dataclasses by their fields.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import importlib
import json
import math
import os
import pathlib
import threading

import numpy as np

from . import reference_kit as K

ROOT = pathlib.Path(__file__).resolve().parent.parent
STORE = ROOT / "tests" / "references"
SAMPLE_EVERY = 16
REL = K.mpf("1e-30")  # close(): far below any bar, far above the references' last digits
MODES = ("", "record", "verify", "off")

_lock = threading.Lock()
_files: dict = {}  # name -> _File


class Mismatch(AssertionError):
    """A recorded reference differs from the value computed now."""


def mode() -> str:
    m = os.environ.get("CIRCLEDIST_REFERENCES", "")
    if m not in MODES:
        raise ValueError(f"CIRCLEDIST_REFERENCES must be one of {MODES[1:]} or unset, not {m!r}")
    return m


# ----------------------------------------------------------------------------------------------
# exact encoding of arguments (the key) and of values
# ----------------------------------------------------------------------------------------------
def _mpf_types():
    from mpmath import mp

    return (K.ctx.mpf, mp.mpf)


def encode(x):
    """A JSON value that decode() turns back into x exactly."""
    if x is None or isinstance(x, (bool, str)):
        return x
    if isinstance(x, (int, np.integer)):
        return {"i": str(int(x))}
    if isinstance(x, np.longdouble) and not isinstance(x, np.float64):
        p, q = x.as_integer_ratio() if math.isfinite(x) else (None, None)
        return {"ld": [str(p), str(q)] if p is not None else repr(float(x))}
    if isinstance(x, (float, np.floating)):
        return {"x": float(x).hex()}
    if isinstance(x, _mpf_types()):
        sign, man, exp, bc = x._mpf_
        return {"mp": [sign, hex(int(man)), int(exp), int(bc)], "ctx": "kit" if isinstance(x, K.ctx.mpf) else "mp"}
    if isinstance(x, np.ndarray):
        return {"nd": str(x.dtype), "shape": list(x.shape), "v": [encode(v) for v in x.ravel().tolist()]}
    if isinstance(x, tuple):
        return {"t": [encode(v) for v in x]}
    if isinstance(x, list):
        return [encode(v) for v in x]
    if isinstance(x, dict):
        return {"d": [[encode(k), encode(v)] for k, v in x.items()]}
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        cls = type(x)
        fields = {f.name: encode(getattr(x, f.name)) for f in dataclasses.fields(x)}
        return {"dc": f"{cls.__module__}:{cls.__qualname__}", "f": fields}
    raise TypeError(f"reference_store cannot record a {type(x).__name__}")


def decode(v):
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, list):
        return [decode(e) for e in v]
    if "i" in v:
        return int(v["i"])
    if "x" in v:
        return float.fromhex(v["x"])
    if "ld" in v:
        if isinstance(v["ld"], list):
            p, q = (int(s) for s in v["ld"])
            return np.longdouble(p) / np.longdouble(q)
        return np.longdouble(float(v["ld"]))
    if "mp" in v:
        from mpmath import mp
        from mpmath.libmp import MPZ

        sign, man, exp, bc = v["mp"]
        context = K.ctx if v["ctx"] == "kit" else mp
        return context.make_mpf((sign, MPZ(int(man, 16)), exp, bc))
    if "nd" in v:
        return np.array([decode(e) for e in v["v"]], dtype=v["nd"]).reshape(v["shape"])
    if "t" in v:
        return tuple(decode(e) for e in v["t"])
    if "d" in v:
        return {decode(k): decode(e) for k, e in v["d"]}
    if "dc" in v:
        module, qualname = v["dc"].split(":")
        cls = importlib.import_module(module)
        for part in qualname.split("."):
            cls = getattr(cls, part)
        return cls(**{k: decode(e) for k, e in v["f"].items()})
    raise ValueError(f"reference_store: unknown record {v!r}")


def close(a, b) -> bool:
    """The same value: numbers within REL of each other (an mpf) or one unit in the last place (a
    float: the rounding of an mpf that differs far below any bar), everything else equal. Not to
    the bit: the references place their brackets with NumPy's binary64 functions, whose last bit
    can differ between machines."""
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return type(a) is type(b) and len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(close(a[k], b[k]) for k in a)
    if dataclasses.is_dataclass(a) and dataclasses.is_dataclass(b):
        return type(a) is type(b) and close(dataclasses.asdict(a), dataclasses.asdict(b))
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return close(np.asarray(a).tolist(), np.asarray(b).tolist())
    number = (float, np.floating) + _mpf_types()
    if isinstance(a, number) and isinstance(b, number) and not isinstance(a, bool):
        if isinstance(a, (float, np.floating)) and isinstance(b, (float, np.floating)):
            return a == b or (math.isnan(a) and math.isnan(b)) or abs(a - b) <= np.spacing(max(abs(a), abs(b)))
        a, b = K.to_mp(a), K.to_mp(b)
        return a == b or abs(a - b) <= REL * max(abs(a), abs(b))
    return a == b


def key_of(args, kwargs) -> str:
    text = json.dumps([encode(list(args)), encode(dict(sorted(kwargs.items())))], sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:32]


# ----------------------------------------------------------------------------------------------
# the files
# ----------------------------------------------------------------------------------------------
def source_hash(sources) -> str:
    """The hash of what computes a stored function's values: the 50-digit toolkit and reference
    modules of circledist_cases (reference*.py, golden.py), the function's own module and the
    files it names besides (paths relative to the repository's root)."""
    here = pathlib.Path(__file__).resolve().parent
    files = {*here.glob("reference*.py"), here / "golden.py"} - {pathlib.Path(__file__).resolve()}
    files |= {ROOT / s for s in sources}
    h = hashlib.sha256()
    for f in sorted(files):
        h.update(f.relative_to(ROOT).as_posix().encode())
        h.update(f.read_bytes())
    return h.hexdigest()[:32]


class _File:
    def __init__(self, name: str, sources):
        self.path = STORE / f"{name}.json"
        self.sources = sorted(sources)
        self.source = source_hash(sources)
        self.values: dict = {}  # a stale file (other reference code recorded it) is not read
        if self.path.exists():
            data = json.loads(self.path.read_text())
            if data.get("source") == self.source:
                self.values = data["values"]
        self.new: dict = {}

    def write(self):
        """The values computed in record mode, added to those recorded now (another process of
        the same run may have written some since this one read the file), one per line, sorted,
        into CIRCLEDIST_REFERENCES_OUT (tools.references record: a folder it then moves into
        place) or else the file itself."""
        import fcntl

        out = pathlib.Path(os.environ.get("CIRCLEDIST_REFERENCES_OUT") or STORE)
        path = out / self.path.name
        out.mkdir(parents=True, exist_ok=True)
        (ROOT / "build").mkdir(exist_ok=True)
        with open(ROOT / "build" / "reference_store.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            values = {}
            if path.exists():
                data = json.loads(path.read_text())
                if data.get("source") == self.source:
                    values = data["values"]
            values.update(self.new)
            lines = [f"  {json.dumps(k)}: {json.dumps(values[k], sort_keys=True)}" for k in sorted(values)]
            head = f'{{\n"source": {json.dumps(self.source)},\n"sources": {json.dumps(self.sources)},\n'
            path.write_text(head + '"values": {\n' + ",\n".join(lines) + "\n}}\n")


def _file(name, sources) -> _File:
    with _lock:
        if name not in _files:
            _files[name] = _File(name, sources)
        return _files[name]


def stored(func=None, *, also=()):
    """The reference function func, its values read from (and recorded to) its file: NAME is its
    module's last part and its name (``reference_round.circle_circle``). also: the files (relative
    to circledist_cases) besides its module and the reference modules whose code its values
    depend on. In-process results are kept too (the same arguments are not recomputed)."""
    if func is None:
        return lambda f: stored(f, also=also)
    import sys

    name = f"{func.__module__.rsplit('.', 1)[-1]}.{func.__qualname__}"
    module = pathlib.Path(sys.modules[func.__module__].__file__).resolve().relative_to(ROOT).as_posix()
    sources = (module, *(f"circledist_cases/{f}" for f in also))
    memo: dict = {}

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        key = key_of(args, kwargs)
        if key in memo:
            return memo[key]
        m = mode()
        f = _file(name, sources) if m != "off" else None
        recorded = f.values.get(key) if f is not None and m != "record" else None
        if recorded is not None and (m == "" and int(key, 16) % SAMPLE_EVERY):
            value = decode(recorded)
        else:
            value = func(*args, **kwargs)
            if recorded is not None and not close(decode(recorded), value):
                raise Mismatch(
                    f"{name}: the recorded reference for {args!r} is {decode(recorded)!r}, computed now "
                    f"{value!r} (python -m tools.references record)"
                )
            if m == "record":
                f.new[key] = encode(value)
        memo[key] = value
        return value

    wrapper.store_name = name
    return wrapper


def write_recorded():
    """Writes every file that got new values (record mode)."""
    for f in _files.values():
        if f.new:
            f.write()
