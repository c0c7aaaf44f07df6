"""Scene.first_contact: the k earliest contacts of a moving shape with a scene's shapes are the
ones brute force (circledist.first_contact against every scene shape) gives, on random scenes of
every kind (swept shapes and lines included) under translations and rotations; the culling passes
only the shapes near the motion to circledist.first_contact; the errors name their argument."""

import numpy as np
import pytest

from circledist_cases.shapes import random_fields

cd = pytest.importorskip("circledist")
motion_module = pytest.importorskip("circledist._scene_motion")

KINDS = ("Point", "Segment", "Circle", "Disk", "Arc", "Annulus", "Bezier", "Line", "Ray")


def random_shape(kind, rng, offset, spread=8.0, sweep=True):
    """A random single shape of a kind near offset (fields from the cases' generator, moved)."""
    fields = random_fields(cd, kind, rng, sweep=sweep)
    place = offset + rng.uniform(-spread, spread, 3)
    for name, role in cd._core._shape_fields()[kind]:
        if role == "vector":
            fields[name] = fields[name] + place
        elif role == "control_points":
            fields[name] = fields[name] + place
    return getattr(cd, kind).from_arrays(fields)


def random_scene(seed, n, offset, kinds=KINDS, spread=8.0):
    rng = np.random.default_rng(seed)
    scene = cd.Scene()
    shapes = []
    for i in range(n):
        kind = kinds[i % len(kinds)]
        s = random_shape(kind, rng, offset, spread, sweep=rng.uniform() < 0.5)
        scene.add(f"{kind.lower()}{i}", s)
        shapes.append(s)
    return scene, shapes


def brute_force(scene, shapes, shape, motion, within, k, skip=()):
    """(name, time) of the k earliest contacts, by time then insertion order, and the contacts."""
    found = []
    for i, (name, s) in enumerate(zip(scene.names, shapes)):
        if name in skip:
            continue
        c = cd.first_contact(shape, s, motion, within=within)
        if np.isfinite(c.time):
            found.append((float(c.time), i, name, c))
    found.sort(key=lambda x: (x[0], x[1]))
    return found[:k]


def motions(rng, kind, offset):
    """A translation across the scene, a short one, a screw (rotation and translation) and a
    turn in place about a point near the scene (lines and rays: translations only)."""
    out = {
        "across": cd.Motion(translation=rng.uniform(-12, 12, 3)),
        "short": cd.Motion(translation=rng.uniform(-1, 1, 3)),
    }
    if kind not in ("Line", "Ray"):
        out["screw"] = cd.Motion(
            translation=rng.uniform(-8, 8, 3), rotation=rng.normal(size=3) * 2, center=offset + rng.normal(size=3)
        )
        out["turn"] = cd.Motion(rotation=rng.normal(size=3) * 3, center=offset + rng.normal(size=3) * 2)
    return out


def check_same_as_brute_force(scene, shapes, shape, motion, within, k, skip=()):
    got = scene.first_contact(shape, motion, within=within, k=k)
    want = brute_force(scene, shapes, shape if not isinstance(shape, str) else scene[shape], motion, within, k, skip)
    assert [h.name for h in got] == [w[2] for w in want]
    for h, (_, _, _, c) in zip(got, want):
        # The same computation as the one-by-one call: the same bits.
        assert h.time == c.time and h.distance == c.distance and h.unique == c.unique
        for field in ("point_a", "point_b", "param_a", "param_b"):
            np.testing.assert_array_equal(getattr(h, field), getattr(c, field))
    return got


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("offset", [0.0, 1e6])
def test_first_contact_equals_brute_force(kind, offset):
    offset = np.array([offset, -offset, 0.5 * offset])
    seed = KINDS.index(kind) + (7 if offset.any() else 0)
    scene, shapes = random_scene(seed, 120, offset)
    rng = np.random.default_rng(100 + seed)
    reached = 0
    for label, motion in motions(rng, kind, offset).items():
        shape = random_shape(kind, rng, offset, spread=6.0, sweep=label != "short")
        for within, k in ((0.0, 1), (0.4, 3), (0.1, 100)):
            got = check_same_as_brute_force(scene, shapes, shape, motion, within, k)
            reached += len(got)
    assert reached > 0  # the random motions do reach shapes


def test_a_scene_shape_named_as_the_moving_shape_is_left_out():
    scene, shapes = random_scene(3, 40, np.zeros(3))
    motion = cd.Motion(translation=[5, -3, 2], rotation=[0.5, 0, 1], center=[0, 0, 0])
    for name in scene.names[:5]:
        got = check_same_as_brute_force(scene, shapes, name, motion, 0.2, 50, skip=(name,))
        assert name not in [h.name for h in got]


def test_the_culling_passes_only_shapes_near_the_motion(monkeypatch):
    # A cluster on the path and far shapes around it: only cluster shapes reach first_contact.
    rng = np.random.default_rng(5)
    scene, near = random_scene(11, 30, np.zeros(3), spread=3.0)
    for i in range(300):
        kind = KINDS[i % 7]  # bounded kinds
        direction = rng.normal(size=3)
        s = random_shape(kind, rng, 60 * direction / np.linalg.norm(direction), spread=5.0)
        scene.add(f"far{i}", s)
    real = cd._core.first_contact

    calls = []

    def recording(a, b, *args, **kwargs):
        calls.append(b)
        return real(a, b, *args, **kwargs)

    monkeypatch.setattr(motion_module._core, "first_contact", recording)
    shape = cd.Circle([-4, 0, 0], [0, 0, 1], 1.0, sweep=0.1)
    cases = [
        cd.Motion(translation=[8, 0, 0]),
        cd.Motion(translation=[8, 1, 0], rotation=[0, 2, 1], center=[-4, 0, 0]),
        cd.Motion(rotation=[0, 0, 7], center=[-2, 0, 0]),
    ]
    for motion in cases:
        calls.clear()
        cd.reset_stats()
        got = scene.first_contact(shape, motion, within=0.5, k=10)
        assert cd.stats()["culled"] == scene.last_stats["culled"] > 250
        evaluated = sum(int(np.prod(b.batch_shape)) for b in calls)
        assert evaluated == scene.last_stats["tested"]
        assert scene.last_stats["culled"] == len(scene) - evaluated
        assert evaluated <= len(near)  # no far shape is ever passed
        # Every passed shape is a cluster shape: the far ones are all beyond 40 of the origin.
        for b in calls:
            assert (np.asarray(cd.distance(b, cd.Point([0, 0, 0]))) < 30).all()
        assert got, "the cluster lies on the path"


def test_more_than_the_hits_and_no_contact():
    scene, shapes = random_scene(8, 40, np.zeros(3))
    motion = cd.Motion(translation=[14, 0, 0])
    shape = cd.Point([-7, 0, 0], sweep=0.5)
    want = brute_force(scene, shapes, shape, motion, 0.0, 10**6)
    got = scene.first_contact(shape, motion, k=10**6)
    assert 0 < len(got) == len(want) < len(scene)
    # Away from everything, and at rest away from everything: no contact.
    away = cd.Point([500, 500, 500])
    assert scene.first_contact(away, cd.Motion(translation=[10, 0, 0]), k=5) == []
    assert scene.first_contact(away, None, within=1.0) == []
    assert scene.last_stats["tested"] == 0
    assert cd.Scene().first_contact(shape, motion) == []


def test_at_rest_is_within_at_time_zero():
    scene, shapes = random_scene(9, 40, np.zeros(3))
    shape = cd.Disk([0, 0, 0], [0, 1, 1], 2.0)
    got = check_same_as_brute_force(scene, shapes, shape, None, 0.5, 100)
    assert all(h.time == 0.0 for h in got)
    assert [h.name for h in got] == [n for n in scene.within(shape, 0.5)]


@pytest.mark.parametrize("kind", ["Line", "Ray"])
def test_a_rotating_line_is_refused_as_by_first_contact(kind):
    scene = cd.Scene({"p": cd.Point([0, 0, 1])})
    shape = getattr(cd, kind)([0, 0, 0], [1, 0, 0])
    spin = cd.Motion(rotation=[0, 0, 1])
    with pytest.raises(ValueError, match="cannot rotate") as library:
        cd.first_contact(shape, cd.Point([0, 0, 1]), spin)
    with pytest.raises(ValueError, match="cannot rotate") as ours:
        scene.first_contact(shape, spin)
    assert str(ours.value).split(": ", 1)[0] == "Scene.first_contact"
    assert str(library.value).split("(")[0].split(": a ")[-1] in str(ours.value)
    # A translating line is fine.
    assert scene.first_contact(shape, cd.Motion(translation=[0, 0, 2]))[0].name == "p"


@pytest.mark.parametrize(
    "kwargs, error, words",
    [
        ({"within": -1.0}, ValueError, "within"),
        ({"within": float("nan")}, ValueError, "within"),
        ({"within": float("inf")}, ValueError, "within"),
        ({"within": "near"}, TypeError, "within"),
        ({"k": 0}, ValueError, "k must"),
        ({"k": 1.5}, TypeError, "k must"),
        ({"k": True}, TypeError, "k must"),
        ({"motion": "fast"}, TypeError, "motion"),
        ({"motion": cd.Motion(translation=np.zeros((2, 3)))}, ValueError, "motion"),
        ({"shape": cd.Point(np.zeros((2, 3)))}, ValueError, "batch"),
    ],
)
def test_bad_arguments_name_the_argument(kwargs, error, words):
    scene = cd.Scene({"p": cd.Point([0, 0, 1])})
    args = {"shape": cd.Point([0, 0, 0]), "motion": cd.Motion(translation=[0, 0, 1])}
    args.update(kwargs)
    with pytest.raises(error, match=words):
        scene.first_contact(**args)
    with pytest.raises(KeyError):
        scene.first_contact("nothing", None)


def test_the_docstring_example_runs_and_lists_the_signature():
    # Scene.first_contact lives on a base class, which the package's docstring tests (vars(Scene))
    # do not reach: its example and its Parameters section are checked here.
    import doctest
    import inspect
    import re

    method = cd.Scene.first_contact
    tests = doctest.DocTestFinder().find(method, "Scene.first_contact", globs={})
    assert tests and tests[0].examples
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for test in tests:
        runner.run(test)
    assert runner.failures == 0
    text = inspect.cleandoc(method.__doc__)
    section = re.search(r"^Parameters\n-+\n(.*?)\n\n\w[\w ]*\n-+\n", text, flags=re.S | re.M).group(1)
    listed = [m.group(1) for m in re.finditer(r"^(\w+) :", section, flags=re.M)]
    assert listed == [p for p in inspect.signature(method).parameters if p != "self"]
    for title in ("Returns", "Raises", "Examples"):
        assert re.search(rf"^{title}\n-+$", text, flags=re.M)


@pytest.mark.parametrize("dtype", [np.float32, np.longdouble])
def test_shapes_of_other_dtypes_are_measured_as_added(dtype):
    # Half the scene's shapes in another dtype (groups of their own): the answers are still brute
    # force's, each pair measured as circledist.first_contact measures it.
    rng = np.random.default_rng(21)
    scene, shapes = cd.Scene(), []
    for i in range(60):
        kind = KINDS[i % len(KINDS)]
        s = random_shape(kind, rng, np.zeros(3), sweep=i % 3 == 0)
        if i % 2:
            s = type(s).from_arrays({k: np.asarray(v).astype(dtype) for k, v in s.to_arrays().items()})
        scene.add(f"s{i}", s)
        shapes.append(scene[f"s{i}"])
    reached = 0
    for motion in motions(rng, "Disk", np.zeros(3)).values():
        shape = random_shape("Segment", rng, np.zeros(3), spread=5.0)
        reached += len(check_same_as_brute_force(scene, shapes, shape, motion, 0.2, 100))
    assert reached > 0


def test_a_shape_on_a_turning_wheel_equals_brute_force():
    # A small shape far from the axis it turns about (the torus about its orbit bounds the
    # motion), with and without a translation along the way, through a dense scene.
    rng = np.random.default_rng(31)
    scene, shapes = random_scene(41, 150, np.zeros(3), spread=9.0)
    reached = 0
    for trial in range(12):
        axis = rng.normal(size=3)
        shape = random_shape(KINDS[trial % 7], rng, np.zeros(3), spread=0.0, sweep=trial % 2 == 0)
        center = rng.normal(size=3) * 7
        travel = rng.normal(size=3) * (0 if trial < 4 else 3)
        motion = cd.Motion(
            translation=travel, rotation=axis * rng.uniform(0.5, 7) / np.linalg.norm(axis), center=center
        )
        reached += len(check_same_as_brute_force(scene, shapes, shape, motion, 0.3, 200))
    assert reached > 20


@pytest.mark.parametrize("travel", [0.0, 3.0])
def test_a_ball_on_a_wheel_reaches_the_points_near_its_path(travel):
    # A ball of radius 0.5 at 5 from the axis it screws about, and points scattered at 0.3 to 0.7
    # from its center's path (so about half of them are reached, many just within): the torus about
    # the orbit must keep every one brute force reaches.
    rng = np.random.default_rng(int(travel) + 51)
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    u = np.cross(n, rng.normal(size=3))
    u /= np.linalg.norm(u)
    c = rng.normal(size=3) * 3
    ball = cd.Point(c + 5 * u, sweep=0.5)
    motion = cd.Motion(translation=travel * n + 0.3 * u, rotation=5.0 * n, center=c)
    times = rng.uniform(0, 1, 300)
    path = ball.moved(motion, times).p
    offsets = rng.normal(size=(300, 3))
    offsets *= rng.uniform(0.3, 0.7, (300, 1)) / np.linalg.norm(offsets, axis=1, keepdims=True)
    scene = cd.Scene()
    scene.extend("p", cd.Point(path + offsets))
    shapes = [scene[name] for name in scene.names]
    got = check_same_as_brute_force(scene, shapes, ball, motion, 0.0, 300)
    assert 60 < len(got) < 240
