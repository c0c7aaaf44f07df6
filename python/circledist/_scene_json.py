"""Scene files: the JSON form."""

from __future__ import annotations

import json
import re
from typing import Any, Iterable

from ._schema import member, shown
from ._scene_format import (
    FORMAT,
    KIND_SINCE,
    SceneFile,
    SceneFileError,
    VERSION,
    _check_shape_count,
    _check_texts,
    _entries_from_json,
    _error,
    _text,
    _validator,
)
from ._scene_queries import _check_names, _check_queries


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
        raise _error(
            file,
            prefix,
            f"missing field 'format': a circledist scene starts with " f'"format": "{FORMAT}", "version": {VERSION}',
        )
    if fmt != FORMAT:
        raise _error(file, member(prefix, "format"), f'expected "{FORMAT}", got {shown(fmt)}')
    if "version" not in data:
        raise _error(file, prefix, f"missing field 'version' (this circledist reads versions 1 to {VERSION})")
    if (
        isinstance(version, (int, float))
        and not isinstance(version, bool)
        and version > VERSION
        and float(version).is_integer()
    ):
        raise _error(
            file,
            member(prefix, "version"),
            f"version {int(version)} is newer than this circledist "
            f"reads (versions 1 to {VERSION}): upgrade circledist",
        )


def _check_kind_version(kind: str, version: int, file: str, where: str) -> None:
    """A kind newer than the file's version (an arc in a version 1 file) is refused."""
    since = KIND_SINCE.get(kind, 1)
    if version < since:
        raise _error(
            file,
            where,
            f"kind {kind!r} needs format version {since} or later, the file says version " f"{int(version)}",
        )


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
        raise _error(
            file, "$", f'expected an object with "format": "{FORMAT}", "version" and "shapes", ' f"got {shown(data)}"
        )
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
    queries = _check_queries(data.get("queries", []), entries, file, version=data["version"])
    return SceneFile(file, data.get("description", ""), entries, queries)
