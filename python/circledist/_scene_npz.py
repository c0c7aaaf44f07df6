"""Scene files: the NumPy .npz form, read member by member within a memory budget."""

from __future__ import annotations

from dataclasses import dataclass
import json
import math
from typing import Optional
import zipfile
import zlib

try:
    import lzma
except ImportError:  # a Python built without it: zipfile cannot inflate lzma either
    lzma = None

import numpy as np

from ._schema import shown
from .scene import MAX_CONTROL_POINTS, ROLE_TRAILING_DIMS
from ._scene_format import (
    FORMAT,
    KINDS,
    SceneFile,
    SceneFileError,
    ShapeEntry,
    VERSION,
    VERSIONS,
    _NPZ_TOP,
    _SWEEP,
    _check_bytes,
    _check_directions,
    _check_shape_count,
    _check_texts,
    _column,
    _error,
    _open_regular,
    _roles,
    _text,
    _validator,
    schema,
)
from ._scene_queries import _check_names, _check_queries
from ._scene_json import _check_kind_version, _nested_too_deeply, _not_json_constant


# ------------------------------------------------------------------------------------------
# npz
# ------------------------------------------------------------------------------------------
# Strings that must equal one of a few words (the format, a kind): a longer string dtype is refused
# from the header, before its data is read.
_WORD_CHARS = 64


def _npz_string(arrays, name: str, file: str, required: bool = True, word: bool = False) -> Optional[str]:
    if name not in arrays:
        if required:
            raise _error(file, f"array {name!r}", "missing (a 0-d string array)")
        return None
    a = arrays.header(name)
    if a.dtype.kind != "U" or a.ndim != 0 or (word and a.dtype.itemsize > 4 * _WORD_CHARS):
        raise _error(
            file,
            f"array {name!r}",
            f"expected a 0-d string array{' of a word' if word else ''}, " f"got dtype {a.dtype} shape {a.shape}",
        )
    return _text(str(arrays[name][()]), file, f"array {name!r}")


def _npz_integer(arrays, name: str, file: str) -> Optional[int]:
    if name not in arrays:
        return None
    a = arrays.header(name)
    if a.dtype.kind not in "iu" or a.ndim != 0:
        raise _error(file, f"array {name!r}", f"expected a 0-d integer array, got dtype {a.dtype} shape {a.shape}")
    return int(arrays[name][()])


def _npz_index(where: str, at) -> str:
    return where + (" at index " + ", ".join(str(int(i)) for i in at) if len(at) else "")


def _npz_field(arrays, key: str, role: str, count: Optional[int], file: str, where: str) -> np.ndarray:
    """A field's array: its dtype and shape checked from the header, then its values."""
    trailing = ROLE_TRAILING_DIMS[role]
    a = arrays.header(key)
    if a.dtype.kind not in "fiu":
        raise _error(file, where, f"expected an array of real numbers (float or integer), got dtype {a.dtype}")
    ndims = (trailing,) if count is None else (trailing, trailing + 1)
    shape_ok = a.ndim in ndims
    inner = a.shape[a.ndim - trailing :] if trailing else ()
    if role in ("vector", "direction"):
        shape_ok = shape_ok and inner == (3,)
    if role == "control_points":
        shape_ok = shape_ok and inner[1:] == (3,) and 2 <= inner[0] <= MAX_CONTROL_POINTS
    if not shape_ok:
        rows = "" if count is None else "[rows (count or 1)] + "
        wanted = {
            "vector": "(3,)",
            "direction": "(3,)",
            "length": "()",
            "angle": "()",
            "control_points": f"(m, 3), m from 2 to {MAX_CONTROL_POINTS}",
        }[role]
        raise _error(file, where, f"expected shape {rows}{wanted}, got {a.shape}")
    if count is not None and a.ndim == trailing + 1 and a.shape[0] not in (count, 1):
        raise _error(file, where, f"expected {count} rows (the batch's count) or 1, got {a.shape[0]}")
    array = arrays[key].astype(np.float64, copy=False)
    bad = ~np.isfinite(array)
    if role == "length":
        bad |= array < 0
    if role == "angle":
        bad |= ~((array > 0) & (array <= 2 * math.pi))
    if bad.any():
        at = np.unravel_index(int(np.argmax(bad)), bad.shape) if bad.ndim else ()
        what = {"length": "a finite number >= 0", "angle": "an angle in (0, 2 pi]"}.get(role, "a finite number")
        raise _error(file, _npz_index(where, at), f"expected {what}, got {float(array[at])!r}")
    if role == "direction":
        _check_directions(array, file, where, _npz_index)
    return _column(array, role, count, file, where, "rows")


def scene_from_npz(path: str, file: Optional[str] = None) -> SceneFile:
    """Validates a .npz scene; `file` is the name messages give (default: path)."""
    file = path if file is None else file
    with _open_regular(path, file) as handle:
        return _scene_from_npz_handle(handle, file)


def _scene_from_npz_handle(handle, file: str) -> SceneFile:
    """scene_from_npz on an open binary file."""
    if handle.read(len(np.lib.format.MAGIC_PREFIX)) == np.lib.format.MAGIC_PREFIX:
        raise SceneFileError(f"{file}: not a NumPy .npz file: it holds one array (.npy), not named arrays")
    handle.seek(0)
    try:
        archive = zipfile.ZipFile(handle)
    except _ZIP_ERRORS as e:
        raise SceneFileError(f"{file}: not a NumPy .npz file: {e}") from None
    with archive:
        return _scene_from_npz(_NpzArrays(archive, file), file)


def _scene_from_npz(arrays: "_NpzArrays", file: str) -> SceneFile:
    names = set(arrays.names)
    fmt = _npz_string(arrays, "format", file, word=True)
    if fmt != FORMAT:
        raise _error(file, "array 'format'", f'expected "{FORMAT}", got {shown(fmt)}')
    version = _npz_integer(arrays, "version", file)
    if version is None:
        raise _error(file, "array 'version'", f"missing (a 0-d integer; this circledist reads versions 1 to {VERSION})")
    if version > VERSION:
        raise _error(
            file,
            "array 'version'",
            f"version {version} is newer than this circledist reads " f"(versions 1 to {VERSION}): upgrade circledist",
        )
    if version not in VERSIONS:
        raise _error(file, "array 'version'", f"expected one of {', '.join(map(str, VERSIONS))}, got {version}")
    description = _npz_string(arrays, "description", file, required=False) or ""
    if "shapes" not in names:
        raise _error(file, "array 'shapes'", "missing (a 1-d string array of the shapes' names, in order)")
    order = arrays.header("shapes")
    if order.dtype.kind != "U" or order.ndim != 1 or len(order) == 0:
        raise _error(
            file,
            "array 'shapes'",
            f"expected a non-empty 1-d string array of names, " f"got dtype {order.dtype} shape {order.shape}",
        )
    order = arrays["shapes"].tolist()
    _check_texts(order, file, lambda i: f"array 'shapes' at index {i}")
    name_error = _validator().first_error
    for i, n in enumerate(order):
        if name_error(n, {"$ref": "#/$defs/name"}):
            raise _error(
                file,
                f"array 'shapes' at index {i}",
                f"expected a non-empty name without '[', ']' or '/', got {shown(n)}",
            )
    _check_names(order, file, lambda i: f"array 'shapes' at index {i}")
    known = set(_NPZ_TOP)
    entries = []
    shapes_so_far = 0
    for name in order:
        kind = _npz_string(arrays, f"{name}/kind", file, word=True)
        if kind not in KINDS:
            raise _error(file, f"array {name + '/kind'!r}", f"expected one of {', '.join(KINDS)}, got {shown(kind)}")
        _check_kind_version(kind, version, file, f"array {name + '/kind'!r}")
        count = _npz_integer(arrays, f"{name}/count", file)
        if count is not None and count < 1:
            raise _error(file, f"array {name + '/count'!r}", f"expected an integer >= 1, got {count}")
        shapes_so_far += 1 if count is None else count
        _check_shape_count(shapes_so_far, count, file, f"array {name + '/count'!r}")
        roles = _roles(kind)
        known |= {f"{name}/kind", f"{name}/count"} | {f"{name}/{f}" for f in roles}
        fields = {}
        for f, role in roles.items():
            key = f"{name}/{f}"
            if key not in names:
                if f != _SWEEP:
                    raise _error(file, f"array {key!r}", f"missing (a {kind} needs {', '.join(KINDS[kind][1])})")
                fields[f] = np.zeros(()) if count is None else np.zeros(count)
                continue
            fields[f] = _npz_field(arrays, key, role, count, file, f"array {key!r}")
        entry = ShapeEntry(name, kind, count, fields)
        try:
            entry.shape()
        except ValueError as e:
            raise _error(file, f"arrays {name + '/...'!r}", str(e)) from None
        entries.append(entry)
    for key in sorted(names - known):
        raise _error(
            file,
            f"array {key!r}",
            "unknown: not a field of a shape listed in 'shapes' nor one of " + ", ".join(_NPZ_TOP),
        )
    queries = []
    text = _npz_string(arrays, "queries", file, required=False)
    if text is not None:
        where = "array 'queries'"
        try:
            specs = json.loads(text, parse_constant=_not_json_constant)
        except ValueError as e:
            raise _error(file, where, f"expected the JSON text of a list of queries: {e}") from None
        except RecursionError:
            raise _error(
                file, where, "expected the JSON text of a list of queries, got values nested " "too deeply"
            ) from None
        try:
            error = _validator().first_error({"queries": specs}, {"properties": schema()["properties"]})
            if error:
                raise _error(file, f"{where}: {error[0]}", error[1])
            queries = _check_queries(specs, entries, file, prefix=f"{where}: ", version=version)
        except RecursionError:
            raise _nested_too_deeply(specs, file, f"{where}: $.queries") from None
    return SceneFile(file, description, entries, queries)


# What reading a damaged zip may raise: zipfile's own errors, the inflaters' (zlib.error for a
# corrupt deflate stream; lzma's and bz2's are an LZMAError and an OSError), numpy's for a bad header.
_ZIP_ERRORS = (ValueError, OSError, zipfile.BadZipFile, EOFError, RuntimeError, NotImplementedError, zlib.error) + (
    (lzma.LZMAError,) if lzma is not None else ()
)
_NPY_HEADERS = {(1, 0): np.lib.format.read_array_header_1_0, (2, 0): np.lib.format.read_array_header_2_0}
# The compression methods zipfile inflates here (bzip2 and lzma only where Python has the module).
_ZIP_METHODS = (
    {zipfile.ZIP_STORED, zipfile.ZIP_DEFLATED}
    | ({zipfile.ZIP_BZIP2} if getattr(zipfile, "bz2", None) is not None else set())
    | ({zipfile.ZIP_LZMA} if getattr(zipfile, "lzma", None) is not None else set())
)


@dataclass(frozen=True)
class _Header:
    """An array's dtype and shape as its .npy header gives them: what the checks of an array's
    role read (dtype, shape, ndim, len), before its data is."""

    dtype: np.dtype
    shape: tuple

    @property
    def ndim(self) -> int:
        return len(self.shape)

    def __len__(self) -> int:
        return self.shape[0]


class _NpzArrays:
    """The arrays of an .npz (a zip of .npy members), each read on first use, its header first.

    The header (numpy.lib.format) gives the dtype and shape without inflating the data: `header`
    returns them for the reader to check against what the array's role allows, and their size
    (shape times item size) must match the
    member's uncompressed size, so that a member is only inflated once its shape is known to be
    one the scene can hold and the data to be what the header says (a small zip that would
    inflate to gigabytes, or a header claiming 10^12 elements, is refused before any of it is
    read)."""

    def __init__(self, archive: zipfile.ZipFile, file: str):
        self.archive, self.file, self.cache, self.headers = archive, file, {}, {}
        self.members = {}
        for info in archive.infolist():
            if info.is_dir():
                continue
            where = f"member {shown(info.filename)}"
            if info.compress_type not in _ZIP_METHODS:
                raise _error(
                    file,
                    where,
                    f"compressed with zip method {info.compress_type}, which this reader "
                    f"cannot inflate (numpy.savez stores, numpy.savez_compressed deflates)",
                )
            # An array's name: the member's without ".npy" (numpy.load's names; a member of another
            # name is read, as numpy.load reads it, under its own and must hold a .npy too).
            name = info.filename[:-4] if info.filename.endswith(".npy") else info.filename
            self.members[name] = info
        self.names = frozenset(self.members)

    def __contains__(self, key):
        return key in self.names

    def _fail(self, key, message):
        return _error(self.file, f"array {key!r}", message)

    def header(self, key) -> "_Header":
        """The array's dtype and shape, checked against the member's size."""
        if key in self.headers:
            return self.headers[key]
        info = self.members[key]
        try:
            with self.archive.open(info) as stream:
                magic = stream.read(len(np.lib.format.MAGIC_PREFIX) + 2)
                if len(magic) < 8 or not magic.startswith(np.lib.format.MAGIC_PREFIX):
                    raise self._fail(
                        key,
                        "expected a plain NumPy array (.npy): the member does not start with " "NumPy's magic string",
                    )
                version = (magic[-2], magic[-1])
                if version not in _NPY_HEADERS:
                    raise self._fail(key, f"expected a .npy header of version 1.0 or 2.0, got {version}")
                shape, fortran, dtype = _NPY_HEADERS[version](stream)
                offset = stream.tell()
        except SceneFileError:
            raise
        except _ZIP_ERRORS as e:
            raise self._fail(key, f"expected a plain NumPy array (.npy): {e}") from None
        if dtype.hasobject:
            raise self._fail(
                key, f"expected a plain NumPy array: dtype {dtype} holds Python objects, " f"which are not read"
            )
        size = math.prod(shape) * dtype.itemsize
        if size != info.file_size - offset:
            raise self._fail(
                key,
                f"its header says shape {shape} of dtype {dtype} ({size} bytes), the member "
                f"holds {info.file_size - offset} bytes of data",
            )
        _check_bytes(size, self.file, f"array {key!r}", f"an array of shape {shape}, dtype {dtype}")
        self.headers[key] = header = _Header(dtype, tuple(shape))
        return header

    def __getitem__(self, key):
        if key not in self.cache:
            self.header(key)
            try:
                with self.archive.open(self.members[key]) as stream:
                    self.cache[key] = np.lib.format.read_array(stream, allow_pickle=False)
            except _ZIP_ERRORS as e:
                raise self._fail(key, f"expected a plain NumPy array: {e}") from None
        return self.cache[key]
