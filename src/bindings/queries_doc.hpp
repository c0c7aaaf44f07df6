// The docstrings of distance, closest_points and their answer, ClosestPoints (bound by
// queries.cpp). NumPy-style; their examples run as doctests (tests/package/test_docstrings.py).
#pragma once

#include "arguments_doc.hpp"

#include <string>

namespace circledist::python::doc {

inline const char* const kClosestPoints =
    R"(The answer of `closest_points`: the distance, a closest pair and its parameters.

For single shapes the distance is a float (a ``numpy.longdouble`` in long double) and the flag
a bool; for batches each attribute is an array of the broadcast batch shape (with a trailing
axis of 3 for points and of 2 for parameters). A batch's arrays are views of one allocation (a
large batch then costs one mapping, not six): any one of them kept keeps all of it, so copy
what you keep of a large batch (``r.distance.copy()``).

Attributes
----------
distance : float or numpy.ndarray
    The distance, as `distance` gives it.
point_a, point_b : numpy.ndarray, shape (..., 3)
    A closest point on the first and on the second argument.
param_a, param_b : numpy.ndarray, shape (..., 2)
    Their parameters: ``(t, 0)`` on points, lines, rays, segments and curves, ``(theta, 0)``
    on circles, ``(s, theta)`` on disks (angles in the shape's own frame about its normal).
    Always in the shape's domain: t >= 0 on rays, t in [0, 1] on segments and curves, t in
    [0, angle] on arcs, s in [0, radius] on disks and in [inner_radius, outer_radius] on annuli.
unique : bool or numpy.ndarray
    False when another distinct pair is as close (a line on a circle's axis, concentric
    coplanar circles).

Examples
--------
>>> import circledist as cd
>>> r = cd.closest_points(cd.Line([-3, 1, 0.5], [1, 0, 0]), cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
>>> r.distance, r.unique
(0.5, True)
>>> print(r.point_a, r.point_b)
[0.  1.  0.5] [0. 1. 0.]
)";

inline const char* kDistance() {
  static const std::string text = std::string() +
                                  "Distance between a and b.\n\n"
                                  "Does no closest-point work. Both argument orders agree to the bit.\n\n"
                                  "Parameters\n----------\n" +
                                  kQueryParameters + kChoiceParameters + kProgressParameter + R"(
Returns
-------
float or numpy.ndarray
    A float for two single shapes (a ``numpy.longdouble`` in long double); otherwise an array of
    the broadcast batch shape (dtype float64, float32 or longdouble, by precision).

)" + kQueryRaises + R"(
See Also
--------
closest_points : the closest points as well.
distance_if_within : the distance only where it is at most a limit.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])  # passes 0.5 above the rim
>>> cd.distance(line, ring)
0.5
>>> cd.distance(line, ring, precision="longdouble", solver="companion") == 0.5
np.True_
>>> cd.distance([[2, 0, 0], [0, 0, 3]], ring)  # two points against one ring
array([1.        , 3.16227766])
>>> rings = cd.Circle(np.zeros((3, 3)), [0, 0, 1], [1.0, 2.0, 3.0])
>>> cd.distance(cd.Point(np.zeros((2, 1, 3))), rings).shape  # (2, 1) with (3,) broadcast
(2, 3)
>>> cd.distance(line, ring, solver="newton")
Traceback (most recent call last):
...
ValueError: solver must be None, 'default', 'companion', 'polished', 'bracketing' or 'eigen', got 'newton'
)";
  return text.c_str();
}

inline const char* kClosest() {
  static const std::string text =
      std::string() +
      "Distance, closest points on a and b, their parameters and whether they are unique.\n\n"
      "``closest_points(b, a)`` is ``closest_points(a, b)`` with the points and parameters "
      "exchanged.\n\n"
      "Parameters\n----------\n" +
      kQueryParameters + kChoiceParameters + kProgressParameter + R"(
Returns
-------
ClosestPoints
    ``distance``, ``point_a``, ``point_b``, ``param_a``, ``param_b`` and ``unique``: scalars and
    single points for two single shapes, arrays of the broadcast batch shape otherwise.

)" + kQueryRaises +
      R"(
Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> r = cd.closest_points(cd.Line([-3, 1, 0.5], [1, 0, 0]), ring)
>>> r
ClosestPoints(distance=0.5, point_a=array([0. , 1. , 0.5]), point_b=array([0., 1., 0.]), unique=True)
>>> print(r.param_a)  # t on the line: origin + 3 * direction
[3. 0.]
>>> cd.closest_points(cd.Line([0, 0, -1], [0, 0, 1]), ring).unique  # on the axis: every ring point
False
)";
  return text.c_str();
}

}  // namespace circledist::python::doc
