"""circledist.Motion and Shape.moved: motions validated, broadcast, pickled and rebuilt from arrays
as shapes are; every kind moved against an independent point map (the quaternion form of the
rotation), radii, angles and sweeps kept, batches broadcast, and distances kept by a common motion."""

import copy
import pickle

import numpy as np
import pytest

from circledist_cases.shapes import random_fields

cd = pytest.importorskip("circledist")

KINDS = tuple(cd._core._shape_fields())
FIELDS = ("translation", "rotation", "center")


def _rotate(w, v):
    """R(w) v by the unit quaternion q = (cos(|w|/2), sin(|w|/2) w/|w|): v + 2 q_w (q x v) + 2 q x (q x v)."""
    w, v = np.broadcast_arrays(np.asarray(w, float), np.asarray(v, float))
    theta = np.linalg.norm(w, axis=-1, keepdims=True)
    safe = np.where(theta > 0, theta, 1.0)
    q = np.sin(theta / 2) * w / safe
    qw = np.cos(theta / 2)
    qv = np.cross(q, v)
    return v + 2 * qw * qv + 2 * np.cross(q, qv)


def _move_points(x, motion, t):
    """The reference map of a point: center + R(t rotation)(x - center) + t translation."""
    a = motion.to_arrays()
    t = np.asarray(t, float)[..., None]
    return a["center"] + _rotate(t * a["rotation"], x - a["center"]) + t * a["translation"]


def _random_motion(rng, batch=()):
    return cd.Motion(
        translation=rng.normal(size=batch + (3,)),
        rotation=rng.normal(size=batch + (3,)) * 4,
        center=rng.normal(size=batch + (3,)),
    )


def _arc_start_point(arrays):
    """The arc's point at its start: the center plus the radius along the start's projection."""
    n = arrays["normal"] / np.linalg.norm(arrays["normal"], axis=-1, keepdims=True)
    s = arrays["start"] - np.sum(arrays["start"] * n, axis=-1, keepdims=True) * n
    s /= np.linalg.norm(s, axis=-1, keepdims=True)
    return arrays["center"] + arrays["radius"][..., None] * s


def test_motion_at_rest_and_fields():
    rest = cd.Motion()
    assert rest.batch_shape == ()
    for name in FIELDS:
        assert np.array_equal(getattr(rest, name), np.zeros(3))
        assert not getattr(rest, name).flags.writeable
    assert repr(cd.Motion(translation=[1, 2, 3])).startswith("Motion(translation=array([1., 2., 3.])")
    assert repr(cd.Motion(rotation=np.zeros((2, 3)))) == "Motion(batch shape (2,))"
    # Every field zero: every kind where it was.
    ring = cd.Circle([1, 2, 3], [0, 1, 1], 0.5, sweep=0.1)
    still = ring.moved(rest, 0.7)
    for name, value in ring.to_arrays().items():
        assert np.array_equal(still.to_arrays()[name], value), name


def test_motion_batches_broadcast():
    m = cd.Motion(translation=np.zeros((4, 3)), rotation=np.zeros((2, 1, 3)))
    assert m.batch_shape == (2, 4)
    with pytest.raises(ValueError, match=r"Motion: rotation of batch shape \(3,\) does not broadcast"):
        cd.Motion(translation=np.zeros((4, 3)), rotation=np.zeros((3, 3)))


@pytest.mark.parametrize("name", FIELDS)
def test_motion_validation_names_field_and_index(name):
    bad = np.zeros((3, 3))
    bad[1, 2] = np.nan
    with pytest.raises(ValueError, match=rf"Motion: {name}\[1\] contains NaN or inf"):
        cd.Motion(**{name: bad})
    bad[1, 2] = np.inf
    with pytest.raises(ValueError, match=rf"Motion: {name}\[1\] contains NaN or inf"):
        cd.Motion(**{name: bad})
    with pytest.raises(ValueError, match=rf"Motion: {name} must have shape \(3,\) or \(\.\.\., 3\), got \(2,\)"):
        cd.Motion(**{name: [1.0, 2.0]})
    with pytest.raises(ValueError, match=rf"Motion: {name} must be a real number array"):
        cd.Motion(**{name: ["a", "b", "c"]})


@pytest.mark.parametrize("dtype", [np.float64, np.float32, np.longdouble])
@pytest.mark.parametrize("batch", [(), (3,), (2, 2)])
def test_motion_pickles_and_round_trips(dtype, batch):
    rng = np.random.default_rng(5)
    m = cd.Motion(*(rng.normal(size=batch + (3,)).astype(dtype) for _ in FIELDS))
    for again in (
        pickle.loads(pickle.dumps(m)),
        copy.copy(m),
        copy.deepcopy(m),
        cd.Motion.from_arrays(m.to_arrays()),
        cd.Motion.from_arrays(m.to_arrays(), copy=False),
    ):
        assert type(again) is cd.Motion and again.batch_shape == batch
        for name, value in m.to_arrays().items():
            got = again.to_arrays()[name]
            assert got.dtype == np.dtype(dtype) and np.array_equal(got, value), name
    arrays = m.to_arrays()
    with pytest.raises(TypeError, match="Motion.from_arrays: unknown array 'spin'"):
        cd.Motion.from_arrays({**arrays, "spin": arrays["rotation"]})
    del arrays["center"]
    with pytest.raises(TypeError, match="Motion.from_arrays: no array 'center'"):
        cd.Motion.from_arrays(arrays)


@pytest.mark.parametrize("kind", KINDS)
def test_moved_every_kind_against_the_point_map(kind):
    rng = np.random.default_rng(abs(hash(kind)) % 2**32)
    fields = random_fields(cd, kind, rng, (6,), sweep=True)
    shape = getattr(cd, kind)(**fields)
    motion = _random_motion(rng, (6,))
    t = rng.uniform(0, 1, 6)
    moved = shape.moved(motion, t)
    assert type(moved) is type(shape) and moved.batch_shape == (6,)
    got = moved.to_arrays()
    roles = dict(cd._core._shape_fields()[kind])
    tol = 1e-13
    for name, value in fields.items():
        role = roles.get(name, "length")
        if role in ("length", "angle"):
            assert np.array_equal(got[name], value), name  # radii, angles, sweep: kept to the bit
        elif role == "vector":
            assert np.allclose(got[name], _move_points(value, motion, t), rtol=0, atol=tol), name
        elif role == "control_points":
            want = _move_points(value, cd.Motion(**{k: v[:, None] for k, v in motion.to_arrays().items()}), t[:, None])
            assert np.allclose(got[name], want, rtol=0, atol=tol), name
        elif name != "start":  # directions and normals rotate
            want = _rotate(t[:, None] * motion.rotation, value)
            assert np.allclose(got[name], want, rtol=0, atol=tol), name
    if kind == "Arc":  # the start rotates with the arc: its start point moves as a point
        assert np.allclose(_arc_start_point(got), _move_points(_arc_start_point(fields), motion, t), atol=tol)


def test_moved_two_turns_and_quarter_turn():
    ring = cd.Circle([3, 0, 0], [1, 0, 0], 1.0)
    turns = cd.Motion(rotation=[0, 0, 4 * np.pi])
    back = ring.moved(turns, 1.0)
    assert np.allclose(back.center, [3, 0, 0], atol=1e-14) and np.allclose(back.normal, [1, 0, 0], atol=1e-15)
    quarter = ring.moved(turns, 1 / 8)  # a quarter turn about z: x to y
    assert np.allclose(quarter.center, [0, 3, 0], atol=1e-14) and np.allclose(quarter.normal, [0, 1, 0], atol=1e-15)


def test_moved_broadcasts_shape_motion_and_time():
    point = cd.Point([1.0, 0.0, 0.0])
    slide = cd.Motion(translation=np.eye(3))
    moved = point.moved(slide, [[0.0], [0.5]])
    assert moved.batch_shape == (2, 3)
    assert np.array_equal(moved.p, np.array([1.0, 0.0, 0.0]) + np.array([0.0, 0.5])[:, None, None] * np.eye(3))
    with pytest.raises(
        ValueError, match=r"moved: batch shapes \(\) of the Point, \(3,\) of the motion and \(2,\) of t"
    ):
        point.moved(slide, [0.0, 1.0])


def test_moved_errors():
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    with pytest.raises(TypeError, match="moved: motion must be a circledist.Motion, got tuple"):
        ring.moved((0, 0, 1), 0.5)
    with pytest.raises(ValueError, match=r"moved: t\[1\] contains NaN or inf"):
        ring.moved(cd.Motion(), [0.0, np.nan])
    with pytest.raises(ValueError, match="moved: t must be a real number array"):
        ring.moved(cd.Motion(), "soon")


def test_moved_precision():
    ring = cd.Circle(np.float32([0, 0, 0]), np.float32([0, 0, 1]), np.float32(1.0), sweep=np.float32(0.25))
    moved = ring.moved(cd.Motion(translation=[0.1, 0, 0]), 1.0)
    arrays = moved.to_arrays()
    assert arrays["center"].dtype == np.float64
    assert arrays["radius"].dtype == np.float32 and arrays["sweep"].dtype == np.float32
    wide = ring.moved(cd.Motion(translation=np.array([1, 0, 0], np.longdouble) / 3), np.longdouble(1))
    if np.finfo(np.longdouble).nmant > np.finfo(np.float64).nmant:
        assert wide.to_arrays()["center"].dtype == np.longdouble
        assert wide.to_arrays()["center"][0] == np.longdouble(1) / 3


@pytest.mark.parametrize("kinds", [("Circle", "Segment"), ("Arc", "Disk"), ("Bezier", "Annulus"), ("Line", "Circle")])
def test_a_common_motion_keeps_distances(kinds):
    rng = np.random.default_rng(11)
    a = getattr(cd, kinds[0])(**random_fields(cd, kinds[0], rng, (5,)))
    b = getattr(cd, kinds[1])(**random_fields(cd, kinds[1], rng, (5,)))
    motion = _random_motion(rng, (5,))
    t = rng.uniform(0, 1, 5)
    before = cd.distance(a, b)
    after = cd.distance(a.moved(motion, t), b.moved(motion, t))
    assert np.allclose(after, before, rtol=0, atol=1e-12 * 10)
