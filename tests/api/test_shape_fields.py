"""The one table of shape fields (src/shapes.hpp, exported as circledist._core._shape_fields): the
shape classes, Scene, the scene files (their reader, writer and shipped JSON Schema) and the
command line all follow it, so a kind's fields are described in one place."""

import importlib.resources
import importlib.util
import json
import re

import numpy as np
import pytest

cd = pytest.importorskip("circledist")
cli = pytest.importorskip("circledist.cli")
sf = pytest.importorskip("circledist.scenefile")
from circledist import scene as scene_module  # noqa: E402

TABLE = cd._core._shape_fields()
SWEEP = cd._core._sweep_field()


# One value per role, in the shape a single shape's field has (distinct per field, so that a field
# read back under another field's name would be caught).
def _value(role, i):
    if role == "vector":
        return [0.5 + i, -1.0, 2.0 - i]
    if role == "direction":
        return [0.0, 0.6, 0.8 + i]
    if role == "length":
        return 0.75 + i
    if role == "angle":
        return 1.25 + i / 8
    assert role == "control_points", role
    return [[0.0, 0.0, i], [1.0, 2.0, 0.0], [2.0, 0.0, 1.0]]


def _shape(kind, sweep=0.25, count=None):
    """A shape of `kind` built from the table, every field given by keyword (a batch of count
    copies where asked)."""
    fields = {name: np.asarray(_value(role, i)) for i, (name, role) in enumerate(TABLE[kind])}
    if count is not None:
        fields = {n: np.broadcast_to(a, (count,) + a.shape) for n, a in fields.items()}
    return getattr(cd, kind)(**fields, sweep=sweep), fields


def test_table_names_every_shape_class_and_its_fields():
    assert list(TABLE) == ["Point", "Line", "Ray", "Segment", "Circle", "Disk", "Bezier", "Arc", "Annulus"]
    assert SWEEP == ("sweep", "length")
    for kind, fields in TABLE.items():
        shape, given = _shape(kind)
        # to_arrays() lists the fields the C++ shape holds, in its order, the sweep last.
        assert list(shape.to_arrays()) == [name for name, _ in fields] + [SWEEP[0]]
        for name in given:
            assert np.array_equal(getattr(shape, name), given[name]), (kind, name)
        assert {role for _, role in fields} <= {"vector", "direction", "length", "angle", "control_points"}


def test_scene_and_scene_files_read_the_table():
    assert scene_module.KIND_FIELDS == {k: tuple(n for n, _ in f) for k, f in TABLE.items()}
    assert sf.KINDS == {k.lower(): (k, dict(f)) for k, f in TABLE.items()}


def test_shipped_schema_describes_the_table():
    """The JSON Schema is a shipped file, not generated: it must agree with the table."""
    schema = sf.schema()["$defs"]
    assert schema["shape"]["properties"]["kind"]["enum"] == [k.lower() for k in TABLE]
    for kind, fields in TABLE.items():
        spec = schema[kind.lower()]
        names = [n for n, _ in fields]
        assert spec["required"] == ["name", "kind"] + names, kind
        assert [p for p in spec["properties"] if p not in ("name", "kind", "count")] == names + [SWEEP[0]], kind


@pytest.mark.parametrize("suffix", [".json", ".npz"])
@pytest.mark.parametrize("count", [None, 3], ids=["single", "batch"])
def test_every_kind_round_trips_through_a_scene_file(tmp_path, suffix, count):
    shapes = {kind.lower(): _shape(kind, count=count)[0] for kind in TABLE}
    path = tmp_path / f"scene{suffix}"
    sf.write_scene(path, shapes)
    back = sf.read_scene(str(path))
    assert [e.kind for e in back.entries] == [k.lower() for k in TABLE]
    for entry in back.entries:
        shape = shapes[entry.name]
        assert entry.class_name == shape.kind and entry.count == count
        assert list(entry.fields) == [n for n, _ in TABLE[shape.kind]] + [SWEEP[0]]
        got, want = back.shapes[entry.name].to_arrays(), shape.to_arrays()
        assert list(got) == list(want)
        for name in want:  # a batch's field given once for all is read back as a column
            assert np.array_equal(got[name], np.broadcast_to(want[name], got[name].shape)), (entry.name, name)
            assert got[name].shape[:1] == (count,) if count else got[name].shape == want[name].shape


def test_command_line_describes_and_draws_every_kind(tmp_path, capsys):
    with pytest.raises(SystemExit):
        cli.main(["--help"])
    help_text = " ".join(capsys.readouterr().out.split())
    kinds = help_text.split("Kinds and fields: ")[1].split("; every kind")[0]
    for kind, fields in TABLE.items():
        # "line and ray (origin, direction)": the kind, then its group's fields
        assert re.search(rf"\b{kind.lower()}\b[a-z ]*\({', '.join(n for n, _ in fields)}\b", kinds), (kind, kinds)
    shapes = [
        {"name": kind.lower(), "kind": kind.lower(), **{n: _value(r, i) for i, (n, r) in enumerate(f)}}
        for kind, f in TABLE.items()
    ]
    queries = [{"a": s["name"], "b": "circle", "effects": ["closest_points"]} for s in shapes if s["name"] != "circle"]
    path = tmp_path / "every_kind.json"
    path.write_text(
        json.dumps({"format": "circledist-scene", "version": sf.VERSION, "shapes": shapes, "queries": queries})
    )
    answers = tmp_path / "answers.json"
    argv = [str(path), "--json", str(answers)]
    if importlib.util.find_spec("matplotlib") is not None:  # the picture draws every kind too
        argv += ["--plot", str(tmp_path / "every_kind.png")]
    assert cli.main(argv) == 0
    got = json.loads(answers.read_text())["answers"]
    scene = sf.read_scene(str(path))
    assert len(got) == len(TABLE) - 1
    for q, a in zip(queries, got):
        assert a["closest_points"]["distance"] == float(cd.distance(scene.shape(q["a"]), scene.shape("circle")))


def test_the_control_point_limit_is_the_modules():
    """A Bezier curve takes 2 to _core._max_control_points control points: the constructor, the
    scene files' reader and schema, and the command line's help all say the same number."""
    most = cd._core._max_control_points
    good = np.zeros((most, 3))
    good[:, 0] = np.arange(most)
    assert cd.Bezier(good).control_points.shape == (most, 3)
    with pytest.raises(ValueError):
        cd.Bezier(np.zeros((most + 1, 3)))
    schema = json.loads(importlib.resources.files("circledist").joinpath(sf.SCHEMA_RESOURCE).read_text())
    sets = [node for node in _nodes(schema) if "maxItems" in node and "2 to" in node.get("title", "")]
    assert len(sets) == 2 and all(
        node["maxItems"] == most and f"2 to {most} control points" in node["title"] for node in sets
    )
    assert f"control_points: 2 to {most} points" in cli.FORMAT_HELP


def _nodes(node):
    """Every dict node of a JSON document."""
    if isinstance(node, dict):
        yield node
        for value in node.values():
            yield from _nodes(value)
    elif isinstance(node, list):
        for value in node:
            yield from _nodes(value)
