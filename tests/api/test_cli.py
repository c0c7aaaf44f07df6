"""The command line (python -m circledist / the circledist console script): the table, --json,
--plot, the shipped demo scene, and bad scene files (an error naming the file, the shape or
query and the field; nothing written; a non-zero exit)."""

import json
import os
import subprocess
import sys
from pathlib import Path

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
    expected = sorted(
        (cd.distance(scene.shapes["ring"], s), i, n) for i, (n, s) in enumerate(scene.shapes.items()) if n != "ring"
    )[:2]
    assert [x["name"] for x in nearest] == [n for _, _, n in expected]
    assert [x["distance"] for x in nearest] == [d for d, _, _ in expected]
    assert answers[3]["within"] == [
        n for n in shapes if n != "coin" and cd.within(scene.shapes["coin"], scene.shapes[n], 3.0)
    ]
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
    r = subprocess.run([sys.executable, "-m", "circledist"], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "closest_points" in r.stdout and "nearest" in r.stdout
    png = tmp_path / cli.DEMO_PICTURE
    assert png.exists() and png.read_bytes()[:4] == b"\x89PNG"


def test_module_no_plot(tmp_path):
    r = subprocess.run(
        [sys.executable, "-m", "circledist", "--no-plot"], cwd=tmp_path, capture_output=True, text=True, timeout=120
    )
    assert r.returncode == 0, r.stderr
    assert os.listdir(tmp_path) == []


def test_console_script_is_declared():
    from importlib import metadata

    scripts = [e for e in metadata.entry_points(group="console_scripts") if e.name == "circledist"]
    assert scripts and scripts[0].value == "circledist.cli:main"


# ---- hostile inputs: one clean line, exit 2, in bounded time and memory -----------------------

MEMORY_LIMIT = 2 << 30  # bytes of address space the command-line subprocesses below may take


def run_limited(args, cwd, timeout=60):
    """python -m circledist ARGS in a subprocess held to MEMORY_LIMIT and timeout: an input that
    would block or eat memory fails the test instead of hanging it."""
    import resource

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))

    try:
        return subprocess.run(
            [sys.executable, "-m", "circledist", *args],
            cwd=cwd,
            capture_output=True,
            text=True,
            timeout=timeout,
            preexec_fn=limit,
        )
    except subprocess.TimeoutExpired:
        pytest.fail(f"circledist {' '.join(args)} still running after {timeout} s")


def assert_one_error_line(r, start):
    assert r.returncode == 2, (r.returncode, r.stderr[-2000:])
    assert r.stderr.startswith(f"circledist: error: {start}"), r.stderr[-2000:]
    assert r.stderr.count("\n") == 1 and "Traceback" not in r.stderr, r.stderr[-2000:]


def _fifo(tmp_path, name="scene.json"):
    path = tmp_path / name
    os.mkfifo(path)
    return str(path)


@pytest.mark.skipif(not hasattr(os, "mkfifo") or not os.path.exists("/dev/zero"), reason="POSIX files")
@pytest.mark.parametrize(
    "make,what",
    [
        (_fifo, "a FIFO"),
        (lambda tmp_path: _fifo(tmp_path, "scene.npz"), "a FIFO"),
        (lambda tmp_path: "/dev/zero", "a character device"),
        (lambda tmp_path: "/dev/urandom", "a character device"),
        (lambda tmp_path: str(tmp_path), "a directory"),
    ],
    ids=["fifo", "fifo-npz", "dev-zero", "dev-urandom", "directory"],
)
@pytest.mark.parametrize("suffix_args", [[], ["--json", "-"]], ids=["table", "json"])
def test_files_that_are_not_regular_are_refused(tmp_path, make, what, suffix_args):
    path = make(tmp_path)
    r = run_limited([path, "--no-plot", *suffix_args], tmp_path, timeout=30)
    assert_one_error_line(r, f"{path}: cannot read the scene file: it is {what}")


HUGE_COUNTS = [10**8, 10**12, 2**62, 10**30]


@pytest.mark.parametrize("count", HUGE_COUNTS, ids=[f"count-{c:.0e}" for c in HUGE_COUNTS])
@pytest.mark.parametrize("form", ["json", "npz", "npz-no-sweep"])
def test_a_count_beyond_memory_is_refused_before_anything_is_built(tmp_path, count, form):
    """A batch's count in a tiny file (one value for all its shapes) is checked against the memory
    the scene would take before any name or array of its shapes is made: one line naming the
    count, in bounded time and memory (the subprocess may take MEMORY_LIMIT bytes)."""
    if form == "json":
        path = write(
            tmp_path,
            {
                "format": "circledist-scene",
                "version": 1,
                "shapes": [{"name": "dust", "kind": "point", "count": count, "p": [0, 0, 0], "sweep": 0}],
                "queries": [{"effects": ["pairs_within"], "d": 1}],
            },
        )
        where = "$.shapes[0].count (shape 'dust')"
    else:
        if count >= 2**63:
            pytest.skip("an .npz count is an int64")
        path = str(tmp_path / "scene.npz")
        arrays = {
            "format": np.array("circledist-scene"),
            "version": np.array(1),
            "shapes": np.array(["dust"]),
            "dust/kind": np.array("point"),
            "dust/count": np.array(count),
            "dust/p": np.zeros(3),
        }
        if form == "npz":
            arrays["dust/sweep"] = np.zeros(1)
        np.savez(path, **arrays)
        where = "array 'dust/count'"
    r = run_limited([path, "--no-plot"], tmp_path, timeout=60)
    assert_one_error_line(r, f"{path}: {where}: a count of {count} makes a scene of {count} shapes")
    assert "more than the" in r.stderr and "of memory there is" in r.stderr


def _deep(depth):
    return "[" * depth + "]" * depth


DEPTHS = [900, 950, 975, 984, 985, 986, 987, 990, 995, 1000, 2000, 10**5]


@pytest.mark.parametrize("place", ["shapes", "field", "description", "query", "top"])
def test_deeply_nested_json_is_one_line(tmp_path, capsys, place):
    """JSON nested about as deep as Python's recursion limit, wherever in the document: one line
    (json.loads may refuse it, or the validator or a message meet the depth), never a
    RecursionError. The depths span the limit whatever the caller's own stack depth."""
    for depth in DEPTHS + list(range(700, 1000, 7)):
        deep = _deep(depth)
        doc = {
            "shapes": '{"format": "circledist-scene", "version": 1, "shapes": %s}' % deep,
            "field": '{"format": "circledist-scene", "version": 1, "shapes": [{"name": "a", "kind": "point", '
            '"count": 2, "p": %s}]}' % deep,
            "description": '{"format": "circledist-scene", "version": 1, "description": %s, "shapes": []}' % deep,
            "query": '{"format": "circledist-scene", "version": 1, "shapes": [{"name": "a", "kind": "point", '
            '"p": [0, 0, 0]}], "queries": [{"a": "a", "effects": %s}]}' % deep,
            "top": deep,
        }[place]
        path = write(tmp_path, doc)
        assert cli.main([path, "--no-plot"]) == 2, depth
        err = capsys.readouterr().err
        assert err.startswith(f"circledist: error: {path}: ") and err.count("\n") == 1, (depth, err[:300])


def test_deeply_nested_json_from_the_console(tmp_path):
    path = write(
        tmp_path,
        '{"format": "circledist-scene", "version": 1, "shapes": [{"name": "a", "kind": "point", '
        '"count": 2, "p": %s}]}' % _deep(985),
    )
    assert_one_error_line(run_limited([path, "--no-plot"], tmp_path), f"{path}: ")


SURROGATE = "\ud800"


@pytest.mark.parametrize("place", ["name", "description", "query name"])
def test_lone_surrogates_are_refused(tmp_path, capsys, place):
    """ "\\ud800" is valid JSON but no character: a name, description or query name holding one is
    refused where it stands (it could not be printed or written as UTF-8 later)."""
    doc = json.loads(json.dumps(SCENE))
    if place == "name":
        doc["shapes"][4]["name"] = "tip" + SURROGATE
        where = "$.shapes[4].name"
    elif place == "description":
        doc["description"] = "x" + SURROGATE
        where = "$.description"
    else:
        doc["queries"][1]["name"] = SURROGATE
        where = "$.queries[1].name"
    path = write(tmp_path, json.dumps(doc))  # json.dumps escapes it as \ud800
    assert "\\ud800" in Path(path).read_text()
    assert cli.main([path, "--no-plot"]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"circledist: error: {path}: {where}: expected text, got a lone surrogate (U+D800)"), err
    assert err.count("\n") == 1
    r = run_limited([path, "--no-plot"], tmp_path)
    assert_one_error_line(r, f"{path}: {where}: ")


@pytest.mark.parametrize("target", ["missing folder", "a folder", "under a file"])
@pytest.mark.parametrize("option", ["--json", "--plot"])
def test_outputs_that_cannot_be_written(tmp_path, capsys, target, option):
    if option == "--plot":
        pytest.importorskip("matplotlib")
    (tmp_path / "file").write_text("")
    out = {
        "missing folder": tmp_path / "absent" / "out",
        "a folder": tmp_path,
        "under a file": tmp_path / "file" / "out",
    }[target]
    scene = write(tmp_path, SCENE)
    other = tmp_path / ("answers.json" if option == "--plot" else "picture.png")
    other_option = "--json" if option == "--plot" else "--plot"
    before = sorted(os.listdir(tmp_path))
    assert cli.main([scene, option, str(out), other_option, str(other)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"circledist: error: {out}: cannot write the output: ") and err.count("\n") == 1, err
    assert sorted(os.listdir(tmp_path)) == before  # nothing written, no temporary files
    r = run_limited([scene, option, str(out), "--no-plot" if option == "--json" else "--json"], tmp_path)
    assert_one_error_line(r, f"{out}: cannot write the output: ")


FAR = 1e308


def test_json_answers_beyond_a_double_are_null(tmp_path, capsys):
    """Two points 2e308 apart: the distance overflows to inf; --json writes null (valid JSON, no
    Infinity) where the table prints inf."""
    doc = {
        "format": "circledist-scene",
        "version": 1,
        "shapes": [
            {"name": "east", "kind": "point", "p": [FAR, 0, 0]},
            {"name": "west", "kind": "point", "p": [-FAR, 0, 0]},
        ],
        "queries": [
            {"a": "east", "b": "west", "effects": ["distance", "closest_points"]},
            {"a": "east", "effects": ["nearest"]},
        ],
    }
    east, west = cd.Point([FAR, 0, 0]), cd.Point([-FAR, 0, 0])
    assert cd.distance(east, west) == float("inf")  # what the answer is, before the format
    path = write(tmp_path, doc)
    out = tmp_path / "answers.json"
    assert cli.main([path, "--json", str(out)]) == 0
    assert " inf" in capsys.readouterr().out

    def refuse(name):
        raise ValueError(f"{name} is not JSON")

    answers = json.loads(out.read_text(), parse_constant=refuse)["answers"]
    assert answers[0]["distance"] is None and answers[0]["closest_points"]["distance"] is None
    assert answers[0]["closest_points"]["point_a"] == [FAR, 0.0, 0.0]
    assert answers[1]["nearest"] == [{"name": "west", "distance": None}]
    assert cli.main([path, "--json"]) == 0
    assert json.loads(capsys.readouterr().out, parse_constant=refuse)["answers"] == answers


@pytest.mark.parametrize("option", ["--json", "--plot"])
def test_outputs_honour_the_umask_and_keep_a_replaced_files_mode(tmp_path, umask_022, option):
    if option == "--plot":
        pytest.importorskip("matplotlib")
    scene = write(tmp_path, SCENE)
    out = tmp_path / "out"
    assert cli.main([scene, option, str(out)]) == 0
    assert os.stat(out).st_mode & 0o777 == 0o644
    os.chmod(out, 0o604)
    assert cli.main([scene, option, str(out)]) == 0
    assert os.stat(out).st_mode & 0o777 == 0o604


def _extreme(shapes, description=""):
    doc = {
        "format": "circledist-scene",
        "version": 3,
        "shapes": shapes,
        "queries": [{"a": shapes[0]["name"], "b": shapes[1]["name"], "effects": ["closest_points"]}],
    }
    if description:
        doc["description"] = description
    return doc


TINY, HUGE = 5e-324, 1e308
RING_AT_ORIGIN = {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}
EXTREME_SCENES = {
    "subnormal normal": _extreme(
        [
            {"name": "coin", "kind": "disk", "center": [0, 0, 0], "normal": [0, 0, TINY], "radius": 1},
            {"name": "tip", "kind": "point", "p": [0, 0, 2]},
        ]
    ),
    "huge normal": _extreme(
        [
            {"name": "coin", "kind": "disk", "center": [0, 0, 0], "normal": [HUGE, HUGE, 0], "radius": 1},
            {
                "name": "washer",
                "kind": "annulus",
                "center": [3, 0, 0],
                "normal": [0, HUGE, HUGE],
                "inner_radius": 0.5,
                "outer_radius": 1,
            },
        ]
    ),
    "subnormal directions": _extreme(
        [
            {"name": "rail", "kind": "line", "origin": [0, 0, 0], "direction": [TINY, 0, 0]},
            {
                "name": "hook",
                "kind": "arc",
                "center": [0, 3, 0],
                "normal": [0, 0, TINY],
                "radius": 1,
                "start": [TINY, TINY, 0],
                "angle": 4,
            },
        ]
    ),
    "huge coordinates": _extreme(
        [
            {"name": "east", "kind": "point", "p": [HUGE, HUGE, HUGE]},
            {"name": "west", "kind": "point", "p": [-HUGE, -HUGE, -HUGE]},
        ]
    ),
    "huge ring": _extreme(
        [
            {"name": "ring", "kind": "circle", "center": [HUGE, 0, 0], "normal": [0, 0, 1], "radius": HUGE},
            {"name": "ray", "kind": "ray", "origin": [-HUGE, 0, 0], "direction": [1, 0, 0]},
        ]
    ),
    "huge curve": _extreme(
        [
            {"name": "cable", "kind": "bezier", "control_points": [[-HUGE, 0, 0], [0, HUGE, 0], [HUGE, 0, 0]]},
            {"name": "stick", "kind": "segment", "p0": [0, 0, -HUGE], "p1": [0, 0, HUGE]},
        ]
    ),
    "tiny scene": _extreme(
        [
            {"name": "a", "kind": "point", "p": [TINY, 0, 0]},
            {"name": "b", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1e-300},
        ]
    ),
    "long description": _extreme(
        [RING_AT_ORIGIN, {"name": "x" * 10**5, "kind": "point", "p": [0, 0, 2]}], description="a" * 10**6
    ),
}


@pytest.mark.parametrize("label", EXTREME_SCENES)
def test_plot_draws_valid_scenes_of_extreme_values(tmp_path, capsys, label):
    """Valid scenes at the edges of a double (normals of length 5e-324 or 1e308, coordinates near
    1e308 or 1e-300, a 10^6-character description, a 10^5-character name): drawn, in units of a
    power of ten where lengths are far from 1, their titles and labels cut short."""
    pytest.importorskip("matplotlib")
    path = write(tmp_path, EXTREME_SCENES[label])
    png = tmp_path / "scene.png"
    status = cli.main([path, "--plot", str(png)])
    err = capsys.readouterr().err
    assert status == 0 and "Traceback" not in err, err[-3000:]
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and 1000 < len(data) < 5 << 20


LINE_BREAKS = ["\n", "\r", "\x0b", "\x0c", "\x1c", "\x85", "\u2028", "\u2029"]


@pytest.mark.parametrize("brk", LINE_BREAKS, ids=[f"U+{ord(c):04X}" for c in LINE_BREAKS])
@pytest.mark.parametrize("place", ["json batch name", "npz name", "file name"])
def test_errors_stay_one_line_whatever_the_names_hold(tmp_path, capsys, brk, place):
    """A line break in a shape's name (the schema's name allows any character but [, ] and /) or
    in the file's path: the error is still one line, the break escaped."""
    name = f"a{brk}b"
    if place == "npz name":
        path = str(tmp_path / "scene.npz")
        np.savez(
            path,
            format=np.array("circledist-scene"),
            version=np.array(1),
            shapes=np.array(["ok", name]),
            **{"ok/kind": np.array("point"), "ok/p": np.zeros(3)},
        )
    else:
        doc = {
            "format": "circledist-scene",
            "version": 1,
            "shapes": [{"name": name, "kind": "point", "count": 2, "p": [0, 0, 0]}],
            "queries": [{"a": name, "effects": ["nearest"]}],
        }
        path = write(tmp_path, doc, f"scene{brk}.json" if place == "file name" else "scene.json")
        if place == "file name":
            doc["shapes"][0]["name"] = "ab"
            doc["queries"][0]["a"] = "ab"
            Path(path).write_text(json.dumps(doc))
    assert cli.main([path, "--no-plot"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("circledist: error: ") and len(err.splitlines()) == 1 and err.endswith("\n"), repr(err)
    assert ("is a batch of 2" if place != "npz name" else "missing") in err
