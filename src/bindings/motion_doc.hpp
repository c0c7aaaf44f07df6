// The docstrings of circledist.Motion and Shape.moved (bound by motion.cpp). NumPy-style; their
// examples run as doctests (tests/package/test_docstrings.py), and the generated stubs
// (python/circledist/_core.pyi) carry them. No behaviour lives here.
#pragma once

#include <string>

namespace circledist::python::doc {

inline const char* const kMotion = R"(Rigid motions over the time interval [0, 1], at constant velocity.

A point ``x`` moves to ``center + R(t * rotation) @ (x - center) + t * translation`` at time
``t``, where ``R(w)`` is the rotation by ``|w|`` radians about ``w / |w|`` (right-handed):
``rotation=(0, 0, 4 * pi)`` turns twice about the z axis through ``center`` while ``translation``
carries the whole along. ``Motion()`` is at rest.

Parameters
----------
translation, rotation, center : array_like, shape (3,) or (..., 3), default (0, 0, 0)
    The displacement over [0, 1], the rotation vector (radians, any number of turns) and the
    point the rotation turns about. Leading dimensions are a batch of motions; the three
    broadcast against each other as shape fields do.
copy : bool, default True
    Keyword only. As a shape constructor's ``copy``.

Attributes
----------
translation, rotation, center : numpy.ndarray
    The fields as stored, shape (..., 3) each; their broadcast leading dimensions are the
    motion's ``batch_shape`` (``()`` for a single motion).

Raises
------
ValueError
    When a field is not an array of real numbers, has a last dimension other than 3, contains
    NaN or inf, or the fields' batch shapes do not broadcast; the message names the field and
    the first offending batch index, e.g. ``Motion: rotation[1] contains NaN or inf``.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> spin = cd.Motion(rotation=[0, 0, np.pi], center=[1, 0, 0])
>>> cd.Point([2, 0, 0]).moved(spin, 1.0).p.round(12) + 0.0
array([0., 0., 0.])
>>> cd.Motion(translation=np.zeros((4, 3))).batch_shape
(4,)
)";

inline const char* motion_field(const std::string& name) {
  if (name == "translation") return "The displacement over [0, 1], shape (..., 3): a read-only array, as stored.";
  if (name == "rotation")
    return "The rotation vector (its length in radians, about its direction), shape (..., 3): a read-only array.";
  return "The point the rotation turns about, shape (..., 3): a read-only array, as stored.";
}

inline const char* const kMotionToArrays = R"(The constructor's arguments, as NumPy arrays.

Returns
-------
dict of str to numpy.ndarray
    ``translation``, ``rotation`` and ``center``: read-only arrays in the dtype each was given
    in (float32, ``numpy.longdouble`` or float64), as a shape's ``to_arrays``.

Examples
--------
>>> import circledist as cd
>>> sorted(cd.Motion(translation=[1, 0, 0]).to_arrays())
['center', 'rotation', 'translation']
)";

inline const char* const kMotionFromArrays = R"(The motion built from ``to_arrays()``'s arrays.

Parameters
----------
arrays : mapping of str to array_like
    ``translation``, ``rotation`` and ``center``, as ``to_arrays`` gives them.
copy : bool, optional
    Keyword only. As the constructor's ``copy``.

Returns
-------
Motion

Raises
------
TypeError
    When an array is missing or its name is not one of the constructor's.
ValueError
    As the constructor, for invalid values.

Examples
--------
>>> import circledist as cd
>>> m = cd.Motion(translation=[1, 2, 3])
>>> cd.Motion.from_arrays(m.to_arrays()).translation
array([1., 2., 3.])
)";

inline const char* const kMoved = R"(The same kind of shape at time ``t`` of a motion.

Centers, origins, end points and control points move as points; directions, normals and an
arc's start rotate (an arc keeps its parameters: its point at angle ``s`` from the start moves
to the moved arc's point at ``s``); radii, angles and the sweep stay.

Parameters
----------
motion : Motion
    The motion (a batch of them broadcasts with the shape's batch).
t : array_like
    The time, finite (the motion is defined on [0, 1]; other times extrapolate the same
    screw); broadcasts with the shape's and the motion's batches.

Returns
-------
Shape
    A shape of this kind whose batch shape is the broadcast of the three. Its points and
    directions are float64 arrays (``numpy.longdouble`` when the shape, the motion or ``t`` was
    given in it; moved float32 values are not float32 values); its radii, angles and sweep are
    the shape's own arrays, in their dtypes.

Raises
------
TypeError
    When ``motion`` is not a ``Motion``.
ValueError
    When ``t`` is not finite real numbers, or the batch shapes do not broadcast.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> lifted = ring.moved(cd.Motion(translation=[0, 0, 2]), [0.0, 0.5, 1.0])
>>> lifted.batch_shape, lifted.center[:, 2]
((3,), array([0., 1., 2.]))
)";

}  // namespace circledist::python::doc
