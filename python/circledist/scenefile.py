"""Scene files: JSON (``.json``) and NumPy (``.npz``), read and written.

A scene file holds named shapes, each a single shape or a batch of one kind whose fields are
columns (NumPy broadcasting: a column holds one row per shape, or one value for all), and
queries naming the effects they want. The JSON form is specified by the JSON Schema shipped in
the package (``circledist/scene.schema.json``, see ``schema_text()``); the ``.npz`` form holds
the same content as arrays, for scenes of millions of shapes. ``python -m circledist --help``
summarizes both; README.md shows their use.

Format version 3 (version 2 without annuli, version 1 without arcs either). The version goes up with any change to what a valid
file may hold or to what it means (a new kind, field, effect or array, a changed default); a
reader refuses files of a newer version with a message saying so instead of misreading them, and
keeps reading older ones. A file of an older version may hold only what that version holds (an
arc in a version 1 file, an annulus in a version 2 one, is refused); `write_scene` writes the oldest version that holds the scene.
Files must say ``"format": "circledist-scene"`` and ``"version"``: without them a JSON file is
refused (the message says which two fields to add), so that a file is never read under a version
it was not written for.

Every error is a SceneFileError with a one-line message naming the file, where in it (a JSON
path such as ``$.shapes[3].radius``, or an array of the .npz and an index) and what was expected.
"""

from __future__ import annotations

import contextlib
import gc
from collections import Counter
import json
import math
import operator
import os
import re
import secrets
import stat
import zipfile
import zlib
from dataclasses import dataclass, field
from importlib import resources
from typing import Any, Iterable, Mapping, Optional

try:
    import lzma
except ImportError:  # a Python built without it: zipfile cannot inflate lzma either
    lzma = None

import numpy as np

from . import _core
from .scene import MAX_CONTROL_POINTS, ROLE_TRAILING_DIMS
from ._schema import Validator, member, shown

__all__ = ["FORMAT", "VERSION", "SceneFileError", "SceneFile", "ShapeEntry", "read_scene", "write_scene",
           "schema", "schema_text", "SCHEMA_RESOURCE"]

FORMAT = "circledist-scene"
VERSION = 3
# The versions this circledist reads: every one up to VERSION. Version 2 added the kind "arc",
# version 3 the kind "annulus"; a file says the first version that holds what it holds
# (write_scene writes that one, so that a scene without arcs stays readable by a circledist that
# reads version 1, and one without annuli by one that reads version 2).
VERSIONS = (1, 2, 3)
KIND_SINCE = {"arc": 2, "annulus": 3}
SCHEMA_RESOURCE = "scene.schema.json"   # inside the circledist package

# kind -> (class name, {field: role}), read from the module's one table of fields (src/shapes.hpp);
# roles: vector, direction (a non-zero vector), length (>= 0), angle (in (0, 2 pi]), control_points. The sweep (a length,
# default 0) comes on top of every kind.
KINDS = {kind.lower(): (kind, dict(fields)) for kind, fields in _core._shape_fields().items()}
_SWEEP, _SWEEP_ROLE = _core._sweep_field()


def _roles(kind: str) -> dict:
    """{field: role} of a kind's fields, the sweep last."""
    return {**KINDS[kind][1], _SWEEP: _SWEEP_ROLE}


PAIR_EFFECTS = ("intersects", "within", "distance", "closest_points")
SCENE_EFFECTS = ("nearest", "within", "intersects")
_REFERENCE = re.compile(r"^([^\[\]/]+)(?:\[(0|[1-9][0-9]*)\])?$")
_NPZ_TOP = ("format", "version", "description", "shapes", "queries")


# What str.splitlines breaks a line at.
_LINE_BREAKS = re.compile("[\n\r\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029]")


class SceneFileError(ValueError):
    """A bad scene file: its one-line message names the file, where in it (a JSON path such as
    ``$.shapes[3].radius``, or an ``.npz`` array and index), and what was expected.

    A ValueError, raised by `read_scene` and `write_scene`; the command line prints its message
    and exits with status 2.

    Parameters
    ----------
    message : str
        The one-line message.

    Attributes
    ----------
    args : tuple
        ``(message,)``, as for every exception.

    Examples
    --------
    >>> import circledist as cd
    >>> try:
    ...     cd.read_scene("scene.json", text='{"shapes": []}')
    ... except cd.SceneFileError as e:
    ...     print(str(e).split(":")[0])
    scene.json
    """

    def __init__(self, message: str):
        # One line whatever the file holds: a line break in a name, a key or the path is escaped.
        super().__init__(_LINE_BREAKS.sub(lambda m: repr(m.group())[1:-1], message))


def schema_text() -> str:
    """The JSON Schema (draft 2020-12) of JSON scene files, as shipped in the package."""
    return resources.files("circledist").joinpath(SCHEMA_RESOURCE).read_text(encoding="utf-8")


_VALIDATOR: Optional[Validator] = None


def schema() -> dict:
    return _validator().root


def _validator() -> Validator:
    global _VALIDATOR
    if _VALIDATOR is None:
        _VALIDATOR = Validator(json.loads(schema_text()))
    return _VALIDATOR


# ------------------------------------------------------------------------------------------
# the content, whatever the file type
# ------------------------------------------------------------------------------------------
@dataclass
class ShapeEntry:
    """One entry of a scene: a single shape (count None) or a batch of count shapes of one kind.
    fields: a mapping of field names to float64 arrays, sweep included; for a batch each has a
    leading axis of count rows (broadcast views where the file gave one value for all)."""

    name: str
    kind: str
    count: Optional[int]
    fields: dict

    @property
    def class_name(self) -> str:
        return KINDS[self.kind][0]

    def shape(self):
        """The library shape: single, or batched with batch shape (count,)."""
        names = list(KINDS[self.kind][1])
        return getattr(_core, self.class_name)(*(self.fields[n] for n in names), sweep=self.fields[_SWEEP])

    def element(self, index: int):
        """Shape `index` of a batch, as a single shape."""
        names = list(KINDS[self.kind][1])
        return getattr(_core, self.class_name)(*(self.fields[n][index] for n in names),
                                                sweep=self.fields[_SWEEP][index])

    def element_names(self) -> list:
        return [self.name] if self.count is None else [f"{self.name}[{i}]" for i in range(self.count)]


@dataclass
class SceneFile:
    """A validated scene file: its entries in file order, its queries (dicts with the keys name,
    a, b, effects, d, k; absent ones None) and its description."""

    path: str
    description: str
    entries: list
    queries: list = field(default_factory=list)

    def __post_init__(self):
        self._by_name = {e.name: e for e in self.entries}

    @property
    def count(self) -> int:
        """The number of shapes (a batch counts its shapes)."""
        return sum(1 if e.count is None else e.count for e in self.entries)

    @property
    def shapes(self) -> dict:
        """name -> library shape, a batch as one batched shape under the batch's name."""
        return {e.name: e.shape() for e in self.entries}

    def queries_as_written(self) -> list:
        """The queries as a file states them (no absent keys): for write_scene."""
        return [{k: v for k, v in q.items() if v is not None} for q in self.queries]

    def lookup(self, reference: str):
        """(entry, index) for 'name' (index None) or 'name[i]'; KeyError if there is no such shape."""
        m = _REFERENCE.match(reference)
        entry = self._by_name.get(m.group(1)) if m else None
        if entry is None:
            raise KeyError(f"no shape named {reference!r}")
        index = None if m.group(2) is None else int(m.group(2))
        if (index is None) != (entry.count is None) or (index is not None and index >= entry.count):
            raise KeyError(f"no shape named {reference!r}")
        return entry, index

    def shape(self, reference: str):
        """The single shape named `reference` ('name' or 'name[i]' for shape i of a batch)."""
        entry, index = self.lookup(reference)
        return entry.shape() if index is None else entry.element(index)

    def scene(self):
        """A circledist.Scene of every shape, in file order; shape i of batch b is named 'b[i]'."""
        from .scene import Scene

        names: list = []
        parts: list = []           # (kind, values, positions, swept): see Scene._insert
        rows: dict = {}            # id of a kind's columns -> (columns, [row, ...], [position, ...])
        singles: dict = {}         # (kind, trailing shapes) -> ([fields, ...], [position, ...])
        for e in self.entries:
            fields = e.fields
            if e.count is not None:
                values = [np.asarray(fields[f], dtype=np.float64) for f in _roles(e.kind)]
                parts.append((e.class_name, values, np.arange(len(names), len(names) + e.count), True))
                names.extend(e.element_names())
                continue
            if isinstance(fields, _RowFields):
                at = rows.setdefault(id(fields.columns), (e.class_name, fields.columns, [], []))
                at[2].append(fields.row)
            else:
                values = [np.asarray(fields[f], dtype=np.float64) for f in _roles(e.kind)]
                at = singles.setdefault((e.class_name,) + tuple(v.shape for v in values), ([], []))
                at[0].append(values)
            at[-1].append(len(names))
            names.append(e.name)
        for kind, columns, taken, positions in rows.values():
            parts.append((kind, [column[taken] for column in columns.values()], np.array(positions, np.int64), True))
        for (kind, *_), (values, positions) in singles.items():
            parts.append((kind, [np.stack(v) for v in zip(*values)], np.array(positions, np.int64), True))
        world = Scene()
        world._insert(names, parts, distinct=True)  # a validated file's names: strings, each of its own
        return world


def _error(path: str, where: str, message: str) -> SceneFileError:
    return SceneFileError(f"{path}: {where}: {message}")


def _text(value: str, file: str, where: str) -> str:
    """A string of the file that will be printed or written (a name, the description): refused
    if it holds a lone surrogate (JSON's "\\ud800", or such a code point in a NumPy string),
    which is no character and which no UTF-8 output can hold."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as e:
        raise _error(file, where, f"expected text, got a lone surrogate (U+{ord(value[e.start]):04X}) at "
                                  f"character {e.start}") from None
    return value


def _check_texts(values: list, file: str, where) -> None:
    """_text on each of many strings: one encoding of them all, each one's only on failure."""
    try:
        "".join(values).encode("utf-8")
    except UnicodeEncodeError:
        for i, value in enumerate(values):
            _text(value, file, where(i))


def _memory_budget() -> int:
    """The bytes a scene may take: the machine's physical memory, or the process's address space
    limit where that is lower."""
    budget = 1 << 62
    try:
        budget = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (AttributeError, ValueError, OSError):
        pass
    try:
        import resource

        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
        if soft != resource.RLIM_INFINITY:
            budget = min(budget, soft)
    except (ImportError, AttributeError, ValueError, OSError):
        pass
    return budget


def _gigabytes(size: int) -> str:
    return f"{size / 2**30:.3g} GiB"


# The memory a shape of a scene takes, in bytes, read and answered by the command line: the peak
# of `python -m circledist` on a batch of 10^6 and 3 * 10^6 points or circles and a nearest query
# is 715 to 745 bytes a shape (Bezier curves of 8 points: 840 to 880), mostly its name as a Python
# string, the Scene's index and the reader's columns. The lowest (points) is the estimate: a file
# it refuses could not be read.
SHAPE_BYTES = 700


def _check_shape_count(total: int, count: Optional[int], file: str, where: str) -> None:
    """Refuses a file whose shapes (total so far, a batch's count included) would take more than
    the memory there is, before any array or name of them is made."""
    need = total * SHAPE_BYTES
    budget = _memory_budget()
    if need > budget:
        raise _error(file, where, f"a count of {count} makes a scene of {total} shapes, which needs about "
                                  f"{_gigabytes(need)}, more than the {_gigabytes(budget)} of memory there is")


def _check_bytes(size: int, file: str, where: str, what: str) -> None:
    budget = _memory_budget()
    if size > budget:
        raise _error(file, where, f"{what} takes {_gigabytes(size)}, more than the {_gigabytes(budget)} of "
                                  f"memory there is")


def _finite_array(value: Any, file: str, where: str) -> np.ndarray:
    """A JSON value (numbers, nested lists, already schema-checked) as float64; the first number
    that is not a finite double is reported with its path."""
    try:
        array = np.asarray(value, dtype=np.float64)
    except OverflowError:  # an integer literal too large for a double
        array = None
    if array is not None and np.isfinite(array).all():
        return array

    def first_bad(v, at):
        if isinstance(v, list):
            for i, item in enumerate(v):
                found = first_bad(item, f"{at}[{i}]")
                if found:
                    return found
            return None
        try:
            return None if math.isfinite(float(v)) else (at, v)
        except OverflowError:
            return at, v

    at, v = first_bad(value, where)
    raise _error(file, at, f"expected a finite number (within a double's range), got {shown(v)}")


def _check_directions(array: np.ndarray, file: str, where: str, index_text) -> None:
    zero = ~np.any(array != 0, axis=-1)
    if zero.any():
        at = np.unravel_index(int(np.argmax(zero)), zero.shape) if zero.ndim else ()
        raise _error(file, index_text(where, at), "expected a non-zero vector, got [0, 0, 0]")


def _check_angles(array: np.ndarray, file: str, where: str, index_text) -> None:
    bad = ~((array > 0) & (array <= 2 * math.pi))
    if bad.any():
        at = np.unravel_index(int(np.argmax(bad)), bad.shape) if bad.ndim else ()
        raise _error(file, index_text(where, at), f"expected an angle in (0, 2 pi], got {float(array[at])!r}")


def _json_index(where: str, at) -> str:
    return where + "".join(f"[{i}]" for i in at)


def _column(array: np.ndarray, role: str, count: Optional[int], file: str, where: str, rows_word: str):
    """Checks a batch column's rows (count or 1, or none: one value for all) and broadcasts it to
    (count, ...); a single shape's field as is."""
    trailing = ROLE_TRAILING_DIMS[role]
    if count is None:
        return array
    if array.ndim == trailing + 1:
        rows = array.shape[0]
        if rows not in (count, 1):
            raise _error(file, where, f"expected {count} {rows_word} (the batch's count) or 1, got {rows}")
        trailing_shape = array.shape[1:]
    else:
        trailing_shape = array.shape
        array = array[None]
    return np.broadcast_to(array, (count,) + trailing_shape)


def _entry_from_json(spec: dict, i: int, file: str) -> ShapeEntry:
    kind = spec["kind"]
    count = None if "count" not in spec else int(spec["count"])
    roles = _roles(kind)
    base = f"$.shapes[{i}]"
    fields = {}
    for name, role in roles.items():
        where = member(base, name)
        value = spec.get(name, 0)
        if role == "control_points" and count is not None and isinstance(value[0][0], list):
            sizes = [len(cp) for cp in value]
            for j, size in enumerate(sizes):
                if size != sizes[0]:
                    raise _error(file, f"{where}[{j}]", f"expected {sizes[0]} control points as curve 0 has "
                                 f"(a batch's curves have one degree), got {size}")
        array = _finite_array(value, file, where)
        if role == "direction":
            _check_directions(array, file, where, _json_index)
        elif role == "angle":
            _check_angles(array, file, where, _json_index)
        rows_word = {"length": "numbers", "angle": "numbers", "control_points": "curves"}.get(role, "vectors")
        fields[name] = _column(array, role, count, file, where, rows_word)
    entry = ShapeEntry(spec["name"], kind, count, fields)
    try:
        entry.shape()
    except ValueError as e:  # anything the library still refuses
        raise _error(file, base, str(e)) from None
    return entry


class _RowFields(Mapping):
    """A single shape's fields as a read-only mapping onto row `row` of columns (field -> array)."""

    __slots__ = ("columns", "row")

    def __init__(self, columns: dict, row: int):
        self.columns, self.row = columns, row

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name][self.row, ...]

    def __iter__(self):
        return iter(self.columns)

    def __len__(self) -> int:
        return len(self.columns)


def _float_column(values: list) -> np.ndarray:
    """Equal-shaped JSON values as one float64 array; a value holding an integer beyond a double's
    range becomes NaN (to be found bad as any other non-finite row)."""
    try:
        return np.array(values, dtype=np.float64)
    except OverflowError:
        rows = []
        for value in values:
            try:
                rows.append(np.asarray(value, dtype=np.float64))
            except OverflowError:
                rows.append(np.full(np.shape(value), np.nan))
        return np.array(rows)


def _refused_rows(kind: str, columns: dict, rows: int) -> np.ndarray:
    """Per shape of `rows` shapes of a kind, given as float64 columns (field -> array of a leading
    axis of rows, the sweep included): whether a reader refuses it for a number that is not finite,
    a zero direction or a length below 0 (which the schema refuses in a file); every shape when
    the library refuses the others (an error the entries' one by one check then finds and words)."""
    bad = np.zeros(rows, bool)
    for name, role in _roles(kind).items():
        column = columns[name]
        finite = np.isfinite(column)
        if not finite.all():  # rows by rows only then (the reduction by rows is the check's dearest step)
            bad |= ~finite.reshape(rows, -1).all(axis=1)
        if role == "direction":
            bad |= ~np.any(column != 0, axis=-1)
        elif role == "length":
            bad |= column < 0
        elif role == "angle":
            bad |= ~((column > 0) & (column <= 2 * math.pi))
    # The rows left, as views where none is bad (a masked copy of 10^6 rows costs more than the check).
    good = slice(None) if not bad.any() else ~bad
    try:
        getattr(_core, KINDS[kind][0])(*(columns[n][good] for n in KINDS[kind][1]), sweep=columns[_SWEEP][good])
    except ValueError:
        bad[:] = True
    return bad


def _entries_from_json(shapes: list, file: str) -> list:
    """The entries of schema-valid shape specs, in file order, each checked as _entry_from_json
    checks it. Single shapes are checked together, a NumPy column per kind and field (a scene of
    10^5 single shapes would spend seconds on 10^5 small arrays): every entry before the first
    one a column shows to be bad is taken from the columns, and from there on each entry goes
    through _entry_from_json, which raises the error the file's first bad entry has."""
    groups: dict = {}  # (kind, control points) -> indices of the single shapes
    for i, spec in enumerate(shapes):
        if "count" not in spec:
            kind = spec["kind"]
            groups.setdefault((kind, len(spec["control_points"]) if kind == "bezier" else 0), []).append(i)
    first_bad = len(shapes)
    rows: dict = {}  # index -> (fields' columns, row)
    for (kind, _), indices in groups.items():
        specs = [shapes[i] for i in indices]
        columns = {}
        for name in _roles(kind):
            columns[name] = _float_column([spec.get(name, 0) for spec in specs])
            columns[name].flags.writeable = False
        bad = _refused_rows(kind, columns, len(indices))
        if bad.any():
            first_bad = min(first_bad, indices[int(np.argmax(bad))])
        for row, i in enumerate(indices[:int(np.argmax(bad)) if bad.any() else len(indices)]):
            rows[i] = (columns, row)
    entries = []
    for i, spec in enumerate(shapes):
        if i < first_bad and i in rows:
            columns, row = rows[i]
            entries.append(ShapeEntry(spec["name"], spec["kind"], None, _RowFields(columns, row)))
        else:
            entries.append(_entry_from_json(spec, i, file))
    return entries


# ------------------------------------------------------------------------------------------
# queries (the same in both file types)
# ------------------------------------------------------------------------------------------
def _check_queries(specs: list, entries: list, file: str, prefix: str = "") -> list:
    """Semantic checks of schema-valid queries; returns them as dicts with every key."""
    by_name = {e.name: e for e in entries}
    supported = {tuple(p) for p in _core._query_kinds()}
    # Entries and shapes of each kind, for the checks against the whole scene: counted once (a
    # count per query made q queries over n shapes cost q * n).
    entries_of_kind: Counter = Counter()
    shapes_of_kind: Counter = Counter()
    for e in entries if specs else ():
        kind = e.class_name
        entries_of_kind[kind] += 1
        shapes_of_kind[kind] += 1 if e.count is None else e.count
    out = []
    for i, spec in enumerate(specs):
        base = f"{prefix}$.queries[{i}]"
        if "name" in spec:
            _text(spec["name"], file, member(base, "name"))

        def fail(key, message):
            return _error(file, member(base, key) if key else base, message)

        refs = {}
        for key in ("a", "b"):
            if key not in spec:
                continue
            m = _REFERENCE.match(spec[key])
            entry = by_name.get(m.group(1))
            if entry is None:
                raise fail(key, f"expected the name of a shape of the scene, got {shown(spec[key])}")
            index = None if m.group(2) is None else int(m.group(2))
            if entry.count is not None and index is None:
                raise fail(key, f"expected one shape: {entry.name!r} is a batch of {entry.count}, name one "
                                f"as {entry.name}[i] with i from 0 to {entry.count - 1}")
            if entry.count is None and index is not None:
                raise fail(key, f"expected a shape's name: {entry.name!r} is a single shape, not a batch")
            if index is not None and index >= entry.count:
                raise fail(key, f"expected an index from 0 to {entry.count - 1} (batch {entry.name!r} has "
                                f"{entry.count} shapes), got {index}")
            refs[key] = (entry, index)
        effects = spec["effects"]
        if "pairs_within" in effects:
            if effects != ["pairs_within"]:
                raise fail("effects", "expected pairs_within alone (it is a query of its own)")
            for key in ("a", "b", "k"):
                if key in spec:
                    raise fail(key, "not expected: pairs_within takes no shapes and no k")
            kinds = sorted(shapes_of_kind)
            for i_kind, ka in enumerate(kinds):
                for kb in kinds[i_kind:]:
                    single = ka == kb and shapes_of_kind[ka] < 2
                    if not single and (ka, kb) not in supported:
                        raise fail("effects", f"expected a scene whose every pair of kinds has a query: none "
                                              f"exists between a {ka} and a {kb}")
        else:
            if "a" not in spec:
                raise fail(None, "missing field 'a' (the shape the query is about)")
            allowed = PAIR_EFFECTS if "b" in spec else SCENE_EFFECTS
            for e in effects:
                if e not in allowed:
                    against = "a pair (with 'b')" if "b" in spec else "the rest of the scene (without 'b')"
                    raise fail("effects", f"expected effects against {against}: {', '.join(allowed)}; "
                                          f"got {shown(e)}")
            a_entry, a_index = refs["a"]
            if "b" in spec:
                others = [refs["b"][0].class_name]
            else:  # every kind in the scene but the query's own shape
                own = a_entry.class_name if a_entry.count is None or a_entry.count == 1 else None
                others = {kind for kind, n in entries_of_kind.items() if n > (kind == own)}
            for kb in sorted(others):
                if (a_entry.class_name, kb) not in supported:
                    raise fail("b" if "b" in spec else "a", f"expected shapes circledist has a query between: "
                                                              f"none exists between a {a_entry.class_name} and a {kb}")
            if "k" in spec and "nearest" not in effects:
                raise fail("k", "not expected: only nearest takes k")
        needs_d = "within" in effects or "pairs_within" in effects
        if needs_d and "d" not in spec:
            raise fail(None, "missing field 'd' (the distance of within / pairs_within)")
        if not needs_d and "d" in spec:
            raise fail("d", "not expected: only within and pairs_within take a distance")
        d = None
        if "d" in spec:
            d = float(_finite_array(spec["d"], file, member(base, "d")))
        out.append({"name": spec.get("name"), "a": spec.get("a"), "b": spec.get("b"), "effects": list(effects),
                    "d": d, "k": int(spec["k"]) if "k" in spec else None})
    return out


def _check_names(names: Iterable[str], file: str, where) -> None:
    seen = set()
    for i, name in enumerate(names):
        if name in seen:
            raise _error(file, where(i), f"expected a name of its own, got {shown(name)}, used by an earlier shape")
        seen.add(name)


# ------------------------------------------------------------------------------------------
# JSON
# ------------------------------------------------------------------------------------------
def _not_json_constant(name: str):
    raise ValueError(f"{name} is not a JSON number")


def _check_format(data: dict, file: str, prefix: str = "$") -> None:
    """The format marker and version, checked before the schema: a newer version is reported as
    such, not as whatever its new content breaks in version 1."""
    fmt, version = data.get("format"), data.get("version")
    if "format" not in data:
        raise _error(file, prefix, f"missing field 'format': a circledist scene starts with "
                                   f"\"format\": \"{FORMAT}\", \"version\": {VERSION}")
    if fmt != FORMAT:
        raise _error(file, member(prefix, "format"), f"expected \"{FORMAT}\", got {shown(fmt)}")
    if "version" not in data:
        raise _error(file, prefix, f"missing field 'version' (this circledist reads versions 1 to {VERSION})")
    if isinstance(version, (int, float)) and not isinstance(version, bool) and version > VERSION \
            and float(version).is_integer():
        raise _error(file, member(prefix, "version"), f"version {int(version)} is newer than this circledist "
                                                      f"reads (versions 1 to {VERSION}): upgrade circledist")


def _check_kind_version(kind: str, version: int, file: str, where: str) -> None:
    """A kind newer than the file's version (an arc in a version 1 file) is refused."""
    since = KIND_SINCE.get(kind, 1)
    if version < since:
        raise _error(file, where, f"kind {kind!r} needs format version {since} or later, the file says version "
                                  f"{int(version)}")


def _file_version(kinds: Iterable[str]) -> int:
    """The oldest version that holds shapes of these kinds."""
    return max([1] + [KIND_SINCE.get(k, 1) for k in kinds])


def _parse_json(text: str, file: str) -> Any:
    try:
        return json.loads(text, parse_constant=_not_json_constant)
    except json.JSONDecodeError as e:
        raise SceneFileError(f"{file}: not valid JSON: {e.msg} at line {e.lineno}, column {e.colno}") from None
    except RecursionError:
        raise SceneFileError(f"{file}: not a scene: JSON nested too deeply") from None
    except ValueError as e:  # NaN / Infinity, an integer literal past Python's digit limit
        raise SceneFileError(f"{file}: not valid JSON: {e}") from None


# Deeper than any valid scene nests ($.shapes[i].control_points[j][k] is five levels): reported as
# such where a recursion over the document meets its depth.
_MAX_DEPTH = 32


def _nested_too_deeply(data: Any, file: str, prefix: str) -> SceneFileError:
    """The error for a document nested deeper than Python's recursion reaches: the path where it
    passes _MAX_DEPTH levels (found without recursion)."""
    stack = [(data, prefix, 0)]
    while stack:
        value, path, depth = stack.pop()
        if depth > _MAX_DEPTH:
            shown_path = path if len(path) <= 120 else path[:117] + "..."
            return _error(file, shown_path, f"expected a scene, got values nested more than {_MAX_DEPTH} deep")
        if isinstance(value, dict):
            stack.extend((v, member(path, k), depth + 1) for k, v in reversed(list(value.items())))
        elif isinstance(value, list):
            stack.extend((v, f"{path}[{i}]", depth + 1) for i, v in reversed(list(enumerate(value))))
    return _error(file, prefix, "expected a scene, got values nested too deeply")


def scene_from_json(data: Any, file: str) -> SceneFile:
    """Validates parsed JSON (schema, then what a schema cannot say) into a SceneFile."""
    if not isinstance(data, dict):
        raise _error(file, "$", f"expected an object with \"format\": \"{FORMAT}\", \"version\" and \"shapes\", "
                                f"got {shown(data)}")
    try:
        return _scene_from_json(data, file)
    except RecursionError:  # nesting that only a recursion (the validator's, a message's) meets
        raise _nested_too_deeply(data, file, "$") from None


def _scene_from_json(data: dict, file: str) -> SceneFile:
    _check_format(data, file)
    error = _validator().first_error(data)
    if error:
        where, message = error
        m = re.match(r"^\$\.shapes\[(\d+)\]", where)
        if m:  # the shape's name helps find it in a long file
            spec = data["shapes"][int(m.group(1))]
            if isinstance(spec, dict) and isinstance(spec.get("name"), str) and where != m.group(0) + ".name":
                where += f" (shape {spec['name']!r})"
        raise _error(file, where, message)
    shapes = data["shapes"]
    for i, s in enumerate(shapes):
        _check_kind_version(s["kind"], data["version"], file, f"$.shapes[{i}].kind (shape {s['name']!r})")
    _check_names((s["name"] for s in shapes), file, lambda i: f"$.shapes[{i}].name")
    _check_texts([s["name"] for s in shapes], file, lambda i: f"$.shapes[{i}].name")
    _text(data.get("description", ""), file, "$.description")
    total = 0
    for i, s in enumerate(shapes):
        total += int(s.get("count", 1))
        if "count" in s:
            _check_shape_count(total, int(s["count"]), file, f"$.shapes[{i}].count (shape {s['name']!r})")
    entries = _entries_from_json(shapes, file)
    queries = _check_queries(data.get("queries", []), entries, file)
    return SceneFile(file, data.get("description", ""), entries, queries)


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
        raise _error(file, f"array {name!r}", f"expected a 0-d string array{' of a word' if word else ''}, "
                                              f"got dtype {a.dtype} shape {a.shape}")
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
    inner = a.shape[a.ndim - trailing:] if trailing else ()
    if role in ("vector", "direction"):
        shape_ok = shape_ok and inner == (3,)
    if role == "control_points":
        shape_ok = shape_ok and inner[1:] == (3,) and 2 <= inner[0] <= MAX_CONTROL_POINTS
    if not shape_ok:
        rows = "" if count is None else "[rows (count or 1)] + "
        wanted = {"vector": "(3,)", "direction": "(3,)", "length": "()", "angle": "()",
                  "control_points": f"(m, 3), m from 2 to {MAX_CONTROL_POINTS}"}[role]
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
        raise _error(file, "array 'format'", f"expected \"{FORMAT}\", got {shown(fmt)}")
    version = _npz_integer(arrays, "version", file)
    if version is None:
        raise _error(file, "array 'version'", f"missing (a 0-d integer; this circledist reads versions 1 to {VERSION})")
    if version > VERSION:
        raise _error(file, "array 'version'", f"version {version} is newer than this circledist reads "
                                              f"(versions 1 to {VERSION}): upgrade circledist")
    if version not in VERSIONS:
        raise _error(file, "array 'version'", f"expected one of {', '.join(map(str, VERSIONS))}, got {version}")
    description = _npz_string(arrays, "description", file, required=False) or ""
    if "shapes" not in names:
        raise _error(file, "array 'shapes'", "missing (a 1-d string array of the shapes' names, in order)")
    order = arrays.header("shapes")
    if order.dtype.kind != "U" or order.ndim != 1 or len(order) == 0:
        raise _error(file, "array 'shapes'", f"expected a non-empty 1-d string array of names, "
                                             f"got dtype {order.dtype} shape {order.shape}")
    order = arrays["shapes"].tolist()
    _check_texts(order, file, lambda i: f"array 'shapes' at index {i}")
    name_error = _validator().first_error
    for i, n in enumerate(order):
        if name_error(n, {"$ref": "#/$defs/name"}):
            raise _error(file, f"array 'shapes' at index {i}",
                         f"expected a non-empty name without '[', ']' or '/', got {shown(n)}")
    _check_names(order, file, lambda i: f"array 'shapes' at index {i}")
    known = set(_NPZ_TOP)
    entries = []
    shapes_so_far = 0
    for name in order:
        kind = _npz_string(arrays, f"{name}/kind", file, word=True)
        if kind not in KINDS:
            raise _error(file, f"array {name + '/kind'!r}",
                         f"expected one of {', '.join(KINDS)}, got {shown(kind)}")
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
        raise _error(file, f"array {key!r}", "unknown: not a field of a shape listed in 'shapes' nor one of "
                                             + ", ".join(_NPZ_TOP))
    queries = []
    text = _npz_string(arrays, "queries", file, required=False)
    if text is not None:
        where = "array 'queries'"
        try:
            specs = json.loads(text, parse_constant=_not_json_constant)
        except ValueError as e:
            raise _error(file, where, f"expected the JSON text of a list of queries: {e}") from None
        except RecursionError:
            raise _error(file, where, "expected the JSON text of a list of queries, got values nested "
                                      "too deeply") from None
        try:
            error = _validator().first_error({"queries": specs}, {"properties": schema()["properties"]})
            if error:
                raise _error(file, f"{where}: {error[0]}", error[1])
            queries = _check_queries(specs, entries, file, prefix=f"{where}: ")
        except RecursionError:
            raise _nested_too_deeply(specs, file, f"{where}: $.queries") from None
    return SceneFile(file, description, entries, queries)


# What reading a damaged zip may raise: zipfile's own errors, the inflaters' (zlib.error for a
# corrupt deflate stream; lzma's and bz2's are an LZMAError and an OSError), numpy's for a bad header.
_ZIP_ERRORS = (ValueError, OSError, zipfile.BadZipFile, EOFError, RuntimeError, NotImplementedError, zlib.error) \
    + ((lzma.LZMAError,) if lzma is not None else ())
_NPY_HEADERS = {(1, 0): np.lib.format.read_array_header_1_0, (2, 0): np.lib.format.read_array_header_2_0}
# The compression methods zipfile inflates here (bzip2 and lzma only where Python has the module).
_ZIP_METHODS = {zipfile.ZIP_STORED, zipfile.ZIP_DEFLATED} \
    | ({zipfile.ZIP_BZIP2} if getattr(zipfile, "bz2", None) is not None else set()) \
    | ({zipfile.ZIP_LZMA} if getattr(zipfile, "lzma", None) is not None else set())


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
                raise _error(file, where, f"compressed with zip method {info.compress_type}, which this reader "
                                          f"cannot inflate (numpy.savez stores, numpy.savez_compressed deflates)")
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
                    raise self._fail(key, "expected a plain NumPy array (.npy): the member does not start with "
                                          "NumPy's magic string")
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
            raise self._fail(key, f"expected a plain NumPy array: dtype {dtype} holds Python objects, "
                                  f"which are not read")
        size = math.prod(shape) * dtype.itemsize
        if size != info.file_size - offset:
            raise self._fail(key, f"its header says shape {shape} of dtype {dtype} ({size} bytes), the member "
                                  f"holds {info.file_size - offset} bytes of data")
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


# ------------------------------------------------------------------------------------------
# reading and writing
# ------------------------------------------------------------------------------------------
_FILE_TYPES = ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
               (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
               (stat.S_ISSOCK, "a socket"))


def _open_regular(path, file: str):
    """The file at path opened for binary reading, refused unless it is a regular file: a FIFO
    would block the reader until something writes to it, a device such as /dev/zero would be
    read until memory runs out. The file is opened without blocking (a FIFO's open waits for a
    writer otherwise) and its type read from the open descriptor (no window between a check
    and the open)."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
    except OSError as e:
        raise SceneFileError(f"{file}: cannot read the scene file: {e.strerror}") from None
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):
            what = next((word for test, word in _FILE_TYPES if test(mode)), "not a regular file")
            raise SceneFileError(f"{file}: cannot read the scene file: it is {what}, not a regular file")
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


def read_scene(path: str, text: Optional[str] = None) -> SceneFile:
    """Reads and validates a scene file, JSON or ``.npz``.

    The format (``circledist --help``, and the JSON Schema ``scene.schema.json`` in the package):
    ``"format": "circledist-scene"``, ``"version": 1`` (or 2, which arcs need, or 3, which annuli need), the shapes (single
    or batches) and the queries.

    Parameters
    ----------
    path : str or os.PathLike
        The file: an ``.npz`` (a zip) is read as one, anything else as JSON.
    text : str, optional
        JSON content given directly; `path` then only names it in messages.

    Returns
    -------
    SceneFile
        Its ``entries`` (shapes and batches in file order), ``queries``, ``description``;
        ``shapes`` maps each name to a circledist shape (a batch to one batched shape).

    Raises
    ------
    SceneFileError
        For a file that cannot be read or is not a valid scene, naming the file, the place in
        it and what was expected.

    Examples
    --------
    >>> import circledist as cd
    >>> ring = '{"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}'
    >>> scene = cd.read_scene("ring.json", text='{"format": "circledist-scene", "version": 1, '
    ...                                         '"shapes": [' + ring + ']}')
    >>> scene.shapes["ring"]
    Circle(center=array([0., 0., 0.]), normal=array([0., 0., 1.]), radius=array(1.))
    """
    if text is None:
        with _open_regular(path, path) as f:
            try:
                head = f.read(4)
                if head.startswith(b"PK") or str(path).endswith(".npz"):
                    f.seek(0)
                    return _scene_from_npz_handle(f, path)
                data = head + f.read()
            except OSError as e:
                raise SceneFileError(f"{path}: cannot read the scene file: {e.strerror}") from None
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as e:
            raise SceneFileError(f"{path}: not a UTF-8 text file (byte {e.start}: {e.reason})") from None
    with _collector_paused():
        return scene_from_json(_parse_json(text, path), path)


@contextlib.contextmanager
def _collector_paused():
    """Python's cycle collector off for a while: parsing and checking a large file makes millions
    of objects and no cycles, and each collection would walk them all (a fifth of the time for
    10^5 shapes)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def _entries_of(shapes) -> tuple[list, list]:
    """write_scene's entries, in order, and the columns that hold their numbers.

    Entries are [name, kind, count, fields], every number float64 (a float32 or long double
    field converted, as a reader reads it back): a single shape's fields as nested lists (its
    row of its group's columns, below), a batch's as arrays, columns of count rows or one value
    where every row agrees (bit for bit: -0.0 stays -0.0); a single shape's zero sweep and a
    batch's all-zero sweep are left out. The columns are (kind, {field: float64 array}, rows):
    one for the single shapes of each kind (and control point count), one per batch (its fields
    broadcast to count rows), for _written_scene_is_valid to check as a reader checks numbers."""
    items = shapes.items() if isinstance(shapes, Mapping) else shapes
    entries: list = []
    columns: list = []
    singles: dict = {}  # kind, or (kind, control points) -> ([the fields' arrays, ...], [entry, ...])
    fields_of = {kind: operator.attrgetter(*_roles(kind)) for kind in KINDS}
    for name, shape in items:
        if not isinstance(shape, _core.Shape):
            raise TypeError(f"write_scene: {name!r} must be a circledist shape, got {type(shape).__name__}")
        kind = shape.kind.lower()
        if shape.batch_shape == ():  # a single shape: in its group's columns, made lists with them
            values = fields_of[kind](shape)
            key = kind if kind != "bezier" else (kind, len(values[0]))
            group = singles.get(key)
            if group is None:
                group = singles[key] = ([], [])
            entry = [str(name), kind, None, None]
            group[0].append(values)
            group[1].append(entry)
            entries.append(entry)
            continue
        batch = tuple(shape.batch_shape)
        count = int(np.prod(batch, dtype=np.int64))
        fields, broadcast = {}, {}
        for f, role in _roles(kind).items():
            a = np.asarray(getattr(shape, f), dtype=np.float64)
            dims = ROLE_TRAILING_DIMS[role]
            trailing = a.shape[a.ndim - dims:] if dims else ()
            # A column: one row per shape, C order; one value if all rows agree.
            a = broadcast[f] = np.broadcast_to(a, batch + trailing).reshape((count,) + trailing)
            bits = a.view(np.uint64)  # bit for bit: -0.0 stays -0.0
            fields[f] = a[0] if count and (bits == bits[:1]).all() else a
        if not np.any(fields[_SWEEP]):
            del fields[_SWEEP]
        columns.append((kind, broadcast, count))
        entries.append([str(name), kind, count, fields])
    for values, group_entries in singles.values():
        kind = group_entries[0][1]
        group = {f: np.array(column, dtype=np.float64) for f, column in zip(_roles(kind), zip(*values))}
        columns.append((kind, group, len(group_entries)))
        for entry, row in zip(group_entries, zip(*[column.tolist() for column in group.values()])):
            entry[3] = fields = dict(zip(group, row))
            if fields[_SWEEP] == 0:
                del fields[_SWEEP]
    return entries, columns


def _written_scene_is_valid(entries: list, columns: list, queries: list, description) -> bool:
    """Whether a reader accepts the scene write_scene makes of _entries_of's entries and columns,
    the queries (as JSON gives them back) and the description, checked without the reader's
    per-entry work. The writer makes the kinds, the fields and their shapes from library shapes;
    what it does not control is checked here: the names (the schema's name, each of its own),
    the counts (>= 1), the numbers (finite, directions non-zero, lengths >= 0 and the library's
    other checks: a float32 or long double field made float64 may have overflowed or vanished),
    the description and the queries (schema and meaning, as a reader checks them).

    False sends write_scene to the reader's full check, which raises the reader's own error;
    True must imply that the reader accepts the file (tests/api/test_scene_file.py checks both on a
    corpus of scenes)."""
    if not entries or not isinstance(description, str):
        return False
    is_name = _validator().test(schema()["$defs"]["name"])
    names = [e[0] for e in entries]
    if not all(map(is_name, names)) or len(set(names)) != len(names):
        return False
    if any(count is not None and count < 1 for _, _, count, _ in entries):
        return False
    if any(_refused_rows(kind, group, rows).any() for kind, group, rows in columns):
        return False
    if queries:
        if not _validator().is_valid({"queries": queries}, {"properties": schema()["properties"]}):
            return False
        try:
            _check_queries(queries, [ShapeEntry(name, kind, count, {}) for name, kind, count, _ in entries], "")
        except SceneFileError:
            return False
    return True


def write_scene(path: str, shapes, queries: Iterable[Mapping] = (), description: str = "") -> None:
    """Writes a scene file, JSON or ``.npz`` by the path's suffix.

    The content is validated before the file is replaced (atomically): what is written can be
    read, and content no reader would accept raises the error `read_scene` would raise. (The
    shapes are checked where the writer does not make them valid itself: names, counts, numbers
    made float64; the queries as a reader checks them. The file is read back only where that
    check declines.)

    Parameters
    ----------
    path : str or os.PathLike
        Ends in ``.json`` or ``.npz`` (for large batches: arrays, no text).
    shapes : mapping or iterable of (str, Shape)
        Name -> circledist shape. A batched shape becomes a batch, flattened in C order (its
        shape i is ``name[i]`` in queries and answers); fields that hold one value for all are
        written once.
    queries : iterable of dict, optional
        As in the JSON format: ``{"a": ..., "b": ..., "effects": [...], "d": ..., "k": ...}``.
    description : str, optional
        Free text.

    Returns
    -------
    None

    Raises
    ------
    ValueError
        For a path with another suffix; SceneFileError (a ValueError) for content no reader
        would accept.

    Examples
    --------
    >>> import os, tempfile
    >>> import numpy as np
    >>> import circledist as cd
    >>> rings = cd.Circle(np.zeros((3, 3)), [0, 0, 1], [1.0, 2.0, 3.0])
    >>> path = os.path.join(tempfile.mkdtemp(), "rings.npz")
    >>> cd.write_scene(path, {"rings": rings}, [{"a": "rings[0]", "effects": ["nearest"]}])
    >>> cd.read_scene(path).count
    3
    """
    path = os.fspath(path)
    if not (path.endswith(".json") or path.endswith(".npz")):
        raise ValueError(f"write_scene: {path}: expected a path ending in .json or .npz")
    with _collector_paused():
        _write_scene(path, shapes, queries, description)


def _write_scene(path: str, shapes, queries: Iterable[Mapping], description: str) -> None:
    entries, columns = _entries_of(shapes)
    # The queries as a reader gets them back (JSON's types: lists, floats, string keys).
    queries = json.loads(json.dumps([dict(q) for q in queries]))
    if path.endswith(".json"):
        data = {"format": FORMAT, "version": _file_version(kind for _, kind, _, _ in entries)}
        if description:
            data["description"] = description
        data["shapes"] = []
        for name, kind, count, fields in entries:
            if count is None:  # fields already lists
                data["shapes"].append({"name": name, "kind": kind, **fields})
            else:
                data["shapes"].append({"name": name, "kind": kind, "count": count,
                                       **{f: a.tolist() for f, a in fields.items()}})
        if queries:
            data["queries"] = queries
        text = _json_text(data)
        if not _written_scene_is_valid(entries, columns, queries, description):
            scene_from_json(json.loads(text), path)  # raises the error a reader reports
        payload = text.encode("utf-8")
        _write_atomically(path, lambda f: f.write(payload))
        return
    arrays = {"format": np.array(FORMAT), "version": np.array(_file_version(e[1] for e in entries), dtype=np.int64),
              "shapes": np.array([e[0] for e in entries], dtype=str)}
    if description:
        arrays["description"] = np.array(description)
    for name, kind, count, fields in entries:
        arrays[f"{name}/kind"] = np.array(kind)
        if count is not None:
            arrays[f"{name}/count"] = np.array(count, dtype=np.int64)
        arrays.update({f"{name}/{f}": a for f, a in fields.items()})
    if queries:
        arrays["queries"] = np.array(json.dumps(queries))
    # What is written must read back. The writer's own check covers it without reading the file
    # (a 10^6-shape file is read in a second or two), except for names holding a NUL, which NumPy's
    # string arrays and the zip's member names cut short; where that check declines, the file is
    # read back before it replaces anything, so that the error raised is the reader's.
    fine = (_written_scene_is_valid(entries, columns, queries, description)
            and not any("\x00" in name for name, _, _, _ in entries))
    _write_atomically(path, lambda f: np.savez(f, **arrays),
                      check=None if fine else lambda tmp: scene_from_npz(tmp, path))


def _item_encoder():
    """json.dumps for many items: its C encoder made once (json.dumps makes one per call, a third
    of the time of a short item), or json.dumps where the C encoder is missing or differs."""
    make = getattr(json.encoder, "c_make_encoder", None)
    try:
        encoder = make(None, json.JSONEncoder().default, json.encoder.encode_basestring_ascii, None, ": ", ", ",
                       False, False, True)

        def encode(item) -> str:
            return "".join(encoder(item, 0))
        sample = {"name": "s\u00e9", "kind": "point", "p": [0.1, -0.0, 1e-300], "sweep": 2, "t": [True, None]}
        if encode(sample) == json.dumps(sample):
            return encode
    except TypeError:  # no C encoder (None), or one of another signature
        pass
    return json.dumps


def _json_text(data: dict) -> str:
    """A scene as JSON text: the top level one key a line, each shape and query on a line of its
    own (json.dumps with indent= would spend its time in the pure-Python encoder)."""
    lines = []
    encode = _item_encoder()
    for key, value in data.items():
        if key in ("shapes", "queries"):
            items = ",\n".join(["  " + encode(item) for item in value])
            lines.append(f" {json.dumps(key)}: [\n{items}\n ]")
        else:
            lines.append(f" {json.dumps(key)}: {json.dumps(value)}")
    return "{\n" + ",\n".join(lines) + "\n}\n"


def _temporary_beside(directory: str) -> tuple:
    """(descriptor, path) of a new file in directory, made as open() makes a file: the kernel
    applies the umask to mode 0o666 (tempfile.mkstemp's files are 0o600 whatever the umask)."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    while True:
        tmp = os.path.join(directory, f".circledist-{secrets.token_hex(8)}")
        try:
            return os.open(tmp, flags, 0o666), tmp
        except FileExistsError:
            continue


def _write_atomically(path: str, write, check=None) -> None:
    """Writes a whole file or nothing: a temporary file beside it, renamed into place. A new file
    gets the mode open() gives (0o666 less the umask); a file replaced keeps its mode."""
    directory = os.path.dirname(os.path.abspath(path))
    try:
        mode = stat.S_IMODE(os.stat(path).st_mode)
    except OSError:
        mode = None
    fd, tmp = _temporary_beside(directory)
    try:
        with os.fdopen(fd, "wb") as f:
            if mode is not None and hasattr(os, "fchmod"):
                os.fchmod(f.fileno(), mode)
            write(f)
        if check is not None:
            check(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
