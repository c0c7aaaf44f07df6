"""Batches, return types, dtypes and input validation of circledist.

* batched calls agree element-wise with single calls: one line vs N circles, N vs N,
  (N,1) vs (M,) -> (N,M), a scalar radius with (N,3) centres, batches of points;
* single queries return Python floats, batches ndarrays of the broadcast shape, and
  closest_points fields have shapes batch, batch+(3,), batch (bool);
* float32 inputs are accepted;
* every bad input raises ValueError naming the argument and, for a batch, the first
  offending index; nothing (including odd inputs) crashes the interpreter.
"""

import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

N, M = 7, 5
RNG_SEED = 20240611


def test_module_imports():
    """Fails (instead of the skips elsewhere) while circledist cannot be imported."""
    import circledist  # noqa: F401


# ----------------------------------------------------------------------------
# data
# ----------------------------------------------------------------------------
def _rounds(n, seed=RNG_SEED):
    rng = np.random.default_rng(seed)
    return rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.2, 2.0, n)


def _linears(n, seed=RNG_SEED + 1):
    rng = np.random.default_rng(seed)
    return rng.normal(scale=1.5, size=(n, 3)), rng.normal(size=(n, 3))


def _make_lin(cd, kind, o, d):
    if kind == "point":
        return np.asarray(o, float)
    if kind == "line":
        return cd.Line(o, d)
    if kind == "ray":
        return cd.Ray(o, d)
    return cd.Segment(o, np.asarray(o) + np.asarray(d))


def _make_round(cd, kind, c, n, r):
    return (cd.Circle if kind == "circle" else cd.Disk)(c, n, r)


LIN_KINDS = ["point", "line", "ray", "segment"]
ROUND_KINDS = ["circle", "disk"]
PAIRS = [(lk, rk) for rk in ROUND_KINDS for lk in LIN_KINDS]
PAIR_IDS = [f"{lk}-{rk}" for lk, rk in PAIRS]


def _close(batch, singles, what):
    batch = np.asarray(batch)
    singles = np.asarray(singles)
    assert batch.shape == singles.shape, f"{what}: shape {batch.shape} vs {singles.shape}"
    scale = np.maximum(np.abs(singles), 1.0)
    bad = np.abs(batch - singles) > 1e-13 * scale
    assert not bad.any(), f"{what}: batch differs from single calls at {np.argwhere(bad)[:5]}"


# ----------------------------------------------------------------------------
# batches
# ----------------------------------------------------------------------------
def _check_n_results(cd, lins, rounds, single_lin, single_round, what, what_swapped):
    """A batch of N answers, in both argument orders, against the N single calls
    distance(single_lin(i), single_round(i))."""
    got = cd.distance(lins, rounds)
    assert isinstance(got, np.ndarray) and got.shape == (N,)
    singles = [cd.distance(single_lin(i), single_round(i)) for i in range(N)]
    _close(got, singles, what)
    _close(cd.distance(rounds, lins), singles, what_swapped)


@pytest.mark.parametrize("lk,rk", PAIRS, ids=PAIR_IDS)
def test_one_linear_vs_n_rounds(cd, lk, rk):
    c, n, r = _rounds(N)
    o, d = _linears(1)
    lin = _make_lin(cd, lk, o[0], d[0])
    _check_n_results(
        cd,
        lin,
        _make_round(cd, rk, c, n, r),
        lambda i: lin,
        lambda i: _make_round(cd, rk, c[i], n[i], r[i]),
        "one vs N",
        "N vs one (swapped)",
    )


@pytest.mark.parametrize("lk,rk", PAIRS, ids=PAIR_IDS)
def test_n_vs_n(cd, lk, rk):
    c, n, r = _rounds(N)
    o, d = _linears(N)
    _check_n_results(
        cd,
        _make_lin(cd, lk, o, d),
        _make_round(cd, rk, c, n, r),
        lambda i: _make_lin(cd, lk, o[i], d[i]),
        lambda i: _make_round(cd, rk, c[i], n[i], r[i]),
        "N vs N",
        "N vs N (swapped)",
    )


@pytest.mark.parametrize("lk,rk", PAIRS, ids=PAIR_IDS)
def test_outer_broadcast(cd, lk, rk):
    """(N,1) vs (M,) -> (N, M)."""
    c, n, r = _rounds(M)
    o, d = _linears(N)
    lins = _make_lin(cd, lk, o[:, None, :], d[:, None, :])
    rounds = _make_round(cd, rk, c, n, r)
    got = cd.distance(lins, rounds)
    assert isinstance(got, np.ndarray) and got.shape == (N, M)
    singles = [
        [cd.distance(_make_lin(cd, lk, o[i], d[i]), _make_round(cd, rk, c[j], n[j], r[j])) for j in range(M)]
        for i in range(N)
    ]
    _close(got, singles, "(N,1) vs (M,)")
    swapped = cd.distance(rounds, lins)
    assert swapped.shape == (N, M)
    _close(swapped, singles, "(M,) vs (N,1)")
    res = cd.closest_points(lins, rounds)
    assert np.shape(res.distance) == (N, M)
    assert np.shape(res.point_a) == (N, M, 3) and np.shape(res.point_b) == (N, M, 3)
    assert np.shape(res.unique) == (N, M)


@pytest.mark.parametrize("rk", ROUND_KINDS)
def test_scalar_radius_with_batched_centres(cd, rk):
    c, n, _ = _rounds(N)
    o, d = _linears(1)
    line = cd.Line(o[0], d[0])
    got = cd.distance(line, _make_round(cd, rk, c, n, 1.25))
    singles = [cd.distance(line, _make_round(cd, rk, c[i], n[i], 1.25)) for i in range(N)]
    _close(got, singles, "scalar radius")
    # a single normal broadcast against N centres
    got = cd.distance(line, _make_round(cd, rk, c, n[0], 1.25))
    singles = [cd.distance(line, _make_round(cd, rk, c[i], n[0], 1.25)) for i in range(N)]
    _close(got, singles, "single normal")


@pytest.mark.parametrize("rk", ROUND_KINDS)
def test_batch_of_points(cd, rk):
    c, n, r = _rounds(1)
    pts, _ = _linears(N)
    rnd = _make_round(cd, rk, c[0], n[0], r[0])
    got = cd.distance(pts, rnd)
    assert isinstance(got, np.ndarray) and got.shape == (N,)
    _close(got, [cd.distance(p, rnd) for p in pts], "points (N,3)")
    _close(cd.distance(rnd, pts), [cd.distance(p, rnd) for p in pts], "points swapped")


@pytest.mark.parametrize("lk,rk", PAIRS, ids=PAIR_IDS)
def test_closest_points_batch_matches_singles(cd, lk, rk):
    c, n, r = _rounds(N)
    o, d = _linears(N)
    res = cd.closest_points(_make_lin(cd, lk, o, d), _make_round(cd, rk, c, n, r))
    assert isinstance(res.distance, np.ndarray) and res.distance.shape == (N,)
    pa, pb, un = np.asarray(res.point_a), np.asarray(res.point_b), np.asarray(res.unique)
    assert pa.shape == (N, 3) and pb.shape == (N, 3)
    assert un.shape == (N,) and un.dtype == np.bool_
    for name in ("param_a", "param_b") if lk != "point" else ("param_b",):
        shape = np.shape(getattr(res, name))
        assert shape[:1] == (N,), f"{name} shape {shape}"
    for i in range(N):
        s = cd.closest_points(_make_lin(cd, lk, o[i], d[i]), _make_round(cd, rk, c[i], n[i], r[i]))
        _close(res.distance[i], s.distance, f"distance[{i}]")
        _close(pa[i], np.asarray(s.point_a), f"point_a[{i}]")
        _close(pb[i], np.asarray(s.point_b), f"point_b[{i}]")
        assert bool(un[i]) == bool(s.unique)


def test_two_dimensional_batch(cd):
    c, n, r = _rounds(6)
    circles = cd.Circle(c.reshape(2, 3, 3), n.reshape(2, 3, 3), r.reshape(2, 3))
    line = cd.Line((0.1, 0.2, 0.3), (1.0, -0.5, 0.25))
    got = cd.distance(line, circles)
    assert got.shape == (2, 3)
    singles = [cd.distance(line, cd.Circle(c[i], n[i], r[i])) for i in range(6)]
    _close(got.reshape(-1), singles, "(2,3) batch")


def test_leading_dimension_one_is_a_batch(cd):
    line = cd.Line(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]))
    got = cd.distance(line, cd.Circle((1.0, 2.0, 3.0), (0.0, 0.0, 1.0), 1.0))
    assert isinstance(got, np.ndarray) and got.shape == (1,)


# ----------------------------------------------------------------------------
# return types and dtypes
# ----------------------------------------------------------------------------
@pytest.mark.parametrize("lk,rk", PAIRS, ids=PAIR_IDS)
def test_single_return_types(cd, lk, rk):
    lin = _make_lin(cd, lk, (0.3, -0.2, 0.9), (0.5, 1.0, -0.25))
    rnd = _make_round(cd, rk, (0.0, 0.1, 0.0), (0.2, 0.3, 1.0), 1.5)
    d = cd.distance(lin, rnd)
    assert type(d) is float
    res = cd.closest_points(lin, rnd)
    assert isinstance(res.distance, float)
    assert np.shape(res.point_a) == (3,) and np.shape(res.point_b) == (3,)
    assert isinstance(res.unique, (bool, np.bool_))
    assert abs(res.distance - d) <= 1e-12 * max(d, 1.5)


def test_array_like_inputs(cd):
    """Lists and tuples are accepted wherever arrays are."""
    d1 = cd.distance([0.5, 0.5, 2.0], cd.Circle([0, 0, 0], [0, 0, 1], 1))
    d2 = cd.distance(np.array([0.5, 0.5, 2.0]), cd.Circle(np.zeros(3), np.array([0, 0, 1.0]), 1.0))
    assert d1 == d2


@pytest.mark.parametrize("lk,rk", PAIRS, ids=PAIR_IDS)
def test_float32_inputs(cd, lk, rk):
    c, n, r = (x.astype(np.float32) for x in _rounds(N))
    o, d = (x.astype(np.float32) for x in _linears(N))
    got = cd.distance(_make_lin(cd, lk, o, d), _make_round(cd, rk, c, n, r))
    want = cd.distance(
        _make_lin(cd, lk, o.astype(float), d.astype(float)),
        _make_round(cd, rk, c.astype(float), n.astype(float), r.astype(float)),
    )
    assert np.shape(got) == (N,)
    # the float32 values, read exactly, describe the same scene
    np.testing.assert_allclose(got, want, rtol=1e-6, atol=1e-6)
    single = cd.distance(_make_lin(cd, lk, o[0], d[0]), _make_round(cd, rk, c[0], n[0], np.float32(r[0])))
    assert isinstance(single, float)


def test_integer_inputs(cd):
    d = cd.distance(cd.Line([0, 0, 5], [0, 0, 1]), cd.Circle([0, 0, 0], [0, 0, 2], 3))
    assert abs(d - 3.0) <= 3e-12


# ----------------------------------------------------------------------------
# input validation
# ----------------------------------------------------------------------------
BAD_AT = 13  # first offending index in a batch of 20
ALSO_BAD = 17


def _good_round():
    rng = np.random.default_rng(5)
    return rng.normal(size=(20, 3)), rng.normal(size=(20, 3)), rng.uniform(0.5, 1.0, 20)


def _good_linear():
    rng = np.random.default_rng(6)
    return rng.normal(size=(20, 3)), rng.normal(size=(20, 3))


def _spoil(arr, value, component=0):
    arr = np.array(arr, float)
    for i in (BAD_AT, ALSO_BAD):
        if arr.ndim == 1:
            arr[i] = value
        elif value == "zero":
            arr[i] = 0.0
        else:
            arr[i, component] = value
    return arr


def _round_case(kind, field, value):
    c, n, r = _good_round()
    if field == "center":
        c = _spoil(c, value)
    elif field == "normal":
        n = _spoil(n, value, component=2)
    else:
        r = _spoil(r, value)

    def build(cd):
        return (cd.Circle if kind == "circle" else cd.Disk)(c, n, r)

    return build


def _lin_case(kind, field, value):
    a, b = _good_linear()
    if field in ("origin", "p0"):
        a = _spoil(a, value, component=1)
    else:
        b = _spoil(b, value, component=1)

    def build(cd):
        return getattr(cd, kind.capitalize())(a, b)

    return build


BAD_BATCH = []
for _k in ("circle", "disk"):
    BAD_BATCH += [
        (f"{_k}-center-nan", _round_case(_k, "center", np.nan), "center", True),
        (f"{_k}-center-inf", _round_case(_k, "center", np.inf), "center", True),
        (f"{_k}-normal-nan", _round_case(_k, "normal", np.nan), "normal", True),
        (f"{_k}-normal-inf", _round_case(_k, "normal", -np.inf), "normal", True),
        (f"{_k}-normal-zero", _round_case(_k, "normal", "zero"), "normal", True),
        (f"{_k}-radius-negative", _round_case(_k, "radius", -0.5), "radius", True),
        (f"{_k}-radius-nan", _round_case(_k, "radius", np.nan), "radius", True),
        (f"{_k}-radius-inf", _round_case(_k, "radius", np.inf), "radius", True),
    ]
for _k in ("line", "ray"):
    BAD_BATCH += [
        (f"{_k}-origin-nan", _lin_case(_k, "origin", np.nan), "origin", False),
        (f"{_k}-origin-inf", _lin_case(_k, "origin", np.inf), "origin", False),
        (f"{_k}-direction-nan", _lin_case(_k, "direction", np.nan), "direction", False),
        (f"{_k}-direction-inf", _lin_case(_k, "direction", np.inf), "direction", False),
        (f"{_k}-direction-zero", _lin_case(_k, "direction", "zero"), "direction", False),
    ]
BAD_BATCH += [
    ("segment-p0-nan", _lin_case("segment", "p0", np.nan), "p0", False),
    ("segment-p0-inf", _lin_case("segment", "p0", -np.inf), "p0", False),
    ("segment-p1-nan", _lin_case("segment", "p1", np.nan), "p1", False),
    ("segment-p1-inf", _lin_case("segment", "p1", np.inf), "p1", False),
]


def _partner(cd, is_round):
    if is_round:
        return cd.Line((0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
    return cd.Circle((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0)


def _raise_on_use(cd, build, is_round):
    """The error may come from the constructor or from the query: both are accepted."""
    with pytest.raises(ValueError) as info:
        shape = build(cd)
        cd.distance(shape, _partner(cd, is_round))
    return str(info.value)


@pytest.mark.parametrize("build,name,is_round", [c[1:] for c in BAD_BATCH], ids=[c[0] for c in BAD_BATCH])
def test_bad_batch_input(cd, build, name, is_round):
    msg = _raise_on_use(cd, build, is_round)
    assert name in msg, f"message does not name {name!r}: {msg!r}"
    assert re.search(
        rf"(?<![\d.]){BAD_AT}(?![\d.])", msg
    ), f"message does not give the first bad index {BAD_AT}: {msg!r}"


SINGLE_BAD = [
    ("circle-center-nan", lambda cd: cd.Circle((np.nan, 0, 0), (0, 0, 1), 1.0), "center", True),
    ("circle-normal-zero", lambda cd: cd.Circle((0, 0, 0), (0, 0, 0), 1.0), "normal", True),
    ("circle-normal-inf", lambda cd: cd.Circle((0, 0, 0), (0, np.inf, 1), 1.0), "normal", True),
    ("circle-radius-negative", lambda cd: cd.Circle((0, 0, 0), (0, 0, 1), -1.0), "radius", True),
    ("circle-radius-nan", lambda cd: cd.Circle((0, 0, 0), (0, 0, 1), np.nan), "radius", True),
    ("disk-radius-negative", lambda cd: cd.Disk((0, 0, 0), (0, 0, 1), -1e-300), "radius", True),
    ("disk-normal-zero", lambda cd: cd.Disk((0, 0, 0), (0.0, -0.0, 0.0), 1.0), "normal", True),
    ("disk-center-inf", lambda cd: cd.Disk((0, 0, -np.inf), (0, 0, 1), 1.0), "center", True),
    ("line-direction-zero", lambda cd: cd.Line((0, 0, 0), (0, 0, 0)), "direction", False),
    ("line-origin-nan", lambda cd: cd.Line((0, np.nan, 0), (0, 0, 1)), "origin", False),
    ("ray-direction-zero", lambda cd: cd.Ray((0, 0, 0), (0, 0, 0)), "direction", False),
    ("ray-origin-inf", lambda cd: cd.Ray((np.inf, 0, 0), (0, 0, 1)), "origin", False),
    ("segment-p0-nan", lambda cd: cd.Segment((np.nan, 0, 0), (0, 0, 1)), "p0", False),
    ("segment-p1-inf", lambda cd: cd.Segment((0, 0, 0), (0, 0, np.inf)), "p1", False),
    # wrong trailing dimension
    ("circle-center-dim2", lambda cd: cd.Circle((0, 0), (0, 0, 1), 1.0), "center", True),
    ("circle-normal-dim4", lambda cd: cd.Circle((0, 0, 0), (0, 0, 1, 0), 1.0), "normal", True),
    ("disk-center-batch-dim2", lambda cd: cd.Disk(np.zeros((4, 2)), (0, 0, 1), 1.0), "center", True),
    ("line-origin-dim4", lambda cd: cd.Line(np.zeros((3, 4)), np.ones((3, 3))), "origin", False),
    ("line-direction-dim2", lambda cd: cd.Line((0, 0, 0), (0, 1)), "direction", False),
    ("ray-direction-dim1", lambda cd: cd.Ray((0, 0, 0), np.ones((5, 1))), "direction", False),
    ("segment-p0-dim2", lambda cd: cd.Segment(np.zeros((3, 2)), np.ones((3, 3))), "p0", False),
    ("segment-p1-dim4", lambda cd: cd.Segment((0, 0, 0), (0, 0, 1, 1)), "p1", False),
]


@pytest.mark.parametrize("build,name,is_round", [c[1:] for c in SINGLE_BAD], ids=[c[0] for c in SINGLE_BAD])
def test_bad_input_names_argument(cd, build, name, is_round):
    msg = _raise_on_use(cd, build, is_round)
    assert name in msg, f"message does not name {name!r}: {msg!r}"


@pytest.mark.parametrize(
    "point", [(np.nan, 0, 0), (0, np.inf, 0), (0, 0), (0, 0, 0, 0)], ids=["nan", "inf", "dim2", "dim4"]
)
def test_bad_point(cd, point):
    with pytest.raises(ValueError):
        cd.distance(np.array(point, float), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    with pytest.raises(ValueError):
        cd.closest_points(cd.Disk((0, 0, 0), (0, 0, 1), 1.0), np.array(point, float))


def test_bad_point_batch_index(cd):
    pts = np.random.default_rng(1).normal(size=(20, 3))
    pts[BAD_AT, 2] = np.nan
    pts[ALSO_BAD, 0] = np.inf
    with pytest.raises(ValueError) as info:
        cd.distance(pts, cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    assert re.search(rf"(?<![\d.]){BAD_AT}(?![\d.])", str(info.value)), str(info.value)


@pytest.mark.parametrize("fn", ["distance", "closest_points"])
def test_batch_shapes_that_do_not_broadcast(cd, fn):
    c, n, r = _rounds(N)
    o, d = _linears(M)
    with pytest.raises(ValueError):
        getattr(cd, fn)(cd.Line(o, d), cd.Circle(c, n, r))
    with pytest.raises(ValueError):
        getattr(cd, fn)(cd.Disk(c, n, r), o[:4])


def test_mismatched_field_batches(cd):
    """Fields of one shape that do not broadcast against each other."""
    c, n, r = _rounds(N)
    with pytest.raises(ValueError):
        cd.distance(cd.Circle(c, n[:3], r), cd.Line((0, 0, 0), (0, 0, 1)))
    with pytest.raises(ValueError):
        cd.distance(cd.Disk(c, n, r[:4]), cd.Line((0, 0, 0), (0, 0, 1)))
    with pytest.raises(ValueError):
        cd.distance(cd.Segment(c, c[:2]), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))


CRASH_SCRIPT = textwrap.dedent(r"""
    import numpy as np
    import circledist as cd
    C = cd.Circle((0, 0, 0), (0, 0, 1), 1.0)
    L = cd.Line((0, 0, 1), (1, 0, 0))
    attempts = [
        lambda: cd.distance(np.zeros((0, 3)), C),
        lambda: cd.distance(cd.Line(np.zeros((0, 3)), np.ones((0, 3))), C),
        lambda: cd.closest_points(cd.Circle(np.zeros((0, 3)), np.ones((0, 3)), 1.0), L),
        lambda: cd.distance(cd.Line((1e300, 1e300, 1e300), (1, 2, 3)), C),
        lambda: cd.distance(cd.Line((0, 0, 0), (1e-300, 1e-300, 1e-300)), C),
        lambda: cd.distance(cd.Line((0, 0, 0), (1e300, -1e300, 1e300)),
                            cd.Disk((0, 0, 0), (1e-300, 0, 1e-300), 1e300)),
        lambda: cd.distance(cd.Circle((0, 0, 0), (5e-324, 0, 0), 1.0), L),
        lambda: cd.distance(cd.Segment((0, 0, 0), (0, 0, 0)), cd.Disk((0, 0, 0), (0, 0, 1), 0.0)),
        lambda: cd.distance(np.zeros((4, 3))[::2], C),
        lambda: cd.distance(np.asfortranarray(np.ones((3, 3))), C),
        lambda: cd.distance(np.ones((3, 3), dtype=np.int64), C),
        lambda: cd.distance(np.ones((3, 3), dtype=np.float16), C),
        lambda: cd.distance(np.array(["a", "b", "c"]), C),
        lambda: cd.distance(None, C),
        lambda: cd.distance(C, "circle"),
        lambda: cd.distance(np.ones((2, 3), dtype=object), C),
        lambda: cd.Circle(np.zeros((3, 3)), np.ones((3, 3)), np.ones((3, 3))),
        lambda: cd.Circle((0, 0, 0), (0, 0, 1), (1.0, 2.0)),
        lambda: cd.Circle(np.zeros(3), np.ones(3), np.ones((2, 2))),
        lambda: cd.Line(np.zeros((2, 1, 3)), np.ones((1, 4, 3))),
        lambda: cd.distance(cd.Line(np.zeros((2, 1, 3)), np.ones((1, 4, 3))), C),
        lambda: cd.distance(np.zeros(()), C),
        lambda: cd.distance(np.zeros((3,) * 8), C),
        lambda: cd.closest_points(np.full((3,), np.nan), np.full((3,), np.nan)),
    ]
    for i, f in enumerate(attempts):
        try:
            f()
        except Exception:
            pass
    print("survived")
""")


def test_odd_inputs_do_not_crash_the_interpreter(cd):
    proc = subprocess.run([sys.executable, "-c", CRASH_SCRIPT], capture_output=True, text=True, timeout=120)
    assert (
        proc.returncode == 0 and "survived" in proc.stdout
    ), f"interpreter died (return code {proc.returncode}): {proc.stderr[-2000:]}"


# Validation checks every value's exponent bits in one pass: the extremes of the finite range
# pass, and a non-finite value anywhere (the last element of a long batch) is still named.
def test_finite_extremes_accepted(cd):
    big, tiny = np.finfo(np.float64).max, 5e-324
    pts = np.array([[big, -big, 0.0], [tiny, -tiny, -0.0], [1.0, 2.0, 3.0]])
    d = cd.distance(cd.Point(pts), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    assert d.shape == (3,)
    assert np.isfinite(d[1]) and np.isfinite(d[2])


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_last_element_named(cd, bad):
    n = 100_003
    centers = np.zeros((n, 3))
    centers[n - 1, 1] = bad
    with pytest.raises(ValueError) as info:
        cd.Circle(centers, (0, 0, 1), 1.0)
    assert f"center[{n - 1}]" in str(info.value), str(info.value)
