"""What the regression files (test_regressions*.py) share: the solver policies, the accuracy
bars and the shape of a flat tuple of numbers."""

import numpy as np
import pytest

cd = pytest.importorskip("circledist")

SOLVERS = ("bracketing", "companion", "polished", "eigen")
BARS = {"float64": 1e-12, "longdouble": 1e-15}
EPS = np.finfo(np.float64).eps
LINEAR = ("point", "line", "ray", "segment")


def make(kind, data):
    if kind == "point":
        return cd.Point(data[:3])
    if kind in ("line", "ray"):
        return getattr(cd, kind.capitalize())(data[:3], data[3:6])
    if kind == "segment":
        return cd.Segment(data[:3], data[3:6])
    if kind in ("circle", "disk"):
        return getattr(cd, kind.capitalize())(data[:3], data[3:6], data[6])
    if kind == "bezier":
        return cd.Bezier(data if isinstance(data, np.ndarray) else np.array(data, dtype=float))
    raise ValueError(kind)
