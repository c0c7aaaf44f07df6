"""
circledist: exact distances and closest points between circles, disks, arcs, annuli, lines, rays, segments, points and Bezier curves in 3D
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['Annulus', 'Approach', 'Arc', 'Bezier', 'Circle', 'ClosestPoints', 'Contact', 'Disk', 'Line', 'Motion', 'Point', 'Ray', 'Segment', 'Shape', 'closest_approach', 'closest_points', 'distance', 'distance_if_within', 'first_contact', 'intersects', 'nearest', 'pairs_within', 'reset_stats', 'stats', 'within']
class Shape:
    """
    Base class of every shape: a single shape or a batch of them.
    
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
    """
    def __bool__(self) -> bool:
        ...
    def __getitem__(self, key: typing.Any) -> typing.Any:
        """
        Shapes of the batch, indexed as NumPy indexes an array of the batch shape.
        
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
        """
    def __iter__(self) -> typing.Any:
        ...
    def __len__(self) -> int:
        """
        The length of the first batch axis; TypeError for a single shape.
        """
    def __reduce__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def from_arrays(self: type, arrays: dict, *, copy: bool = True) -> typing.Any:
        """
        The shape of this class built from ``to_arrays()``'s arrays.
        
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
        """
    def moved(self, motion: Motion, t: numpy.typing.ArrayLike) -> Shape:
        """
        The same kind of shape at time ``t`` of a motion.
        
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
        """
    def to_arrays(self) -> dict:
        """
        The constructor's arguments, as NumPy arrays.
        
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
        """
    @property
    def batch_shape(self) -> tuple[int, ...]:
        """
        Leading batch dimensions; () for a single shape.
        """
    @property
    def kind(self) -> str:
        """
        The class name, e.g. 'Circle'.
        """
    @property
    def sweep(self) -> numpy.ndarray:
        """
        The sweep radius (>= 0; 0-d 0 when not given): the shape grown by it (a ball, a capsule, a torus, a tube).
        """
class Point(Shape):
    """
    A point, or a batch of points.
    
    Wherever a query takes a shape, a plain array of shape ``(3,)`` or ``(..., 3)`` is taken as
    ``Point(array)``.
    
    Parameters
    ----------
    p : array_like, shape (3,) or (..., 3)
        Coordinates.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    p : numpy.ndarray, shape (..., 3)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
    >>> import circledist as cd
    >>> p = cd.Point([1, 2, 3])
    >>> p
    Point(p=array([1., 2., 3.]))
    >>> cd.Point([[0, 0, 0], [1, 0, 0]]).batch_shape
    (2,)
    >>> cd.distance(cd.Point([0, 0, 5], sweep=1.0), [0, 0, 0])
    4.0
    """
    def __init__(self, p: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def p(self) -> numpy.ndarray:
        """
        The coordinates, shape (..., 3): a read-only array, as stored.
        """
class Line(Shape):
    """
    The line ``origin + t * direction``, t real.
    
    Parameters
    ----------
    origin : array_like, shape (3,) or (..., 3)
        A point on the line, the parameter origin (t = 0).
    direction : array_like, shape (3,) or (..., 3)
        Direction, of any finite nonzero length (it is normalized internally; parameters t of
        `closest_points` are in units of this vector as given).
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    origin : numpy.ndarray, shape (..., 3)
    direction : numpy.ndarray, shape (..., 3)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
    >>> import circledist as cd
    >>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])
    >>> cd.distance(line, cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
    0.5
    """
    def __init__(self, origin: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def direction(self) -> numpy.ndarray:
        """
        The direction as given (not normalized), shape (..., 3): a read-only array.
        """
    @property
    def origin(self) -> numpy.ndarray:
        """
        The origin (t = 0), shape (..., 3): a read-only array, as stored.
        """
class Ray(Shape):
    """
    The ray ``origin + t * direction``, t >= 0.
    
    Parameters
    ----------
    origin : array_like, shape (3,) or (..., 3)
        The ray's start (t = 0).
    direction : array_like, shape (3,) or (..., 3)
        Direction, of any finite nonzero length.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    origin : numpy.ndarray, shape (..., 3)
    direction : numpy.ndarray, shape (..., 3)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
    >>> import circledist as cd
    >>> ray = cd.Ray([0, 0, 2], [0, 0, 1])
    >>> cd.distance(ray, [0, 0, 0])  # the point lies behind the start
    2.0
    """
    def __init__(self, origin: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def direction(self) -> numpy.ndarray:
        """
        The direction as given (not normalized), shape (..., 3): a read-only array.
        """
    @property
    def origin(self) -> numpy.ndarray:
        """
        The origin (t = 0), shape (..., 3): a read-only array, as stored.
        """
class Segment(Shape):
    """
    The segment ``p0 + t * (p1 - p0)``, t in [0, 1]; ``p0 == p1`` is a point.
    
    Parameters
    ----------
    p0, p1 : array_like, shape (3,) or (..., 3)
        End points.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    p0, p1 : numpy.ndarray, shape (..., 3)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
    >>> import circledist as cd
    >>> capsule = cd.Segment([0, 0, 0], [1, 0, 0], sweep=0.1)
    >>> round(cd.distance(capsule, [0.5, 0, 1]), 12)
    0.9
    """
    def __init__(self, p0: numpy.typing.ArrayLike, p1: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def p0(self) -> numpy.ndarray:
        """
        The end point at t = 0, shape (..., 3): a read-only array, as stored.
        """
    @property
    def p1(self) -> numpy.ndarray:
        """
        The end point at t = 1, shape (..., 3): a read-only array, as stored.
        """
class Circle(Shape):
    """
    The circle (ring) of a center, a normal and a radius.
    
    `closest_points` reports a circle point by its angle: ``param = (theta, 0)``.
    
    Parameters
    ----------
    center : array_like, shape (3,) or (..., 3)
        Center.
    normal : array_like, shape (3,) or (..., 3)
        Normal of the plane, of any finite nonzero length.
    radius : array_like, shape () or (...)
        Radius >= 0.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    center : numpy.ndarray, shape (..., 3)
    normal : numpy.ndarray, shape (..., 3)
    radius : numpy.ndarray, shape (...)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
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
    """
    def __init__(self, center: numpy.typing.ArrayLike, normal: numpy.typing.ArrayLike, radius: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def center(self) -> numpy.ndarray:
        """
        The center, shape (..., 3): a read-only array, as stored.
        """
    @property
    def normal(self) -> numpy.ndarray:
        """
        The normal as given (not normalized), shape (..., 3): a read-only array.
        """
    @property
    def radius(self) -> numpy.ndarray:
        """
        The radius, of the radius's own batch shape (0-d for one): a read-only array.
        """
class Disk(Shape):
    """
    The filled disk of a center, a normal and a radius.
    
    `closest_points` reports a disk point by polar coordinates: ``param = (s, theta)``.
    
    Parameters
    ----------
    center : array_like, shape (3,) or (..., 3)
        Center.
    normal : array_like, shape (3,) or (..., 3)
        Normal of the plane, of any finite nonzero length.
    radius : array_like, shape () or (...)
        Radius >= 0.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    center : numpy.ndarray, shape (..., 3)
    normal : numpy.ndarray, shape (..., 3)
    radius : numpy.ndarray, shape (...)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
    >>> import circledist as cd
    >>> coin = cd.Disk([0, 0, 0], [0, 0, 1], 1.0)
    >>> cd.distance(coin, [0.5, 0, 2])  # above the disk: the height
    2.0
    >>> cd.distance(coin, [3, 0, 0])  # beside it: the distance to the rim
    2.0
    """
    def __init__(self, center: numpy.typing.ArrayLike, normal: numpy.typing.ArrayLike, radius: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def center(self) -> numpy.ndarray:
        """
        The center, shape (..., 3): a read-only array, as stored.
        """
    @property
    def normal(self) -> numpy.ndarray:
        """
        The normal as given (not normalized), shape (..., 3): a read-only array.
        """
    @property
    def radius(self) -> numpy.ndarray:
        """
        The radius, of the radius's own batch shape (0-d for one): a read-only array.
        """
class Bezier(Shape):
    """
    The Bezier curve of k + 1 control points, degree k from 1 to 7, t in [0, 1].
    
    Queries exist between Bezier curves and circles or disks.
    
    Parameters
    ----------
    control_points : array_like, shape (k + 1, 3) or (..., k + 1, 3)
        Control points, 2 to 8 of them.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    control_points : numpy.ndarray, shape (..., k + 1, 3)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
    >>> import circledist as cd
    >>> cable = cd.Bezier([[-2, 0, 0.5], [0, 0, 0.5], [2, 0, 0.5]])  # a straight piece at height 0.5
    >>> cd.distance(cable, cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
    0.5
    """
    def __init__(self, control_points: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def control_points(self) -> numpy.ndarray:
        """
        The control points, shape (..., k + 1, 3): a read-only array, as stored.
        """
class Arc(Shape):
    """
    The circular arc ``center + radius * (cos(t) u + sin(t) v)``, t in [0, angle], where u is
    the unit projection of `start` onto the plane normal to `normal` and v = n x u.
    
    An angle of 2 pi is the whole circle (the circle's answers). `closest_points` reports an
    arc point by its angle from the start: ``param = (t, 0)``.
    
    Parameters
    ----------
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
        (0, 2 pi].
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    center : numpy.ndarray, shape (..., 3)
    normal : numpy.ndarray, shape (..., 3)
    radius : numpy.ndarray, shape (...)
    start : numpy.ndarray, shape (..., 3)
    angle : numpy.ndarray, shape (...)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
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
    """
    def __init__(self, center: numpy.typing.ArrayLike, normal: numpy.typing.ArrayLike, radius: numpy.typing.ArrayLike, start: numpy.typing.ArrayLike, angle: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def angle(self) -> numpy.ndarray:
        """
        The angle in (0, 2 pi], of the angle's own batch shape (0-d for one): a read-only array.
        """
    @property
    def center(self) -> numpy.ndarray:
        """
        The center, shape (..., 3): a read-only array, as stored.
        """
    @property
    def normal(self) -> numpy.ndarray:
        """
        The normal as given (not normalized), shape (..., 3): a read-only array.
        """
    @property
    def radius(self) -> numpy.ndarray:
        """
        The radius, of the radius's own batch shape (0-d for one): a read-only array.
        """
    @property
    def start(self) -> numpy.ndarray:
        """
        The start direction as given (its projection onto the plane starts the arc), shape (..., 3): a read-only array.
        """
class Annulus(Shape):
    """
    The annulus (a flat ring, a washer): the points of the plane disk of `outer_radius` about
    `center` at distance >= `inner_radius` from the center.
    
    An inner radius of 0 is the disk (the disk's answers), an inner radius equal to the outer
    one the circle (the circle's answers). `closest_points` reports an annulus point as a disk
    point: ``param = (s, theta)``, s in [inner_radius, outer_radius] its distance from the
    center.
    
    Parameters
    ----------
    center : array_like, shape (3,) or (..., 3)
        Center.
    normal : array_like, shape (3,) or (..., 3)
        Normal of the plane, of any finite nonzero length.
    inner_radius : array_like, shape () or (...)
        Radius >= 0 of the hole, at most `outer_radius`.
    outer_radius : array_like, shape () or (...)
        Radius >= 0 of the outer rim.
    sweep : array_like, optional
        Keyword only. Radius >= 0 by which the shape is grown (a point becomes a ball, a segment a
        capsule, a circle a torus, a curve a tube); broadcasts with the other fields. Default 0.
    copy : bool, default True
        Keyword only. True keeps a read-only copy of every field, so later changes to the caller's
        arrays change nothing. False makes the shape refer to float64 C-contiguous arrays without
        copying them (a read-only view, validated once, of arrays the caller promises not to
        change); other dtypes and layouts are still converted, which copies.
    
    Attributes
    ----------
    center : numpy.ndarray, shape (..., 3)
    normal : numpy.ndarray, shape (..., 3)
    inner_radius : numpy.ndarray, shape (...)
    outer_radius : numpy.ndarray, shape (...)
    sweep : numpy.ndarray
        The sweep radius, of the sweep's batch shape.
    batch_shape : tuple of int
        Leading batch dimensions; ``()`` for a single shape.
    
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
    
    Examples
    --------
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
    """
    def __init__(self, center: numpy.typing.ArrayLike, normal: numpy.typing.ArrayLike, inner_radius: numpy.typing.ArrayLike, outer_radius: numpy.typing.ArrayLike, *, sweep: numpy.typing.ArrayLike | None = None, copy: bool = True) -> None:
        ...
    @property
    def center(self) -> numpy.ndarray:
        """
        The center, shape (..., 3): a read-only array, as stored.
        """
    @property
    def inner_radius(self) -> numpy.ndarray:
        """
        The inner radius (of the hole), of its own batch shape (0-d for one): a read-only array.
        """
    @property
    def normal(self) -> numpy.ndarray:
        """
        The normal as given (not normalized), shape (..., 3): a read-only array.
        """
    @property
    def outer_radius(self) -> numpy.ndarray:
        """
        The outer radius, of its own batch shape (0-d for one): a read-only array.
        """
class ClosestPoints:
    """
    The answer of `closest_points`: the distance, a closest pair and its parameters.
    
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
    """
    def __repr__(self) -> str:
        ...
    @property
    def distance(self) -> float | numpy.longdouble | numpy.ndarray:
        """
        The distance, as distance() gives it.
        """
    @property
    def param_a(self) -> numpy.ndarray:
        """
        point_a's parameters, shape (..., 2): (t, 0), (theta, 0) on circles, (s, theta) on disks.
        """
    @property
    def param_b(self) -> numpy.ndarray:
        """
        point_b's parameters, shape (..., 2).
        """
    @property
    def point_a(self) -> numpy.ndarray:
        """
        A closest point on the first argument, shape (..., 3).
        """
    @property
    def point_b(self) -> numpy.ndarray:
        """
        A closest point on the second argument, shape (..., 3).
        """
    @property
    def unique(self) -> bool | numpy.ndarray:
        """
        False when another distinct pair is as close.
        """
class _Broadphase:
    """
    The broadphase over a scene's items, numbered in the order added, which can grow between queries (used by circledist.Scene).
    """
    def __init__(self) -> None:
        ...
    def __len__(self) -> int:
        ...
    def add(self, parts: list, workers: int = 1) -> None:
        """
        Adds items numbered on from len(self): parts are (shape, item numbers, group, first row).
        """
    def limit(self, shape: typing.Any, d: typing.SupportsFloat | typing.SupportsIndex, items: typing.Any = None) -> typing.Any:
        """
        The culling limit of d for a single shape: one above every item's, or each of items' own.
        """
    def locate(self, items: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> tuple:
        """
        (groups, rows) of items.
        """
    def merge(self, workers: int = 1) -> None:
        """
        Merges the trees into one (pairs_within's tree), the GIL released.
        """
    def nearest_by_bound(self, shape: typing.Any, k: typing.SupportsInt | typing.SupportsIndex) -> tuple:
        """
        (indices, lower bounds) of the k elements of smallest lower bound, by bound.
        """
    def pairs_within(self, groups: list, names: list, d: typing.SupportsFloat | typing.SupportsIndex, workers: int = 1, max_pairs: typing.Any = 100000000) -> tuple:
        """
        (pairs, candidates): (names[i], names[j]) for the items i < j within d, sorted, and how many pairs were tested.
        """
    def within(self, shape: typing.Any, d: typing.SupportsFloat | typing.SupportsIndex) -> tuple:
        """
        (indices, lower bounds) of the elements within their culling limit of d of a single shape, sorted.
        """
    @property
    def scale(self) -> float:
        ...
    @property
    def trees(self) -> int:
        """
        How many trees hold the items (at most log2(len) + 1).
        """
class Motion:
    """
    Rigid motions over the time interval [0, 1], at constant velocity.
    
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
    """
    def __init__(self, translation: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), rotation: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), center: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), *, copy: bool = True) -> None:
        ...
    def __reduce__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def from_arrays(self: type, arrays: dict, *, copy: bool = True) -> Motion:
        """
        The motion built from ``to_arrays()``'s arrays.
        
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
        """
    def to_arrays(self) -> dict:
        """
        The constructor's arguments, as NumPy arrays.
        
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
        """
    @property
    def batch_shape(self) -> tuple[int, ...]:
        """
        Leading batch dimensions; () for a single motion.
        """
    @property
    def center(self) -> numpy.ndarray:
        """
        The point the rotation turns about, shape (..., 3): a read-only array, as stored.
        """
    @property
    def rotation(self) -> numpy.ndarray:
        """
        The rotation vector (its length in radians, about its direction), shape (..., 3): a read-only array.
        """
    @property
    def translation(self) -> numpy.ndarray:
        """
        The displacement over [0, 1], shape (..., 3): a read-only array, as stored.
        """
class Contact:
    """
    The answer of `first_contact`: when the shapes first come within reach, and where.
    
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
    """
    def __repr__(self) -> str:
        ...
    @property
    def distance(self) -> float | numpy.longdouble | numpy.ndarray:
        """
        The distance at that time (at most `within`, within rounding); NaN where there is no contact.
        """
    @property
    def param_a(self) -> numpy.ndarray:
        """
        point_a's parameters on the moved first shape, shape (..., 2), as closest_points' param_a.
        """
    @property
    def param_b(self) -> numpy.ndarray:
        """
        point_b's parameters on the moved second shape, shape (..., 2).
        """
    @property
    def point_a(self) -> numpy.ndarray:
        """
        A closest point on the first shape at that time, shape (..., 3); NaN where there is no contact.
        """
    @property
    def point_b(self) -> numpy.ndarray:
        """
        A closest point on the second shape at that time, shape (..., 3); NaN where there is no contact.
        """
    @property
    def time(self) -> float | numpy.longdouble | numpy.ndarray:
        """
        The earliest time in [0, 1] within reach; inf where the shapes never come within it.
        """
    @property
    def unique(self) -> bool | numpy.ndarray:
        """
        closest_points' unique at that time (True where there is no contact).
        """
class Approach:
    """
    The answer of `closest_approach`: the least distance of two moving shapes, when, and where.
    
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
    """
    def __repr__(self) -> str:
        ...
    @property
    def distance(self) -> float | numpy.longdouble | numpy.ndarray:
        """
        The least distance over [0, 1] (closest_points' distance at that time).
        """
    @property
    def param_a(self) -> numpy.ndarray:
        """
        point_a's parameters on the moved first shape, shape (..., 2), as closest_points' param_a.
        """
    @property
    def param_b(self) -> numpy.ndarray:
        """
        point_b's parameters on the moved second shape, shape (..., 2).
        """
    @property
    def point_a(self) -> numpy.ndarray:
        """
        A closest point on the first shape at that time, shape (..., 3).
        """
    @property
    def point_b(self) -> numpy.ndarray:
        """
        A closest point on the second shape at that time, shape (..., 3).
        """
    @property
    def time(self) -> float | numpy.longdouble | numpy.ndarray:
        """
        A time in [0, 1] of the least distance (the earliest of equal ones found); NaN for NaN input.
        """
    @property
    def unique(self) -> bool | numpy.ndarray:
        """
        False where another time is as close (within the bar) or closest_points' pair is not unique.
        """
def _count_culled(n: typing.SupportsInt | typing.SupportsIndex) -> None:
    """
    Adds n to stats()['culled'] (used by circledist.Scene).
    """
def _distance_limit(owner: str, d: typing.Any) -> float:
    """
    The distance limit d as a float (finite, >= 0), or a TypeError / ValueError naming it.
    """
def _from_arrays(cls: type, arrays: dict, copy: bool) -> typing.Any:
    """
    cls.from_arrays(arrays, copy=copy): how pickle rebuilds a shape.
    """
def _integer_argument(owner: str, name: str, value: typing.Any, wanted: str) -> int:
    """
    The integer argument `value` (bools refused, 64 bits at most), or a TypeError / ValueError naming it.
    """
def _motion_from_arrays(arrays: dict, copy: bool) -> Motion:
    """
    Motion.from_arrays(arrays, copy=copy): how pickle rebuilds a motion.
    """
def _query_kinds() -> list[tuple[str, str]]:
    """
    The (kind, kind) pairs that have a query (used by circledist.Scene).
    """
def _shape_fields() -> dict[str, tuple[tuple[str, str], ...]]:
    """
    Each kind's constructor fields in order, as (name, role) pairs; role 'vector' (shape (3,)), 'direction' (shape (3,), not zero), 'length' (a number >= 0), 'angle' (a number in (0, 2 pi]) or 'control_points' (shape (k + 1, 3)). Read by the scene files, the command line and circledist.Scene.
    """
def _sweep_field() -> tuple[str, str]:
    """
    The (name, role) of the optional keyword field every kind takes after its own fields.
    """
def closest_approach(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, motion_a: Motion | None = None, motion_b: Motion | None = None, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> Approach:
    """
    The least distance between two moving shapes over the motion, and when.
    
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
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    motion_a, motion_b : Motion or None, optional
        The motions of a and b over [0, 1]; None (the default) is at rest. Their batch shapes
        broadcast with the shapes'. A line or ray cannot rotate: only translations move them.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
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
    """
def closest_points(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> ClosestPoints:
    """
    Distance, closest points on a and b, their parameters and whether they are unique.
    
    ``closest_points(b, a)`` is ``closest_points(a, b)`` with the points and parameters exchanged.
    
    Parameters
    ----------
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
    Returns
    -------
    ClosestPoints
        ``distance``, ``point_a``, ``point_b``, ``param_a``, ``param_b`` and ``unique``: scalars and
        single points for two single shapes, arrays of the broadcast batch shape otherwise.
    
    Raises
    ------
    ValueError
        For an unknown precision or solver, batch shapes that do not broadcast, an invalid
        array-like given as a point, (float32) an input beyond float32's range, or a worker count
        that is neither positive nor -1.
    TypeError
        When there is no query between the two kinds (every pair of this module's kinds has one),
        or `progress` is neither None, a bool nor a callable.
    
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
    """
def distance(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> float | numpy.longdouble | numpy.ndarray:
    """
    Distance between a and b.
    
    Does no closest-point work. Both argument orders agree to the bit.
    
    Parameters
    ----------
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
    Returns
    -------
    float or numpy.ndarray
        A float for two single shapes (a ``numpy.longdouble`` in long double); otherwise an array of
        the broadcast batch shape (dtype float64, float32 or longdouble, by precision).
    
    Raises
    ------
    ValueError
        For an unknown precision or solver, batch shapes that do not broadcast, an invalid
        array-like given as a point, (float32) an input beyond float32's range, or a worker count
        that is neither positive nor -1.
    TypeError
        When there is no query between the two kinds (every pair of this module's kinds has one),
        or `progress` is neither None, a bool nor a callable.
    
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
    """
def distance_if_within(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, d: numpy.typing.ArrayLike, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> float | numpy.longdouble | numpy.ndarray:
    """
    ``distance(a, b)`` where ``within(a, b, d)`` holds, inf elsewhere.
    
    The distance is only computed where the bounds cannot show that it exceeds d.
    
    Parameters
    ----------
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    d : array_like
        Finite distance limits >= 0, a scalar or an array broadcasting with the batch shapes of a
        and b.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
    Returns
    -------
    float or numpy.ndarray
        As `distance`, with inf where the distance exceeds d.
    
    Raises
    ------
    ValueError
        For an unknown precision or solver, batch shapes that do not broadcast, an invalid
        array-like given as a point, (float32) an input beyond float32's range, or a worker count
        that is neither positive nor -1.
    TypeError
        When there is no query between the two kinds (every pair of this module's kinds has one),
        or `progress` is neither None, a bool nor a callable.
        Also ValueError when d is negative, NaN, inf or not a real number.
    
    Examples
    --------
    >>> import circledist as cd
    >>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    >>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])
    >>> cd.distance_if_within(line, ring, [0.4, 0.6])
    array([inf, 0.5])
    """
def first_contact(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, motion_a: Motion | None = None, motion_b: Motion | None = None, *, within: numpy.typing.ArrayLike = 0.0, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> Contact:
    """
    The earliest time at which two moving shapes come within a distance of each other.
    
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
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    motion_a, motion_b : Motion or None, optional
        The motions of a and b over [0, 1]; None (the default) is at rest. Their batch shapes
        broadcast with the shapes'. A line or ray cannot rotate (its points reach infinitely far
        from the center, so no speed bound exists): only translations move them.
    within : array_like, optional
        Keyword only. Finite contact distances >= 0, a scalar or an array broadcasting with the
        batch; default 0 (touching).
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
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
    """
def intersects(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> bool | numpy.ndarray:
    """
    Whether a and b touch or overlap (sweeps included): ``within(a, b, 0)``.
    
    Cheap exact bounds decide first; the polynomial solver runs only where they cannot.
    
    Parameters
    ----------
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
    Returns
    -------
    bool or numpy.ndarray
        A bool for two single shapes, a bool array of the broadcast batch shape otherwise.
    
    Raises
    ------
    ValueError
        For an unknown precision or solver, batch shapes that do not broadcast, an invalid
        array-like given as a point, (float32) an input beyond float32's range, or a worker count
        that is neither positive nor -1.
    TypeError
        When there is no query between the two kinds (every pair of this module's kinds has one),
        or `progress` is neither None, a bool nor a callable.
    
    Examples
    --------
    >>> import circledist as cd
    >>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    >>> cd.intersects(ring, cd.Disk([0, 0, 0], [1, 0, 0], 2.0))  # the disk cuts through the ring
    True
    >>> cd.intersects(ring, [[0, 0, 0], [1, 0, 0]])
    array([False,  True])
    """
def nearest(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, k: int = 1, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> tuple[numpy.ndarray, numpy.ndarray]:
    """
    The k shapes of b nearest to each shape of a, with their distances.
    
    The same as sorting every ``distance(a[i], b[j])`` by (distance, j) and keeping the first k,
    with the same distances to the bit; far fewer pairs are evaluated. Like
    ``scipy.spatial.cKDTree.query(x, k)``, for shapes (but indices first, and always two-dimensional).
    
    Parameters
    ----------
    a : Shape or array_like
        The query shapes: a batch of any kind and batch shape, indexed flat (see Notes).
    b : Shape or array_like
        The shapes to search: a batch of any kind, indexed flat.
    k : int, default 1
        How many nearest shapes per query, >= 1.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` about every 0.1 s and once with ``(total, total)`` at the end.
        The work runs in stages (the search for candidate pairs, then their exact distances; twice
        for `nearest`), each counted as ``len(a)`` steps: total is 2 ``len(a)`` for `pairs_within`,
        4 ``len(a)`` for `nearest`, and done never decreases. An exception it raises stops the work
        and propagates.
    
    Returns
    -------
    indices : numpy.ndarray of numpy.intp, shape (len(a), k)
        Flat indices into b, nearest first (ties: the smaller index first). Where b holds fewer than
        k shapes, the missing places are -1 (as in cKDTree, where they are len(b)).
    distances : numpy.ndarray, shape (len(a), k)
        The distances, ascending; inf in the missing places. Dtype float64, float32 or longdouble,
        by precision.
    
    Raises
    ------
    TypeError
        When k or `workers` is not an integer (a bool is not), a or b is not a shape or an array of
        points, there is no query between their kinds, or `progress` is neither None, a bool nor a
        callable.
    ValueError
        When k < 1 or k >= 2**63, for an unknown precision or solver, or a worker count that is
        neither positive nor -1.
    MemoryError
        When the answers, two arrays of shape (len(a), k), do not fit in memory (the columns past
        len(b) are only -1 and inf: a k beyond len(b) costs their memory, nothing more).
    
    See Also
    --------
    pairs_within : every pair within a distance.
    Scene.nearest : the nearest named shapes of a scene to one shape.
    
    Notes
    -----
    Each batch is indexed flat, in C order: element ``i`` of a batch of shape (2, 3) is the one at
    ``numpy.unravel_index(i, (2, 3))``; a single shape is a batch of one. Fields that broadcast
    within a shape (one radius for many centers) count once per element.
    
    A bounding-volume hierarchy (the C++ header ``circledist/broadphase.hpp``) culls the pairs that
    cheap exact lower bounds (boxes, balls, the distance from a line to a ball) put beyond d plus a
    margin of ``sqrt(eps) * (d + 2 * scale)`` (scale: how far the pair's two shapes reach from the
    origin, the farther of them, so that a far or huge shape widens only its own pairs' margins;
    float32's eps for float32 answers): no pair the exact distance puts within d is culled. Lines
    and rays are tested against every ball. Each remaining pair is gathered into a batch and
    answered by the kernel `distance` runs, with the GIL released, on `workers` threads.
    
    Examples
    --------
    >>> import circledist as cd
    >>> rings = cd.Circle([[0, 0, 0], [3, 0, 0], [9, 0, 0]], [0, 0, 1], 1.0)
    >>> probes = cd.Point([[0, 0, 0], [8, 0, 0]])
    >>> idx, dist = cd.nearest(probes, rings, k=2)
    >>> idx
    array([[0, 1],
           [2, 1]])
    >>> dist
    array([[1., 2.],
           [0., 4.]])
    >>> cd.nearest(probes, rings, k=4)[0]  # b holds 3 rings: the fourth place is empty
    array([[ 0,  1,  2, -1],
           [ 2,  1,  0, -1]])
    >>> cd.nearest(probes, rings, k=0)
    Traceback (most recent call last):
    ...
    ValueError: nearest: k must be an integer >= 1, got 0
    """
def pairs_within(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike | None, d: float, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None, max_pairs: int | None = 100000000) -> tuple[numpy.ndarray, numpy.ndarray, numpy.ndarray]:
    """
    Every pair of a and b within distance d of each other, with its distance.
    
    Exactly the pairs ``(i, j)`` for which ``distance(a[i], b[j]) <= d``, as a brute-force double loop
    over `distance` finds them, with the same distances to the bit; far fewer pairs are evaluated.
    Like ``scipy.spatial.cKDTree.query_pairs`` (b None) and ``sparse_distance_matrix`` (with b), for
    shapes.
    
    Parameters
    ----------
    a : Shape or array_like
        A batch of shapes of any kind and batch shape, indexed flat (see Notes). An array of shape
        (..., 3) is a `Point` batch.
    b : Shape, array_like or None
        A second batch, indexed flat; None pairs a with itself, i < j (no pair of an element with
        itself).
    d : float
        Distance limit, finite and >= 0. Pairs at distance exactly d are included.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` about every 0.1 s and once with ``(total, total)`` at the end.
        The work runs in stages (the search for candidate pairs, then their exact distances; twice
        for `nearest`), each counted as ``len(a)`` steps: total is 2 ``len(a)`` for `pairs_within`,
        4 ``len(a)`` for `nearest`, and done never decreases. An exception it raises stops the work
        and propagates.
    max_pairs : int or None, default 100_000_000
        Keyword only. The most candidate pairs (pairs the culling keeps: within d of each other,
        or within the margin of it, by their bounds) the call holds, each about 16 bytes, more
        while they are sorted and answered. The candidates are counted while they are found, and
        once more than max_pairs are, the search stops and MemoryError is raised, instead of
        memory running out on a d that pairs nearly everything. None: no limit.
    
    Returns
    -------
    i, j : numpy.ndarray of numpy.intp, shape (m,)
        Flat indices into a and into b (into a twice when b is None, i < j), sorted by (i, j).
    distance : numpy.ndarray, shape (m,)
        ``distance(a[i], b[j])`` for each pair: dtype float64, float32 or longdouble, by precision.
        With float32 answers the comparison with d is made in double on the float32 value, as a
        loop over single `distance` calls (which return Python floats) makes it.
    
    Raises
    ------
    TypeError
        When d is not a real number, a or b is not a shape or an array of points, there is no
        query between the kinds of a and b (even when no pair is near), or `progress` is neither
        None, a bool nor a callable.
    ValueError
        When d is negative, NaN or inf, for an unknown precision or solver, a worker count that
        is neither positive nor -1, or a negative max_pairs.
    MemoryError
        When more than max_pairs pairs are candidates (raised as soon as the search has counted
        them, before more memory is taken).
    
    See Also
    --------
    nearest : the k nearest shapes of b to each shape of a.
    Scene.pairs_within : the same culling over a scene's named shapes.
    
    Notes
    -----
    Each batch is indexed flat, in C order: element ``i`` of a batch of shape (2, 3) is the one at
    ``numpy.unravel_index(i, (2, 3))``; a single shape is a batch of one. Fields that broadcast
    within a shape (one radius for many centers) count once per element.
    
    A bounding-volume hierarchy (the C++ header ``circledist/broadphase.hpp``) culls the pairs that
    cheap exact lower bounds (boxes, balls, the distance from a line to a ball) put beyond d plus a
    margin of ``sqrt(eps) * (d + 2 * scale)`` (scale: how far the pair's two shapes reach from the
    origin, the farther of them, so that a far or huge shape widens only its own pairs' margins;
    float32's eps for float32 answers): no pair the exact distance puts within d is culled. Lines
    and rays are tested against every ball. Each remaining pair is gathered into a batch and
    answered by the kernel `distance` runs, with the GIL released, on `workers` threads.
    
    Examples
    --------
    >>> import numpy as np
    >>> import circledist as cd
    >>> rings = cd.Circle([[0, 0, 0], [3, 0, 0], [9, 0, 0]], [0, 0, 1], 1.0)
    >>> sticks = cd.Segment([[0, 0, -1], [5, 0, 0]], [[0, 0, 1], [6, 0, 0]])
    >>> i, j, dist = cd.pairs_within(rings, sticks, 1.0)
    >>> i, j, dist
    (array([0, 1]), array([0, 1]), array([1., 1.]))
    >>> cd.pairs_within(rings, None, 1.0)  # rings 0 and 1 are 1 apart
    (array([0]), array([1]), array([1.]))
    >>> cd.pairs_within(rings, sticks, -1)
    Traceback (most recent call last):
    ...
    ValueError: pairs_within: d must be a finite number >= 0, got -1
    """
def reset_stats() -> None:
    """
    Sets every counter of `stats` to 0 (the calling thread's).
    
    Returns
    -------
    None
    
    Examples
    --------
    >>> import circledist as cd
    >>> _ = cd.distance([0, 0, 0], [1, 0, 0])
    >>> cd.reset_stats()
    >>> set(cd.stats().values())
    {0}
    """
def stats() -> dict[str, int]:
    """
    The calling thread's work counters since the last `reset_stats`.
    
    Returns
    -------
    dict of str to int
        ``solves`` (polynomial solves), ``distances`` (exact distance evaluations),
        ``closest_points``, ``within`` (within and intersects pair tests), ``decided_by_bounds``
        (of those, decided by cheap bounds without an exact distance) and ``culled`` (pairs a
        `Scene`'s hierarchy skipped).
    
    Examples
    --------
    >>> import circledist as cd
    >>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    >>> cd.reset_stats()
    >>> cd.intersects(ring, cd.Circle([5, 5, 5], [0, 0, 1], 1.0))  # far apart: the bounds decide
    False
    >>> cd.intersects(ring, cd.Circle([0.5, 0, 0], [0, 1, 1], 1.0))  # close: an octic is solved
    False
    >>> s = cd.stats()
    >>> s["within"], s["decided_by_bounds"], s["distances"], s["solves"]
    (2, 1, 1, 1)
    """
def within(a: Shape | numpy.typing.ArrayLike, b: Shape | numpy.typing.ArrayLike, d: numpy.typing.ArrayLike, *, precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None, solver: typing.Literal['default', 'bracketing', 'companion', 'polished', 'eigen'] | None = None, workers: int = 1, progress: bool | collections.abc.Callable[[int, int], typing.Any] | None = None) -> bool | numpy.ndarray:
    """
    Whether distance(a, b) <= d.
    
    Up to a rounding tolerance of 64 eps times the pair's size. Cheap exact bounds decide first; the polynomial solver runs only where they cannot.
    
    Parameters
    ----------
    a, b : Shape or array_like
        The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
        batch shapes broadcast like NumPy's.
    d : array_like
        Finite distance limits >= 0, a scalar or an array broadcasting with the batch shapes of a
        and b.
    precision : {None, 'float32', 'float64', 'longdouble'}, optional
        Keyword only. The arithmetic of the query. None follows the inputs: long double when any
        field was given as ``numpy.longdouble``, float32 when every one was float32, float64
        otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
        ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
        ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
        are accepted as aliases.)
    solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
        Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
        'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
        companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
        bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
        pairs give the same answer with every solver.
    workers : int, optional
        Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
        convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
        core; default 1. The answers are the same bits for any count, and stats() counts every
        thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
    progress : bool or callable, optional
        Keyword only. None or False (the default): no report. True: a progress bar on stderr
        (tqdm's when it is installed), shown once the work has taken a second. A callable is called
        as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
        batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
        an exception it raises stops the work and propagates.
    
    Returns
    -------
    bool or numpy.ndarray
        A bool when a, b and d are single, otherwise a bool array of their broadcast shape.
    
    Raises
    ------
    ValueError
        For an unknown precision or solver, batch shapes that do not broadcast, an invalid
        array-like given as a point, (float32) an input beyond float32's range, or a worker count
        that is neither positive nor -1.
    TypeError
        When there is no query between the two kinds (every pair of this module's kinds has one),
        or `progress` is neither None, a bool nor a callable.
        Also ValueError when d is negative, NaN, inf or not a real number.
    
    Examples
    --------
    >>> import circledist as cd
    >>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    >>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])  # 0.5 from the ring
    >>> cd.within(line, ring, 0.5)
    True
    >>> cd.within(line, ring, [0.4, 0.6])
    array([False,  True])
    """
__version__: str
_max_control_points: int = 8
