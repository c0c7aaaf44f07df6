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
    u = np.where(
        x_major[:, None], np.stack([-w[:, 2], zero, w[:, 0]], axis=1), np.stack([zero, w[:, 2], -w[:, 1]], axis=1)
    )
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
    assert not bad.any(), (
        f"{bad.sum()} of {len(bad)} points are not the point their parameter names; "
        f"worst {np.max(err / scale):.3g} x scale"
    )


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("round_kind", ROUND_KINDS)
@pytest.mark.parametrize("other", OTHER_KINDS)
def test_round_param_names_its_point(other, round_kind, solver):
    rng = np.random.default_rng([OTHER_KINDS.index(other), ROUND_KINDS.index(round_kind), SOLVERS.index(solver)])
    target, fields = round_shape(round_kind, rng, N)
    a, _ = other_shape(other, rng, N)
    for order in ("other first", "round first"):
        r = (
            cd.closest_points(a, target, solver=solver)
            if order == "other first"
            else cd.closest_points(target, a, solver=solver)
        )
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
    check(
        round_kind,
        fields,
        np.array([r.point_b for r in rows]),
        np.array([r.param_b for r in rows]),
        np.array([r.distance for r in rows]),
        np.array([r.unique for r in rows]),
    )


# A point on a disk's axis has no in-plane direction: its angle is 0 (the documented choice), for
# every normal and either sign of zero in the inputs; atan2(0, -0) is pi, and a -0 from the
# angle's terms once made it so (a disk facing -z, a point above its center).
@pytest.mark.parametrize(
    "normal", [[0, 0, -1], [0, 0, 1], [-1, 0, 0], [1, 0, 0], [0, -1, 0], [-1, 0, 1], [0.0, -0.0, -2.0]]
)
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


# Parameters stay in their shape's domain (a ray's t >= 0, a segment's and a curve's t in [0, 1],
# an arc's t in [0, angle], a disk's s in [0, radius], an annulus's s in [inner, outer]) where the
# solvers' rounding put them an ulp or a few outside it (a segment's t of -1e-23 against an arc, a
# disk's s one ulp above its radius): near-degenerate pairs, the other shape's origin within
# 1e-17 .. 1e-6 of a point of the shape (its end, its rim, its center). The point the clamped
# parameter names is the reported point within the accuracy bar.
DOMAIN_KINDS = ["Ray", "Segment", "Bezier", "Arc", "Disk", "Annulus"]
ALL_KINDS = ["Point", "Line", "Ray", "Segment", "Circle", "Disk", "Bezier", "Arc", "Annulus"]


def _unit(rng, n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _shape(kind, rng, n, near=None):
    """n shapes of `kind` and their fields; with `near`, each starting (origin, p0, first control
    point, center) within 1e-17 .. 1e-6 of near's row."""
    base = rng.normal(size=(n, 3))
    if near is not None:
        base = near + _unit(rng, n) * 10.0 ** rng.uniform(-17, -6, (n, 1))
    if kind == "Point":
        fields = (base,)
    elif kind in ("Line", "Ray"):
        fields = (base, _unit(rng, n) * rng.uniform(0.5, 2, (n, 1)))
    elif kind == "Segment":
        fields = (base, base + _unit(rng, n) * rng.uniform(0.5, 2, (n, 1)))
    elif kind in ("Circle", "Disk"):
        fields = (base, _unit(rng, n), rng.uniform(0.5, 2, n))
    elif kind == "Arc":
        fields = (base, _unit(rng, n), rng.uniform(0.5, 2, n), _unit(rng, n), rng.uniform(0.3, 6.2, n))
    elif kind == "Annulus":
        outer = rng.uniform(0.5, 2, n)
        fields = (base, _unit(rng, n), outer * rng.uniform(0.2, 0.8, n), outer)
    else:
        control = rng.normal(size=(n, 3, 3))
        control[:, 0] = base
        fields = (control,)
    return getattr(cd, kind)(*fields), fields


def _anchors(kind, shape, fields, rng, n):
    """Points of the shape where degenerate neighbours sit: its ends, rims and centers, and the
    closest points of random points."""
    on = cd.closest_points(shape, rng.normal(size=(n, 3)) * 2).point_a
    if kind == "Segment":
        special = fields[int(rng.integers(0, 2))]
    elif kind == "Bezier":
        special = fields[0][:, -1]
    elif kind == "Arc":
        special = cd.closest_points(shape, fields[0] + fields[3] * 5).point_a  # toward the start
    else:  # a ray's origin, a disk's or an annulus's center
        special = fields[0]
    return np.where(rng.random((n, 1)) < 0.5, on, special)


def _in_domain(kind, fields, param):
    t = param[:, 0]
    if kind == "Ray":
        return t >= 0
    if kind in ("Segment", "Bezier"):
        return (t >= 0) & (t <= 1)
    if kind == "Arc":
        return (t >= 0) & (t <= fields[4])
    if kind == "Disk":
        return (t >= 0) & (t <= fields[2])
    return (t >= fields[2]) & (t <= fields[3])


def _named(kind, fields, param):
    """The point the parameter names, in long double from the documented definitions."""
    t = np.asarray(param[:, 0], dtype=LD)
    if kind == "Ray":
        return np.asarray(fields[0], dtype=LD) + t[:, None] * np.asarray(fields[1], dtype=LD)
    if kind == "Segment":
        p0, p1 = np.asarray(fields[0], dtype=LD), np.asarray(fields[1], dtype=LD)
        return p0 + t[:, None] * (p1 - p0)
    if kind == "Bezier":
        q = np.asarray(fields[0], dtype=LD)
        while q.shape[1] > 1:
            q = (1 - t)[:, None, None] * q[:, :-1] + t[:, None, None] * q[:, 1:]
        return q[:, 0]
    if kind == "Arc":
        center, normal, radius, start, _ = fields
        u, v = frame(normal)
        s = np.asarray(start, dtype=LD)
        theta = np.arctan2((s * v).sum(axis=1), (s * u).sum(axis=1)) + t
        return np.asarray(center, dtype=LD) + np.asarray(radius, dtype=LD)[:, None] * (
            np.cos(theta)[:, None] * u + np.sin(theta)[:, None] * v
        )
    return named_point("disk", (fields[0], fields[1], None), param)


@pytest.mark.parametrize("other", ALL_KINDS)
@pytest.mark.parametrize("kind", DOMAIN_KINDS)
def test_params_stay_in_their_domain_near_degenerate_pairs(kind, other):
    rng = np.random.default_rng([DOMAIN_KINDS.index(kind), ALL_KINDS.index(other)])
    n = 500
    shape, fields = _shape(kind, rng, n)
    near, near_fields = _shape(other, rng, n, near=_anchors(kind, shape, fields, rng, n))
    forward, backward = cd.closest_points(shape, near), cd.closest_points(near, shape)
    for r, param, point, other_param in [
        (forward, forward.param_a, forward.point_a, forward.param_b),
        (backward, backward.param_b, backward.point_b, backward.param_a),
    ]:
        bad = ~_in_domain(kind, fields, param)
        assert not bad.any(), f"{bad.sum()} of {n} params outside the domain, e.g. {param[bad][:3, 0]}"
        err = np.sqrt(((np.asarray(point, dtype=LD) - _named(kind, fields, param)) ** 2).sum(axis=1)).astype(float)
        scale = np.maximum(1.0, np.abs(r.distance))
        assert np.all(err <= 1e-12 * scale), f"worst {np.max(err / scale):.3g} x scale"
        if other in DOMAIN_KINDS:  # the near shape's own parameters too
            assert _in_domain(other, near_fields, other_param).all()
