"""Random shapes of every kind, built from the module's table of fields (_core._shape_fields), so
that a new kind or field is drawn without a change here."""

from __future__ import annotations

import numpy as np


def random_fields(cd, kind: str, rng, batch=(), dtype=np.float64, sweep: bool = False) -> dict:
    """{field: array} for a batch of random shapes of `kind` (batch shape `batch`, values of
    `dtype`), drawn field by field in the table's order: vectors and directions standard normal,
    lengths (radii) uniform in [0.2, 2), control points four standard normal points (a cubic),
    angles (an arc's) uniform in [0.3, 2 pi), an annulus's inner radius drawn as a fraction of its
    outer one (uniform in [0, 1): the table's order puts it first, so it is set after the loop);
    with `sweep`, a sweep uniform in [0, 0.3) drawn last."""
    batch = tuple(batch)
    out = {}
    for name, role in cd._core._shape_fields()[kind]:
        if role in ("vector", "direction"):
            value = rng.normal(size=batch + (3,))
        elif role == "length":
            value = rng.uniform(0.2, 2.0, batch)
        elif role == "control_points":
            value = rng.normal(size=batch + (4, 3))
        elif role == "angle":
            value = rng.uniform(0.3, 2 * np.pi, batch)
        else:
            raise ValueError(f"no random values for role {role!r} of {kind}.{name}")
        out[name] = np.asarray(value).astype(dtype)
    if "inner_radius" in out:  # at most the outer radius (shapes.hpp's at_most)
        out["inner_radius"] = (rng.uniform(0.0, 1.0, batch) * out["outer_radius"]).astype(dtype)
    if sweep:
        out[cd._core._sweep_field()[0]] = random_sweep(rng, batch, dtype)
    return out


def random_sweep(rng, batch=(), dtype=np.float64):
    """Sweep radii uniform in [0, 0.3) of batch shape `batch`."""
    return np.asarray(rng.uniform(0.0, 0.3, tuple(batch))).astype(dtype)


def query_pairs(cd) -> list:
    """The (kind, kind) pairs that have a query, each once (sorted, the first kind <= the second)."""
    kinds = {tuple(p) for p in cd._core._query_kinds()}
    return sorted(p for p in kinds if p[0] <= p[1])


def same_bits(x, y) -> None:
    """Asserts that two answers are the same to the bit: dtype, shape and values (NaN where NaN)."""
    x, y = np.asarray(x), np.asarray(y)
    assert x.dtype == y.dtype and x.shape == y.shape
    assert np.array_equal(x, y, equal_nan=True)


def make_shape(cd, kind: str, values):
    """The library shape of a flat value layout (accuracy.py's, and bench/accuracy_vs_time.cpp's):
    point (x, y, z), given as a plain array (the library makes it a Point); line, ray (origin,
    direction); segment (p0, p1); circle, disk (center, normal, radius); arc (center, normal,
    radius, start, angle); annulus (center, normal, inner radius, outer radius); bezier (k, then k
    control points)."""
    v = np.asarray(values, dtype=float)
    if kind == "point":
        return v[:3].copy()
    if kind in ("line", "ray", "segment"):
        return getattr(cd, kind.capitalize())(v[:3], v[3:6])
    if kind in ("circle", "disk"):
        return getattr(cd, kind.capitalize())(v[:3], v[3:6], float(v[6]))
    if kind == "arc":
        return cd.Arc(v[:3], v[3:6], float(v[6]), v[7:10], float(v[10]))
    if kind == "annulus":
        return cd.Annulus(v[:3], v[3:6], float(v[6]), float(v[7]))
    if kind == "bezier":
        k = int(v[0])
        return cd.Bezier(v[1 : 1 + 3 * k].reshape(k, 3))
    raise ValueError(kind)


def random_motion(cd, rng, kind: str, translation=None):
    """A random motion for a shape of `kind`; lines and rays translate only (they cannot rotate)."""
    rotation = np.zeros(3) if kind in ("Line", "Ray") else rng.normal(size=3) * 2
    translation = rng.normal(size=3) * 3 if translation is None else translation
    return cd.Motion(translation=translation, rotation=rotation, center=rng.normal(size=3))


def swapped_agree(c, d) -> None:
    """A motion query's answer for (b, a, motion_b, motion_a), `d`, is its answer for (a, b,
    motion_a, motion_b), `c`, with a and b exchanged, to the bit."""
    for name in ("time", "distance", "unique"):
        same_bits(getattr(c, name), getattr(d, name))
    for x, y in (("point_a", "point_b"), ("param_a", "param_b")):
        same_bits(getattr(c, x), getattr(d, y))
        same_bits(getattr(c, y), getattr(d, x))
