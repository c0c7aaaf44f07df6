// The docstrings of the shape classes: each kind's class, its fields, and the methods of Shape
// (bound by shapes.cpp). NumPy-style; their examples run as doctests (tests/package/test_docstrings.py),
// and the generated stubs (python/circledist/_core.pyi) carry them. No behaviour lives here.
#pragma once

#include "../kernels/batch.hpp"

#include <string>

namespace circledist::python::doc {

// The docstring of a shape's field property, by the field's name (shapes.hpp's FieldSpec).
inline const char* field(const std::string& name) {
  if (name == "p") return "The coordinates, shape (..., 3): a read-only array, as stored.";
  if (name == "origin") return "The origin (t = 0), shape (..., 3): a read-only array, as stored.";
  if (name == "direction") return "The direction as given (not normalized), shape (..., 3): a read-only array.";
  if (name == "p0") return "The end point at t = 0, shape (..., 3): a read-only array, as stored.";
  if (name == "p1") return "The end point at t = 1, shape (..., 3): a read-only array, as stored.";
  if (name == "center") return "The center, shape (..., 3): a read-only array, as stored.";
  if (name == "normal") return "The normal as given (not normalized), shape (..., 3): a read-only array.";
  if (name == "radius") return "The radius, of the radius's own batch shape (0-d for one): a read-only array.";
  if (name == "start")
    return "The start direction as given (its projection onto the plane starts the arc), shape (..., 3): a read-only array.";
  if (name == "angle")
    return "The angle in (0, 2 pi], of the angle's own batch shape (0-d for one): a read-only array.";
  if (name == "inner_radius")
    return "The inner radius (of the hole), of its own batch shape (0-d for one): a read-only array.";
  if (name == "outer_radius") return "The outer radius, of its own batch shape (0-d for one): a read-only array.";
  if (name == "control_points") return "The control points, shape (..., k + 1, 3): a read-only array, as stored.";
  if (name == "sweep")
    return "The sweep radius (>= 0; 0-d 0 when not given): the shape grown by it (a ball, a capsule, a torus, a tube).";
  return "A field of the shape: a read-only array, as stored.";
}

// ---- pieces shared by the shape classes -------------------------------------------------------

inline const char* const kShapeParameters = R"(
sweep : array_like, optional
    Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
    capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
copy : bool, default True
    Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
    arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
    copying them (a read-only view, validated once, of arrays the caller promises not to
    change); other dtypes and layouts are still converted, which copies.
)";

inline const char* const kShapeRaises = R"(
Raises
------
ValueError
    When a field is not an array of real numbers, has the wrong trailing shape, contains NaN or
    inf, when a direction or normal has zero length, a radius or sweep is negative, an arc's
    angle is outside (0, 2 pi] or its start is parallel to its normal, an annulus's inner
    radius exceeds its outer radius, or the fields' batch shapes do not broadcast. The message names the class, the field and the first
    offending batch index, e.g. ``Circle: radius[1] is negative``.

Notes
-----
Every field may carry leading batch dimensions; the shape's ``batch_shape`` is their broadcast,
and queries broadcast it against the other argument's like NumPy. Fields are stored as float64
(float32 and integer inputs convert exactly; the shape remembers float32 inputs, which
``precision=None`` follows), or as ``numpy.longdouble`` when given as such, so that
``precision='longdouble'`` reads them unrounded.
)";

inline std::string shape_doc(const char* summary, const char* parameters, const char* attributes,
                             const char* examples) {
  return std::string(summary) + "\n\nParameters\n----------" + parameters + kShapeParameters +
         "\nAttributes\n----------" + attributes +
         "sweep : numpy.ndarray\n    The sweep radius, of the sweep's batch shape.\n"
         "batch_shape : tuple of int\n    Leading batch dimensions; ``()`` for a single shape.\n" +
         kShapeRaises + "\nExamples\n--------" + examples;
}

inline const std::string& point() {
  static const std::string text = shape_doc(
      "A point, or a batch of points.\n\n"
      "Wherever a query takes a shape, a plain array of shape ``(3,)`` or ``(..., 3)`` is taken as\n"
      "``Point(array)``.",
      R"(
p : array_like, shape (3,) or (..., 3)
    Coordinates.)",
      R"(
p : numpy.ndarray, shape (..., 3)
)",
      R"(
>>> import circledist as cd
>>> p = cd.Point([1, 2, 3])
>>> p
Point(p=array([1., 2., 3.]))
>>> cd.Point([[0, 0, 0], [1, 0, 0]]).batch_shape
(2,)
>>> cd.distance(cd.Point([0, 0, 5], sweep=1.0), [0, 0, 0])
4.0
)");
  return text;
}

inline const std::string& linear(const char* kind) {
  static const std::string line = shape_doc("The line ``origin + t * direction``, t real.",
                                            R"(
origin : array_like, shape (3,) or (..., 3)
    A point on the line, the parameter origin (t = 0).
direction : array_like, shape (3,) or (..., 3)
    Direction, of any finite nonzero length (it is normalized internally; parameters t of
    `closest_points` are in units of this vector as given).)",
                                            R"(
origin : numpy.ndarray, shape (..., 3)
direction : numpy.ndarray, shape (..., 3)
)",
                                            R"(
>>> import circledist as cd
>>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])
>>> cd.distance(line, cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
0.5
)");
  static const std::string ray = shape_doc("The ray ``origin + t * direction``, t >= 0.",
                                           R"(
origin : array_like, shape (3,) or (..., 3)
    The ray's start (t = 0).
direction : array_like, shape (3,) or (..., 3)
    Direction, of any finite nonzero length.)",
                                           R"(
origin : numpy.ndarray, shape (..., 3)
direction : numpy.ndarray, shape (..., 3)
)",
                                           R"(
>>> import circledist as cd
>>> ray = cd.Ray([0, 0, 2], [0, 0, 1])
>>> cd.distance(ray, [0, 0, 0])  # the point lies behind the start
2.0
)");
  return std::string(kind) == "Line" ? line : ray;
}

inline const std::string& segment() {
  static const std::string text = shape_doc("The segment ``p0 + t * (p1 - p0)``, t in [0, 1]; ``p0 == p1`` is a point.",
                                            R"(
p0, p1 : array_like, shape (3,) or (..., 3)
    End points.)",
                                            R"(
p0, p1 : numpy.ndarray, shape (..., 3)
)",
                                            R"(
>>> import circledist as cd
>>> capsule = cd.Segment([0, 0, 0], [1, 0, 0], sweep=0.1)
>>> round(cd.distance(capsule, [0.5, 0, 1]), 12)
0.9
)");
  return text;
}

inline const std::string& round_shape(const char* kind) {
  static const char* const parameters = R"(
center : array_like, shape (3,) or (..., 3)
    Center.
normal : array_like, shape (3,) or (..., 3)
    Normal of the plane, of any finite nonzero length.
radius : array_like, shape () or (...)
    Radius >= 0.)";
  static const char* const attributes = R"(
center : numpy.ndarray, shape (..., 3)
normal : numpy.ndarray, shape (..., 3)
radius : numpy.ndarray, shape (...)
)";
  static const std::string circle = shape_doc(
      "The circle (ring) of a center, a normal and a radius.\n\n"
      "`closest_points` reports a circle point by its angle: ``param = (theta, 0)``.",
      parameters, attributes,
      R"(
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> ring
Circle(center=array([0., 0., 0.]), normal=array([0., 0., 1.]), radius=array(1.))
>>> cd.distance(ring, [0, 0, 0])  # every ring point is 1 from the center
1.0
>>> rings = cd.Circle([[0, 0, 0], [0, 0, 2]], [0, 0, 1], [1.0, 2.0])  # a batch of two
>>> rings.batch_shape
(2,)
>>> torus = cd.Circle([0, 0, 0], [0, 0, 1], 1.0, sweep=0.25)
>>> cd.distance(torus, [0, 0, 0])
0.75
)");
  static const std::string disk = shape_doc(
      "The filled disk of a center, a normal and a radius.\n\n"
      "`closest_points` reports a disk point by polar coordinates: ``param = (s, theta)``.",
      parameters, attributes,
      R"(
>>> import circledist as cd
>>> coin = cd.Disk([0, 0, 0], [0, 0, 1], 1.0)
>>> cd.distance(coin, [0.5, 0, 2])  # above the disk: the height
2.0
>>> cd.distance(coin, [3, 0, 0])  # beside it: the distance to the rim
2.0
)");
  return std::string(kind) == "Circle" ? circle : disk;
}

inline const std::string& bezier() {
  static const std::string text = shape_doc(
      "The Bezier curve of k + 1 control points, degree k from 1 to 7, t in [0, 1].\n\n"
      "Queries exist between Bezier curves and circles or disks.",
      R"(
control_points : array_like, shape (k + 1, 3) or (..., k + 1, 3)
    Control points, 2 to 8 of them.)",
      R"(
control_points : numpy.ndarray, shape (..., k + 1, 3)
)",
      R"(
>>> import circledist as cd
>>> cable = cd.Bezier([[-2, 0, 0.5], [0, 0, 0.5], [2, 0, 0.5]])  # a straight piece at height 0.5
>>> cd.distance(cable, cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
0.5
)");
  return text;
}

inline const std::string& arc() {
  static const std::string text = shape_doc(
      "The circular arc ``center + radius * (cos(t) u + sin(t) v)``, t in [0, angle], where u is\n"
      "the unit projection of `start` onto the plane normal to `normal` and v = n x u.\n\n"
      "An angle of 2 pi is the whole circle (the circle's answers). `closest_points` reports an\n"
      "arc point by its angle from the start: ``param = (t, 0)``.",
      R"(
center : array_like, shape (3,) or (..., 3)
    Center of the arc's circle.
normal : array_like, shape (3,) or (..., 3)
    Normal of the plane, of any finite nonzero length.
radius : array_like, shape () or (...)
    Radius >= 0.
start : array_like, shape (3,) or (..., 3)
    Direction of the arc's start from the center: its projection onto the plane, which must
    not be zero (`start` not parallel to `normal`).
angle : array_like, shape () or (...)
    The angle the arc turns through from its start, counterclockwise about the normal, in
    (0, 2 pi].)",
      R"(
center : numpy.ndarray, shape (..., 3)
normal : numpy.ndarray, shape (..., 3)
radius : numpy.ndarray, shape (...)
start : numpy.ndarray, shape (..., 3)
angle : numpy.ndarray, shape (...)
)",
      R"(
>>> import numpy as np
>>> import circledist as cd
>>> quarter = cd.Arc([0, 0, 0], [0, 0, 1], 1.0, [1, 0, 0], np.pi / 2)  # from (1, 0, 0) to (0, 1, 0)
>>> cd.distance(quarter, [0, 0, 0])
1.0
>>> round(cd.distance(quarter, [-2, 0, 0]) ** 2, 12)  # nearest at the end (0, 1, 0): sqrt(5)
5.0
>>> r = cd.closest_points(quarter, [1, 1, 0])
>>> round(float(r.param_a[0]), 12)  # the angle t from the start: the middle of the arc
0.785398163397
)");
  return text;
}

inline const std::string& annulus() {
  static const std::string text = shape_doc(
      "The annulus (a flat ring, a washer): the points of the plane disk of `outer_radius` about\n"
      "`center` at distance >= `inner_radius` from the center.\n\n"
      "An inner radius of 0 is the disk (the disk's answers), an inner radius equal to the outer\n"
      "one the circle (the circle's answers). `closest_points` reports an annulus point as a disk\n"
      "point: ``param = (s, theta)``, s in [inner_radius, outer_radius] its distance from the\n"
      "center.",
      R"(
center : array_like, shape (3,) or (..., 3)
    Center.
normal : array_like, shape (3,) or (..., 3)
    Normal of the plane, of any finite nonzero length.
inner_radius : array_like, shape () or (...)
    Radius >= 0 of the hole, at most `outer_radius`.
outer_radius : array_like, shape () or (...)
    Radius >= 0 of the outer rim.)",
      R"(
center : numpy.ndarray, shape (..., 3)
normal : numpy.ndarray, shape (..., 3)
inner_radius : numpy.ndarray, shape (...)
outer_radius : numpy.ndarray, shape (...)
)",
      R"(
>>> import circledist as cd
>>> washer = cd.Annulus([0, 0, 0], [0, 0, 1], 1.0, 2.0)
>>> cd.distance(washer, [0, 0, 0])  # the center lies in the hole
1.0
>>> cd.distance(washer, [1.5, 0, 3])  # above the ring
3.0
>>> r = cd.closest_points(washer, [0.5, 0, 0])
>>> r.point_a  # on the inner rim
array([1., 0., 0.])
>>> float(r.param_a[0])  # s, the point's distance from the center
1.0
)");
  return text;
}

// The class docstring of each kind, in Kind's order (kernels/batch.hpp): the module binds every kind
// from this list and shapes.hpp's field table, with no per-kind code.
inline const std::string& shape_class(int kind) {
  static const std::string* const docs[] = {
      &point(),  &linear("Line"), &linear("Ray"), &segment(), &round_shape("Circle"), &round_shape("Disk"),
      &bezier(), &arc(),          &annulus()};
  static_assert(sizeof(docs) / sizeof(docs[0]) == kKindCount, "a kind without a class docstring");
  return *docs[kind];
}

inline const char* const kShape = R"(Base class of every shape: a single shape or a batch of them.

Not constructed directly: build a `Point`, `Line`, `Ray`, `Segment`, `Circle`, `Disk`,
`Bezier`, `Arc` or `Annulus`. ``isinstance(x, Shape)`` tells shapes from the array-likes a query takes as points.

Attributes
----------
batch_shape : tuple of int
    Leading batch dimensions; ``()`` for a single shape.
kind : str
    The class name: ``'Point'``, ``'Line'``, ``'Ray'``, ``'Segment'``, ``'Circle'``, ``'Disk'``,
    ``'Bezier'``, ``'Arc'`` or ``'Annulus'``.
sweep : numpy.ndarray
    The sweep radius.

Examples
--------
>>> import circledist as cd
>>> s = cd.Disk([0, 0, 0], [0, 0, 1], [1.0, 2.0, 3.0])
>>> isinstance(s, cd.Shape), s.kind, s.batch_shape
(True, 'Disk', (3,))
)";

inline const char* const kToArrays = R"(The constructor's arguments, as NumPy arrays.

Returns
-------
dict of str to numpy.ndarray
    Keyed by the constructor's argument names (``center``, ``normal``, ``radius``, ...), and
    ``sweep`` when one was given; read-only arrays. Each keeps the dtype it was given in:
    float32, ``numpy.longdouble`` (unrounded), or float64 for everything else. ``from_arrays``
    rebuilds the shape, and ``numpy.savez(path, **shape.to_arrays())`` stores a batch.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> rings = cd.Circle(np.zeros((2, 3)), [0, 0, 1], np.float32([1.0, 2.5]))
>>> arrays = rings.to_arrays()
>>> sorted(arrays), arrays["radius"].dtype
(['center', 'normal', 'radius'], dtype('float32'))
)";

inline const char* const kGetItem = R"(Shapes of the batch, indexed as NumPy indexes an array of the batch shape.

Parameters
----------
key : int, slice, Ellipsis, array_like of int or bool, or a tuple of these
    One entry per batch axis at most (missing trailing axes are taken whole); the fields' own
    axes (a center's 3 values, a curve's control points) are never indexed.

Returns
-------
Shape
    A shape of the same kind holding its own copy of the selected elements' fields (the
    dtypes kept): batch shape ``()`` for one integer per batch axis.

Raises
------
TypeError
    For a single shape (batch shape ``()``), or an entry that is not an index (a float). ``None``
    (``numpy.newaxis``) is not supported: indexing adds no batch axis (give the fields of
    `to_arrays` new axes and rebuild the shape with `from_arrays`).
IndexError
    For more indices than batch axes, or an index out of range.

Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> rings = cd.Circle(np.zeros((4, 3)), [0, 0, 1], [1.0, 2.0, 3.0, 4.0])
>>> rings[1]
Circle(center=array([0., 0., 0.]), normal=array([0., 0., 1.]), radius=array(2.))
>>> rings[rings.to_arrays()["radius"] > 2].batch_shape, len(rings)
((2,), 4)
)";

inline const char* const kFromArrays = R"(The shape of this class built from ``to_arrays()``'s arrays.

Parameters
----------
arrays : mapping of str to array_like
    The constructor's arguments by name (``sweep`` optional), as ``to_arrays`` gives them or
    as read back from an ``.npz`` file.
copy : bool, optional
    Keyword only. As the constructor's ``copy``.

Returns
-------
Shape
    An instance of the class it is called on; the same values and dtypes as the shape the
    arrays came from, so it answers every query with the same bits.

Raises
------
TypeError
    When an argument is missing or an array's name is not one of the constructor's.
ValueError
    As the constructor, for invalid values.

Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0, sweep=0.1)
>>> again = cd.Circle.from_arrays(ring.to_arrays())
>>> cd.distance(again, [0, 0, 3]) == cd.distance(ring, [0, 0, 3])
True
)";

}  // namespace circledist::python::doc
