"""Batched closest_points of a point against a circle, a disk or an annulus answers four elements
at a time (AVX lanes, cpp/include/circledist/detail/point_round_lanes.hpp) where the processor has AVX:
the answers must be the single queries', bit for bit, in every field, whatever the batch's length
(the elements left after the last block of four), its layout (a field repeated, broadcast over a
grid, strided views), the argument order, the dtype and the thread count, and wherever a lane
leaves the common path (points on the axis, on the rim, normals of extreme length, huge and
tiny scenes, points over an annulus's hole and on its inner rim), alone in its block or not.
cpp/tests/test_point_round_lanes.cpp
checks the lanes themselves against the scalar query."""

import numpy as np
import pytest

import circledist as cd

FIELDS = ("distance", "point_a", "point_b", "param_a", "param_b", "unique")


def annulus(center, normal, radius):
    """An annulus of outer radius `radius` and a hole of 0.4 of it."""
    return cd.Annulus(center, normal, 0.4 * np.asarray(radius), radius)


annulus.__name__ = "Annulus"
KINDS = (cd.Circle, cd.Disk, annulus)


def same_bits(x, y):
    x, y = np.asarray(x), np.asarray(y)
    return x.shape == y.shape and x.dtype == y.dtype and x.tobytes() == y.tobytes()


def check(points, centers, normals, radii, kind, reverse=False, **kw):
    shape = kind(centers, normals, radii)
    got = cd.closest_points(shape, points, **kw) if reverse else cd.closest_points(points, shape, **kw)
    batch = np.shape(got.distance)
    pts = np.broadcast_to(points, batch + (3,))
    c = np.broadcast_to(centers, batch + (3,))
    n = np.broadcast_to(normals, batch + (3,))
    r = np.broadcast_to(radii, batch)
    for i in np.ndindex(*batch):
        one_shape = kind(c[i], n[i], r[i])
        want = cd.closest_points(one_shape, pts[i], **kw) if reverse else cd.closest_points(pts[i], one_shape, **kw)
        for field in FIELDS:
            mine = np.asarray(getattr(got, field))[i]
            # a single float32 query answers Python floats holding float32 values: compared in the batch's dtype
            assert same_bits(mine, np.asarray(getattr(want, field), dtype=mine.dtype)), (kind, i, field)
    assert same_bits(cd.distance(points, shape, **kw), got.distance)


def random_batch(n, seed):
    rng = np.random.default_rng(seed)
    return rng.normal(size=(n, 3)) * 2, rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), rng.uniform(0, 2, n)


@pytest.mark.parametrize("kind", KINDS, ids=lambda k: k.__name__)
@pytest.mark.parametrize("n", [1, 3, 4, 5, 7, 8, 9, 13, 64])
def test_every_length_and_order(kind, n):
    p, c, w, r = random_batch(n, n)
    check(p, c, w, r, kind)
    check(p, c, w, r, kind, reverse=True)


@pytest.mark.parametrize("kind", KINDS, ids=lambda k: k.__name__)
def test_layouts(kind):
    p, c, w, r = random_batch(24, 7)
    check(p[0], c, w, r, kind)  # one point against many rounds (a field repeated)
    check(p, c[0], w[0], r[0], kind)  # many points against one round
    check(p[:, None, :], c[None, :6], w[None, :6], r[None, :6], kind)  # a grid (N, 1) x (M,)
    check(p[::2], c[::2], w[1::2], r[::2], kind)  # strided views
    check(np.asfortranarray(p), c, w, 0.5, kind)  # another memory order, a scalar radius
    check(
        p.astype(np.float32),
        c.astype(np.float32),
        w.astype(np.float32),
        r.astype(np.float32),
        kind,
        precision="float32",
    )
    check(p, c, w, r, kind, workers=2)


def hard_points():
    """Points where a lane leaves the common path, or sits on its edge, for the unit round about z."""
    e = np.finfo(float).eps
    return np.array(
        [
            [0, 0, 1],
            [0, 0, 0],
            [0, 0, -3],
            [1e-300, 0, 0.5],
            [1, 0, 0],
            [0, 1, 0],
            [1 + e, 0, 0],
            [0.5, 0.5, 0],
            [1, 0, 1e-300],
            [2, 0, 0],
            [1e-17, 1e-17, 1],
            [1e200, 1e200, 0],
            [3e-310, 0, 0],
            [0.3, -0.4, 5],
            [0.4, 0, 0.2],
            [0.4 * (1 - 1e-16), 0, 0],
            [0.2, 0.1, -1],
            [1e-9, 0, 2],
        ],
        dtype=float,
    )


@pytest.mark.parametrize("kind", KINDS, ids=lambda k: k.__name__)
@pytest.mark.parametrize(
    "normal", [[0, 0, 1], [0, 0, -1], [1, 1, 0], [1e-200, 0, 1e-200], [1e200, 1, 0], [1e-17, 1, 0]]
)
def test_hard_points_alone_and_among_random_ones(kind, normal):
    hard = hard_points()
    p, c, w, r = random_batch(4 * len(hard), 11)
    p = p.copy()
    p[::4] = hard  # one hard point in every block of four (and the block's other lanes random)
    check(hard, [0, 0, 0], normal, 1.0, kind)
    check(p, np.zeros(3), normal, 1.0, kind)
    check(p, c, w, r, kind)
    check(hard, [0, 0, 0], normal, 0.0, kind)  # a radius of zero
