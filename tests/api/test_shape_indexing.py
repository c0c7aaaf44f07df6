"""Indexing, len() and iteration of a batch of shapes, as NumPy indexes an array of the batch's
shape: the selected shapes answer every query with the bits the whole batch gives them."""

import numpy as np
import pytest

import circledist as cd


def rings(n=6, dtype=float):
    rng = np.random.default_rng(3)
    return cd.Circle(
        rng.normal(size=(n, 3)).astype(dtype),
        np.array([0.2, 0.3, 1.0], dtype=dtype),
        rng.uniform(0.5, 2, n).astype(dtype),
        sweep=np.full(n, 0.125, dtype=dtype),
    )


def lines(n=6):
    rng = np.random.default_rng(4)
    return cd.Line(rng.normal(size=(n, 3)), rng.normal(size=(n, 3)))


KEYS = [
    0,
    -1,
    3,
    slice(1, 5),
    slice(None, None, -2),
    Ellipsis,
    (Ellipsis,),
    [4, 0, 4],
    np.array([True, False, True, True, False, False]),
    np.arange(6) % 2 == 0,
    np.int64(2),
    [],
    slice(7, 9),
]


@pytest.mark.parametrize("key", KEYS, ids=repr)
def test_index_answers_as_the_batch(key):
    a, b = lines(), rings()
    whole = cd.closest_points(a, b)
    part = cd.closest_points(a[key], b[key])
    np.testing.assert_array_equal(part.distance, whole.distance[key])
    np.testing.assert_array_equal(part.point_b, whole.point_b[key])
    np.testing.assert_array_equal(part.param_b, whole.param_b[key])
    np.testing.assert_array_equal(cd.distance(a[key], b[key]), cd.distance(a, b)[key])


def test_fields_kept_with_their_dtypes_and_sweep():
    for dtype in (np.float32, np.float64, np.longdouble):
        batch = rings(dtype=dtype)
        one = batch[2]
        assert one.batch_shape == ()
        arrays, whole = one.to_arrays(), batch.to_arrays()
        assert set(arrays) == {"center", "normal", "radius", "sweep"} == set(whole)
        for name, value in arrays.items():
            assert value.dtype == whole[name].dtype, (name, dtype)
            own = (3,) if name in ("center", "normal") else ()
            np.testing.assert_array_equal(value, np.broadcast_to(whole[name], (6,) + own)[2])


def test_several_batch_axes_and_bezier_control_points():
    rng = np.random.default_rng(5)
    control = rng.normal(size=(2, 3, 4, 3))
    curves = cd.Bezier(control)
    assert curves.batch_shape == (2, 3) and len(curves) == 2
    np.testing.assert_array_equal(curves[1, 2].to_arrays()["control_points"], control[1, 2])
    np.testing.assert_array_equal(curves[1].to_arrays()["control_points"], control[1])
    np.testing.assert_array_equal(curves[..., 0].to_arrays()["control_points"], control[:, 0])
    np.testing.assert_array_equal(curves[:, [0, 2]].to_arrays()["control_points"], control[:, [0, 2]])
    mask = np.array([[True, False, True], [False, False, True]])
    np.testing.assert_array_equal(curves[mask].to_arrays()["control_points"], control[mask])
    target = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    np.testing.assert_array_equal(cd.distance(curves[mask], target), cd.distance(curves, target)[mask])


def test_len_iteration_and_truth():
    batch = rings()
    assert len(batch) == 6
    items = list(batch)
    assert len(items) == 6 and all(s.batch_shape == () for s in items)
    np.testing.assert_array_equal(
        [cd.distance(s, cd.Point([1, 2, 3])) for s in items], cd.distance(batch, cd.Point([1, 2, 3]))
    )
    single = cd.Point([1, 2, 3])
    assert bool(single) and bool(batch)
    with pytest.raises(TypeError, match="single Point"):
        len(single)
    with pytest.raises(TypeError, match="single Point"):
        iter(single)


@pytest.mark.parametrize(
    "key, error, match",
    [
        ((0, 0), IndexError, "too many indices"),
        (6, IndexError, "out of bounds"),
        (None, TypeError, r"None \(numpy.newaxis\) is not supported in a batch index"),
        ((slice(None), None), TypeError, r"None \(numpy.newaxis\) is not supported in a batch index"),
        ((None, 0), TypeError, r"None \(numpy.newaxis\) is not supported in a batch index"),
        ((Ellipsis, np.newaxis), TypeError, r"None \(numpy.newaxis\) is not supported in a batch index"),
        (True, TypeError, "index a batch"),
        (1.5, TypeError, "index a batch"),
        ((Ellipsis, Ellipsis), IndexError, "single ellipsis"),
        (np.array([0.5]), TypeError, "index a batch"),
    ],
    ids=repr,
)
def test_bad_indices(key, error, match):
    with pytest.raises(error, match=match):
        rings()[key]


def test_single_shape_is_not_indexable():
    with pytest.raises(TypeError, match="single Circle"):
        cd.Circle([0, 0, 0], [0, 0, 1], 1.0)[0]


def test_numpy_does_not_unpack_shapes():
    """A list of shapes stays a list of shapes in an object array."""
    shapes = [rings(), rings()]
    holder = np.empty(2, dtype=object)
    holder[:] = shapes
    assert holder[0] is shapes[0]


def test_arc_batches_index_as_the_batch_with_fields_broadcast():
    """An arc's five fields broadcast among themselves (angles (3, 1) against centers (4,)); every
    index answers with the bits the whole batch gives it, dtypes kept."""
    rng = np.random.default_rng(8)
    for dtype in (np.float64, np.float32, np.longdouble):
        arcs = cd.Arc(
            rng.normal(size=(4, 3)).astype(dtype),
            np.array([0.2, 0.3, 1.0], dtype=dtype),
            rng.uniform(0.5, 2, 4).astype(dtype),
            np.array([1.0, 0.0, 0.0], dtype=dtype),
            rng.uniform(0.5, 6, (3, 1)).astype(dtype),
        )
        assert arcs.batch_shape == (3, 4)
        target = cd.Segment([0, 0, 0], [1, 2, 0.5])
        whole = cd.distance(arcs, target)
        for key in ((1, 2), (slice(None), 0), (Ellipsis, 3), (np.array([2, 0]),), (whole > np.median(whole),)):
            part = arcs[key]
            assert part.kind == "Arc" and part.to_arrays()["angle"].dtype == np.dtype(dtype)
            assert np.array_equal(cd.distance(part, target), whole[key])


# An integer index beyond int64 (a Python int or numpy.uint64), alone or in a tuple, is out of
# bounds of every batch: NumPy's own conversion raised OverflowError ("Python int too large to
# convert to C long") or called it no integer.
@pytest.mark.parametrize("form", ["alone", "tuple", "with ellipsis"])
@pytest.mark.parametrize("index", [2**63, 2**64 - 1, "uint64", 2**64, 10**30, -(2**63) - 1])
@pytest.mark.parametrize("rows", [0, 3])
def test_batch_index_beyond_int64_is_out_of_bounds(index, form, rows):
    index = np.uint64(2**64 - 1) if index == "uint64" else index
    key = {"alone": index, "tuple": (index,), "with ellipsis": (index, Ellipsis)}[form]
    batch = cd.Point(np.zeros((rows, 3)))
    with pytest.raises(IndexError, match=f"Point: index {int(index)} is out of bounds for axis 0 with size {rows}"):
        batch[key]
    with pytest.raises(IndexError, match="out of bounds for axis 1 with size 2"):
        cd.Point(np.zeros((3, 2, 3)))[0, index]
