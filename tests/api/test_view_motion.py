"""circledist.figure with motions (circledist/_view_motion.py): one frame per time step over
[0, 1] and one at each pair's first contact, the moving shapes drawn where the motion puts them
(checked against the motion's formula, x(t) = c + R(t w)(x - c) + t T with R from Rodrigues'
formula, worked out here, not by Shape.moved), the shapes at rest drawn once, the pairs' closest
points at every time, the view's box around every time, and bad arguments. That the page
animates in a browser is test_view_browser.py's."""

import math
import pathlib
import runpy

import numpy as np
import pytest

import circledist as cd
from circledist import cli, view

pytest.importorskip("plotly", reason="plotly is the view extra (pip install 'circledist[view]')")

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "motion_demo.py"


def vertices(trace):
    xyz = np.stack([np.asarray(trace.x, float), np.asarray(trace.y, float), np.asarray(trace.z, float)], axis=1)
    return xyz[np.isfinite(xyz).all(axis=1)]


def rotation(w):
    """Rodrigues: the rotation by |w| radians about w / |w|."""
    w = np.asarray(w, float)
    theta = np.linalg.norm(w)
    if theta == 0:
        return np.eye(3)
    k = w / theta
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(theta) * K + (1 - np.cos(theta)) * K @ K


def move(x, t, translation=(0, 0, 0), rotation_vector=(0, 0, 0), center=(0, 0, 0)):
    """A point at time t of the motion."""
    c = np.asarray(center, float)
    return (
        c
        + rotation(t * np.asarray(rotation_vector, float)) @ (np.asarray(x, float) - c)
        + t * np.asarray(translation, float)
    )


def turn(v, t, rotation_vector):
    """A direction at time t of the motion."""
    return rotation(t * np.asarray(rotation_vector, float)) @ np.asarray(v, float)


def frame_times(fig):
    return np.array([float(f.name) for f in fig.frames])


def traces_named(fig, frame, name):
    """The traces of a shape in a frame (frame None: the figure's own data, at t = 0)."""
    data = fig.data if frame is None else frame.data
    return [t for t in data if t.name == name]


def unit_and_origin(fig):
    """The scale and origin the axes' titles state (1 and 0 for plain scenes)."""
    titles = [fig.layout.scene[f"{a}axis"].title.text for a in "xyz"]
    scale = float(titles[0].split("\u00d7 ")[1].rstrip(")")) if "\u00d7" in titles[0] else 1.0
    origin = np.array([float(t.split("\u2212 ")[1].split(" ")[0]) if "\u2212" in t else 0.0 for t in titles])
    return scale, origin


@pytest.mark.parametrize("frames", [None, 2, 7, 100])
def test_one_frame_per_time_step_over_the_unit_interval(frames):
    shapes = {"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0), "probe": cd.Point([0, 0, 3])}
    fig = cd.figure(shapes, motions={"probe": cd.Motion(translation=[0, 1, 0])}, frames=frames)
    count = view.FRAMES if frames is None else frames
    assert np.array_equal(frame_times(fig), np.linspace(0, 1, count))
    (slider,) = fig.layout.sliders
    assert len(slider.steps) == count
    assert [list(s.args[0]) for s in slider.steps] == [[f.name] for f in fig.frames]
    assert [float(s.label) for s in slider.steps] == pytest.approx(np.linspace(0, 1, count), abs=1e-3)
    assert slider.currentvalue.prefix == "t = "
    (menu,) = fig.layout.updatemenus
    assert [b.method for b in menu.buttons] == ["animate", "animate"]
    assert menu.buttons[0].args[0] is None  # play: every frame from the current one
    assert list(menu.buttons[1].args[0]) == [None]  # pause


CASES = {
    # a ring turning about a tilted axis through a point off its center while it moves
    "circle": (
        cd.Circle([1.0, 0.5, -0.2], [0.3, 0.1, 1.0], 0.8),
        {"translation": [2.0, -1.0, 0.5], "rotation": [0.4, -1.0, 2.5], "center": [0.5, 0.0, 0.0]},
    ),
    "disk with a sweep": (
        cd.Disk([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 0.5, sweep=0.1),
        {"translation": [0.0, 3.0, 0.0], "rotation": [0.0, 0.0, 2 * np.pi], "center": [0.0, 0.0, 0.0]},
    ),
}


@pytest.mark.parametrize("size", [1e-9, 1.0, 1e12])
@pytest.mark.parametrize("case", sorted(CASES))
def test_the_moving_rim_is_where_the_motion_puts_it(case, size):
    """In every frame the moving shape's rim lies on the circle the motion carries it to: at its
    radius from the moved center, in the plane of the rotated normal (float32 coordinates); a
    sweep's surface at the sweep's distance from the moved shape."""
    shape, motion = CASES[case]
    shape = type(shape)(
        *(np.asarray(a) * (size if k != "normal" else 1.0) for k, a in shape.to_arrays().items() if k != "sweep"),
        sweep=float(shape.to_arrays().get("sweep", 0.0)) * size,
    )
    motion = {k: np.asarray(v) * (size if k != "rotation" else 1.0) for k, v in motion.items()}
    arrays = shape.to_arrays()
    fig = cd.figure({"it": shape, "still": cd.Point([0, 0, 4 * size])}, motions={"it": cd.Motion(**motion)}, frames=9)
    scale, origin = unit_and_origin(fig)
    for frame, t in zip(fig.frames, frame_times(fig)):
        center = move(arrays["center"], t, motion["translation"], motion["rotation"], motion["center"])
        normal = turn(arrays["normal"], t, motion["rotation"])
        normal /= np.linalg.norm(normal)
        mine = traces_named(fig, frame, "it")
        (rim,) = [tr for tr in mine if tr.type == "scatter3d"]
        points = vertices(rim) * scale + origin
        radius = float(arrays["radius"])
        assert len(points) >= view.MIN_RIM
        off = points - center
        assert np.allclose(np.linalg.norm(off, axis=1), radius, rtol=0, atol=1e-6 * size), t
        assert np.allclose(off @ normal, 0.0, rtol=0, atol=1e-6 * size), t
        assert set(rim.text) == {"it"}
        sweep = float(arrays.get("sweep", 0.0))
        if sweep:
            moved = cd.Disk(center, normal, radius)
            tube = vertices([tr for tr in mine if tr.type == "mesh3d" and tr.opacity < 0.4][0]) * scale + origin
            assert cd.distance(moved, tube).max() <= sweep + 1e-6 * size
            assert abs(np.median(cd.distance(moved, tube)) - sweep) <= 1e-6 * size


def test_a_batch_moves_by_its_batch_of_motions():
    """Segments each with its own motion (a batch broadcasting to the batch), and one shape of a
    batch moved by name: the end points at each time are the motion's."""
    p0 = np.array([[0.0, 0, 0], [2, 0, 0], [4, 0, 0]])
    p1 = p0 + [0, 0, 1]
    rods = cd.Segment(p0, p1)
    translation = np.array([[0.0, 1, 0], [0, 2, 0], [0, 3, 0]])
    rotation_vector = np.array([[0.0, 0, 0], [1.0, 0, 0], [0, 2.0, 0]])
    beads = cd.Point([[0.0, -2, 0], [1, -2, 0]])
    motions = {"rods": cd.Motion(translation=translation, rotation=rotation_vector, center=p0)}
    motions["beads[1]"] = cd.Motion(translation=[0, 0, -1])
    fig = cd.figure({"rods": rods, "beads": beads}, motions=motions, frames=5)
    for frame, t in zip(fig.frames, frame_times(fig)):
        for i in range(3):
            (trace,) = traces_named(fig, frame, f"rods[{i}]")
            ends = vertices(trace)
            expected = [move(p, t, translation[i], rotation_vector[i], p0[i]) for p in (p0[i], p1[i])]
            assert np.allclose(ends, expected, atol=1e-6), (t, i)
        (bead,) = traces_named(fig, frame, "beads[1]")
        assert np.allclose(vertices(bead), [[1, -2, -t]], atol=1e-6)
        assert traces_named(fig, frame, "beads[0]") == []  # at rest: drawn once, in no frame
    assert np.allclose(vertices(traces_named(fig, None, "beads[0]")[0]), [[0, -2, 0]])


def test_only_the_moving_traces_change_between_frames():
    shapes = {
        "plate": cd.Disk([0, 0, -1], [0, 0, 1], 2.0, sweep=0.05),
        "rail": cd.Line([0, 3, 0], [1, 0, 0]),
        "tool": cd.Circle([-2, 0, 0], [1, 0, 0], 0.3, sweep=0.05),
        "probe": cd.Point([1, 1, 1]),
    }
    fig = cd.figure(
        shapes,
        motions={"tool": cd.Motion(translation=[4, 0, 0])},
        pairs=[("plate", "probe"), ("tool", "probe")],
        frames=6,
    )
    changing = list(fig.frames[0].traces)
    assert all(list(f.traces) == changing for f in fig.frames)
    assert all(len(f.data) == len(changing) for f in fig.frames)
    names = [fig.data[i].name for i in changing]
    pair = [n for n in names if n.startswith("tool \u2013 probe")]
    assert set(names) == {"tool", pair[0]} and len(names) == 2 + 2  # rim, torus; segment, label
    for i, trace in enumerate(fig.data):  # the shapes at rest and the still pair: in no frame
        if i not in changing:
            assert not trace.name.startswith("tool"), trace.name
    # The figure's own data is the first frame's (t = 0).
    for i, trace in zip(changing, fig.frames[0].data):
        assert np.array_equal(vertices(fig.data[i]), vertices(trace))
    # Each frame's moving traces differ from the last (the tool moves).
    rims = [vertices(f.data[names.index("tool")]) for f in fig.frames]
    assert all(not np.allclose(a, b) for a, b in zip(rims, rims[1:]))


@pytest.mark.parametrize("speed", [2.5, 2.2, 2.9])  # t = 0.8 (a time step), 0.909..., 0.689...
def test_the_first_contact_is_a_frame_of_its_own(speed):
    """A point moving at speed s < 3 along the x axis towards a unit ring from 3 away touches it
    at t = 2 / s (worked out by hand): a frame at that time, its slider step saying so, and at
    every time the segment from the point to (1, 0, 0), labelled |2 - s t| (0 at the contact)."""
    shapes = {"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0), "probe": cd.Point([3, 0, 0]), "far": cd.Point([0, 5, 0])}
    motions = {"probe": cd.Motion(translation=[-speed, 0, 0])}
    fig = cd.figure(shapes, motions=motions, pairs=[("probe", "ring"), ("far", "probe")], frames=11)
    contact = 2 / speed
    times = frame_times(fig)
    grid = np.linspace(0, 1, 11)
    near = np.isclose(grid, contact, rtol=0, atol=1e-9)  # a step this near is the contact's frame
    assert set(grid[~near]) <= set(times) and len(times) == 11 + (not near.any())
    k = int(np.argmin(abs(times - contact)))
    assert abs(times[k] - contact) <= 1e-12
    labels = [s.label for s in fig.layout.sliders[0].steps]
    assert [i for i, label in enumerate(labels) if label.endswith("contact")] == [k]
    legend = f"probe \u2013 ring: first contact at t = {contact:.4g}"
    assert legend in {t.name for t in fig.data}
    assert "far \u2013 probe: no contact for t in [0, 1]" in {t.name for t in fig.data}
    (marker,) = [t for t in fig.data if t.name == legend and t.mode == "markers"]
    assert np.allclose(vertices(marker), [[1, 0, 0]], atol=1e-6)
    for frame, t in zip(fig.frames, times):
        segment, label = [tr for tr in frame.data if tr.name == legend]
        assert np.allclose(vertices(segment), [[3 - speed * t, 0, 0], [1, 0, 0]], atol=1e-6)
        expected = "contact" if t == times[k] else f"{abs(2 - speed * t):.3g}"
        assert list(label.text) == [expected], t
        far_segment, _ = [tr for tr in frame.data if tr.name.startswith("far")]
        assert np.allclose(vertices(far_segment), [[0, 5, 0], [3 - speed * t, 0, 0]], atol=1e-6)


def test_the_view_holds_the_shapes_at_every_time():
    tool = cd.Circle([0, 0, 0], [0, 0, 1], 0.5, sweep=0.1)
    fig = cd.figure(
        {"tool": tool, "still": cd.Point([0, 0, 0])},
        motions={"tool": cd.Motion(translation=[10, 0, 0], rotation=[0, 3, 0], center=[0, 0, 0])},
    )
    scene = fig.layout.scene
    lo = np.array([scene.xaxis.range[0], scene.yaxis.range[0], scene.zaxis.range[0]])
    hi = np.array([scene.xaxis.range[1], scene.yaxis.range[1], scene.zaxis.range[1]])
    for frame in fig.frames:
        for trace in frame.data:
            xyz = vertices(trace)
            assert np.all(xyz >= lo) and np.all(xyz <= hi), frame.name
    assert hi[0] - lo[0] >= 10 + 2 * 0.6


def test_a_scene_file_entry_and_a_scene_move_by_name():
    demo = cli.load_scene("demo.json", cli.demo_scene_text())
    lift = cd.Motion(translation=[0, 0, 1])
    fig = cd.figure(demo, motions={"coin": lift}, frames=3)
    (rim,) = [t for t in fig.frames[-1].data if t.name == "coin" and t.type == "scatter3d"]
    assert np.allclose(cd.distance(demo.shape("coin").moved(lift, 1.0), vertices(rim)), 0, atol=1e-6)
    assert any(t.name.startswith("coin \u2013 ring: ") for t in fig.data)  # the file's query, moving
    shapes = {"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0), "probe": cd.Point([0, 0, 2])}
    expected = cd.figure(shapes, motions={"probe": lift}, pairs=[("probe", "ring")], frames=4)
    got = cd.Scene(shapes).figure(motions={"probe": lift}, pairs=[("probe", "ring")], frames=4)
    assert [f.name for f in got.frames] == [f.name for f in expected.frames]
    for a, b in zip(got.frames, expected.frames):
        assert [t.name for t in a.data] == [t.name for t in b.data]
        assert all(np.array_equal(vertices(x), vertices(y)) for x, y in zip(a.data, b.data))


def test_a_large_moving_batch_is_one_trace_group_counted_once_per_frame():
    count = view.LEGEND_LIMIT + 10
    rng = np.random.default_rng(3)
    rings = cd.Circle(rng.uniform(-5, 5, (count, 3)), rng.normal(size=(count, 3)), 0.3)
    fig = cd.figure(
        {"rings": rings, "rail": cd.Line([0, 0, 0], [1, 0, 0])}, motions={"rings": cd.Motion(rotation=[0, 0, 1])}
    )
    changing = list(fig.frames[0].traces)
    # Outlines, and the markers that carry the names (above FULL_LIMIT drawn shapes).
    assert [fig.data[i].name for i in changing] == [f"circle \u00d7 {count} (moving)"] * 2
    steps = len(fig.frames)
    rim = view.rim_points(1 + count * steps)
    assert len(fig.frames[0].data[0].x) == count * (rim + 2)  # the moving rims share the budget over the frames
    assert 1 + count * steps > view.FULL_LIMIT and fig.frames[0].data[0].hoverinfo == "skip"


def test_without_motions_the_figure_is_still():
    shapes = {"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0)}
    for motions in (None, {}):
        fig = cd.figure(shapes, motions=motions, frames=5)
        assert not fig.frames and not fig.layout.sliders
    fig = cd.figure(shapes, motions={"ring": cd.Motion()}, frames=3)  # at rest: still three frames
    assert len(fig.frames) == 3 and math.isclose(float(fig.frames[-1].name), 1.0)


RING = {
    "ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0),
    "beads": cd.Point([[0, 0, 1], [0, 0, 2]]),
    "rail": cd.Line([0, 2, 0], [1, 0, 0]),
}
STILL = cd.Motion()


@pytest.mark.parametrize(
    "arguments, error, message",
    [
        ({"motions": [("ring", STILL)]}, TypeError, "figure: motions must be a mapping of shape names to Motions"),
        ({"motions": {1: STILL}}, TypeError, "figure: motions: names must be strings"),
        ({"motions": {"disk": STILL}}, ValueError, "figure: motions: no shape named 'disk'"),
        ({"motions": {"ring": (1, 0, 0)}}, TypeError, r"figure: motions\['ring'\] must be a circledist Motion"),
        (
            {"motions": {"beads": cd.Motion(translation=np.zeros((3, 3)))}},
            ValueError,
            r"motions\['beads'\]: a batch of motions of shape \(3,\) does not broadcast",
        ),
        (
            {"motions": {"beads[0]": cd.Motion(translation=np.zeros((2, 3)))}},
            ValueError,
            r"motions\['beads\[0\]'\] moves one shape: it takes a single Motion",
        ),
        ({"motions": {"beads": STILL, "beads[1]": STILL}}, ValueError, "'beads\\[1\\]' is given two motions"),
        ({"motions": {"ring": STILL}, "frames": 1}, ValueError, "figure: frames must be at least 2"),
        ({"motions": {"ring": STILL}, "frames": 2.0}, TypeError, "figure: frames must be an integer"),
        ({"motions": {"ring": STILL}, "frames": True}, TypeError, "figure: frames must be an integer"),
        ({"frames": "10"}, TypeError, "figure: frames must be an integer"),
        (
            {"motions": {"rail": cd.Motion(rotation=[0, 0, 1])}, "pairs": [("rail", "ring")]},
            ValueError,
            r"figure: pairs\[0\] \('rail', 'ring'\): first_contact: .* cannot rotate",
        ),
    ],
)
def test_bad_motions_and_frames_are_named(arguments, error, message):
    with pytest.raises(error, match=message):
        cd.figure(RING, **arguments)


def test_the_motion_example_writes_its_page(tmp_path):
    """examples/motion_demo.py: a page with the frames, opening at t = 0 (no autoplay), the tool
    touching the sensor at the contact's frame and never the probe."""
    example = runpy.run_path(str(EXAMPLE))
    page = tmp_path / "motion.html"
    fig = example["main"](str(page))
    text = page.read_text()
    assert "Plotly.newPlot" in text and "addFrames" in text and "Plotly.animate(" not in text
    contact = cd.first_contact(example["tool"], example["shapes"]["sensor"], example["slide_and_turn"])
    assert 0 < contact.time < 1
    names = {t.name for t in fig.data}
    assert f"tool \u2013 sensor: first contact at t = {contact.time:.4g}" in names
    assert "tool \u2013 probe: no contact for t in [0, 1]" in names
    assert contact.time in frame_times(fig)


def test_a_scene_files_queries_move_their_shapes_by_default(tmp_path, capsys):
    """The packaged motion example: its queries' motions animate the figure and the CLI's page.
    The tool (a circle of radius 0.4 swept by 0.1 at z = 0.6, sliding 5 along x from x = -2.5)
    first touches the upright fixture (a segment crossing its plane at (0, -0.2), swept by 0.15)
    when the crossing is 0.4 + 0.1 + 0.15 from the tool's center: x^2 + 0.2^2 = 0.65^2."""
    path = pathlib.Path(cd.__file__).parent / "scenes" / "motion.json"
    fig = cd.figure(cd.read_scene(path))
    touch = (math.sqrt(0.65**2 - 0.2**2) * -1 + 2.5) / 5
    contacts = [float(s.args[0][0]) for s in fig.layout.sliders[0].steps if s.label.endswith("contact")]
    assert any(abs(t - touch) < 1e-9 for t in contacts), (contacts, touch)
    assert len(fig.frames) >= view.FRAMES
    assert len(cd.figure(cd.read_scene(path), motions={}).frames) == 0  # motions={} draws it still
    out = tmp_path / "motion.html"
    assert cli.main([str(path), "--no-plot", "--html", str(out)]) == 0
    page = out.read_text()
    assert '"frames"' in page or "addFrames" in page
    assert "Plotly.animate" not in page  # opens at t = 0: no autoplay
