"""circledist.pairs_within and circledist.nearest against brute force: a double loop over single
`circledist.distance` calls (or, for the larger sets, the full matrix of distances), compared to
the bit: the same pairs, the same order, the same distances and dtypes. Every kind pair (swept
shapes, lines and rays among them), batch shapes indexed flat, empty batches, k larger than b,
d = 0 with touching shapes, duplicates, every worker count, precisions, and bad arguments."""

import itertools
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import circledist as cd
from circledist_cases.batches import SUPPORTED, TRAILING, random_batch

KINDS = list(cd._core._shape_fields())  # every kind, Arc included


def size(shape):
    return int(np.prod(shape.batch_shape, dtype=np.int64))


def elements(shape):
    """The single shapes of a batch, in flat C order (fields broadcast within the shape first)."""
    arrays = shape.to_arrays()
    batch = shape.batch_shape
    flat = {}
    for name, value in arrays.items():
        trailing = value.shape[value.ndim - TRAILING[name] :] if TRAILING[name] else ()
        flat[name] = np.broadcast_to(value, batch + trailing).reshape((-1,) + trailing)
    return [type(shape).from_arrays({name: v[i] for name, v in flat.items()}) for i in range(size(shape))]


def brute_pairs(a, b, d, **options):
    """(i, j, distance) of every pair with distance(a[i], b[j]) <= d, by single calls."""
    ea = elements(a)
    eb = ea if b is None else elements(b)
    found = []
    for i, x in enumerate(ea):
        for j, y in enumerate(eb):
            if b is None and j <= i:
                continue
            dist = cd.distance(x, y, **options)
            if dist <= d:
                found.append((i, j, dist))
    return found


def brute_nearest(a, b, k, **options):
    rows = []
    for x in elements(a):
        found = sorted((cd.distance(x, y, **options), j) for j, y in enumerate(elements(b)))[:k]
        rows.append(found + [(np.inf, -1)] * (k - len(found)))
    return rows


def assert_pairs(got, expected, dtype=np.float64):
    i, j, dist = got
    assert i.dtype == np.intp and j.dtype == np.intp and dist.dtype == dtype
    assert i.shape == j.shape == dist.shape == (len(expected),)
    assert list(zip(i.tolist(), j.tolist())) == [(e[0], e[1]) for e in expected]
    # To the bit: the single calls' floats (or long doubles) are the pairs' distances.
    assert np.array_equal(dist, np.array([e[2] for e in expected], dtype=dtype))


def assert_nearest(got, expected, dtype=np.float64):
    idx, dist = got
    k = len(expected[0]) if expected else idx.shape[1]
    assert idx.shape == dist.shape == (len(expected), k)
    assert idx.dtype == np.intp and dist.dtype == dtype
    assert idx.tolist() == [[j for _, j in row] for row in expected]
    assert np.array_equal(dist, np.array([[v for v, _ in row] for row in expected], dtype=dtype).reshape(dist.shape))


@pytest.mark.parametrize("ka,kb", [p for p in itertools.product(KINDS, KINDS) if p in SUPPORTED])
def test_every_kind_pair_equals_brute_force(ka, kb):
    rng = np.random.default_rng(abs(hash((ka, kb))) % 2**32)
    a, b = random_batch(ka, 14, rng), random_batch(kb, 12, rng)
    for d in (0.0, 0.5, 2.0):
        assert_pairs(cd.pairs_within(a, b, d), brute_pairs(a, b, d))
    assert_nearest(cd.nearest(a, b, k=3), brute_nearest(a, b, 3))
    if ka == kb:
        assert_pairs(cd.pairs_within(a, None, 1.0), brute_pairs(a, None, 1.0))


def test_every_kind_pair_has_a_query():
    """The kind matrix is complete: every pair of kinds, in both orders, has a query
    (the all-pairs test above runs each against brute force). A new kind must bring its pairs."""
    assert SUPPORTED == set(itertools.product(KINDS, KINDS)), sorted(set(itertools.product(KINDS, KINDS)) - SUPPORTED)


def column(shape):
    """A batch of shape (n,) made (n, 1), to broadcast against another batch into a matrix."""
    return type(shape).from_arrays(
        {k: np.expand_dims(v, 1) if v.ndim > TRAILING[k] else v for k, v in shape.to_arrays().items()}
    )


def test_larger_mixed_sets_equal_the_distance_matrix():
    """Rings against segments, lines, rays, disks and points, swept, in a box where pairs are
    neither rare nor everywhere: pairs and nearest equal the full distance matrix's."""
    rng = np.random.default_rng(7)
    rings = random_batch("Circle", 500, rng, box=10.0)
    for kind in ("Segment", "Line", "Ray", "Disk", "Point"):
        other = random_batch(kind, 300, rng, box=10.0)
        matrix = cd.distance(column(rings), other)  # rows: rings
        for d in (0.0, 0.3, 1.0):
            i, j = np.nonzero(matrix <= d)
            i_got, j_got, dist = cd.pairs_within(rings, other, d)
            assert np.array_equal(i_got, i) and np.array_equal(j_got, j)
            assert np.array_equal(dist, matrix[i, j])
        idx, dist = cd.nearest(rings, other, k=4)
        order = np.lexsort((np.broadcast_to(np.arange(300), matrix.shape), matrix), axis=1)[:, :4]
        assert np.array_equal(idx, order)
        assert np.array_equal(dist, np.take_along_axis(matrix, order, axis=1))
    # Within one set, i < j.
    matrix = cd.distance(column(rings), rings)
    for d in (0.0, 0.4):
        i, j = np.nonzero(np.triu(matrix <= d, k=1))
        i_got, j_got, dist = cd.pairs_within(rings, None, d)
        assert len(i) > 0 or d == 0.0
        assert np.array_equal(i_got, i) and np.array_equal(j_got, j)
        assert np.array_equal(dist, matrix[i, j])


def test_batches_are_indexed_flat():
    rng = np.random.default_rng(3)
    centers = rng.uniform(-3, 3, (3, 4, 3))
    rings = cd.Circle(centers, [0, 0, 1], 1.0, sweep=[[0.0], [0.1], [0.2]])  # radius and sweep broadcast
    points = cd.Point(rng.uniform(-3, 3, (2, 5, 3)))
    assert_pairs(cd.pairs_within(rings, points, 0.7), brute_pairs(rings, points, 0.7))
    assert_pairs(cd.pairs_within(rings, None, 0.5), brute_pairs(rings, None, 0.5))
    assert_nearest(cd.nearest(points, rings, k=2), brute_nearest(points, rings, 2))
    # Single shapes are batches of one; arrays of points are Points.
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    assert_pairs(cd.pairs_within(ring, [[1, 0, 0.5], [5, 0, 0]], 0.5), [(0, 0, 0.5)])
    assert_pairs(cd.pairs_within(ring, ring, 0.0), [(0, 0, 0.0)])
    assert_nearest(cd.nearest([0, 0, 3], ring, k=2), [[(cd.distance([0, 0, 3], ring), 0), (np.inf, -1)]])


def test_empty_batches_and_k_beyond_b():
    rng = np.random.default_rng(4)
    none = cd.Point(np.zeros((0, 3)))
    some = random_batch("Circle", 5, rng)
    for got in (cd.pairs_within(none, some, 1.0), cd.pairs_within(some, none, 1.0), cd.pairs_within(none, None, 1.0)):
        assert_pairs(got, [])
    idx, dist = cd.nearest(none, some, k=3)
    assert idx.shape == dist.shape == (0, 3)
    idx, dist = cd.nearest(some, none, k=2)
    assert idx.tolist() == [[-1, -1]] * 5 and np.all(np.isinf(dist))
    # k larger than b: every shape of b, then -1 and inf (as cKDTree pads with len(b) and inf).
    assert_nearest(cd.nearest(some, some, k=8), brute_nearest(some, some, 8))
    assert cd.pairs_within(random_batch("Segment", 1, rng), None, 5.0)[0].shape == (0,)


# Every k answers or refuses: (n, k) answers of n * k * 16 bytes beyond 64 bits (n * k wrapped
# to a small count and the answers were written past their end), or beyond what an address space
# holds (2**44 columns of 4 queries: 2**50 bytes), are a MemoryError naming k; so is a row too
# large for NumPy's shapes with no query. Run in a child process, so that a regression fails the
# test instead of taking pytest down.
@pytest.mark.parametrize(
    "n, k", [(4, 2**62), (8, 2**61), (3, 2**63 - 1), (2, 2**59 + 1), (4, 2**44), (1, 2**60), (0, 2**62), (0, 2**63 - 1)]
)
def test_nearest_k_whose_answers_cannot_exist_is_a_memory_error(n, k):
    code = textwrap.dedent(f"""
        import numpy as np, circledist as cd
        a, b = cd.Point(np.zeros(({n}, 3))), cd.Point(np.arange(30.0).reshape(10, 3))
        try:
            cd.nearest(a, b, {k})
        except MemoryError as e:
            print("MemoryError", e)
    """)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.startswith(f"MemoryError nearest: k={k} asks for answers of shape ({n}, {k})"), proc.stdout


@pytest.mark.parametrize("k", [11, 1000, 2**20])
def test_nearest_k_beyond_b_pads_every_column(k):
    rng = np.random.default_rng(6)
    a, b = random_batch("Segment", 3, rng), random_batch("Circle", 10, rng)
    idx, dist = cd.nearest(a, b, k)
    assert idx.shape == dist.shape == (3, k)
    head = cd.nearest(a, b, 10)
    np.testing.assert_array_equal(idx[:, :10], head[0])
    np.testing.assert_array_equal(dist[:, :10], head[1])
    assert np.all(idx[:, 10:] == -1) and np.all(np.isinf(dist[:, 10:]))


# Coincident shapes tie at every bound and at distance 0: the answers are the k smallest (0,
# index), and the search among them must not make every pair a candidate (it once held n^2 pairs
# and ran seconds before its first progress call). Sets where each shape appears many times
# (several kinds, both orders, swept ones) against brute force; then 40,000 coincident points,
# whose k nearest are found in well under a second.
@pytest.mark.parametrize("kind", ["Point", "Segment", "Circle", "Disk", "Arc", "Annulus", "Bezier"])
@pytest.mark.parametrize("copies", [1, 7, 40])
def test_nearest_among_coincident_shapes_equals_brute_force(kind, copies):
    rng = np.random.default_rng(len(kind) * 100 + copies)
    few = random_batch(kind, max(1, 40 // copies), rng)
    arrays = few.to_arrays()
    many = type(few).from_arrays(
        {name: np.repeat(np.asarray(v), copies, axis=0) if np.ndim(v) else v for name, v in arrays.items()}
    )
    mixed = random_batch("Point", 5, rng)
    for a, b in ((many, many), (mixed, many), (many, few)):
        for k in (1, 3, copies + 2):
            assert_nearest(cd.nearest(a, b, k=k), brute_nearest(a, b, k))


def test_nearest_among_coincident_points_is_fast_and_reports_progress():
    import time

    a = cd.Point(np.zeros((40_000, 3)))
    calls = []
    start = time.perf_counter()
    idx, dist = cd.nearest(a, a, k=2, progress=lambda done, total: calls.append((done, total)))
    assert time.perf_counter() - start < 1.0
    assert np.all(dist == 0) and np.all(idx == [0, 1])
    assert calls and calls[-1][0] == calls[-1][1]


@pytest.mark.parametrize("k", [2**40, 2**58])
def test_nearest_of_no_queries_takes_a_k_numpy_can_shape(k):
    idx, dist = cd.nearest(cd.Point(np.zeros((0, 3))), cd.Point(np.zeros((5, 3))), k)
    assert idx.shape == dist.shape == (0, k)


@pytest.mark.parametrize("k", [2**62, 2**63 - 1])
def test_scene_nearest_with_a_huge_k_gives_every_shape(k):
    s = cd.Scene()
    s.extend("p", cd.Point(np.arange(30.0).reshape(10, 3)))
    got = s.nearest([0, 0, 0], k=k)
    assert [name for name, _ in got] == [f"p{i}" for i in range(10)]


def test_touching_shapes_at_d_zero():
    balls = cd.Point([[0, 0, 0], [1, 0, 0], [2.5, 0, 0]], sweep=0.5)  # 0-1 touch, 1-2 do not
    assert_pairs(cd.pairs_within(balls, None, 0.0), [(0, 1, 0.0)])
    segments = cd.Segment([[0, 0, 0], [1, 0, 0], [5, 5, 5]], [[1, 0, 0], [2, 1, 0], [6, 5, 5]])
    assert_pairs(cd.pairs_within(segments, None, 0.0), brute_pairs(segments, None, 0.0))
    assert [tuple(p) for p in zip(*cd.pairs_within(segments, None, 0.0)[:2])] == [(0, 1)]
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    on_ring = cd.Point([[1, 0, 0], [0, -1, 0], [0, 0, 0]])
    assert_pairs(cd.pairs_within(on_ring, ring, 0.0), brute_pairs(on_ring, ring, 0.0))
    disks = cd.Disk([[0, 0, 0], [2, 0, 0]], [[0, 0, 1], [0, 0, 1]], 1.0)  # rims touch at (1, 0, 0)
    assert_pairs(cd.pairs_within(disks, None, 0.0), brute_pairs(disks, None, 0.0))
    assert len(cd.pairs_within(disks, None, 0.0)[0]) == 1


def test_duplicates_and_one_spot():
    rng = np.random.default_rng(5)
    base = random_batch("Disk", 6, rng)
    arrays = {k: np.concatenate([v] * 4) for k, v in base.to_arrays().items()}
    dup = cd.Disk.from_arrays(arrays)
    assert_pairs(cd.pairs_within(dup, None, 0.0), brute_pairs(dup, None, 0.0))
    assert_nearest(cd.nearest(base, dup, k=5), brute_nearest(base, dup, 5))
    spot = cd.Point(np.full((40, 3), 1.25))
    i, j, dist = cd.pairs_within(spot, None, 0.0)
    assert len(i) == 40 * 39 // 2 and np.all(dist == 0) and np.all(i < j)
    idx, dist = cd.nearest(spot, spot, k=3)
    assert idx.tolist() == [[0, 1, 2]] * 40 and np.all(dist == 0)


def test_every_worker_count_gives_the_same_bits():
    rng = np.random.default_rng(6)
    rings = random_batch("Circle", 3000, rng, box=12.0)
    segments = random_batch("Segment", 3000, rng, box=12.0)
    lines = random_batch("Line", 20, rng, box=12.0)
    counts = (1, 2, 3, 7, -1)
    results = [cd.pairs_within(rings, segments, 0.2, workers=w) for w in counts]
    selfs = [cd.pairs_within(rings, None, 0.1, workers=w) for w in counts]
    nears = [cd.nearest(segments, rings, k=3, workers=w) for w in counts]
    liness = [cd.pairs_within(lines, rings, 0.05, workers=w) for w in counts]
    for group in (results, selfs, nears, liness):
        for other in group[1:]:
            for x, y in zip(group[0], other):
                assert x.dtype == y.dtype and np.array_equal(x, y)
    assert len(results[0][0]) > 100 and len(liness[0][0]) > 10
    with pytest.raises(ValueError, match="workers must be a positive integer or -1"):
        cd.pairs_within(rings, segments, 0.2, workers=0)


@pytest.mark.parametrize(
    "precision,dtype", [("float32", np.float32), ("longdouble", np.longdouble), ("float64", np.float64)]
)
def test_precisions_equal_brute_force(precision, dtype):
    rng = np.random.default_rng(8)
    a, b = random_batch("Circle", 12, rng), random_batch("Segment", 12, rng)
    assert_pairs(cd.pairs_within(a, b, 1.0, precision=precision), brute_pairs(a, b, 1.0, precision=precision), dtype)
    assert_nearest(cd.nearest(a, b, 3, precision=precision), brute_nearest(a, b, 3, precision=precision), dtype)
    for solver in ("companion", "polished"):
        assert_pairs(
            cd.pairs_within(a, b, 1.0, precision=precision, solver=solver),
            brute_pairs(a, b, 1.0, precision=precision, solver=solver),
            dtype,
        )
    # Inputs given as float32 (precision=None follows them) and as long double.
    a32 = cd.Circle.from_arrays({k: np.asarray(v, np.float32) for k, v in a.to_arrays().items()})
    assert_pairs(
        cd.pairs_within(a32, b.to_arrays()["p0"].astype(np.float32), 1.5),
        brute_pairs(a32, cd.Point(b.to_arrays()["p0"].astype(np.float32)), 1.5),
        np.float32,
    )
    along = cd.Circle.from_arrays({k: np.asarray(v, np.longdouble) for k, v in a.to_arrays().items()})
    assert_pairs(cd.pairs_within(along, b, 1.0), brute_pairs(along, b, 1.0), np.longdouble)


@pytest.mark.parametrize(
    "d,error,match",
    [
        (-1.0, ValueError, "pairs_within: d must be a finite number >= 0, got -1.0"),
        (float("nan"), ValueError, "pairs_within: d must be a finite number >= 0, got nan"),
        (float("inf"), ValueError, "pairs_within: d must be a finite number >= 0, got inf"),
        ("0.1", TypeError, "pairs_within: d must be a real number >= 0, got '0.1'"),
        (None, TypeError, "pairs_within: d must be a real number >= 0, got None"),
        (True, TypeError, "pairs_within: d must be a real number >= 0, got True"),
        (np.array([0.1, 0.2]), TypeError, "pairs_within: d must be a real number"),
    ],
)
def test_bad_d(d, error, match):
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    with pytest.raises(error, match=match.replace("(", r"\(").replace(")", r"\)")):
        cd.pairs_within(ring, ring, d)


@pytest.mark.parametrize(
    "k,error,match",
    [
        (0, ValueError, "nearest: k must be an integer >= 1, got 0"),
        (-2, ValueError, "nearest: k must be an integer >= 1, got -2"),
        (1.5, TypeError, "nearest: k must be an integer >= 1, got 1.5"),
        ("2", TypeError, "nearest: k must be an integer >= 1, got '2'"),
        (True, TypeError, "nearest: k must be an integer >= 1, got True"),
    ],
)
def test_bad_k(k, error, match):
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    with pytest.raises(error, match=match):
        cd.nearest(ring, ring, k)


def test_numpy_integers_and_reals_are_accepted():
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    assert cd.nearest(ring, ring, np.int64(2))[0].shape == (1, 2)
    assert len(cd.pairs_within(ring, ring, np.float32(0.5))[0]) == 1


def test_bad_shapes_name_the_argument():
    """As distance(): what is not a shape is read as points, and a ValueError when it is not."""
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    with pytest.raises(ValueError, match="pairs_within: b must be a circledist shape or an array of points, got str"):
        cd.pairs_within(ring, "ring", 1.0)
    with pytest.raises(ValueError, match="pairs_within: a must be a circledist shape or an array of points"):
        cd.pairs_within([1, 2], ring, 1.0)
    with pytest.raises(ValueError, match="nearest: b must be a circledist shape or an array of points, got object"):
        cd.nearest(ring, object())
    with pytest.raises(ValueError, match="nearest: a must be"):
        cd.nearest(None, ring)


def test_culled_pairs_are_counted():
    rng = np.random.default_rng(9)
    a = random_batch("Point", 200, rng, box=50.0)
    cd.reset_stats()
    i, _, _ = cd.pairs_within(a, None, 0.5)
    s = cd.stats()
    # Every pair is either evaluated or culled.
    assert s["distances"] + s["culled"] == 200 * 199 // 2
    assert s["culled"] > 19000


@pytest.mark.parametrize("scale,offset", [(1e-6, 0.0), (1e6, 0.0), (1e-3, 1e6), (1.0, -1e8)])
def test_scaled_and_far_scenes_equal_the_distance_matrix(scale, offset):
    """The culling margin follows the scene's size and its distance from the origin: tiny,
    huge and far-off scenes (lines among them) give the full matrix's pairs and nearest."""
    rng = np.random.default_rng(10)

    def moved(shape):
        arrays = shape.to_arrays()
        for key in ("p", "p0", "p1", "center", "origin", "control_points"):
            if key in arrays:
                arrays[key] = arrays[key] * scale + offset
        for key in ("radius", "sweep"):
            if key in arrays:
                arrays[key] = arrays[key] * scale
        return type(shape).from_arrays(arrays)

    a = moved(random_batch("Disk", 150, rng, box=6.0))
    for kind in ("Segment", "Line", "Circle"):
        b = moved(random_batch(kind, 120, rng, box=6.0))
        matrix = cd.distance(column(a), b)
        for d in (0.0, 0.2 * scale, scale):
            i, j = np.nonzero(matrix <= d)
            i_got, j_got, dist = cd.pairs_within(a, b, d)
            assert np.array_equal(i_got, i) and np.array_equal(j_got, j)
            assert np.array_equal(dist, matrix[i, j])
        idx, dist = cd.nearest(a, b, k=2)
        order = np.lexsort((np.broadcast_to(np.arange(matrix.shape[1]), matrix.shape), matrix), axis=1)[:, :2]
        assert np.array_equal(idx, order) and np.array_equal(dist, np.take_along_axis(matrix, order, axis=1))


def _tested(call, total):
    """How many pairs a call tested exactly: total less the pairs it counted as culled."""
    cd.reset_stats()
    answer = call()
    return answer, total - cd.stats()["culled"]


OUTLIERS = {  # one ring of the set made far or huge (the others within a box of 20)
    "far": dict(center=[1e12, 0.0, 0.0]),
    "far_diagonal": dict(center=[-3e11, 2e11, 5e10]),
    "huge": dict(radius=1e9),
    "far_and_huge": dict(center=[0.0, 4e12, 0.0], radius=1e9),
}


@pytest.mark.parametrize("outlier", list(OUTLIERS))
def test_one_far_or_huge_shape_costs_only_its_own_pairs(outlier):
    """The culling margin is each pair's own (from its two shapes' reach from the origin): one
    ring moved to 1e12 or grown to a radius of 1e9 adds at most its own pairs to the exact tests
    of pairs_within (one set, two sets), nearest and the Scene's queries (counted by cd.stats()
    and last_stats), where a margin of the whole set's extent tested every pair; the answers
    stay the distance matrix's."""
    rng = np.random.default_rng(21)
    n, m, d = 400, 150, 0.05
    fields = dict(center=rng.uniform(-10, 10, (n, 3)), normal=rng.normal(size=(n, 3)), radius=rng.uniform(0.2, 1.0, n))
    plain = cd.Circle(**fields)
    for key, value in OUTLIERS[outlier].items():
        fields[key] = fields[key].copy()
        fields[key][17] = value
    rings = cd.Circle(**fields)
    points = cd.Point(rng.uniform(-10, 10, (m, 3)))
    matrix = cd.distance(column(rings), rings)
    cross = cd.distance(column(points), rings)

    (i, j, dist), tested = _tested(lambda: cd.pairs_within(rings, None, d), n * (n - 1) // 2)
    _, base = _tested(lambda: cd.pairs_within(plain, None, d), n * (n - 1) // 2)
    ei, ej = np.nonzero(np.triu(matrix <= d, 1))
    assert np.array_equal(i, ei) and np.array_equal(j, ej) and np.array_equal(dist, matrix[ei, ej])
    assert tested <= base + n - 1, (tested, base)

    (i, j, dist), tested = _tested(lambda: cd.pairs_within(points, rings, 1.0), m * n)
    _, base = _tested(lambda: cd.pairs_within(points, plain, 1.0), m * n)
    ei, ej = np.nonzero(cross <= 1.0)
    assert np.array_equal(i, ei) and np.array_equal(j, ej) and np.array_equal(dist, cross[ei, ej])
    assert tested <= base + m, (tested, base)

    (idx, dist), tested = _tested(lambda: cd.nearest(points, rings, k=2), m * n)
    _, base = _tested(lambda: cd.nearest(points, plain, k=2), m * n)
    order = np.lexsort((np.broadcast_to(np.arange(n), cross.shape), cross), axis=1)[:, :2]
    assert np.array_equal(idx, order) and np.array_equal(dist, np.take_along_axis(cross, order, axis=1))
    assert tested <= base + m, (tested, base)

    names = [f"r{k}" for k in range(n)]
    scene, plain_scene = cd.Scene(), cd.Scene()
    scene.extend(names, rings)
    plain_scene.extend(names, plain)
    assert scene.pairs_within(d) == [(names[a], names[b]) for a, b in zip(*np.nonzero(np.triu(matrix <= d, 1)))]
    plain_scene.pairs_within(d)
    assert scene.last_stats["tested"] <= plain_scene.last_stats["tested"] + n - 1
    line = cd.Line([-10, 0.5, 0.3], [1, 0.2, 0.1])
    to_line = np.asarray(cd.distance(line, rings))
    order = np.lexsort((np.arange(n), to_line))[:3]
    assert scene.nearest(line, k=3) == [(names[k], to_line[k]) for k in order]
    plain_scene.nearest(line, k=3)
    assert scene.last_stats["tested"] <= plain_scene.last_stats["tested"] + 1
    probe = cd.Point([1.0, 2.0, 0.5])
    to_probe = np.asarray(cd.distance(probe, rings))
    assert scene.within(probe, 1.0) == [names[k] for k in np.flatnonzero(to_probe <= 1.0)]
    plain_scene.within(probe, 1.0)
    assert scene.last_stats["tested"] <= plain_scene.last_stats["tested"] + 1


def test_max_pairs_refuses_a_d_that_pairs_nearly_everything():
    """Candidates are counted while they are found: past max_pairs the search stops and a
    MemoryError names the limit (one set, two sets, a Scene), instead of storing them all; at
    the limit, or with None, every pair comes back. 20,000 points within d of each other (2e8
    pairs, 3 GB of candidates) are refused without the memory growing."""
    import resource

    rng = np.random.default_rng(30)
    points = cd.Point(rng.uniform(0, 1, (300, 3)))
    total = 300 * 299 // 2
    message = r"pairs_within: more than max_pairs=1,000 candidate pairs to test"
    with pytest.raises(MemoryError, match=message):
        cd.pairs_within(points, None, 10.0, max_pairs=1000)
    with pytest.raises(MemoryError, match=message):
        cd.pairs_within(points, points, 10.0, max_pairs=1000, workers=2)
    for most in (total, None):
        i, j, _ = cd.pairs_within(points, None, 10.0, max_pairs=most)
        assert len(i) == total
    assert len(cd.pairs_within(points, points, 10.0, max_pairs=300 * 300)[0]) == 300 * 300
    scene = cd.Scene()
    scene.extend("p", points)
    with pytest.raises(MemoryError, match="Scene.pairs_within: more than max_pairs=1,000 candidate pairs"):
        scene.pairs_within(10.0, max_pairs=1000)
    assert len(scene.pairs_within(10.0, max_pairs=total)) == total
    for bad, error in ((-1, ValueError), (1.5, TypeError), (True, TypeError), ("10", TypeError)):
        with pytest.raises(error, match="max_pairs must be an integer >= 0 or None"):
            cd.pairs_within(points, None, 1.0, max_pairs=bad)
        with pytest.raises(error, match="max_pairs must be an integer >= 0 or None"):
            scene.pairs_within(1.0, max_pairs=bad)

    crowd = cd.Point(rng.uniform(0, 1, (20_000, 3)))
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB on Linux
    with pytest.raises(MemoryError, match=r"more than max_pairs=1,000,000 candidate pairs"):
        cd.pairs_within(crowd, None, 10.0, max_pairs=1_000_000, workers=2)
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 300_000
