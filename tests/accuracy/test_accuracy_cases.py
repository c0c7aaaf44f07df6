"""The accuracy report's cases describe the shapes they name.

circledist_cases/accuracy.py keeps each case as one flat tuple in the layout
bench/accuracy_vs_time.cpp reads (its module docstring). The adversarial families of the
differential test come in with their own layout and are converted (accuracy.differential_cases):
a field read in the wrong place there gives the C++ program and the reference the same wrong
shape, which no accuracy check can notice (an annulus's radii were swapped that way). Here every
converted case, read back in the documented layout, must be the differential test's own shapes:
the same fields, and the same distance to the bit.
"""

import numpy as np
import pytest

import circledist as cd
from circledist_cases import accuracy as acc
from circledist_cases import differential as D
from circledist_cases.shapes import make_shape


def _from_layout(kind, v):
    """A shape from accuracy.py's documented layout (shapes.make_shape: the order
    accuracy_vs_time.cpp reads), a point as a Point so that its fields compare too."""
    shape = make_shape(cd, kind, v)
    return cd.Point(shape) if kind == "point" else shape


def _pairs():
    """(family case, accuracy case) for every differential case accuracy.differential_cases takes."""
    converted = acc.differential_cases(list(acc.KINDS))
    by_name = {c.name: c for c in converted}
    out = []
    for family, (pairs, _) in D.FAMILIES.items():
        if family == "random" or family.endswith("_random"):
            continue
        for i in range(2 * len(pairs)):
            c = D.generate_one(family, 2026, i)
            name = f"{family} ({c['id']})"
            if name in by_name:
                out.append((c, by_name[name]))
    assert len(out) == len(converted)
    return out


PAIRS = _pairs()


def test_every_kind_is_converted():
    kinds = {case.kind for _, case in PAIRS}
    assert {"point-annulus", "annulus-annulus", "point-arc", "circle-disk", "bezier-circle"} <= kinds


FIELDS = (
    "center",
    "normal",
    "radius",
    "inner_radius",
    "outer_radius",
    "start",
    "angle",
    "origin",
    "direction",
    "p0",
    "p1",
    "control_points",
)


@pytest.mark.parametrize("kind", sorted({case.kind for _, case in PAIRS}))
def test_converted_shapes_are_the_family_shapes(kind):
    checked = 0
    for c, case in PAIRS:
        if case.kind != kind:
            continue
        (ka, va), (kb, vb) = acc.split_values(case.kind, case.values)
        mine = [_from_layout(ka, va), _from_layout(kb, vb)]
        theirs = [
            D.make_shape(cd, k, np.asarray(data, dtype=np.float64))
            for k, data in ((c["a"], c["a_data"]), (c["b"], c["b_data"]))
        ]
        if (c["a"], c["b"]) != (ka, kb):  # converted to the report's order of the kinds
            theirs.reverse()
        for shape, other in zip(mine, theirs):
            for field in FIELDS:
                if hasattr(shape, field):
                    np.testing.assert_array_equal(
                        np.asarray(getattr(shape, field)),
                        np.asarray(getattr(other, field)),
                        err_msg=f"{case.name}: {field}",
                    )
            if getattr(shape, "kind", None) == "annulus":
                assert shape.inner_radius <= shape.outer_radius, case.name
        assert cd.distance(*mine) == cd.distance(*theirs), case.name
        checked += 1
    assert checked > 0
