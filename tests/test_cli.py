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

from circledist_cases.scene_documents import BAD, SCENE  # noqa: E402


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
