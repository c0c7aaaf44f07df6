"""Scene files with motions (format version 4): a query's "motion" / "motion_b" and the effects
first_contact and closest_approach, read from JSON and .npz, written back, refused in older
versions; the command line's answers (the library's, to the bit), its table and JSON, and the
picture's poses of each moving shape (start, contact, end). The bad documents of
circledist_cases.scene_documents (motions among them) run through test_cli / test_scene_file."""

import json
from importlib import resources

import numpy as np
import pytest

cd = pytest.importorskip("circledist")
cli = pytest.importorskip("circledist.cli")
sf = pytest.importorskip("circledist.scenefile")

from circledist_cases.scene_documents import SCENE  # noqa: E402

TIP_QUERY, PROBE_QUERY = len(SCENE["queries"]) - 2, len(SCENE["queries"]) - 1


def read(doc, name="scene.json"):
    return sf.read_scene(name, text=json.dumps(doc))


def same_motion(m, translation=(0, 0, 0), rotation=(0, 0, 0), center=(0, 0, 0)):
    a = m.to_arrays()
    return (
        np.array_equal(a["translation"], translation)
        and np.array_equal(a["rotation"], rotation)
        and np.array_equal(a["center"], center)
    )


def test_queries_expose_their_motions():
    scene = read(SCENE)
    tip, probe = scene.queries[TIP_QUERY], scene.queries[PROBE_QUERY]
    assert isinstance(tip["motion"], cd.Motion) and tip["motion_b"] is None
    assert same_motion(tip["motion"], translation=[0, 1, -2])
    assert tip["d"] == 0.1 and tip["k"] is None and tip["effects"] == ["first_contact"]
    assert same_motion(probe["motion"], [-3, 0, 0], [0, 0, 3.0], [1.5, 0, 0]) and probe["k"] == 2
    assert all(q["motion"] is None and q["motion_b"] is None for q in scene.queries[:TIP_QUERY])
    # Fields left out are zero; motion_b moves b.
    doc = {**SCENE, "queries": [{"a": "tip", "b": "ring", "motion_b": {}, "effects": ["first_contact"]}]}
    q = read(doc).queries[0]
    assert q["motion"] is None and same_motion(q["motion_b"])
    from circledist._cli_load import scene_queries

    queries = scene_queries(read(SCENE))
    assert queries[TIP_QUERY].motion is not None and queries[TIP_QUERY].motion_b is None


@pytest.mark.parametrize("version", [1, 2, 3])
def test_older_versions_still_load(version):
    shapes = [s for s in SCENE["shapes"] if sf.KIND_SINCE.get(s["kind"], 1) <= version]
    names = {s["name"] for s in shapes}
    queries = [q for q in SCENE["queries"] if "motion" not in q and q["a"] in names and q.get("b", "ring") in names]
    scene = read({**SCENE, "version": version, "shapes": shapes, "queries": queries})
    assert len(scene.queries) == len(queries) > 0


@pytest.mark.parametrize("suffix", [".json", ".npz"])
def test_write_and_read_back_motions(tmp_path, suffix):
    scene = read(SCENE)
    path = tmp_path / f"again{suffix}"
    sf.write_scene(str(path), scene.shapes, scene.queries_as_written(), description=scene.description)
    back = sf.read_scene(str(path))
    for q, r in zip(scene.queries, back.queries):
        for key in ("motion", "motion_b"):
            assert (q[key] is None) == (r[key] is None)
            if q[key] is not None:
                for field, value in q[key].to_arrays().items():
                    assert np.array_equal(value, r[key].to_arrays()[field])
        assert {k: v for k, v in q.items() if "motion" not in k} == {k: v for k, v in r.items() if "motion" not in k}
    assert back.queries_as_written() == scene.queries_as_written()
    # The version written is the oldest that holds the content: 4 with motions, 3 without.
    version = json.loads(path.read_text())["version"] if suffix == ".json" else int(np.load(path)["version"])
    assert version == 4
    static = [q for q in scene.queries_as_written() if "motion" not in q]
    sf.write_scene(str(path), scene.shapes, static)
    version = json.loads(path.read_text())["version"] if suffix == ".json" else int(np.load(path)["version"])
    assert version == 3


def test_an_npz_of_version_3_with_a_motion_is_refused(tmp_path):
    scene = read(SCENE)
    path = tmp_path / "scene.npz"
    sf.write_scene(str(path), scene.shapes, scene.queries_as_written())
    arrays = dict(np.load(path))
    arrays["version"] = np.array(3)
    np.savez(path, **arrays)
    with pytest.raises(sf.SceneFileError) as error:
        sf.read_scene(str(path))
    message = str(error.value)
    assert f"array 'queries': $.queries[{TIP_QUERY}].motion: a query's motion needs format version 4" in message


def test_closest_approach_is_the_librarys_and_the_least_worked_out_by_hand():
    # A point passing a unit ring at height 1, offset 2 in y, sliding 6 along x from x = -3: its
    # least distance is at t = 0.5 (x = 0), from (0, 2, 1) to the rim point (0, 1, 0): sqrt(2).
    doc = {
        "format": "circledist-scene",
        "version": 4,
        "shapes": [
            {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1.0},
            {"name": "p", "kind": "point", "p": [-3, 2, 1]},
        ],
        "queries": [{"a": "p", "b": "ring", "motion": {"translation": [6, 0, 0]}, "effects": ["closest_approach"]}],
    }
    scene = read(doc)
    (answered,) = cli.answer(scene)
    got = answered.answers["closest_approach"]
    assert got["time"] == pytest.approx(0.5, abs=1e-9)
    assert got["distance"] == pytest.approx(2**0.5, rel=1e-12)
    want = cd.closest_approach(scene.shape("p"), scene.shape("ring"), scene.queries[0]["motion"])
    assert got["time"] == float(want.time) and got["distance"] == float(want.distance)
    assert "closest_approach" in cli.table(scene, [answered])


def test_answers_are_the_librarys(tmp_path):
    scene = read(SCENE)
    queries = cli.answer(scene)
    tip, ring, probe = scene.shape("tip"), scene.shape("ring"), scene.shape("probe")
    want = cd.first_contact(tip, ring, scene.queries[TIP_QUERY]["motion"], within=0.1)
    got = queries[TIP_QUERY].answers["first_contact"]
    assert got["time"] == want.time and got["distance"] == want.distance and np.isfinite(want.time)
    assert got["point_a"] == list(want.point_a) and got["point_b"] == list(want.point_b)
    assert got["param_a"] == list(want.param_a) and got["unique"] == bool(want.unique)
    hits = scene.scene().first_contact("probe", scene.queries[PROBE_QUERY]["motion"], k=2)
    got = queries[PROBE_QUERY].answers["first_contact"]
    assert [x["name"] for x in got] == [h.name for h in hits] and len(hits) == 2
    assert [x["time"] for x in got] == [h.time for h in hits]
    assert probe.kind == "Segment"
    table = cli.table(scene, queries)
    line = next(x for x in table.splitlines() if x.startswith("tip ~ ring") and "first_contact" in x)
    assert "first_contact within 0.1" in line and f"at t={want.time:.6g}:" in line
    line = next(x for x in table.splitlines() if x.startswith("swinging probe"))
    assert "first_contact k=2" in line and all(f"{h.name} at t={h.time:.6g}" in line for h in hits)
    data = json.loads(cli.as_json(scene, queries))["answers"][TIP_QUERY]
    assert data["motion"] == {"translation": [0.0, 1.0, -2.0], "rotation": [0.0] * 3, "center": [0.0] * 3}
    assert data["first_contact"]["time"] == want.time


def test_no_contact_is_none_and_null(tmp_path, capsys):
    doc = {
        **SCENE,
        "queries": [
            {"a": "tip", "b": "ring", "motion": {"translation": [0, 0, 5]}, "effects": ["first_contact"]},
            {"a": "tip", "motion": {"translation": [0, 0, 5]}, "effects": ["first_contact"]},
        ],
    }
    path = tmp_path / "away.json"
    path.write_text(json.dumps(doc))
    assert cli.main([str(path), "--json"]) == 0
    answers = json.loads(capsys.readouterr().out)["answers"]
    assert answers[0]["first_contact"]["time"] is None and answers[0]["first_contact"]["distance"] is None
    assert answers[1]["first_contact"] == []
    assert cli.main([str(path)]) == 0
    lines = [x for x in capsys.readouterr().out.splitlines() if "first_contact" in x]
    assert len(lines) == 2 and all(x.endswith("none") for x in lines)


def _texts(fig):
    return [t.get_text().strip() for ax in fig.axes for t in ax.texts]


def test_the_picture_draws_each_moving_shape_at_start_contact_and_end(tmp_path):
    pytest.importorskip("matplotlib")
    from circledist._cli_present import figure_of

    scene = read(SCENE)
    queries = cli.answer(scene)
    fig = figure_of(scene, queries)
    texts = _texts(fig)
    tip_time = queries[TIP_QUERY].answers["first_contact"]["time"]
    probe_time = queries[PROBE_QUERY].answers["first_contact"][0]["time"]
    for name, t in (("tip", tip_time), ("probe", probe_time)):
        assert f"{name} t=0 (start)" in texts and f"{name} t=1 (end)" in texts
        assert f"{name} t={t:.6g} (contact)" in texts
    # The poses are the moved shapes: the tip's contact pose is where the motion puts it.
    moved = scene.shape("tip").moved(scene.queries[TIP_QUERY]["motion"], tip_time).p
    points = [c._offsets3d for ax in fig.axes for c in ax.collections if hasattr(c, "_offsets3d")]
    assert any(np.allclose([float(np.ravel(v)[0]) for v in p], moved) for p in points)
    import matplotlib.pyplot as plt

    plt.close(fig)
    # Without motion, no pose; and --plot writes the picture.
    static = {**SCENE, "queries": SCENE["queries"][:TIP_QUERY]}
    fig = figure_of(read(static), cli.answer(read(static)))
    assert not [t for t in _texts(fig) if "(start)" in t]
    plt.close(fig)
    path, png = tmp_path / "scene.json", tmp_path / "scene.png"
    path.write_text(json.dumps(SCENE))
    assert cli.main([str(path), "--plot", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_example_scene_with_motion():
    import jsonschema

    text = resources.files("circledist").joinpath("scenes", "motion.json").read_text(encoding="utf-8")
    jsonschema.validate(json.loads(text), sf.schema(), cls=jsonschema.Draft202012Validator)
    scene = sf.read_scene("motion.json", text=text)
    queries = cli.answer(scene)
    assert json.loads(text)["version"] == sf.VERSION == 4
    assert len(queries) == 3 and all(q.motion is not None for q in queries)
    assert any(q.motion_b is not None for q in queries)
    for q in queries:
        v = q.answers["first_contact"]
        for r in v if isinstance(v, list) else [v]:
            assert 0 < r["time"] < 1  # each motion reaches its shape during the motion, not at rest


def test_the_help_example_is_a_valid_scene_with_motions():
    from circledist._cli_load import format_help

    text = format_help()
    doc, _ = json.JSONDecoder().raw_decode(text[text.index('{"format"') :])
    scene = read(doc, "help.json")
    assert doc["version"] == sf.VERSION and any(q["motion"] is not None for q in scene.queries)
    queries = cli.answer(scene)
    assert all(q.answers for q in queries)


def test_the_guide_example_loads_and_reaches_its_shapes():
    import re
    from pathlib import Path

    guide = (Path(__file__).resolve().parents[2] / "docs" / "guide" / "scene_files.md").read_text()
    doc = json.loads(re.search(r"```json\n(.*?)```", guide, flags=re.S).group(1))
    scene = read(doc, "guide.json")
    pair, against_scene = cli.answer(scene)
    assert 0 < pair.answers["first_contact"]["time"] < 1
    assert [x["name"] for x in against_scene.answers["first_contact"]] == ["fixture"]


def test_write_scene_takes_motions_as_read(tmp_path):
    # The queries as read_scene gives them (a Motion each) are written as their vectors.
    scene = read(SCENE)
    queries = [{k: v for k, v in q.items() if v is not None} for q in scene.queries]
    path = tmp_path / "again.json"
    sf.write_scene(str(path), scene.shapes, queries)
    assert sf.read_scene(str(path)).queries_as_written() == scene.queries_as_written()
    bad = [{"a": "tip", "b": "ring", "motion": cd.Motion(translation=np.zeros((2, 3))), "effects": ["first_contact"]}]
    with pytest.raises(TypeError, match="write_scene: a query holds Motion"):
        sf.write_scene(str(path), scene.shapes, bad)
