"""Animated figures: ``circledist.figure(..., motions=...)``.

Shapes given a `Motion` are drawn at each time step over [0, 1] (``frames`` of them, both ends
included) and at each pair's first contact (`first_contact`), each time one plotly frame; a
frame holds only the moving shapes' traces and the moving pairs' closest points, so the shapes
at rest are drawn once. A slider steps through the times (the contact's step says so) and a
button plays them. The view's box holds the shapes at every time, so the view stands still while
they move. Drawing is view.py's (its parts, geometry and traces); this module picks the rows that
move, moves them (`Shape.moved`, every time in one call) and lays out the frames.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from . import _core
from ._scene_format import KINDS
from .view import (
    FRAMES,
    LEGEND_LIMIT,
    _PAIR_COLOR,
    _box,
    _closest,
    _draw,
    _hover,
    _laid_out,
    _options,
    _origin,
    _pair_traces,
    _Part,
    _rescaled,
    _rim,
    _scale,
    _shape_part,
    _xyz,
)

PLAY_MS = 80  # a frame's time on screen when playing
CONTACT_SNAP = 1e-9  # a time step this near a contact's time is the contact's frame


def frame_count(frames) -> int:
    """The time steps of an animation: frames, checked, or the default."""
    if frames is None:
        return FRAMES
    if isinstance(frames, bool) or not isinstance(frames, (int, np.integer)):
        raise TypeError(f"figure: frames must be an integer (time steps over [0, 1]), got {type(frames).__name__}")
    if frames < 2:
        raise ValueError(f"figure: frames must be at least 2 (time steps over [0, 1], both ends), got {frames!r}")
    return int(frames)


@dataclass
class _Mover:
    """Rows of one part that move by one motion: motion is a single one or a batch of one per row."""

    key: str
    part: int
    rows: np.ndarray
    motion: _core.Motion

    def row_motion(self, j: int) -> _core.Motion:
        """The motion of the j-th of the rows."""
        if self.motion.batch_shape == ():
            return self.motion
        return _core.Motion(**{k: v[j] for k, v in self.motion.to_arrays().items()})


def _flat_motion(key: str, motion: _core.Motion, batch: tuple) -> _core.Motion:
    """A motion for a batch's rows (C order): a single one as it is, a batch broadcast to the
    batch's shape and flattened."""
    if motion.batch_shape == ():
        return motion
    try:
        fits = np.broadcast_shapes(batch, motion.batch_shape) == batch
    except ValueError:
        fits = False
    if not fits:
        raise ValueError(
            f"figure: motions[{key!r}]: a batch of motions of shape {motion.batch_shape} does not broadcast to "
            f"the shapes' batch shape {batch}"
        )
    arrays = {k: np.broadcast_to(v, batch + (3,)).reshape(-1, 3) for k, v in motion.to_arrays().items()}
    return _core.Motion(**arrays)


def movers(parts: list, motions) -> list:
    """The motions given, checked and matched to the parts' rows: a name of a whole part (a
    mapping's key, a scene file's entry) moves all its rows, a shape's name its one row."""
    if motions is None:
        return []
    if not isinstance(motions, Mapping):
        raise TypeError(f"figure: motions must be a mapping of shape names to Motions, got {type(motions).__name__}")
    wholes = {p.label: i for i, p in enumerate(parts) if p.label is not None}
    rows = {n: (i, j) for i, p in enumerate(parts) for j, n in enumerate(p.names)}
    out, moved_by = [], {}
    for key, motion in motions.items():
        if not isinstance(key, str):
            raise TypeError(f"figure: motions: names must be strings, got {key!r}")
        if not isinstance(motion, _core.Motion):
            raise TypeError(f"figure: motions[{key!r}] must be a circledist Motion, got {type(motion).__name__}")
        if key in wholes:
            i = wholes[key]
            mover = _Mover(key, i, np.arange(len(parts[i])), _flat_motion(key, motion, parts[i].batch))
        elif key in rows:
            if motion.batch_shape != ():
                raise ValueError(
                    f"figure: motions[{key!r}] moves one shape: it takes a single Motion, got a batch of shape "
                    f"{motion.batch_shape}"
                )
            i, j = rows[key]
            mover = _Mover(key, i, np.array([j]), motion)
        else:
            raise ValueError(f"figure: motions: no shape named {key!r}")
        for j in mover.rows:
            name = parts[mover.part].names[j]
            if name in moved_by:
                raise ValueError(f"figure: motions: {name!r} is given two motions ({moved_by[name]!r} and {key!r})")
            moved_by[name] = key
        out.append(mover)
    return out


def _rows_of(part: _Part, rows) -> _Part:
    return _Part(part.kind, [part.names[i] for i in rows], [v[rows] for v in part.values], part.sweep[rows])


def _moved(part: _Part, mover: _Mover, times: np.ndarray) -> list:
    """The mover's rows at each time: a part per time (one call of Shape.moved for all)."""
    shape = getattr(_core, KINDS[part.kind][0])(*(v[mover.rows] for v in part.values), sweep=part.sweep[mover.rows])
    every = _shape_part("", shape.moved(mover.motion, times[:, None]))  # (times, rows), C order
    n = len(mover.rows)
    names = [part.names[j] for j in mover.rows]
    return [
        _Part(part.kind, names, [v[k * n : (k + 1) * n] for v in every.values], every.sweep[k * n : (k + 1) * n])
        for k in range(len(times))
    ]


@dataclass
class _MovingPair:
    """A pair with a moving shape: its first contact (time inf where none, and where) and its
    closest points at each time of the animation."""

    a: str
    b: str
    time: float
    point: np.ndarray
    distance: np.ndarray | None = None
    point_a: np.ndarray | None = None
    point_b: np.ndarray | None = None
    shapes: tuple = ()  # (shape a, its motion or None, shape b, its motion or None)


def _moving_pairs(named: list, movers: list, parts: list) -> tuple[list, list]:
    """(still, moving): the checked pairs with no moving shape, and the others with their first
    contacts."""
    motion_of = {parts[m.part].names[r]: (m, j) for m in movers for j, r in enumerate(m.rows)}
    still, moving = [], []
    for i, a, b, shape_a, shape_b in named:
        if a not in motion_of and b not in motion_of:
            still.append((i, a, b, shape_a, shape_b))
            continue
        motion_a, motion_b = (motion_of[n][0].row_motion(motion_of[n][1]) if n in motion_of else None for n in (a, b))
        try:
            c = _core.first_contact(shape_a, shape_b, motion_a, motion_b)
        except ValueError as error:  # a rotating line or ray: no speed bound
            raise ValueError(f"figure: pairs[{i}] ({a!r}, {b!r}): {error}") from None
        middle = (np.asarray(c.point_a, np.float64) + np.asarray(c.point_b, np.float64)) / 2
        moving.append(_MovingPair(a, b, float(c.time), middle, shapes=(shape_a, motion_a, shape_b, motion_b)))
    return still, moving


def _pair_frames(pair: _MovingPair, times: np.ndarray) -> None:
    """The pair's closest points at every time (one batched call)."""
    shape_a, motion_a, shape_b, motion_b = pair.shapes
    a = shape_a if motion_a is None else shape_a.moved(motion_a, times)
    b = shape_b if motion_b is None else shape_b.moved(motion_b, times)
    r = _core.closest_points(a, b)
    count = len(times)
    pair.distance = np.broadcast_to(np.asarray(r.distance, np.float64), (count,))
    pair.point_a = np.broadcast_to(np.asarray(r.point_a, np.float64), (count, 3))
    pair.point_b = np.broadcast_to(np.asarray(r.point_b, np.float64), (count, 3))


def _legend(pair: _MovingPair) -> str:
    if math.isfinite(pair.time):
        return f"{pair.a} \u2013 {pair.b}: first contact at t = {pair.time:.4g}"
    return f"{pair.a} \u2013 {pair.b}: no contact for t in [0, 1]"


def _pair_frame_traces(go, pair: _MovingPair, k: int, t: float, origin: np.ndarray) -> list:
    """The pair's closest points at the k-th time: a dashed segment and its distance's label."""
    p, q, d = pair.point_a[k], pair.point_b[k], float(pair.distance[k])
    line = f"{pair.a} \u2013 {pair.b}: distance {d:.6g} at t = {t:.4g}"
    label = f"{d:.3g}"
    if t == pair.time:  # touching: the distance is 0 to rounding, whose digits say nothing
        line, label = f"{pair.a} \u2013 {pair.b}: first contact at t = {t:.6g} (distance {d:.3g})", "contact"
    style = {"color": _PAIR_COLOR}
    common = {"name": _legend(pair), "legendgroup": _legend(pair)}
    return [
        go.Scatter3d(
            mode="lines+markers",
            line={**style, "width": 3, "dash": "dash"},
            marker={**style, "size": 3},
            **_xyz(np.array([p, q]), origin),
            **_hover([line, line], True),
            **common,
        ),
        go.Scatter3d(
            mode="text",
            text=[label],
            textfont=style,
            textposition="top center",
            showlegend=False,
            hoverinfo="skip",
            **_xyz(((p + q) / 2)[None], origin),
            **common,
        ),
    ]


def _contact_marker(go, pair: _MovingPair, origin: np.ndarray) -> list:
    """Where the pair first touches, drawn at every time."""
    if not math.isfinite(pair.time):
        return []
    text = f"{pair.a} \u2013 {pair.b}: first contact at t = {pair.time:.6g}"
    return [
        go.Scatter3d(
            mode="markers",
            marker={"color": _PAIR_COLOR, "size": 6, "symbol": "x"},
            **_xyz(pair.point[None], origin),
            **_hover([text], True),
            name=_legend(pair),
            legendgroup=_legend(pair),
            showlegend=False,
        )
    ]


def animated(go, parts: list, named: list, movers: list, steps: int, detail, box, title):
    """The figure with the movers animated over [0, 1] (figure's arguments, checked)."""
    still_pairs, moving = _moving_pairs(named, movers, parts)
    contacts = [p.time for p in moving if math.isfinite(p.time)]
    grid = np.linspace(0.0, 1.0, steps)
    # A step a rounding's width from a contact (first_contact's time meets a bar, not the digits
    # of a step such as 0.5) gives way to it: one frame, not two a hair apart.
    near = np.zeros(steps, bool)
    for t in contacts:
        near |= np.abs(grid - t) <= CONTACT_SNAP
    times = np.unique(np.concatenate([grid[~near], contacts]))
    for pair in moving:
        _pair_frames(pair, times)

    # The items to draw, in the parts' order: the rows at rest of each part, then its movers.
    moved_rows = {}
    for m in movers:
        moved_rows.setdefault(m.part, []).append(m)
    items = []  # (part at rest) or (list of parts, one per time)
    for i, part in enumerate(parts):
        rest = np.setdiff1d(np.arange(len(part)), [r for m in moved_rows.get(i, []) for r in m.rows])
        if len(rest):
            items.append(_rows_of(part, rest) if len(rest) < len(part) else part)
        items += [_moved(part, m, times) for m in moved_rows.get(i, [])]

    # One scale for every time, the view's box around the shapes at every time.
    closest = _closest(still_pairs)
    every = [(p.a, p.b, d, qa, qb) for p in moving for d, qa, qb in zip(p.distance, p.point_a, p.point_b)]
    every += [(p.a, p.b, 0.0, p.point, p.point) for p in moving if math.isfinite(p.time)]
    flat = [x for item in items for x in (item if isinstance(item, list) else [item])]
    scale = _scale(flat, closest + every)
    rescale = lambda ps: _rescaled(ps, [], scale)[0]  # noqa: E731
    items = [rescale(item) if isinstance(item, list) else rescale([item])[0] for item in items]
    closest = _rescaled([], closest, scale)[1]
    for pair in moving:
        pair.point_a, pair.point_b, pair.point = pair.point_a / scale, pair.point_b / scale, pair.point / scale
    every = _rescaled([], every, scale)[1]
    still = [item for item in items if not isinstance(item, list)]
    movings = [item for item in items if isinstance(item, list)]
    count = sum(len(p) for p in still) + sum(len(item[0]) for item in movings)
    drawn = sum(len(p) for p in still) + len(times) * sum(len(item[0]) for item in movings)
    rim = _rim(detail, drawn)
    lo, hi = _box(box, scale, still + [p for item in movings for p in item], closest + every)
    origin = _origin(lo, hi)
    options = _options(drawn, rim, origin)

    # The traces: those at rest once; the moving ones at t = 0, and again in each frame.
    per_shape = count <= LEGEND_LIMIT
    if per_shape:  # (moves, what to draw: parts, or per time the parts then)
        groups = [(True, [[p] for p in item]) if isinstance(item, list) else (False, [item]) for item in items]
    else:
        groups = [(False, still)] + ([(True, [list(at) for at in zip(*movings)])] if movings else [])
    data, changing, per_frame, k = [], [], [[] for _ in times], 0
    for moves, what in groups:
        if not moves:
            traces, k = _draw(go, what, rim, lo, hi, options, per_shape, k)
            data += traces
            continue
        k0 = k
        for f, parts_then in enumerate(what):
            traces, k = _draw(go, parts_then, rim, lo, hi, options, per_shape, k0, "" if per_shape else " (moving)")
            per_frame[f] += traces
            if f == 0:
                changing += range(len(data), len(data) + len(traces))
                data += traces
    data += _pair_traces(go, closest, origin)
    for pair in moving:
        data += _contact_marker(go, pair, origin)
        for f, t in enumerate(times):
            traces = _pair_frame_traces(go, pair, f, t, origin)
            per_frame[f] += traces
            if f == 0:
                changing += range(len(data), len(data) + len(traces))
                data += traces

    fig = _laid_out(go, data, title, lo, hi, origin, scale, bottom=70)
    names = [repr(float(t)) for t in times]
    fig.frames = [go.Frame(name=n, data=d, traces=changing) for n, d in zip(names, per_frame)]
    contact_times = set(contacts)
    still_step = {"mode": "immediate", "frame": {"duration": 0, "redraw": True}, "transition": {"duration": 0}}
    steps_ = [
        {
            "method": "animate",
            "label": f"{t:.3g} contact" if t in contact_times else f"{t:.3g}",
            "args": [[n], still_step],
        }
        for n, t in zip(names, times)
    ]
    play = {"frame": {"duration": PLAY_MS, "redraw": True}, "fromcurrent": True, "transition": {"duration": 0}}
    fig.update_layout(
        sliders=[
            {
                "active": 0,
                "steps": steps_,
                # The steps' own labels would overlap (dozens of them): the current one is shown.
                "font": {"color": "rgba(0, 0, 0, 0)"},
                "currentvalue": {"prefix": "t = ", "font": {"color": "#444", "size": 14}},
                "x": 0.12,
                "len": 0.86,
                "pad": {"t": 10},
            }
        ],
        updatemenus=[
            {
                "type": "buttons",
                "showactive": False,
                "x": 0.0,
                "y": 0.0,
                "xanchor": "left",
                "yanchor": "top",
                "pad": {"t": 10},
                "direction": "left",
                "buttons": [
                    {"label": "\u25b6", "method": "animate", "args": [None, play]},
                    {"label": "\u275a\u275a", "method": "animate", "args": [[None], still_step]},
                ],
            }
        ],
    )
    return fig
