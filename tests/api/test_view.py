"""circledist.figure (circledist/view.py): the figure's data for every kind (names on hover,
geometry on the shape), lines clipped to the view's box, closest pairs labelled with their
distances, the reduced detail of large batches, bad arguments, plotly as an optional extra (never
imported by `import circledist`, and an ImportError naming the extra without it), and the command
line's --html page. That the pages draw in a browser is test_view_browser.py's."""

import subprocess
import sys

import numpy as np
import pytest

import circledist as cd
from circledist import cli, view

pytest.importorskip("plotly", reason="plotly is the view extra (pip install 'circledist[view]')")

SHAPES = {
    "point": cd.Point([0.5, 0.2, 0.1]),
    "line": cd.Line([0, 0, 0.3], [1, 0.2, 0]),
    "ray": cd.Ray([0.1, 0.1, 0.1], [0, 1, 0.5]),
    "segment": cd.Segment([0, 0, 0], [1, 1, 1]),
    "circle": cd.Circle([0, 0, 0], [0, 0, 1], 1.0),
    "disk": cd.Disk([1, 0, 0], [1, 1, 0], 0.5),
    "arc": cd.Arc([0, 1, 0], [0, 1, 1], 0.8, [1, 0, 0], 2.0),
    "annulus": cd.Annulus([0, 0, 1], [0, 0, 1], 0.4, 0.9),
    "bezier": cd.Bezier([[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 0, 0]]),
}


def with_sweep(shape, sweep):
    return type(shape)(*(a for k, a in shape.to_arrays().items() if k != "sweep"), sweep=sweep)


def vertices(trace):
    xyz = np.stack([np.asarray(trace.x, float), np.asarray(trace.y, float), np.asarray(trace.z, float)], axis=1)
    return xyz[np.isfinite(xyz).all(axis=1)]


@pytest.mark.parametrize("sweep", [0.0, 0.1])
@pytest.mark.parametrize("kind", sorted(SHAPES))
def test_every_kind_is_drawn_and_named_on_hover(kind, sweep):
    shape = with_sweep(SHAPES[kind], sweep)
    fig = cd.figure({"it": shape, "other": cd.Point([5, 5, 5])})
    mine = [t for t in fig.data if t.name == "it"]
    assert mine, [t.name for t in fig.data]
    for trace in mine:
        assert len(vertices(trace)) > 0
        assert set(trace.text) == {"it"}, trace.type
        assert trace.hovertemplate.startswith("%{text}")
    meshes = [t for t in mine if t.type == "mesh3d"]
    faces = kind in ("disk", "annulus")
    assert len(meshes) == faces + (sweep > 0)
    if sweep:
        tube = meshes[-1]
        assert tube.opacity < 0.5
        # The sweep's surface: its vertices no farther from the shape than the sweep (float32
        # coordinates), most of them at the sweep (the balls at open ends reach inside the tube).
        d = cd.distance(with_sweep(shape, 0.0), vertices(tube))
        assert d.max() <= sweep + 1e-6, d.max()
        assert abs(np.median(d) - sweep) <= 1e-6 + 0.01 * (kind == "bezier") * sweep, np.median(d)


@pytest.mark.parametrize("kind", ["circle", "disk", "arc", "annulus", "bezier", "segment"])
def test_rims_lie_on_the_shape(kind):
    """Every vertex of a curve's or rim's polyline is on the shape (float32 coordinates)."""
    fig = cd.figure({"it": SHAPES[kind]}, detail=48)
    lines = [t for t in fig.data if t.type == "scatter3d"]
    assert len(lines) == 1
    points = vertices(lines[0])
    assert len(points) >= (2 if kind == "segment" else 48)
    assert np.all(cd.distance(SHAPES[kind], points) < 1e-6)


def test_a_batch_is_named_element_by_element():
    rings = cd.Circle([[0, 0, 0], [3, 0, 0], [6, 0, 0]], [0, 0, 1], [1.0, 0.5, 0.25])
    fig = cd.figure({"ring": rings})
    assert [t.name for t in fig.data] == ["ring[0]", "ring[1]", "ring[2]"]
    for i, trace in enumerate(fig.data):
        assert np.allclose(cd.distance(rings[i], vertices(trace)), 0, atol=1e-6)
    assert [t.name for t in cd.figure(rings).data] == ["circle[0]", "circle[1]", "circle[2]"]


@pytest.mark.parametrize("kind", ["line", "ray"])
@pytest.mark.parametrize(
    "origin, direction",
    [
        ([0, 0, 0], [1, 0, 0]),
        ([-1.5, 0, -0.5], [1, 1, 0.5]),
        ([0.9, -0.9, 0.9], [0, 0, -1]),
        ([0, 0, 0], [1e-300, 1, 0]),
    ],
)
def test_lines_are_clipped_to_the_box(kind, origin, direction):
    shape = getattr(cd, kind.capitalize())(origin, direction)
    lo, hi = np.array([-1.0, -1.0, -1.0]), np.array([1.0, 2.0, 1.0])
    (trace,) = cd.figure({"it": shape}, box=(lo, hi)).data
    ends = vertices(trace)
    assert len(ends) == 2
    assert np.all(ends >= lo - 1e-6) and np.all(ends <= hi + 1e-6)
    assert np.allclose(cd.distance(shape, ends), 0, atol=1e-6)
    # The far end is on the box's surface; a line's both ends (a ray's start is its origin).
    on_face = lambda p: np.isclose(p, lo, atol=1e-6).any() or np.isclose(p, hi, atol=1e-6).any()  # noqa: E731
    assert on_face(ends[1])
    if kind == "line" or not np.all((lo <= origin) & (np.array(origin) <= hi)):
        assert on_face(ends[0])
    else:
        assert np.allclose(ends[0], origin, atol=1e-6)


@pytest.mark.parametrize("sweep", [0.0, 0.2])
def test_a_line_that_misses_the_box_is_left_out(sweep):
    far = cd.Line([0, 5, 0], [1, 0, 0], sweep=sweep)
    fig = cd.figure({"far": far, "ring": SHAPES["circle"]}, box=([-1, -1, -1], [1, 1, 1]))
    drawn = [t for t in fig.data if t.name == "far"]
    assert [t.type for t in drawn] == ["scatter3d"] + ["mesh3d"] * (sweep > 0)
    for trace in drawn:
        assert len(vertices(trace)) == 0
        if trace.type == "mesh3d":  # no vertex at all: NaN vertices would reach WebGL
            assert len(trace.x) == 0 and len(trace.i) == 0


def test_the_default_box_holds_the_bounded_shapes_and_clips_the_lines():
    fig = cd.figure({"ring": cd.Circle([10, 0, 0], [0, 0, 1], 2.0, sweep=0.5), "rail": cd.Line([0, 0, 0], [1, 0, 0])})
    scene = fig.layout.scene
    lo = np.array([scene.xaxis.range[0], scene.yaxis.range[0], scene.zaxis.range[0]])
    hi = np.array([scene.xaxis.range[1], scene.yaxis.range[1], scene.zaxis.range[1]])
    assert np.all(lo <= [7.5, -2.5, -0.5]) and np.all(hi >= [12.5, 2.5, 0.5])
    assert np.allclose(hi - lo, (hi - lo)[0])  # a cube: aspectmode cube draws it undistorted
    rail = vertices([t for t in fig.data if t.name == "rail"][0])
    assert np.allclose(rail[:, 0], [lo[0], hi[0]], rtol=1e-6)


def test_pairs_are_drawn_with_their_distances():
    shapes = {"coin": cd.Disk([3, 0, 0], [1, 0, 1], 0.5), "ring": SHAPES["circle"], "probe": cd.Point([0, 0, 2])}
    fig = cd.figure(shapes, pairs=[("coin", "ring"), ("probe", "ring")])
    segments, labels = [t for t in fig.data if t.name == "closest points"]
    points = vertices(segments)
    for i, (a, b) in enumerate([("coin", "ring"), ("probe", "ring")]):
        r = cd.closest_points(shapes[a], shapes[b])
        assert np.allclose(points[2 * i : 2 * i + 2], [r.point_a, r.point_b], atol=1e-6)
        assert segments.text[3 * i] == f"{a} \u2013 {b}: distance {r.distance:.6g}"
        assert labels.text[i] == f"{r.distance:.3g}"


def test_a_scene_file_draws_its_pair_queries():
    scene = cli.load_scene("demo.json", cli.demo_scene_text())
    fig = cd.figure(scene)
    assert fig.layout.title.text == scene.description
    names = {t.name for t in fig.data}
    assert {e.name for e in scene.entries} | {"closest points"} == names
    pairs = list(dict.fromkeys((q["a"], q["b"]) for q in scene.queries if q["b"] is not None))
    (segments,) = [t for t in fig.data if t.name == "closest points" and t.mode != "text"]
    assert len(vertices(segments)) == 2 * len(pairs)
    assert len(cd.figure(scene, pairs=[]).data) == len(fig.data) - 2


def test_a_scene_draws_as_its_shapes_do():
    shapes = {"ring": SHAPES["circle"], "probe": cd.Point([0, 0, 2], sweep=0.1), "coin": SHAPES["disk"]}
    expected = cd.figure(shapes, pairs=[("probe", "ring")])
    got = cd.Scene(shapes).figure(pairs=[("probe", "ring")])
    assert [(t.type, t.name) for t in got.data] == [(t.type, t.name) for t in expected.data]
    for a, b in zip(got.data, expected.data):
        assert np.array_equal(vertices(a), vertices(b))


@pytest.mark.parametrize("count", [view.LEGEND_LIMIT + 1, view.FULL_LIMIT + 1, 20_000, 100_000])
def test_large_batches_are_drawn_at_reduced_detail(count):
    """One trace per kind and role whatever the count; rims of rim_points(count) points, their
    vertices within the budget; above FULL_LIMIT outlines only, and one name marker per shape;
    where the budget leaves too few points for a rim, one marker per shape alone."""
    rng = np.random.default_rng(7)
    disks = cd.Disk(
        rng.uniform(-50, 50, (count, 3)), rng.normal(size=(count, 3)), rng.uniform(0.2, 1, count), sweep=0.1
    )
    fig = cd.figure({"disk": disks, "rail": cd.Line([0, 0, 0], [1, 0, 0])})
    mine = [t for t in fig.data if t.name.startswith("disk")]
    full = count <= view.FULL_LIMIT
    rim = view.rim_points(count)
    assert rim == 0 or view.MIN_RIM <= rim <= view.MAX_RIM
    if full:
        assert [t.type for t in mine] == ["scatter3d", "mesh3d", "mesh3d"]
        assert set(mine[0].text) == {f"disk[{i}]" for i in range(count)}
    elif rim:
        assert [t.type for t in mine] == ["scatter3d", "scatter3d"]
        assert mine[0].hoverinfo == "skip" and "sweeps not drawn" in mine[0].name
    else:
        assert [t.type for t in mine] == ["scatter3d"] and mine[0].mode == "markers"
        assert "a marker each" in mine[0].name
    if rim:
        assert len(mine[0].x) == count * (rim + 2) <= view.VERTEX_BUDGET  # rim + 1 points (closed), a gap
    markers = mine[-1]
    if not full:
        assert markers.mode == "markers" and list(markers.text) == [f"disk[{i}]" for i in range(count)]
        # Each marker on its shape (float32 coordinates).
        assert np.all(cd.distance(disks, np.stack([markers.x, markers.y, markers.z], axis=1).astype(float)) < 1e-4)


def test_the_vertex_budget_rule():
    assert view.rim_points(1) == view.MAX_RIM
    for count in (10, 1_000, 3_000, 10_000, 30_000, 100_000, 10**6):
        rim = view.rim_points(count)
        assert rim == 0 or count * (rim + 2) <= view.VERTEX_BUDGET
        assert (rim == 0) == (view.VERTEX_BUDGET // count - 2 < view.MIN_RIM)


def test_detail_sets_the_points_on_a_rim():
    for detail in (3, 17, 200):
        (trace,) = cd.figure({"ring": SHAPES["circle"]}, detail=detail).data
        assert len(vertices(trace)) == detail + 1


@pytest.mark.parametrize(
    "call, error, message",
    [
        (lambda: cd.figure(42), TypeError, "figure: shapes must be"),
        (lambda: cd.figure({"a": 1}), TypeError, r"shapes\['a'\] must be a circledist shape"),
        (lambda: cd.figure({1: SHAPES["point"]}), TypeError, "names must be strings"),
        (lambda: cd.figure(SHAPES, pairs=[("point", "nothing")]), ValueError, r"pairs\[0\]: no shape named 'nothing'"),
        (lambda: cd.figure(SHAPES, pairs=[("point",)]), TypeError, r"pairs\[0\] must be a pair"),
        (lambda: cd.figure(SHAPES, pairs="ab"), TypeError, "pairs must be a sequence"),
        (lambda: cd.figure(SHAPES, detail=2), ValueError, "detail must be an integer >= 3"),
        (lambda: cd.figure(SHAPES, detail=8.0), ValueError, "detail must be an integer >= 3"),
        (lambda: cd.figure(SHAPES, box=([0, 0], [1, 1])), ValueError, "box must be two 3-vectors"),
        (lambda: cd.figure(SHAPES, box=([1, 0, 0], [0, 1, 1])), ValueError, "lower corner below"),
    ],
)
def test_bad_arguments_are_named(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_import_circledist_does_not_import_plotly():
    code = "import sys, circledist; assert 'plotly' not in sys.modules, 'plotly imported'"
    subprocess.run([sys.executable, "-c", code], check=True)


@pytest.fixture
def no_plotly(monkeypatch):
    """plotly as if it were not installed: its import raises ImportError."""
    for name in list(sys.modules):
        if name == "plotly" or name.startswith("plotly."):
            monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "plotly", None)


def test_without_plotly_figure_says_what_to_install(no_plotly):
    with pytest.raises(ImportError, match=r"pip install 'circledist\[view\]'"):
        cd.figure(SHAPES["circle"])
    with pytest.raises(ImportError, match=r"circledist\[view\]"):
        cd.Scene({"ring": SHAPES["circle"]}).figure()


def test_cli_writes_one_self_contained_page(tmp_path, capsys):
    out = tmp_path / "demo.html"
    assert cli.main(["--no-plot", "--html", str(out)]) == 0
    assert f"interactive view written to {out}" in capsys.readouterr().out
    page = out.read_text()
    assert "<script src=" not in page.replace('<script src="data:', "")  # plotly.js is inline
    assert "Plotly.newPlot" in page and len(page) > 1_000_000
    for name in ("ring", "coin", "cable", "rail", "probe", "plate", "sensor", "closest points"):
        assert f'"name":"{name}"' in page, name


def test_cli_html_without_plotly_says_what_to_install(tmp_path, capsys, no_plotly):
    out = tmp_path / "demo.html"
    assert cli.main(["--no-plot", "--html", str(out)]) == 1
    assert "circledist[view]" in capsys.readouterr().err
    assert not out.exists()


def test_cli_html_refuses_an_unwritable_path_before_any_work(tmp_path, capsys):
    assert cli.main(["--no-plot", "--html", str(tmp_path / "no" / "such" / "dir.html")]) == 2
    assert "cannot write the output" in capsys.readouterr().err


@pytest.mark.parametrize("size", [1e-300, 1e-9, 1.0, 1e12, 1e300])
def test_far_from_unit_lengths_are_drawn_in_powers_of_ten(size):
    """Coordinates go to the browser as float32, which holds neither 1e300 nor 1e-300: a scene far
    from unit lengths is drawn in units of a power of ten (the axes say which), its shapes where
    they are in those units, the distances' labels as they are."""
    ring = cd.Circle([size, 0, 0], [0, 0, 1], size / 2, sweep=size / 20)
    probe = cd.Point([size, 0, size])
    fig = cd.figure({"ring": ring, "probe": probe}, pairs=[("probe", "ring")])
    scale = 1.0 if size == 1.0 else 10.0 ** np.floor(np.log10(size))
    title = fig.layout.scene.xaxis.title.text
    assert title == ("x" if scale == 1 else f"x (\u00d7 {scale:.0e})")
    for trace in fig.data:
        xyz = np.stack([np.asarray(trace.x, float), np.asarray(trace.y, float), np.asarray(trace.z, float)], axis=1)
        assert np.all(np.isfinite(xyz) | np.isnan(xyz)) and np.isfinite(xyz).any(), trace.name
    (rim,) = [t for t in fig.data if t.name == "ring" and t.type == "scatter3d"]
    unit_ring = cd.Circle([size / scale, 0, 0], [0, 0, 1], size / scale / 2)
    assert np.all(cd.distance(unit_ring, vertices(rim)) < 1e-6 * size / scale)
    segments = [t for t in fig.data if t.name == "closest points" and t.mode != "text"][0]
    assert segments.text[0] == f"probe \u2013 ring: distance {cd.distance(probe, ring):.6g}"


@pytest.mark.parametrize("offset", [1e4, 1e6, 1e9])
def test_far_translated_scenes_keep_their_digits(offset):
    """A unit ring far from the origin: float32 steps at 1e6 are 0.06, so the coordinates are
    drawn from an origin near the scene (the axes say which), and the rims stay on the ring."""
    center = np.array([offset, -2 * offset, 3 * offset])
    ring = cd.Circle(center, [0, 1, 1], 1.0)
    fig = cd.figure({"ring": ring, "probe": cd.Point(center + [0, 0, 2])}, detail=32)
    scene = fig.layout.scene
    titles = [scene.xaxis.title.text, scene.yaxis.title.text, scene.zaxis.title.text]
    assert all("\u2212" in t for t in titles), titles
    scale = 1.0 if 3 * offset <= 1e6 else 10.0 ** np.floor(np.log10(3 * offset))
    origin = np.array([float(t.split("\u2212 ")[1].split(" ")[0]) for t in titles])
    (rim,) = [t for t in fig.data if t.name == "ring"]
    drawn = (vertices(rim) + origin) * scale
    assert np.all(cd.distance(ring, drawn) < 1e-5 * max(1.0, offset * 1e-7)), cd.distance(ring, drawn).max()
