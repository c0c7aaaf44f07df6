"""circledist on Dask: the shapes and queries of `circledist` over dask arrays, answered chunk by
chunk, on one machine's threads or on a `distributed` cluster.

    import circledist.dask as cdd
    rings = cdd.Circle(centers, normals, radii)          # dask or NumPy arrays, cd's signature
    d = cdd.distance(points, rings)                      # a dask array, one task per chunk
    i, j, dist = cdd.pairs_within(rings, cables, 0.05)   # spatially partitioned, sorted by (i, j)

Every chunk is answered by the single-process `circledist` call on that chunk, and each element
is answered alone there, so the results are those of `circledist` on the whole batch, to the bit.
Needs the `circledist[dask]` extra (dask[array]; distributed for clusters).
"""

import math
import operator

try:
    import dask
    import dask.array as da
except ImportError as error:  # pragma: no cover - exercised only without dask
    raise ImportError(
        "circledist.dask needs dask: pip install 'circledist[dask]' (dask[array], distributed)"
    ) from error
import numpy as np

from . import _core

__all__ = ["Bezier", "Circle", "ClosestPoints", "Disk", "Line", "Point", "Ray", "Segment",
           "closest_points", "distance", "pairs_within", "within"]

# The per-element (trailing) dimensions of each constructor argument; the leading ones are batch.
_CORE_NDIM = {"p": 1, "origin": 1, "direction": 1, "p0": 1, "p1": 1, "center": 1, "normal": 1,
              "radius": 0, "control_points": 2, "sweep": 0}


class _Shape:
    """A batch of one kind whose fields are dask arrays, as the `circledist` class's arguments."""

    _names = ()

    def __init__(self, *args, sweep=None):
        if len(args) != len(self._names):
            raise TypeError(f"{type(self).__name__}() takes {len(self._names)} arrays "
                            f"({', '.join(self._names)}), got {len(args)}")
        fields = dict(zip(self._names, args))
        if sweep is not None:
            fields["sweep"] = sweep
        self._init(fields)

    def _init(self, fields):
        self.fields = {}
        batches = []
        for name, value in fields.items():
            value = da.asarray(value)
            core = _CORE_NDIM[name]
            if value.ndim < core or (core and value.shape[-1] != 3):
                raise ValueError(f"{type(self).__name__}: {name} must have shape (..., "
                                 f"{'3' if core == 1 else 'k+1, 3' if core == 2 else ''}), "
                                 f"got {value.shape}")
            # The per-element dimensions in one chunk: each block then holds whole elements.
            if core:
                value = value.rechunk({axis: -1 for axis in range(value.ndim - core, value.ndim)})
            self.fields[name] = value
            batches.append(value.shape[:value.ndim - core])
        try:
            self.batch_shape = np.broadcast_shapes(*batches)
        except ValueError as error:
            raise ValueError(f"{type(self).__name__}: the fields' batch shapes {batches} do not "
                             "broadcast") from error
        for name, value in self.fields.items():
            setattr(self, name, value)

    kind = property(lambda self: type(self).__name__)

    def to_arrays(self):
        """The fields by constructor-argument name (dask arrays)."""
        return dict(self.fields)

    @classmethod
    def from_arrays(cls, arrays):
        """The shape from a dict of arrays by argument name (as `to_arrays` or cd's to_arrays)."""
        shape = cls.__new__(cls)
        shape._init(dict(arrays))
        return shape

    def compute(self, **kwargs):
        """The `circledist` shape of the computed fields."""
        arrays = dask.compute(self.fields, **kwargs)[0]
        return getattr(_core, self.kind).from_arrays(arrays)

    def __repr__(self):
        return f"circledist.dask.{self.kind}(batch_shape={self.batch_shape})"


def _shape_class(name, names, doc):
    return type(name, (_Shape,), {"_names": names, "__doc__": doc, "__module__": __name__})


Point = _shape_class("Point", ("p",), "Point(p, *, sweep=None): points as dask arrays.")
Line = _shape_class("Line", ("origin", "direction"), "Line(origin, direction, *, sweep=None).")
Ray = _shape_class("Ray", ("origin", "direction"), "Ray(origin, direction, *, sweep=None).")
Segment = _shape_class("Segment", ("p0", "p1"), "Segment(p0, p1, *, sweep=None).")
Circle = _shape_class("Circle", ("center", "normal", "radius"),
                      "Circle(center, normal, radius, *, sweep=None).")
Disk = _shape_class("Disk", ("center", "normal", "radius"), "Disk(center, normal, radius, *, sweep=None).")
Bezier = _shape_class("Bezier", ("control_points",), "Bezier(control_points, *, sweep=None).")
_CLASSES = {cls.__name__: cls for cls in (Point, Line, Ray, Segment, Circle, Disk, Bezier)}


def _as_dask_shape(x):
    """A dask shape from a dask shape, a `circledist` shape (through to_arrays) or points."""
    if isinstance(x, _Shape):
        return x
    if isinstance(x, _core.Shape):
        return _CLASSES[x.kind].from_arrays(x.to_arrays())
    # cd's queries read an array of shape (..., 3) as points: so do these.
    return Point(x)


def _block_shape(kind, fields):
    return getattr(_core, kind).from_arrays(fields)


# A dummy element per field, to learn the answers' dtypes from circledist itself (its rule: the
# precision keyword, else the fields' dtypes) instead of restating that rule here.
_DUMMY = {"p": [1.0, 2.0, 3.0], "origin": [0.0, 0.0, 0.0], "direction": [1.0, 0.0, 0.0],
          "p0": [0.0, 0.0, 0.0], "p1": [1.0, 0.0, 0.0], "center": [0.0, 0.0, 0.0],
          "normal": [0.0, 0.0, 1.0], "radius": 1.0, "sweep": 0.0}


def _dummy(shape):
    fields = {}
    for name, value in shape.fields.items():
        if name == "control_points":
            k = value.shape[-2]
            base = np.stack([np.arange(k), np.arange(k) ** 2, np.zeros(k)], axis=-1)
        else:
            base = np.array(_DUMMY[name])
        fields[name] = base.astype(value.dtype)[None]
    return _block_shape(shape.kind, fields)


def _indices(ndim_out, shapes, extra=()):
    """blockwise's arguments: each field's batch axes right-aligned with the output's, its
    per-element axes named apart (single chunks, concatenated whole into the block)."""
    out = tuple(f"b{k}" for k in range(ndim_out))
    args, layout = [], []
    for s, shape in enumerate(shapes):
        for name, value in shape.fields.items():
            core = _CORE_NDIM[name]
            batch = value.ndim - core
            args += [value, out[ndim_out - batch:] + tuple(f"c{s}{name}{k}" for k in range(core))]
            layout.append((s, name))
    for value in extra:
        args += [value, out[ndim_out - value.ndim:]]
    return out, args, layout


def _unpack(layout, kinds, blocks, ndim_out):
    fields = [{}, {}]
    for (s, name), block in zip(layout, blocks):
        fields[s][name] = block
    a, b = (_block_shape(kind, f) for kind, f in zip(kinds, fields))
    # The block's shape: the fields' batch shapes broadcast, padded on the left to the output's
    # rank (cd returns the rank of its inputs, or a scalar for single shapes).
    shape = np.broadcast_shapes(a.batch_shape, b.batch_shape, *[x.shape for x in blocks[len(layout):]])
    return a, b, (1,) * (ndim_out - len(shape)) + shape


def _prepare(a, b, extra=()):
    a, b = _as_dask_shape(a), _as_dask_shape(b)
    extra = [da.asarray(x) for x in extra]
    ndim = len(np.broadcast_shapes(a.batch_shape, b.batch_shape, *[x.shape for x in extra]))
    return a, b, extra, ndim


def _options(precision, solver, workers):
    return {"precision": precision, "solver": solver, "workers": workers}


def _distance_block(*blocks, layout, kinds, ndim, options):
    a, b, shape = _unpack(layout, kinds, blocks, ndim)
    return np.asarray(_core.distance(a, b, **options)).reshape(shape)


def distance(a, b, *, precision=None, solver=None, workers=1):
    """`circledist.distance` over dask batches: a dask array of the broadcast batch shape."""
    a, b, _, ndim = _prepare(a, b)
    options = _options(precision, solver, workers)
    dtype = np.asarray(_core.distance(_dummy(a), _dummy(b), **options)).dtype
    out, args, layout = _indices(ndim, (a, b))
    return da.blockwise(_distance_block, out, *args, dtype=dtype, concatenate=True,
                        layout=layout, kinds=(a.kind, b.kind), ndim=ndim, options=options)


def _within_block(*blocks, layout, kinds, ndim, options):
    a, b, shape = _unpack(layout, kinds, blocks, ndim)
    return np.asarray(_core.within(a, b, blocks[-1], **options)).reshape(shape)


def within(a, b, d, *, precision=None, solver=None, workers=1):
    """`circledist.within` over dask batches; d a scalar or an array broadcasting with them."""
    a, b, (d,), ndim = _prepare(a, b, (d,))
    options = _options(precision, solver, workers)
    out, args, layout = _indices(ndim, (a, b), (d,))
    return da.blockwise(_within_block, out, *args, dtype=bool, concatenate=True,
                        layout=layout, kinds=(a.kind, b.kind), ndim=ndim, options=options)


_RESULT_FIELDS = (("distance", ()), ("point_a", (3,)), ("point_b", (3,)), ("param_a", (2,)),
                  ("param_b", (2,)), ("unique", ()))


def _closest_block(*blocks, layout, kinds, ndim, options):
    a, b, shape = _unpack(layout, kinds, blocks, ndim)
    r = _core.closest_points(a, b, **options)
    # A dict of arrays (it pickles and has a size for the scheduler), read by the getters below.
    return {name: np.asarray(getattr(r, name)).reshape(shape + trailing) for name, trailing in _RESULT_FIELDS}


class ClosestPoints:
    """`circledist.closest_points`'s attributes as dask arrays, all read from one shared solve:
    ``dask.compute(r.distance, r.point_a)`` solves each chunk once."""

    def __init__(self, **fields):
        for name, value in fields.items():
            setattr(self, name, value)

    def compute(self, **kwargs):
        """The attributes computed together, as a dict of NumPy arrays."""
        names = [name for name, _ in _RESULT_FIELDS]
        return dict(zip(names, dask.compute(*[getattr(self, n) for n in names], **kwargs)))

    def __repr__(self):
        return f"circledist.dask.ClosestPoints(shape={self.distance.shape})"


def closest_points(a, b, *, precision=None, solver=None, workers=1):
    """`circledist.closest_points` over dask batches: a `ClosestPoints` of dask arrays."""
    a, b, _, ndim = _prepare(a, b)
    options = _options(precision, solver, workers)
    probe = _core.closest_points(_dummy(a), _dummy(b), **options)
    out, args, layout = _indices(ndim, (a, b))
    solved = da.blockwise(_closest_block, out, *args, dtype=object, meta=np.empty((0,) * ndim, object),
                          concatenate=True, layout=layout, kinds=(a.kind, b.kind), ndim=ndim,
                          options=options)
    fields = {}
    for name, trailing in _RESULT_FIELDS:
        dtype = np.asarray(getattr(probe, name)).dtype
        new_axis = list(range(ndim, ndim + len(trailing))) or None
        fields[name] = da.map_blocks(operator.itemgetter(name), solved, dtype=dtype,
                                     meta=np.empty((0,) * (ndim + len(trailing)), dtype),
                                     new_axis=new_axis, chunks=solved.chunks + tuple((n,) for n in trailing),
                                     name=f"closest-{name}-" + dask.base.tokenize(solved, name))
    return ClosestPoints(**fields)
