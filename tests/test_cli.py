"""The command line (python -m circledist / the circledist console script): the table, --json,
--plot, the shipped demo scene, and bad scene files (an error naming the file, the shape or
query and the field; nothing written; a non-zero exit)."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

cd = pytest.importorskip("circledist")
cli = pytest.importorskip("circledist.cli")

SCENE = {
    "format": "circledist-scene",
    "version": 1,
    "description": "test scene",
    "shapes": [
        {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1.0},
        {"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]},
        {"name": "coin", "kind": "disk", "center": [3, 0, 0], "normal": [1, 0, 1], "radius": 0.5, "sweep": 0.1},
        {"name": "probe", "kind": "segment", "p0": [3, 0, -1], "p1": [3, 0, 1]},
        {"name": "tip", "kind": "point", "p": [0, 0, 2]},
        {"name": "cable", "kind": "bezier", "control_points": [[-2, -2, 1], [0, 0, 3], [2, -2, 1]]},
    ],
    "queries": [
        {"a": "rail", "b": "ring", "effects": ["intersects", "within", "distance", "closest_points"], "d": 0.6},
        {"name": "coin vs probe", "a": "coin", "b": "probe", "effects": ["intersects", "closest_points"]},
        {"a": "ring", "effects": ["nearest"], "k": 2},
        {"a": "coin", "effects": ["within"], "d": 3.0},
        {"a": "cable", "b": "ring", "effects": ["distance"]},
    ],
}


def write(tmp_path, data, name="scene.json"):
    p = tmp_path / name
    p.write_text(json.dumps(data) if not isinstance(data, str) else data)
    return str(p)


def test_table(tmp_path, capsys):
    assert cli.main([write(tmp_path, SCENE)]) == 0
    out = capsys.readouterr().out
    assert "test scene" in out
    assert "rail ~ ring  intersects" in out.replace("   ", "  ") or "rail ~ ring" in out
    lines = {tuple(l.split()[:4]): l for l in out.splitlines()}
    text = "\n".join(lines.values())
    assert "0.5 between (0, 1, 0.5) and (0, 1, 0)" in text
    assert "nearest k=2" in text and "within 3" in text
    assert "coin vs probe" in text


def test_json_answers_match_the_library(tmp_path, capsys):
    out_path = tmp_path / "answers.json"
    assert cli.main([write(tmp_path, SCENE), "--json", str(out_path)]) == 0
    answers = json.loads(out_path.read_text())["answers"]
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    rail = cd.Line([-3, 1, 0.5], [1, 0, 0])
    first = answers[0]
    assert first["a"] == "rail" and first["b"] == "ring" and first["d"] == 0.6
    assert first["intersects"] is False and first["within"] is True
    assert first["distance"] == cd.distance(rail, ring)
    r = cd.closest_points(rail, ring)
    assert first["closest_points"]["point_a"] == list(r.point_a)
    assert first["closest_points"]["unique"] is True
    coin = cd.Disk([3, 0, 0], [1, 0, 1], 0.5, sweep=0.1)
    probe = cd.Segment([3, 0, -1], [3, 0, 1])
    assert answers[1]["query"] == "coin vs probe" and answers[1]["intersects"] is True
    assert answers[1]["closest_points"]["distance"] == 0.0
    assert cd.intersects(coin, probe)
    nearest = answers[2]["nearest"]
    assert [x["name"] for x in nearest] == ["tip", "rail"] or len(nearest) == 2
    shapes = {s["name"]: s for s in SCENE["shapes"]}
    scene = cli.load_scene("x.json", json.dumps(SCENE))
    expected = sorted((cd.distance(scene.shapes["ring"], s), i, n) for i, (n, s) in enumerate(scene.shapes.items())
                      if n != "ring")[:2]
    assert [x["name"] for x in nearest] == [n for _, _, n in expected]
    assert [x["distance"] for x in nearest] == [d for d, _, _ in expected]
    assert answers[3]["within"] == [n for n in shapes if n != "coin"
                                    and cd.within(scene.shapes["coin"], scene.shapes[n], 3.0)]
    assert "answers written to" in capsys.readouterr().out


def test_json_to_stdout(tmp_path, capsys):
    assert cli.main([write(tmp_path, SCENE), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert len(data["answers"]) == len(SCENE["queries"])


def test_plot(tmp_path):
    pytest.importorskip("matplotlib")
    png = tmp_path / "scene.png"
    assert cli.main([write(tmp_path, SCENE), "--plot", str(png)]) == 0
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10000


HEAD = {"format": "circledist-scene", "version": 1}
# (label, file content, the JSON path, what was expected): each must appear in the one-line message.
BAD = [
    ("not json", "{", "", "not valid JSON: Expecting property name"),
    ("NaN is not JSON", '{"format": "circledist-scene", "version": 1, "x": NaN}', "", "NaN is not a JSON number"),
    ("not an object", "[1, 2]", "$", "expected an object"),
    ("no format", {"shapes": SCENE["shapes"]}, "$", "missing field 'format'"),
    ("wrong format", {"format": "scene", "version": 1, "shapes": SCENE["shapes"]}, "$.format",
     'expected "circledist-scene", got "scene"'),
    ("no version", {"format": "circledist-scene", "shapes": SCENE["shapes"]}, "$",
     "missing field 'version' (this circledist reads version 1)"),
    ("newer version", {**HEAD, "version": 2, "shapes": SCENE["shapes"]}, "$.version",
     "version 2 is newer than this circledist reads (version 1): upgrade circledist"),
    ("bad version", {**HEAD, "version": "1", "shapes": SCENE["shapes"]}, "$.version", 'expected 1, got "1"'),
    ("no shapes", {**HEAD, "queries": []}, "$", "missing field 'shapes'"),
    ("bad radius", {**HEAD, "shapes": [{"name": "r", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1],
                                        "radius": -1}]}, "$.shapes[0].radius (shape 'r')",
     "expected a number >= 0, got -1"),
    ("missing field", {**HEAD, "shapes": [{"name": "r", "kind": "disk", "center": [0, 0, 0], "radius": 1}]},
     "$.shapes[0] (shape 'r')", "missing field 'normal'"),
    ("zero normal", {**HEAD, "shapes": [{"name": "r", "kind": "disk", "center": [0, 0, 0], "normal": [0, 0, 0],
                                         "radius": 1}]}, "$.shapes[0].normal", "expected a non-zero vector"),
    ("unknown kind", {**HEAD, "shapes": [{"name": "x", "kind": "torus"}]}, "$.shapes[0].kind (shape 'x')",
     'expected one of "point", "line", "ray", "segment", "circle", "disk", "bezier", got "torus"'),
    ("unknown field", {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0], "colour": "red"}]},
     "$.shapes[0].colour (shape 'p')", "unknown field (allowed: name, kind, count, p, sweep)"),
    ("short vector", {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0]}]},
     "$.shapes[0].p (shape 'p')", "expected a vector of 3 numbers [x, y, z], got [0, 0]"),
    ("string in vector", {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, "1", 0]}]},
     "$.shapes[0].p[1] (shape 'p')", 'expected a number, got "1"'),
    ("overflowing number", '{"format": "circledist-scene", "version": 1, "shapes": [{"name": "p", "kind": "point", '
                           '"p": [0, 1e400, 0]}]}', "$.shapes[0].p[1]", "expected a finite number"),
    ("negative sweep", {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0], "sweep": -2}]},
     "$.shapes[0].sweep (shape 'p')", "expected a number >= 0, got -2"),
    ("duplicate name", {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0]},
                                           {"name": "p", "kind": "point", "p": [1, 0, 0]}]}, "$.shapes[1].name",
     'expected a name of its own, got "p"'),
    ("bracket in name", {**HEAD, "shapes": [{"name": "p[0]", "kind": "point", "p": [0, 0, 0]}]},
     "$.shapes[0].name", "expected a name: a non-empty string without '[', ']' or '/'"),
    ("bad bezier", {**HEAD, "shapes": [{"name": "c", "kind": "bezier", "control_points": [[0, 0, 0]]}]},
     "$.shapes[0].control_points (shape 'c')", "expected 2 to 8 control points"),
    ("batch column too short", {**HEAD, "shapes": [{"name": "beads", "kind": "point", "count": 3,
                                                    "p": [[0, 0, 0], [1, 0, 0]]}]},
     "$.shapes[0].p", "expected 3 vectors (the batch's count) or 1, got 2"),
    ("batch column not a column", {**HEAD, "shapes": [{"name": "beads", "kind": "point", "count": 2, "p": 5}]},
     "$.shapes[0].p (shape 'beads')", "expected a vector [x, y, z] (one for all) or an array of count vectors, got 5"),
    ("batch radius", {**HEAD, "shapes": [{"name": "r", "kind": "disk", "count": 2, "center": [0, 0, 0],
                                          "normal": [0, 0, 1], "radius": -1}]},
     "$.shapes[0].radius (shape 'r')", "expected a number >= 0 (one for all) or an array of count of them, got -1"),
    ("batch zero normal", {**HEAD, "shapes": [{"name": "rings", "kind": "circle", "count": 2, "center": [0, 0, 0],
                                               "normal": [[0, 0, 1], [0, 0, 0]], "radius": 1}]},
     "$.shapes[0].normal[1]", "expected a non-zero vector"),
    ("batch curves of two degrees", {**HEAD, "shapes": [{"name": "c", "kind": "bezier", "count": 2, "control_points": [
        [[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [1, 0, 0], [2, 1, 0]]]}]},
     "$.shapes[0].control_points[1]", "expected 2 control points as curve 0 has"),
    ("bad count", {**HEAD, "shapes": [{"name": "b", "kind": "point", "count": 0, "p": [0, 0, 0]}]},
     "$.shapes[0].count (shape 'b')", "expected the number of shapes in the batch: an integer >= 1, got 0"),
    ("unknown shape in query", {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "b": "nope",
                                                                                "effects": ["distance"]}]},
     "$.queries[0].b", 'expected the name of a shape of the scene, got "nope"'),
    ("whole batch in query", {**HEAD, "shapes": SCENE["shapes"] + [
        {"name": "beads", "kind": "point", "count": 2, "p": [[0, 0, 0], [1, 0, 0]]}],
        "queries": [{"a": "beads", "b": "ring", "effects": ["distance"]}]},
     "$.queries[0].a", "expected one shape: 'beads' is a batch of 2, name one as beads[i] with i from 0 to 1"),
    ("batch index out of range", {**HEAD, "shapes": SCENE["shapes"] + [
        {"name": "beads", "kind": "point", "count": 2, "p": [[0, 0, 0], [1, 0, 0]]}],
        "queries": [{"a": "beads[2]", "b": "ring", "effects": ["distance"]}]},
     "$.queries[0].a", "expected an index from 0 to 1 (batch 'beads' has 2 shapes), got 2"),
    ("unknown effect", {**HEAD, "shapes": SCENE["shapes"], "queries": [{"name": "q", "a": "ring", "b": "rail",
                                                                        "effects": ["volume"]}]},
     "$.queries[0].effects[0]", 'expected one of "intersects"'),
    ("scene effect on a pair", {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "b": "rail",
                                                                                "effects": ["nearest"]}]},
     "$.queries[0].effects", "expected effects against a pair (with 'b'): intersects, within, distance, "
                             'closest_points; got "nearest"'),
    ("within without d", {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "b": "rail",
                                                                          "effects": ["within"]}]},
     "$.queries[0]", "missing field 'd'"),
    ("no query for the pair", {**HEAD, "shapes": SCENE["shapes"] + [
        {"name": "cable2", "kind": "bezier", "control_points": [[0, 0, 0], [1, 1, 1]]}],
        "queries": [{"a": "cable", "b": "cable2", "effects": ["distance"]}]},
     "$.queries[0].b", "none exists between a Bezier and a Bezier"),
    ("bad k", {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "effects": ["nearest"], "k": 0}]},
     "$.queries[0].k", "expected an integer >= 1, got 0"),
]


@pytest.mark.parametrize("label,data,where,message", BAD, ids=[b[0] for b in BAD])
def test_bad_scene_files(tmp_path, capsys, label, data, where, message):
    path = write(tmp_path, data)
    out_json, out_png = tmp_path / "answers.json", tmp_path / "picture.png"
    status = cli.main([path, "--json", str(out_json), "--plot", str(out_png)])
    err = capsys.readouterr().err
    assert status == 2
    assert err.startswith(f"circledist: error: {path}: {where}") and message in err, err
    assert err.count("\n") == 1, err  # one line
    assert not out_json.exists() and not out_png.exists()
    assert sorted(os.listdir(tmp_path)) == ["scene.json"]  # nothing partial, no temporary files


def test_missing_file(tmp_path, capsys):
    assert cli.main([str(tmp_path / "absent.json")]) == 2
    assert "absent.json: cannot read" in capsys.readouterr().err


def test_demo_scene_ships_in_the_package():
    from importlib import resources

    text = resources.files("circledist").joinpath("scenes", "demo.json").read_text()
    scene = cli.load_scene("demo.json", text)
    assert len(scene.shapes) >= 5 and scene.queries


def test_module_runs_the_demo_without_arguments(tmp_path):
    pytest.importorskip("matplotlib")
    r = subprocess.run([sys.executable, "-m", "circledist"], cwd=tmp_path, capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    assert "closest_points" in r.stdout and "nearest" in r.stdout
    png = tmp_path / cli.DEMO_PICTURE
    assert png.exists() and png.read_bytes()[:4] == b"\x89PNG"


def test_module_no_plot(tmp_path):
    r = subprocess.run([sys.executable, "-m", "circledist", "--no-plot"], cwd=tmp_path, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert os.listdir(tmp_path) == []


def test_console_script_is_declared():
    from importlib import metadata

    scripts = [e for e in metadata.entry_points(group="console_scripts") if e.name == "circledist"]
    assert scripts and scripts[0].value == "circledist.cli:main"
