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

import functools
import math
import operator
import re

try:
    import dask
    import dask.array as da
except ImportError as error:  # pragma: no cover - exercised only without dask
    raise ImportError(
        "circledist.dask needs dask: pip install 'circledist[dask]' (dask[array], distributed)"
    ) from error
import numpy as np
from dask.delayed import Delayed
from dask.highlevelgraph import HighLevelGraph

from . import _core
from ._batch import TRAILING_DIMS, index_fields

__all__ = [
    "Annulus",
    "Arc",
    "Bezier",
    "Circle",
    "ClosestPoints",
    "Disk",
    "Line",
    "Point",
    "Ray",
    "Segment",
    "closest_points",
    "distance",
    "pairs_within",
    "within",
]


class _Shape:
    """A batch of one kind whose fields are dask arrays, as the `circledist` class's arguments."""

    _names = ()

    def __init__(self, *args, sweep=None):
        if len(args) != len(self._names):
            raise TypeError(
                f"{type(self).__name__}() takes {len(self._names)} arrays "
                f"({', '.join(self._names)}), got {len(args)}"
            )
        fields = dict(zip(self._names, args))
        if sweep is not None:
            fields["sweep"] = sweep
        self._init(fields)

    def _init(self, fields):
        self.fields = {}
        batches = []
        for name, value in fields.items():
            value = da.asarray(value)
            core = TRAILING_DIMS[name]
            if value.ndim < core or (core and value.shape[-1] != 3):
                raise ValueError(
                    f"{type(self).__name__}: {name} must have shape (..., "
                    f"{'3' if core == 1 else 'k+1, 3' if core == 2 else ''}), "
                    f"got {value.shape}"
                )
            # The per-element dimensions in one chunk: each block then holds whole elements.
            if core:
                value = value.rechunk({axis: -1 for axis in range(value.ndim - core, value.ndim)})
            self.fields[name] = value
            batches.append(value.shape[: value.ndim - core])
        try:
            self.batch_shape = np.broadcast_shapes(*batches)
        except ValueError as error:
            raise ValueError(
                f"{type(self).__name__}: the fields' batch shapes {batches} do not " "broadcast"
            ) from error
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

    def __len__(self):
        """The length of the first batch axis (a single shape has none: TypeError, as len() of
        a 0-d NumPy array)."""
        if not self.batch_shape:
            raise TypeError(f"len() of a single {self.kind} (batch shape ())")
        return self.batch_shape[0]

    def __getitem__(self, key):
        """Basic indexing of the batch axes, as NumPy indexes an array of the batch's shape:
        integers (negative from the end), slices and one Ellipsis, one per batch axis at most.

        Returns a dask shape of the same kind (batch shape () for one integer per axis), lazy:
        every field is broadcast to the batch shape and indexed, its per-element axes kept.
        Fancy indexing (arrays, lists, booleans) and None are refused with a TypeError.

        Examples
        --------
        >>> import numpy as np
        >>> import circledist.dask as cdd
        >>> rings = cdd.Circle(np.zeros((4, 3)), [0, 0, 1], np.arange(1.0, 5.0))
        >>> rings[1:3], len(rings)
        (circledist.dask.Circle(batch_shape=(2,)), 4)
        >>> rings[-1].compute()
        Circle(center=array([0., 0., 0.]), normal=array([0., 0., 1.]), radius=array(4.))
        """
        fields = index_fields(self.fields, self.batch_shape, key, self.kind, da.broadcast_to, fancy=False)
        return type(self).from_arrays(fields)


def _shape_class(name, names):
    signature = f"{name}({', '.join(names)}, *, sweep=None)"
    doc = (
        f"{signature}\n\nA batch of `circledist.{name}` shapes whose fields are dask arrays (NumPy arrays "
        f"and scalars are taken as dask arrays), with the arguments of `circledist.{name}`.\n\n"
        "Indexing (``shape[i]``, ``shape[a:b]``) selects along the batch axes, lazily; ``compute()`` "
        "gives the `circledist` shape."
    )
    return type(name, (_Shape,), {"_names": names, "__doc__": doc, "__module__": __name__})


Point = _shape_class("Point", ("p",))
Line = _shape_class("Line", ("origin", "direction"))
Ray = _shape_class("Ray", ("origin", "direction"))
Segment = _shape_class("Segment", ("p0", "p1"))
Circle = _shape_class("Circle", ("center", "normal", "radius"))
Disk = _shape_class("Disk", ("center", "normal", "radius"))
Bezier = _shape_class("Bezier", ("control_points",))
Arc = _shape_class("Arc", ("center", "normal", "radius", "start", "angle"))
Annulus = _shape_class("Annulus", ("center", "normal", "inner_radius", "outer_radius"))
_CLASSES = {cls.__name__: cls for cls in (Point, Line, Ray, Segment, Circle, Disk, Bezier, Arc, Annulus)}
assert set(_CLASSES) == set(_core._shape_fields()), "a kind without a dask class"


def _as_dask_shape(x):
    """A dask shape from a dask shape, a `circledist` shape (through to_arrays) or points."""
    if isinstance(x, _Shape):
        return x
    if isinstance(x, _core.Shape):
        return _CLASSES[x.kind].from_arrays(x.to_arrays())
    # cd's queries read an array of shape (..., 3) as points: so do these.
    return Point(x)


def _block_shape(kind, fields):
    # copy=False: the blocks are dask's, unchanged while the call runs and dropped after it; a
    # copy of a 2*10^6 point-circle chunk cost 1.0 s against 0.09 s (the query itself: 0.2 s).
    return getattr(_core, kind).from_arrays(fields, copy=False)


# An element's index in circledist's messages: "center[2345]", "normal[1, 0]".
_INDEX = re.compile(r"\b([A-Za-z_]\w*)\[(\d+(?:, \d+)*)\]")


def _renumbered(error, index_of):
    """The error with the first element index it names (within a chunk) made the index within
    the whole batch: index_of(name, local index tuple) -> global index tuple, or None to keep it.
    The same exception type and words as circledist's own message for the whole batch."""
    message = str(error)
    m = _INDEX.search(message)
    if m is None:
        return error
    local = tuple(int(i) for i in m.group(2).split(", "))
    found = index_of(m.group(1), local)
    if found is None:
        return error
    if found == ():  # a single shape: circledist names the field alone
        text = message[: m.start(2) - 1] + message[m.end(2) + 1 :]
    else:
        text = message[: m.start(2)] + ", ".join(str(int(i)) for i in found) + message[m.end(2) :]
    return type(error)(text)


def _checked_block_shape(kind, fields, index_of):
    """_block_shape, its errors naming the element's index within the whole batch."""
    try:
        return _block_shape(kind, fields)
    except (ValueError, TypeError, OverflowError) as error:
        raise _renumbered(error, index_of) from None


# A dummy element per field, to learn the answers' dtypes from circledist itself (its rule: the
# precision keyword, else the fields' dtypes) instead of restating that rule here.
_DUMMY = {
    "p": [1.0, 2.0, 3.0],
    "origin": [0.0, 0.0, 0.0],
    "direction": [1.0, 0.0, 0.0],
    "p0": [0.0, 0.0, 0.0],
    "p1": [1.0, 0.0, 0.0],
    "center": [0.0, 0.0, 0.0],
    "normal": [0.0, 0.0, 1.0],
    "radius": 1.0,
    "start": [1.0, 0.0, 0.0],
    "angle": 1.0,
    "inner_radius": 0.5,
    "outer_radius": 1.0,
    "sweep": 0.0,
}


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
    per-element axes named apart (single chunks, concatenated whole into the block); then, per
    output axis, the indices along it (each block gets its own: where the block starts, for
    messages naming an element of the whole batch)."""
    out = tuple(f"b{k}" for k in range(ndim_out))
    args, layout = [], []
    batch_shape = np.broadcast_shapes(*[s.batch_shape for s in shapes], *[np.shape(x) for x in extra])
    for s, shape in enumerate(shapes):
        for name, value in shape.fields.items():
            core = TRAILING_DIMS[name]
            batch = value.ndim - core
            args += [value, out[ndim_out - batch :] + tuple(f"c{s}{name}{k}" for k in range(core))]
            layout.append((s, name))
    for value in extra:
        args += [value, out[ndim_out - value.ndim :]]
    for k in range(ndim_out):
        args += [da.arange(batch_shape[k], chunks=-1 if batch_shape[k] <= 1 else "auto"), (out[k],)]
    return out, args, layout


def _field_batches(shapes, extra=()):
    """The batch shapes of the whole batch, for the blocks' messages: (shape, field) -> the
    field's; "d" -> within's d; "out" -> the answers'."""
    batches = {
        (s, name): value.shape[: value.ndim - TRAILING_DIMS[name]]
        for s, shape in enumerate(shapes)
        for name, value in shape.fields.items()
    }
    if extra:
        batches["d"] = extra[0].shape
    batches["out"] = np.broadcast_shapes(*[s.batch_shape for s in shapes], *[x.shape for x in extra])
    return batches


def _shifted(whole, local, starts):
    """Index `local` within a block of an array whose whole batch shape is `whole` (its axes the
    output's last ones), as an index within the whole: each axis moved by where the block starts
    on it, a broadcast axis (length 1) left at 0."""
    if len(local) != len(whole):
        return None
    offset = starts[len(starts) - len(whole) :] if whole else []
    return tuple(i + (o if n > 1 else 0) for i, o, n in zip(local, offset, whole))


def _unpack(layout, kinds, blocks, ndim_out, batches):
    """The two shapes of a block (blocks: the fields, the extra arrays, then one array of indices
    per output axis), the block's output shape, the extra arrays, and a function that renumbers
    the call's errors; an error names its element's index within the whole batch."""
    starts = [int(axis[0]) if len(axis) else 0 for axis in blocks[len(blocks) - ndim_out :]]
    blocks = blocks[: len(blocks) - ndim_out]
    fields = [{}, {}]
    for (s, name), block in zip(layout, blocks):
        fields[s][name] = block

    def field_index(s):
        def index_of(name, local):
            # A field's own batch axes (right-aligned with the output's); the shape's otherwise.
            whole = (
                batches[(s, name)]
                if (s, name) in batches
                else np.broadcast_shapes(*[b for key, b in batches.items() if isinstance(key, tuple) and key[0] == s])
            )
            return _shifted(whole, local, starts)

        return index_of

    def answer_index(name, local):
        # within's d by its own shape; the answers (float32's range) by the output's.
        return _shifted(batches.get(name, batches["out"]), local, starts)

    a, b = (_checked_block_shape(kind, f, field_index(s)) for s, (kind, f) in enumerate(zip(kinds, fields)))
    # The block's shape: the fields' batch shapes broadcast, padded on the left to the output's
    # rank (cd returns the rank of its inputs, or a scalar for single shapes).
    extra = blocks[len(layout) :]
    shape = np.broadcast_shapes(a.batch_shape, b.batch_shape, *[x.shape for x in extra])
    return a, b, (1,) * (ndim_out - len(shape)) + shape, extra, answer_index


def _answered(call, index_of, *args, **options):
    """call(*args, **options), its errors naming the element within the whole batch."""
    try:
        return call(*args, **options)
    except (ValueError, TypeError, OverflowError) as error:
        raise _renumbered(error, index_of) from None


def _prepare(a, b, extra=()):
    a, b = _as_dask_shape(a), _as_dask_shape(b)
    extra = [da.asarray(x) for x in extra]
    ndim = len(np.broadcast_shapes(a.batch_shape, b.batch_shape, *[x.shape for x in extra]))
    return a, b, extra, ndim


def _options(precision, solver, workers):
    return {"precision": precision, "solver": solver, "workers": workers}


def _distance_block(*blocks, layout, kinds, ndim, options, batches):
    a, b, shape, _, index_of = _unpack(layout, kinds, blocks, ndim, batches)
    return np.asarray(_answered(_core.distance, index_of, a, b, **options)).reshape(shape)


def distance(a, b, *, precision=None, solver=None, workers=1):
    """`circledist.distance` over dask batches: a dask array of the broadcast batch shape."""
    a, b, _, ndim = _prepare(a, b)
    options = _options(precision, solver, workers)
    dtype = np.asarray(_core.distance(_dummy(a), _dummy(b), **options)).dtype
    out, args, layout = _indices(ndim, (a, b))
    return da.blockwise(
        _distance_block,
        out,
        *args,
        dtype=dtype,
        concatenate=True,
        layout=layout,
        kinds=(a.kind, b.kind),
        ndim=ndim,
        options=options,
        batches=_field_batches((a, b)),
    )


def _within_block(*blocks, layout, kinds, ndim, options, batches):
    a, b, shape, (d,), index_of = _unpack(layout, kinds, blocks, ndim, batches)
    return np.asarray(_answered(_core.within, index_of, a, b, d, **options)).reshape(shape)


def within(a, b, d, *, precision=None, solver=None, workers=1):
    """`circledist.within` over dask batches; d a scalar or an array broadcasting with them."""
    a, b, (d,), ndim = _prepare(a, b, (d,))
    options = _options(precision, solver, workers)
    out, args, layout = _indices(ndim, (a, b), (d,))
    return da.blockwise(
        _within_block,
        out,
        *args,
        dtype=bool,
        concatenate=True,
        layout=layout,
        kinds=(a.kind, b.kind),
        ndim=ndim,
        options=options,
        batches=_field_batches((a, b), (d,)),
    )


_RESULT_FIELDS = (
    ("distance", ()),
    ("point_a", (3,)),
    ("point_b", (3,)),
    ("param_a", (2,)),
    ("param_b", (2,)),
    ("unique", ()),
)


def _closest_block(*blocks, layout, kinds, ndim, options, batches):
    a, b, shape, _, index_of = _unpack(layout, kinds, blocks, ndim, batches)
    r = _answered(_core.closest_points, index_of, a, b, **options)
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
    solved = da.blockwise(
        _closest_block,
        out,
        *args,
        dtype=object,
        meta=np.empty((0,) * ndim, object),
        concatenate=True,
        layout=layout,
        kinds=(a.kind, b.kind),
        ndim=ndim,
        options=options,
        batches=_field_batches((a, b)),
    )
    fields = {}
    for name, trailing in _RESULT_FIELDS:
        dtype = np.asarray(getattr(probe, name)).dtype
        new_axis = list(range(ndim, ndim + len(trailing))) or None
        fields[name] = da.map_blocks(
            operator.itemgetter(name),
            solved,
            dtype=dtype,
            meta=np.empty((0,) * (ndim + len(trailing)), dtype),
            new_axis=new_axis,
            chunks=solved.chunks + tuple((n,) for n in trailing),
            name=f"closest-{name}-" + dask.base.tokenize(solved, name),
        )
    return ClosestPoints(**fields)


# ---- pairs_within: spatial tiles --------------------------------------------------------------


def _flat(shape):
    """The fields broadcast to the batch and flattened: (N, per-element...), one chunking."""
    n = int(np.prod(shape.batch_shape, dtype=np.int64))
    flat = {}
    for name, value in shape.fields.items():
        core = value.shape[value.ndim - TRAILING_DIMS[name] :] if TRAILING_DIMS[name] else ()
        flat[name] = da.broadcast_to(value, shape.batch_shape + core).reshape((n,) + core)
    # The finest chunking any field has along the batch: broadcast fields follow it.
    chunks = max((v.chunks[0] for v in flat.values()), key=len)
    return n, chunks, {name: v.rechunk({0: chunks}) for name, v in flat.items()}


def _balls(kind, fields):
    """Each element's bounding ball (centers (n, 3), radii (n,)), or None for lines and rays."""
    if kind in ("Line", "Ray"):
        return None
    if kind == "Point":
        c, r = fields["p"], np.zeros(len(fields["p"]))
    elif kind == "Segment":
        c = (fields["p0"] + fields["p1"]) / 2
        r = np.linalg.norm(fields["p1"] - fields["p0"], axis=-1) / 2
    elif "center" in fields and "radius" in fields:  # a circle, disk or arc: in its circle's ball
        c, r = fields["center"], fields["radius"]
    elif "outer_radius" in fields:  # an annulus: in its outer disk's ball
        c, r = fields["center"], fields["outer_radius"]
    else:
        # A Bezier curve lies in its control points' convex hull, so in their ball about the mean.
        c = fields["control_points"].mean(axis=1)
        r = np.linalg.norm(fields["control_points"] - c[:, None], axis=-1).max(axis=1)
    c, r = np.asarray(c, np.float64), np.asarray(r, np.float64)
    if "sweep" in fields:
        r = r + fields["sweep"]
    return c, r


def _flat_index(name, local, *, start, batch, fields):
    """The index within the whole batch of element `local` of a flat chunk starting at `start`:
    circledist's index of the field `name` (its own batch shape, broadcast axes at 0) or of the
    shape."""
    if len(local) != 1:
        return None
    whole = tuple(fields.get(name, batch))
    index = np.unravel_index(start + local[0], batch) if batch else ()
    index = index[len(index) - len(whole) :]
    return tuple(int(i) if n > 1 else 0 for i, n in zip(index, whole))


def _check_chunk(kind, fields, index_of):
    """A flat chunk's fields checked as circledist checks a shape's: its errors (NaN, a zero
    direction, a negative radius) name the element within the whole batch, before any tiling
    arithmetic meets the value."""
    _checked_block_shape(kind, fields, index_of)


def _extent(kind, fields, index_of=None):
    """(lowest center, highest center, largest radius, largest |coordinate|) of a chunk."""
    if index_of is not None:
        _check_chunk(kind, fields, index_of)
    balls = _balls(kind, fields)
    if balls is None or len(balls[1]) == 0:
        return None
    c, r = balls
    return c.min(axis=0), c.max(axis=0), r.max(), np.abs(c).max() + r.max()


class _Grid:
    """Cubic tiles of side `side` over the box [lo, hi] of A's ball centers; or, when A is
    unbounded (lines, rays), one tile per A chunk."""

    def __init__(self, lo, hi, side, pad, scale, n_chunks=None):
        self.lo, self.side, self.pad, self.scale = lo, side, pad, scale
        self.chunk_tiles = n_chunks
        if n_chunks is not None:
            self.dims, self.size = None, n_chunks
        else:
            self.dims = np.maximum(1, np.ceil((hi - lo) / side).astype(np.int64))
            self.hi = hi
            self.size = int(np.prod(self.dims))

    def cell(self, x):
        # Monotone in x, so a center between two bounds lands between their cells.
        return np.clip(np.floor((x - self.lo) / self.side), 0, self.dims - 1).astype(np.int64)

    def owners(self, kind, fields, chunk):
        """The tile of each A element: the one holding its ball's center."""
        if self.dims is None:
            return np.full(len(next(iter(fields.values()))), chunk, np.int64)
        i = self.cell(_balls(kind, fields)[0])
        return (i[:, 0] * self.dims[1] + i[:, 1]) * self.dims[2] + i[:, 2]

    def reach(self, kind, fields):
        """(element, tile) for every tile each B element's padded ball can reach."""
        n = len(next(iter(fields.values())))
        balls = _balls(kind, fields)
        if balls is None or self.dims is None:
            # Unbounded B, or A tiled by chunk: every element to every tile.
            e, t = np.meshgrid(np.arange(n), np.arange(self.size), indexing="ij")
            return e.ravel(), t.ravel()
        c, r = balls
        pad = self.pad + r
        # A margin far above the rounding of these bounds and of float32 inputs (their rounding
        # moves a shape by eps32 * scale): a pair within d is never left out of a tile; a wider
        # pad only costs replication, never a duplicate (A elements have one tile each).
        pad = pad + 4e-4 * (pad + self.scale + np.abs(c).max(axis=1))
        low, high = c - pad[:, None], c + pad[:, None]
        keep = np.all((high >= self.lo) & (low <= self.hi), axis=1)
        e = np.nonzero(keep)[0]
        lo_i, hi_i = self.cell(low[e]), self.cell(high[e])
        counts = np.prod(hi_i - lo_i + 1, axis=1)
        owner = np.repeat(e, counts)
        # Each element's box of cells, enumerated by one running index per element.
        k = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
        span = (hi_i - lo_i + 1)[np.repeat(np.arange(len(e)), counts)]
        base = lo_i[np.repeat(np.arange(len(e)), counts)]
        iz = base[:, 2] + k % span[:, 2]
        iy = base[:, 1] + (k // span[:, 2]) % span[:, 1]
        ix = base[:, 0] + k // (span[:, 2] * span[:, 1])
        return owner, (ix * self.dims[1] + iy) * self.dims[2] + iz


def _count_a(fields, *, kind, grid, chunk):
    return np.bincount(grid.owners(kind, fields, chunk), minlength=grid.size)


def _count_b(fields, *, kind, grid, index_of=None):
    if index_of is not None:
        _check_chunk(kind, fields, index_of)
    return np.bincount(grid.reach(kind, fields)[1], minlength=grid.size)


def _split(fields, *, kind, grid, chunk, offset, is_a):
    """{tile: (global indices, fields)} of a chunk's elements, B's replicated."""
    if is_a:
        tiles = grid.owners(kind, fields, chunk)
        element = np.arange(len(tiles))
    else:
        element, tiles = grid.reach(kind, fields)
    order = np.argsort(tiles, kind="stable")
    element, tiles = element[order], tiles[order]
    starts = np.flatnonzero(np.r_[True, tiles[1:] != tiles[:-1]]) if len(tiles) else []
    parts = {}
    for s, e in zip(starts, list(starts[1:]) + [len(tiles)]):
        take = element[s:e]
        parts[int(tiles[s])] = (offset + take, {n: v[take] for n, v in fields.items()})
    return parts


def _join(parts):
    idx = np.concatenate([p[0] for p in parts])
    return idx, {n: np.concatenate([p[1][n] for p in parts]) for n in parts[0][1]}


def _tile_pairs(a_parts, b_parts, *, kinds, d, self_pairs, a_bounds, options):
    """cd.pairs_within in one tile, indices made global, split by A's output chunk."""
    ia, fa = _join(a_parts)
    ib, fb = _join(b_parts)
    i, j, dist = _core.pairs_within(_block_shape(kinds[0], fa), _block_shape(kinds[1], fb), d, **options)
    i, j = ia[i], ib[j]
    if self_pairs:  # b is a: each unordered pair once, as cd.pairs_within(a, None) gives it
        keep = i < j
        i, j, dist = i[keep], j[keep], dist[keep]
    out = {}
    for c, (start, stop) in a_bounds.items():
        mine = (i >= start) & (i < stop)
        out[c] = (i[mine], j[mine], dist[mine])
    return out


def _merge(parts, *, dtype):
    if not parts:
        return np.empty(0, np.intp), np.empty(0, np.intp), np.empty(0, dtype)
    i, j, dist = (np.concatenate(x) for x in zip(*parts))
    order = np.lexsort((j, i))
    return i[order].astype(np.intp), j[order].astype(np.intp), dist[order]


def _fields_of(names, *blocks):
    return dict(zip(names, blocks))


class _Graph:
    """A task graph written directly: nested dask.delayed calls re-walk the whole graph at each
    call, which took seconds for a few thousand tasks; this builds it once."""

    def __init__(self, name, dependencies):
        self.name, self.dependencies, self.tasks = name, list(dependencies), {}

    def add(self, key, function, *args):
        key = (self.name,) + key
        self.tasks[key] = (function,) + args
        return key

    def graph(self):
        return HighLevelGraph.from_collections(self.name, dict(self.tasks), dependencies=self.dependencies)

    def compute(self, keys):
        graph = self.graph()
        return dask.compute([Delayed(k, graph, layer=self.name) for k in keys])[0]


def _chunk_fields(g, label, flat):
    """Per chunk: the key of a task giving that chunk's fields as a dict."""
    names = list(flat)
    keys = [list(dask.core.flatten(v.__dask_keys__())) for v in flat.values()]
    return [g.add((label, c), functools.partial(_fields_of, names), *[k[c] for k in keys]) for c in range(len(keys[0]))]


def pairs_within(a, b, d, *, tiles=None, precision=None, solver=None, workers=1):
    """`circledist.pairs_within` over batches too large for one machine, partitioned in space.

    Each shape of a belongs to the tile (a cube of space) holding its bounding ball's center;
    each shape of b is copied into every tile its ball, padded by d plus the largest ball of a,
    reaches (lines and rays: every tile). Each tile is answered by `circledist.pairs_within`, so
    every pair within d is found exactly once, with cd's distances to the bit. When a holds lines
    or rays, its chunks are the tiles and every b goes to every tile.

    Parameters
    ----------
    a, b : dask shape, circledist shape or array of points
        Indexed flat, in C order, as `circledist.pairs_within`; b None pairs a with itself (i < j).
    d : float
        Distance limit, finite and >= 0.
    tiles : int, optional
        About how many tiles to cut a's box into (default: 4 per chunk of a; at most one per
        element of a). More tiles mean smaller tasks and more copies of b.
    precision, solver, workers
        As `circledist.pairs_within`, for each tile.

    Returns
    -------
    i, j, distance : dask arrays of unknown chunk sizes, one chunk per chunk of a
        Sorted by (i, j); ``dask.compute(i, j, distance)`` gives cd.pairs_within's columns.
        The tiles' sizes are counted (computed) when this is called; the pairs, when the
        results are computed.
    """
    if tiles is not None:
        tiles = _core._integer_argument("pairs_within", "tiles", tiles, "an integer >= 1")
        if tiles < 1:
            raise ValueError(f"pairs_within: tiles must be an integer >= 1, got {tiles}")
    self_pairs = b is None
    a = _as_dask_shape(a)
    b = a if self_pairs else _as_dask_shape(b)
    options = _options(precision, solver, workers)
    kinds = (a.kind, b.kind)
    # circledist's own checks of d (its type and value: the same errors, word for word) and of
    # the kinds (a TypeError for kinds without a query); it gives the distances' dtype.
    dtype = _core.pairs_within(_dummy(a), _dummy(b), d, **options)[2].dtype
    d = float(d)
    na, chunks_a, flat_a = _flat(a)
    nb, chunks_b, flat_b = _flat(b)
    token = dask.base.tokenize(a.fields, b.fields, d, tiles, options, self_pairs)
    g = _Graph(f"pairs-within-{token}", list(flat_a.values()) + list(flat_b.values()))
    blocks_a, blocks_b = _chunk_fields(g, "a", flat_a), _chunk_fields(g, "b", flat_b)
    starts_a = np.r_[0, np.cumsum(chunks_a)].astype(np.int64)
    starts_b = np.r_[0, np.cumsum(chunks_b)].astype(np.int64)
    merged = []
    if na and nb:

        def index_of(shape, starts, c):
            return functools.partial(
                _flat_index,
                start=int(starts[c]),
                batch=tuple(shape.batch_shape),
                fields={n: v.shape[: v.ndim - TRAILING_DIMS[n]] for n, v in shape.fields.items()},
            )

        extents = g.compute(
            [
                g.add(("extent", c), functools.partial(_extent, a.kind, index_of=index_of(a, starts_a, c)), f)
                for c, f in enumerate(blocks_a)
            ]
        )
        extents = [x for x in extents if x is not None]
        if extents:
            lo = np.min([x[0] for x in extents], axis=0)
            hi = np.max([x[1] for x in extents], axis=0)
            pad = d + max(x[2] for x in extents)
            scale = max(x[3] for x in extents)
            # At most a tile per element of a: more would be empty, and the grid's per-tile
            # arrays would grow with the count asked for (tiles=2**62 asked for gigabytes).
            per_axis = math.ceil(min(tiles or 4 * len(chunks_a), max(1, na)) ** (1 / 3))
            # No thinner than the padding: thinner tiles would only copy each b more often.
            side = max(float(np.max(hi - lo)) / per_axis, pad, 1e-300)
            grid = _Grid(lo, hi, side, pad, scale)
        else:
            grid = _Grid(None, None, None, d, 0.0, n_chunks=len(chunks_a))
        # The tiles' sizes first, so that the graph below holds only non-empty parts.
        counts = g.compute(
            [
                g.add(("count-a", c), functools.partial(_count_a, kind=a.kind, grid=grid, chunk=c), f)
                for c, f in enumerate(blocks_a)
            ]
            + [
                g.add(
                    ("count-b", c),
                    functools.partial(
                        _count_b, kind=b.kind, grid=grid, index_of=None if self_pairs else index_of(b, starts_b, c)
                    ),
                    f,
                )
                for c, f in enumerate(blocks_b)
            ]
        )
        count_a, count_b = np.array(counts[: len(blocks_a)]), np.array(counts[len(blocks_a) :])
        split_a = [
            g.add(
                ("split-a", c),
                functools.partial(_split, kind=a.kind, grid=grid, chunk=c, offset=starts_a[c], is_a=True),
                f,
            )
            for c, f in enumerate(blocks_a)
        ]
        split_b = [
            g.add(
                ("split-b", c),
                functools.partial(_split, kind=b.kind, grid=grid, chunk=c, offset=starts_b[c], is_a=False),
                f,
            )
            for c, f in enumerate(blocks_b)
        ]
        per_chunk = {c: [] for c in range(len(chunks_a))}
        for t in np.flatnonzero(count_a.sum(axis=0) * count_b.sum(axis=0)):
            t = int(t)
            ca, cb = np.flatnonzero(count_a[:, t]), np.flatnonzero(count_b[:, t])
            answered = g.add(
                ("tile", t),
                functools.partial(
                    _tile_pairs,
                    kinds=kinds,
                    d=d,
                    self_pairs=self_pairs,
                    options=options,
                    a_bounds={int(c): (int(starts_a[c]), int(starts_a[c + 1])) for c in ca},
                ),
                [g.add(("part-a", int(c), t), operator.getitem, split_a[c], t) for c in ca],
                [g.add(("part-b", int(c), t), operator.getitem, split_b[c], t) for c in cb],
            )
            for c in ca:
                per_chunk[c].append(g.add(("answer", int(c), t), operator.getitem, answered, int(c)))
        merged = [
            g.add(("merged", c), functools.partial(_merge, dtype=dtype), per_chunk[c]) for c in range(len(chunks_a))
        ]
    else:
        merged = [g.add(("merged", 0), functools.partial(_merge, dtype=dtype), [])]
    columns = []
    # The columns' layers name the pairs' layer as a dependency: a task's arguments are read as
    # keys only when their layer depends on the layer holding them.
    solved = Delayed(merged[0], g.graph(), layer=g.name)
    for k, (label, column_dtype) in enumerate((("i", np.intp), ("j", np.intp), ("distance", dtype))):
        column = _Graph(f"pairs-within-{label}-{token}", [solved])
        for c, m in enumerate(merged):
            column.add((c,), operator.getitem, m, k)
        columns.append(da.Array(column.graph(), column.name, chunks=((np.nan,) * len(merged),), dtype=column_dtype))
    return tuple(columns)
