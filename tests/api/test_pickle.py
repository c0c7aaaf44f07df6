"""Shapes travel: every kind, single or batched, pickles, copies and deep-copies with its values
and dtypes kept (float32, float64 and long double inputs, sweeps), and answers every query as the
original does; to_arrays() / from_arrays() round trip through plain NumPy arrays (and .npz)."""

import copy
import io
import pickle

import numpy as np
import pytest

from circledist_cases.shapes import random_fields, random_sweep

cd = pytest.importorskip("circledist")

KINDS = tuple(cd._core._shape_fields())  # every kind, from the module's table


def _shapes():
    rng = np.random.default_rng(3)
    for kind in KINDS:
        for batch in ((), (5,), (2, 3)):
            for dtype in (np.float64, np.float32, np.longdouble):
                args = random_fields(cd, kind, rng, batch, dtype)
                yield kind, getattr(cd, kind)(**args)
                yield kind, getattr(cd, kind)(**args, sweep=random_sweep(rng, batch, dtype))


def _same_shape(x, y):
    assert type(x) is type(y) and x.batch_shape == y.batch_shape
    ax, ay = x.to_arrays(), y.to_arrays()
    assert list(ax) == list(ay)
    for name in ax:
        assert ax[name].dtype == ay[name].dtype and np.array_equal(ax[name], ay[name]), name


def _same_answers(x, y):
    ring = cd.Circle([0.1, 0.2, 0.3], [0.3, -0.2, 1.0], 0.7)
    for got, want in (
        (cd.distance(y, ring), cd.distance(x, ring)),
        (cd.closest_points(y, ring).point_a, cd.closest_points(x, ring).point_a),
    ):
        got, want = np.asarray(got), np.asarray(want)
        assert got.dtype == want.dtype and np.array_equal(got, want)


@pytest.mark.parametrize("protocol", [2, pickle.HIGHEST_PROTOCOL])
def test_pickle_round_trip(protocol):
    for kind, shape in _shapes():
        back = pickle.loads(pickle.dumps(shape, protocol=protocol))
        _same_shape(shape, back)
        _same_answers(shape, back)


def test_copy_and_deepcopy():
    for kind, shape in _shapes():
        for twin in (copy.copy(shape), copy.deepcopy(shape)):
            _same_shape(shape, twin)
            _same_answers(shape, twin)


def test_to_arrays_names_the_constructor_arguments_and_keeps_dtypes():
    rng = np.random.default_rng(4)
    for kind in KINDS:
        for dtype in (np.float64, np.float32, np.longdouble):
            args = random_fields(cd, kind, rng, (4,), dtype)
            shape = getattr(cd, kind)(**args)
            arrays = shape.to_arrays()
            assert list(arrays) == list(args)  # no sweep given: none listed (the default stays the default)
            swept = getattr(cd, kind)(**args, sweep=np.full(4, 0.25, dtype=dtype))
            assert list(swept.to_arrays()) == list(args) + ["sweep"]
            assert swept.to_arrays()["sweep"].dtype == dtype
            for name, given in args.items():
                assert arrays[name].dtype == given.dtype and np.array_equal(arrays[name], given), (kind, name)
            _same_shape(shape, getattr(cd, kind).from_arrays(arrays))


def test_from_arrays_through_npz():
    rng = np.random.default_rng(5)
    rings = cd.Circle(**random_fields(cd, "Circle", rng, (100,), np.float64), sweep=rng.uniform(0, 0.1, 100))
    buffer = io.BytesIO()
    np.savez(buffer, **rings.to_arrays())
    buffer.seek(0)
    with np.load(buffer) as data:
        back = cd.Circle.from_arrays(dict(data))
    _same_shape(rings, back)


def test_from_arrays_rejects_what_the_constructor_rejects():
    with pytest.raises(ValueError, match="radius"):
        cd.Circle.from_arrays({"center": [0, 0, 0], "normal": [0, 0, 1], "radius": -1.0})
    with pytest.raises(TypeError):
        cd.Circle.from_arrays({"center": [0, 0, 0], "normal": [0, 0, 1]})


def test_copy_false_keeps_zero_dimensional_fields():
    """copy=False (what unpickling uses) keeps a 0-d field 0-d: a single shape stays single."""
    ring = cd.Circle(np.zeros(3), np.array([0.0, 0, 1]), np.float64(1.0), sweep=np.float64(0.5), copy=False)
    assert ring.batch_shape == () and ring.radius.shape == () and ring.sweep.shape == ()
