"""Strict inputs: a shape made without its constructor is a TypeError (not a crash),
shapes are values (no aliasing of the caller's arrays, read-only fields), only real numbers are
accepted, errors are clear, Scene bounds stay conservative at every magnitude, and the CLI answers
bad files with its one-line error. Each crash-prone call runs in a child process so that a
regression fails the test instead of taking pytest down."""

import math
import re
import subprocess
import sys

import numpy as np
import pytest

cd = pytest.importorskip("circledist")
cli = pytest.importorskip("circledist.cli")

PROBE = cd.Circle([0.3, -0.7, 2.5], [0.0, 1.0, 1.0], 0.5)
KINDS = {
    "Point": ([1.0, 2.0, 3.0],),
    "Line": ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    "Ray": ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    "Segment": ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    "Circle": ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0),
    "Disk": ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0),
    "Bezier": ([[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]],),
}


@pytest.mark.parametrize("kind", sorted(KINDS))
@pytest.mark.parametrize(
    "use",
    [
        "repr(p)",
        "p.kind",
        "p.batch_shape",
        "p.sweep",
        "cd.distance(p, cd.Point([0, 0, 5]))",
        "cd.closest_points(cd.Point([0, 0, 5]), p)",
        "cd.within(p, p, 1.0)",
        "cd.intersects(p, cd.Circle([0, 0, 0], [0, 0, 1], 1.0))",
    ],
)
def test_shape_without_constructor_is_a_type_error(kind, use):
    code = (
        f"import circledist as cd\np = cd.{kind}.__new__(cd.{kind})\n"
        f"try:\n    {use}\nexcept TypeError as e:\n    print('TypeError', e)\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("TypeError") and "not initialized" in proc.stdout, proc.stdout


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_fields_are_read_only_copies(kind):
    args = [np.array(a, dtype=float) for a in KINDS[kind]]
    shape = getattr(cd, kind)(*args)
    before = cd.distance(shape, PROBE)
    for a in args:
        a[...] = 0.0 if a.ndim == 0 else 7.0  # the caller's arrays change ...
    assert cd.distance(shape, PROBE) == before  # ... the shape does not
    for name in ("sweep",) + tuple(
        n
        for n in ("p", "origin", "direction", "p0", "p1", "center", "normal", "radius", "control_points")
        if hasattr(shape, n)
    ):
        field = getattr(shape, name)
        with pytest.raises(ValueError, match="read-only"):
            field[...] = 0


def test_copy_false_refers_to_the_callers_arrays():
    """copy=False (as cKDTree's copy_data=False): a float64 C-contiguous field is a read-only view
    of the caller's array, not a copy; the caller promises not to change it. Other inputs are
    converted (a copy is then unavoidable); the default keeps its own copy."""
    p = np.zeros((1000, 3))
    c, n, r = np.zeros((1000, 3)), np.tile([0.0, 0.0, 1.0], (1000, 1)), np.ones(1000)
    shared = cd.Circle(c, n, r, copy=False)
    assert np.shares_memory(shared.center, c) and np.shares_memory(shared.radius, r)
    own = cd.Circle(c, n, r)
    assert not np.shares_memory(own.center, c)
    points = cd.Point(p, copy=False)
    assert np.shares_memory(points.p, p)
    np.testing.assert_array_equal(cd.distance(points, shared), np.ones(1000))
    with pytest.raises(ValueError, match="read-only"):
        shared.center[0, 0] = 1.0  # the view is read-only, the caller's array is not
    c[0, 2] = 3.0  # the caller changes its array: the shared shape sees it, the copy does not
    origin = cd.Point([0.0, 0.0, 0.0])
    assert cd.distance(origin, shared)[0] == pytest.approx(math.sqrt(10), rel=1e-15)
    assert cd.distance(origin, own)[0] == 1.0
    # Validation still happens at construction.
    with pytest.raises(ValueError, match="NaN or inf"):
        cd.Point(np.array([[0.0, np.nan, 0.0]]), copy=False)
    # float32 / int inputs are converted, so nothing is shared.
    q = np.zeros((4, 3), dtype=np.float32)
    assert not np.shares_memory(cd.Point(q, copy=False).p, q)


def test_batch_fields_do_not_alias():
    a = np.zeros((2, 3))
    p = cd.Point(a)
    a[0, 0] = 5
    np.testing.assert_array_equal(cd.distance(p, cd.Point([0, 0, 0])), [0.0, 0.0])
    c = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    with pytest.raises(ValueError):
        c.normal[:] = 0
    with pytest.raises(ValueError):
        c.radius[...] = -1
    assert cd.distance(c, cd.Point([0, 0, 2])) == pytest.approx(math.sqrt(5), rel=1e-15)


@pytest.mark.parametrize(
    "value",
    [
        [0, 0, 3 + 4j],
        np.array([1, 2, 3], dtype=complex),
        np.array([1, 2, 3], dtype="datetime64[s]"),
        np.array([1, 2, 3], dtype="timedelta64[s]"),
        ["1", "2", "3"],
        np.array(["1", "2", "3"]),
        [b"1", b"2", b"3"],
        [None, None, None],
        [1.0, None, 2.0],
        [True, False, True],
        [1.0, "x", 2.0],
    ],
)
def test_only_real_numbers(value):
    with pytest.raises(ValueError, match="Point: p must be a real number array"):
        cd.Point(value)


@pytest.mark.parametrize("value", [3 + 4j, np.complex64(1), np.datetime64(1, "s"), "1", b"1", None, True])
def test_only_real_scalars(value):
    with pytest.raises(ValueError, match="Circle: radius must be a real number array"):
        cd.Circle([0, 0, 0], [0, 0, 1], value)


ROLE_VALUES = {
    "vector": [1.0, 2.0, 3.0],
    "direction": [0.0, 0.0, 1.0],
    "length": 1.0,
    "angle": 1.0,
    "control_points": [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]],
}
FIELDS = [(kind, i) for kind, fields in cd._core._shape_fields().items() for i in range(len(fields))]


@pytest.mark.parametrize("copy", [True, False])
@pytest.mark.parametrize("kind, field", FIELDS, ids=[f"{k}.{i}" for k, i in FIELDS])
def test_a_field_too_large_to_copy_is_a_memory_error_naming_it(kind, field, copy):
    """A valid batch whose contiguous float64 copy cannot be made (a broadcast view of 10**15
    elements: petabytes, more than an address space holds, so nothing is allocated) is a
    MemoryError naming the field and its size, not "must be a real number array"."""
    fields = cd._core._shape_fields()[kind]
    values = [ROLE_VALUES[role] for _, role in fields]
    name = fields[field][0]
    one = np.asarray(values[field], dtype=float)
    values[field] = np.broadcast_to(one, (10**15,) + one.shape)
    with pytest.raises(
        MemoryError,
        match=(
            rf"{kind}: {name} cannot be copied: out of memory "
            rf"\(shape \(1000000000000000,.*\), [0-9.e+]+ bytes as a contiguous float64 array"
        ),
    ):
        getattr(cd, kind)(*values, copy=copy)


def test_limits_and_sweeps_too_large_to_copy_are_a_memory_error():
    huge = np.broadcast_to(np.float64(1.0), (10**15,))
    with pytest.raises(MemoryError, match=r"within: d cannot be copied: out of memory \(shape \(1000000000000000,\)"):
        cd.within(cd.Point([0, 0, 0]), cd.Point([0, 0, 1]), huge)
    with pytest.raises(MemoryError, match=r"Point: sweep cannot be copied"):
        cd.Point([0, 0, 0], sweep=huge)


def test_real_objects_are_accepted():
    from fractions import Fraction

    assert cd.distance(cd.Point([Fraction(1, 2), 0, 0]), cd.Point([0, 0, 0])) == 0.5
    assert cd.distance(cd.Point(np.array([1, 2, 2], dtype=np.int8)), [0, 0, 0]) == 3.0


def test_limit_errors_are_clear():
    a, b = cd.Point([0, 0, 0]), cd.Point([0, 0, 1])
    with pytest.raises(ValueError, match="within: d must be a real number array"):
        cd.within(a, b, None)
    with pytest.raises(ValueError, match="within: d must be a real number array"):
        cd.within(a, b, "1")
    with pytest.raises(ValueError, match="within: d contains NaN or inf"):
        cd.within(a, b, float("nan"))


def test_scene_nearest_k_is_checked():
    s = cd.Scene([("a", cd.Point([0, 0, 1])), ("b", cd.Point([0, 0, 2]))])
    for bad in (float("nan"), 1.7, "2", None, True):
        with pytest.raises(TypeError, match="k must be an integer"):
            s.nearest(cd.Point([0, 0, 0]), k=bad)
    with pytest.raises(ValueError, match="k must be an integer >= 1"):
        s.nearest(cd.Point([0, 0, 0]), k=0)
    assert s.nearest(cd.Point([0, 0, 0]), k=np.int64(2)) == [("a", 1.0), ("b", 2.0)]
    for bad in (None, "5"):
        with pytest.raises(TypeError, match="d must be a real number"):
            s.within(cd.Point([0, 0, 0]), bad)


# Integer arguments (k, workers, tiles) have one reader and one rule everywhere: an int or a NumPy
# integer; bools refused (True is not a count); a value beyond 64 bits refused in the library's
# words (pybind11 said "Unable to cast ... to C++ type '?'" or dumped the signature).
_P, _RING = cd.Point(np.zeros((4, 3))), cd.Circle([0, 0, 0], [0, 0, 1], 1.0)


def _scene():
    return cd.Scene([("a", cd.Point([0, 0, 1])), ("b", cd.Point([0, 0, 2]))])


def _dask_pairs(**options):
    pytest.importorskip("dask.array")
    import circledist.dask as dask_module

    return dask_module.pairs_within(_P, _RING, 1.0, **options)


INTEGER_ARGUMENTS = {
    "distance workers": ("workers", lambda v: cd.distance(_P, _RING, workers=v)),
    "closest_points workers": ("workers", lambda v: cd.closest_points(_P, _RING, workers=v)),
    "intersects workers": ("workers", lambda v: cd.intersects(_P, _RING, workers=v)),
    "within workers": ("workers", lambda v: cd.within(_P, _RING, 1.0, workers=v)),
    "distance_if_within workers": ("workers", lambda v: cd.distance_if_within(_P, _RING, 1.0, workers=v)),
    "pairs_within workers": ("workers", lambda v: cd.pairs_within(_P, _RING, 1.0, workers=v)),
    "nearest workers": ("workers", lambda v: cd.nearest(_P, _RING, 1, workers=v)),
    "nearest k": ("k", lambda v: cd.nearest(_P, _RING, v)),
    "Scene.nearest k": ("k", lambda v: _scene().nearest([0, 0, 0], k=v)),
    "Scene.pairs_within workers": ("workers", lambda v: _scene().pairs_within(1.0, workers=v)),
    "dask pairs_within workers": ("workers", lambda v: _dask_pairs(workers=v)),
    "dask pairs_within tiles": ("tiles", lambda v: _dask_pairs(tiles=v)),
}


@pytest.mark.parametrize("entry", sorted(INTEGER_ARGUMENTS))
@pytest.mark.parametrize("value", [True, False, np.True_, 1.0, np.float64(2), "1", 1 + 0j])
def test_integer_arguments_refuse_bools_and_non_integers(entry, value):
    name, call = INTEGER_ARGUMENTS[entry]
    with pytest.raises(TypeError, match=f"{name} must be .*, got {re.escape(repr(value))}") as error:
        call(value)
    assert "Unable to cast" not in str(error.value) and "incompatible" not in str(error.value)


@pytest.mark.parametrize("entry", sorted(INTEGER_ARGUMENTS))
@pytest.mark.parametrize("value", [2**63, 2**64 + 1, 10**30, -(2**63) - 1, -(10**400)])
def test_integer_arguments_beyond_64_bits_are_a_value_error(entry, value):
    name, call = INTEGER_ARGUMENTS[entry]
    bound = "at most 2\\*\\*63 - 1" if value > 0 else "at least -2\\*\\*63"
    with pytest.raises(ValueError, match=f"{name} must be .*{bound}") as error:
        call(value)
    assert "Unable to cast" not in str(error.value) and "incompatible" not in str(error.value)


@pytest.mark.parametrize("entry", sorted(INTEGER_ARGUMENTS))
@pytest.mark.parametrize("value", [np.int64(2), np.uint8(3), 2**40])
def test_integer_arguments_take_ints_and_numpy_integers(entry, value):
    """A count as large as 2**40 is a valid k and a valid worker count (threads are bounded by the
    work); tiles as large cost one tile per occupied cell."""
    name, call = INTEGER_ARGUMENTS[entry]
    if name == "k" and entry == "nearest k" and value == 2**40:
        value = 5  # 4 x 2**40 answers do not fit in memory: test_pairs covers that MemoryError
    call(value)


DISTANCE_LIMITS = {
    "pairs_within": lambda d: cd.pairs_within(_P, _RING, d),
    "Scene.within": lambda d: _scene().within([0, 0, 0], d),
    "Scene.pairs_within": lambda d: _scene().pairs_within(d),
    "dask pairs_within": lambda d: _dask_pairs_d(d),
}


def _dask_pairs_d(d):
    pytest.importorskip("dask.array")
    import circledist.dask as dask_module

    return dask_module.pairs_within(_P, _RING, d)


def _owner(entry):
    return entry.replace("dask ", "")


@pytest.mark.parametrize("entry", sorted(DISTANCE_LIMITS))
@pytest.mark.parametrize("d", [10**400, -(10**400)])
def test_distance_limits_beyond_float64_are_a_value_error(entry, d):
    with pytest.raises(ValueError, match=f"{_owner(entry)}: d must be a .*number >= 0, got an integer of 401 digits"):
        DISTANCE_LIMITS[entry](d)


@pytest.mark.parametrize("entry", sorted(DISTANCE_LIMITS))
@pytest.mark.parametrize("d", [True, np.True_, "1", None, 1 + 0j])
def test_distance_limits_refuse_bools_and_non_reals(entry, d):
    with pytest.raises(TypeError, match=f"{_owner(entry)}: d must be a real number >= 0, got {re.escape(repr(d))}"):
        DISTANCE_LIMITS[entry](d)


@pytest.mark.parametrize("entry", sorted(DISTANCE_LIMITS))
@pytest.mark.parametrize("d", [float("inf"), float("nan"), -1.0])
def test_distance_limits_refuse_inf_nan_and_negatives(entry, d):
    with pytest.raises(ValueError, match=f"{_owner(entry)}: d must be a finite number >= 0"):
        DISTANCE_LIMITS[entry](d)


@pytest.mark.parametrize("far", [1e155, 1e200, 1e300, 1.7e308, -1e300])
def test_scene_bounds_stay_conservative_with_far_shapes(far):
    """One far shape must not overflow the hierarchy's bounds into culling the near ones."""
    near = {
        "seg": cd.Segment([1, 0, 0], [1, 1, 0]),
        "ring": cd.Circle([0, 3, 0], [0, 0, 1], 1.0),
        "coin": cd.Disk([0, 0, -2], [1, 1, 1], 0.5),
    }
    shapes = dict(near)
    shapes["far"] = cd.Point([far, 0, 0])
    shapes["far ring"] = cd.Circle([far, far, 0], [0, 0, 1], abs(far) / 10)
    shapes["far line"] = cd.Line([far, 0, far], [1e-200, 1, 0])
    s = cd.Scene(list(shapes.items()))
    q = cd.Point([0, 0, 0])
    brute = [n for n, sh in shapes.items() if cd.within(q, sh, 5.0)]
    assert s.within(q, 5.0) == brute == ["seg", "ring", "coin"]
    assert s.nearest(q, k=3) == sorted(((n, cd.distance(q, sh)) for n, sh in near.items()), key=lambda x: x[1])
    pairs = s.pairs_within(5.0)
    assert ("seg", "ring") in pairs and ("seg", "coin") in pairs


@pytest.mark.parametrize(
    "text,message",
    [
        (
            '{"format": "circledist-scene", "version": 1, "shapes": [{"name": "a", "kind": "circle", '
            '"center": [0, 0, 0], '
            '"normal": [0, 0, 1], "radius": 1' + "0" * 400 + "}]}",
            "$.shapes[0].radius: expected a finite number (within a double's range), got an integer of 401 digits",
        ),
        ("[" * 100000 + "]" * 100000, "nested too deeply"),
    ],
)
def test_cli_bad_files_give_the_one_line_error(tmp_path, capsys, text, message):
    path = tmp_path / "scene.json"
    path.write_text(text)
    assert cli.main([str(path), "--no-plot"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("circledist: error:") and message in err and "Traceback" not in err


def test_cli_non_utf8_file(tmp_path, capsys):
    path = tmp_path / "scene.json"
    path.write_bytes(b'{"shapes": [\xff\xfe]}')
    assert cli.main([str(path), "--no-plot"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("circledist: error:") and "UTF-8" in err


@pytest.mark.parametrize("scale", [1e-300, 1e-200, 1e-155, 1e-40, 1e-20, 1e20, 1e155, 1e200, 1e300])
@pytest.mark.parametrize("precision", ["float64", "longdouble"])
def test_effects_at_extreme_scales(scale, precision):
    """within / intersects / distance_if_within agree with the distance at every magnitude (a scale
    of inf from an overflowed |c_a - c_b| made every pair 'within')."""
    q = cd.Point([0, 0, 0])
    shapes = [
        (cd.Point([3 * scale, 4 * scale, 0]), 5 * scale),
        (cd.Circle([0, 0, 6 * scale], [0, 0, 1], scale), math.sqrt(37) * scale),
        (cd.Line([0, 2 * scale, 0], [1e-200, 0, 1]), 2 * scale),
        (cd.Segment([2 * scale, -scale, 0], [2 * scale, scale, 0]), 2 * scale),
        (cd.Disk([0, 0, 2 * scale], [0, 1e200, 1e200], scale), math.sqrt(2 + (math.sqrt(2) - 1) ** 2) * scale),
    ]
    for shape, truth in shapes:
        for a, b in ((q, shape), (shape, q)):
            assert cd.distance(a, b, precision=precision) == pytest.approx(truth, rel=1e-14)
            for d, expected in ((truth / 2, False), (truth * 0.999, False), (truth * 1.001, True), (truth * 2, True)):
                assert bool(cd.within(a, b, d, precision=precision)) is expected, (shape, d)
                got = cd.distance_if_within(a, b, d, precision=precision)
                assert (got == pytest.approx(truth, rel=1e-14)) if expected else got == math.inf
            assert bool(cd.intersects(a, b, precision=precision)) is False


def test_float32_effects_past_float_squares():
    a = cd.Point(np.float32([0, 0, 0]))
    b = cd.Point(np.float32([3e20, 4e20, 0]))
    assert cd.distance(a, b) == np.float32(5e20)
    assert bool(cd.within(a, b, np.float32(6e20))) and not bool(cd.within(a, b, np.float32(4e20)))
    assert cd.distance_if_within(a, b, np.float32(6e20)) == np.float32(5e20)


def test_float32_answers_beyond_float32_range_are_an_overflow_error():
    """Inputs float32 holds can have answers it cannot: a closest point (or distance, or line
    parameter) past 3.4e38 would round to inf. Found by the 10^7 crash fuzz (seed 3, case 2103976:
    a circle of radius 2.1e38 centered 3.1e38 from the origin)."""
    ring = cd.Circle([3.1e38, 0, 0], [0, 0, 1], 2.1e38)
    probe = cd.Point([3.2e38, 0, 0])
    # The closest point of the ring lies at x = 5.2e38 (exact reference: centre + radius).
    with pytest.raises(OverflowError, match=r"closest_points: point_b is beyond float32's range"):
        cd.closest_points(probe, ring, precision="float32")
    with pytest.raises(OverflowError, match=r"closest_points: point_a is beyond float32's range"):
        cd.closest_points(ring, probe, precision="float32")
    # The same pair in float64 answers, and the distance alone fits float32.
    r = cd.closest_points(probe, ring)
    assert r.point_b[0] == pytest.approx(5.2e38, rel=1e-15) and r.distance == pytest.approx(2e38, rel=1e-15)
    assert cd.distance(probe, ring, precision="float32") == pytest.approx(2e38, rel=1e-6)
    # A distance past the range (two points 6e38 apart), scalar and in a batch (named by index).
    with pytest.raises(OverflowError, match=r"distance: the distance is beyond float32's range"):
        cd.distance(cd.Point([-3e38, 0, 0]), cd.Point([3e38, 0, 0]), precision="float32")
    batch = cd.Point([[0, 0, 0], [0, 1, 0], [-3e38, 0, 0]])
    with pytest.raises(OverflowError, match=r"distance: the distance\[2\] is beyond"):
        cd.distance(batch, cd.Point([3e38, 0, 0]), precision="float32")
    with pytest.raises(OverflowError, match=r"closest_points: distance\[2\] is beyond"):
        cd.closest_points(batch, cd.Point([3e38, 0, 0]), precision="float32")
    # A line parameter past the range: p = origin + t * direction with |direction| = 1e-30.
    with pytest.raises(OverflowError, match=r"param_a is beyond float32's range"):
        cd.closest_points(cd.Line([3e38, 0, 0], [1e-30, 0, 0]), cd.Point([0, 1, 0]), precision="float32")
    # Answers inside the range are unaffected, and float32 stays float32.
    r = cd.closest_points(
        cd.Point(np.float32([1e38, 0, 0])),
        cd.Circle(np.float32([3.1e38, 0, 0]), np.float32([0, 0, 1]), np.float32(2.1e38)),
    )
    assert r.point_b.dtype == np.float32 and np.all(np.isfinite(r.point_b))
    # distance_if_within's inf means "beyond the limit", which a distance past float32 always is.
    assert cd.distance_if_within(cd.Point([-3e38, 0, 0]), cd.Point([3e38, 0, 0]), 1.0, precision="float32") == math.inf
