"""A scene: named shapes of any kinds, and the few questions a user asks of it.

``Scene.nearest``, ``Scene.within`` and ``Scene.pairs_within`` cull with a bounding-volume
hierarchy before any exact test: a linear BVH (shapes sorted along a Morton curve, leaves of
``LEAF`` shapes, every node the box of ``BRANCH`` consecutive children), built and traversed
level by level with NumPy. A node or a shape is skipped only when a lower bound on its
distance (box gap, ball gap, distance from a line to a ball) exceeds the limit by a margin
far above rounding, so every answer is the one brute force gives: the exact tests that
remain go through ``circledist.within`` / ``circledist.distance_if_within``, which try
cheap exact bounds again before they solve a polynomial.

Lines and rays are unbounded: they are kept out of the hierarchy and always tested (with
the bounds of ``circledist.within``).
"""

from __future__ import annotations

from typing import Iterable, Sequence

import functools
import numbers

import numpy as np

from . import _core

__all__ = ["Scene"]

# The constructor arguments of each kind, in order (the sweep comes on top as a keyword), from
# the module's one table of fields (src/shapes.hpp).
KIND_FIELDS = {kind: tuple(name for name, _ in fields) for kind, fields in _core._shape_fields().items()}
# Trailing dimensions of a field per element (the rest is batch).
_TRAILING = {"p": 1, "origin": 1, "direction": 1, "p0": 1, "p1": 1, "center": 1, "normal": 1,
             "radius": 0, "control_points": 2, "sweep": 0}
UNBOUNDED = ("Line", "Ray")

LEAF = 8     # shapes per leaf
BRANCH = 4   # children per node
BEAM = 16    # nodes per level kept by the descent that seeds a nearest query
RELATIVE_MARGIN = 1e-9  # culling margin, relative to the scene's and the query's size


class _Group:
    """Shapes of one kind (and, for Bezier curves, one control point count), column-stored."""

    def __init__(self, kind: str):
        self.kind = kind
        self.cls = getattr(_core, kind)
        self.names = KIND_FIELDS[kind] + ("sweep",)
        self.chunks: list[list[np.ndarray]] = []
        self.id_chunks: list[np.ndarray] = []
        self.fields: list[np.ndarray] | None = None
        self.ids: np.ndarray | None = None

    def append(self, arrays: list[np.ndarray], ids: np.ndarray) -> None:
        self.chunks.append(arrays)
        self.id_chunks.append(ids)
        self.fields = None

    def finish(self) -> None:
        if self.fields is None:
            self.fields = [np.concatenate([c[i] for c in self.chunks]) for i in range(len(self.names))]
            self.ids = np.concatenate(self.id_chunks)
            self.chunks = [self.fields]
            self.id_chunks = [self.ids]

    def batch(self, rows, column: bool = False):
        """The shapes at local rows as one batched shape; column=True gives batch shape (n, 1)."""
        arrays = [f[rows] for f in self.fields]
        if column:
            arrays = [a[:, None] for a in arrays]
        return self.cls(*arrays[:-1], sweep=arrays[-1])

    def single(self, row: int):
        arrays = [f[row] for f in self.fields]
        return self.cls(*arrays[:-1], sweep=arrays[-1])


def _fields_of(shape) -> tuple[str, list[np.ndarray], tuple[int, ...]]:
    kind = shape.kind
    arrays = [np.array(getattr(shape, name), dtype=np.float64) for name in KIND_FIELDS[kind] + ("sweep",)]
    batch = tuple(shape.batch_shape)
    full = []
    for name, a in zip(KIND_FIELDS[kind] + ("sweep",), arrays):
        trailing = a.shape[a.ndim - _TRAILING[name]:] if _TRAILING[name] else ()
        full.append(np.broadcast_to(a, batch + trailing).reshape((-1,) + trailing))
    return kind, full, batch


def _group_key(kind: str, arrays: list[np.ndarray]):
    return (kind, arrays[0].shape[1]) if kind == "Bezier" else (kind, 0)


# ------------------------------------------------------------------------------------------
# bounding volumes (vectorized): boxes [lo, hi] and balls (center, radius), sweeps included
# ------------------------------------------------------------------------------------------
def _overflow_handled():
    """Overflow and inf - inf are handled where they matter (_norm, _conservative): no warnings."""
    return np.errstate(over="ignore", invalid="ignore")


def _quiet(fn):
    @functools.wraps(fn)
    def quiet(*args, **kwargs):
        with _overflow_handled():
            return fn(*args, **kwargs)
    return quiet


def _norm(v: np.ndarray, axis: int = -1) -> np.ndarray:
    """Euclidean norms along `axis` that overflow only where the norm itself does (a vector of
    1e200 has norm 1e200, not inf, as with hypot): scaled by the largest component."""
    scale = np.abs(v).max(axis=axis, keepdims=True)
    with _overflow_handled():
        unit = np.where((scale > 0) & np.isfinite(scale), v / np.where(scale > 0, scale, 1.0), 0.0)
        out = np.squeeze(scale, axis=axis) * np.sqrt((unit * unit).sum(axis=axis))
    return np.where(np.isfinite(np.squeeze(scale, axis=axis)), out, np.inf)


def _limit(owner: str, d) -> float:
    """A distance limit: a real number >= 0 (strings, None and NaN are errors)."""
    if isinstance(d, (str, bytes, bool, np.bool_)) or not isinstance(d, numbers.Real):
        raise TypeError(f"{owner}: d must be a real number >= 0, got {d!r}")
    d = float(d)
    if not d >= 0:
        raise ValueError(f"{owner}: d must be a number >= 0, got {d}")
    return d


def _conservative(bound: np.ndarray) -> np.ndarray:
    """Lower bounds that rounding past overflow made NaN (inf - inf) are no bound at all: -inf,
    so culling never drops a shape for it."""
    return np.where(np.isnan(bound), -np.inf, bound)


@_quiet
def _volumes(kind: str, f: list[np.ndarray]):
    sweep = f[-1]
    if kind == "Point":
        p = f[0]
        lo, hi, center, radius = p, p, p, np.zeros(len(p))
    elif kind == "Segment":
        p0, p1 = f[0], f[1]
        lo, hi = np.minimum(p0, p1), np.maximum(p0, p1)
        center, radius = p0 / 2 + p1 / 2, _norm(p1 / 2 - p0 / 2, axis=1)
    elif kind in ("Circle", "Disk"):
        c, n, r = f[0], f[1], f[2]
        nn = n / np.abs(n).max(axis=1, keepdims=True)
        nn = nn / _norm(nn, axis=1)[:, None]
        ext = r[:, None] * np.sqrt(np.maximum(0.0, 1.0 - nn * nn))
        lo, hi, center, radius = c - ext, c + ext, c, r.copy()
    elif kind == "Bezier":
        cp = f[0]
        lo, hi = cp.min(axis=1), cp.max(axis=1)
        center = lo / 2 + hi / 2
        radius = _norm(cp - center[:, None, :], axis=2).max(axis=1)
    else:
        raise AssertionError(kind)
    # Rounding of the above is far below this pad (and the culling margin is larger still).
    size = np.abs(center).max(axis=1) + radius + sweep
    pad = 1e-12 * size
    grow = sweep + pad
    return lo - grow[:, None], hi + grow[:, None], center, radius + grow


@_quiet
def _box_gap(lo, hi, qlo, qhi):
    gap = np.maximum(0.0, np.maximum(lo - qhi, qlo - hi))
    return _norm(gap)


@_quiet
def _point_line_distance(points, origin, direction, ray: bool):
    unit = direction / np.abs(direction).max()
    unit = unit / _norm(unit)
    w = points - origin
    t = w @ unit
    if ray:
        t = np.maximum(t, 0.0)
    return _norm(w - t[..., None] * unit)


@_quiet
def _morton(points: np.ndarray) -> np.ndarray:
    lo, hi = points.min(axis=0), points.max(axis=0)
    span = np.where(hi > lo, hi - lo, 1.0)
    q = np.clip(((points - lo) / span * 1023.0).astype(np.int64), 0, 1023).astype(np.uint64)

    def spread(v):
        v = (v | (v << np.uint64(16))) & np.uint64(0x030000FF)
        v = (v | (v << np.uint64(8))) & np.uint64(0x0300F00F)
        v = (v | (v << np.uint64(4))) & np.uint64(0x030C30C3)
        v = (v | (v << np.uint64(2))) & np.uint64(0x09249249)
        return v

    return (spread(q[:, 0]) << np.uint64(2)) | (spread(q[:, 1]) << np.uint64(1)) | spread(q[:, 2])


class _Query:
    """The bounds side of a query shape: its box and ball, or its line for lines and rays."""

    def __init__(self, shape):
        if shape.batch_shape != ():
            raise ValueError(f"Scene queries take a single shape, got a batch of shape {shape.batch_shape}")
        self.shape = shape
        self.kind = shape.kind
        kind, f, _ = _fields_of(shape)
        self.sweep = float(f[-1][0])
        self.unbounded = kind in UNBOUNDED
        if self.unbounded:
            self.origin, self.direction = f[0][0], f[1][0]
            self.ray = kind == "Ray"
            self.size = float(np.abs(self.origin).max())
        else:
            lo, hi, c, r = _volumes(kind, f)
            self.lo, self.hi, self.center, self.radius = lo[0], hi[0], c[0], float(r[0])
            self.size = float(np.abs(self.center).max() + self.radius)

    @_quiet
    def node_bound(self, lo, hi):
        """Lower bounds on the distance to anything inside the boxes [lo, hi]."""
        center = lo / 2 + hi / 2
        half = _norm(hi / 2 - lo / 2)
        if self.unbounded:
            return _conservative(_point_line_distance(center, self.origin, self.direction, self.ray) - half - self.sweep)
        gap = _box_gap(lo, hi, self.lo, self.hi)
        return _conservative(np.maximum(gap, _norm(center - self.center) - half - self.radius))

    @_quiet
    def item_bound(self, lo, hi, center, radius):
        """Lower bounds on the distance to shapes with these boxes and balls (inf radius: unbounded)."""
        bounded = np.isfinite(radius)
        out = np.zeros(len(radius))
        if self.unbounded:
            out[bounded] = (_point_line_distance(center[bounded], self.origin, self.direction, self.ray)
                            - radius[bounded] - self.sweep)
            return _conservative(out)
        out[bounded] = np.maximum(
            _box_gap(lo[bounded], hi[bounded], self.lo, self.hi),
            _norm(center[bounded] - self.center) - radius[bounded] - self.radius)
        # A bounded query against a line or ray of the scene: the line's distance to the query's ball.
        return _conservative(out)


class Scene:
    """Named shapes of any kinds (each a single shape) and culled queries over them.

    A bounding-volume hierarchy skips the shapes a query cannot reach; every answer is the one
    brute force over `circledist.within` and `circledist.distance` gives.

    Parameters
    ----------
    shapes : mapping or iterable of (str, Shape) pairs, optional
        Initial shapes by name, added in order with `add`.

    Attributes
    ----------
    names : list of str
        The shapes' names, in insertion order.
    last_stats : dict
        Of the last query: ``shapes`` (in the scene), ``tested`` (exact tests run) and
        ``culled`` (shapes the hierarchy skipped).

    Raises
    ------
    TypeError, ValueError
        As `add` does for each initial shape.

    Examples
    --------
    >>> import circledist as cd
    >>> s = cd.Scene()
    >>> s.add("ring", cd.Circle([0, 0, 0], [0, 0, 1], 1.0))
    >>> s.add("coin", cd.Disk([3, 0, 0], [1, 0, 0], 0.5, sweep=0.1))
    >>> s.nearest(cd.Line([-5, 1, 0.5], [1, 0, 0]))
    [('ring', 0.5)]
    >>> len(s), "coin" in s, s.names
    (2, True, ['ring', 'coin'])
    """

    def __init__(self, shapes=None):
        self._names: list[str] = []
        self._index: dict[str, int] = {}
        self._groups: dict[tuple, _Group] = {}
        self._item_group: list[np.ndarray] = []   # chunks of (group number) per item
        self._item_row: list[np.ndarray] = []     # chunks of (row in its group) per item
        self._built = None
        self.last_stats: dict = {}
        if shapes is not None:
            items = shapes.items() if hasattr(shapes, "items") else shapes
            for name, shape in items:
                self.add(name, shape)

    # ---- contents --------------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self._names)

    def __contains__(self, name) -> bool:
        return name in self._index

    @property
    def names(self) -> list[str]:
        """The shapes' names, in insertion order (a new list)."""
        return list(self._names)

    def add(self, name: str, shape) -> None:
        """Adds one (unbatched) shape under a new name.

        Parameters
        ----------
        name : str
            A name not yet in the scene.
        shape : Shape
            A single shape (batch shape ``()``).

        Returns
        -------
        None

        Raises
        ------
        TypeError
            When `shape` is not a circledist shape or `name` not a string.
        ValueError
            When `shape` is a batch (use `extend`) or `name` is taken.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.add("probe", cd.Point([0, 0, 1]))
        >>> s["probe"]
        Point(p=array([0., 0., 1.]))
        """
        if not isinstance(shape, _core.Shape):
            raise TypeError(f"Scene.add: {name!r} must be a circledist shape, got {type(shape).__name__}")
        if shape.batch_shape != ():
            raise ValueError(f"Scene.add: {name!r} is a batch of shape {shape.batch_shape}; "
                             "add batches with Scene.extend(names, batch)")
        self._insert([name], shape)

    def extend(self, names, batch) -> None:
        """Adds every shape of a batch.

        Parameters
        ----------
        names : str or sequence of str
            New names, one per element of the batch in C order, or a prefix string: the names
            are then prefix0, prefix1, ...
        batch : Shape
            A shape of any batch shape.

        Returns
        -------
        None

        Raises
        ------
        TypeError
            When `batch` is not a circledist shape or a name is not a string.
        ValueError
            When the number of names differs from the batch's size, or a name is taken.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("disk", cd.Disk([[0, 0, 0], [4, 0, 0]], [0, 0, 1], 1.0))
        >>> s.names
        ['disk0', 'disk1']
        """
        if not isinstance(batch, _core.Shape):
            raise TypeError(f"Scene.extend: expected a circledist shape, got {type(batch).__name__}")
        count = int(np.prod(batch.batch_shape, dtype=np.int64))
        if isinstance(names, str):
            start = len(self._names)
            names = [f"{names}{i}" for i in range(count)]
            del start
        names = list(names)
        if len(names) != count:
            raise ValueError(f"Scene.extend: {len(names)} names for a batch of {count} shapes")
        self._insert(names, batch)

    def _insert(self, names: list[str], shape) -> None:
        seen = set()
        for name in names:
            if not isinstance(name, str):
                raise TypeError(f"Scene: shape names must be strings, got {name!r}")
            if name in self._index or name in seen:
                raise ValueError(f"Scene: a shape named {name!r} is already in the scene")
            seen.add(name)
        kind, arrays, _ = _fields_of(shape)
        key = _group_key(kind, arrays)
        if key not in self._groups:
            self._groups[key] = _Group(kind)
        group = self._groups[key]
        number = list(self._groups).index(key)
        start = len(self._names)
        ids = np.arange(start, start + len(names))
        before = sum(len(i) for i in group.id_chunks)
        group.append(arrays, ids)
        self._item_group.append(np.full(len(names), number))
        self._item_row.append(np.arange(before, before + len(names)))
        for i, name in enumerate(names):
            self._index[name] = start + i
        self._names.extend(names)
        self._built = None

    def shape(self, name: str):
        """The shape stored under `name` (also ``scene[name]``).

        Parameters
        ----------
        name : str
            The shape's name.

        Returns
        -------
        Shape
            A single shape equal to the one added.

        Raises
        ------
        KeyError
            When no shape has that name.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene({"ring": cd.Circle([0, 0, 0], [0, 0, 1], 2.0)})
        >>> s.shape("ring").radius
        array(2.)
        """
        b = self._build()
        i = self._lookup(name)
        return b.groups[b.group[i]].single(b.row[i])

    def __getitem__(self, name: str):
        return self.shape(name)

    def _lookup(self, name: str) -> int:
        try:
            return self._index[name]
        except KeyError:
            raise KeyError(f"Scene: no shape named {name!r}") from None

    # ---- the hierarchy ---------------------------------------------------------------------
    @_quiet
    def _build(self):
        if self._built is not None:
            return self._built
        b = _Built()
        b.groups = list(self._groups.values())
        for g in b.groups:
            g.finish()
        n = len(self._names)
        b.group = np.concatenate(self._item_group) if n else np.zeros(0, int)
        b.row = np.concatenate(self._item_row) if n else np.zeros(0, int)
        b.lo = np.full((n, 3), -np.inf)
        b.hi = np.full((n, 3), np.inf)
        b.center = np.zeros((n, 3))
        b.radius = np.full(n, np.inf)
        b.line_origin = np.zeros((n, 3))
        b.line_direction = np.zeros((n, 3))
        for g in b.groups:
            if g.kind in UNBOUNDED:
                b.line_origin[g.ids] = g.fields[0]
                b.line_direction[g.ids] = g.fields[1]
                b.center[g.ids] = g.fields[0]
                continue
            lo, hi, c, r = _volumes(g.kind, g.fields)
            b.lo[g.ids], b.hi[g.ids], b.center[g.ids], b.radius[g.ids] = lo, hi, c, r
        b.bounded = np.flatnonzero(np.isfinite(b.radius))
        b.unbounded = np.flatnonzero(~np.isfinite(b.radius))
        b.sweep = np.zeros(n)
        for g in b.groups:
            b.sweep[g.ids] = g.fields[-1]
        if len(b.bounded):
            lo, hi = b.lo[b.bounded], b.hi[b.bounded]
            b.scale = float(np.abs(np.concatenate([lo, hi])).max() + (hi - lo).max())
            order = b.bounded[np.argsort(_morton(lo / 2 + hi / 2), kind="stable")]
            b.leaf_items = order
            starts = np.arange(0, len(order), LEAF)
            levels = [(np.minimum.reduceat(b.lo[order], starts), np.maximum.reduceat(b.hi[order], starts))]
            while len(levels[-1][0]) > 1:
                lo, hi = levels[-1]
                starts = np.arange(0, len(lo), BRANCH)
                levels.append((np.minimum.reduceat(lo, starts), np.maximum.reduceat(hi, starts)))
            b.levels = levels[::-1]  # root first; the last level holds the leaves
        else:
            b.scale = 1.0
            b.leaf_items = np.zeros(0, int)
            b.levels = []
        if len(b.unbounded):
            b.scale = max(b.scale, float(np.abs(b.line_origin[b.unbounded]).max()))
        self._built = b
        return b

    def _children(self, level: int, nodes: np.ndarray) -> np.ndarray:
        """The nodes of level + 1 under `nodes` (of level `level`)."""
        b = self._built
        count = len(b.levels[level + 1][0])
        kids = (nodes[:, None] * BRANCH + np.arange(BRANCH)).ravel()
        return kids[kids < count]

    def _leaf_items(self, leaves: np.ndarray) -> np.ndarray:
        b = self._built
        items = (leaves[:, None] * LEAF + np.arange(LEAF)).ravel()
        items = items[items < len(b.leaf_items)]
        return b.leaf_items[items]

    def _candidates(self, q: _Query, limit: float, margin: float) -> tuple[np.ndarray, np.ndarray]:
        """Items whose lower bound is <= limit + margin (bounded ones via the hierarchy, then
        every unbounded one), with their lower bounds."""
        b = self._built
        items = np.zeros(0, int)
        if b.levels:
            nodes = np.zeros(1, int)
            for level in range(len(b.levels)):
                lo, hi = b.levels[level]
                nodes = nodes[q.node_bound(lo[nodes], hi[nodes]) <= limit + margin]
                if level + 1 < len(b.levels):
                    nodes = self._children(level, nodes)
            items = self._leaf_items(nodes)
        items = np.concatenate([items, b.unbounded])
        bound = q.item_bound(b.lo[items], b.hi[items], b.center[items], b.radius[items])
        bound = self._unbounded_item_bound(q, items, bound)
        keep = bound <= limit + margin
        return items[keep], bound[keep]

    def _unbounded_item_bound(self, q: _Query, items, bound):
        """A bounded query against the scene's lines and rays: its ball's distance to them."""
        b = self._built
        if q.unbounded:
            return bound
        for i in np.flatnonzero(~np.isfinite(b.radius[items])):
            item = items[i]
            ray = b.groups[b.group[item]].kind == "Ray"
            d = _point_line_distance(q.center, b.line_origin[item], b.line_direction[item], ray)
            with _overflow_handled():
                bound[i] = d - q.radius - b.sweep[item]
        return _conservative(bound)

    def _margin(self, q: _Query, limit: float) -> float:
        b = self._built
        return RELATIVE_MARGIN * (abs(limit) + b.scale + q.size)

    # ---- evaluation helpers ----------------------------------------------------------------
    def _check_kinds(self, kind: str, items: Iterable[int] | None = None) -> None:
        b = self._build()
        supported = _supported()
        for g in b.groups:
            if (kind, g.kind) not in supported:
                raise TypeError(f"circledist has no query between a {kind} and a {g.kind} "
                                f"(the scene holds {g.kind} shapes)")

    def _evaluate(self, shape, items: np.ndarray, fn, *args) -> np.ndarray:
        """fn(shape, batch_of_items, *args) for items grouped by kind; results in items' order."""
        b = self._built
        out = None
        for gnum in np.unique(b.group[items]):
            sel = np.flatnonzero(b.group[items] == gnum)
            g = b.groups[gnum]
            values = np.asarray(fn(shape, g.batch(b.row[items[sel]]), *args))
            if out is None:
                out = np.empty(len(items), dtype=values.dtype)
            out[sel] = values
        if out is None:
            out = np.zeros(0)
        return out

    def _resolve(self, shape):
        """A query shape, or the name of a scene shape (which then is not its own answer)."""
        if isinstance(shape, str):
            i = self._lookup(shape)
            return self.shape(shape), {i}
        if not isinstance(shape, _core.Shape):
            shape = _core.Point(shape)
        return shape, set()

    # ---- queries ---------------------------------------------------------------------------
    def nearest(self, shape, k: int = 1, *, exclude: Sequence[str] = ()) -> list[tuple[str, float]]:
        """The k scene shapes nearest to `shape`.

        Parameters
        ----------
        shape : Shape, array_like or str
            A single shape, a point as an array of shape (3,), or the name of a scene shape
            (which is then left out of its own answer).
        k : int, default 1
            How many shapes to return (fewer when the scene holds fewer).
        exclude : sequence of str, optional
            Keyword only. Names of scene shapes to leave out.

        Returns
        -------
        list of (str, float)
            (name, distance) pairs sorted by distance, then by insertion order: the same as
            sorting every distance (brute force).

        Raises
        ------
        KeyError
            When `shape` or a name in `exclude` is not a scene shape's name.
        TypeError
            When k is not an integer, or there is no query between `shape`'s kind and a kind
            in the scene.
        ValueError
            When k < 1 or `shape` is a batch.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ball", cd.Point([[0, 0, 0], [2, 0, 0], [5, 0, 0]], sweep=0.5))
        >>> s.nearest([1.5, 0, 0], k=2)
        [('ball1', 0.0), ('ball0', 1.0)]
        >>> s.nearest("ball0")
        [('ball1', 1.0)]
        """
        shape, skip = self._resolve(shape)
        skip |= {self._lookup(n) for n in exclude}
        if isinstance(k, (bool, np.bool_)) or not isinstance(k, (int, np.integer)):
            raise TypeError(f"Scene.nearest: k must be an integer >= 1, got {k!r}")
        k = int(k)
        if k < 1:
            raise ValueError(f"Scene.nearest: k must be an integer >= 1, got {k}")
        b = self._build()
        q = _Query(shape)
        self._check_kinds(q.kind)
        n = len(self._names)
        available = n - len(skip)
        if available <= 0:
            return []
        k = min(k, available)
        skip_arr = np.fromiter(skip, int, len(skip))
        known: dict[int, float] = {}

        # 1. An upper bound tau on the k-th distance: the exact distances of a few shapes reached
        #    by a greedy descent (the best nodes by lower bound, level by level).
        seeds = self._greedy_seeds(q, k, skip_arr)
        if len(seeds):
            d = self._evaluate(shape, seeds, _core.distance)
            known.update(zip(seeds.tolist(), d.tolist()))
        tau = np.inf if len(known) < k else float(np.partition(np.fromiter(known.values(), float), k - 1)[k - 1])

        # 2. Every shape whose lower bound is within tau, nearest bound first, in chunks; each
        #    chunk only evaluates where its bounds cannot show the distance exceeds tau.
        margin = self._margin(q, 0.0 if not np.isfinite(tau) else tau)
        items, bound = self._candidates(q, tau, margin if np.isfinite(tau) else np.inf)
        fresh = ~np.isin(items, skip_arr) & ~np.isin(items, np.fromiter(known, int, len(known)))
        items, bound = items[fresh], bound[fresh]
        order = np.argsort(bound, kind="stable")
        items, bound = items[order], bound[order]
        tested = len(known)
        chunk = max(16, 2 * k)
        at = 0
        while at < len(items):
            if np.isfinite(tau) and bound[at] > tau + self._margin(q, tau):
                break
            part = items[at:at + chunk]
            if np.isfinite(tau):
                d = self._evaluate(shape, part, _core.distance_if_within, tau)
            else:
                d = self._evaluate(shape, part, _core.distance)
            tested += len(part)
            for i, v in zip(part.tolist(), d.tolist()):
                if np.isfinite(v):
                    known[i] = v
            if len(known) >= k:
                tau = float(np.partition(np.fromiter(known.values(), float), k - 1)[k - 1])
            at += len(part)
            chunk = min(2 * chunk, 4096)
        best = sorted(known.items(), key=lambda kv: (kv[1], kv[0]))[:k]
        culled = available - tested
        _core._count_culled(max(culled, 0))
        self.last_stats = {"shapes": n, "tested": tested, "culled": culled}
        return [(self._names[i], d) for i, d in best]

    def _greedy_seeds(self, q: _Query, k: int, skip: np.ndarray) -> np.ndarray:
        """A few shapes likely to be among the nearest: a beam descent keeps the BEAM nodes of
        smallest lower bound per level; of the shapes in the leaves reached (and the lines and
        rays), the k + 2 of smallest lower bound."""
        b = self._built
        items = np.zeros(0, int)
        if b.levels:
            nodes = np.zeros(1, int)
            for level in range(len(b.levels)):
                lo, hi = b.levels[level]
                if len(nodes) > BEAM:
                    bound = q.node_bound(lo[nodes], hi[nodes])
                    nodes = nodes[np.argsort(bound, kind="stable")[:BEAM]]
                if level + 1 < len(b.levels):
                    nodes = self._children(level, nodes)
            items = self._leaf_items(nodes)
        items = np.concatenate([items, b.unbounded])
        items = items[~np.isin(items, skip)]
        bound = q.item_bound(b.lo[items], b.hi[items], b.center[items], b.radius[items])
        bound = self._unbounded_item_bound(q, items, bound)
        return items[np.argsort(bound, kind="stable")[:k + 2]]

    def within(self, shape, d: float) -> list[str]:
        """Names of the scene shapes within distance d of `shape`.

        Parameters
        ----------
        shape : Shape, array_like or str
            A single shape, a point, or the name of a scene shape (then left out).
        d : float
            Distance limit >= 0.

        Returns
        -------
        list of str
            In insertion order: the shapes for which ``circledist.within(shape, s, d)`` holds.

        Raises
        ------
        KeyError
            When `shape` is a name not in the scene.
        TypeError
            When d is not a real number, or there is no query between the kinds.
        ValueError
            When d is negative or NaN, or `shape` is a batch.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ball", cd.Point([[0, 0, 0], [2, 0, 0], [5, 0, 0]], sweep=0.5))
        >>> s.within(cd.Segment([0, 1, 0], [3, 1, 0]), 0.5)
        ['ball0', 'ball1']
        """
        shape, skip = self._resolve(shape)
        d = _limit("Scene.within", d)
        b = self._build()
        q = _Query(shape)
        self._check_kinds(q.kind)
        items, _ = self._candidates(q, d, self._margin(q, d))
        items = np.sort(items[~np.isin(items, np.fromiter(skip, int, len(skip)))])
        hit = self._evaluate(shape, items, _core.within, d).astype(bool) if len(items) else np.zeros(0, bool)
        culled = len(self._names) - len(skip) - len(items)
        _core._count_culled(culled)
        self.last_stats = {"shapes": len(self._names), "tested": len(items), "culled": culled}
        return [self._names[i] for i in items[hit]]

    def pairs_within(self, d: float) -> list[tuple[str, str]]:
        """Every pair of scene shapes within distance d of each other.

        Parameters
        ----------
        d : float
            Distance limit >= 0.

        Returns
        -------
        list of (str, str)
            (name_i, name_j) with i added before j, sorted by (i, j): the pairs for which
            `circledist.within` holds.

        Raises
        ------
        TypeError
            When d is not a real number, or the scene holds two kinds without a query.
        ValueError
            When d is negative or NaN.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ball", cd.Point([[0, 0, 0], [2, 0, 0], [5, 0, 0]], sweep=0.5))
        >>> s.pairs_within(1.0)
        [('ball0', 'ball1')]
        """
        d = _limit("Scene.pairs_within", d)
        b = self._build()
        supported = _supported()
        kinds = [g.kind for g in b.groups]
        for i, ka in enumerate(kinds):
            for kb in kinds[i:]:
                if ka == kb and len(b.groups[i].ids) < 2:
                    continue
                if (ka, kb) not in supported:
                    raise TypeError(f"circledist has no query between a {ka} and a {kb} (the scene holds both)")
        margin = RELATIVE_MARGIN * (d + b.scale)
        pa, pb = self._bounded_pairs(d, margin)
        # Lines and rays against everything after... and before them: all pairs with one of them.
        extra_a, extra_b = [], []
        for u in b.unbounded:
            q = _Query(b.groups[b.group[u]].single(b.row[u]))
            items, _ = self._candidates(q, d, self._margin(q, d))
            items = items[items != u]
            # A pair of two unbounded shapes is found from both ends: keep it once.
            items = items[~(np.isin(items, b.unbounded) & (items < u))]
            extra_a.append(np.full(len(items), u))
            extra_b.append(items)
        if extra_a:
            pa = np.concatenate([pa] + extra_a)
            pb = np.concatenate([pb] + extra_b)
        i, j = np.minimum(pa, pb), np.maximum(pa, pb)
        hit = np.zeros(len(i), bool)
        for ga in np.unique(b.group[i]) if len(i) else []:
            for gb in np.unique(b.group[j[b.group[i] == ga]]):
                sel = np.flatnonzero((b.group[i] == ga) & (b.group[j] == gb))
                A, B = b.groups[ga], b.groups[gb]
                hit[sel] = _core.within(A.batch(b.row[i[sel]]), B.batch(b.row[j[sel]]), d)
        n = len(self._names)
        culled = n * (n - 1) // 2 - len(i)
        _core._count_culled(culled)
        self.last_stats = {"shapes": n, "tested": len(i), "culled": culled}
        order = np.lexsort((j[hit], i[hit]))
        return [(self._names[a], self._names[c]) for a, c in zip(i[hit][order], j[hit][order])]

    def _bounded_pairs(self, d: float, margin: float):
        """Pairs of bounded items whose boxes and balls are within d + margin (dual traversal)."""
        b = self._built
        if not b.levels:
            return np.zeros(0, int), np.zeros(0, int)
        na = np.zeros(1, int)
        nb = np.zeros(1, int)
        limit = d + margin
        for level in range(len(b.levels)):
            lo, hi = b.levels[level]
            keep = _box_gap(lo[na], hi[na], lo[nb], hi[nb]) <= limit
            na, nb = na[keep], nb[keep]
            if level + 1 < len(b.levels):
                na, nb = self._child_pairs(level, na, nb)
        # Leaf pairs -> item pairs.
        count = len(b.leaf_items)
        ia = (na[:, None, None] * LEAF + np.arange(LEAF)[None, :, None])
        ib = (nb[:, None, None] * LEAF + np.arange(LEAF)[None, None, :])
        ia, ib = np.broadcast_arrays(ia, ib)
        same = (na == nb)[:, None, None]
        ok = (ia < count) & (ib < count) & (~same | (ia < ib))
        ia, ib = b.leaf_items[ia[ok]], b.leaf_items[ib[ok]]
        with _overflow_handled():
            gap = _conservative(np.maximum(_box_gap(b.lo[ia], b.hi[ia], b.lo[ib], b.hi[ib]),
                                           _norm(b.center[ia] - b.center[ib]) - b.radius[ia] - b.radius[ib]))
        keep = gap <= limit
        return ia[keep], ib[keep]

    def _child_pairs(self, level: int, na: np.ndarray, nb: np.ndarray):
        b = self._built
        count = len(b.levels[level + 1][0])
        ca = (na[:, None, None] * BRANCH + np.arange(BRANCH)[None, :, None])
        cb = (nb[:, None, None] * BRANCH + np.arange(BRANCH)[None, None, :])
        ca, cb = np.broadcast_arrays(ca, cb)
        same = (na == nb)[:, None, None]
        ok = (ca < count) & (cb < count) & (~same | (ca <= cb))
        return ca[ok], cb[ok]

    def distance_matrix(self, a_names: Sequence[str], b_names: Sequence[str]) -> np.ndarray:
        """The distances between every named shape of a_names (rows) and of b_names (columns).

        No culling (every entry is asked for) and no closest-point work.

        Parameters
        ----------
        a_names, b_names : sequence of str
            Names of scene shapes.

        Returns
        -------
        numpy.ndarray, shape (len(a_names), len(b_names))
            ``circledist.distance`` of each pair.

        Raises
        ------
        KeyError
            When a name is not in the scene.
        TypeError
            When there is no query between two of the kinds.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ball", cd.Point([[0, 0, 0], [2, 0, 0], [5, 0, 0]], sweep=0.5))
        >>> s.distance_matrix(["ball0"], ["ball1", "ball2"])
        array([[1., 4.]])
        """
        b = self._build()
        ia = np.array([self._lookup(n) for n in a_names], dtype=int)
        ib = np.array([self._lookup(n) for n in b_names], dtype=int)
        out = np.empty((len(ia), len(ib)))
        for ga in np.unique(b.group[ia]) if len(ia) else []:
            ra = np.flatnonzero(b.group[ia] == ga)
            for gb in np.unique(b.group[ib]) if len(ib) else []:
                rb = np.flatnonzero(b.group[ib] == gb)
                A, B = b.groups[ga], b.groups[gb]
                out[np.ix_(ra, rb)] = _core.distance(A.batch(b.row[ia[ra]], column=True), B.batch(b.row[ib[rb]]))
        return out


class _Built:
    """The consolidated arrays and the hierarchy of a scene (rebuilt after any change)."""


_SUPPORTED: set | None = None


def _supported() -> set:
    global _SUPPORTED
    if _SUPPORTED is None:
        _SUPPORTED = {tuple(p) for p in _core._query_kinds()}
    return _SUPPORTED
