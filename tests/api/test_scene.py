"""cd.Scene: named shapes of mixed kinds; nearest / within / pairs_within / distance_matrix give
exactly the brute-force answers on random (seeded) scenes while the bounding-volume hierarchy
spares most pairs any exact work."""

import numpy as np
import pytest

cd = pytest.importorskip("circledist")


def rand_dirs(rng, n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def mixed_scene(seed, n=600, box=20.0, sweeps=True, kinds=("Disk", "Circle", "Segment", "Point", "Bezier")):
    """A scene of n shapes of the given kinds (in turn), and the same shapes as a list."""
    rng = np.random.default_rng(seed)
    scene = cd.Scene()
    shapes = []
    for i in range(n):
        kind = kinds[i % len(kinds)]
        c = rng.uniform(-box, box, 3)
        sweep = float(rng.uniform(0, 0.2)) if sweeps and rng.uniform() < 0.5 else 0.0
        if kind in ("Disk", "Circle"):
            s = getattr(cd, kind)(c, rand_dirs(rng, 1)[0], rng.uniform(0.2, 1.2), sweep=sweep)
        elif kind == "Segment":
            s = cd.Segment(c, c + rng.uniform(-1, 1, 3), sweep=sweep)
        elif kind == "Point":
            s = cd.Point(c, sweep=sweep)
        elif kind == "Bezier":
            s = cd.Bezier(c + rng.uniform(-1, 1, (4, 3)), sweep=sweep)
        elif kind == "Line":
            s = cd.Line(c, rand_dirs(rng, 1)[0], sweep=sweep)
        else:
            raise AssertionError(kind)
        scene.add(f"{kind.lower()}{i}", s)
        shapes.append(s)
    return scene, shapes


def brute_distances(query, shapes):
    return np.array([cd.distance(query, s) for s in shapes])


QUERIES = {
    "line": cd.Line([-20, 1.0, 2.0], [1, 0.3, -0.2]),
    "ray": cd.Ray([0, 0, 0], [0.2, 1, 0.1]),
    "circle": cd.Circle([1, 2, 3], [0.3, 0.1, 1], 2.0, sweep=0.1),
    "disk": cd.Disk([-4, 5, 0], [1, 1, 0], 1.5),
}


@pytest.mark.parametrize("query", list(QUERIES))
@pytest.mark.parametrize("k", [1, 4])
def test_nearest_equals_brute_force(query, k):
    # Bezier curves have queries against circles and disks only.
    kinds = (
        ("Disk", "Circle", "Segment", "Point")
        if query in ("line", "ray")
        else ("Disk", "Circle", "Segment", "Point", "Bezier")
    )
    scene, shapes = mixed_scene(5 + k, kinds=kinds)
    q = QUERIES[query]
    d = brute_distances(q, shapes)
    order = np.argsort(d, kind="stable")[:k]
    expected = [(scene.names[i], d[i]) for i in order]
    cd.reset_stats()
    got = scene.nearest(q, k)
    assert got == expected
    s = cd.stats()
    assert s["distances"] < len(shapes) / 5, s
    assert s["culled"] > 0.8 * len(shapes)


def test_nearest_with_sweeps_and_names():
    scene, shapes = mixed_scene(2, n=300, kinds=("Disk", "Circle", "Point", "Segment"))
    name = scene.names[10]
    q = scene[name]
    d = brute_distances(q, shapes)
    d[10] = np.inf  # a name as the query leaves that shape out
    order = np.argsort(d, kind="stable")[:3]
    assert scene.nearest(name, 3) == [(scene.names[i], d[i]) for i in order]
    assert scene.nearest(q, 1)[0] == (name, 0.0)
    assert [n for n, _ in scene.nearest(q, 2, exclude=[name])] == [scene.names[order[0]], scene.names[order[1]]]


@pytest.mark.parametrize("query", list(QUERIES))
@pytest.mark.parametrize("d", [0.0, 0.5, 3.0])
def test_within_equals_brute_force(query, d):
    kinds = (
        ("Disk", "Circle", "Segment", "Point")
        if query in ("line", "ray")
        else ("Disk", "Circle", "Segment", "Point", "Bezier")
    )
    scene, shapes = mixed_scene(11, kinds=kinds)
    q = QUERIES[query]
    expected = [scene.names[i] for i, s in enumerate(shapes) if cd.within(q, s, d)]
    dist = brute_distances(q, shapes)
    assert expected == [scene.names[i] for i in np.flatnonzero(dist <= d)]
    cd.reset_stats()
    assert scene.within(q, d) == expected
    s = cd.stats()
    assert s["within"] < len(shapes) / 4, s


@pytest.mark.parametrize("d", [0.0, 0.4, 2.0])
def test_pairs_within_equals_brute_force(d):
    scene, shapes = mixed_scene(21, n=240, box=8.0, kinds=("Disk", "Circle", "Segment", "Point"))
    names = scene.names
    expected = [
        (names[i], names[j])
        for i in range(len(shapes))
        for j in range(i + 1, len(shapes))
        if cd.within(shapes[i], shapes[j], d)
    ]
    cd.reset_stats()
    got = scene.pairs_within(d)
    assert got == expected
    total = len(shapes) * (len(shapes) - 1) // 2
    assert cd.stats()["within"] < total / 5
    assert cd.stats()["culled"] + cd.stats()["within"] == total


def test_pairs_within_with_lines():
    scene, shapes = mixed_scene(4, n=150, box=6.0, kinds=("Disk", "Circle", "Segment", "Line"))
    names = scene.names
    expected = [
        (names[i], names[j])
        for i in range(len(shapes))
        for j in range(i + 1, len(shapes))
        if cd.within(shapes[i], shapes[j], 0.5)
    ]
    assert scene.pairs_within(0.5) == expected


def test_distance_matrix():
    scene, shapes = mixed_scene(8, n=60, kinds=("Disk", "Circle", "Segment", "Point"))
    a = scene.names[::3]
    b = scene.names[1::4] + [scene.names[0]]
    m = scene.distance_matrix(a, b)
    assert m.shape == (len(a), len(b))
    index = {n: i for i, n in enumerate(scene.names)}
    for i, na in enumerate(a):
        for j, nb in enumerate(b):
            assert m[i, j] == cd.distance(shapes[index[na]], shapes[index[nb]])
    cd.reset_stats()
    scene.distance_matrix(a, b)
    assert cd.stats()["closest_points"] == 0


def test_large_disk_scene_solves_a_small_fraction():
    rng = np.random.default_rng(99)
    n = 20000
    disks = cd.Disk(rng.uniform(-50, 50, (n, 3)), rand_dirs(rng, n), rng.uniform(0.2, 1.0, n))
    scene = cd.Scene()
    scene.extend("disk", disks)
    line = cd.Line([-60, 3, -2], [1, 0.1, 0.05])
    cd.reset_stats()
    best = scene.nearest(line, 3)
    s = cd.stats()
    assert s["solves"] < 0.01 * n, s
    assert s["distances"] < 0.01 * n, s
    d = cd.distance(line, disks)
    order = np.argsort(d, kind="stable")[:3]
    assert best == [(f"disk{i}", d[i]) for i in order]
    expected = [f"disk{i}" for i in np.flatnonzero(cd.within(line, disks, 0.5))]
    cd.reset_stats()
    assert scene.within(line, 0.5) == expected
    assert cd.stats()["solves"] < 0.01 * n


def test_scene_errors():
    scene = cd.Scene({"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0)})
    assert len(scene) == 1 and "ring" in scene
    with pytest.raises(ValueError, match="already"):
        scene.add("ring", cd.Point([0, 0, 0]))
    with pytest.raises(ValueError, match="extend"):
        scene.add("many", cd.Point(np.zeros((2, 3))))
    with pytest.raises(TypeError):
        scene.add("thing", [0, 0, 0])
    with pytest.raises(KeyError, match="nope"):
        scene.nearest("nope")
    with pytest.raises(ValueError, match="k must be"):
        scene.nearest(cd.Point([0, 0, 0]), 0)
    with pytest.raises(ValueError, match="d must be"):
        scene.within(cd.Point([0, 0, 0]), -1)
    with pytest.raises(ValueError, match="2 names"):
        scene.extend(["a", "b"], cd.Point(np.zeros((3, 3))))
    scene.add("cable", cd.Bezier([[0, 0, 0], [1, 1, 0], [2, 0, 0]]))
    # every pair of kinds has a query now, curves against curves too (bezier_bezier.hpp)
    assert ("cable", 0.0) in scene.nearest(cd.Bezier([[0, 0, 0], [1, 0, 0]]), 2)
    with pytest.raises(ValueError, match="single shape"):
        scene.nearest(cd.Point(np.zeros((2, 3))))


def test_extend_names_and_contents():
    scene = cd.Scene()
    scene.extend("p", cd.Point(np.arange(12.0).reshape(4, 3), sweep=[0, 1, 2, 3]))
    scene.add("ring", cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
    assert scene.names == ["p0", "p1", "p2", "p3", "ring"]
    assert float(scene["p2"].sweep) == 2.0
    np.testing.assert_array_equal(scene["p3"].p, [9, 10, 11])
    # From the origin: the ring at 1, then the balls at |p_i| - sweep_i (sqrt 5, sqrt 50 - 1, ...).
    nearest = scene.nearest(cd.Point([0, 0, 0]), 5)
    assert [name for name, _ in nearest] == ["ring", "p0", "p1", "p2", "p3"]
    expected = [1.0] + [np.linalg.norm(np.arange(12.0).reshape(4, 3)[i]) - i for i in range(4)]
    np.testing.assert_allclose([d for _, d in nearest], expected, rtol=1e-15)
    # Adding after a query rebuilds the hierarchy.
    scene.add("close", cd.Point([0.1, 0, 0]))
    assert scene.nearest(cd.Point([0.1, 0, 0]))[0] == ("close", 0.0)


def check_copies(scene):
    """A scene's pickled, deep-copied and copied versions have the same names, the same stored
    arrays (dtypes kept) and the same answers, and are independent of it."""
    import copy
    import pickle

    scene.add("ring32", cd.Circle(np.float32([1, 2, 3]), [0, 0, 1], np.float32(0.5), sweep=np.float32(0.25)))
    before = scene.pairs_within(0.5)  # built: the broadphase is not part of the state
    probe = cd.Circle([0.5, 0.2, 0.1], [0, 1, 1], 1.5)
    for again in (pickle.loads(pickle.dumps(scene)), copy.deepcopy(scene), copy.copy(scene)):
        assert again.names == scene.names and len(again) == len(scene)
        for name in scene.names:
            x, y = scene[name].to_arrays(), again[name].to_arrays()
            assert x.keys() == y.keys()
            for key in x:
                assert x[key].dtype == y[key].dtype and np.array_equal(x[key], y[key])
        for (key, g), (key2, h) in zip(scene._groups.items(), again._groups.items()):
            assert key == key2 and g.kind == h.kind
            for f, e in zip(g.fields, h.fields):
                assert f.dtype == e.dtype and np.array_equal(f, e)
            assert np.array_equal(g.ids, h.ids)
        ring32 = again["ring32"].to_arrays()
        assert {k: v.dtype for k, v in ring32.items()} == {
            "center": np.float32,
            "normal": np.float64,
            "radius": np.float32,
            "sweep": np.float32,
        }
        assert again.pairs_within(0.5) == before
        assert again.nearest(probe, 5) == scene.nearest(probe, 5)
        assert again.within(probe, 1.0) == scene.within(probe, 1.0)
        # Independent: adding to the copy leaves the original as it was.
        extra = cd.Circle([0, 0, 0], [0, 0, 1], 0.1)
        again.add("extra", extra)
        assert "extra" not in scene and len(again) == len(scene) + 1
        assert again.nearest(extra)[0] == ("extra", 0.0)


def test_pickle_and_deepcopy_round_trip():
    import pickle

    lines, _ = mixed_scene(31, n=120, box=5.0, kinds=("Disk", "Circle", "Segment", "Point", "Line"))
    curves, _ = mixed_scene(32, n=60, box=5.0, kinds=("Disk", "Circle"))
    curves.add("curve", cd.Bezier(np.arange(12.0).reshape(4, 3) / 10))
    for scene in (lines, curves):
        check_copies(scene)
    empty = pickle.loads(pickle.dumps(cd.Scene()))
    assert len(empty) == 0 and empty.nearest([0, 0, 0]) == [] and empty.pairs_within(1.0) == []


def test_adding_after_queries_and_mixing_add_and_extend():
    """Single adds wait in lists until a read: reads in between (shape, queries) see every shape,
    in insertion order, whatever the mix of add and extend."""
    rng = np.random.default_rng(12)
    scene = cd.Scene()
    expected = []
    for step in range(30):
        if step % 3 == 0:
            batch = cd.Disk(rng.uniform(-4, 4, (5, 3)), rand_dirs(rng, 5), rng.uniform(0.2, 1, 5))
            scene.extend(f"b{step}_", batch)
            arrays = batch.to_arrays()
            expected += [cd.Disk(arrays["center"][i], arrays["normal"][i], arrays["radius"][i]) for i in range(5)]
        else:
            s = cd.Disk(rng.uniform(-4, 4, 3), rand_dirs(rng, 1)[0], rng.uniform(0.2, 1))
            scene.add(f"s{step}", s)
            expected.append(s)
        if step % 4 == 0:
            name = scene.names[-1]
            assert np.array_equal(scene[name].center, expected[-1].center)
            probe = cd.Point(rng.uniform(-4, 4, 3))
            d = np.array([cd.distance(probe, e) for e in expected])
            order = np.lexsort((np.arange(len(d)), d))[:3]
            assert scene.nearest(probe, 3) == [(scene.names[i], d[i]) for i in order]
    pairs = [
        (scene.names[i], scene.names[j])
        for i in range(len(expected))
        for j in range(i + 1, len(expected))
        if cd.within(expected[i], expected[j], 0.3)
    ]
    assert scene.pairs_within(0.3) == pairs
    assert scene.pairs_within(0.3, workers=2) == pairs


def test_pairs_within_gives_the_same_pairs_for_every_worker_count():
    """Scene.pairs_within's search, grouping, exact tests and order run on the workers: 1, 2, 3
    and 7 of them (each on a scene of its own, whose hierarchy they build) give brute force's
    pairs; Bezier curves and float32 shapes among the groups."""
    scene, shapes = mixed_scene(31, n=500, box=7.0, kinds=("Disk", "Circle", "Segment", "Point"))
    rng = np.random.default_rng(31)
    for k in range(40):
        c = rng.uniform(-7, 7, 3)
        s = cd.Circle(np.float32(c), np.float32(rand_dirs(rng, 1)[0]), np.float32(0.5))
        scene.add(f"f{k}", s)
        shapes.append(s)
    names = scene.names
    expected = [
        (names[i], names[j])
        for i in range(len(shapes))
        for j in range(i + 1, len(shapes))
        if cd.within(shapes[i], shapes[j], 0.3)
    ]
    assert len(expected) > 200
    state = scene.__getstate__()
    for workers in (1, 2, 3, 7):
        fresh = cd.Scene()
        fresh.__setstate__(state)
        assert fresh.pairs_within(0.3, workers=workers) == expected
        assert fresh.pairs_within(0.3, workers=workers) == expected  # the hierarchy built
    assert scene.pairs_within(0.3, workers=-1) == expected
    with pytest.raises(ValueError, match="workers must be a positive integer or -1"):
        scene.pairs_within(0.3, workers=0)


def test_adds_between_queries_grow_the_hierarchy_and_answers_stay_brute_force():
    """Single adds and small batches alternating with queries: each query sees every shape
    (nearest, within, pairs_within equal brute force), the broadphase grows instead of being
    rebuilt (a few trees, at most log2(n) + 1), and pairs_within merges them."""
    rng = np.random.default_rng(44)
    scene = cd.Scene()
    shapes = []
    for step in range(400):
        if step % 25 == 24:
            count = int(rng.integers(2, 30))
            batch = cd.Segment(
                rng.uniform(-6, 6, (count, 3)), rng.uniform(-6, 6, (count, 3)) * 0.1 + rng.uniform(-6, 6, (count, 3))
            )
            scene.extend(f"b{step}_", batch)
            arrays = batch.to_arrays()
            shapes += [cd.Segment(arrays["p0"][i], arrays["p1"][i]) for i in range(count)]
        else:
            kind = step % 3
            c = rng.uniform(-6, 6, 3)
            s = (
                cd.Disk(c, rand_dirs(rng, 1)[0], rng.uniform(0.1, 0.6))
                if kind == 0
                else cd.Point(c, sweep=float(rng.uniform(0, 0.3)))
                if kind == 1
                else cd.Line(c, rand_dirs(rng, 1)[0])
                if step % 30 == 2
                else cd.Circle(c, rand_dirs(rng, 1)[0], 0.4)
            )
            scene.add(f"s{step}", s)
            shapes.append(s)
        if step % 7 == 0 or step == 399:
            probe = cd.Point(rng.uniform(-6, 6, 3))
            d = np.array([cd.distance(probe, e) for e in shapes])
            order = np.lexsort((np.arange(len(d)), d))[:3]
            assert scene.nearest(probe, 3) == [(scene.names[i], d[i]) for i in order]
            assert scene.within(probe, 1.0) == [scene.names[i] for i in np.flatnonzero(d <= 1.0)]
            assert 1 <= scene._broadphase.trees <= np.log2(len(shapes)) + 1
    assert scene._broadphase.trees > 1
    names = scene.names
    pairs = [
        (names[i], names[j])
        for i in range(len(shapes))
        for j in range(i + 1, len(shapes))
        if cd.within(shapes[i], shapes[j], 0.2)
    ]
    assert scene.pairs_within(0.2, workers=2) == pairs
    assert scene._broadphase.trees == 1
    scene.add("last", cd.Point([0, 0, 0]))
    assert scene.nearest([0, 0, 0])[0] == ("last", 0.0)
    assert scene._broadphase.trees == 2


def as_dtype(shape, dtypes):
    """The shape rebuilt from its arrays, field f in dtypes.get(f) (others as they are)."""
    arrays = {k: np.asarray(v, dtype=dtypes.get(k, v.dtype)) for k, v in shape.to_arrays().items()}
    return getattr(cd, shape.kind).from_arrays(arrays)


def dtypes_of(shape):
    return {k: v.dtype for k, v in shape.to_arrays().items()}


def test_shapes_come_back_with_the_dtypes_they_were_added_with():
    """Each field keeps its dtype (float32, float64, long double, mixed within one shape), and a
    shape added without a sweep comes back without one; by add, by extend, in any mix, after
    queries, and through pickling."""
    import pickle

    f32, f64, ld = np.float32, np.float64, np.longdouble
    _, shapes = mixed_scene(41, n=70, box=5.0)
    variants = [
        {},
        {
            "center": f32,
            "normal": f32,
            "radius": f32,
            "p": f32,
            "p0": f32,
            "p1": f32,
            "control_points": f32,
            "sweep": f32,
        },
        {"center": ld, "p": ld, "control_points": ld},
        {"radius": f32, "p1": f32, "sweep": ld},
    ]
    scene, added = cd.Scene(), {}
    for i, s in enumerate(shapes):
        shape = as_dtype(s, variants[i % 4])
        scene.add(f"s{i}", shape)
        added[f"s{i}"] = shape
        if i == 35:
            scene.nearest(cd.Circle([0, 0, 0], [0, 0, 1], 1.0))  # a query in between: arrays consolidated
    batch = cd.Circle(np.float32([[0, 0, 0], [1, 0, 0], [2, 0, 0]]), [0, 0, 1], np.float32([1, 2, 3]))
    scene.extend("b", batch)
    added.update(
        {f"b{i}": cd.Circle(np.float32([i, 0, 0]), np.float64([0, 0, 1]), np.float32(i + 1)) for i in range(3)}
    )
    assert {dt for s in added.values() for dt in dtypes_of(s).values()} == {np.dtype(f32), np.dtype(f64), np.dtype(ld)}
    assert any("sweep" not in s.to_arrays() for s in added.values())
    for copy in (scene, pickle.loads(pickle.dumps(scene))):
        for name, shape in added.items():
            got, want = copy[name].to_arrays(), shape.to_arrays()
            assert got.keys() == want.keys(), name
            for key in want:
                assert got[key].dtype == want[key].dtype and np.array_equal(got[key], want[key]), (name, key)


def test_queries_measure_shapes_as_added_in_any_mix_of_dtypes():
    """Answers equal brute force over the shapes as added: a float32 query among float32 shapes
    gets float32-rounded distances (the library's precision rule), among float64 ones float64."""
    _, shapes = mixed_scene(42, n=90, box=4.0, kinds=("Disk", "Circle", "Segment", "Point"))
    f32 = {k: np.float32 for k in ("center", "normal", "radius", "p", "p0", "p1", "sweep")}
    shapes = [as_dtype(s, f32) if i % 3 else s for i, s in enumerate(shapes)]
    scene = cd.Scene([(f"s{i}", s) for i, s in enumerate(shapes)])
    ring = cd.Circle([0.5, 0.2, 0.1], [0, 1, 1], 1.5)
    for query in (as_dtype(ring, f32), ring):
        d = brute_distances(query, shapes)
        order = sorted(range(len(shapes)), key=lambda i: (d[i], i))[:7]
        assert scene.nearest(query, 7) == [(f"s{i}", float(d[i])) for i in order]
        assert scene.within(query, 1.0) == [f"s{i}" for i in range(len(shapes)) if cd.within(query, shapes[i], 1.0)]
    query32 = as_dtype(ring, f32)
    f64 = {k: np.float64 for k in f32}
    # The float32 shapes are measured in float32 against a float32 query: not as float64 copies.
    rounded = [
        i
        for i in range(len(shapes))
        if i % 3 and cd.distance(query32, shapes[i]) != cd.distance(query32, as_dtype(shapes[i], f64))
    ]
    assert rounded
    i = rounded[0]
    assert scene.distance_matrix([f"s{i}"], ["s0"])[0, 0] == cd.distance(shapes[i], shapes[0])
    names = [n for n, _ in scene.nearest(query32, len(shapes))]
    assert dict(scene.nearest(query32, len(shapes)))[f"s{i}"] == cd.distance(query32, shapes[i]) and f"s{i}" in names
    pairs = [
        (f"s{a}", f"s{b}")
        for a in range(len(shapes))
        for b in range(a + 1, len(shapes))
        if cd.within(shapes[a], shapes[b], 0.3)
    ]
    assert scene.pairs_within(0.3) == pairs


def test_a_pickle_of_float64_groups_without_dtypes_still_loads():
    """Scenes pickled when every group was float64 with a sweep (keys (kind, control points))."""
    import pickle

    scene = cd.Scene({"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0, sweep=0.0), "dot": cd.Point([0, 0, 2])})
    state = scene.__getstate__()
    state["groups"] = [
        ((key[0], key[1]), kind, [np.asarray(f, np.float64) for f in fields], ids)
        for key, kind, fields, ids in state["groups"]
    ]
    old = cd.Scene.__new__(cd.Scene)
    old.__setstate__(pickle.loads(pickle.dumps(state)))
    assert old.names == ["ring", "dot"]
    assert old["dot"].to_arrays().keys() == {"p", "sweep"}
    assert old.nearest(cd.Point([0, 0, 1.5])) == [("dot", 0.5)]


def _state(scene):
    """Everything a scene stores: names, groups (keys, kinds, each field's array with its dtype,
    item numbers) and each item's group and row."""
    state = scene.__getstate__()
    groups = [
        (key, kind, [(f.dtype, f.shape, f.tobytes()) for f in fields], ids.tolist())
        for key, kind, fields, ids in state["groups"]
    ]
    return state["names"], groups, state["item_group"].tolist(), state["item_row"].tolist()


def test_a_scene_added_one_by_one_equals_the_scene_extended_by_batches():
    """Shapes of every kind, dtypes and sweeps (given or not) added one by one, extended as batches
    (one per run of shapes alike: kind, control points, dtypes, sweep given), or half and half, in
    the same order: the same stored scene, shapes and answers; reads in between change nothing."""
    f32, ld = np.float32, np.longdouble
    _, shapes = mixed_scene(43, n=120, box=5.0, kinds=("Disk", "Circle", "Segment", "Point", "Line"))
    _, curves = mixed_scene(44, n=12, box=5.0, kinds=("Bezier",))
    shapes += curves + [cd.Bezier(np.arange(6.0).reshape(2, 3) + i) for i in range(3)]  # another degree
    dtypes = [
        {},
        {"center": f32, "p": f32, "p0": f32, "origin": f32, "control_points": f32, "sweep": f32},
        {"radius": ld, "p1": ld, "direction": ld},
    ]
    shapes = [as_dtype(s, dtypes[(i // 5) % 3]) for i, s in enumerate(shapes)]
    runs = []  # [signature, [(name, shape), ...]]: consecutive shapes that one batch can hold
    for i, s in enumerate(shapes):
        arrays = s.to_arrays()
        signature = (s.kind, arrays[next(iter(arrays))].shape, tuple((k, v.dtype) for k, v in arrays.items()))
        if not runs or runs[-1][0] != signature:
            runs.append([signature, []])
        runs[-1][1].append((f"s{i}", s))
    assert len(runs) > 20 and max(len(r) for _, r in runs) >= 5
    one_by_one, batched, mixed = cd.Scene(), cd.Scene(), cd.Scene()
    for n, (_, run) in enumerate(runs):
        arrays = [s.to_arrays() for _, s in run]
        batch = getattr(cd, run[0][1].kind).from_arrays({k: np.stack([a[k] for a in arrays]) for k in arrays[0]})
        batched.extend([name for name, _ in run], batch)
        for name, s in run:
            one_by_one.add(name, s)
        if n % 2:
            mixed.extend([name for name, _ in run], batch)
        else:
            for name, s in run:
                mixed.add(name, s)
        if n % 7 == 3:  # a read in between: the single shapes so far move into the arrays
            assert one_by_one[run[-1][0]].kind == run[-1][1].kind
    assert _state(one_by_one) == _state(batched) == _state(mixed)
    for name, s in zip(one_by_one.names, shapes):
        for scene in (one_by_one, batched, mixed):
            got, want = scene[name].to_arrays(), s.to_arrays()
            assert got.keys() == want.keys()
            assert all(got[k].dtype == want[k].dtype and np.array_equal(got[k], want[k]) for k in want)
    probe = cd.Circle([0.5, 0.2, 0.1], [0, 1, 1], 1.5)
    answers = [
        (s.nearest(probe, 9), s.within(probe, 0.7), s.nearest("s7", 4), s.within("s3", 1.0))
        for s in (one_by_one, batched, mixed)
    ]
    assert answers[0] == answers[1] == answers[2]
    d = brute_distances(probe, shapes)
    assert answers[0][0] == [(f"s{i}", d[i]) for i in sorted(range(len(shapes)), key=lambda i: (d[i], i))[:9]]


def test_names_are_checked_as_before_in_batches():
    """extend refuses as add does (the first bad name, in order), whether the names are given or
    made from a prefix, and leaves the scene as it was."""
    scene = cd.Scene()
    scene.extend("d", cd.Point(np.zeros((3, 3))))
    before = _state(scene)
    three = cd.Point(np.ones((3, 3)))
    for names, error, message in [
        (["a", "b", "a"], ValueError, "a shape named 'a' is already in the scene"),
        (["a", "d1", "d1"], ValueError, "a shape named 'd1' is already in the scene"),
        (["a", 7, "a"], TypeError, "shape names must be strings, got 7"),
        (["a", None, "b"], TypeError, "shape names must be strings, got None"),
        (["a", ["x"], "b"], TypeError, r"shape names must be strings, got \['x'\]"),
        ("d", ValueError, "a shape named 'd0' is already in the scene"),
        (["x", "y"], ValueError, "2 names for a batch of 3 shapes"),
    ]:
        with pytest.raises(error, match=message):
            scene.extend(names, three)
        assert _state(scene) == before

    class Name(str):
        pass

    scene.extend([Name("e0"), "e1", Name("e2")], three)  # str subclasses are strings
    scene.extend("f", three)
    assert scene.names == ["d0", "d1", "d2", "e0", "e1", "e2", "f0", "f1", "f2"]


def _prefix_pairs(pairs, names, n):
    """The pairs among the first n shapes of a list of all pairs (sorted by index)."""
    index = {name: i for i, name in enumerate(names)}
    return [p for p in pairs if index[p[1]] < n]


def _prefix_nearest(distances, names, n, k):
    d = distances[:n]
    order = np.lexsort((np.arange(n), d))[:k]
    return [(names[i], float(d[i])) for i in order]


@pytest.mark.parametrize("seed", [0, 1])
def test_a_scene_shared_by_threads_answers_as_serial_queries_do(seed):
    """Two threads ask pairs_within, one nearest and within, while one adds shapes one by one
    (and in small batches): each answer is the serial answer of a scene state between the
    query's start and its end (a prefix of the adds), the scene ends as the serial scene, and
    nothing raises or crashes (the hierarchy grows with the GIL released while others read)."""
    import pickle
    import threading
    import time

    rng = np.random.default_rng(seed)
    first, added = 2000, 700
    n = first + added
    centers = rng.uniform(0, 1, (n, 3))
    sweeps = rng.uniform(0, 0.004, n)
    names = [f"p{i}" for i in range(n)]
    line = cd.Line([-1, 0.5, 0.5], [1, 0.2, 0.1])
    probe = cd.Point([0.5, 0.5, 0.5])
    d = 0.05
    # Serial references, by brute force over every shape (batched distances).
    balls = cd.Point(centers, sweep=sweeps)
    near = np.asarray(cd.within(cd.Point(centers[:, None], sweep=sweeps[:, None]), balls, d))
    i, j = np.nonzero(np.triu(near, 1))
    all_pairs = [(names[a], names[b]) for a, b in zip(i, j)]
    line_distances = np.asarray(cd.distance(line, balls))
    probe_distances = np.asarray(cd.distance(probe, balls))

    scene = cd.Scene()
    scene.extend([names[i] for i in range(first)], cd.Point(centers[:first], sweep=sweeps[:first]))
    scene.nearest(probe)  # the first hierarchy: later adds grow it
    seen, failures = [], []
    done = threading.Event()

    def guarded(body):
        def run():
            try:
                body()
            except BaseException as error:  # noqa: BLE001 (reported by the main thread)
                failures.append(error)
                done.set()

        return run

    def adder():
        at = first
        while at < n:
            if at % 50 == 0 and at + 5 <= n:
                scene.extend(names[at : at + 5], cd.Point(centers[at : at + 5], sweep=sweeps[at : at + 5]))
                at += 5
            else:
                scene.add(names[at], cd.Point(centers[at], sweep=sweeps[at]))
                at += 1
            if at % 64 == 0:
                time.sleep(0.001)
        done.set()

    def pairs_reader():
        while not done.is_set():
            before = len(scene)
            got = scene.pairs_within(d)
            seen.append(("pairs", before, len(scene), got))

    def nearest_reader():
        while not done.is_set():
            before = len(scene)
            got = scene.nearest(line, k=3)
            inside = scene.within(probe, 0.1)
            seen.append(("nearest", before, len(scene), got))
            seen.append(("within", before, len(scene), inside))

    threads = [threading.Thread(target=guarded(f)) for f in (adder, pairs_reader, pairs_reader, nearest_reader)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(120)
    assert not failures, failures
    assert not any(t.is_alive() for t in threads)
    kinds = {kind for kind, *_ in seen}
    assert kinds == {"pairs", "nearest", "within"}, kinds
    for kind, before, after, got in seen:
        if kind == "pairs":
            serial = [_prefix_pairs(all_pairs, names, m) for m in range(before, after + 1)]
        elif kind == "nearest":
            serial = [_prefix_nearest(line_distances, names, m, 3) for m in range(before, after + 1)]
        else:
            serial = [[names[i] for i in np.flatnonzero(probe_distances[:m] <= 0.1)] for m in range(before, after + 1)]
        assert got in serial, (kind, before, after)
    # The end state: the serial scene's.
    assert scene.names == names
    assert scene.pairs_within(d) == all_pairs
    assert scene.nearest(line, k=3) == _prefix_nearest(line_distances, names, n, 3)
    serial_scene = cd.Scene()
    for i in range(n):
        serial_scene.add(names[i], cd.Point(centers[i], sweep=sweeps[i]))
    ours, theirs = pickle.loads(pickle.dumps(scene)), serial_scene
    for name in names[::97]:
        for key, value in ours[name].to_arrays().items():
            np.testing.assert_array_equal(value, theirs[name].to_arrays()[key])
    assert ours.pairs_within(d) == theirs.pairs_within(d) == all_pairs


def _tampered(state, how):
    """A copy of a scene's state with one inconsistency of the family `how`."""
    import copy

    state = copy.deepcopy(state)
    groups = [list(g) for g in state["groups"]]
    state["groups"] = groups
    if how == "duplicated_ids":  # two rows of a group claim one item; another item is in none
        groups[0][3] = groups[0][3].copy()
        groups[0][3][1] = groups[0][3][0]
    elif how == "swapped_ids":  # every id valid and distinct, but not where item_group/item_row say
        groups[0][3] = groups[0][3][::-1].copy()
    elif how == "id_out_of_range":
        groups[0][3] = groups[0][3].copy()
        groups[0][3][0] = len(state["names"]) + 5
    elif how == "row_out_of_range":
        state["item_row"] = state["item_row"].copy()
        state["item_row"][0] = 10_000
    elif how == "group_out_of_range":
        state["item_group"] = state["item_group"].copy()
        state["item_group"][0] = len(groups)
    elif how == "short_item_column":
        state["item_group"] = state["item_group"][:-1]
    elif how == "duplicated_name":
        state["names"][1] = state["names"][0]
    elif how == "name_not_a_string":
        state["names"][0] = 3
    elif how == "fewer_rows_than_ids":
        groups[0][2] = [f[:-1] for f in groups[0][2]]
    elif how == "missing_field":
        groups[0][2] = groups[0][2][:-1]
    elif how == "unknown_kind":
        groups[0][1] = "Sphere"
    elif how == "negative_radius":  # group 0 holds disks (mixed_scene's first kind)
        groups[0][2] = [f.copy() for f in groups[0][2]]
        groups[0][2][2][0] = -1.0
    elif how == "not_a_dict":
        state = [state]
    else:
        raise AssertionError(how)
    return state


TAMPERED = [
    "duplicated_ids",
    "swapped_ids",
    "id_out_of_range",
    "row_out_of_range",
    "group_out_of_range",
    "short_item_column",
    "duplicated_name",
    "name_not_a_string",
    "fewer_rows_than_ids",
    "missing_field",
    "unknown_kind",
    "negative_radius",
    "not_a_dict",
]


@pytest.mark.parametrize("how", TAMPERED)
def test_unpickling_a_tampered_scene_is_a_value_error(how):
    """A pickle is data: a state whose names, groups and item columns disagree (duplicated ids
    answered nearest wrongly, silently) or whose shapes are invalid does not load."""
    import copyreg
    import pickle

    scene, _ = mixed_scene(61, n=40, box=4.0, kinds=("Disk", "Point"))
    state = _tampered(scene.__getstate__(), how)

    class Forged:  # pickles as a Scene of the given state (what a tampered file holds)
        def __reduce__(self):
            return copyreg._reconstructor, (cd.Scene, object, None), state

    data = pickle.dumps(Forged())
    with pytest.raises(ValueError, match="Scene: the pickled state is invalid"):
        pickle.loads(data)
    # The state as written loads, and answers as the scene does.
    loaded = pickle.loads(pickle.dumps(scene))
    assert loaded.nearest([0, 0, 0], k=5) == scene.nearest([0, 0, 0], k=5)
