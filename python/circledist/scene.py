"""A scene: named shapes of any kinds, and the few questions a user asks of it.

``Scene.nearest``, ``Scene.within`` and ``Scene.pairs_within`` cull with the broadphase that
``circledist.pairs_within`` and ``circledist.nearest`` use (the C++ header
``circledist/broadphase.hpp``): a bounding-volume hierarchy over the shapes' boxes and balls,
which the shapes added since the last query join at the next query (it grows: a few trees,
merged as they grow, so adds and queries may alternate at O(log^2 n) per shape amortized). A
shape or a pair is skipped only when a lower bound on its distance (box gap, ball gap, distance
from a line to a ball) exceeds the limit by a margin far above rounding, so every answer is the
one brute force gives: the exact tests that remain go
through ``circledist.within`` / ``circledist.distance_if_within``, which try cheap exact bounds
again before they solve a polynomial.

Shapes are kept per kind (and, for Bezier curves, per control point count, and per the dtypes of
their fields) in arrays that grow by doubling, so adding n shapes one by one costs O(n) in all.
A shape keeps the dtypes it was added with (float32, float64, long double, per field, as its
``to_arrays()`` reports them) and whether it was given a sweep: the scene returns it as it was
added, and queries measure it as ``circledist.distance`` measures it (float32 answers where the
query and the shape are float32 throughout, as the library's precision rule says).
"""

from __future__ import annotations

from array import array
from contextlib import contextmanager
from typing import Iterable, Sequence

import threading

import numpy as np

from . import _core
from ._batch import ROLE_TRAILING_DIMS, TRAILING_DIMS  # noqa: F401 (ROLE_TRAILING_DIMS: scenefile.py)
from ._scene_motion import MotionQueries, SceneContact  # noqa: F401 (SceneContact: its answers)

__all__ = ["Scene"]

# The constructor arguments of each kind, in order (the sweep comes on top as a keyword), from
# the module's one table of fields (src/shapes.hpp).
KIND_FIELDS = {kind: tuple(name for name, _ in fields) for kind, fields in _core._shape_fields().items()}
# Bezier curves take 2 to MAX_CONTROL_POINTS control points.
MAX_CONTROL_POINTS = _core._max_control_points


class _Grown:
    """An array of rows (float32, float64, long double or int64) that grows by doubling:
    appending is O(1) amortized."""

    def __init__(self, trailing: tuple, dtype=np.float64, data: np.ndarray | None = None):
        self.data = np.empty((0,) + trailing, dtype) if data is None else data
        self.count = len(self.data)

    def reserve(self, extra: int) -> None:
        if self.count + extra > len(self.data):
            grown = np.empty((max(2 * len(self.data), self.count + extra, 16),) + self.data.shape[1:], self.data.dtype)
            grown[: self.count] = self.data[: self.count]
            self.data = grown

    def append(self, value) -> None:
        self.reserve(1)
        self.data[self.count] = value
        self.count += 1

    def extend(self, values: np.ndarray) -> None:
        self.reserve(len(values))
        self.data[self.count : self.count + len(values)] = values
        self.count += len(values)

    @property
    def array(self) -> np.ndarray:
        return self.data[: self.count]


class _Group:
    """Shapes of one kind (and, for Bezier curves, one control point count), one dtype per field,
    with a sweep or without, column-stored (a sweep column of zeros when without).

    Single shapes are appended to a Python list, their fields' arrays as a tuple (the cheapest
    step per call; a tuple of arrays, unlike a list, leaves the cycle collector's lists), and moved
    into the growing arrays when the arrays are next read: adding stays O(1), reading after adds
    O(adds).
    """

    def __init__(self, kind: str, trailing: list[tuple], dtypes: list, swept: bool = True):
        self.kind = kind
        self.cls = getattr(_core, kind)
        self.names = KIND_FIELDS[kind] + ("sweep",)
        self.swept = swept
        self.columns = [_Grown(t, dtype) for t, dtype in zip(trailing, dtypes)]
        self.pending: list[tuple] = []  # rows: one shape's fields, the sweep last
        self.id_column = _Grown((), np.int64)
        self.pending_ids: list[int] = []
        self.size = 0
        self.indexed = 0  # rows [0, indexed) are in the scene's broadphase

    def __len__(self) -> int:
        return self.size

    def append(self, values: tuple, item: int) -> int:
        """Adds one shape's fields (the sweep last) as item `item`; returns its row."""
        self.pending.append(values)
        self.pending_ids.append(item)
        self.size += 1
        return self.size - 1

    def extend(self, values: list[np.ndarray], items: np.ndarray) -> None:
        self._flush()
        for column, value in zip(self.columns, values):
            column.extend(value)
        self.id_column.extend(items)
        self.size += len(items)

    def _flush(self) -> None:
        if self.pending_ids:
            for j, column in enumerate(self.columns):
                pending = [row[j] for row in self.pending]
                column.extend(np.array(pending, dtype=column.data.dtype).reshape((-1,) + column.data.shape[1:]))
            self.pending.clear()
            self.id_column.extend(np.array(self.pending_ids, dtype=np.int64))
            self.pending_ids.clear()

    @property
    def fields(self) -> list[np.ndarray]:
        self._flush()
        return [c.array for c in self.columns]

    @property
    def ids(self) -> np.ndarray:
        self._flush()
        return self.id_column.array

    def batch(self, rows, column: bool = False):
        """The shapes at local rows as one batched shape; column=True gives batch shape (n, 1)."""
        arrays = [f[rows] for f in self.fields]
        if column:
            arrays = [a[:, None] for a in arrays]
        return self._shape(arrays)

    def whole(self):
        """Every shape of the group as one batch, referring to the stored arrays (no copy)."""
        return self._shape([np.ascontiguousarray(f) for f in self.fields], copy=False)

    def rows_from(self, first: int):
        """The shapes at rows [first, len) as one batch, referring to the stored arrays (no copy)."""
        return self._shape([f[first:] for f in self.fields], copy=False)

    def single(self, row: int):
        return self._shape([f[row] for f in self.fields])

    def _shape(self, arrays: list, copy: bool = True):
        """The shape of the fields' arrays, the sweep last (left out for shapes added without one)."""
        if self.swept:
            return self.cls(*arrays[:-1], sweep=arrays[-1], copy=copy)
        return self.cls(*arrays[:-1], copy=copy)


class _ReadersWriter:
    """A readers-writer lock: queries read together, a change (an add, the hierarchy's growth)
    waits for the readers and keeps them out. A waiting writer holds new readers back, so a
    stream of queries does not starve the adds. `downgrade` turns the writer into a reader with
    no writer between (a query that first brought the hierarchy up to date then reads it as it
    left it). Not reentrant: the Scene's public methods take it once and call unlocked helpers."""

    def __init__(self):
        self._condition = threading.Condition(threading.Lock())
        self._readers = 0
        self._writer = False
        self._waiting = 0  # writers waiting

    def acquire_read(self) -> None:
        with self._condition:
            while self._writer or self._waiting:
                self._condition.wait()
            self._readers += 1

    def release_read(self) -> None:
        with self._condition:
            self._readers -= 1
            if self._readers == 0:
                self._condition.notify_all()

    def acquire_write(self) -> None:
        with self._condition:
            self._waiting += 1
            try:
                while self._writer or self._readers:
                    self._condition.wait()
            finally:
                self._waiting -= 1
            self._writer = True

    def release_write(self) -> None:
        with self._condition:
            self._writer = False
            self._condition.notify_all()

    def downgrade(self) -> None:
        with self._condition:
            self._writer = False
            self._readers += 1
            self._condition.notify_all()

    @contextmanager
    def reading(self):
        self.acquire_read()
        try:
            yield
        finally:
            self.release_read()

    @contextmanager
    def writing(self):
        self.acquire_write()
        try:
            yield
        finally:
            self.release_write()


def _limit(owner: str, d) -> float:
    """A distance limit: a finite real number >= 0 (strings, bools, None, NaN and inf are errors),
    read by the reader every entry point's d goes through."""
    return _core._distance_limit(owner, d)


class Scene(MotionQueries):
    """Named shapes of any kinds (each a single shape) and culled queries over them.

    A bounding-volume hierarchy (the C++ broadphase of `circledist.pairs_within`) skips the
    shapes a query cannot reach; every answer is the one brute force over `circledist.within`
    and `circledist.distance` gives. Adding a shape costs O(1); the next query adds the new
    shapes to the hierarchy, which grows (O(log^2 n) per shape amortized, not a rebuild), so
    adds and queries may alternate. A scene pickles and deep-copies.

    Shapes keep the dtypes they were added with (per field: float32, float64 or long double)
    and come back as added; queries measure them as ``circledist.distance`` measures those
    shapes (float32 answers where the query and the shape are float32 throughout).

    A scene may be shared between threads: queries run side by side, while an add (or a query
    that first brings the hierarchy up to date) runs alone, between them. Each query answers for
    the scene as it was when it began (every shape added before it, none added during it).

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
        self._lock = _ReadersWriter()
        self._names: list[str] = []
        self._index: dict[str, int] = {}
        self._groups: dict[tuple, _Group] = {}
        self._keys: dict[tuple, int] = {}  # group key -> group number
        self._group_list: list[_Group] = []  # group number -> group
        self._item_group = array("q")  # per item: its group number
        self._item_row = array("q")  # per item: its row in the group
        self._broadphase = None  # made by the first query; holds items [0, len(it))
        self.last_stats: dict = {}
        if shapes is not None:
            items = shapes.items() if hasattr(shapes, "items") else shapes
            for name, shape in items:
                self.add(name, shape)

    # ---- pickling and copying: the stored arrays (the hierarchy is rebuilt on demand) -------
    def __getstate__(self) -> dict:
        with self._current(build=False):
            return {
                "names": list(self._names),
                "groups": [
                    (key, g.kind, [f.copy() for f in g.fields], g.ids.copy()) for key, g in self._groups.items()
                ],
                "item_group": np.array(self._item_group, dtype=np.int64),
                "item_row": np.array(self._item_row, dtype=np.int64),
                "last_stats": dict(self.last_stats),
            }

    def __setstate__(self, state: dict) -> None:
        try:
            self._load(state)
        except ValueError as error:
            raise ValueError(f"Scene: the pickled state is invalid: {error}") from None
        except (TypeError, KeyError, IndexError, AttributeError) as error:
            raise ValueError(f"Scene: the pickled state is invalid: {type(error).__name__}: {error}") from None

    def _load(self, state: dict) -> None:
        """The scene of a state __getstate__ wrote, checked: the state may come from anywhere
        (a pickle is data), and a scene whose items and groups disagree answers wrongly, not
        loudly. ValueError names what is wrong."""
        self._lock = _ReadersWriter()
        if not isinstance(state, dict):
            raise ValueError(f"expected a dict, got {type(state).__name__}")
        self._names = list(state["names"])
        n = len(self._names)
        for i, name in enumerate(self._names):
            if not isinstance(name, str):
                raise ValueError(f"name {i} is not a string: {name!r}")
        self._index = {name: i for i, name in enumerate(self._names)}
        if len(self._index) != n:
            seen = set()
            name = next(x for x in self._names if x in seen or seen.add(x))
            raise ValueError(f"the name {name!r} is given twice")
        item_group = np.asarray(state["item_group"])
        item_row = np.asarray(state["item_row"])
        for label, column in (("item_group", item_group), ("item_row", item_row)):
            if column.shape != (n,) or (n and column.dtype.kind not in "iu"):
                raise ValueError(
                    f"{label} must hold one integer per name ({n}), got shape {column.shape}, " f"dtype {column.dtype}"
                )
        item_group, item_row = item_group.astype(np.int64), item_row.astype(np.int64)
        self._groups, self._keys, self._group_list = {}, {}, []
        owner = np.full(n, -1, np.int64)  # the group that holds each item, from the groups' ids
        for number, (key, kind, fields, ids) in enumerate(state["groups"]):
            key = tuple(key)
            if kind not in KIND_FIELDS:
                raise ValueError(f"group {number}: unknown kind {kind!r}")
            fields = [np.asarray(f) for f in fields]
            if len(fields) != len(KIND_FIELDS[kind]) + 1:
                raise ValueError(
                    f"group {number}: a {kind} group has {len(KIND_FIELDS[kind]) + 1} fields "
                    f"(the sweep last), got {len(fields)}"
                )
            if len(key) == 2:  # written before groups had dtypes: float64 throughout, with a sweep
                key = key + (tuple(np.dtype(np.float64) for _ in fields), True)
            if len(key) != 4 or key[0] != kind or len(key[2]) != len(fields):
                raise ValueError(f"group {number}: its key {key!r} does not describe a {kind} group")
            ids = np.asarray(ids)
            if ids.ndim != 1 or (len(ids) and ids.dtype.kind not in "iu"):
                raise ValueError(f"group {number}: ids must be a 1-d array of integers")
            ids = ids.astype(np.int64)
            for name, f in zip(KIND_FIELDS[kind] + ("sweep",), fields):
                if f.ndim < 1 or len(f) != len(ids):
                    raise ValueError(
                        f"group {number}: field {name} has {len(f) if f.ndim else 0} rows for " f"{len(ids)} ids"
                    )
            if len(ids) and (ids.min() < 0 or ids.max() >= n):
                raise ValueError(f"group {number}: an id is not an item number in [0, {n})")
            rows = np.arange(len(ids))
            if np.any(owner[ids] != -1) or len(np.unique(ids)) != len(ids):
                raise ValueError(f"group {number}: an item is held twice (duplicated ids)")
            owner[ids] = number
            if np.any(item_group[ids] != number) or np.any(item_row[ids] != rows):
                raise ValueError(f"group {number}: item_group and item_row do not point at the group's rows")
            g = _Group(kind, [f.shape[1:] for f in fields], [np.dtype(d) for d in key[2]], key[3])
            g.columns = [_Grown(f.shape[1:], data=np.array(f, dtype=np.dtype(d))) for f, d in zip(fields, key[2])]
            g.id_column = _Grown((), np.int64, ids)
            g.size = len(ids)
            if len(ids):
                g.whole()  # the shapes' own checks (finite values, radii, control points, ...)
            if key in self._groups:
                raise ValueError(f"group {number}: its key {key!r} is given twice")
            self._groups[key] = g
            self._keys[key] = number
            self._group_list.append(g)
        if np.any(owner == -1):
            raise ValueError(f"item {int(np.flatnonzero(owner == -1)[0])} is in no group")
        self._item_group = array("q", item_group.tobytes())
        self._item_row = array("q", item_row.tobytes())
        self._broadphase = None
        self.last_stats = dict(state["last_stats"])

    # ---- contents --------------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self._names)

    def __contains__(self, name) -> bool:
        return name in self._index

    @property
    def names(self) -> list[str]:
        """The shapes' names, in insertion order (a new list)."""
        with self._lock.reading():
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
            raise ValueError(
                f"Scene.add: {name!r} is a batch of shape {shape.batch_shape}; "
                "add batches with Scene.extend(names, batch)"
            )
        if not isinstance(name, str):
            raise TypeError(f"Scene: shape names must be strings, got {name!r}")
        with self._lock.writing():
            self._add(name, shape)

    def _add(self, name: str, shape) -> None:
        if name in self._index:
            raise ValueError(f"Scene: a shape named {name!r} is already in the scene")
        # One shape: its fields as they are (trailing dimensions and dtypes), no broadcasting to do;
        # to_arrays() lists them in the table's order (KIND_FIELDS), then the sweep if it was given.
        kind = shape.kind
        values = tuple(shape.to_arrays().values())
        swept = len(values) > len(KIND_FIELDS[kind])
        if not swept:
            values += (_NO_SWEEP,)
        group, number = self._group(kind, values[0].shape if kind == "Bezier" else None, values, swept)
        item = len(self._names)
        self._item_group.append(number)
        self._item_row.append(group.append(values, item))
        self._index[name] = item
        self._names.append(name)

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
        generated = isinstance(names, str)
        names = [f"{names}{i}" for i in range(count)] if generated else list(names)
        if len(names) != count:
            raise ValueError(f"Scene.extend: {len(names)} names for a batch of {count} shapes")
        kind = batch.kind
        shape = tuple(batch.batch_shape)
        arrays = batch.to_arrays()
        values = []
        for field in KIND_FIELDS[kind] + ("sweep",):
            a = arrays.get(field, _NO_SWEEP)
            trailing = a.shape[a.ndim - TRAILING_DIMS[field] :] if TRAILING_DIMS[field] else ()
            values.append(np.broadcast_to(a, shape + trailing).reshape((-1,) + trailing))
        with self._lock.writing():
            self._insert(names, [(kind, values, np.arange(count), "sweep" in arrays)], distinct=generated)

    def _insert(self, names: list, parts: list, distinct: bool = False) -> None:
        """Adds len(names) shapes at once, named in order: parts are (kind, values, positions,
        swept), values one array per field (the sweep last; zeros when swept is false: shapes
        without a sweep) whose rows are the shapes at `positions` (in names) of that kind; the
        parts' positions together cover every name once. The rows are taken as valid shapes (they
        come from shapes, or from a validated scene file); distinct: the names are strings, each
        of its own (a prefix and numbers), and only checked against the scene's."""
        self._check_new_names(names, distinct)
        start = len(self._names)
        item_group = np.empty(len(names), np.int64)
        item_row = np.empty(len(names), np.int64)
        for kind, values, positions, swept in parts:
            group, number = self._group(
                kind,
                values[0].shape[1:] if kind == "Bezier" else None,
                [np.zeros(v.shape[1:], v.dtype) for v in values],
                swept,
            )
            item_group[positions] = number
            item_row[positions] = np.arange(len(group), len(group) + len(positions))
            group.extend(values, start + np.asarray(positions, dtype=np.int64))
        self._item_group.frombytes(item_group.tobytes())
        self._item_row.frombytes(item_row.tobytes())
        self._index.update(zip(names, range(start, start + len(names))))
        self._names.extend(names)

    def _check_new_names(self, names: list, distinct: bool) -> None:
        """Raises as `add` would for the first of the names that is no string, or is in the scene
        or earlier in names: whole-list checks (C loops) first, the name by name loop only to find
        and word an error."""
        if distinct or (set(map(type, names)) <= {str} and len(set(names)) == len(names)):
            if self._index.keys().isdisjoint(names):
                return
        seen = set()
        for name in names:
            if not isinstance(name, str):
                raise TypeError(f"Scene: shape names must be strings, got {name!r}")
            if name in self._index or name in seen:
                raise ValueError(f"Scene: a shape named {name!r} is already in the scene")
            seen.add(name)

    def _group(self, kind: str, control, element: list, swept: bool) -> tuple[_Group, int]:
        """The group of a kind (Bezier curves: and control point count, from the shape `control`
        of their control points), of the dtypes of `element`'s fields (one shape's) and of shapes
        with a sweep or without; made on first use with the trailing shapes of those fields."""
        dtypes = tuple([v.dtype for v in element])
        key = (kind, control[0] if kind == "Bezier" else 0, dtypes, swept)
        number = self._keys.get(key)
        if number is None:
            group = self._groups[key] = _Group(kind, [v.shape for v in element], dtypes, swept)
            number = self._keys[key] = len(self._group_list)
            self._group_list.append(group)
        return self._group_list[number], number

    def shape(self, name: str):
        """The shape stored under `name` (also ``scene[name]``).

        Parameters
        ----------
        name : str
            The shape's name.

        Returns
        -------
        Shape
            A single shape equal to the one added: the same values, each field in the dtype it
            was added with (float32, float64 or long double), with a sweep only if it was given
            one.

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
        with self._current(build=False):
            return self._single(self._lookup(name))

    def _single(self, i: int):
        """Item i as a single shape (the groups flushed: under `_current`)."""
        group = self._group_list[self._item_group[i]]
        return group.single(self._item_row[i])

    def __getitem__(self, name: str):
        return self.shape(name)

    def _lookup(self, name: str) -> int:
        try:
            return self._index[name]
        except KeyError:
            raise KeyError(f"Scene: no shape named {name!r}") from None

    def figure(self, *, pairs=None, detail=None, box=None, title=None, motions=None, frames=None):
        """An interactive 3-D figure (plotly) of the scene: ``circledist.figure(scene, ...)``.

        Parameters
        ----------
        pairs : sequence of (str, str), optional
            Pairs of shape names whose closest points are drawn, each labelled with its distance.
        detail : int, optional
            Points on each closed rim; default: fewer for more shapes.
        box : pair of 3-vectors, optional
            The region shown, which lines and rays are clipped to; default: around the shapes.
        title : str, optional
            The figure's title.
        motions, frames : optional
            Shapes' motions by name, animated over ``frames`` time steps (`circledist.figure`).

        Returns
        -------
        plotly.graph_objects.Figure
            Each shape labelled with its name on hover (`circledist.figure`).

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene({"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0), "probe": cd.Point([0, 0, 2])})
        >>> [trace.name for trace in s.figure(pairs=[("probe", "ring")]).data][:2]
        ['ring', 'probe']
        """
        from .view import figure

        return figure(self, pairs=pairs, detail=detail, box=box, title=title, motions=motions, frames=frames)

    # ---- the hierarchy ---------------------------------------------------------------------
    def _fresh(self, build: bool, merge: bool) -> bool:
        """Whether reading needs no change first: no group has rows pending, and (build) the
        broadphase holds every item, (merge) in one tree."""
        if any(g.pending_ids for g in self._group_list):
            return False
        if not build:
            return True
        bp = self._broadphase
        return bp is not None and len(bp) == len(self._names) and (not merge or bp.trees == 1)

    @contextmanager
    def _current(self, workers: int = 1, build: bool = True, merge: bool = False):
        """Read access to the scene, brought up to date first (the groups' pending rows moved into
        their arrays; build: the shapes added since the last query into the broadphase; merge: its
        trees merged into one) under the write lock, which then becomes a read lock with no writer
        between: inside, nothing changes the scene, and other readers may run."""
        lock = self._lock
        lock.acquire_read()
        if not self._fresh(build, merge):
            lock.release_read()
            lock.acquire_write()
            try:
                for g in self._group_list:
                    g._flush()
                if build:
                    self._build(workers)
                    if merge:
                        self._broadphase.merge(workers)
            except BaseException:
                lock.release_write()
                raise
            lock.downgrade()
        try:
            yield
        finally:
            lock.release_read()

    def _build(self, workers: int = 1):
        """The broadphase over every shape: the shapes added since the last query join it here,
        group by group (its trees grow; none is rebuilt for the shapes already in it)."""
        if self._broadphase is None:
            self._broadphase = _core._Broadphase()
            for g in self._group_list:
                g.indexed = 0
        bp = self._broadphase
        if len(bp) < len(self._names):
            fresh = [(number, g) for number, g in enumerate(self._group_list) if g.indexed < len(g)]
            bp.add([(g.rows_from(g.indexed), g.ids[g.indexed :], number, g.indexed) for number, g in fresh], workers)
            for _, g in fresh:
                g.indexed = len(g)
        return bp

    # ---- evaluation helpers ----------------------------------------------------------------
    def _check_kinds(self, kind: str, items: Iterable[int] | None = None) -> None:
        supported = _supported()
        for g in self._group_list:
            if (kind, g.kind) not in supported:
                raise TypeError(
                    f"circledist has no query between a {kind} and a {g.kind} " f"(the scene holds {g.kind} shapes)"
                )

    def _evaluate(self, shape, items: np.ndarray, fn, *args) -> np.ndarray:
        """fn(shape, batch_of_items, *args) for items grouped by kind; results in items' order."""
        group, row = self._broadphase.locate(items)
        parts = []
        for gnum in np.unique(group):
            sel = np.flatnonzero(group == gnum)
            g = self._group_list[gnum]
            parts.append((sel, np.asarray(fn(shape, g.batch(row[sel]), *args))))
        if not parts:
            return np.zeros(0)
        # Groups of different dtypes answer in different dtypes: the widest holds each exactly.
        out = np.empty(len(items), dtype=np.result_type(*(values for _, values in parts)))
        for sel, values in parts:
            out[sel] = values
        return out

    def _resolve(self, shape):
        """A query shape, or the name of a scene shape (which then is not its own answer)."""
        if isinstance(shape, str):
            i = self._lookup(shape)
            return self._single(i), {i}
        if not isinstance(shape, _core.Shape):
            shape = _core.Point(shape)
        if shape.batch_shape != ():
            raise ValueError(f"Scene queries take a single shape, got a batch of shape {shape.batch_shape}")
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
            When k is not an integer (a bool is not), or there is no query between `shape`'s
            kind and a kind in the scene.
        ValueError
            When k < 1 or k >= 2**63, or `shape` is a batch.

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
        k = _core._integer_argument("Scene.nearest", "k", k, "an integer >= 1")
        if k < 1:
            raise ValueError(f"Scene.nearest: k must be an integer >= 1, got {k}")
        with self._current():
            return self._nearest(shape, k, exclude)

    def _nearest(self, shape, k: int, exclude: Sequence[str]) -> list[tuple[str, float]]:
        shape, skip = self._resolve(shape)
        skip |= {self._lookup(n) for n in exclude}
        bp = self._broadphase
        self._check_kinds(shape.kind)
        n = len(self._names)
        available = n - len(skip)
        if available <= 0:
            return []
        k = min(k, available)
        skip_arr = np.fromiter(skip, np.int64, len(skip))
        known: dict[int, float] = {}

        # 1. An upper bound tau on the k-th distance: the exact distances of the few shapes of
        #    smallest lower bound (the broadphase's best-first search).
        seeds, _ = bp.nearest_by_bound(shape, k + 2 + len(skip))
        seeds = seeds[~np.isin(seeds, skip_arr)][: k + 2]
        if len(seeds):
            d = self._evaluate(shape, seeds, _core.distance)
            known.update(zip(seeds.tolist(), d.tolist()))
        tau = np.inf if len(known) < k else float(np.partition(np.fromiter(known.values(), float), k - 1)[k - 1])

        # 2. Every shape whose lower bound is within tau, nearest bound first, in chunks; each
        #    chunk only evaluates where its bounds cannot show the distance exceeds tau.
        items, bound = bp.within(shape, tau)
        fresh = ~np.isin(items, skip_arr) & ~np.isin(items, np.fromiter(known, np.int64, len(known)))
        items, bound = items[fresh], bound[fresh]
        order = np.argsort(bound, kind="stable")
        items, bound = items[order], bound[order]
        tested = len(known)
        chunk = max(16, 2 * k)
        at = 0
        while at < len(items):
            # Past a bound above every item's limit, none is left to test; before it, each item's
            # own limit (its pair's margin) decides.
            if np.isfinite(tau) and bound[at] > bp.limit(shape, tau):
                break
            part = items[at : at + chunk]
            if np.isfinite(tau):
                part = part[bound[at : at + chunk] <= bp.limit(shape, tau, part)]
                d = self._evaluate(shape, part, _core.distance_if_within, tau)
            else:
                d = self._evaluate(shape, part, _core.distance)
            tested += len(part)
            for i, v in zip(part.tolist(), d.tolist()):
                if np.isfinite(v):
                    known[i] = v
            if len(known) >= k:
                tau = float(np.partition(np.fromiter(known.values(), float), k - 1)[k - 1])
            at += chunk
            chunk = min(2 * chunk, 4096)
        best = sorted(known.items(), key=lambda kv: (kv[1], kv[0]))[:k]
        culled = available - tested
        _core._count_culled(max(culled, 0))
        self.last_stats = {"shapes": n, "tested": tested, "culled": culled}
        return [(self._names[i], d) for i, d in best]

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
            When d is negative, NaN or inf, or `shape` is a batch.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ball", cd.Point([[0, 0, 0], [2, 0, 0], [5, 0, 0]], sweep=0.5))
        >>> s.within(cd.Segment([0, 1, 0], [3, 1, 0]), 0.5)
        ['ball0', 'ball1']
        """
        d = _limit("Scene.within", d)
        with self._current():
            return self._within(shape, d)

    def _within(self, shape, d: float) -> list[str]:
        shape, skip = self._resolve(shape)
        bp = self._broadphase
        self._check_kinds(shape.kind)
        items, _ = bp.within(shape, d)
        items = items[~np.isin(items, np.fromiter(skip, np.int64, len(skip)))]
        hit = self._evaluate(shape, items, _core.within, d).astype(bool) if len(items) else np.zeros(0, bool)
        culled = len(self._names) - len(skip) - len(items)
        _core._count_culled(culled)
        self.last_stats = {"shapes": len(self._names), "tested": len(items), "culled": culled}
        return [self._names[i] for i in items[hit]]

    def pairs_within(self, d: float, *, workers: int = 1, max_pairs: int | None = 100_000_000) -> list[tuple[str, str]]:
        """Every pair of scene shapes within distance d of each other.

        Parameters
        ----------
        d : float
            Distance limit >= 0.
        workers : int, default 1
            Keyword only. Threads for the broadphase and the exact tests (SciPy's convention: -1
            for every core); the answer is the same for any count.
        max_pairs : int or None, default 100_000_000
            Keyword only. The most candidate pairs (pairs the culling keeps: within d of each
            other, or within the margin of it, by their bounds) the query holds; once more than
            max_pairs are counted, the search stops and MemoryError is raised, instead of memory
            running out on a d that pairs nearly everything. None: no limit.

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
            When d is negative, NaN or inf, or max_pairs negative.
        MemoryError
            When more than max_pairs pairs are candidates.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ball", cd.Point([[0, 0, 0], [2, 0, 0], [5, 0, 0]], sweep=0.5))
        >>> s.pairs_within(1.0)
        [('ball0', 'ball1')]
        """
        d = _limit("Scene.pairs_within", d)
        with self._current(workers, merge=True):
            return self._pairs_within(d, workers, max_pairs)

    def _pairs_within(self, d: float, workers, max_pairs) -> list[tuple[str, str]]:
        bp = self._broadphase
        supported = _supported()
        groups = self._group_list
        kinds = [g.kind for g in groups]
        for i, ka in enumerate(kinds):
            for kb in kinds[i:]:
                if ka == kb and len(groups[i]) < 2:
                    continue
                if (ka, kb) not in supported:
                    raise TypeError(f"circledist has no query between a {ka} and a {kb} (the scene holds both)")
        # Candidates, exact tests, their order (i, j) and the list of names, in C++ (on the workers
        # but the list).
        pairs, tested = bp.pairs_within([g.whole() for g in groups], self._names, d, workers, max_pairs)
        n = len(self._names)
        culled = n * (n - 1) // 2 - tested
        _core._count_culled(culled)
        self.last_stats = {"shapes": n, "tested": tested, "culled": culled}
        return pairs

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
        with self._current():
            return self._distance_matrix(a_names, b_names)

    def _distance_matrix(self, a_names: Sequence[str], b_names: Sequence[str]) -> np.ndarray:
        bp = self._broadphase
        ia = np.array([self._lookup(n) for n in a_names], dtype=np.int64)
        ib = np.array([self._lookup(n) for n in b_names], dtype=np.int64)
        (group_a, row_a), (group_b, row_b) = bp.locate(ia), bp.locate(ib)
        out = np.empty((len(ia), len(ib)))
        for ga in np.unique(group_a):
            ra = np.flatnonzero(group_a == ga)
            for gb in np.unique(group_b):
                rb = np.flatnonzero(group_b == gb)
                A, B = self._group_list[ga], self._group_list[gb]
                out[np.ix_(ra, rb)] = _core.distance(A.batch(row_a[ra], column=True), B.batch(row_b[rb]))
        return out


# The sweep of a shape given none: a zero, only to fill the group's sweep column.
_NO_SWEEP = np.zeros(())
_NO_SWEEP.flags.writeable = False


_SUPPORTED: set | None = None


def _supported() -> set:
    global _SUPPORTED
    if _SUPPORTED is None:
        _SUPPORTED = {tuple(p) for p in _core._query_kinds()}
    return _SUPPORTED
