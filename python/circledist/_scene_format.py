"""Scene files: the format's constants, errors, schema, and the content whatever the file type
(ShapeEntry, SceneFile, the checks on fields and columns, shapes from JSON). circledist.scenefile
is the public face.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from importlib import resources
import json
import math
import os
import re
import stat
from typing import Any, Mapping, Optional

import numpy as np

from . import _core
from ._schema import Validator, member, shown
from .scene import ROLE_TRAILING_DIMS


FORMAT = "circledist-scene"
VERSION = 4
# The versions this circledist reads: every one up to VERSION. Version 2 added the kind "arc",
# version 3 the kind "annulus", version 4 a query's motions ("motion", "motion_b") and the
# effects that use them; a file says the first version that holds what it holds (write_scene
# writes that one, so that a scene without arcs stays readable by a circledist that reads
# version 1, one without annuli by one that reads version 2, one without motions by version 3).
VERSIONS = (1, 2, 3, 4)
KIND_SINCE = {"arc": 2, "annulus": 3}
MOTION_SINCE = 4
SCHEMA_RESOURCE = "scene.schema.json"  # inside the circledist package

# kind -> (class name, {field: role}), read from the module's one table of fields (src/shapes.hpp);
# roles: vector, direction (a non-zero vector), length (>= 0), angle (in (0, 2 pi]), control_points. The
# sweep (a length,
# default 0) comes on top of every kind.
KINDS = {kind.lower(): (kind, dict(fields)) for kind, fields in _core._shape_fields().items()}
_SWEEP, _SWEEP_ROLE = _core._sweep_field()


def _roles(kind: str) -> dict:
    """{field: role} of a kind's fields, the sweep last."""
    return {**KINDS[kind][1], _SWEEP: _SWEEP_ROLE}


PAIR_EFFECTS = ("intersects", "within", "distance", "closest_points", "first_contact", "closest_approach")
SCENE_EFFECTS = ("nearest", "within", "intersects", "first_contact")
# The effects of moving shapes: a query asking for them carries a motion, and asks for no other.
MOTION_EFFECTS = ("first_contact", "closest_approach")
MOTION_FIELDS = ("translation", "rotation", "center")
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
        return getattr(_core, self.class_name)(
            *(self.fields[n][index] for n in names), sweep=self.fields[_SWEEP][index]
        )

    def element_names(self) -> list:
        return [self.name] if self.count is None else [f"{self.name}[{i}]" for i in range(self.count)]


@dataclass
class SceneFile:
    """A validated scene file: its entries in file order, its queries (dicts with the keys name,
    a, b, motion, motion_b, effects, d, k; absent ones None; motion and motion_b a
    circledist.Motion: the motion of a, of b) and its description."""

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
        """The queries as a file states them (no absent keys; motions as their three vectors):
        for write_scene."""
        return [
            {k: (_motion_as_written(v) if isinstance(v, _core.Motion) else v) for k, v in q.items() if v is not None}
            for q in self.queries
        ]

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
        parts: list = []  # (kind, values, positions, swept): see Scene._insert
        rows: dict = {}  # id of a kind's columns -> (columns, [row, ...], [position, ...])
        singles: dict = {}  # (kind, trailing shapes) -> ([fields, ...], [position, ...])
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


def _motion_as_written(motion) -> dict:
    """A single motion as a file states it: its three vectors as lists of floats."""
    arrays = motion.to_arrays()
    return {f: [float(x) for x in arrays[f]] for f in MOTION_FIELDS}


def _error(path: str, where: str, message: str) -> SceneFileError:
    return SceneFileError(f"{path}: {where}: {message}")


def _text(value: str, file: str, where: str) -> str:
    """A string of the file that will be printed or written (a name, the description): refused
    if it holds a lone surrogate (JSON's "\\ud800", or such a code point in a NumPy string),
    which is no character and which no UTF-8 output can hold."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as e:
        raise _error(
            file, where, f"expected text, got a lone surrogate (U+{ord(value[e.start]):04X}) at " f"character {e.start}"
        ) from None
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
        raise _error(
            file,
            where,
            f"a count of {count} makes a scene of {total} shapes, which needs about "
            f"{_gigabytes(need)}, more than the {_gigabytes(budget)} of memory there is",
        )


def _check_bytes(size: int, file: str, where: str, what: str) -> None:
    budget = _memory_budget()
    if size > budget:
        raise _error(
            file, where, f"{what} takes {_gigabytes(size)}, more than the {_gigabytes(budget)} of " f"memory there is"
        )


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
                    raise _error(
                        file,
                        f"{where}[{j}]",
                        f"expected {sizes[0]} control points as curve 0 has "
                        f"(a batch's curves have one degree), got {size}",
                    )
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
        for row, i in enumerate(indices[: int(np.argmax(bad)) if bad.any() else len(indices)]):
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
# files: only regular files are read
# ------------------------------------------------------------------------------------------
_FILE_TYPES = (
    (stat.S_ISDIR, "a directory"),
    (stat.S_ISFIFO, "a FIFO (named pipe)"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


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
