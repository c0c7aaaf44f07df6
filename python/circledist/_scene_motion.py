"""Scene.first_contact: which of a scene's (static) shapes a moving shape reaches first, and when.

The motion's sweep is bounded by a volume the scene's broadphase can query (the culling of
``Scene.within``), so that ``circledist.first_contact`` runs only on the shapes that volume comes
within ``within`` of. docs/derivations/motion.md gives the motion, the reach and the bar.

- A rotating shape: every point x stays at |x(t) - (c + t T)| = |x - c| <= reach(shape, c) from
  the moving center (the rotation keeps |R (x - c)| = |x - c|), so the whole motion lies in the
  capsule of radius reach about the segment [c, c + T]. Where the shape is small beside its
  distance from the axis (a ball (m, rho) holding it, rho + |T| / 2 < reach), the torus about
  the circle m turns on, moved by T / 2, of tube radius rho + |T| / 2, is taken instead.
- A translating shape (no rotation): its point x(t) = x + t T is within |T| / 2 of x + T / 2, so
  the motion lies in the shape moved by T / 2 with |T| / 2 added to its sweep (lines and rays
  too); for a bounded shape whose travel exceeds its size, the capsule of radius rho about
  [m, m + T] (m, rho: a ball holding the shape) is the smaller volume and is taken instead.

A candidate is kept when ``circledist.within(volume, shape, within)`` holds: a shape the motion
reaches within ``within`` is within ``within`` of the volume, which holds the moving shape at every
time. The volume is padded by far more than the rounding of its reach and of the contact bar
(1e-12 of the query's size), so that a contact brute force reports is never culled.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from . import _core

# The pad of the culling volume, relative to the query's size: the contact bar is 1e-12 of it.
_PAD = 1e-9


class SceneContact(NamedTuple):
    """One answer of `Scene.first_contact`: a scene shape the moving shape reaches, and when.

    Attributes
    ----------
    name : str
        The scene shape's name.
    time : float
        The earliest time in [0, 1] at which the moving shape is within ``within`` of it.
    distance : float
        Their distance at that time.
    point_a, point_b : numpy.ndarray, shape (3,)
        A closest pair at that time: on the moving shape (at that time), on the scene shape.
    param_a, param_b : numpy.ndarray, shape (2,)
        Their parameters (as `circledist.closest_points` gives them).
    unique : bool
        `circledist.closest_points`' ``unique`` at that time.
    """

    name: str
    time: float
    distance: float
    point_a: np.ndarray
    point_b: np.ndarray
    param_a: np.ndarray
    param_b: np.ndarray
    unique: bool


def _float64_fields(shape) -> dict:
    return {name: np.asarray(value, dtype=np.float64) for name, value in shape.to_arrays().items()}


def _rim_reach(center, normal, radius, c) -> float:
    """The farthest point of the circle (center, normal, radius) from c (motion.md, the reach)."""
    n = normal / np.linalg.norm(normal)
    v = center - c
    h = float(np.dot(n, v))
    q = float(np.linalg.norm(v - h * n))
    return float(np.hypot(h, q + radius))


def reach(shape, c) -> float:
    """An upper bound of |x - c| over the points x of a single shape (motion.md: exact for points,
    segments, circles, disks and annuli, a bound for arcs and curves; inf for lines and rays),
    in float64, sweep included."""
    f = _float64_fields(shape)
    c = np.asarray(c, dtype=np.float64)
    kind = shape.kind
    if kind in ("Line", "Ray"):
        return np.inf
    if kind == "Point":
        core = float(np.linalg.norm(f["p"] - c))
    elif kind == "Segment":
        core = max(float(np.linalg.norm(f["p0"] - c)), float(np.linalg.norm(f["p1"] - c)))
    elif kind == "Bezier":
        core = float(np.linalg.norm(f["control_points"] - c, axis=-1).max())
    elif kind == "Annulus":
        core = _rim_reach(f["center"], f["normal"], float(f["outer_radius"]), c)
    else:  # Circle, Disk, Arc (an arc lies on its circle)
        core = _rim_reach(f["center"], f["normal"], float(f["radius"]), c)
    return core + float(f.get("sweep", 0.0))


def _anchor(shape) -> np.ndarray:
    """A point near the middle of a bounded shape (the center its ball is taken about)."""
    f = _float64_fields(shape)
    kind = shape.kind
    if kind == "Point":
        return f["p"]
    if kind == "Segment":
        return 0.5 * (f["p0"] + f["p1"])
    if kind == "Bezier":
        points = f["control_points"]
        return 0.5 * (points.min(axis=0) + points.max(axis=0))
    return f["center"]


def _size(shape) -> float:
    """The largest coordinate or length of a shape's fields (directions included: harmless)."""
    return max(float(np.max(np.abs(v))) for v in _float64_fields(shape).values())


def _with_sweep(shape, extra: float):
    """The shape with `extra` added to its sweep."""
    arrays = dict(shape.to_arrays())
    sweep = _core._sweep_field()[0]
    arrays[sweep] = np.float64(arrays.get(sweep, 0.0)) + extra
    return type(shape).from_arrays(arrays)


def _capsule(start, travel, radius: float):
    """The points within radius of the segment [start, start + travel] (a ball where travel = 0)."""
    if not np.any(travel):
        return _core.Point(start, sweep=radius)
    return _core.Segment(start, start + travel, sweep=radius)


def sweep_volume(shape, motion, scale: float):
    """A single shape holding the moving shape at every time of the motion (module docstring),
    padded by _PAD of the query's size (at least `scale`, the scene's)."""
    m = {name: np.asarray(v, dtype=np.float64) for name, v in motion.to_arrays().items()}
    T, w, c = m["translation"], m["rotation"], m["center"]
    travel = float(np.linalg.norm(T))
    if np.any(w):
        r = reach(shape, c)
        size = max(scale, _size(shape), float(np.abs(c).max()) + r + travel)
        # The ball (m, rho) holding the shape turns about the axis: its center stays on a circle
        # about the axis, which the translation carries within |T| / 2 of its place at t = 1/2.
        m_ = _anchor(shape)
        rho = reach(shape, m_)
        tube = rho + 0.5 * travel
        if tube < r:
            n = w / np.linalg.norm(w)
            v = m_ - c
            h = float(np.dot(v, n))
            center = c + h * n + 0.5 * T
            radius = float(np.linalg.norm(v - h * n))
            if radius > 0:
                return _core.Circle(center, n, radius, sweep=tube + _PAD * size)
            return _core.Point(center, sweep=tube + _PAD * size)
        return _capsule(c, T, r + _PAD * size)
    size = max(scale, _size(shape), float(np.abs(T).max()))
    if shape.kind not in ("Line", "Ray"):
        m_ = _anchor(shape)
        rho = reach(shape, m_)
        if travel > 2 * rho:
            return _capsule(m_, T, rho + _PAD * (size + travel))
    half = _core.Motion(translation=T)
    return _with_sweep(shape.moved(half, 0.5), 0.5 * travel + _PAD * (size + travel))


class MotionQueries:
    """Scene's queries of moving shapes (a base class of Scene: scene.py stays within its size)."""

    def first_contact(self, shape, motion=None, within: float = 0.0, k: int = 1) -> list:
        """The k scene shapes a moving shape reaches first, and when.

        With ``a(t) = shape.moved(motion, t)``, `circledist.first_contact` of the moving shape
        and each (static) scene shape: the earliest time in [0, 1] at which they are within
        `within` of each other. Only the shapes within `within` of a volume that holds the whole
        motion (a capsule about the motion's path; for a translation, the shape swept along it)
        are evaluated, in one batched call per kind; every answer is the one brute force gives.

        Parameters
        ----------
        shape : Shape, array_like or str
            A single shape, a point as an array of shape (3,), or the name of a scene shape
            (which is then left out of its own answer and moves from where it is).
        motion : Motion or None
            A single motion of `shape` over [0, 1]; None is at rest. A line or ray cannot
            rotate (no speed bound exists for its points).
        within : float, default 0
            The contact distance, finite and >= 0.
        k : int, default 1
            How many contacts to return, earliest first (fewer where fewer shapes are reached).

        Returns
        -------
        list of SceneContact
            (name, time, distance, point_a, point_b, param_a, param_b, unique) of the shapes
            reached, sorted by time, then by insertion order; empty where none is reached.
            ``point_a`` lies on the moving shape at that time.

        Raises
        ------
        KeyError
            When `shape` is a name not in the scene.
        TypeError
            When `motion` is neither a Motion nor None, or k is not an integer.
        ValueError
            When `within` is negative, NaN or inf, k < 1, `shape` or `motion` is a batch, or a
            line or ray is given a rotating motion.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene()
        >>> s.extend("ring", cd.Circle([[0, 0, 0], [4, 0, 0]], [0, 0, 1], 1.0))
        >>> hits = s.first_contact(cd.Point([-3, 0, 0]), cd.Motion(translation=[10, 0, 0]), k=2)
        >>> [(h.name, round(h.time, 12)) for h in hits]
        [('ring0', 0.2), ('ring1', 0.6)]
        """
        owner = "Scene.first_contact"
        k = _core._integer_argument(owner, "k", k, "an integer >= 1")
        if k < 1:
            raise ValueError(f"{owner}: k must be an integer >= 1, got {k}")
        try:  # the library's reader of distance limits, which calls its argument d
            within = _core._distance_limit(owner, within)
        except (TypeError, ValueError) as error:
            raise type(error)(str(error).replace(f"{owner}: d ", f"{owner}: within ", 1)) from None
        if motion is None:
            motion = _core.Motion()
        if not isinstance(motion, _core.Motion):
            raise TypeError(f"{owner}: motion must be a circledist.Motion or None, got {type(motion).__name__}")
        if motion.batch_shape != ():
            raise ValueError(f"{owner}: motion must be a single motion, got a batch of shape {motion.batch_shape}")
        with self._current():
            return self._first_contact(shape, motion, within, k)

    def _first_contact(self, shape, motion, within: float, k: int) -> list:
        shape, skip = self._resolve(shape)
        if shape.kind in ("Line", "Ray") and np.any(motion.rotation != 0):
            raise ValueError(
                f"Scene.first_contact: motion rotates the shape, a {shape.kind}: a line or ray "
                "cannot rotate (its points reach infinitely far from the motion's center, so no "
                "speed bound exists); give it a motion without rotation"
            )
        bp = self._broadphase
        self._check_kinds(shape.kind)
        n = len(self._names)
        if n == 0:
            self.last_stats = {"shapes": 0, "tested": 0, "culled": 0}
            return []
        volume = sweep_volume(shape, motion, bp.scale)
        items, _ = bp.within(volume, within)
        items = items[~np.isin(items, np.fromiter(skip, np.int64, len(skip)))]
        if len(items):
            near = self._evaluate(volume, items, _core.within, within).astype(bool)
            items = items[near]
        culled = n - len(skip) - len(items)
        _core._count_culled(culled)
        self.last_stats = {"shapes": n, "tested": len(items), "culled": culled}
        if not len(items):
            return []
        # One batched call per group of the candidates; the contacts in the items' order.
        group, row = bp.locate(items)
        times = np.full(len(items), np.inf)
        parts = []
        for gnum in np.unique(group):
            sel = np.flatnonzero(group == gnum)
            contact = _core.first_contact(shape, self._group_list[gnum].batch(row[sel]), motion, None, within=within)
            times[sel] = np.asarray(contact.time, dtype=np.float64)
            parts.append((sel, contact))
        reached = np.flatnonzero(np.isfinite(times))
        order = reached[np.lexsort((items[reached], times[reached]))][:k]
        where = np.empty(len(items), np.int64)  # candidate -> its place in its group's call
        owner = np.empty(len(items), np.int64)
        for p, (sel, _) in enumerate(parts):
            where[sel] = np.arange(len(sel))
            owner[sel] = p
        out = []
        for j in order:
            c = parts[owner[j]][1]
            at = where[j]
            out.append(
                SceneContact(
                    self._names[items[j]],
                    c.time[at].item(),
                    c.distance[at].item(),
                    np.array(c.point_a[at]),
                    np.array(c.point_b[at]),
                    np.array(c.param_a[at]),
                    np.array(c.param_b[at]),
                    bool(c.unique[at]),
                )
            )
        return out
