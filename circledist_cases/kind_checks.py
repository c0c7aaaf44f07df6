"""Checks a Python kind's test runs against every other kind (tests/pairs/test_arc.py, tests/pairs/test_annulus.py):
shapes as plain tuples (kind, *fields) of floats, both argument orders agreeing to the bit, the
accuracy bar, batches equal to single calls, effects and Scene against brute force, the
broadphase against brute force. Each test file keeps its own reference and its own cases."""

from __future__ import annotations

import numpy as np

import circledist as cd


def as_floats(v):
    return tuple(float(x) for x in v)


CLASSES = {
    "point": cd.Point,
    "line": cd.Line,
    "ray": cd.Ray,
    "segment": cd.Segment,
    "circle": cd.Circle,
    "disk": cd.Disk,
    "arc": cd.Arc,
    "annulus": cd.Annulus,
}


def make(shape, dtype=np.float64, **kw):
    """The circledist shape of a tuple (kind, *fields)."""
    kind, *f = shape
    return CLASSES[kind](*[np.asarray(x, dtype=dtype) for x in f], **kw)


def batch_of(shapes, dtype=np.float64):
    """One batched shape of tuples of one kind."""
    kind = shapes[0][0]
    fields = list(zip(*[s[1:] for s in shapes]))
    return make((kind, *[np.asarray(f, dtype=dtype) for f in fields]), dtype)


def rounded(shape, dtype):
    """The same shape with every number rounded to dtype (and back to float: exact)."""
    out = [shape[0]]
    for f in shape[1:]:
        out.append(as_floats(np.asarray(f, dtype=dtype)) if isinstance(f, tuple) else float(np.asarray(f, dtype=dtype)))
    return tuple(out)


def translated(shape, by):
    """The shape moved by `by`: its points move (a segment's two ends, every other kind's first field)."""
    kind, *f = shape
    moved = (0, 1) if kind == "segment" else (0,)
    return (kind, *[tuple(x + y for x, y in zip(v, by)) if i in moved else v for i, v in enumerate(f)])


def radii(shape):
    """The radii a query's accuracy bar counts: a round's or an arc's radius, an annulus's outer one."""
    kind = shape[0]
    if kind in ("circle", "disk", "arc"):
        return [shape[3]]
    return [shape[4]] if kind == "annulus" else []


def check(a, b, d, ref, rel):
    """|d - ref| <= rel x max(ref, largest radius in the query)."""
    scale = max([ref] + radii(a) + radii(b))
    assert abs(float(d) - ref) <= rel * scale, (float(d), ref, abs(float(d) - ref) / scale)
    return ref


def both_orders(a, b, **kw):
    """distance and closest_points of (a, b) and (b, a): equal to the bit, swapped; (d, closest)."""
    x, y = make(a), make(b)
    d_ab, d_ba = cd.distance(x, y, **kw), cd.distance(y, x, **kw)
    assert d_ab == d_ba  # one compiled query serves both orders, to the bit
    r_ab, r_ba = cd.closest_points(x, y, **kw), cd.closest_points(y, x, **kw)
    assert r_ab.distance == d_ab and r_ba.distance == d_ba
    assert np.array_equal(r_ab.point_a, r_ba.point_b) and np.array_equal(r_ab.param_a, r_ba.param_b)
    assert r_ab.unique == r_ba.unique
    return d_ab, r_ab


def assert_batched_equals_single(cases, n):
    """The n cases (a, b) batched: distance both ways and closest_points equal the single calls, in
    double and long double; returns the two batches."""
    subjects, others = batch_of([a for a, _ in cases]), batch_of([b for _, b in cases])
    for precision in ("float64", "longdouble"):
        d = cd.distance(subjects, others, precision=precision)
        d_rev = cd.distance(others, subjects, precision=precision)
        r = cd.closest_points(subjects, others, precision=precision)
        assert d.shape == (n,) and np.array_equal(d, d_rev) and np.array_equal(r.distance, d)
        for i, (a, b) in enumerate(cases):
            assert d[i] == cd.distance(make(a), make(b), precision=precision)
            single = cd.closest_points(make(a), make(b), precision=precision)
            assert np.array_equal(r.point_a[i], single.point_a) and np.array_equal(r.param_a[i], single.param_a)
            assert np.array_equal(r.point_b[i], single.point_b) and r.unique[i] == single.unique
    return subjects, others


def random_shape(kind, rng, box=1.5):
    """A random shape tuple of `kind` about a point of the box [-box, box]^3: radii in [0.2, 2), an
    arc's angle in [0.2, 2 pi), an annulus's outer radius in [0.3, 2) and inner one a tenth to nine
    tenths of it."""
    at = rng.uniform(-box, box, 3)
    if kind == "point":
        return ("point", as_floats(at))
    if kind in ("line", "ray"):
        return (kind, as_floats(at), as_floats(rng.normal(size=3)))
    if kind == "segment":
        return (kind, as_floats(at), as_floats(at + rng.uniform(-2, 2, 3)))
    if kind in ("circle", "disk"):
        return (kind, as_floats(at), as_floats(rng.normal(size=3)), float(rng.uniform(0.2, 2)))
    if kind == "arc":
        return (
            "arc",
            as_floats(at),
            as_floats(rng.normal(size=3)),
            float(rng.uniform(0.2, 2)),
            as_floats(rng.normal(size=3)),
            float(rng.uniform(0.2, 2 * np.pi)),
        )
    assert kind == "annulus", kind
    outer = rng.uniform(0.3, 2)
    return ("annulus", as_floats(at), as_floats(rng.normal(size=3)), float(outer * rng.uniform(0.1, 0.9)), float(outer))


def mixed_shapes(kinds, seed, n):
    """{name: shape}: n random shapes of each kind (random_shape, in a box of 3)."""
    rng = np.random.default_rng(seed)
    return {f"{kind}{i}": make(random_shape(kind, rng, box=3.0)) for kind in kinds for i in range(n)}


def assert_effects_agree_with_distance(subjects, shapes):
    """within, distance_if_within and intersects of each subject against every shape, both orders,
    as distance() says (away from the limits' tolerance)."""
    for a in subjects:
        for b in shapes:
            d = cd.distance(a, b)
            for limit in (0.0, 0.3, 1.0, 2.5):
                tol = 64 * np.finfo(float).eps * 10
                if abs(d - limit) > 1e-9:
                    assert cd.within(a, b, limit) == (d <= limit + tol)
                    assert cd.within(b, a, limit) == (d <= limit + tol)
                    assert cd.distance_if_within(a, b, limit) == (d if d <= limit else np.inf)
            if d > 1e-9:
                assert not cd.intersects(a, b)
            elif d == 0:
                assert cd.intersects(a, b)


def assert_scene_equals_brute_force(shapes, probes, word):
    """Scene.nearest / within for each probe (a name or a shape) and pairs_within, against brute
    force; some pair within the larger limits names a shape whose name holds `word`."""
    scene = cd.Scene(shapes)
    names = list(shapes)
    for probe in probes:
        shape = shapes[probe] if isinstance(probe, str) else probe
        others = [n for n in names if n != probe]
        order = sorted(((cd.distance(shape, shapes[n]), names.index(n)) for n in others))
        assert scene.nearest(probe, k=6) == [(names[i], d) for d, i in order[:6]]
        assert scene.within(probe, 1.0) == [n for n in others if cd.within(shape, shapes[n], 1.0)]
    for d in (0.0, 0.5, 1.5):
        brute = [(x, y) for i, x in enumerate(names) for y in names[i + 1 :] if cd.within(shapes[x], shapes[y], d)]
        assert scene.pairs_within(d) == brute
        assert any(word in x + y for x, y in brute) or d == 0.0


def assert_broadphase_finds_points_on(batch, on, rng):
    """Points on each of the batch's n shapes (`on`, (n, 3)) and 1e-3 off them are found by
    pairs_within and nearest exactly as brute force finds them (a box missing part of its shape
    would lose pairs)."""
    n = len(on)
    points = cd.Point(np.concatenate([on, on + 1e-3 * rng.normal(size=(n, 3))]))
    i, j, d = cd.pairs_within(batch, points, 0.01)
    dist = cd.distance(type(batch).from_arrays({k: a[:, None] for k, a in batch.to_arrays().items()}), points)
    want_i, want_j = np.nonzero(dist <= 0.01)
    assert np.array_equal(i, want_i) and np.array_equal(j, want_j) and np.array_equal(d, dist[want_i, want_j])
    assert {(k, k) for k in range(n)} <= set(zip(i.tolist(), j.tolist()))
    idx, nd = cd.nearest(points, batch, k=2)
    order = np.argsort(dist.T, axis=1, kind="stable")[:, :2]
    assert np.array_equal(nd, np.take_along_axis(dist.T, order, axis=1))


def assert_exact_and_unique(name, a, b, d, r, ref, exact, unique, rel):
    """A hard case's analytic distance (when known): the reference agrees with it to 1e-14 and
    the answer to `rel`, of max(distance, largest radius); its `unique` (when known)."""
    if exact is not None:
        scale = max([exact] + radii(a) + radii(b))
        assert abs(ref - exact) <= 1e-14 * scale  # the reference agrees with the analytic answer
        assert abs(d - exact) <= rel * scale
    if unique is not None:
        assert bool(r.unique) is unique, name


def assert_long_double(cases, reference, solvers, rel):
    """precision='longdouble' on float64 inputs (which it reads exactly), every solver, both orders:
    a long double within rel x max(reference, largest radius)."""
    for a, b in cases:
        for solver in solvers:
            d, _ = both_orders(a, b, precision="longdouble", solver=solver)
            assert isinstance(d, np.longdouble)
            ref = reference(a, b)
            scale = max([ref] + radii(a) + radii(b))
            assert abs(float(d - np.longdouble(ref))) <= rel * scale, (a, b, float(d), ref)


def assert_float32(cases, reference):
    """float32 inputs give float32 answers within 4 float32 ulps of max(d, radius) of the exact
    answer for the float32 inputs (the reference of the rounded shapes)."""
    for a, b in cases:
        a32, b32 = rounded(a, np.float32), rounded(b, np.float32)
        x, y = make(a, np.float32), make(b, np.float32)
        d = cd.distance(x, y)  # a single float32 answer comes back as a Python float of a float32
        assert float(np.float32(d)) == d and cd.distance(y, x) == d
        ref = reference(a32, b32)
        scale = max([ref] + radii(a32) + radii(b32))
        assert abs(float(d) - ref) <= 4 * float(np.spacing(np.float32(scale))), (float(d), ref)


def assert_scene_file_round_trip(path, shapes, queries, other):
    """shapes written to `path` (.json or .npz) with the queries read back to the bit (every field,
    the sweep where one was given), answering as before against the shape named `other`."""
    cd.write_scene(path, shapes, queries)
    back = cd.read_scene(str(path))
    for name, shape in shapes.items():
        got, want = back.shapes[name].to_arrays(), shape.to_arrays()
        assert [k for k in got if k != "sweep"] == [k for k in want if k != "sweep"]
        assert not np.any(got.get("sweep", 0) != want.get("sweep", 0))
        for field in want:
            assert np.array_equal(got[field], np.broadcast_to(want[field], got[field].shape)), (name, field)
        assert np.array_equal(cd.distance(back.shapes[name], shapes[other]), cd.distance(shape, shapes[other]))


def file_version(path):
    """The format version a scene file (.json or .npz) says."""
    import json

    if str(path).endswith(".json"):
        return json.loads(path.read_text())["version"]
    with np.load(path) as npz:
        return int(npz["version"])


def assert_older_version_refused(path, version, name, kind):
    """The file at `path` (.json or .npz) says `version`; said one lower, it is refused at the
    shape `name` of `kind`, the kind that version lacks."""
    import json

    import pytest

    assert file_version(path) == version
    older = version - 1
    if str(path).endswith(".json"):
        data = json.loads(path.read_text())
        data["version"] = older
        message = (
            rf"\$\.shapes\[0\]\.kind \(shape '{name}'\): kind '{kind}' needs format version {version} or "
            rf"later, the file says version {older}"
        )
        with pytest.raises(cd.SceneFileError, match=message):
            cd.scenefile.scene_from_json(data, "old.json")
    else:
        with np.load(path) as npz:
            arrays = dict(npz)
        old = path.parent / "old.npz"
        np.savez(old, **{**arrays, "version": np.array(older)})
        message = f"array '{name}/kind': kind '{kind}' needs format version {version}"
        with pytest.raises(cd.SceneFileError, match=message):
            cd.read_scene(str(old))
