"""circledist.dask against the single-process circledist calls, to the bit, computed on a real
distributed.LocalCluster of two worker processes: every kind pair with chunkings that line up and
that do not, (N, 1) x (M,) broadcasting, circledist shapes and point arrays as arguments,
precisions and solvers, one solve behind all of closest_points' attributes, and pairs_within on
random and clustered scenes (lines and rays, self pairs, empty batches)."""

import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("dask.array")
distributed = pytest.importorskip("distributed")

import dask  # noqa: E402
import dask.array as da  # noqa: E402

import circledist as cd  # noqa: E402
import circledist.dask as cdd  # noqa: E402
from circledist_cases.batches import SUPPORTED, TRAILING, random_batch  # noqa: E402

KIND_PAIRS = sorted(SUPPORTED)


# The tests that take this client are marked serial: one cluster of two processes, started once by
# the pytest process that runs them all, with no other test process beside it. They are marked
# slow too: the cluster's start alone takes seconds.
@pytest.fixture(scope="module")
def client():
    # No dashboard: its fixed port may be taken by another run on this machine.
    with (
        distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cluster,
        distributed.Client(cluster) as c,
    ):
        yield c


def chunked(shape, chunks):
    """The dask shape of a circledist shape, its batched fields cut into `chunks`."""
    fields = {
        name: da.from_array(value, chunks={0: chunks} if value.ndim > TRAILING[name] else -1)
        for name, value in shape.to_arrays().items()
    }
    return getattr(cdd, shape.kind).from_arrays(fields)


def same(got, expected):
    got, expected = np.asarray(got), np.asarray(expected)
    assert got.dtype == expected.dtype and got.shape == expected.shape
    # Equal values and signs of zero: the same bits (long double's padding bytes aside; no NaN here).
    assert np.array_equal(got, expected)
    if got.dtype.kind == "f":
        assert np.array_equal(np.signbit(got), np.signbit(expected))


def every_kind_pair(n, chunkings, seed):
    """(dask answers, cd answers) of every query on every kind pair, in the given chunkings."""
    rng = np.random.default_rng(seed)
    lazy, expected = [], []
    for ka, kb in KIND_PAIRS:
        a, b = random_batch(ka, n, rng), random_batch(kb, n, rng)
        d = rng.uniform(0, 3, n)
        for ca, cb in chunkings:
            da_, db_ = chunked(a, ca), chunked(b, cb)
            r = cdd.closest_points(da_, db_)
            lazy += [cdd.distance(da_, db_), cdd.within(da_, db_, d)] + [getattr(r, n) for n, _ in cdd._RESULT_FIELDS]
            e = cd.closest_points(a, b)
            expected += [cd.distance(a, b), cd.within(a, b, d)] + [getattr(e, n) for n, _ in cdd._RESULT_FIELDS]
        # circledist shapes go through to_arrays().
        lazy.append(cdd.distance(a, chunked(b, 6)))
        expected.append(cd.distance(a, b))
    return lazy, expected


@pytest.mark.slow
def test_every_kind_pair_and_chunking_equals_the_single_process_calls():
    # Chunks that line up (5 and 5), that do not (4 and 7), one chunk against many; in this
    # process (the cluster test below runs the same graphs over two worker processes).
    lazy, expected = every_kind_pair(17, ((5, 5), (4, 7), (17, 3)), 18)
    for got, e in zip(dask.compute(*lazy, scheduler="sync"), expected):
        same(got, e)


@pytest.mark.slow
@pytest.mark.serial
def test_every_kind_pair_on_the_cluster(client):
    lazy, expected = every_kind_pair(12, ((4, 7),), 19)
    for got, e in zip(dask.compute(*lazy), expected):
        same(got, e)


@pytest.mark.slow
@pytest.mark.serial
def test_broadcasting_n1_by_m(client):
    rng = np.random.default_rng(3)
    rings, points = random_batch("Circle", 17, rng), random_batch("Point", 29, rng)
    arrays = rings.to_arrays()
    column = {name: v[:, None] for name, v in arrays.items()}
    rings_n1 = cd.Circle.from_arrays(column)
    # Fields chunked three ways, and one a NumPy array.
    lazy_rings = cdd.Circle(
        da.from_array(column["center"], chunks=(5, 1, 3)),
        column["normal"],
        da.from_array(column["radius"], chunks=(4, 1)),
        sweep=da.from_array(column["sweep"], chunks=(6, 1)),
    )
    lazy_points = chunked(points, 8)
    # d broadcasting against both, and a point array read as points, as cd reads it.
    d = rng.uniform(0, 4, (1, 29))
    got = dask.compute(
        cdd.distance(lazy_rings, lazy_points),
        cdd.within(lazy_rings, lazy_points, d),
        cdd.closest_points(lazy_rings, lazy_points).point_a,
        cdd.distance(lazy_rings, da.from_array(points.to_arrays()["p"], chunks=10)),
    )
    assert got[0].shape == (17, 29)
    same(got[0], cd.distance(rings_n1, points))
    same(got[1], cd.within(rings_n1, points, d))
    same(got[2], cd.closest_points(rings_n1, points).point_a)
    same(got[3], cd.distance(rings_n1, points.to_arrays()["p"]))


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.parametrize("precision", [None, "float32", "longdouble"])
@pytest.mark.parametrize("solver", ["bracketing", "companion"])
def test_precision_solver_and_workers_pass_through(client, precision, solver):
    rng = np.random.default_rng(5)
    a, b = random_batch("Disk", 20, rng), random_batch("Bezier", 20, rng)
    opts = {"precision": precision, "solver": solver}
    got = dask.compute(
        cdd.distance(chunked(a, 6), chunked(b, 9), workers=2, **opts),
        cdd.closest_points(chunked(a, 6), chunked(b, 9), **opts).point_b,
    )
    same(got[0], cd.distance(a, b, **opts))
    same(got[1], cd.closest_points(a, b, **opts).point_b)


def test_float32_fields_keep_float32():
    rng = np.random.default_rng(6)
    p = rng.normal(size=(10, 3)).astype(np.float32)
    ring = cd.Circle(np.float32([0, 0, 0]), np.float32([0, 0, 1]), np.float32(1))
    got = cdd.distance(cdd.Point(da.from_array(p, chunks=3)), ring).compute(scheduler="sync")
    same(got, cd.distance(cd.Point(p), ring))


def test_closest_points_solves_once_for_all_attributes(monkeypatch):
    calls = []
    solve = cdd._closest_block

    def counting(*blocks, **kwargs):
        calls.append(1)
        return solve(*blocks, **kwargs)

    monkeypatch.setattr(cdd, "_closest_block", counting)
    rng = np.random.default_rng(7)
    r = cdd.closest_points(chunked(random_batch("Circle", 12, rng), 4), chunked(random_batch("Line", 12, rng), 4))
    dask.compute(*[getattr(r, n) for n, _ in cdd._RESULT_FIELDS], scheduler="sync")
    assert len(calls) == 3  # three chunks, each solved once


def test_kinds_without_a_query_and_bad_fields_raise():
    line = cdd.Line([0, 0, 0], [1, 0, 0])
    # every pair of kinds has a query now, curves against curves too (bezier_bezier.hpp)
    assert float(
        cdd.distance(cdd.Bezier([[0, 0, 1], [1, 0, 1]]), cdd.Bezier([[0, 0, 0], [1, 1, 1]])).compute()
    ) == cd.distance(cd.Bezier([[0, 0, 1], [1, 0, 1]]), cd.Bezier([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(ValueError, match="center"):
        cdd.Circle(np.zeros((4, 2)), [0, 0, 1], 1.0)
    with pytest.raises(ValueError, match="do not broadcast"):
        cdd.Circle(np.zeros((4, 3)), [0, 0, 1], np.ones(5))
    with pytest.raises(ValueError, match="d must be"):
        cdd.pairs_within(line, line, -1.0)


def scene(kind, n, rng, clustered):
    """Random shapes over a box, or packed into three tight clusters (many per tile)."""
    if not clustered:
        return random_batch(kind, n, rng, box=8.0)
    arrays = random_batch(kind, n, rng, box=0.5).to_arrays()
    spots = rng.uniform(-8, 8, (3, 3))[rng.integers(0, 3, n)]
    for name in ("p", "origin", "p0", "p1", "center"):
        if name in arrays:
            arrays[name] = arrays[name] + spots
    if "control_points" in arrays:
        arrays["control_points"] = arrays["control_points"] + spots[:, None]
    return getattr(cd, kind).from_arrays(arrays)


PAIR_CASES = [
    ("Circle", "Segment"),
    ("Point", "Circle"),
    ("Disk", "Disk"),
    ("Bezier", "Circle"),
    ("Line", "Disk"),
    ("Segment", "Ray"),
    ("Line", "Line"),
    ("Circle", "Bezier"),
    ("Arc", "Segment"),
    ("Disk", "Arc"),
    ("Arc", "Arc"),
    ("Annulus", "Circle"),
    ("Segment", "Annulus"),
    ("Annulus", "Annulus"),
]


def pairs_cases(clustered, n_a, n_b, cases):
    rng = np.random.default_rng(11 + clustered)
    lazy, expected = [], []
    for ka, kb in cases:
        a, b = scene(ka, n_a, rng, clustered), scene(kb, n_b, rng, clustered)
        for d, tiles in ((0.0, None), (0.4, 50), (1.5, 8)):
            lazy.append(cdd.pairs_within(chunked(a, n_a // 3), chunked(b, n_b // 2 - 1), d, tiles=tiles))
            expected.append(cd.pairs_within(a, b, d))
        if ka == kb:
            lazy.append(cdd.pairs_within(chunked(a, n_a // 4), None, 0.7))
            expected.append(cd.pairs_within(a, None, 0.7))
    return lazy, expected


def check_pairs(got, expected):
    found = 0
    for g, e in zip(got, expected):
        for x, y in zip(g, e):
            same(x, y)
        found += len(e[0])
    return found


@pytest.mark.slow
@pytest.mark.parametrize("clustered", [False, True])
def test_pairs_within_equals_the_single_process_call(clustered):
    lazy, expected = pairs_cases(clustered, 70, 56, PAIR_CASES)
    # The scenes are dense enough for many pairs across tile borders.
    assert check_pairs(dask.compute(*lazy, scheduler="sync"), expected) > 300


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.parametrize("clustered", [False, True])
def test_pairs_within_on_the_cluster(client, clustered):
    lazy, expected = pairs_cases(clustered, 200, 150, [("Circle", "Segment"), ("Line", "Disk")])
    assert check_pairs(dask.compute(*lazy), expected) > 200


@pytest.mark.slow
@pytest.mark.serial
def test_pairs_within_a_batch_shape_and_empty_batches(client):
    rng = np.random.default_rng(13)
    rings = random_batch("Circle", 24, rng)
    arrays = {
        n: (v.reshape((4, 6) + v.shape[1:]) if v.ndim and v.shape[0] == 24 else v) for n, v in rings.to_arrays().items()
    }
    grid_rings = cd.Circle.from_arrays(arrays)
    points = rng.uniform(-4, 4, (40, 3))
    got = dask.compute(*cdd.pairs_within(grid_rings, da.from_array(points, chunks=(9, 3)), 1.0))
    for g, e in zip(got, cd.pairs_within(grid_rings, points, 1.0)):
        same(g, e)
    none = cd.Point(np.zeros((0, 3)))
    for g, e in zip(dask.compute(*cdd.pairs_within(none, rings, 1.0)), cd.pairs_within(none, rings, 1.0)):
        same(g, e)
    for g, e in zip(dask.compute(*cdd.pairs_within(rings, none, 1.0)), cd.pairs_within(rings, none, 1.0)):
        same(g, e)


def test_circledist_does_not_import_dask_and_the_error_without_it_is_clear():
    run = subprocess.run(
        [sys.executable, "-c", "import sys, circledist; assert 'dask' not in sys.modules"],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    # sys.modules[name] = None makes that import fail, as an environment without dask would.
    run = subprocess.run(
        [sys.executable, "-c", "import sys; sys.modules['dask'] = None; import circledist.dask"],
        capture_output=True,
        text=True,
    )
    assert "circledist.dask needs dask: pip install 'circledist[dask]'" in run.stderr


BATCH_KEYS = [
    0,
    -1,
    2,
    slice(1, 3),
    slice(None, None, -2),
    (1, 2),
    (slice(None), 3),
    (-2, slice(1, None)),
    (Ellipsis, 1),
    (1, Ellipsis),
    (Ellipsis,),
    (),
    np.int64(1),
    (slice(0, 0),),
]


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.parametrize("key", BATCH_KEYS, ids=repr)
def test_indexing_a_batch_is_numpy_indexing_of_its_broadcast_fields(client, key):
    """A (3, 4) batch whose fields have batch shapes (3, 4), (3, 1) and (4,), chunked: indexed,
    it is the circledist shape of the NumPy-indexed broadcast fields (dtypes kept), and answers
    queries on the cluster as that shape does."""
    rng = np.random.default_rng(5)
    center = rng.normal(size=(3, 4, 3))
    normal = rng.normal(size=(3, 1, 3)).astype(np.float32)
    radius = rng.uniform(0.5, 2, 4)
    lazy = cdd.Circle(
        da.from_array(center, chunks=(2, 3, 3)),
        da.from_array(normal, chunks=(1, 1, 3)),
        da.from_array(radius, chunks=2),
        sweep=0.25,
    )
    assert lazy.batch_shape == (3, 4) and len(lazy) == 3
    # Which elements, by NumPy on an array of the batch's shape; then those rows of each field.
    taken = np.arange(12).reshape(3, 4)[key]
    fields = {
        "center": np.broadcast_to(center, (3, 4, 3)).reshape(12, 3)[taken],
        "normal": np.broadcast_to(normal, (3, 4, 3)).reshape(12, 3)[taken],
        "radius": np.broadcast_to(radius, (3, 4)).reshape(12)[taken],
        "sweep": np.full(12, 0.25)[taken],
    }
    part = lazy[key]
    assert isinstance(part, cdd.Circle) and part.batch_shape == fields["radius"].shape
    got = part.compute().to_arrays()
    assert sorted(got) == sorted(fields)
    for name, value in fields.items():
        same(got[name], value)
    expected = cd.Circle(fields["center"], fields["normal"], fields["radius"], sweep=fields["sweep"])
    probe = cd.Point([0.5, -0.25, 1.0])
    same(cdd.distance(part, probe).compute(), cd.distance(expected, probe))


def test_indexing_refuses_what_is_not_basic_indexing():
    rings = cdd.Circle(np.zeros((4, 3)), [0, 0, 1], np.arange(1.0, 5.0))
    assert len(rings) == 4 and len(rings[1:]) == 3 and rings[2].batch_shape == ()
    with pytest.raises(IndexError, match="too many indices for a batch of 1 dimension"):
        rings[0, 0]
    with pytest.raises(IndexError):
        rings[4].compute()
    with pytest.raises(IndexError, match="single ellipsis"):
        rings[..., ...]
    for key in ([0, 1], np.array([0, 1]), np.array([True, False, True, True]), True, 1.0, "a"):
        with pytest.raises(TypeError, match="only integers, slices and ... index a batch"):
            rings[key]
    for key in (None, (slice(None), None), (None, 0)):
        with pytest.raises(TypeError, match=r"None \(numpy.newaxis\) is not supported in a batch index"):
            rings[key]
    with pytest.raises(TypeError, match=r"len\(\) of a single Circle"):
        len(rings[0])


# ---- bad input: circledist's own errors, word for word, naming the element of the whole batch --


def _message(call):
    with pytest.raises((ValueError, TypeError, OverflowError)) as error:
        call()
    return type(error.value), str(error.value)


def _spoilt(batch, where, field, value):
    """Circle fields (centers on a grid, radius 0.1) of batch shape `batch`, field[where] = value."""
    n = int(np.prod(batch))
    fields = {
        "center": np.stack([np.arange(n) * 3.0, np.zeros(n), np.zeros(n)], axis=-1).reshape(batch + (3,)),
        "normal": np.tile([0.0, 0.0, 1.0], (n, 1)).reshape(batch + (3,)),
        "radius": np.full(batch, 0.1),
    }
    fields[field] = fields[field].copy()
    fields[field][where] = value
    return fields


BAD_ELEMENTS = [
    ((20000,), (12345,), "center", np.nan, {0: 10000}),
    ((20000,), (12345,), "normal", 0.0, {0: 7000}),
    ((20000,), (19999,), "radius", -1.0, {0: 6000}),
    ((30, 40), (17, 29), "center", np.inf, {0: 7, 1: 15}),
    ((30, 40), (3, 38), "radius", -2.0, {0: 11, 1: 9}),
]


@pytest.mark.parametrize(
    "batch, where, field, value, chunks",
    BAD_ELEMENTS,
    ids=[f"{f}-{'x'.join(map(str, b))}" for b, _, f, _, _ in BAD_ELEMENTS],
)
@pytest.mark.parametrize("call", ["distance", "within", "closest_points", "pairs_within-a", "pairs_within-b"])
def test_bad_elements_are_named_as_circledist_names_them(batch, where, field, value, chunks, call):
    """A NaN, a zero normal or a negative radius deep in a chunked batch: the error is the one
    circledist raises for the whole batch (same type and words, the element's index in the whole
    batch, not within its chunk), from every call, pairs_within's tiling included."""
    fields = _spoilt(batch, where, field, value)
    expected = _message(lambda: cd.Circle(*fields.values()))
    assert f"{field}[{', '.join(map(str, where))}]" in expected[1]
    lazy = cdd.Circle(
        *[
            da.from_array(v, chunks={**chunks, **({v.ndim - 1: -1} if v.ndim > len(batch) else {})})
            for v in fields.values()
        ]
    )
    other = cdd.Point(np.zeros(batch + (3,)))
    run = {
        "distance": lambda: cdd.distance(lazy, other).compute(scheduler="sync"),
        "within": lambda: cdd.within(other, lazy, 0.5).compute(scheduler="sync"),
        "closest_points": lambda: cdd.closest_points(lazy, other).distance.compute(scheduler="sync"),
        "pairs_within-a": lambda: dask.compute(*cdd.pairs_within(lazy, other, 0.5), scheduler="sync"),
        "pairs_within-b": lambda: dask.compute(*cdd.pairs_within(other, lazy, 0.5), scheduler="sync"),
    }[call]
    assert _message(run) == expected


@pytest.mark.parametrize(
    "d",
    ["0.3", b"0.3", True, None, -1.0, float("nan"), float("inf"), [0.3]],
    ids=["str", "bytes", "bool", "none", "negative", "nan", "inf", "list"],
)
def test_pairs_within_checks_d_as_circledist_does(d):
    points = np.zeros((5, 3))
    expected = _message(lambda: cd.pairs_within(cd.Point(points), cd.Point(points), d))
    assert _message(lambda: cdd.pairs_within(cdd.Point(points), cdd.Point(points), d)) == expected


@pytest.mark.parametrize(
    "tiles, kind, words",
    [
        (-5, ValueError, "-5"),
        (0, ValueError, "0"),
        (2.5, TypeError, "2.5"),
        (True, TypeError, "True"),
        ("4", TypeError, "'4'"),
        (float("nan"), TypeError, "nan"),
    ],
)
def test_pairs_within_tiles_must_be_a_positive_integer(tiles, kind, words):
    points = cdd.Point(np.zeros((5, 3)))
    with pytest.raises(kind) as error:
        cdd.pairs_within(points, points, 0.1, tiles=tiles)
    assert str(error.value) == f"pairs_within: tiles must be an integer >= 1, got {words}"
    i, j, _ = dask.compute(*cdd.pairs_within(points, points, 0.1, tiles=np.int64(3)), scheduler="sync")
    assert len(i) == 25


@pytest.mark.parametrize(
    "batch, where, chunks", [((20000,), (12345,), {0: 5000}), ((30, 40), (17, 29), {0: 7, 1: 15})], ids=["1d", "2d"]
)
@pytest.mark.parametrize("bad", ["negative d", "nan d", "float32 overflow"])
def test_errors_of_the_calls_name_the_whole_batch_index(batch, where, chunks, bad):
    """Errors the calls themselves raise (within's d, an answer beyond float32's range) name the
    element as circledist does for the whole batch, not its index within the chunk."""
    points = np.zeros(batch + (3,))
    others = np.zeros(batch + (3,))
    d = np.full(batch, 0.5)
    if bad == "float32 overflow":
        points[where] = [3e38, 0, 0]
        others[where] = [-3e38, 0, 0]
        expected = _message(lambda: cd.distance(cd.Point(points), cd.Point(others), precision="float32"))
        lazy = cdd.distance(
            cdd.Point(da.from_array(points, chunks={**chunks, len(batch): -1})),
            cdd.Point(da.from_array(others, chunks={**chunks, len(batch): -1})),
            precision="float32",
        )
    else:
        d[where] = -1.0 if bad == "negative d" else np.nan
        expected = _message(lambda: cd.within(cd.Point(points), cd.Point(others), d))
        lazy = cdd.within(cdd.Point(points), cdd.Point(others), da.from_array(d, chunks=chunks))
    assert f"[{', '.join(map(str, where))}]" in expected[1]
    assert _message(lambda: lazy.compute(scheduler="sync")) == expected


# More tiles than a has elements are empty tiles: the count is capped at one per element, so a
# huge tiles= neither allocates per-tile arrays of that size (tiles=2**62 grew 400 MB and raised
# MemoryError) nor changes the answers.
@pytest.mark.parametrize("d", [0.0, 1e-9, 0.3])
@pytest.mark.parametrize("tiles", [41, 10**6, 2**62])
def test_pairs_within_with_more_tiles_than_shapes_stays_small(tiles, d):
    import tracemalloc

    rng = np.random.default_rng(17)
    a, b = rng.uniform(-1, 1, (40, 3)), cd.Point(rng.uniform(-1, 1, (30, 3)))
    tracemalloc.start()
    try:
        got = dask.compute(*cdd.pairs_within(da.from_array(a, chunks=(7, 3)), b, d, tiles=tiles), scheduler="sync")
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 16 << 20, f"{peak / 2**20:.0f} MiB at the peak"
    for g, e in zip(got, cd.pairs_within(cd.Point(a), b, d)):
        same(g, e)
