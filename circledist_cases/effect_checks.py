"""Checks that every curve family runs (tests/pairs/test_bezier_point_linear.py,
tests/pairs/test_bezier_bezier.py): within(), intersects() and swept shapes against the reference
distance, and the other argument order's closest points."""

from __future__ import annotations

import numpy as np

import circledist as cd


def assert_other_order_swapped(a, b, r, solver):
    """closest_points(b, a) is r, closest_points(a, b), with its two sides swapped."""
    o = cd.closest_points(b, a, solver=solver)
    assert o.distance == r.distance and o.unique == r.unique
    assert np.array_equal(o.point_a, r.point_b) and np.array_equal(o.point_b, r.point_a)
    assert np.array_equal(o.param_a, r.param_b) and np.array_equal(o.param_b, r.param_a)


def assert_effects_and_sweeps(a, b, swept, d_ref, scale, size):
    """a, b: the pair; swept(ra, rb): the same pair swept by ra and rb; d_ref: the reference
    distance; scale: the bar's scale; size: the pair's size, which within()'s tolerance follows
    (64 eps x the pair's bounding balls, effects.hpp)."""
    margin = 1e-6 * scale + 1e-12 * size
    for x, y in ((a, b), (b, a)):
        assert cd.within(x, y, d_ref + 1e-9 * scale)
        if d_ref > margin:
            assert not cd.within(x, y, d_ref - margin)
            assert not cd.intersects(x, y)
        if d_ref == 0:
            assert cd.intersects(x, y)
    # swept: the core distance less both sweeps, never below 0
    ra, rb = 0.1 * scale, 0.05 * scale
    sa, sb = swept(ra, rb)
    d = cd.distance(a, b)
    assert cd.distance(sa, sb) == cd.distance(sb, sa)
    assert abs(cd.distance(sa, sb) - max(0.0, d - ra - rb)) <= 1e-12 * scale
    if d > ra + rb + 1e-9 * scale:
        assert not cd.intersects(sa, sb) and not cd.intersects(sb, sa)
    elif d < ra + rb - 1e-9 * scale:
        assert cd.intersects(sa, sb) and cd.intersects(sb, sa)
    r = cd.closest_points(sa, sb)
    assert r.distance == cd.distance(sa, sb)
