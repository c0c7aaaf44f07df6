// The docstrings of circledist.Motion, Shape.moved, first_contact and its answer, Contact, and
// closest_approach and its answer, Approach (bound by motion.cpp). NumPy-style; their examples
// run as doctests (tests/package/test_docstrings.py), and the generated stubs
// (python/circledist/_core.pyi) carry them. No behaviour lives here.
#pragma once

#include "arguments_doc.hpp"

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

inline const char* const kContact =
    R"(The answer of `first_contact`: when the shapes first come within reach, and where.

For single shapes ``time`` and ``distance`` are floats (``numpy.longdouble`` in long double)
and ``unique`` a bool; for batches each attribute is an array of the broadcast batch shape
(with a trailing axis of 3 for points and of 2 for parameters).

Attributes
----------
time : float or numpy.ndarray
    The earliest time in [0, 1] at which the moving shapes are within ``within`` of each
    other; ``inf`` where they never are.
distance : float or numpy.ndarray
    The distance at that time (at most ``within``, to the bar given in `first_contact`); NaN
    where there is no contact.
point_a, point_b : numpy.ndarray, shape (..., 3)
    A closest pair of the moved shapes at that time, as `closest_points` gives it; NaN where
    there is no contact.
param_a, param_b : numpy.ndarray, shape (..., 2)
    Their parameters on the moved shapes (as `closest_points`' ``param_a``, ``param_b``); NaN
    where there is no contact.
unique : bool or numpy.ndarray
    `closest_points`' ``unique`` at that time; True where there is no contact.

Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> c = cd.first_contact(cd.Point([3, 0, 0]), ring, cd.Motion(translation=[-4, 0, 0]))
>>> round(c.time, 12), c.point_b.round(12) + 0.0
(0.5, array([1., 0., 0.]))
)";

inline const char* kFirstContact() {
  static const std::string text = std::string() +
                                  R"(The earliest time at which two moving shapes come within a distance of each other.

With ``a(t) = a.moved(motion_a, t)`` and ``b(t)`` likewise, the earliest ``t`` in [0, 1] with
``distance(a(t), b(t)) <= within``, found by conservative advancement on the exact distance:
from a time ``t`` where the gap ``g = distance - within`` is positive, no time before
``t + g / L`` can close it, ``L`` a bound on how fast the distance can fall (the relative
translation speed plus each rotation's angular speed times the shape's reach from its center).
The answer meets the bar ``delta = 1e-12 S`` (``S`` the largest coordinate, radius or travel of
the query): the distance at ``time`` is at most ``within + delta``, and no earlier time has a
distance below ``within - delta``. A tangential approach takes of the order of
``sqrt(S / delta)`` distance evaluations; each counts in `stats` (``distances``, and
``closest_points`` for the contact), and each is `distance`'s own, with the chosen solver. Both
argument orders agree to the bit (with the motions exchanged). ``precision=None`` follows the
motions given as well as the shapes (a motion's fields of zeros, as its defaults, decide
nothing).

Parameters
----------
)" + kQueryParameters + R"(motion_a, motion_b : Motion or None, optional
    The motions of a and b over [0, 1]; None (the default) is at rest. Their batch shapes
    broadcast with the shapes'. A line or ray cannot rotate (its points reach infinitely far
    from the center, so no speed bound exists): only translations move them.
within : array_like, optional
    Keyword only. Finite contact distances >= 0, a scalar or an array broadcasting with the
    batch; default 0 (touching).
)" + kChoiceParameters + kProgressParameter +
                                  R"(
Returns
-------
Contact
    ``time`` (inf where there is no contact), ``distance``, ``point_a``, ``point_b``,
    ``param_a``, ``param_b`` (NaN where there is no contact) and ``unique``.

Raises
------
ValueError
    When a line or ray is given a rotating motion (the message names the motion and the
    batch index), ``within`` is negative or not finite, the batch shapes do not broadcast, an
    input is beyond float32's range (float32), the precision or solver is unknown, or the worker
    count is neither positive nor -1.
RuntimeError
    When a query needs more than 2**20 distance evaluations (motions vastly faster than the
    shapes' size over the bar, or a tangential approach at such a speed); the message names
    the batch index. No answer is given rather than "no contact" for a contact not excluded.
TypeError
    When a motion is neither a `Motion` nor None, or `progress` is neither None, a bool nor a
    callable.

See Also
--------
closest_approach : the least distance over the motion.
Motion : the motions.
Shape.moved : a shape at one time of its motion.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> point = cd.Point([3, 0, 0])
>>> towards = cd.Motion(translation=[-4, 0, 0])  # closes the gap of 2 at speed 4
>>> round(cd.first_contact(point, ring, towards).time, 12)
0.5
>>> round(cd.first_contact(point, ring, towards, within=0.5).time, 12)
0.375
>>> cd.first_contact(point, ring).time  # both at rest: never
inf
>>> speeds = cd.Motion(translation=[[-4, 0, 0], [-8, 0, 0], [-1, 0, 0]])
>>> cd.first_contact(point, ring, speeds).time.round(12)  # a batch of motions
array([0.5 , 0.25,  inf])
)";
  return text.c_str();
}

inline const char* const kApproach =
    R"(The answer of `closest_approach`: the least distance of two moving shapes, when, and where.

For single shapes ``time`` and ``distance`` are floats (``numpy.longdouble`` in long double)
and ``unique`` a bool; for batches each attribute is an array of the broadcast batch shape
(with a trailing axis of 3 for points and of 2 for parameters).

Attributes
----------
time : float or numpy.ndarray
    A time in [0, 1] at which the distance is least (0 for shapes at rest relative to each
    other); NaN for NaN input.
distance : float or numpy.ndarray
    The least distance over the motion (`closest_points`' distance at ``time``).
point_a, point_b : numpy.ndarray, shape (..., 3)
    A closest pair of the moved shapes at that time, as `closest_points` gives it.
param_a, param_b : numpy.ndarray, shape (..., 2)
    Their parameters on the moved shapes (as `closest_points`' ``param_a``, ``param_b``).
unique : bool or numpy.ndarray
    False where another time is as close (the shapes at rest relative to each other, a
    distance constant over a stretch of time, two separate times within the bar) or where
    `closest_points`' pair at ``time`` is not unique.

Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> a = cd.closest_approach(cd.Point([-3, 2, 1]), ring, cd.Motion(translation=[6, 0, 0]))
>>> round(a.time, 9), round(a.distance, 12)
(0.5, 1.414213562373)
)";

inline const char* kClosestApproach() {
  static const std::string text = std::string() +
                                  R"(The least distance between two moving shapes over the motion, and when.

With ``a(t) = a.moved(motion_a, t)`` and ``b(t)`` likewise, the least of
``distance(a(t), b(t))`` over ``t`` in [0, 1], the time it happens and the closest points then.
A branch and bound over ``t`` on the exact distance, with the speed bound ``L`` of
`first_contact` (no stretch ``[t0, t1]`` holds a distance below
``(d(t0) + d(t1) - L (t1 - t0)) / 2``), excludes every stretch of time that cannot come closer
than ``1e-5 S`` below the best distance found (``S`` the query's size, as in `first_contact`);
a golden-section polish of every dip the stretches left show (each local least of their
samples, the least first) then finds the least to the bar ``1e-12 S`` where it is a local least
of its dip's bracket (past the fourth dip the polish stops at four times the search's
evaluations: a distance flat over many stretches). Shapes at rest relative to each other
(the same motion, or a ring spinning about its own axis) have one distance: time 0, ``unique``
False. Each distance counts in `stats` (``distances``, and ``closest_points`` for the answer);
both argument orders agree to the bit (with the motions exchanged). ``precision=None`` follows
the motions given as well as the shapes.

Parameters
----------
)" + kQueryParameters + R"(motion_a, motion_b : Motion or None, optional
    The motions of a and b over [0, 1]; None (the default) is at rest. Their batch shapes
    broadcast with the shapes'. A line or ray cannot rotate: only translations move them.
)" + kChoiceParameters + kProgressParameter +
                                  R"(
Returns
-------
Approach
    ``time``, ``distance``, ``point_a``, ``point_b``, ``param_a``, ``param_b`` and ``unique``.

Raises
------
ValueError
    When a line or ray is given a rotating motion (the message names the motion and the
    batch index), the batch shapes do not broadcast, an input is beyond float32's range
    (float32), the precision or solver is unknown, or the worker count is neither positive
    nor -1.
RuntimeError
    When a query needs more than 2**20 distance evaluations (motions vastly faster than the
    shapes' size over the bar); the message names the batch index. No answer is given rather
    than one that could miss a closer time.
TypeError
    When a motion is neither a `Motion` nor None, or `progress` is neither None, a bool nor a
    callable.

See Also
--------
first_contact : the earliest time within a distance.
Motion : the motions.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> passing = cd.Motion(translation=[6, 0, 0])  # from x = -3 to 3, 2 off the axis, 1 above
>>> a = cd.closest_approach(cd.Point([-3, 2, 1]), ring, passing)
>>> round(a.time, 9), a.point_b.round(9) + 0.0
(0.5, array([0., 1., 0.]))
>>> spin = cd.Motion(rotation=[0, 0, 4 * np.pi])  # about its own axis: the ring stays put
>>> s = cd.closest_approach(ring, cd.Point([2, 0, 0]), spin)
>>> s.time, s.distance, s.unique
(0.0, 1.0, False)
)";
  return text.c_str();
}

}  // namespace circledist::python::doc
