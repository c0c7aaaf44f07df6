"""The part of JSON Schema (draft 2020-12) that circledist's scene schema uses, as a small
validator: the package needs no `jsonschema` at run time. tests/test_scene_file.py checks that
`jsonschema` accepts and rejects a corpus of scenes exactly as this validator does.

Errors are (JSON path, message) for the first violation met, the path written like
``$.shapes[3].radius``; a schema's "title" (when the violated keyword sits in a titled schema)
says what was expected in words.
"""

from __future__ import annotations

import json
import re
from typing import Any, Optional, Tuple

# Keywords this validator implements; any other keyword in a schema is refused when the schema
# is loaded (check_keywords), so the shipped schema cannot silently say more than is checked.
ANNOTATIONS = {"$schema", "$id", "$comment", "title", "description"}
KEYWORDS = ANNOTATIONS | {
    "$ref", "$defs", "type", "const", "enum", "minimum", "pattern", "minItems", "maxItems", "items",
    "uniqueItems", "required", "properties", "additionalProperties", "allOf", "if", "then", "else",
}

Error = Tuple[str, str]

_TYPE_WORDS = {"object": "an object", "array": "an array", "string": "a string", "number": "a number",
               "integer": "an integer", "boolean": "true or false", "null": "null"}


def shown(value: Any, limit: int = 60) -> str:
    """A short JSON rendering of a value for messages."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**30:
        return f"an integer of {len(str(abs(value)))} digits"
    text = json.dumps(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def member(path: str, key: str) -> str:
    return f"{path}.{key}" if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", key) else f"{path}[{json.dumps(key)}]"


def _is_type(value: Any, name: str) -> bool:
    if name == "object":
        return isinstance(value, dict)
    if name == "array":
        return isinstance(value, list)
    if name == "string":
        return isinstance(value, str)
    if name == "boolean":
        return isinstance(value, bool)
    if name == "null":
        return value is None
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    if name == "number":
        return True
    if name == "integer":  # draft 2020-12: any number with a zero fractional part (1.0 too)
        return isinstance(value, int) or value.is_integer()
    raise ValueError(f"unknown JSON Schema type {name!r}")


def _equal(a: Any, b: Any) -> bool:
    """JSON equality: 1 == 1.0, but true is not 1."""
    if isinstance(a, bool) or isinstance(b, bool):
        return isinstance(a, bool) and isinstance(b, bool) and a == b
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return a == b
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_equal(a[k], b[k]) for k in a)
    return type(a) is type(b) and a == b


def check_keywords(schema: Any, where: str = "#") -> None:
    """Raises ValueError if a schema uses a keyword this validator does not implement."""
    if isinstance(schema, bool):
        return
    for key, value in schema.items():
        if key not in KEYWORDS:
            raise ValueError(f"{where}: JSON Schema keyword {key!r} is not implemented by circledist._schema")
        if key in ("items", "additionalProperties", "if", "then", "else"):
            check_keywords(value, f"{where}/{key}")
        elif key in ("properties", "$defs"):
            for name, sub in value.items():
                check_keywords(sub, f"{where}/{key}/{name}")
        elif key == "allOf":
            for i, sub in enumerate(value):
                check_keywords(sub, f"{where}/{key}/{i}")


class Validator:
    def __init__(self, schema: dict):
        check_keywords(schema)
        self.root = schema
        self._resolved: dict = {}

    def _resolve(self, ref: str) -> Any:
        if ref in self._resolved:
            return self._resolved[ref]
        if not ref.startswith("#/"):
            raise ValueError(f"only local $ref are implemented, got {ref!r}")
        node = self.root
        for part in ref[2:].split("/"):
            node = node[part.replace("~1", "/").replace("~0", "~")]
        self._resolved[ref] = node
        return node

    def first_error(self, value: Any, schema: Any = None, path: str = "$") -> Optional[Error]:
        """The first violation of `schema` (default: the root) by `value`, or None."""
        return self._check(value, self.root if schema is None else schema, path)

    def _check(self, value: Any, schema: Any, path: str, explain: bool = True) -> Optional[Error]:
        """The first violation; explain=False (an "if" only asks whether there is one) skips
        composing the message."""
        if schema is True:
            return None
        if schema is False:
            return path, "not allowed here"

        def expected(generic: str) -> Error:
            if not explain:
                return path, ""
            what = schema.get("title") or generic
            return path, f"expected {what}, got {shown(value)}"

        if "$ref" in schema:
            error = self._check(value, self._resolve(schema["$ref"]), path, explain)
            if error:
                return error
        if "type" in schema:
            names = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
            if not any(_is_type(value, n) for n in names):
                return expected(" or ".join(_TYPE_WORDS[n] for n in names))
        if "const" in schema and not _equal(value, schema["const"]):
            return expected(shown(schema["const"]))
        if "enum" in schema and not any(_equal(value, option) for option in schema["enum"]):
            return expected("one of " + ", ".join(shown(option) for option in schema["enum"]))
        if _is_type(value, "number"):
            if "minimum" in schema and not value >= schema["minimum"]:
                return expected(f"a number >= {schema['minimum']}")
        if isinstance(value, str) and "pattern" in schema and not re.search(schema["pattern"], value):
            return expected(f"a string matching {schema['pattern']}")
        if isinstance(value, list):
            if "minItems" in schema and len(value) < schema["minItems"]:
                return expected(f"an array of at least {schema['minItems']} items")
            if "maxItems" in schema and len(value) > schema["maxItems"]:
                return expected(f"an array of at most {schema['maxItems']} items")
            if "items" in schema:
                for i, item in enumerate(value):
                    error = self._check(item, schema["items"], f"{path}[{i}]", explain)
                    if error:
                        return error
            if schema.get("uniqueItems"):
                for j, item in enumerate(value):
                    for i in range(j):
                        if _equal(value[i], item):
                            return f"{path}[{j}]", f"expected {schema.get('title') or 'distinct items'}, " \
                                                   f"got a repeat of item {i} ({shown(item)})"
        if isinstance(value, dict):
            for key in schema.get("required", ()):
                if key not in value:
                    what = f" ({schema['title']})" if "title" in schema else ""
                    return path, f"missing field {key!r}{what}"
            properties = schema.get("properties", {})
            for key, sub in properties.items():
                if key in value:
                    error = self._check(value[key], sub, member(path, key), explain)
                    if error:
                        return error
            if "additionalProperties" in schema:
                extra = schema["additionalProperties"]
                for key in value:
                    if key in properties:
                        continue
                    if extra is False:
                        return member(path, key), f"unknown field (allowed: {', '.join(properties)})"
                    error = self._check(value[key], extra, member(path, key), explain)
                    if error:
                        return error
        for sub in schema.get("allOf", ()):
            error = self._check(value, sub, path, explain)
            if error:
                return error
        if "if" in schema:
            branch = "then" if self._check(value, schema["if"], path, explain=False) is None else "else"
            if branch in schema:
                error = self._check(value, schema[branch], path, explain)
                if error:
                    return error
        return None
