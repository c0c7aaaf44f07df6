"""A circle's or disk's reported parameter names its reported closest point.

closest_points reports theta for a circle and (s, theta) for a disk, in the round's frame as the
documentation defines it (N = W / |W|; U = (-W.z, 0, W.x) / |.| when |W.x| > |W.y|, else
(0, W.z, -W.y) / |.|; V = N x U). The point C + R (cos theta U + sin theta V) (circle) or
C + s (cos theta U + sin theta V) (disk), built here in long double from that definition, must be
the reported point within the accuracy bar, for every kind against circles and disks, in both
argument orders, under every root policy, batched and one by one.
"""

import numpy as np
import pytest

import circledist as cd

LD = np.longdouble
SOLVERS = ["bracketing", "companion", "polished", "eigen"]
OTHER_KINDS = ["point", "line", "ray", "segment", "circle", "disk", "bezier"]
ROUND_KINDS = ["circle", "disk"]
N = 400


def frame(normal):
    """U, V of the documented frame, in long double, for normals of shape (n, 3)."""
    w = np.asarray(normal, dtype=LD)
    n = w / np.sqrt((w * w).sum(axis=1))[:, None]
    x_major = np.abs(w[:, 0]) > np.abs(w[:, 1])
    zero = np.zeros(len(w), dtype=LD)
    u = np.where(x_major[:, None], np.stack([-w[:, 2], zero, w[:, 0]], axis=1),
                 np.stack([zero, w[:, 2], -w[:, 1]], axis=1))
    u = u / np.sqrt((u * u).sum(axis=1))[:, None]
    return u, np.cross(n, u)


def round_shape(kind, rng, n):
    center = rng.normal(size=(n, 3))
    normal = rng.normal(size=(n, 3)) * rng.uniform(0.1, 10, size=(n, 1))
    radius = rng.uniform(0.5, 2, size=n)
    shape = (cd.Circle if kind == "circle" else cd.Disk)(center, normal, radius)
    return shape, (center, normal, radius)


def other_shape(kind, rng, n):
    """(the batch of n shapes of `kind`, a function giving its i-th shape alone)."""
    p = rng.normal(size=(n, 3)) * 2
    q = rng.normal(size=(n, 3)) * 2
    if kind in ROUND_KINDS:
        shape, (center, normal, radius) = round_shape(kind, rng, n)
        make = cd.Circle if kind == "circle" else cd.Disk
        return shape, lambda i: make(center[i], normal[i], radius[i])
    if kind == "bezier":
        control = rng.normal(size=(n, 4, 3)) * 2
        return cd.Bezier(control), lambda i: cd.Bezier(control[i])
    make = {"point": lambda p, q: cd.Point(p), "line": cd.Line, "ray": cd.Ray, "segment": cd.Segment}[kind]
    return make(p, q), lambda i: make(p[i], q[i])


def named_point(kind, fields, param):
    center, normal, radius = fields
    u, v = frame(normal)
    param = np.asarray(param, dtype=LD)
    if kind == "circle":
        s, theta = np.asarray(radius, dtype=LD), param[:, 0]
    else:
        s, theta = param[:, 0], param[:, 1]
    direction = np.cos(theta)[:, None] * u + np.sin(theta)[:, None] * v
    return np.asarray(center, dtype=LD) + s[:, None] * direction


def check(kind, fields, point, param, distance, unique):
    expected = named_point(kind, fields, param)
    err = np.sqrt(((np.asarray(point, dtype=LD) - expected) ** 2).sum(axis=1)).astype(float)
    scale = np.maximum(fields[2], np.abs(distance))
    bad = unique & ~(err <= 1e-12 * scale)
    assert not bad.any(), (f"{bad.sum()} of {len(bad)} points are not the point their parameter names; "
                           f"worst {np.max(err / scale):.3g} x scale")


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("round_kind", ROUND_KINDS)
@pytest.mark.parametrize("other", OTHER_KINDS)
def test_round_param_names_its_point(other, round_kind, solver):
    rng = np.random.default_rng([OTHER_KINDS.index(other), ROUND_KINDS.index(round_kind), SOLVERS.index(solver)])
    target, fields = round_shape(round_kind, rng, N)
    a, _ = other_shape(other, rng, N)
    for order in ("other first", "round first"):
        r = cd.closest_points(a, target, solver=solver) if order == "other first" else \
            cd.closest_points(target, a, solver=solver)
        point, param = (r.point_b, r.param_b) if order == "other first" else (r.point_a, r.param_a)
        check(round_kind, fields, point, param, r.distance, np.asarray(r.unique))


@pytest.mark.parametrize("round_kind", ROUND_KINDS)
@pytest.mark.parametrize("other", OTHER_KINDS)
def test_round_param_one_by_one(other, round_kind):
    rng = np.random.default_rng([7, OTHER_KINDS.index(other), ROUND_KINDS.index(round_kind)])
    n = 40
    _, fields = round_shape(round_kind, rng, n)
    make = cd.Circle if round_kind == "circle" else cd.Disk
    _, single = other_shape(other, rng, n)
    rows = [cd.closest_points(single(i), make(*(f[i] for f in fields))) for i in range(n)]
    check(round_kind, fields, np.array([r.point_b for r in rows]), np.array([r.param_b for r in rows]),
          np.array([r.distance for r in rows]), np.array([r.unique for r in rows]))


# A point on a disk's axis has no in-plane direction: its angle is 0 (the documented choice), for
# every normal and either sign of zero in the inputs; atan2(0, -0) is pi, and a -0 from the
# angle's terms once made it so (a disk facing -z, a point above its center).
@pytest.mark.parametrize("normal", [[0, 0, -1], [0, 0, 1], [-1, 0, 0], [1, 0, 0], [0, -1, 0], [-1, 0, 1], [0.0, -0.0, -2.0]])
@pytest.mark.parametrize("height", [2.0, -2.0, 0.0, -0.0])
def test_disk_angle_on_the_axis_is_zero(normal, height):
    n = np.asarray(normal, float)
    center = np.array([0.5, -0.0, 0.0])
    p = center + height * n  # exactly on the axis
    for batch in (False, True):
        a = cd.Point(p[None] if batch else p)
        b = cd.Disk(center[None] if batch else center, n[None] if batch else n, [1.0] if batch else 1.0)
        for r, theta in ((cd.closest_points(a, b), 1), (cd.closest_points(b, a), 0)):
            param = np.asarray(r.param_b if theta else r.param_a).reshape(2)
            assert param[1] == 0 and not np.signbit(param[1]), f"angle {param[1]!r} on the axis"
            assert param[0] == 0
