"""Scene files, format version 1 (circledist.scenefile): the JSON Schema shipped in the package
and the small validator that applies it (they agree with the `jsonschema` package on a corpus of
valid scenes and of every single-node mutation of them), batches (columns, broadcasting, name[i]
in queries and answers), .npz scenes (10^6 shapes loaded and queried in seconds), the writer and
JSON <-> npz round trips, and the one-line errors of bad files (file, JSON path or array and
index, what was expected; exit status 2)."""

import copy
import json
import os
import re
import subprocess
import sys
import time
from importlib import resources

import numpy as np
import pytest

cd = pytest.importorskip("circledist")
cli = pytest.importorskip("circledist.cli")
sf = pytest.importorskip("circledist.scenefile")
from circledist import _schema  # noqa: E402

HEAD = {"format": "circledist-scene", "version": 1}
RING = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)

BATCH_SCENE = {
    **HEAD,
    "description": "batches",
    "shapes": [
        {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1.0, "sweep": 0.05},
        {
            "name": "rings",
            "kind": "circle",
            "count": 4,
            "center": [[3, 0, 0], [0, 3, 0], [-3, 0, 0], [0, -3, 0.5]],
            "normal": [0, 0, 1],  # one vector for all four
            "radius": [0.5, 0.75, 1.0, 1.25],
        },
        {
            "name": "coins",
            "kind": "disk",
            "count": 2,
            "center": [[1, 1, 2]],
            "normal": [[1, 0, 0], [0, 1, 0]],
            "radius": 0.3,
            "sweep": [0.0, 0.1],
        },  # a column of one row broadcasts (NumPy rules)
        {"name": "beads", "kind": "point", "count": 3, "p": [[0, 0, 2], [1, 0, 2], [2, 0, 2]], "sweep": 0.1},
        {
            "name": "cables",
            "kind": "bezier",
            "count": 2,
            "control_points": [[[-2, -2, 1], [0, 0, 3], [2, -2, 1]], [[-2, 2, -1], [0, 0, -3], [2, 2, -1]]],
        },
        {"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]},
    ],
    "queries": [
        {"a": "rail", "b": "rings[2]", "effects": ["distance", "closest_points"]},
        {"a": "rings[3]", "effects": ["nearest"], "k": 3},
        {"a": "coins[0]", "effects": ["within"], "d": 1.5},
        {"a": "cables[0]", "b": "coins[1]", "effects": ["intersects", "distance"]},
        {"a": "beads[1]", "b": "rail", "effects": ["within"], "d": 0.7},
    ],
}


def test_schema_ships_in_the_package_and_is_valid_draft_2020_12():
    import jsonschema

    text = resources.files("circledist").joinpath("scene.schema.json").read_text(encoding="utf-8")
    schema = json.loads(text)
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    jsonschema.Draft202012Validator.check_schema(schema)
    assert schema == sf.schema()
    assert schema["properties"]["format"] == {"const": "circledist-scene"}
    assert schema["properties"]["version"] == {"enum": list(sf.VERSIONS)} and sf.VERSIONS == (1, 2, 3, 4) == (
        1,
        2,
        3,
        sf.VERSION,
    )
    assert set(schema["$defs"]["shape"]["properties"]["kind"]["enum"]) == set(sf.KINDS)
    demo = json.loads(resources.files("circledist").joinpath("scenes", "demo.json").read_text())
    assert demo["format"] == "circledist-scene" and demo["version"] == 1
    jsonschema.validate(demo, schema, cls=jsonschema.Draft202012Validator)


def test_validator_refuses_keywords_it_does_not_implement():
    _schema.check_keywords(sf.schema())  # the shipped schema uses only implemented keywords
    with pytest.raises(ValueError, match="'oneOf' is not implemented"):
        _schema.Validator({"properties": {"x": {"oneOf": [{"type": "string"}]}}})


def _mutations(doc):
    """Every single-node change of a document: each value replaced by a string, a negative number,
    an empty list, a float, true and an object; each list shortened and lengthened; each
    object missing each key or given an unknown one."""
    out = []

    def walk(node, setter):
        for replacement in ("x", -1, [], 2.5, True, {"k": 1}):
            out.append(setter(replacement))
        if isinstance(node, list):
            if node:
                out.append(setter(node[:-1]))
                out.append(setter(node + [node[-1]]))
            numbers = all(isinstance(x, (int, float)) for x in node)
            for i, item in enumerate(node):
                if numbers and 0 < i < len(node) - 1:
                    continue  # the middle of [x, y, z] behaves as its ends: spare the time
                walk(item, lambda v, i=i, node=node, setter=setter: setter(node[:i] + [v] + node[i + 1 :]))
        elif isinstance(node, dict):
            for key in node:
                out.append(setter({k: v for k, v in node.items() if k != key}))
                walk(node[key], lambda v, key=key, node=node, setter=setter: setter({**node, key: v}))
            out.append(setter({**node, "extra": 1}))

    walk(doc, lambda v: copy.deepcopy(v))
    return out


def _corpus():
    from circledist_cases.scene_documents import BAD, SCENE

    valid = [SCENE, BATCH_SCENE, json.loads(cli.demo_scene_text())]
    docs = list(valid)
    for doc in (SCENE, BATCH_SCENE):
        docs += _mutations(doc)
    docs += [data for _, data, _, _ in BAD if not isinstance(data, str)]
    return valid, docs


@pytest.mark.slow
def test_validator_agrees_with_jsonschema_on_a_corpus():
    import jsonschema

    validator = jsonschema.Draft202012Validator(sf.schema())
    valid, docs = _corpus()
    assert len(docs) > 1500
    accepted = rejected = 0
    for doc in docs:
        theirs = validator.is_valid(doc)
        ours = sf._validator().first_error(doc)
        assert theirs == (ours is None), (doc, ours, [e.message for e in validator.iter_errors(doc)][:3])
        accepted += theirs
        rejected += not theirs
        # The loader is the schema plus what a schema cannot say: it accepts nothing the schema refuses.
        if (
            not theirs
            and isinstance(doc, dict)
            and doc.get("format") == "circledist-scene"
            and doc.get("version") in sf.VERSIONS
        ):
            with pytest.raises(sf.SceneFileError):
                sf.scene_from_json(doc, "corpus.json")
    assert accepted > 200 and rejected > 1000, (accepted, rejected)
    for doc in valid:
        sf.scene_from_json(doc, "valid.json")


@pytest.mark.slow
def test_compiled_predicates_decide_as_the_step_by_step_check():
    """The validator answers well-formed documents with compiled predicates and composes messages
    step by step only where one fails; both must agree exactly on every document and entry, and
    the reported error must be the one the step-by-step check alone reports."""
    schema = sf.schema()
    fast, slow = _schema.Validator(schema), _schema.Validator(schema, compiled=False)
    shape = schema["$defs"]["shape"]
    valid, docs = _corpus()
    entries = [
        e for doc in docs if isinstance(doc, dict) and isinstance(doc.get("shapes"), list) for e in doc["shapes"]
    ]
    odd = [
        None,
        True,
        False,
        0,
        1.0,
        -0.0,
        float("nan"),
        10**40,
        "",
        "x",
        [],
        {},
        [[]],
        {"kind": 1},
        {"name": "a", "kind": ["circle"]},
        {"name": "a", "kind": "nope"},
        np.float64(1.5),
        [1, 2, np.float64(3)],
    ]
    assert len(entries) > 5000
    for value in docs + odd:
        expected = slow.first_error(value)
        assert fast.first_error(value) == expected, value
        assert fast.is_valid(value) == (expected is None), value
    for value in entries + odd:
        for node in (shape, schema["$defs"]["vectors"], schema["$defs"]["control_points_batch"]):
            expected = slow.first_error(value, node, "$.x")
            assert fast.first_error(value, node, "$.x") == expected, (value, node.get("title"))
            assert fast.is_valid(value, node) == (expected is None), value


def _many_single_shapes(n):
    """n single shapes of every kind, in turn, as a scene document."""
    specs = []
    for i in range(n):
        x = [i * 0.5, (i % 7) - 3.0, (i % 11) * 0.25]
        kind = ("circle", "disk", "segment", "point", "bezier", "line", "ray")[(i + 3) % 7]
        spec = {"name": f"s{i}", "kind": kind}
        if kind in ("circle", "disk"):
            spec.update(center=x, normal=[0, (i % 3) - 1, 1], radius=0.5 + (i % 5) * 0.1)
        elif kind == "segment":
            spec.update(p0=x, p1=[x[0] + 1, x[1], x[2]])
        elif kind == "point":
            spec.update(p=x, sweep=0.1)
        elif kind == "bezier":
            spec.update(control_points=[x, [x[0] + 1, x[1] + 1, x[2]], [x[0] + 2, x[1], x[2]]][: 2 + i % 2])
        else:
            spec.update(origin=x, direction=[1, 0.5, 0])
        specs.append(spec)
    return {**HEAD, "shapes": specs, "queries": [{"a": "s0", "b": "s2", "effects": ["distance"]}]}


@pytest.fixture(scope="module")
def big_scene():
    doc = _many_single_shapes(200_001)
    sf.scene_from_json(doc, "big.json")  # valid as it is
    return doc


@pytest.mark.parametrize(
    "label, mutate, where, message",
    [
        (
            "bad field",
            lambda s: s.update(radius=-1),
            "$.shapes[150000].radius (shape 's150000')",
            "expected a number >= 0, got -1",
        ),
        (
            "zero normal",
            lambda s: s.update(normal=[0, 0, 0]),
            "$.shapes[150000].normal",
            "expected a non-zero vector, got [0, 0, 0]",
        ),
        (
            "huge number",
            lambda s: s.update(center=[1, 10**400, 0]),
            "$.shapes[150000].center[1]",
            "expected a finite number (within a double's range), got an integer of 401 digits",
        ),
        (
            "unknown field",
            lambda s: s.update(colour="red"),
            "$.shapes[150000].colour (shape 's150000')",
            "unknown field (allowed: name, kind, count, center, normal, radius, sweep)",
        ),
    ],
)
@pytest.mark.slow
def test_a_bad_entry_deep_in_a_large_file_is_reported_as_in_a_small_one(big_scene, label, mutate, where, message):
    """The fast paths for large files (compiled schema, single shapes checked as columns) report
    the first bad entry exactly as the step-by-step check does, with its index."""
    doc = {**big_scene, "shapes": list(big_scene["shapes"])}
    spec = doc["shapes"][150000] = copy.deepcopy(doc["shapes"][150000])
    assert spec["kind"] in ("circle", "disk")
    mutate(spec)
    doc["shapes"][150007] = {**doc["shapes"][150007], "normal": [0, 0, 0]}  # a later bad entry: not reported
    with pytest.raises(sf.SceneFileError) as big:
        sf.scene_from_json(doc, "big.json")
    assert str(big.value) == f"big.json: {where}: {message}"
    # The same entry alone in a small file: the same message, at index 0.
    small = {**HEAD, "shapes": [spec]}
    with pytest.raises(sf.SceneFileError) as one:
        sf.scene_from_json(small, "big.json")
    assert str(one.value) == f"big.json: {where.replace('150000]', '0]')}: {message}"


def test_a_large_file_of_single_shapes_reads_as_shapes_added_one_by_one(tmp_path):
    doc = _many_single_shapes(3000)
    path = tmp_path / "many.json"
    path.write_text(json.dumps(doc))
    scene = sf.read_scene(str(path))
    assert scene.count == 3000
    expected = cd.Scene()
    for spec in doc["shapes"]:
        fields = {k: v for k, v in spec.items() if k not in ("name", "kind")}
        expected.add(spec["name"], getattr(cd, sf.KINDS[spec["kind"]][0])(**fields))
    for i in (0, 1, 2, 3, 4, 5, 6, 1234, 2999):
        assert repr(scene.shape(f"s{i}")) == repr(expected[f"s{i}"])
        assert repr(scene.scene()[f"s{i}"]) == repr(expected[f"s{i}"])
    world = scene.scene()
    assert world.names == expected.names
    probe = cd.Circle([100, 0.5, 0.2], [0, 1, 1], 2.0)
    assert world.nearest(probe, 5) == expected.nearest(probe, 5)
    assert world.within(probe, 1.5) == expected.within(probe, 1.5)
    # written back, one shape a line, and read again: the same shapes
    again = tmp_path / "again.json"
    sf.write_scene(str(again), scene.shapes, scene.queries_as_written())
    assert len(again.read_text().splitlines()) == 3000 + 9
    reread = sf.read_scene(str(again))
    assert [repr(reread.shape(n)) for n in world.names] == [repr(scene.shape(n)) for n in world.names]
    assert reread.queries == scene.queries


def test_batches_in_queries_and_answers(tmp_path):
    path = tmp_path / "batches.json"
    path.write_text(json.dumps(BATCH_SCENE))
    scene = sf.read_scene(str(path))
    assert [(e.name, e.count) for e in scene.entries] == [
        ("ring", None),
        ("rings", 4),
        ("coins", 2),
        ("beads", 3),
        ("cables", 2),
        ("rail", None),
    ]
    assert scene.count == 13
    rings = scene.shapes["rings"]
    assert rings.batch_shape == (4,)
    np.testing.assert_array_equal(np.broadcast_to(rings.normal, (4, 3)), [[0, 0, 1]] * 4)
    np.testing.assert_array_equal(np.broadcast_to(scene.shapes["coins"].center, (2, 3)), [[1, 1, 2]] * 2)
    world = scene.scene()
    assert world.names == [
        "ring",
        "rings[0]",
        "rings[1]",
        "rings[2]",
        "rings[3]",
        "coins[0]",
        "coins[1]",
        "beads[0]",
        "beads[1]",
        "beads[2]",
        "cables[0]",
        "cables[1]",
        "rail",
    ]

    out = tmp_path / "answers.json"
    assert cli.main([str(path), "--json", str(out)]) == 0
    answers = json.loads(out.read_text())["answers"]
    rail = cd.Line([-3, 1, 0.5], [1, 0, 0])
    ring2 = cd.Circle([-3, 0, 0], [0, 0, 1], 1.0)
    assert answers[0]["b"] == "rings[2]" and answers[0]["distance"] == cd.distance(rail, ring2)
    assert answers[0]["closest_points"]["point_b"] == list(cd.closest_points(rail, ring2).point_b)
    # nearest of rings[3] against every other shape, by brute force over the element shapes
    ring3 = scene.shape("rings[3]")
    others = [n for n in world.names if n != "rings[3]"]
    d = [cd.distance(ring3, world[n]) for n in others]
    order = np.argsort(d, kind="stable")[:3]
    assert answers[1]["nearest"] == [{"name": others[i], "distance": d[i]} for i in order]
    coin0 = cd.Disk([1, 1, 2], [1, 0, 0], 0.3)
    assert answers[2]["within"] == [n for n in world.names if n != "coins[0]" and cd.within(coin0, world[n], 1.5)]
    assert answers[2]["within"]  # not a vacuous check
    cable0 = cd.Bezier([[-2, -2, 1], [0, 0, 3], [2, -2, 1]])
    coin1 = cd.Disk([1, 1, 2], [0, 1, 0], 0.3, sweep=0.1)
    assert answers[3]["distance"] == cd.distance(cable0, coin1)
    assert answers[4]["within"] == cd.within(cd.Point([1, 0, 2], sweep=0.1), rail, 0.7)


def test_pairs_within_over_batches(tmp_path):
    doc = copy.deepcopy(BATCH_SCENE)
    doc["shapes"] = [s for s in doc["shapes"] if s["kind"] != "bezier"]
    doc["queries"] = [{"effects": ["pairs_within"], "d": 1.2}]
    scene = sf.scene_from_json(doc, "pairs.json")
    assert cli.answer(scene)[0].answers["pairs_within"] == [list(p) for p in scene.scene().pairs_within(1.2)]
    world = scene.scene()
    expected = [
        [a, b] for i, a in enumerate(world.names) for b in world.names[i + 1 :] if cd.within(world[a], world[b], 1.2)
    ]
    assert cli.answer(scene)[0].answers["pairs_within"] == expected and len(expected) >= 3
    doc["shapes"].append(BATCH_SCENE["shapes"][4])  # Bezier curves against Bezier curves: a query too
    assert len(sf.scene_from_json(doc, "pairs.json").queries) == 1


CABLE = {"kind": "bezier", "control_points": [[0, 0, 0], [1, 1, 0], [2, 0, 0]]}
CABLES = {"kind": "bezier", "count": 2, "control_points": CABLE["control_points"]}
HOOP = {"name": "hoop", "kind": "circle", "center": [0, 0, 3], "normal": [0, 0, 1], "radius": 1}


@pytest.mark.parametrize(
    "shapes, query, error",
    [
        ([{"name": "cable", **CABLE}, HOOP], {"a": "cable", "effects": ["nearest"]}, None),
        (
            [{"name": "cable", **CABLE}, {"name": "cable2", **CABLE}, HOOP],
            {"a": "cable", "effects": ["nearest"]},
            None,
        ),  # curves against curves have a query (bezier_bezier.hpp)
        ([{"name": "cables", **CABLES, "count": 1}, HOOP], {"a": "cables[0]", "effects": ["within"], "d": 1}, None),
        (
            [{"name": "cables", **CABLES}, HOOP],
            {"a": "cables[1]", "effects": ["intersects"]},
            None,
        ),  # curves against curves have a query (bezier_bezier.hpp)
        ([{"name": "cables", **CABLES, "count": 1}, HOOP], {"effects": ["pairs_within"], "d": 1}, None),
        (
            [{"name": "cable", **CABLE}, {"name": "cables", **CABLES, "count": 1}],
            {"effects": ["pairs_within"], "d": 1},
            None,
        ),
    ],
)
def test_queries_against_the_scene_are_checked_by_the_kinds_it_holds(shapes, query, error):
    """A query against the rest of the scene needs a query between its shape's kind and every
    other shape's (its own shape left out unless it is one of a batch of more); pairs_within
    between every two kinds, a kind with one shape left out. Many queries and one check each."""
    doc = {**HEAD, "shapes": shapes, "queries": [query] * 50}
    if error is None:
        assert len(sf.scene_from_json(doc, "q.json").queries) == 50
    else:
        with pytest.raises(sf.SceneFileError) as raised:
            sf.scene_from_json(doc, "q.json")
        assert str(raised.value) == "q.json: " + error


def _same_scene(a, b):
    assert a.description == b.description and a.queries == b.queries
    assert [(e.name, e.kind, e.count) for e in a.entries] == [(e.name, e.kind, e.count) for e in b.entries]
    for ea, eb in zip(a.entries, b.entries):
        assert ea.fields.keys() == eb.fields.keys()
        for f in ea.fields:
            np.testing.assert_array_equal(ea.fields[f], eb.fields[f], err_msg=f"{ea.name}/{f}")


def test_round_trip_json_npz_json(tmp_path):
    rng = np.random.default_rng(3)
    shapes = {
        "rings": cd.Circle(
            rng.normal(size=(5, 3)), rng.normal(size=(5, 3)), rng.uniform(0.1, 2, 5), sweep=rng.uniform(0, 0.1, 5)
        ),
        "grid": cd.Point(rng.normal(size=(2, 3, 3))),  # a 2-d batch: flattened in C order
        "rail": cd.Line(rng.normal(size=3), [1e-300, 2.0, -1 / 3]),
        "cables": cd.Bezier(rng.normal(size=(3, 4, 3)), sweep=0.25),
        "probe": cd.Segment([0, 0, 0], [1, 1, 1]),
        "plate": cd.Disk([0, 0, 0], [0, 0, 1], [2.0, 3.0]),  # a batch: columns broadcast
    }
    queries = [
        {"a": "plate[1]", "effects": ["nearest"], "k": 2},
        {"name": "pair", "a": "rings[1]", "b": "plate[1]", "effects": ["distance"]},
        {"a": "rings[0]", "effects": ["within", "intersects"], "d": 0.5},
    ]
    first = tmp_path / "first.json"
    sf.write_scene(first, shapes, queries, description="round trip")
    a = sf.read_scene(str(first))
    assert a.entries[1].count == 6 and a.entries[0].count == 5 and a.entries[2].count is None
    np.testing.assert_array_equal(a.entries[1].fields["p"], np.asarray(shapes["grid"].p).reshape(6, 3))
    np.testing.assert_array_equal(a.entries[2].fields["direction"], [1e-300, 2.0, -1 / 3])  # exact digits
    # a column given as one value is written as one value
    assert json.loads(first.read_text())["shapes"][3]["sweep"] == 0.25
    npz = tmp_path / "second.npz"
    sf.write_scene(npz, a.shapes, a.queries_as_written(), description=a.description)
    b = sf.read_scene(str(npz))
    _same_scene(a, b)
    third = tmp_path / "third.json"
    sf.write_scene(third, b.shapes, b.queries_as_written(), description=b.description)
    assert third.read_text() == first.read_text()
    outs = []
    for path in (first, npz):
        out = tmp_path / f"{path.stem}.answers.json"
        assert cli.main([str(path), "--json", str(out)]) == 0
        outs.append(json.loads(out.read_text())["answers"])
    assert outs[0] == outs[1]


def test_write_scene_refuses_what_no_reader_accepts(tmp_path):
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    for name in ("bad.json", "bad.npz"):
        with pytest.raises(sf.SceneFileError, match=r"bad\.(json|npz): .*\$\.queries\[0\]\.b: expected the name"):
            sf.write_scene(tmp_path / name, {"ring": ring}, [{"a": "ring", "b": "nope", "effects": ["distance"]}])
    with pytest.raises(ValueError, match="expected a path ending in .json or .npz"):
        sf.write_scene(tmp_path / "scene.txt", {"ring": ring})
    with pytest.raises(sf.SceneFileError, match=r"\$\.shapes\[0\]\.name: expected a name"):
        sf.write_scene(tmp_path / "bad.json", {"ring[0]": ring})
    assert list(tmp_path.iterdir()) == []  # nothing written, no temporary files


def _writer_corpus():
    """Shapes write_scene must write as they are: every kind single and in batches (columns and
    one value for all, a 2-d batch), float32 and long double fields, -0.0, numbers near a
    double's limits, sweeps given as zero and not given, Bezier curves of every degree."""
    rng = np.random.default_rng(18)
    shapes = {
        "p": cd.Point([-0.0, 1e-300, 1.7e308]),
        "p-swept": cd.Point([1, 2, 3], sweep=0.0),
        "line": cd.Line(rng.normal(size=3), [5e-324, 0, 0], sweep=0.5),
        "ray": cd.Ray(np.float32([0.1, 0.2, 0.3]), np.float32([0, 1, 0])),
        "seg": cd.Segment([0, 0, 0], [0, 0, 0], sweep=np.longdouble(1) / 3),
        "ring32": cd.Circle(np.float32([0.1, 0, 0]), [0, 0, 1], np.float32(0.7)),
        "ring-ld": cd.Circle([0, 0, 0], np.array([1, 1, 0], np.longdouble), np.longdouble(2) / 3),
        "coin": cd.Disk(rng.normal(size=3), rng.normal(size=3), 0.25, sweep=1e-310),
        "rings": cd.Circle(rng.normal(size=(5, 3)), [0, 0, 1], rng.uniform(0.1, 2, 5), sweep=[0, 0, 0, 0, -0.0]),
        "grid": cd.Disk(rng.normal(size=(2, 3, 3)), rng.normal(size=(2, 3, 3)), 0.5, sweep=rng.uniform(0, 1, (2, 3))),
        "one": cd.Point(rng.normal(size=(1, 3)), sweep=0.1),
    }
    for m in range(2, sf.MAX_CONTROL_POINTS + 1):
        shapes[f"cable{m}"] = cd.Bezier(rng.normal(size=(m, 3)), sweep=0.01 * m)
        shapes[f"cables{m}"] = cd.Bezier(rng.normal(size=(3, m, 3)))
    for i in range(40):  # many single shapes of a kind: one column in the writer's check
        shapes[f"s{i}"] = cd.Segment(rng.normal(size=3), rng.normal(size=3), sweep=[0.0, 0.2][i % 2])
    return shapes


def _writer_check(shapes, queries=(), description=""):
    """write_scene's own check of what it writes (True: no reader's check needed)."""
    entries, columns = sf._entries_of(shapes)
    return sf._written_scene_is_valid(entries, columns, json.loads(json.dumps(list(queries))), description)


def test_write_scene_writes_every_number_as_it_reads_back(tmp_path):
    """The writer checks only what it does not make valid itself; what it writes reads back bit
    for bit (as float64), in JSON as in .npz, and its check passes exactly where a reader accepts."""
    shapes = _writer_corpus()
    queries = [{"a": "rings[4]", "effects": ["nearest"], "k": 3}, {"a": "p", "b": "grid[5]", "effects": ["distance"]}]
    assert _writer_check(shapes, queries, "corpus")
    path = tmp_path / "corpus.json"
    sf.write_scene(path, shapes, queries, description="corpus")
    assert len(path.read_text().splitlines()) == len(shapes) + len(queries) + 9  # one shape a line
    back = sf.read_scene(str(path))
    sf.write_scene(tmp_path / "corpus.npz", shapes, queries, description="corpus")
    _same_scene(back, sf.read_scene(str(tmp_path / "corpus.npz")))
    assert back.queries_as_written() == queries and back.description == "corpus"
    assert [e.name for e in back.entries] == list(shapes)
    for entry in back.entries:
        shape = shapes[entry.name]
        count = None if shape.batch_shape == () else int(np.prod(shape.batch_shape))
        assert entry.count == count
        for field in entry.fields:
            got = np.asarray(entry.fields[field])  # a batch's: count rows
            want = np.asarray(getattr(shape, field), dtype=np.float64)
            if count is not None:
                want = np.broadcast_to(want, shape.batch_shape + got.shape[1:]).reshape(got.shape)
            assert got.shape == want.shape, (entry.name, field)
            if field == sf._SWEEP and not want.any():  # a zero sweep (-0.0 too) is left out, read as 0
                assert not got.any(), entry.name
                continue
            assert np.array_equal(got.view(np.uint64), want.view(np.uint64)), (entry.name, field)


# Content the writer does not make valid itself and a reader refuses: (label, shapes, queries,
# description, the JSON reader's message).
WRITER_REFUSALS = [
    (
        "a name with [",
        {"ring[0]": RING},
        [],
        "",
        r"\$\.shapes\[0\]\.name: expected a name: a non-empty string " r"without '\[', '\]' or '/', got \"ring\[0\]\"$",
    ),
    ("an empty name", {"": RING}, [], "", r"\$\.shapes\[0\]\.name: expected a name"),
    (
        "a name twice",
        [("a", RING), ("a", RING)],
        [],
        "",
        r"\$\.shapes\[1\]\.name: expected a name of its own, got \"a\", used by an earlier shape$",
    ),
    ("names equal as text", [(1, RING), ("1", RING)], [], "", r"\$\.shapes\[1\]\.name: expected a name of its own"),
    ("no shapes", {}, [], "", r"\$\.shapes: expected a non-empty array of shapes, got \[\]$"),
    (
        "an empty batch",
        {"none": cd.Point(np.zeros((0, 3)))},
        [],
        "",
        r"\$\.shapes\[0\]\.count \(shape 'none'\): expected the number of shapes in the batch: an integer >= 1, got 0$",
    ),
    ("a description not text", {"ring": RING}, [], 5, r"\$\.description: expected a string, got 5$"),
    (
        "a query's unknown shape",
        {"ring": RING},
        [{"a": "ring", "b": "nope", "effects": ["distance"]}],
        "",
        r"\$\.queries\[0\]\.b: expected the name of a shape of the scene, got \"nope\"$",
    ),
    (
        "a query's NaN",
        {"ring": RING, "coin": RING},
        [{"a": "ring", "effects": ["within"], "d": float("nan")}],
        "",
        r"\$\.queries\[0\]\.d: expected a number >= 0, got NaN$",
    ),
    (
        "a query's unknown field",
        {"ring": RING},
        [{"a": "ring", "effects": ["nearest"], "q": 1}],
        "",
        r"\$\.queries\[0\]\.q: unknown field",
    ),
    (
        "an effect of pairs",
        {"ring": RING, "coin": RING},
        [{"a": "ring", "effects": ["distance"]}],
        "",
        r"\$\.queries\[0\]\.effects: expected effects against the rest of the scene",
    ),
]


@pytest.mark.parametrize("label, shapes, queries, description, message", WRITER_REFUSALS)
def test_write_scene_refuses_as_a_reader_would(tmp_path, label, shapes, queries, description, message):
    """What the writer does not make valid itself is checked: its check refuses, and the error is
    the reader's, naming the entry or query and the field; nothing is written."""
    assert not _writer_check(shapes, queries, description)
    path = tmp_path / "bad.json"
    with pytest.raises(sf.SceneFileError, match=f"^{re.escape(str(path))}: " + message):
        sf.write_scene(path, shapes, queries, description=description)
    assert list(tmp_path.iterdir()) == []


# The zip module warns of the member names a NUL cuts short (a/kind, a/center, ... all "a").
ZIP_CUT_NAME = "ignore:Duplicate name:UserWarning"


@pytest.mark.parametrize(
    "label, shapes, queries, description, message",
    WRITER_REFUSALS
    + [
        pytest.param("a name with a NUL", {"a\x00": RING}, [], "", None, marks=pytest.mark.filterwarnings(ZIP_CUT_NAME))
    ],
)
def test_npz_writer_refuses_as_a_reader_would(tmp_path, label, shapes, queries, description, message):
    """The .npz writer reads its file back where its check declines (and only there): the error
    is the .npz reader's, naming the array; nothing is written. NumPy's string arrays cut a name
    at a NUL, which the check does not see: the read back does."""
    assert not _writer_check(shapes, queries, description) or any("\x00" in name for name in shapes)
    path = tmp_path / "bad.npz"
    with pytest.raises(sf.SceneFileError, match=f"^{re.escape(str(path))}: array '"):
        sf.write_scene(path, shapes, queries, description=description)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.filterwarnings(ZIP_CUT_NAME)
def test_npz_writer_does_not_read_back_what_its_check_accepts(tmp_path, monkeypatch):
    """A scene the writer's check accepts is written without reading the file back (a 10^6-shape
    scene took as long again to read); the corpus reads back as written (the test above)."""
    read_back = []
    monkeypatch.setattr(sf, "scene_from_npz", lambda tmp, path: read_back.append(path))
    shapes = _writer_corpus()
    sf.write_scene(tmp_path / "corpus.npz", shapes, [{"a": "rings[4]", "effects": ["nearest"], "k": 3}], "corpus")
    assert read_back == [] and (tmp_path / "corpus.npz").exists()
    sf.write_scene(tmp_path / "nul.npz", {"a\x00": RING})  # the check declines: read back (here, not refused)
    assert read_back == [str(tmp_path / "nul.npz")]


def test_writer_check_refuses_numbers_a_reader_refuses():
    """Numbers the library's shapes cannot hold but a conversion to float64 could make (the
    columns the writer checks): not finite, a zero direction, a negative length."""
    entries, columns = sf._entries_of(
        {"rail": cd.Line([0, 0, 0], [1, 0, 0]), "rails": cd.Line([0, 0, 0], [[1, 0, 0]] * 2)}
    )
    assert sf._written_scene_is_valid(entries, columns, [], "")
    for kind, group, rows in columns:
        for field, bad in (("origin", np.inf), ("direction", 0.0), ("sweep", -1.0), ("origin", np.nan)):
            spoilt = {f: np.array(c) for f, c in group.items()}
            spoilt[field][-1] = bad
            assert sf._refused_rows(kind, spoilt, rows).tolist() == [False] * (rows - 1) + [True], (field, bad)
            assert not sf._written_scene_is_valid(entries, [(kind, spoilt, rows)], [], "")


def _npz(tmp_path, arrays, name="scene.npz"):
    path = tmp_path / name
    with open(path, "wb") as f:
        np.savez(f, **arrays)
    return str(path)


GOOD_NPZ = {
    "format": np.array("circledist-scene"),
    "version": np.array(1),
    "shapes": np.array(["rings", "rail"]),
    "rings/kind": np.array("circle"),
    "rings/count": np.array(3),
    "rings/center": np.arange(9.0).reshape(3, 3),
    "rings/normal": np.array([0.0, 0, 1]),
    "rings/radius": np.array([1.0, 2, 3]),
    "rail/kind": np.array("line"),
    "rail/origin": np.zeros(3),
    "rail/direction": np.array([1.0, 0, 0]),
    "queries": np.array(json.dumps([{"a": "rail", "effects": ["nearest"], "k": 2}])),
}


def _without(key):
    return {k: v for k, v in GOOD_NPZ.items() if k != key}


BAD_NPZ = [
    ("missing format", _without("format"), "array 'format'", "missing (a 0-d string array)"),
    ("wrong format", {**GOOD_NPZ, "format": np.array("other")}, "array 'format'", 'expected "circledist-scene"'),
    (
        "newer version",
        {**GOOD_NPZ, "version": np.array(5)},
        "array 'version'",
        "version 5 is newer than this circledist reads (versions 1 to 4): upgrade circledist",
    ),
    ("version 0", {**GOOD_NPZ, "version": np.array(0)}, "array 'version'", "expected one of 1, 2, 3, 4, got 0"),
    ("float version", {**GOOD_NPZ, "version": np.array(1.0)}, "array 'version'", "expected a 0-d integer array"),
    ("missing shapes", _without("shapes"), "array 'shapes'", "missing (a 1-d string array"),
    ("unlisted kind", {**GOOD_NPZ, "shapes": np.array(["rings", "rail", "x"])}, "array 'x/kind'", "missing"),
    (
        "unknown kind",
        {**GOOD_NPZ, "rail/kind": np.array("plane")},
        "array 'rail/kind'",
        'expected one of point, line, ray, segment, circle, disk, bezier, arc, annulus, got "plane"',
    ),
    (
        "missing field",
        _without("rings/radius"),
        "array 'rings/radius'",
        "missing (a circle needs center, normal, radius)",
    ),
    (
        "string field",
        {**GOOD_NPZ, "rings/radius": np.array(["1", "2", "3"])},
        "array 'rings/radius'",
        "expected an array of real numbers (float or integer), got dtype <U1",
    ),
    (
        "wrong rows",
        {**GOOD_NPZ, "rings/center": np.zeros((2, 3))},
        "array 'rings/center'",
        "expected 3 rows (the batch's count) or 1, got 2",
    ),
    (
        "wrong shape",
        {**GOOD_NPZ, "rings/center": np.zeros((3, 2))},
        "array 'rings/center'",
        "expected shape [rows (count or 1)] + (3,), got (3, 2)",
    ),
    (
        "nan at an index",
        {**GOOD_NPZ, "rings/center": np.where(np.arange(9).reshape(3, 3) == 7, np.nan, 0.0)},
        "array 'rings/center' at index 2, 1",
        "expected a finite number, got nan",
    ),
    (
        "negative radius",
        {**GOOD_NPZ, "rings/radius": np.array([1.0, -2, 3])},
        "array 'rings/radius' at index 1",
        "expected a finite number >= 0, got -2.0",
    ),
    (
        "zero normal",
        {**GOOD_NPZ, "rings/normal": np.array([[0.0, 0, 1], [0, 0, 1], [0, 0, 0]])},
        "array 'rings/normal' at index 2",
        "expected a non-zero vector",
    ),
    ("unknown array", {**GOOD_NPZ, "rings/colour": np.zeros(3)}, "array 'rings/colour'", "unknown"),
    (
        "object array",
        {**GOOD_NPZ, "rings/radius": np.array([1, "a", None], dtype=object)},
        "array 'rings/radius'",
        "expected a plain NumPy array",
    ),
    ("bad query json", {**GOOD_NPZ, "queries": np.array("[{")}, "array 'queries'", "expected the JSON text"),
    (
        "bad query",
        {**GOOD_NPZ, "queries": np.array(json.dumps([{"a": "rings", "effects": ["nearest"]}]))},
        "array 'queries': $.queries[0].a",
        "expected one shape: 'rings' is a batch of 3",
    ),
    (
        "query schema",
        {**GOOD_NPZ, "queries": np.array(json.dumps([{"a": "rail", "effects": ["nearest"], "k": -1}]))},
        "array 'queries': $.queries[0].k",
        "expected an integer >= 1, got -1",
    ),
]


def test_good_npz_reads(tmp_path, capsys):
    path = _npz(tmp_path, GOOD_NPZ)
    assert cli.main([path, "--json"]) == 0
    answers = json.loads(capsys.readouterr().out)["answers"]
    assert [x["name"] for x in answers[0]["nearest"]] == ["rings[0]", "rings[1]"]


@pytest.mark.parametrize("label,arrays,where,message", BAD_NPZ, ids=[b[0] for b in BAD_NPZ])
def test_bad_npz_files(tmp_path, capsys, label, arrays, where, message):
    path = _npz(tmp_path, arrays)
    assert cli.main([path, "--json", str(tmp_path / "answers.json")]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"circledist: error: {path}: {where}") and message in err, err
    assert err.count("\n") == 1, err
    assert [p.name for p in tmp_path.iterdir()] == ["scene.npz"]


@pytest.mark.parametrize(
    "content,message",
    [
        (b"PK\x03\x04 this is no zip", "not a NumPy .npz file"),
        (np.lib.format.MAGIC_PREFIX + b"\x01\x00", "not a NumPy .npz file"),
    ],
)
def test_npz_that_is_no_npz(tmp_path, capsys, content, message):
    path = tmp_path / "broken.npz"
    path.write_bytes(content)
    assert cli.main([str(path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"circledist: error: {path}: {message}") and err.count("\n") == 1, err


def test_bad_files_exit_2_with_one_line_from_the_console(tmp_path):
    cases = {
        "absent.json": None,
        "bad.json": b"{",
        "old.json": json.dumps({"shapes": []}).encode(),
        "bad.npz": b"PK\x03\x04garbage",
        "latin1.json": b'{"description": "\xe9"}',
    }
    for name, content in cases.items():
        path = tmp_path / name
        if content is not None:
            path.write_bytes(content)
        r = subprocess.run([sys.executable, "-m", "circledist", str(path)], capture_output=True, text=True, timeout=120)
        assert r.returncode == 2 and r.stdout == "", (name, r)
        assert r.stderr.startswith(f"circledist: error: {path}: ") and r.stderr.count("\n") == 1, (name, r.stderr)
    r = subprocess.run(
        [sys.executable, "-m", "circledist", str(tmp_path / "old.json")], capture_output=True, text=True, timeout=120
    )
    assert (
        'missing field \'format\': a circledist scene starts with "format": "circledist-scene", "version": 4'
        in r.stderr
    )


def test_help_documents_the_format():
    r = subprocess.run([sys.executable, "-m", "circledist", "--help"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0
    text = r.stdout
    for needle in (
        '"format": "circledist-scene", "version": 4',
        '"count": 3',
        "beads[2]",
        ".npz scenes",
        "<name>/count",
        "queries (0-d str",
        "exit status 2",
        "write_scene",
    ):
        assert needle in text, needle
    schema_path = text.split("JSON Schema: ")[1].split()[0]
    with open(schema_path, encoding="utf-8") as f:
        assert json.loads(f.read()) == sf.schema()


@pytest.mark.slow
@pytest.mark.serial
def test_million_shape_npz_scene(tmp_path):
    """10^6 swept points and a ring in an .npz: written, read (vectorized checks), and the nearest
    three points of the ring found through the CLI equal brute force over the batch."""
    rng = np.random.default_rng(7)
    n = 10**6
    centers = rng.uniform(-100, 100, (n, 3))
    sweeps = rng.uniform(0, 0.05, n)
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 5.0)
    path = tmp_path / "big.npz"
    start = time.perf_counter()
    sf.write_scene(
        path,
        {"probe": ring, "dust": cd.Point(centers, sweep=sweeps)},
        [{"a": "probe", "effects": ["nearest"], "k": 3}, {"a": "dust[12345]", "effects": ["within"], "d": 2.0}],
    )
    written = time.perf_counter()
    scene = sf.read_scene(str(path))
    read = time.perf_counter()
    assert scene.count == n + 1
    out = tmp_path / "answers.json"
    assert cli.main([str(path), "--json", str(out)]) == 0
    answered = time.perf_counter()
    answers = json.loads(out.read_text())["answers"]
    d = cd.distance(ring, cd.Point(centers, sweep=sweeps))
    order = np.argsort(d, kind="stable")[:3]
    assert answers[0]["nearest"] == [{"name": f"dust[{i}]", "distance": d[i]} for i in order]
    near = cd.within(cd.Point(centers[12345], sweep=sweeps[12345]), cd.Point(centers, sweep=sweeps), 2.0)
    near[12345] = False
    assert answers[1]["within"] == [f"dust[{i}]" for i in np.flatnonzero(near)]
    print(
        f"10^6 points: write {written - start:.2f} s, read {read - written:.2f} s, "
        f"CLI read + answer {answered - read:.2f} s"
    )
    assert read - written < 2.0  # vectorized checks: no per-shape Python work
    # A bad value deep in a column is found, with its index, as fast.
    with np.load(path) as npz:
        arrays = dict(npz)
    arrays["dust/p"] = arrays["dust/p"].copy()
    arrays["dust/p"][765432, 1] = np.inf
    bad = _npz(tmp_path, arrays, "bad.npz")
    start = time.perf_counter()
    with pytest.raises(sf.SceneFileError) as error:
        sf.read_scene(bad)
    assert time.perf_counter() - start < 2.0
    assert str(error.value) == f"{bad}: array 'dust/p' at index 765432, 1: expected a finite number, got inf"


def test_plot_draws_batches_and_refuses_huge_scenes(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    path = tmp_path / "batches.json"
    path.write_text(json.dumps(BATCH_SCENE))
    png = tmp_path / "batches.png"
    assert cli.main([str(path), "--plot", str(png)]) == 0
    assert png.read_bytes()[:4] == b"\x89PNG"
    big = tmp_path / "big.npz"
    sf.write_scene(big, {"dust": cd.Point(np.arange(3.0 * (cli.PICTURE_LIMIT + 1)).reshape(-1, 3))})
    capsys.readouterr()
    assert cli.main([str(big), "--plot", str(tmp_path / "big.png")]) == 1
    err = capsys.readouterr().err
    assert err == (
        f"circledist: --plot draws at most {cli.PICTURE_LIMIT} shapes, {big} holds "
        f"{cli.PICTURE_LIMIT + 1}; use --no-plot\n"
    )
    assert not (tmp_path / "big.png").exists()


def test_installed_package_holds_every_file_of_the_source_package():
    """The wheel packages python/circledist whole: the schema and the demo scene are read through
    importlib.resources from wherever circledist is installed."""

    source = os.path.join(
        os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "python", "circledist"
    )
    if not os.path.isdir(source):
        pytest.skip("no source tree next to the tests")
    wanted = set()
    for folder, dirs, files in os.walk(source):
        dirs[:] = [d for d in dirs if d != "__pycache__"]
        wanted |= {os.path.relpath(os.path.join(folder, f), source) for f in files if not f.endswith((".so", ".pyc"))}
    installed = set()

    def walk(node, prefix=""):
        for child in node.iterdir():
            if child.is_dir():
                walk(child, f"{prefix}{child.name}/")
            else:
                installed.add(prefix + child.name)

    walk(resources.files("circledist"))
    assert {"scene.schema.json", "_schema.py", "scenefile.py", os.path.join("scenes", "demo.json")} <= wanted
    assert wanted <= installed, sorted(wanted - installed)
