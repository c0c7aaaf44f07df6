"""The part of JSON Schema (draft 2020-12) that circledist's scene schema uses, as a small
validator: the package needs no `jsonschema` at run time. tests/api/test_scene_file.py checks that
`jsonschema` accepts and rejects a corpus of scenes exactly as this validator does.

Errors are (JSON path, message) for the first violation met, the path written like
``$.shapes[3].radius``; a schema's "title" (when the violated keyword sits in a titled schema)
says what was expected in words.

Speed: each schema node is also compiled, once, into a predicate (value -> valid?) built from
plain type and length tests. A document is first checked with the predicates alone; the step that
composes the message runs only where a predicate fails, so a scene of 10^5 well-formed shapes
costs a few microseconds per shape, and a bad one is reported exactly as by the step-by-step check.
The predicates decide exactly what the step-by-step check decides (tests/api/test_scene_file.py
compares them on a corpus of mutated scenes), since an "if" takes its branch from them.
"""

from __future__ import annotations

import json
import re
from typing import Any, Callable, Optional, Tuple

# Keywords this validator implements; any other keyword in a schema is refused when the schema
# is loaded (check_keywords), so the shipped schema cannot silently say more than is checked.
ANNOTATIONS = {"$schema", "$id", "$comment", "title", "description"}
KEYWORDS = ANNOTATIONS | {
    "$ref",
    "$defs",
    "type",
    "const",
    "enum",
    "minimum",
    "pattern",
    "minItems",
    "maxItems",
    "items",
    "uniqueItems",
    "required",
    "properties",
    "additionalProperties",
    "allOf",
    "if",
    "then",
    "else",
}

Error = Tuple[str, str]

_ARRAY_KEYWORDS = ("minItems", "maxItems", "items", "uniqueItems")
_OBJECT_KEYWORDS = ("required", "properties", "additionalProperties")

_TYPE_WORDS = {
    "object": "an object",
    "array": "an array",
    "string": "a string",
    "number": "a number",
    "integer": "an integer",
    "boolean": "true or false",
    "null": "null",
}


def shown(value: Any, limit: int = 60) -> str:
    """A short JSON rendering of a value for messages."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**30:
        return f"an integer of {len(str(abs(value)))} digits"
    text = json.dumps(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


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


# ------------------------------------------------------------------------------------------
# compiled predicates: value -> bool, exactly "the step-by-step check finds no violation"
# ------------------------------------------------------------------------------------------
Predicate = Callable[[Any], bool]


def _always(value: Any) -> bool:
    return True


def _never(value: Any) -> bool:
    return False


def _is_number(value: Any) -> bool:
    """_is_type(value, "number"), the common types first."""
    t = type(value)
    if t is float or t is int:
        return True
    return t is not bool and isinstance(value, (int, float)) and not isinstance(value, bool)


def _is_integer(value: Any) -> bool:
    return _is_number(value) and (isinstance(value, int) or value.is_integer())


_TYPE_TESTS = {
    "object": lambda v: isinstance(v, dict),
    "array": lambda v: isinstance(v, list),
    "string": lambda v: isinstance(v, str),
    "boolean": lambda v: isinstance(v, bool),
    "null": lambda v: v is None,
    "number": _is_number,
    "integer": _is_integer,
}


def _all(tests: list) -> Predicate:
    tests = [t for t in tests if t is not _always]
    if not tests:
        return _always
    if len(tests) == 1:
        return tests[0]
    if len(tests) == 2:
        first, second = tests
        return lambda v: first(v) and second(v)
    tests = tuple(tests)

    def every(v):
        for test in tests:
            if not test(v):
                return False
        return True

    return every


def _type_test(names: list) -> Predicate:
    for n in names:
        if n not in _TYPE_TESTS:
            raise ValueError(f"unknown JSON Schema type {n!r}")
    tests = [_TYPE_TESTS[n] for n in names]
    if len(tests) == 1:
        return tests[0]
    return lambda v: any(t(v) for t in tests)


def _const_test(const: Any) -> Predicate:
    if type(const) is str:  # _equal(v, a string) holds only for a str equal to it
        return lambda v: type(v) is str and v == const
    return lambda v: _equal(v, const)


def _array_test(schema: dict, item: Optional[Predicate], other: bool = True) -> Predicate:
    """The array keywords; `other`: the answer for a value that is no array (False where the
    node's type is "array": the type test folded in)."""
    low = schema.get("minItems", 0)
    high = schema.get("maxItems")
    unique = bool(schema.get("uniqueItems"))
    numbers = item is _is_number

    def array(v):
        if not isinstance(v, list):
            return other
        n = len(v)
        if n < low or (high is not None and n > high):
            return False
        if numbers:
            for x in v:
                t = type(x)
                if t is not float and t is not int and not _is_number(x):
                    return False
        elif item is not None:
            for x in v:
                if not item(x):
                    return False
        if unique:
            for j in range(n):
                for i in range(j):
                    if _equal(v[i], v[j]):
                        return False
        return True

    return array


def _object_test(schema: dict, properties: dict, extra: Any, other: bool = True) -> Predicate:
    """The object keywords; `other`: the answer for a value that is no object (False where the
    node's type is "object": the type test folded in)."""
    required = tuple(schema.get("required", ()))
    checked = tuple((key, test) for key, test in properties.items() if test is not _always)
    names = frozenset(properties)

    def obj(v):
        if not isinstance(v, dict):
            return other
        for key in required:
            if key not in v:
                return False
        for key, test in checked:
            if key in v and not test(v[key]):
                return False
        if extra is False:
            if not names.issuperset(v):
                return False
        elif extra is not None:
            for key in v:
                if key not in names and not extra(v[key]):
                    return False
        return True

    return obj


def _discriminator(subs: list) -> Optional[tuple]:
    """(key, {value: then}) when every schema of an allOf is
    {"if": {"properties": {key: {"const": "a string"}}, "required": [key]}, "then": ...}, one key,
    distinct strings: on an object at most one "then" applies, picked by a dictionary lookup."""
    key, table = None, {}
    for sub in subs:
        if not isinstance(sub, dict) or set(sub) != {"if", "then"}:
            return None
        cond = sub["if"]
        if not isinstance(cond, dict) or set(cond) != {"properties", "required"} or len(cond["properties"]) != 1:
            return None
        ((k, test),) = cond["properties"].items()
        if cond["required"] != [k] or key not in (None, k) or not isinstance(test, dict) or set(test) != {"const"}:
            return None
        if type(test["const"]) is not str or test["const"] in table:
            return None
        key = k
        table[test["const"]] = sub["then"]
    return (key, table) if key is not None else None


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
    def __init__(self, schema: dict, compiled: bool = True):
        """compiled=False: the step-by-step check alone (to compare the predicates against)."""
        check_keywords(schema)
        self.root = schema
        self._resolved: dict = {}
        self._tests: dict = {}  # id(node) -> (node, predicate), for the nodes of the root schema
        self._compiled = compiled
        if compiled:
            self._root_test = self.test(schema)

    def is_valid(self, value: Any, schema: Any = None) -> bool:
        """Whether `value` satisfies `schema` (default: the root): first_error(...) is None."""
        return self.test(self.root if schema is None else schema)(value)

    def test(self, schema: Any) -> Predicate:
        """The compiled predicate of a schema node (cached for the nodes of the root schema)."""
        if schema is True:
            return _always
        if schema is False:
            return _never
        found = self._tests.get(id(schema))
        if found is not None and found[0] is schema:
            return found[1]
        if found is None and self._tests and not self._owned(schema):
            return self._compile(schema)  # a schema of the caller's: not kept
        # A placeholder first, so that a $ref back to this node while it compiles finds it.
        cell: list = []
        self._tests[id(schema)] = (schema, lambda v: cell[0](v))
        test = self._compile(schema)
        cell.append(test)
        self._tests[id(schema)] = (schema, test)
        return test

    def _owned(self, schema: Any) -> bool:
        """Whether a node belongs to the root schema (then its id is stable and it may be cached)."""
        if not hasattr(self, "_owned_ids"):
            ids: set = set()

            def walk(node):
                if isinstance(node, dict):
                    ids.add(id(node))
                    for sub in node.values():
                        walk(sub)
                elif isinstance(node, list):
                    for sub in node:
                        walk(sub)

            walk(self.root)
            self._owned_ids = ids
        return id(schema) in self._owned_ids

    def _compile(self, schema: dict) -> Predicate:
        tests = []
        if "$ref" in schema:
            tests.append(self.test(self._resolve(schema["$ref"])))
        # A node of one type whose other keywords test that type folds the type test into theirs
        # (one call per value instead of two): they answer False, not True, for other values.
        types = schema.get("type", [])
        types = types if isinstance(types, list) else [types]
        only = types[0] if len(types) == 1 else None
        arrays = any(k in schema for k in _ARRAY_KEYWORDS)
        objects = any(k in schema for k in _OBJECT_KEYWORDS)
        folded = (
            (only == "string" and "pattern" in schema)
            or (only == "number" and "minimum" in schema)
            or (only == "array" and arrays)
            or (only == "object" and objects)
        )
        if "type" in schema and not folded:
            tests.append(_type_test(types))
        if "const" in schema:
            tests.append(_const_test(schema["const"]))
        if "enum" in schema:
            options = schema["enum"]
            if all(type(o) is str for o in options):
                strings = frozenset(options)
                tests.append(lambda v: type(v) is str and v in strings)
            else:
                tests.append(lambda v: any(_equal(v, o) for o in options))
        if "minimum" in schema:
            low = schema["minimum"]
            if folded and only == "number":
                tests.append(lambda v: _is_number(v) and v >= low)
            else:
                tests.append(lambda v: not _is_number(v) or v >= low)
        if "pattern" in schema:
            search = re.compile(schema["pattern"]).search
            if folded and only == "string":
                tests.append(lambda v: isinstance(v, str) and search(v) is not None)
            else:
                tests.append(lambda v: not isinstance(v, str) or search(v) is not None)
        if arrays:
            tests.append(
                _array_test(
                    schema,
                    self.test(schema["items"]) if "items" in schema else None,
                    other=not (folded and only == "array"),
                )
            )
        if objects:
            properties = {key: self.test(sub) for key, sub in schema.get("properties", {}).items()}
            extra = schema.get("additionalProperties")
            extra = None if extra is None or extra is True else False if extra is False else self.test(extra)
            tests.append(_object_test(schema, properties, extra, other=not (folded and only == "object")))
        if "allOf" in schema:
            subs = [self.test(sub) for sub in schema["allOf"]]
            found = _discriminator(schema["allOf"])
            if found is None:
                tests.append(_all(subs))
            else:
                key, table = found
                thens = {value: self.test(then) for value, then in table.items()}
                every = _all(subs)

                def one_of_kinds(v):
                    if not isinstance(v, dict):  # no "if" tests an object's keys: every "then" applies
                        return every(v)
                    if key not in v or type(v[key]) is not str:
                        return True
                    then = thens.get(v[key])
                    return then is None or then(v)

                tests.append(one_of_kinds)
        if "if" in schema:
            cond = self.test(schema["if"])
            then = self.test(schema["then"]) if "then" in schema else _always
            other = self.test(schema["else"]) if "else" in schema else _always
            tests.append(lambda v: then(v) if cond(v) else other(v))
        return _all(tests)

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
        if self._compiled and self.test(schema)(value):
            return None  # the common case: only a failing node needs the step-by-step check

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
                            return (
                                f"{path}[{j}]",
                                f"expected {schema.get('title') or 'distinct items'}, "
                                f"got a repeat of item {i} ({shown(item)})",
                            )
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
