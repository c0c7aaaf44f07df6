"""Hostile files: the command line on files made to break a reader (``--files``)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from .common import _limit_memory


# ----------------------------------------------------------------------------------------------
# hostile files: the command line on files made to break a reader
# ----------------------------------------------------------------------------------------------
# Files a reader must refuse: each run as `python -m circledist FILE --no-plot` in a process held to
# FILE_MEMORY bytes of address space and FILE_TIMEOUT seconds; a finding is anything but exit
# status 2 with one line "circledist: error: FILE: ..." on stderr and nothing on stdout (the
# mutated classes may also be valid: exit 0 then).
FILE_CLASSES = (
    "fifo",
    "device",
    "zip_bomb",
    "lying_header",
    "deep_json",
    "deep_queries",
    "surrogate",
    "huge_count",
    "compression",
    "foreign_member",
    "truncated",
    "flipped",
)
MUST_REFUSE = set(FILE_CLASSES) - {"truncated", "flipped"}
FILE_TIMEOUT = 60.0
_FILE_SCENE = {
    "format": "circledist-scene",
    "version": 3,
    "description": "hostile",
    "shapes": [
        {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1},
        {"name": "dust", "kind": "point", "count": 3, "p": [[0, 0, 2], [1, 0, 2], [2, 0, 2]]},
        {"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]},
    ],
    "queries": [{"a": "rail", "b": "ring", "effects": ["distance"]}, {"a": "dust[1]", "effects": ["nearest"], "k": 2}],
}
_NPZ_ROLES = {
    "format": ("<U", ()),
    "version": ("<i8", ()),
    "shapes": ("<U", (3,)),
    "queries": ("<U", ()),
    "ring/kind": ("<U", ()),
    "ring/center": ("<f8", (3,)),
    "ring/radius": ("<f8", ()),
    "dust/count": ("<i8", ()),
    "dust/p": ("<f8", (3, 3)),
    "rail/direction": ("<f8", (3,)),
}


def _npz_arrays():
    arrays = {
        "format": np.array("circledist-scene"),
        "version": np.array(3),
        "description": np.array("hostile"),
        "shapes": np.array(["ring", "dust", "rail"]),
        "queries": np.array(json.dumps(_FILE_SCENE["queries"])),
    }
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
            zeros = size  # under a scalar's header too: a member declaring one value over 32 MiB
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
        target = {
            "shapes": (doc, "shapes"),
            "description": (doc, "description"),
            "center": (doc["shapes"][0], "center"),
            "p": (doc["shapes"][1], "p"),
            "queries": (doc, "queries"),
            "effects": (doc["queries"][0], "effects"),
        }.get(place)
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
                data[at + offset : at + offset + 2] = method.to_bytes(2, "little")
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


def run_file_case(path, kind, python=sys.executable):
    """None, or what is wrong with the command line's answer to the file."""
    try:
        proc = subprocess.run(
            [python, "-m", "circledist", path, "--no-plot"],
            capture_output=True,
            text=True,
            timeout=FILE_TIMEOUT,
            preexec_fn=_limit_memory,
            stdin=subprocess.DEVNULL,
        )
    except subprocess.TimeoutExpired:
        return "hang", ""
    err = proc.stderr
    if proc.returncode == 0 and kind not in MUST_REFUSE:
        return None
    if proc.returncode != 2:
        return f"exit {proc.returncode}", err[-2000:]
    if not err.startswith(f"circledist: error: {path}: ") or err.count("\n") != 1 or "Traceback" in err or proc.stdout:
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
                summary["examples"].append(
                    {"finding": found[0], "case": {"index": index, "class": kind, "file": what}, "stderr": found[1]}
                )
            if progress:
                print(
                    f"  {index} {kind} ({what[:60]}): {found[0] if found else 'ok'} {time.time() - start:.1f} s",
                    file=sys.stderr,
                    flush=True,
                )
    return summary
