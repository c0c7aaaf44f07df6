"""circledist.first_contact: analytic contacts (a point driven straight at a ring, a ring turning
through a point, contact at the start, no contact), broadcasting over shapes and motions, both
argument orders to the bit, precisions, the errors, and random moving pairs of several kinds
against a reference made here by dense sampling of distance(a.moved(ma, t), b.moved(mb, t)) and
bisection of the first crossing."""

import numpy as np
import pytest

from circledist_cases.shapes import random_fields, random_motion, same_bits, swapped_agree

cd = pytest.importorskip("circledist")

BAR = 1e-12  # the contact bar: 1e-12 times the query's size (docs/derivations/motion.md)
ANSWERS = ("time", "distance", "point_a", "point_b", "param_a", "param_b", "unique")
RING = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)


def _size(shapes_and_motions, times):
    """An upper bound of the query's size: the largest field of each shape moved over the samples,
    and each motion's travel and swing (its center's distance from the origin and how far the
    shape reaches from it, bounded by the largest field again)."""
    size = 0.0
    for shape, motion in shapes_and_motions:
        moved = shape.moved(motion, times)
        largest = max(float(np.max(np.abs(v))) for v in moved.to_arrays().values())
        m = motion.to_arrays()
        center = float(np.max(np.linalg.norm(m["center"], axis=-1)))
        travel = float(np.max(np.linalg.norm(m["translation"], axis=-1)))
        size = max(size, 4 * largest + 2 * center + travel)
    return size


def _distances(a, b, ma, mb, times):
    return np.asarray(cd.distance(a.moved(ma, times), b.moved(mb, times)), dtype=float)


def _check_against_sampling(a, b, ma, mb, within, samples=2001):
    """The bar: at the reported time the distance is at most within + delta; no sampled earlier
    time, nor the bisected first crossing of within - delta, lies below within - delta; NaN
    answers where there is no contact."""
    c = cd.first_contact(a, b, ma, mb, within=within)
    times = np.linspace(0.0, 1.0, samples)
    d = _distances(a, b, ma, mb, times)
    delta = BAR * _size([(a, ma), (b, mb)], times)
    below = np.flatnonzero(d < within - delta)
    if below.size:  # the first sampled time well within: bisect the crossing before it
        k = below[0]
        if k == 0:
            crossing = 0.0
        else:
            lo, hi = times[k - 1], times[k]
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if _distances(a, b, ma, mb, np.array([mid]))[0] < within - delta:
                    hi = mid
                else:
                    lo = mid
            crossing = hi
        assert c.time <= crossing, (c.time, crossing)
    if np.isinf(c.time):
        assert not below.size
        assert np.isnan(c.distance) and np.isnan(c.point_a).all() and np.isnan(c.point_b).all()
        assert np.isnan(c.param_a).all() and np.isnan(c.param_b).all()
        return c, None
    assert 0.0 <= c.time <= 1.0
    at = _distances(a, b, ma, mb, np.array([c.time]))[0]
    assert at <= within + delta, (at, within, delta)
    assert c.distance == at  # closest_points' distance of the moved shapes is distance()'s
    assert not (d[times < c.time] < within - delta).any()
    return c, delta


@pytest.mark.parametrize("gap, speed", [(2.0, 4.0), (0.5, 0.5), (1e-3, 3.0), (3.0, 3.0), (1.0, 7.0)])
def test_point_driven_at_a_ring(gap, speed):
    """A point on the ring's plane, outside it, driven straight at the rim: contact at gap / speed,
    at the rim point it aims at."""
    point = cd.Point([1 + gap, 0, 0])
    c = cd.first_contact(point, RING, cd.Motion(translation=[-speed, 0, 0]))
    size = 1 + gap + speed
    assert abs(c.time - gap / speed) <= BAR * size / speed
    assert 0 <= c.distance <= BAR * size
    assert np.allclose(c.point_b, [1, 0, 0], rtol=0, atol=1e-12)
    assert np.allclose(c.point_a, [1 + gap - speed * c.time, 0, 0], rtol=0, atol=1e-14)
    assert np.isfinite(c.param_a).all() and np.isfinite(c.param_b).all()


@pytest.mark.parametrize("within", [0.0, 0.25, 1.5])
def test_within_ends_the_approach_earlier(within):
    c = cd.first_contact(cd.Point([4, 0, 0]), RING, cd.Motion(translation=[-6, 0, 0]), within=within)
    assert abs(c.time - (3 - within) / 6) <= BAR * 10
    assert within - BAR * 10 <= c.distance <= within + BAR * 10


@pytest.mark.parametrize("height", [0.6, 0.8, 0.28])
def test_a_ring_turns_through_a_point(height):
    """A unit ring turning about the x axis passes through a point at unit distance from its
    center at one instant: the ring's plane contains (0, y, z) when its normal (0, -sin th, cos th)
    is orthogonal to it, th = atan2(z, y)."""
    y = np.sqrt(1 - height**2)
    point = cd.Point([0, y, height])
    turn = cd.Motion(rotation=[np.pi, 0, 0])
    c = cd.first_contact(RING, point, turn)
    expected = np.arctan2(height, y) / np.pi
    assert abs(c.time - expected) <= 1e-11
    assert c.distance <= BAR * 4
    assert np.allclose(c.point_a, point.p, atol=1e-11)
    # The same instant from the point's side: the ring at rest, the point turning back about x.
    d = cd.first_contact(point, RING, cd.Motion(rotation=[-np.pi, 0, 0]))
    assert abs(d.time - expected) <= 1e-11


def test_within_at_the_start_is_time_zero():
    c = cd.first_contact(cd.Point([1.5, 0, 0]), RING, cd.Motion(translation=[5, 0, 0]), within=0.5)
    assert c.time == 0.0 and c.distance == 0.5
    assert c.point_a.tolist() == [1.5, 0, 0] and c.point_b.tolist() == [1, 0, 0]
    touching = cd.first_contact(cd.Segment([0, 0, -1], [0, 0, 1]), cd.Disk([0, 0, 0], [0, 0, 1], 1.0))
    assert touching.time == 0.0 and touching.distance == 0.0


def test_never_is_inf_and_nan():
    for motion in (None, cd.Motion(translation=[-1, 0, 0]), cd.Motion(translation=[0, 0, 5])):
        c = cd.first_contact(cd.Point([3, 0, 0]), RING, motion)
        assert c.time == np.inf and np.isnan(c.distance)
        for name in ("point_a", "point_b", "param_a", "param_b"):
            assert np.isnan(getattr(c, name)).all(), name
        assert c.unique is True
        assert repr(c).startswith("Contact(time=inf, distance=nan")


def test_broadcasts_shapes_over_motions():
    """(4, 1) points against (3,) motions and (3,) within: a (4, 3) batch, each element the
    single query's answer to the bit."""
    rng = np.random.default_rng(3)
    points = cd.Point(rng.uniform([-1, -1, 1], [1, 1, 3], size=(4, 1, 3)))
    disk = cd.Disk([0, 0, 0], [0, 0, 1], 2.0)
    t = np.array([[0.3, 0, -4], [0, 0.2, -1.5], [0.5, 0.5, -0.5]])  # down fast, slowly, too slowly
    motions = cd.Motion(translation=t, rotation=[[0, 0, 0], [0.3, 0.2, 0], [0, 0, 3]])
    within = np.array([0.0, 0.1, 0.3])
    c = cd.first_contact(points, disk, motions, within=within)
    assert c.time.shape == (4, 3) and c.point_a.shape == (4, 3, 3) and c.param_b.shape == (4, 3, 2)
    assert c.unique.shape == (4, 3) and c.unique.dtype == bool
    assert np.isfinite(c.time).any() and np.isinf(c.time).any()
    rotations = motions.rotation
    for i in range(4):
        for j in range(3):
            one = cd.first_contact(
                cd.Point(points.p[i, 0]), disk, cd.Motion(translation=t[j], rotation=rotations[j]), within=within[j]
            )
            for name in ANSWERS:
                same_bits(getattr(c, name)[i, j], getattr(one, name))
    # The second shape's motion broadcasts too, and None leaves it at rest.
    both = cd.first_contact(points, disk, motions, cd.Motion(translation=np.zeros((3, 3))), within=within)
    for name in ANSWERS:
        same_bits(getattr(both, name), getattr(c, name))


PAIRS = [
    ("Point", "Circle"),
    ("Segment", "Disk"),
    ("Circle", "Circle"),
    ("Arc", "Annulus"),
    ("Bezier", "Segment"),
    ("Line", "Disk"),
    ("Ray", "Arc"),
    ("Disk", "Disk"),
    ("Point", "Point"),
    ("Segment", "Line"),
]


def _a_point_of(shape):
    """A point of a shape (its first vector field: a center, an origin, an end, a control point)."""
    return np.asarray(next(iter(shape.to_arrays().values())), dtype=float).reshape(-1, 3)[0]


@pytest.mark.parametrize("kinds", PAIRS, ids="-".join)
def test_random_pairs_against_sampling(kinds):
    """Random moving pairs (swept in part) against the sampled reference; both orders agree to
    the bit; and a contact happens in most of them (the reference is not only about misses)."""
    rng = np.random.default_rng(sum(map(ord, "".join(kinds))))
    contacts = 0
    for case in range(6):
        a, b = (getattr(cd, kind)(**random_fields(cd, kind, rng, sweep=bool(case % 2))) for kind in kinds)
        b = b.moved(cd.Motion(translation=[5, 0, 0]), 1.0)  # apart at the start, mostly
        # Each shape turning, a translating so that a point of it meets one of b about mid-way (give
        # or take 0.3), so that most cases touch.
        turn, mb = random_motion(cd, rng, kinds[0], np.zeros(3)), random_motion(cd, rng, kinds[1], np.zeros(3))
        aim = 2 * (_a_point_of(b.moved(mb, 0.5)) - _a_point_of(a.moved(turn, 0.5))) + rng.normal(size=3) * 0.3
        ma = cd.Motion(translation=aim, rotation=turn.rotation, center=turn.center)
        within = float(rng.uniform(0.1, 0.6)) if case else 0.0
        c, _ = _check_against_sampling(a, b, ma, mb, within)
        contacts += bool(np.isfinite(c.time))
        swapped_agree(c, cd.first_contact(b, a, mb, ma, within=within))
    assert contacts >= 2


def test_both_orders_agree_for_every_pair_of_kinds():
    """Every pair of kinds the module has, in both orders, with a batch that mixes contacts and
    misses (lines and rays translating only)."""
    rng = np.random.default_rng(11)
    kinds = sorted({k for pair in cd._core._query_kinds() for k in pair})
    for first in kinds:
        for second in kinds:
            a = getattr(cd, first)(**random_fields(cd, first, rng, batch=(3,)))
            b = getattr(cd, second)(**random_fields(cd, second, rng, batch=(3,)))
            ma = cd.Motion(translation=rng.normal(size=(3, 3)) * 3)
            mb = random_motion(cd, rng, second)
            c = cd.first_contact(a, b, ma, mb, within=0.1)
            swapped_agree(c, cd.first_contact(b, a, mb, ma, within=0.1))


def test_precisions():
    point, motion = cd.Point([3, 0, 0]), cd.Motion(translation=[-4, 0, 0])
    double = cd.first_contact(point, RING, motion)
    wide_point = cd.Point(np.array([3, 0, 0], dtype=np.longdouble))
    wide = cd.first_contact(wide_point, RING, motion)
    assert isinstance(wide.time, np.longdouble) and wide.point_a.dtype == np.longdouble
    assert abs(wide.time - np.longdouble(0.5)) <= BAR * 8 and 0 <= wide.distance <= BAR * 8
    # A long double motion decides the precision too; precision= overrides.
    wide_motion = cd.Motion(translation=np.array([-4, 0, 0], dtype=np.longdouble))
    assert cd.first_contact(point, RING, wide_motion).point_b.dtype == np.longdouble
    assert cd.first_contact(point, RING, motion, precision="longdouble").point_b.dtype == np.longdouble
    assert cd.first_contact(wide_point, RING, motion, precision="float64").point_b.dtype == np.float64
    # float32 shapes and motions: the double query on their float32 values, answers in float32.
    single_ring = cd.Circle(np.zeros(3, np.float32), np.array([0, 0, 1], np.float32), np.float32(1))
    single_point = cd.Point(np.array([3, 0, 0], np.float32))
    single_motion = cd.Motion(translation=np.array([-4, 0, 0], np.float32))
    single = cd.first_contact(single_point, single_ring, single_motion)
    assert single.point_a.dtype == np.float32 and single.time == np.float32(double.time)
    assert cd.first_contact(single_point, single_ring, motion).point_a.dtype == np.float64  # a float64 motion
    assert cd.first_contact(single_point, single_ring).point_a.dtype == np.float32  # at rest decides nothing
    never = cd.first_contact(single_point, single_ring, precision="float32")
    assert never.time == np.inf and np.isnan(never.point_a).all()


@pytest.mark.parametrize("kind", ["Line", "Ray"])
def test_a_rotating_line_or_ray_names_the_motion_and_index(kind):
    line = getattr(cd, kind)(np.zeros((3, 3)) + [0, 0, 5], [1, 0, 0])
    rotations = np.zeros((3, 3))
    rotations[2] = [0, 0, 1]
    turning = cd.Motion(rotation=rotations)
    message = rf"first_contact: motion_a\[2\] rotates the first argument, a {kind}: a line or ray cannot rotate"
    with pytest.raises(ValueError, match=message):
        cd.first_contact(line, RING, turning)
    # The other order: the table's kernel is (line, ring), run reversed; the message keeps the caller's names.
    message = rf"first_contact: motion_b\[2\] rotates the second argument, a {kind}: a line or ray cannot rotate"
    with pytest.raises(ValueError, match=message):
        cd.first_contact(RING, line, None, turning)
    with pytest.raises(ValueError, match=r"motion_b rotates the second argument, a Line"):
        cd.first_contact(
            cd.Line([0, 0, 5], [1, 0, 0]), cd.Line([0, 0, 0], [0, 1, 0]), None, cd.Motion(rotation=[1, 0, 0])
        )
    # Translating is fine, and so is a rotation of the other shape.
    assert np.isfinite(cd.first_contact(line, RING, cd.Motion(translation=[0, 0, -10])).time).all()
    assert cd.first_contact(line, RING, None, cd.Motion(rotation=[1, 0, 0])).time.shape == (3,)


def test_argument_errors():
    point = cd.Point([3, 0, 0])
    with pytest.raises(TypeError, match="first_contact: motion_a must be a circledist.Motion or None, got str"):
        cd.first_contact(point, RING, "up")
    with pytest.raises(TypeError, match="first_contact: motion_b must be a circledist.Motion or None, got list"):
        cd.first_contact(point, RING, None, [1, 0, 0])
    with pytest.raises(TypeError, match="motion_a must be a circledist.Motion or None, got circledist._core.Circle"):
        cd.first_contact(point, RING, RING)
    with pytest.raises(ValueError, match=r"first_contact: within\[1\] is negative"):
        cd.first_contact(point, RING, within=[0.0, -1.0])
    with pytest.raises(ValueError, match="first_contact: within contains NaN or inf"):
        cd.first_contact(point, RING, within=np.inf)
    with pytest.raises(ValueError, match=r"first_contact: motion_b of batch shape \(2,\) does not broadcast"):
        cd.first_contact(cd.Point(np.zeros((3, 3))), RING, None, cd.Motion(translation=np.zeros((2, 3))))
    with pytest.raises(ValueError, match=r"first_contact: within of batch shape \(4,\) does not broadcast"):
        cd.first_contact(cd.Point(np.zeros((3, 3))), RING, within=np.zeros(4))
    with pytest.raises(ValueError, match="first_contact: batch shapes"):
        cd.first_contact(cd.Point(np.zeros((3, 3))), cd.Point(np.zeros((2, 3))))
    with pytest.raises(ValueError, match="workers must be a positive integer or -1"):
        cd.first_contact(point, RING, workers=0)
    with pytest.raises(ValueError, match="precision must be None"):
        cd.first_contact(point, RING, precision="half")
    with pytest.raises(ValueError, match=r"motion_a: translation is outside float32's range"):
        cd.first_contact(point, RING, cd.Motion(translation=[1e300, 0, 0]), precision="float32")


def test_workers_progress_and_stats():
    rng = np.random.default_rng(5)
    points = cd.Point(rng.normal(size=(600, 3)) * 3)
    motions = cd.Motion(translation=rng.normal(size=(600, 3)) * 4, rotation=rng.normal(size=(600, 3)))
    cd.reset_stats()
    one = cd.first_contact(points, RING, motions, within=0.05)
    counted = cd.stats()
    contacts = int(np.isfinite(one.time).sum())
    assert counted["closest_points"] == contacts > 0
    assert counted["distances"] >= 600
    calls = []
    two = cd.first_contact(points, RING, motions, within=0.05, workers=2, progress=lambda *a: calls.append(a))
    for name in ANSWERS:
        same_bits(getattr(one, name), getattr(two, name))
    assert calls[-1] == (600, 600)


@pytest.mark.parametrize("solver", ["bracketing", "companion", "polished", "eigen"])
def test_every_solver(solver):
    """A tilted line falling through a ring (a pair that solves polynomials): every root policy
    meets the sampled reference, with its solves counted."""
    line, fall = cd.Line([0, 0.5, 2], [1, 0.2, 0.3]), cd.Motion(translation=[0.3, 0, -4])
    reference, delta = _check_against_sampling(line, RING, fall, cd.Motion(), 0.0)
    cd.reset_stats()
    c = cd.first_contact(line, RING, fall, solver=solver)
    assert cd.stats()["solves"] > 0
    assert abs(c.time - reference.time) <= 1e-11 and c.distance <= delta
    with pytest.raises(ValueError, match="solver must be None"):
        cd.first_contact(line, RING, solver="newton")


@pytest.mark.parametrize("dtype", [np.float64, np.longdouble], ids=["float64", "longdouble"])
def test_answers_are_closest_points_of_the_moved_shapes(dtype):
    """Every kind against a few, turning, translating only (a rotation of zeros, negative zeros
    among them) and at rest: first_contact's and closest_approach's answers are closest_points of
    a.moved(ma, time) and b.moved(mb, time) to the bit, as the queries move the shapes as
    Shape.moved does."""
    rng = np.random.default_rng(29)
    kinds = sorted({k for pair in cd._core._query_kinds() for k in pair})
    n = 4
    for first in kinds:
        for second in ("Point", "Circle", "Arc", "Bezier"):
            a = getattr(cd, first)(**random_fields(cd, first, rng, batch=(n,), dtype=dtype))
            b = getattr(cd, second)(**random_fields(cd, second, rng, batch=(n,), dtype=dtype))
            b = b.moved(cd.Motion(translation=np.array([2.5, 0, 0], dtype=dtype)), np.array(1.0, dtype=dtype))
            still = np.zeros((n, 3), dtype=dtype)
            still[::2, 1] = -0.0
            turning = rng.normal(size=(n, 3)).astype(dtype) * 2
            rotation_a = still if first in ("Line", "Ray") else turning
            for ma, mb in (
                (
                    cd.Motion(
                        translation=rng.normal(size=(n, 3)).astype(dtype) * 3,
                        rotation=rotation_a,
                        center=rng.normal(size=(n, 3)).astype(dtype),
                    ),
                    cd.Motion(translation=rng.normal(size=(n, 3)).astype(dtype), rotation=still),
                ),
                (
                    cd.Motion(
                        translation=-rng.normal(size=(n, 3)).astype(dtype) * 3,
                        rotation=still,
                        center=rng.normal(size=(n, 3)).astype(dtype),
                    ),
                    cd.Motion(rotation=turning, center=rng.normal(size=(n, 3)).astype(dtype)),
                ),
                (cd.Motion(translation=rng.normal(size=(n, 3)).astype(dtype) * 3, rotation=still), None),
            ):
                for r in (cd.first_contact(a, b, ma, mb, within=0.3), cd.closest_approach(a, b, ma, mb)):
                    t = np.asarray(r.time)
                    assert t.dtype == dtype
                    met = np.isfinite(t)
                    at = np.where(met, t, 0).astype(dtype)
                    expected = cd.closest_points(a.moved(ma, at), b.moved(mb if mb is not None else cd.Motion(), at))
                    for name in ("distance", "point_a", "point_b", "param_a", "param_b"):
                        same_bits(np.asarray(getattr(r, name))[met], np.asarray(getattr(expected, name))[met])
