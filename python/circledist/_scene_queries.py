"""Scene files: the queries, the same in both file types."""

from __future__ import annotations

from collections import Counter
from typing import Iterable

from . import _core
from ._schema import member, shown
from ._scene_format import (
    MOTION_EFFECTS,
    MOTION_FIELDS,
    MOTION_SINCE,
    PAIR_EFFECTS,
    SCENE_EFFECTS,
    VERSION,
    _REFERENCE,
    _error,
    _finite_array,
    _text,
)


# ------------------------------------------------------------------------------------------
# queries (the same in both file types)
# ------------------------------------------------------------------------------------------
def _check_queries(specs: list, entries: list, file: str, prefix: str = "", version: int = VERSION) -> list:
    """Semantic checks of schema-valid queries of a file of `version`; returns them as dicts with
    every key (a motion as a circledist.Motion)."""
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
                raise fail(
                    key,
                    f"expected one shape: {entry.name!r} is a batch of {entry.count}, name one "
                    f"as {entry.name}[i] with i from 0 to {entry.count - 1}",
                )
            if entry.count is None and index is not None:
                raise fail(key, f"expected a shape's name: {entry.name!r} is a single shape, not a batch")
            if index is not None and index >= entry.count:
                raise fail(
                    key,
                    f"expected an index from 0 to {entry.count - 1} (batch {entry.name!r} has "
                    f"{entry.count} shapes), got {index}",
                )
            refs[key] = (entry, index)
        effects = spec["effects"]
        _check_motion_version(spec, effects, version, fail)
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
                        raise fail(
                            "effects",
                            f"expected a scene whose every pair of kinds has a query: none "
                            f"exists between a {ka} and a {kb}",
                        )
        else:
            if "a" not in spec:
                raise fail(None, "missing field 'a' (the shape the query is about)")
            allowed = PAIR_EFFECTS if "b" in spec else SCENE_EFFECTS
            for e in effects:
                if e not in allowed:
                    against = "a pair (with 'b')" if "b" in spec else "the rest of the scene (without 'b')"
                    raise fail(
                        "effects", f"expected effects against {against}: {', '.join(allowed)}; " f"got {shown(e)}"
                    )
            a_entry, a_index = refs["a"]
            if "b" in spec:
                others = [refs["b"][0].class_name]
            else:  # every kind in the scene but the query's own shape
                own = a_entry.class_name if a_entry.count is None or a_entry.count == 1 else None
                others = {kind for kind, n in entries_of_kind.items() if n > (kind == own)}
            for kb in sorted(others):
                if (a_entry.class_name, kb) not in supported:
                    raise fail(
                        "b" if "b" in spec else "a",
                        f"expected shapes circledist has a query between: "
                        f"none exists between a {a_entry.class_name} and a {kb}",
                    )
            if "k" in spec and "nearest" not in effects and ("first_contact" not in effects or "b" in spec):
                raise fail("k", "not expected: only nearest and first_contact against the scene take k")
        motions = _motions(spec, effects, refs, file, base, fail)
        needs_d = "within" in effects or "pairs_within" in effects
        if needs_d and "d" not in spec:
            raise fail(None, "missing field 'd' (the distance of within / pairs_within)")
        if not needs_d and "d" in spec and "first_contact" not in effects:
            raise fail("d", "not expected: only within, pairs_within and first_contact take a distance")
        d = None
        if "d" in spec:
            d = float(_finite_array(spec["d"], file, member(base, "d")))
        out.append(
            {
                "name": spec.get("name"),
                "a": spec.get("a"),
                "b": spec.get("b"),
                "motion": motions.get("motion"),
                "motion_b": motions.get("motion_b"),
                "effects": list(effects),
                "d": d,
                "k": int(spec["k"]) if "k" in spec else None,
            }
        )
    return out


def _check_motion_version(spec: dict, effects: list, version, fail) -> None:
    """Motions and the effects that use them are refused in a file older than MOTION_SINCE."""
    if version >= MOTION_SINCE:
        return
    for key in ("motion", "motion_b"):
        if key in spec:
            raise fail(
                key,
                f"a query's motion needs format version {MOTION_SINCE} or later, the file says version {int(version)}",
            )
    for e in effects:
        if e in MOTION_EFFECTS:
            raise fail(
                "effects",
                f"effect {e!r} needs format version {MOTION_SINCE} or later, the file says version {int(version)}",
            )


def _motions(spec: dict, effects: list, refs: dict, file: str, base: str, fail) -> dict:
    """The query's motions ("motion" moves a, "motion_b" moves b) as circledist.Motion, checked
    against its effects: the motion effects ask for a motion and for no static effect beside
    them, and a motion is given only where they are asked for."""
    moving = [key for key in ("motion", "motion_b") if key in spec]
    asked = [e for e in effects if e in MOTION_EFFECTS]
    if not asked:
        for key in moving:
            raise fail(key, f"not expected: only {' and '.join(MOTION_EFFECTS)} take a motion")
        return {}
    if len(asked) != len(effects):
        static = [e for e in effects if e not in MOTION_EFFECTS]
        raise fail(
            "effects",
            f"expected {' and '.join(asked)} without {', '.join(static)}: the motion effects are a "
            "query of their own (ask for the others in another query)",
        )
    if "motion_b" in spec and "b" not in spec:
        raise fail("motion_b", "not expected: motion_b moves 'b', and the query has no 'b'")
    if not moving:
        wanted = "'motion' (the motion of 'a')" + (" or 'motion_b' (of 'b')" if "b" in spec else "")
        raise fail(None, f"missing field {wanted}, which {asked[0]} needs")
    out = {}
    for key in moving:
        where = member(base, key)
        fields = {f: _finite_array(spec[key].get(f, [0, 0, 0]), file, member(where, f)) for f in MOTION_FIELDS}
        entry, index = refs["a" if key == "motion" else "b"]
        if entry.kind in ("line", "ray") and fields["rotation"].any():
            shape = entry.name if index is None else f"{entry.name}[{index}]"
            raise _error(
                file,
                member(where, "rotation"),
                f"expected no rotation: {shape!r} is a {entry.kind}, which cannot rotate (its points reach "
                "infinitely far from the motion's center); give it a translation only",
            )
        out[key] = _core.Motion(**fields)
    return out


def _queries_version(queries) -> int:
    """The oldest version that holds these queries (as a file states them)."""
    for q in queries:
        if "motion" in q or "motion_b" in q or any(e in MOTION_EFFECTS for e in q.get("effects", ())):
            return MOTION_SINCE
    return 1


def _check_names(names: Iterable[str], file: str, where) -> None:
    seen = set()
    for i, name in enumerate(names):
        if name in seen:
            raise _error(file, where(i), f"expected a name of its own, got {shown(name)}, used by an earlier shape")
        seen.add(name)
