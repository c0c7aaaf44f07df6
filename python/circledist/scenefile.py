"""Scene files: JSON (``.json``) and NumPy (``.npz``), read and written.

A scene file holds named shapes, each a single shape or a batch of one kind whose fields are
columns (NumPy broadcasting: a column holds one row per shape, or one value for all), and
queries naming the effects they want. The JSON form is specified by the JSON Schema shipped in
the package (``circledist/scene.schema.json``, see ``schema_text()``); the ``.npz`` form holds
the same content as arrays, for scenes of millions of shapes. ``python -m circledist --help``
summarizes both; README.md shows their use.

Format version 4 (version 3 without motions, version 2 without annuli either, version 1 without
arcs either). The version goes up with any change to what a valid file may hold or to what it
means (a new kind, field, effect or array, a changed default); a reader refuses files of a newer
version with a message saying so instead of misreading them, and keeps reading older ones. A file
of an older version may hold only what that version holds (an arc in a version 1 file, an annulus
in a version 2 one, a query's motion in a version 3 one, is refused); `write_scene` writes the
oldest version that holds the scene.
Files must say ``"format": "circledist-scene"`` and ``"version"``: without them a JSON file is
refused (the message says which two fields to add), so that a file is never read under a version
it was not written for.

Every error is a SceneFileError with a one-line message naming the file, where in it (a JSON
path such as ``$.shapes[3].radius``, or an array of the .npz and an index) and what was expected.
"""

from __future__ import annotations

import contextlib
import gc
import json
import operator
import os
import secrets
import stat
from typing import Iterable, Mapping, Optional

import numpy as np

from . import _core
from .scene import MAX_CONTROL_POINTS, ROLE_TRAILING_DIMS  # noqa: F401

# The format, its checks and the two file types live in the modules below; every name stays
# reachable here, as circledist.scenefile.NAME.
from ._scene_format import (  # noqa: F401
    FORMAT,
    KINDS,
    KIND_SINCE,
    PAIR_EFFECTS,
    SCENE_EFFECTS,
    SCHEMA_RESOURCE,
    SHAPE_BYTES,
    SceneFile,
    SceneFileError,
    ShapeEntry,
    VERSION,
    VERSIONS,
    _FILE_TYPES,
    _LINE_BREAKS,
    _NPZ_TOP,
    _REFERENCE,
    _RowFields,
    _SWEEP,
    _SWEEP_ROLE,
    _VALIDATOR,
    _check_angles,
    _check_bytes,
    _check_directions,
    _check_shape_count,
    _check_texts,
    _column,
    _entries_from_json,
    _entry_from_json,
    _error,
    _finite_array,
    _float_column,
    _gigabytes,
    _json_index,
    _memory_budget,
    _motion_as_written,
    _open_regular,
    _refused_rows,
    _roles,
    _text,
    _validator,
    schema,
    schema_text,
)
from ._scene_queries import (  # noqa: F401
    _check_names,
    _check_queries,
    _queries_version,
)
from ._scene_json import (  # noqa: F401
    _MAX_DEPTH,
    _check_format,
    _check_kind_version,
    _file_version,
    _nested_too_deeply,
    _not_json_constant,
    _parse_json,
    _scene_from_json,
    scene_from_json,
)
from ._scene_npz import (  # noqa: F401
    _Header,
    _NPY_HEADERS,
    _NpzArrays,
    _WORD_CHARS,
    _ZIP_ERRORS,
    _ZIP_METHODS,
    _npz_field,
    _npz_index,
    _npz_integer,
    _npz_string,
    _scene_from_npz,
    _scene_from_npz_handle,
    scene_from_npz,
)


__all__ = [
    "FORMAT",
    "VERSION",
    "SceneFileError",
    "SceneFile",
    "ShapeEntry",
    "read_scene",
    "write_scene",
    "schema",
    "schema_text",
    "SCHEMA_RESOURCE",
]


def read_scene(path: str, text: Optional[str] = None) -> SceneFile:
    """Reads and validates a scene file, JSON or ``.npz``.

    The format (``circledist --help``, and the JSON Schema ``scene.schema.json`` in the package):
    ``"format": "circledist-scene"``, ``"version": 1`` (or 2, which arcs need, 3, which annuli
    need, or 4, which a query's motions need), the shapes (single or batches) and the queries.

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
            trailing = a.shape[a.ndim - dims :] if dims else ()
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
        As in the JSON format: ``{"a": ..., "b": ..., "effects": [...], "d": ..., "k": ...}``,
        with ``"motion"`` / ``"motion_b"`` (``{"translation": [x, y, z], "rotation": ...,
        "center": ...}``, or a single `Motion`) for the effects first_contact and
        closest_approach.
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
    # The queries as a reader gets them back (JSON's types: lists, floats, string keys; a
    # circledist.Motion, as read_scene gives it, as its three vectors).
    queries = json.loads(json.dumps([dict(q) for q in queries], default=_json_motion))
    if path.endswith(".json"):
        data = {"format": FORMAT, "version": _version_of(entries, queries)}
        if description:
            data["description"] = description
        data["shapes"] = []
        for name, kind, count, fields in entries:
            if count is None:  # fields already lists
                data["shapes"].append({"name": name, "kind": kind, **fields})
            else:
                data["shapes"].append(
                    {"name": name, "kind": kind, "count": count, **{f: a.tolist() for f, a in fields.items()}}
                )
        if queries:
            data["queries"] = queries
        text = _json_text(data)
        if not _written_scene_is_valid(entries, columns, queries, description):
            scene_from_json(json.loads(text), path)  # raises the error a reader reports
        payload = text.encode("utf-8")
        _write_atomically(path, lambda f: f.write(payload))
        return
    arrays = {
        "format": np.array(FORMAT),
        "version": np.array(_version_of(entries, queries), dtype=np.int64),
        "shapes": np.array([e[0] for e in entries], dtype=str),
    }
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
    fine = _written_scene_is_valid(entries, columns, queries, description) and not any(
        "\x00" in name for name, _, _, _ in entries
    )
    _write_atomically(
        path, lambda f: np.savez(f, **arrays), check=None if fine else lambda tmp: scene_from_npz(tmp, path)
    )


def _json_motion(value):
    """json.dumps' default: a single circledist.Motion as a file states it; anything else is not JSON."""
    if isinstance(value, _core.Motion) and value.batch_shape == ():
        return _motion_as_written(value)
    raise TypeError(f"write_scene: a query holds {type(value).__name__}, which is not JSON (nor a single Motion)")


def _version_of(entries: list, queries: list) -> int:
    """The oldest version that holds the shapes' kinds and the queries."""
    return max(_file_version(kind for _, kind, _, _ in entries), _queries_version(queries))


def _item_encoder():
    """json.dumps for many items: its C encoder made once (json.dumps makes one per call, a third
    of the time of a short item), or json.dumps where the C encoder is missing or differs."""
    make = getattr(json.encoder, "c_make_encoder", None)
    try:
        encoder = make(
            None, json.JSONEncoder().default, json.encoder.encode_basestring_ascii, None, ": ", ", ", False, False, True
        )

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
