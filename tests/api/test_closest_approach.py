"""circledist.closest_approach: the least distance of moving shapes over [0, 1] against a 50-digit
reference (circledist_cases.accuracy.reference_distance of the shapes moved in mpmath, minimised
over t by dense sampling and refinement), on random pairs of several kinds and the hard cases (a
ring spinning about its axis, coaxial rings, a ring through an annulus's hole, many turns, a
scene 1e6 from the origin, the least at t = 0 and t = 1, tangential grazes, many near-equal
dips against a closed form at 50 digits); both argument orders to the bit, broadcasting,
precisions, workers, progress, stats, the errors and the evaluation limit."""

import numpy as np
import pytest
from mpmath import mp, mpf

from circledist_cases.accuracy import reference_distance
from circledist_cases.shapes import random_fields, random_motion, same_bits, swapped_agree

cd = pytest.importorskip("circledist")

BAR = 1e-12  # 1e-12 times the query's size (docs/derivations/motion.md)
ANSWERS = ("time", "distance", "point_a", "point_b", "param_a", "param_b", "unique")
RING = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
LAYOUT = {  # the fields of each kind in reference_distance's value layout
    "Point": ("p",),
    "Line": ("origin", "direction"),
    "Ray": ("origin", "direction"),
    "Segment": ("p0", "p1"),
    "Circle": ("center", "normal", "radius"),
    "Disk": ("center", "normal", "radius"),
    "Arc": ("center", "normal", "radius", "start", "angle"),
    "Annulus": ("center", "normal", "inner_radius", "outer_radius"),
    "Bezier": ("control_points",),
}
VECTORS = {"direction", "normal", "start"}  # rotate; the other 3-vectors move as points


def _rotation(w):
    """R(w) in mpmath at 50 digits (Rodrigues' formula with 1 - cos as 2 sin^2(theta / 2))."""
    theta = mp.sqrt(sum(x * x for x in w))
    if theta == 0:
        return [[mpf(int(i == j)) for j in range(3)] for i in range(3)]
    k = [x / theta for x in w]
    c, s, h = mp.cos(theta), mp.sin(theta), 2 * mp.sin(theta / 2) ** 2
    cross = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[(c if i == j else 0) + s * cross[i][j] + h * k[i] * k[j] for j in range(3)] for i in range(3)]


def _mp(x):
    return mpf(float(x))  # exact: a double is a binary fraction


def _moved_values(shape, motion, t):
    """The shape's values (reference_distance's layout) moved to time t in mpmath and rounded to
    double (the references take doubles; the rounding moves the shape by an ulp of its size,
    far inside the bar), its kind's name for reference_distance, and its sweep."""
    kind = type(shape).__name__
    fields = shape.to_arrays()
    m = {name: [_mp(x) for x in np.asarray(v, dtype=float)] for name, v in motion.to_arrays().items()}
    t = mpf(str(t)) if isinstance(t, str) else _mp(t)
    r = _rotation([t * x for x in m["rotation"]])

    def rotate(v):
        return [sum(r[i][j] * v[j] for j in range(3)) for i in range(3)]

    def point(p):
        d = rotate([p[i] - m["center"][i] for i in range(3)])
        return [m["center"][i] + d[i] + t * m["translation"][i] for i in range(3)]

    values = []
    if kind == "Bezier":
        control = np.asarray(fields["control_points"], dtype=float)
        values.append(len(control))
        for p in control:
            values += point([_mp(x) for x in p])
    else:
        for name in LAYOUT[kind]:
            v = np.asarray(fields[name], dtype=float)
            if v.shape == (3,):
                v = [_mp(x) for x in v]
                values += rotate(v) if name in VECTORS else point(v)
            else:
                values.append(_mp(v))
    sweep = float(fields.get("sweep", 0.0))
    return kind.lower(), [float(v) for v in values], sweep


RANK = {"point": 0, "segment": 0, "line": 0, "ray": 0, "bezier": 1, "circle": 2, "disk": 3, "arc": 4, "annulus": 5}


def _point_segment(p, q0, q1):
    """The 50-digit distance of a point and a segment (or a point: q0 == q1)."""
    p, q0, q1 = ([_mp(x) for x in v] for v in (p, q0, q1))
    d = [q1[i] - q0[i] for i in range(3)]
    dd = sum(x * x for x in d)
    s = min(max(sum((p[i] - q0[i]) * d[i] for i in range(3)) / dd, 0), 1) if dd else mpf(0)
    return mp.sqrt(sum((p[i] - q0[i] - s * d[i]) ** 2 for i in range(3)))


def reference_at(a, b, ma, mb, t):
    """The 50-digit distance of a(t) and b(t) (mpf): reference_distance's, with the rounder
    shape second, or for a point against a point or a segment the closed form here."""
    ka, va, sa = _moved_values(a, ma, t)
    kb, vb, sb = _moved_values(b, mb, t)
    if RANK[ka] > RANK[kb]:
        (ka, va), (kb, vb) = (kb, vb), (ka, va)
    if ka == "point" and kb in ("point", "segment"):
        va, vb = (va, vb) if ka == "point" else (vb, va)
        core = _point_segment(va[:3], vb[:3], vb[-3:])
    elif ka == "segment" and kb == "point":
        core = _point_segment(vb[:3], va[:3], va[3:6])
    else:
        core = mpf(reference_distance(f"{ka}-{kb}", tuple(va) + tuple(vb)))
    return max(mpf(0), core - _mp(sa) - _mp(sb))


def _distances(a, b, ma, mb, times):
    return np.asarray(cd.distance(a.moved(ma, times), b.moved(mb, times)), dtype=float)


def reference_least(a, b, ma, mb, samples=2001):
    """The least distance over [0, 1]: d(t) sampled densely, each of the three least local minima
    of the samples refined by golden section on the sampled function, then at 50 digits: the
    reference distance at the refined time and at a parabola's vertex through it and two
    neighbours. Returns the least 50-digit value found (an upper bound of the least, exact to
    the refinement's rounding) as a float."""
    times = np.linspace(0.0, 1.0, samples)
    d = _distances(a, b, ma, mb, times)
    left = np.r_[np.inf, d[:-1]]
    right = np.r_[d[1:], np.inf]
    minima = np.flatnonzero((d <= left) & (d <= right))
    minima = minima[np.argsort(d[minima])][:3]
    best = None
    for k in minima:
        lo, hi = times[max(k - 1, 0)], times[min(k + 1, samples - 1)]
        g = (np.sqrt(5) - 1) / 2
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        f1, f2 = _distances(a, b, ma, mb, np.array([x1, x2]))
        for _ in range(80):
            if f1 <= f2:
                hi, x2, f2 = x2, x1, f1
                x1 = hi - g * (hi - lo)
                f1 = _distances(a, b, ma, mb, np.array([x1]))[0]
            else:
                lo, x1, f1 = x1, x2, f2
                x2 = lo + g * (hi - lo)
                f2 = _distances(a, b, ma, mb, np.array([x2]))[0]
        if best is not None and min(f1, f2) > best[1] + 1e-9:
            continue  # a local least well above the best: not the least
        t = x1 if f1 <= f2 else x2
        e = 1e-7
        ts = [min(max(t + s, 0.0), 1.0) for s in (-e, 0.0, e)]
        vs = [reference_at(a, b, ma, mb, s) for s in ts]
        value = min(vs)
        h0, h1 = mpf(ts[1]) - mpf(ts[0]), mpf(ts[2]) - mpf(ts[1])
        curvature = (vs[2] - vs[1]) / h1 - (vs[1] - vs[0]) / h0 if h0 and h1 else mpf(0)
        if curvature > 0:
            vertex = float(mpf(ts[1]) - ((vs[2] - vs[0]) / (h0 + h1)) / (2 * curvature / (h0 + h1)))
            if 0.0 <= vertex <= 1.0:
                value = min(value, reference_at(a, b, ma, mb, vertex))
        if best is None or float(value) < best[1]:
            best = (value, float(value))
    return best[1]


def query_size(a, b, ma, mb):
    """An upper bound of the query's size S (docs/derivations/motion.md): each shape's largest
    field at both ends, each translation, and a rotating shape's swing (|center| + its reach from
    the center, bounded by its farthest point field plus its largest radius and sweep, + travel)."""
    size = 0.0
    for shape, motion in ((a, ma), (b, mb)):
        m = {k: np.asarray(v, dtype=float) for k, v in motion.to_arrays().items()}
        travel = float(np.linalg.norm(m["translation"]))
        for t in (0.0, 1.0):
            arrays = shape.moved(motion, t).to_arrays()
            size = max(size, max(float(np.max(np.abs(v))) for v in arrays.values()) + float(arrays.get("sweep", 0)))
        size = max(size, travel)
        if np.linalg.norm(m["rotation"]) > 0:
            arrays = {k: np.asarray(v, dtype=float) for k, v in shape.to_arrays().items()}
            points = [v.reshape(-1, 3) for k, v in arrays.items() if v.shape[-1:] == (3,) and k not in VECTORS]
            far = max(float(np.max(np.linalg.norm(p - m["center"], axis=-1))) for p in points)
            radii = [float(v) for k, v in arrays.items() if v.ndim == 0]
            size = max(size, float(np.linalg.norm(m["center"])) + far + max(radii, default=0.0) + travel)
    return size


def check_against_reference(a, b, ma, mb):
    c = cd.closest_approach(a, b, ma, mb)
    size = query_size(a, b, ma, mb)
    reference = reference_least(a, b, ma, mb)
    assert abs(c.distance - reference) <= BAR * size, (c.distance, reference, size)
    assert 0.0 <= c.time <= 1.0
    # closest_points' distance of the moved shapes at that time, to the bit.
    assert c.distance == _distances(a, b, ma, mb, np.array([c.time]))[0]
    assert np.linalg.norm(c.point_a - c.point_b) == pytest.approx(c.distance, abs=BAR * size)
    swapped_agree(c, cd.closest_approach(b, a, mb, ma))
    return c, reference, size


PAIRS = [
    ("Point", "Circle"),
    ("Segment", "Disk"),
    ("Circle", "Circle"),
    ("Circle", "Disk"),
    ("Disk", "Disk"),
    ("Point", "Annulus"),
    ("Arc", "Annulus"),
    ("Segment", "Arc"),
    ("Circle", "Arc"),
    ("Bezier", "Circle"),
    ("Line", "Disk"),
    ("Ray", "Arc"),
]


@pytest.mark.parametrize("kinds", PAIRS, ids="-".join)
def test_random_pairs_against_the_reference(kinds):
    """Two random moving pairs of each kind (one swept where the reference takes sweeps): the
    least distance within 1e-12 S of the 50-digit reference; both orders to the bit."""
    rng = np.random.default_rng(sum(map(ord, "".join(kinds))) + 7)
    for case in range(2):
        a, b = (getattr(cd, kind)(**random_fields(cd, kind, rng, sweep=bool(case))) for kind in kinds)
        if not case:  # apart by 2 at the start: a least above 0, mostly
            b = b.moved(cd.Motion(translation=[2, 0, 0]), 1.0)
        check_against_reference(a, b, random_motion(cd, rng, kinds[0]), random_motion(cd, rng, kinds[1]))


def test_a_ring_spinning_about_its_axis_is_at_rest():
    """The distance never changes: time 0, one evaluation, not unique; off the axis it moves."""
    point = cd.Point([2.5, 0.3, 0.7])
    for rotation in ([0, 0, 8 * np.pi], [0, 0, -1e9]):
        cd.reset_stats()
        c = cd.closest_approach(RING, point, cd.Motion(rotation=rotation))
        assert cd.stats()["distances"] == 1
        assert c.time == 0.0 and c.unique is False
        assert c.distance == cd.distance(RING, point)
    # Spinning about a parallel axis through another center: the ring circles it.
    swing = cd.Motion(rotation=[0, 0, np.pi], center=[1.5, 0, 0])
    c, reference, _ = check_against_reference(RING, point, swing, cd.Motion())
    assert c.unique is True


def test_coaxial_rings_and_a_ring_through_an_annulus():
    """Every rim point at once (not unique): the smaller ring rising through the larger's plane,
    least 0.5 level with it; a ring of radius 0.3 through a hole of radius 0.5, least 0.2."""
    small = cd.Circle([0, 0, -1], [0, 0, 1], 0.5)
    c, reference, size = check_against_reference(small, RING, cd.Motion(translation=[0, 0, 2]), cd.Motion())
    assert abs(reference - 0.5) <= 1e-15 and abs(c.time - 0.5) <= 1e-6 and c.unique is False
    washer = cd.Annulus([0, 0, 0], [0, 0, 1], 0.5, 1.0)
    thread = cd.Circle([0, 0, -2], [0, 0, 1], 0.3)
    c, reference, _ = check_against_reference(thread, washer, cd.Motion(translation=[0, 0, 4]), cd.Motion())
    assert abs(c.distance - 0.2) <= BAR * 4 and c.unique is False
    tilted = cd.Circle([0.1, 0, -2], [0, 0.1, 1], 0.3)  # off center and tilted: still through the hole
    c, reference, _ = check_against_reference(tilted, washer, cd.Motion(translation=[0, 0, 4]), cd.Motion())
    assert 0.05 < c.distance < 0.2


def test_many_turns_and_far_scenes():
    """A ring tumbling 20 times past a point (the least |p| - 1 forty times: not unique); a clock
    hand turning once about z 1e6 from the origin past a point off its plane (least at its tip)."""
    p = cd.Point([0, 0.6, 0.9])
    c, reference, size = check_against_reference(RING, p, cd.Motion(rotation=[40 * np.pi, 0, 0]), cd.Motion())
    assert abs(c.distance - (np.sqrt(1.17) - 1)) <= BAR * size and c.unique is False
    for shift in (np.zeros(3), np.array([1e6, -1e6, 1e6])):
        hand = cd.Segment(shift, shift + [1, 0, 0])
        q = cd.Point(shift + [1.5 * np.cos(2.0), 1.5 * np.sin(2.0), 0.25])
        turn = cd.Motion(rotation=[0, 0, 2 * np.pi], center=shift)
        c, reference, size = check_against_reference(hand, q, turn, cd.Motion())
        assert abs(c.distance - np.sqrt(0.3125)) <= BAR * size and abs(c.time - 1 / np.pi) <= 1e-5


def test_least_at_the_ends_and_tangential_grazes():
    away = cd.closest_approach(cd.Point([2, 0, 0]), RING, cd.Motion(translation=[3, 1, 0]))
    assert away.time == 0.0 and away.distance == 1.0 and away.unique is True
    closer = check_against_reference(cd.Point([5, 0, 0]), RING, cd.Motion(translation=[-2, 0, 1]), cd.Motion())[0]
    assert closer.time == 1.0
    # A point along a tangent of the ring touches it at t = 0.5 only; 1e-6 outside it, it misses.
    for gap in (0.0, 1e-6):
        c, reference, size = check_against_reference(
            cd.Point([-5, 1 + gap, 0]), RING, cd.Motion(translation=[10, 0, 0]), cd.Motion()
        )
        assert abs(c.distance - gap) <= BAR * size and abs(c.time - 0.5) <= 1e-5
        assert c.unique is True  # one instant: its neighbourhood within the bar is the same dip
    # A point sliding across a disk's face: distance 0 over a stretch, so not unique (though
    # closest_points' pair is unique at any one time).
    disk = cd.Disk([0, 0, 0], [0, 0, 1], 2.0)
    across = cd.closest_approach(cd.Point([-0.5, 0.2, 0]), disk, cd.Motion(translation=[1, 0, 0]))
    assert across.distance == 0.0 and across.unique is False
    # A segment sliding along a disk's face 1e-9 above it: least 1e-9 over a stretch (not unique).
    segment = cd.Segment([-0.5, 0, 1e-9], [0.5, 0, 1e-9])
    slide = cd.closest_approach(segment, disk, cd.Motion(translation=[1, 0, 0]))
    assert abs(slide.distance - 1e-9) <= BAR * 3 and slide.unique is False


def _tumbling_ring_least(w, p, v, samples):
    """The least over [0, 1] of the distance of the unit ring about the origin tumbling about x
    at w rad per unit time and the point p + (v t, 0, 0), in closed form (the ring's normal
    n = R_x(w t) e_z, the point's height h = p.n over its plane and distance rho from its axis,
    d = |(rho - 1, h)|): sampled in double, then every local least of the samples refined by
    golden section at 50 digits."""

    def at(t):
        px = p[0] + v * t
        h = -p[1] * np.sin(w * t) + p[2] * np.cos(w * t)
        rho = np.sqrt(np.maximum(px * px + p[1] ** 2 + p[2] ** 2 - h * h, 0))
        return np.hypot(rho - 1, h)

    def exact(t):
        px, y, z = _mp(p[0]) + _mp(v) * t, _mp(p[1]), _mp(p[2])
        h = -y * mp.sin(_mp(w) * t) + z * mp.cos(_mp(w) * t)
        rho = mp.sqrt(max(px * px + y * y + z * z - h * h, mpf(0)))
        return mp.sqrt((rho - 1) ** 2 + h * h)

    times = np.linspace(0.0, 1.0, samples)
    d = at(times)
    minima = np.flatnonzero((d <= np.r_[np.inf, d[:-1]]) & (d <= np.r_[d[1:], np.inf]))
    g = (mp.sqrt(5) - 1) / 2
    least = min(exact(mpf(t)) for t in (0, 1))
    for k in minima:
        lo, hi = mpf(float(times[max(k - 1, 0)])), mpf(float(times[min(k + 1, samples - 1)]))
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        f1, f2 = exact(x1), exact(x2)
        for _ in range(70):
            if f1 <= f2:
                hi, x2, f2 = x2, x1, f1
                x1 = hi - g * (hi - lo)
                f1 = exact(x1)
            else:
                lo, x1, f1 = x1, x2, f2
                x2 = lo + g * (hi - lo)
                f2 = exact(x2)
        least = min(least, f1, f2)
    return float(least)


@pytest.mark.parametrize("phi", [0.3, 2.2])
def test_many_near_equal_dips_are_all_polished(phi):
    """A ring tumbling 20 times past a point 1e-3 outside it, the point drifting slowly along the
    axis it tumbles about: 40 dips (twice a turn the ring's plane holds the point) whose leasts,
    about |p(t)| - 1, differ by as little as 1e-11 S, far below the search's screen; its samples
    mis-order the dips, and only polishing every one finds the least within 1e-12 S."""
    w, ring = 40 * np.pi, RING
    for v in (3e-4, 1e-3):
        for k in range(3):
            p = np.array([-v / 2 + k * v / 40 / 3, 1.001 * np.cos(phi), 1.001 * np.sin(phi)])
            tumble, drift = cd.Motion(rotation=[w, 0, 0]), cd.Motion(translation=[v, 0, 0])
            c = cd.closest_approach(ring, cd.Point(p), tumble, drift)
            size = query_size(ring, cd.Point(p), tumble, drift)
            reference = _tumbling_ring_least(w, p, v, 1601)
            assert abs(c.distance - reference) <= BAR * size, (v, k, c.distance, reference, size)
            assert c.distance == _distances(ring, cd.Point(p), tumble, drift, np.array([c.time]))[0]


def test_broadcasts_shapes_over_motions():
    rng = np.random.default_rng(3)
    points = cd.Point(rng.uniform([-1, -1, 1], [1, 1, 3], size=(4, 1, 3)))
    disk = cd.Disk([0, 0, 0], [0, 0, 1], 2.0)
    t = np.array([[0.3, 0, -4], [0, 0.2, -1.5], [0.5, 0.5, -0.5]])
    motions = cd.Motion(translation=t, rotation=[[0, 0, 0], [0.3, 0.2, 0], [0, 0, 3]])
    c = cd.closest_approach(points, disk, motions)
    assert c.time.shape == (4, 3) and c.point_a.shape == (4, 3, 3) and c.param_b.shape == (4, 3, 2)
    assert c.unique.shape == (4, 3) and c.unique.dtype == bool
    for i in range(4):
        for j in range(3):
            one = cd.closest_approach(
                cd.Point(points.p[i, 0]), disk, cd.Motion(translation=t[j], rotation=motions.rotation[j])
            )
            for name in ANSWERS:
                same_bits(getattr(c, name)[i, j], getattr(one, name))
    swapped_agree(c, cd.closest_approach(disk, points, None, motions))
    assert repr(cd.closest_approach(cd.Point([3, 0, 0]), RING)).startswith("Approach(time=0.0, distance=2.0")


def test_every_pair_of_kinds_in_both_orders():
    rng = np.random.default_rng(12)
    kinds = sorted({k for pair in cd._core._query_kinds() for k in pair})
    for first in kinds:
        for second in kinds:
            a = getattr(cd, first)(**random_fields(cd, first, rng, batch=(2,)))
            b = getattr(cd, second)(**random_fields(cd, second, rng, batch=(2,)))
            ma = cd.Motion(translation=rng.normal(size=(2, 3)) * 3)
            mb = random_motion(cd, rng, second)
            c = cd.closest_approach(a, b, ma, mb)
            assert np.isfinite(c.distance).all() and ((0 <= c.time) & (c.time <= 1)).all()
            swapped_agree(c, cd.closest_approach(b, a, mb, ma))


def test_precisions():
    point, motion = cd.Point([-3, 2, 1]), cd.Motion(translation=[6, 0, 0])
    double = cd.closest_approach(point, RING, motion)
    assert abs(double.distance - np.sqrt(2)) <= BAR * 6 and abs(double.time - 0.5) <= 1e-6
    wide = cd.closest_approach(cd.Point(np.array([-3, 2, 1], dtype=np.longdouble)), RING, motion)
    assert isinstance(wide.time, np.longdouble) and wide.point_a.dtype == np.longdouble
    assert abs(wide.distance - np.sqrt(np.longdouble(2))) <= BAR * 6
    single = cd.closest_approach(
        cd.Point(np.array([-3, 2, 1], np.float32)), RING.moved(cd.Motion(), 0.0), cd.Motion(), precision="float32"
    )
    assert single.point_a.dtype == np.float32


def test_workers_progress_and_stats():
    rng = np.random.default_rng(5)
    points = cd.Point(rng.normal(size=(200, 3)) * 3)
    motions = cd.Motion(translation=rng.normal(size=(200, 3)) * 4, rotation=rng.normal(size=(200, 3)))
    cd.reset_stats()
    one = cd.closest_approach(points, RING, motions)
    counted = cd.stats()
    assert counted["closest_points"] == 200 and counted["distances"] >= 400
    calls = []
    two = cd.closest_approach(points, RING, motions, workers=2, progress=lambda *a: calls.append(a))
    for name in ANSWERS:
        same_bits(getattr(one, name), getattr(two, name))
    assert calls[-1] == (200, 200)


@pytest.mark.parametrize("query", ["first_contact", "closest_approach"])
def test_the_evaluation_limit_is_an_error_naming_the_element(query):
    """A ring tumbling at 1e9 rad per unit time past a point: more evaluations than the limit
    (2**20) to exclude every time; a RuntimeError naming the batch element, never an answer."""
    rates = np.zeros((3, 3))
    rates[:, 0] = [1.0, 1.0, 1e9]
    turning = cd.Motion(rotation=rates)
    with pytest.raises(RuntimeError, match=rf"{query}: query\[2\] needs more than 1048576 distance evaluations"):
        getattr(cd, query)(RING, cd.Point([0, 0, 1.5]), turning)
    with pytest.raises(RuntimeError, match=rf"{query}: the query needs more than 1048576"):
        getattr(cd, query)(RING, cd.Point([0, 0, 1.5]), cd.Motion(rotation=[1e9, 0, 0]))


def test_argument_errors():
    point = cd.Point([3, 0, 0])
    with pytest.raises(TypeError, match="closest_approach: motion_a must be a circledist.Motion or None, got str"):
        cd.closest_approach(point, RING, "up")
    with pytest.raises(TypeError, match="closest_approach: motion_b must be a circledist.Motion or None, got list"):
        cd.closest_approach(point, RING, None, [1, 0, 0])
    with pytest.raises(TypeError):
        cd.closest_approach(point, RING, within=0.5)
    with pytest.raises(ValueError, match=r"closest_approach: motion_b of batch shape \(2,\) does not broadcast"):
        cd.closest_approach(cd.Point(np.zeros((3, 3))), RING, None, cd.Motion(translation=np.zeros((2, 3))))
    with pytest.raises(ValueError, match="closest_approach: batch shapes"):
        cd.closest_approach(cd.Point(np.zeros((3, 3))), cd.Point(np.zeros((2, 3))))
    with pytest.raises(ValueError, match="workers must be a positive integer or -1"):
        cd.closest_approach(point, RING, workers=0)
    line = cd.Line(np.zeros((3, 3)) + [0, 0, 5], [1, 0, 0])
    rotations = np.zeros((3, 3))
    rotations[2] = [0, 0, 1]
    message = r"closest_approach: motion_a\[2\] rotates the first argument, a Line: a line or ray cannot rotate"
    with pytest.raises(ValueError, match=message):
        cd.closest_approach(line, RING, cd.Motion(rotation=rotations))
    message = r"closest_approach: motion_b\[2\] rotates the second argument, a Line"
    with pytest.raises(ValueError, match=message):
        cd.closest_approach(RING, line, None, cd.Motion(rotation=rotations))
