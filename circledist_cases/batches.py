"""Random batches of shapes of every kind, and the kind pairs the module answers: the all-pairs
tests (tests/pairs/test_pairs.py) check them against brute force, the Dask tests against single calls."""

import numpy as np

import circledist as cd

# The trailing (per element) dimensions of each constructor argument: the rest is batch.
TRAILING = {
    "p": 1,
    "origin": 1,
    "direction": 1,
    "p0": 1,
    "p1": 1,
    "center": 1,
    "normal": 1,
    "radius": 0,
    "control_points": 2,
    "start": 1,
    "angle": 0,
    "inner_radius": 0,
    "outer_radius": 0,
    "sweep": 0,
}
SUPPORTED = {tuple(p) for p in cd._core._query_kinds()}


def random_batch(kind, n, rng, box=4.0, swept=True):
    """n shapes of a kind around a box of side 2 * box; half of them swept (when `swept`)."""
    at = rng.uniform(-box, box, (n, 3))
    sweep = np.where(rng.random(n) < 0.5, 0.0, rng.uniform(0, 0.4, n)) if swept else None
    if kind == "Point":
        args = (at,)
    elif kind in ("Line", "Ray"):
        args = (at, rng.normal(size=(n, 3)))
    elif kind == "Segment":
        args = (at, at + rng.uniform(-1.5, 1.5, (n, 3)))
    elif kind in ("Circle", "Disk"):
        args = (at, rng.normal(size=(n, 3)), rng.uniform(0.1, 1.2, n))
    elif kind == "Arc":
        args = (
            at,
            rng.normal(size=(n, 3)),
            rng.uniform(0.1, 1.2, n),
            rng.normal(size=(n, 3)),
            rng.uniform(0.2, 2 * np.pi, n),
        )
    elif kind == "Annulus":
        outer = rng.uniform(0.1, 1.2, n)
        args = (at, rng.normal(size=(n, 3)), outer * rng.uniform(0, 1, n), outer)
    else:
        args = (at[:, None, :] + rng.uniform(-1, 1, (n, 4, 3)),)
    return getattr(cd, kind)(*args, sweep=sweep)
