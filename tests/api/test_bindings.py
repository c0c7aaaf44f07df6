"""How the module dispatches a query, checked on every pair of kinds, solver and precision.

* both argument orders run one compiled query: distance, within and distance_if_within agree to
  the bit, and closest_points gives the same answer with the points and parameters exchanged;
* float32 is the float64 query on the inputs rounded to float32, its answers rounded to float32
  (what the C++ front end does for float shapes), to the bit;
* a broadcast that is not a plain stride ((N, 1) against (M,), gathered chunk by chunk) gives
  to the bit what the same elements give when tiled out in full.
"""

import zlib

import numpy as np
import pytest

from circledist_cases.shapes import query_pairs, random_fields, same_bits

cd = pytest.importorskip("circledist")

SOLVERS = ("companion", "polished", "bracketing", "eigen")
PRECISIONS = ("float32", "float64", "longdouble")
N = 5


def _fields(kind, n, rng, sweep):
    """{field: array} of n random shapes of a kind (plus a sweep where asked)."""
    return random_fields(cd, kind, rng, (n,), sweep=sweep)


def _make(kind, fields, transform=lambda x: x):
    return getattr(cd, kind)(**{k: transform(v) for k, v in fields.items()})


def _seed(pair):
    return zlib.crc32("-".join(pair).encode())


def _pairs():
    return query_pairs(cd)


_same = same_bits


@pytest.mark.parametrize("pair", _pairs(), ids="-".join)
@pytest.mark.parametrize("sweep", [False, True], ids=["bare", "swept"])
def test_both_orders_give_the_same_answers(pair, sweep):
    rng = np.random.default_rng(_seed(pair))
    a = _make(pair[0], _fields(pair[0], N, rng, sweep))
    b = _make(pair[1], _fields(pair[1], N, rng, sweep))
    d = rng.uniform(0.0, 2.0, N)
    for solver in SOLVERS:
        for precision in PRECISIONS:
            opts = dict(solver=solver, precision=precision)
            _same(cd.distance(a, b, **opts), cd.distance(b, a, **opts))
            _same(cd.within(a, b, d, **opts), cd.within(b, a, d, **opts))
            _same(cd.distance_if_within(a, b, d, **opts), cd.distance_if_within(b, a, d, **opts))
            ab, ba = cd.closest_points(a, b, **opts), cd.closest_points(b, a, **opts)
            _same(ab.distance, ba.distance)
            _same(ab.point_a, ba.point_b)
            _same(ab.point_b, ba.point_a)
            _same(ab.param_a, ba.param_b)
            _same(ab.param_b, ba.param_a)
            _same(ab.unique, ba.unique)
            _same(ab.distance, cd.distance(a, b, **opts))


def _to_float32(x):
    return np.asarray(x, dtype=np.float32).astype(np.float64)


@pytest.mark.parametrize("pair", _pairs(), ids="-".join)
def test_float32_is_the_double_query_on_rounded_inputs(pair):
    rng = np.random.default_rng(7 + _seed(pair))
    fa, fb = _fields(pair[0], N, rng, True), _fields(pair[1], N, rng, True)
    d = rng.uniform(0.0, 2.0, N)
    a, b = _make(pair[0], fa), _make(pair[1], fb)  # float64 inputs, asked in float32
    ra, rb = _make(pair[0], fa, transform=_to_float32), _make(pair[1], fb, transform=_to_float32)
    for solver in SOLVERS:
        single, double = dict(solver=solver, precision="float32"), dict(solver=solver, precision="float64")
        _same(cd.distance(a, b, **single), cd.distance(ra, rb, **double).astype(np.float32))
        _same(
            cd.distance_if_within(a, b, d, **single),
            cd.distance_if_within(ra, rb, _to_float32(d), **double).astype(np.float32),
        )
        _same(cd.within(a, b, d, **single), cd.within(ra, rb, _to_float32(d), **double))
        got, want = cd.closest_points(a, b, **single), cd.closest_points(ra, rb, **double)
        for name in ("distance", "point_a", "point_b", "param_a", "param_b"):
            _same(getattr(got, name), getattr(want, name).astype(np.float32))
        _same(got.unique, want.unique)
    # A single query's distance is a Python float holding the float32 value.
    first = [{k: v[0] for k, v in f.items() if k != "sweep"} for f in (fa, fb)]
    one = cd.distance(_make(pair[0], first[0]), _make(pair[1], first[1]), precision="float32")
    assert type(one) is float and one == float(np.float32(one))


@pytest.mark.parametrize("pair", _pairs(), ids="-".join)
def test_gathered_broadcast_equals_the_tiled_batch(pair):
    rng = np.random.default_rng(11 + _seed(pair))
    n, m = 3, 100  # 300 elements: more than one gathered chunk is not needed, several rows are
    fa, fb = _fields(pair[0], n, rng, True), _fields(pair[1], m, rng, True)
    a = _make(pair[0], fa, transform=lambda x: x[:, None])
    b = _make(pair[1], fb)
    a_full = _make(pair[0], fa, transform=lambda x: np.repeat(x, m, axis=0))
    b_full = _make(pair[1], fb, transform=lambda x: np.tile(x, (n,) + (1,) * (x.ndim - 1)))
    d = rng.uniform(0.0, 2.0, (n, m))
    got = cd.closest_points(a, b)
    want = cd.closest_points(a_full, b_full)
    for name in ("distance", "point_a", "point_b", "param_a", "param_b", "unique"):
        w = np.asarray(getattr(want, name))
        _same(getattr(got, name), w.reshape((n, m) + w.shape[1:]))
    _same(cd.distance(a, b), cd.distance(a_full, b_full).reshape(n, m))
    _same(cd.distance_if_within(a, b, d), cd.distance_if_within(a_full, b_full, d.ravel()).reshape(n, m))
    _same(cd.within(a, b, d), cd.within(a_full, b_full, d.ravel()).reshape(n, m))


CLOSED_FORMS = {("Point", "Circle"), ("Point", "Disk")} | {
    tuple(sorted((x, y))) for x in ("Point", "Line", "Ray", "Segment") for y in ("Point", "Line", "Ray", "Segment")
}


@pytest.mark.parametrize("pair", _pairs(), ids="-".join)
def test_single_queries_are_the_batch_elements(pair):
    """A single query (answered without an array, the GIL held) is, to the bit, the element the
    same shapes give in a batch; and the closed-form pairs, compiled once for every solver, give
    the same bits whichever solver is asked."""
    rng = np.random.default_rng(13 + _seed(pair))
    fa, fb = _fields(pair[0], N, rng, True), _fields(pair[1], N, rng, True)
    a, b = _make(pair[0], fa), _make(pair[1], fb)
    d = rng.uniform(0.0, 2.0, N)
    for precision in PRECISIONS:
        answers = {}
        for solver in SOLVERS:
            opts = dict(solver=solver, precision=precision)
            batch = (cd.distance(a, b, **opts), cd.within(a, b, d, **opts), cd.distance_if_within(a, b, d, **opts))
            for i in range(N):
                ai = _make(pair[0], fa, transform=lambda x: x[i])
                bi = _make(pair[1], fb, transform=lambda x: x[i])
                single = (
                    cd.distance(ai, bi, **opts),
                    cd.within(ai, bi, d[i], **opts),
                    cd.distance_if_within(ai, bi, d[i], **opts),
                )
                assert type(single[1]) is bool
                for got, want in zip(single, batch):
                    _same(np.asarray(got, dtype=np.asarray(want).dtype), np.asarray(want)[i])
            answers[solver] = batch
        if tuple(sorted(pair)) in CLOSED_FORMS:
            for solver in SOLVERS:
                for got, want in zip(answers[solver], answers["bracketing"]):
                    _same(got, want)
