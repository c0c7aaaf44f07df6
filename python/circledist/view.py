"""Interactive 3-D pictures (plotly): ``circledist.figure`` and ``Scene.figure``.

plotly is an optional extra (``pip install 'circledist[view]'``): this module imports it only when
a figure is made, so ``import circledist`` never does, and without it `figure` raises an
ImportError that names what to install.

A figure is built in three steps: the shapes to draw become *parts* (one kind, rows of field
values, a name per row), whatever they came from (a shape or batch, a mapping of names to shapes,
a Scene, a scene file); each part's geometry is computed for all its rows at once (rims, faces,
tubes, as NumPy arrays); the rows are then drawn as a few traces: one per shape in a small scene
(each with its own colour and legend entry), one per kind and role (rim, face, sweep) in a large
one, with the shapes' polylines joined by gaps. One trace per shape does not scale to large
batches: a browser spends its time per trace, not per vertex.

Reduced detail (the rule; ``python -m bench.bench_view`` measures what it costs): a browser's
time grows with the vertices, so the outlines of n shapes share ``VERTEX_BUDGET`` of them: a rim
has ``VERTEX_BUDGET / n - 2`` points (a closed rim repeats its first, a gap follows), at most
``MAX_RIM``; where that is fewer than ``MIN_RIM`` each shape is one marker on it instead. Above
``FULL_LIMIT`` shapes only outlines are drawn (no faces, no sweeps: the legend says so) and the
names are carried by one marker per shape instead of by every vertex. Coordinates are sent as
float32, the precision WebGL draws them in.

Shapes given motions are animated by _view_motion.py, which draws each time with these parts,
geometry and traces (the moving shapes count once per frame in the rule above).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Mapping, Sequence

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._batch import TRAILING_DIMS
from ._cli_present import _PLAIN_LENGTHS, _scaled
from ._scene_format import KINDS, SceneFile, _SWEEP
from .scene import Scene

if TYPE_CHECKING:  # the annotation only: plotly is imported when a figure is made
    import plotly.graph_objects

__all__ = ["figure"]

VERTEX_BUDGET = 250_000  # outline vertices of the whole figure, shared among its shapes
MIN_RIM, MAX_RIM = 8, 64  # points on one closed rim (a circle's; arcs and curves as many)
FULL_LIMIT = 2_000  # up to this many shapes: faces, sweeps, every vertex named
LEGEND_LIMIT = 40  # up to this many shapes, one trace (colour, legend entry) per shape
FRAMES = 41  # time steps of an animation over [0, 1] (steps of 0.025)
TUBE_SIDES = 10  # points around a tube's cross-section
PADDING = 0.15  # the view's margin around the shapes, a fraction of its half-width

_INSTALL = "circledist.figure needs plotly: pip install 'circledist[view]' (or pip install plotly)"
_PAIR_COLOR = "crimson"


def _plotly():
    """plotly.graph_objects, or an ImportError saying what to install."""
    try:
        import plotly.graph_objects as go
    except ImportError as error:
        raise ImportError(_INSTALL) from error
    return go


# ------------------------------------------------------------------------------------------
# the shapes to draw, whatever they came from
# ------------------------------------------------------------------------------------------
@dataclass
class _Part:
    """Shapes of one kind (scene-file kind names: 'circle', ...): values holds one float64 array
    per field in the kind's order, each with a leading axis of one row per shape; sweep one
    number per shape."""

    kind: str
    names: list
    values: list
    sweep: np.ndarray
    label: str | None = None  # the input's name for all the rows (a batch's), if it has one
    batch: tuple = ()  # the batch shape the rows came from (C order), where label is set

    def __len__(self) -> int:
        return len(self.names)


def _shape_part(name: str, shape) -> _Part:
    """A shape or batch as a part: a batch's shapes are named name[i] (C order)."""
    kind = shape.kind.lower()
    fields = list(KINDS[kind][1])
    arrays = shape.to_arrays()
    batch = tuple(shape.batch_shape)
    count = int(np.prod(batch, dtype=np.int64))
    values = []
    for field in fields + [_SWEEP]:
        a = np.asarray(arrays.get(field, 0.0), dtype=np.float64)
        trailing = a.shape[a.ndim - TRAILING_DIMS[field] :] if TRAILING_DIMS[field] else ()
        values.append(np.broadcast_to(a, batch + trailing).reshape((count,) + trailing))
    names = [name] if batch == () else [f"{name}[{i}]" for i in range(count)]
    return _Part(kind, names, values[:-1], values[-1], name, batch)


def _parts_of(shapes) -> tuple[list, object, list, dict]:
    """(parts, resolve, pairs, motions): the parts to draw; resolve(name) the single shape named so
    (for closest points); the scene file's pairs (its queries that name two shapes) and motions
    (the shapes its queries move, each by the first query that moves it), else [] and {}."""
    if isinstance(shapes, _core.Shape):
        shapes = {shapes.kind.lower(): shapes}
    if isinstance(shapes, SceneFile):
        parts = []
        for e in shapes.entries:
            fields = list(KINDS[e.kind][1])
            rows = 1 if e.count is None else e.count
            values = [
                np.asarray(e.fields[f], np.float64).reshape((rows,) + np.shape(e.fields[f])[e.count is not None :])
                for f in fields + [_SWEEP]
            ]
            batch = () if e.count is None else (rows,)
            parts.append(_Part(e.kind, e.element_names(), values[:-1], values[-1].reshape(rows), e.name, batch))
        pairs = [(q["a"], q["b"]) for q in shapes.queries if q.get("b") is not None]
        motions = {}
        for q in shapes.queries:
            for key, name in (("motion", q["a"]), ("motion_b", q.get("b"))):
                if q.get(key) is not None:
                    motions.setdefault(name, q[key])
        return parts, shapes.shape, list(dict.fromkeys(pairs)), motions
    if isinstance(shapes, Scene):
        return _scene_parts(shapes), shapes.shape, [], {}
    if isinstance(shapes, Mapping):
        parts = []
        for name, shape in shapes.items():
            if not isinstance(name, str):
                raise TypeError(f"figure: shapes: names must be strings, got {name!r}")
            if not isinstance(shape, _core.Shape):
                raise TypeError(f"figure: shapes[{name!r}] must be a circledist shape, got {type(shape).__name__}")
            parts.append(_shape_part(name, shape))
        index = {n: (p, i) for p in parts for i, n in enumerate(p.names)}

        def resolve(name):
            part, i = index[name]
            cls = getattr(_core, KINDS[part.kind][0])
            return cls(*(v[i] for v in part.values), sweep=part.sweep[i])

        return parts, resolve, [], {}
    raise TypeError(
        "figure: shapes must be a circledist shape, a mapping of names to shapes, a Scene or a scene file "
        f"(read_scene), got {type(shapes).__name__}"
    )


def _scene_parts(scene) -> list:
    """A Scene's shapes as parts, one per stored group, named as in the scene."""
    parts = []
    with scene._current(build=False):
        names = scene._names
        for g in scene._group_list:
            if not len(g):
                continue
            fields = [np.asarray(f, np.float64) for f in g.fields]
            parts.append(_Part(g.kind.lower(), [names[i] for i in g.ids], fields[:-1], fields[-1]))
    return parts


# ------------------------------------------------------------------------------------------
# geometry, every row of a part at once
# ------------------------------------------------------------------------------------------
def _unit_rows(v) -> np.ndarray:
    """Each row v / |v|, scaled by its largest component first (no overflow or underflow)."""
    v = np.asarray(v, np.float64)
    v = v / np.abs(v).max(axis=-1, keepdims=True)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _plane_frames(normal, start=None):
    """(u, v) spanning each row's plane, n = u x v; u is start projected onto the plane if given."""
    n = _unit_rows(normal)
    if start is None:
        helper = np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
        u = _unit_rows(np.cross(n, helper))
    else:
        s = _unit_rows(start)
        u = _unit_rows(s - np.sum(s * n, axis=1, keepdims=True) * n)
    return u, np.cross(n, u)


def _ring(center, normal, radius, angles, start=None) -> np.ndarray:
    """Points at angles (rows x count, or count) around each row's circle: (rows, count, 3)."""
    u, v = _plane_frames(normal, start)
    angles = np.broadcast_to(angles, (len(u),) + np.shape(angles)[-1:])
    r = np.asarray(radius, np.float64)[:, None, None]
    return center[:, None, :] + r * (
        np.cos(angles)[..., None] * u[:, None, :] + np.sin(angles)[..., None] * v[:, None, :]
    )


def _bezier(control, count: int) -> np.ndarray:
    """Each row's curve at count parameters (de Casteljau): (rows, count, 3)."""
    t = np.linspace(0.0, 1.0, count)[None, :, None, None]
    q = np.broadcast_to(control[:, None], (len(control), count) + control.shape[1:])
    for k in range(control.shape[1] - 1, 0, -1):
        q = (1 - t) * q[:, :, :k] + t * q[:, :, 1 : k + 1]
    return q[:, :, 0]


def _clip(origin, direction, lo, hi, ray: bool) -> np.ndarray:
    """The part of each line (or ray) inside the box [lo, hi]: (rows, 2, 3), NaN where none."""
    d = _unit_rows(direction)
    t0 = np.full(len(d), 0.0 if ray else -np.inf)
    t1 = np.full(len(d), np.inf)
    missed = np.zeros(len(d), bool)  # parallel to a slab, outside it
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(3):
            a, b = (lo[i] - origin[:, i]) / d[:, i], (hi[i] - origin[:, i]) / d[:, i]
            flat = d[:, i] == 0
            missed |= flat & ~((lo[i] <= origin[:, i]) & (origin[:, i] <= hi[i]))
            a, b = np.where(flat, -np.inf, a), np.where(flat, np.inf, b)
            t0, t1 = np.maximum(t0, np.minimum(a, b)), np.minimum(t1, np.maximum(a, b))
    seg = origin[:, None, :] + np.stack([t0, t1], axis=1)[..., None] * d[:, None, :]
    seg[missed | ~(t0 <= t1)] = np.nan
    return seg


@dataclass
class _Geometry:
    """A part's drawing: curves (each (rows, points, 3)), the open ones' end points (for the
    sweep's caps), the face's triangles (vertices (rows, m, 3), triangles (t, 3) of one row's)."""

    curves: list
    ends: list
    face: tuple | None = None
    points: np.ndarray | None = None  # the kind point: (rows, 3)


def _geometry(part: _Part, rim: int, lo, hi) -> _Geometry:
    v, kind = part.values, part.kind
    full = np.linspace(0.0, 2 * np.pi, rim + 1)
    if kind == "point":
        return _Geometry([], [v[0]], points=v[0])
    if kind in ("line", "ray"):
        seg = _clip(v[0], v[1], lo, hi, kind == "ray")
        return _Geometry([seg], [v[0]] if kind == "ray" else [])
    if kind == "segment":
        return _Geometry([np.stack([v[0], v[1]], axis=1)], [v[0], v[1]])
    if kind == "bezier":
        return _Geometry([_bezier(v[0], rim + 1)], [v[0][:, 0], v[0][:, -1]])
    if kind == "arc":
        angles = np.linspace(0.0, 1.0, rim + 1)[None, :] * v[4][:, None]
        curve = _ring(v[0], v[1], v[2], angles, start=v[3])
        return _Geometry([curve], [curve[:, 0], curve[:, -1]])
    if kind in ("circle", "disk"):
        ring = _ring(v[0], v[1], v[2], full)
        if kind == "circle":
            return _Geometry([ring], [])
        vertices = np.concatenate([v[0][:, None, :], ring[:, :-1]], axis=1)  # centre, then the rim
        j = np.arange(1, rim + 1)
        triangles = np.stack([np.zeros(rim, int), j, j % rim + 1], axis=1)
        return _Geometry([ring], [], face=(vertices, triangles))
    if kind == "annulus":
        outer, inner = _ring(v[0], v[1], v[3], full), _ring(v[0], v[1], v[2], full)
        vertices = np.concatenate([outer[:, :-1], inner[:, :-1]], axis=1)
        j = np.arange(rim)
        k = (j + 1) % rim
        triangles = np.concatenate([np.stack([j, k, rim + j], 1), np.stack([k, rim + k, rim + j], 1)])
        return _Geometry([outer, inner], [], face=(vertices, triangles))
    raise ValueError(f"figure: no drawing for the kind {kind!r}")  # pragma: no cover (every kind is drawn)


def _tube(curve: np.ndarray, radius: np.ndarray, sides: int):
    """A tube of the radius around each row's polyline, its frames carried along the curve without
    twist (parallel transport): vertices (rows, points * sides, 3) and one row's triangles."""
    rows, m, _ = curve.shape
    tangent = np.gradient(curve, axis=1) if m > 2 else np.repeat(curve[:, 1:] - curve[:, :1], m, axis=1)
    tangent = np.nan_to_num(tangent)
    tangent[np.abs(tangent).max(axis=2) == 0] = [0.0, 0.0, 1.0]
    tangent = _unit_rows(tangent)
    normal = np.empty_like(tangent)
    normal[:, 0] = _plane_frames(tangent[:, 0])[0]
    for i in range(1, m):
        carried = normal[:, i - 1] - np.sum(normal[:, i - 1] * tangent[:, i], axis=1, keepdims=True) * tangent[:, i]
        bad = np.linalg.norm(carried, axis=1) < 1e-12
        carried[bad] = _plane_frames(tangent[bad, i])[0] if bad.any() else carried[bad]
        normal[:, i] = _unit_rows(carried)
    binormal = np.cross(tangent, normal)
    phi = np.linspace(0.0, 2 * np.pi, sides, endpoint=False)
    offset = (
        np.cos(phi)[None, None, :, None] * normal[:, :, None] + np.sin(phi)[None, None, :, None] * binormal[:, :, None]
    )
    vertices = curve[:, :, None, :] + radius[:, None, None, None] * offset
    i, s = np.meshgrid(np.arange(m - 1), np.arange(sides), indexing="ij")
    a, b = i * sides + s, i * sides + (s + 1) % sides
    c, d = a + sides, b + sides
    triangles = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([b, d, c], -1).reshape(-1, 3)])
    return vertices.reshape(rows, m * sides, 3), triangles


def _sphere(center: np.ndarray, radius: np.ndarray, sides: int):
    """A sphere around each row's point (circles of latitude, pole to pole): vertices (rows, v, 3)
    and one row's triangles."""
    theta = np.linspace(0.0, np.pi, sides // 2 + 1)
    phi = np.linspace(0.0, 2 * np.pi, sides, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    unit = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1).reshape(-1, 3)
    vertices = center[:, None, :] + radius[:, None, None] * unit[None]
    i, s = np.meshgrid(np.arange(len(theta) - 1), np.arange(sides), indexing="ij")
    a, b = i * sides + s, i * sides + (s + 1) % sides
    triangles = np.concatenate(
        [np.stack([a, b, a + sides], -1).reshape(-1, 3), np.stack([b, b + sides, a + sides], -1).reshape(-1, 3)]
    )
    return vertices, triangles


def _extent(part: _Part) -> np.ndarray:
    """Points that bound each row's shape (sweep aside): (rows, k, 3); a line's or ray's origin."""
    v, kind = part.values, part.kind
    if kind in ("point", "line", "ray"):
        return v[0][:, None, :]
    if kind == "segment":
        return np.stack([v[0], v[1]], axis=1)
    if kind == "bezier":
        return v[0]  # the control points: their hull holds the curve
    if kind == "arc":
        return _ring(v[0], v[1], v[2], np.linspace(0.0, 1.0, 17)[None, :] * v[4][:, None], start=v[3])
    radius = v[3] if kind == "annulus" else v[2]
    # The box of a circle of radius r and unit normal n: centre +- r sqrt(1 - n_i^2) on axis i.
    n = _unit_rows(v[1])
    half = radius[:, None] * np.sqrt(np.clip(1.0 - n * n, 0.0, 1.0))
    return np.stack([v[0] - half, v[0] + half], axis=1)


def _view_box(parts: list, closest: list):
    """The cube the view shows: every bounded shape with its sweep, the lines' origins and the
    closest points, with a margin."""
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for part in parts:
        pts = _extent(part)
        pad = part.sweep[:, None, None]
        with np.errstate(invalid="ignore"):
            low, high = np.where(np.isfinite(pts), pts - pad, np.inf), np.where(np.isfinite(pts), pts + pad, -np.inf)
        lo, hi = np.minimum(lo, low.min(axis=(0, 1))), np.maximum(hi, high.max(axis=(0, 1)))
    for _, _, _, p_a, p_b in closest:
        for p in (p_a, p_b):
            if np.isfinite(p).all():
                lo, hi = np.minimum(lo, p), np.maximum(hi, p)
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        lo, hi = np.zeros(3), np.zeros(3)
    mid, half = (lo + hi) / 2, max(float((hi - lo).max()) / 2, 1e-9) * (1 + PADDING)
    return mid - half, mid + half


def _merged(parts: list) -> list:
    """Parts of one kind (and field shapes: Bezier curves of one control point count) as one."""
    groups: dict = {}
    for p in parts:
        groups.setdefault((p.kind,) + tuple(v.shape[1:] for v in p.values), []).append(p)
    out = []
    for same in groups.values():
        if len(same) == 1:
            out.append(same[0])
            continue
        out.append(
            _Part(
                same[0].kind,
                [n for p in same for n in p.names],
                [np.concatenate([p.values[i] for p in same]) for i in range(len(same[0].values))],
                np.concatenate([p.sweep for p in same]),
            )
        )
    return out


def _polylines(curves: list, names: list):
    """The rows' curves as one polyline with gaps (NaN rows) between them, and each vertex's name."""
    xyz, text = [], []
    for curve in curves:
        rows, m, _ = curve.shape
        padded = np.concatenate([curve, np.full((rows, 1, 3), np.nan)], axis=1).reshape(-1, 3)
        xyz.append(padded)
        text.append(np.repeat(np.asarray(names, dtype=object), m + 1))
    return np.concatenate(xyz), np.concatenate(text)


def _meshes(pieces: list, names: list):
    """Meshes (vertices (rows, v, 3), one row's triangles) of the rows as one: vertices, triangles
    and each vertex's name."""
    xyz, ijk, text, offset = [], [], [], 0
    for vertices, triangles in pieces:
        drawn = np.isfinite(vertices).all(axis=(1, 2))  # a line that misses the box has no tube
        vertices, names_drawn = vertices[drawn], [n for n, keep in zip(names, drawn) if keep]
        rows, count, _ = vertices.shape
        xyz.append(vertices.reshape(-1, 3))
        ijk.append((triangles[None] + (offset + count * np.arange(rows))[:, None, None]).reshape(-1, 3))
        text.append(np.repeat(np.asarray(names_drawn, dtype=object), count))
        offset += rows * count
    return np.concatenate(xyz), np.concatenate(ijk).astype(np.int32), np.concatenate(text)


def _sweep_pieces(part: _Part, geometry: _Geometry, rows: np.ndarray, sides: int) -> list:
    """The surfaces of the rows' sweeps: tubes around their curves, balls at the open ends and
    at points, a filled kind's face moved by the sweep to either side."""
    r = part.sweep[rows]
    pieces = [_tube(c[rows], r, sides) for c in geometry.curves]
    pieces += [_sphere(end[rows], r, sides) for end in geometry.ends]
    if geometry.face is not None:
        vertices, triangles = geometry.face
        n = _unit_rows(part.values[1][rows])[:, None, :] * r[:, None, None]
        pieces += [(vertices[rows] + n, triangles), (vertices[rows] - n, triangles)]
    return pieces


def _xyz(points: np.ndarray, origin: np.ndarray) -> dict:
    """Coordinates for the browser: from the view's origin (the far-translated scenes' digits
    kept), as float32, WebGL's precision (half the page of float64)."""
    points = (points - origin).astype(np.float32)
    return {"x": points[:, 0], "y": points[:, 1], "z": points[:, 2]}


def _hover(text, on: bool) -> dict:
    if not on:
        return {"hoverinfo": "skip"}
    return {"text": list(text), "hovertemplate": "%{text}<extra></extra>"}


def _anchors(geometry: _Geometry) -> np.ndarray:
    """One point on each row's shape (where its name is shown when vertices do not carry it)."""
    if geometry.points is not None:
        return geometry.points
    curve = geometry.curves[0]
    return curve[:, curve.shape[1] // 2 if curve.shape[1] > 2 else 0]


def _traces(go, part: _Part, geometry: _Geometry, rows: np.ndarray, label: str, colour: str, options: dict) -> list:
    """The traces of some rows of a part, drawn alike: curves, face, points, sweep, and (large
    figures) the markers that carry the names."""
    names = [part.names[i] for i in rows]
    hover = options["hover"]
    common = {"name": label, "legendgroup": label}
    out = []
    if geometry.curves and options["outlines"]:
        xyz, text = _polylines([c[rows] for c in geometry.curves], names)
        out.append(
            go.Scatter3d(
                mode="lines",
                line={"color": colour, "width": 4},
                **_xyz(xyz, options["origin"]),
                **_hover(text, hover),
                **common,
            )
        )
    if geometry.points is not None:
        p = geometry.points[rows]
        out.append(
            go.Scatter3d(
                mode="markers",
                marker={"color": colour, "size": 4},
                **_xyz(p, options["origin"]),
                **_hover(names, True),
                **common,
            )
        )

    def mesh(pieces, piece_names, opacity, flat):
        xyz, ijk, text = _meshes(pieces, piece_names)
        return go.Mesh3d(
            i=ijk[:, 0],
            j=ijk[:, 1],
            k=ijk[:, 2],
            color=colour,
            opacity=opacity,
            flatshading=flat,
            **_xyz(xyz, options["origin"]),
            **_hover(text, hover),
            **common,
        )

    if geometry.face is not None and options["faces"]:
        out.append(mesh([(geometry.face[0][rows], geometry.face[1])], names, 0.45, True))
    swept = rows[part.sweep[rows] > 0]
    if len(swept) and options["sweeps"]:
        pieces = _sweep_pieces(part, geometry, swept, TUBE_SIDES)
        out.append(mesh(pieces, [part.names[i] for i in swept], 0.25, False))
    if not hover and geometry.points is None:
        a = _anchors(geometry)[rows]
        out.append(
            go.Scatter3d(
                mode="markers",
                marker={"color": colour, "size": 2},
                **_xyz(a, options["origin"]),
                **_hover(names, True),
                **common,
            )
        )
    for i, trace in enumerate(out):
        trace.showlegend = i == 0
    return out


def _pair_traces(go, closest: list, origin: np.ndarray) -> list:
    """A dashed segment between each pair's closest points, labelled with the distance."""
    if not closest:
        return []
    xyz, text, middles, labels = [], [], [], []
    for a, b, d, p, q in closest:
        if not (np.isfinite(p).all() and np.isfinite(q).all()):
            continue
        line = f"{a} \u2013 {b}: distance {d:.6g}"
        xyz += [p, q, np.full(3, np.nan)]
        text += [line, line, line]
        middles.append((p + q) / 2)
        labels.append(f"{d:.3g}")
    if not xyz:
        return []
    style = {"color": _PAIR_COLOR}
    common = {"name": "closest points", "legendgroup": "closest points"}
    return [
        go.Scatter3d(
            mode="lines+markers",
            line={**style, "width": 3, "dash": "dash"},
            marker={**style, "size": 3},
            **_xyz(np.array(xyz), origin),
            **_hover(text, True),
            **common,
        ),
        go.Scatter3d(
            mode="text",
            text=labels,
            textfont=style,
            textposition="top center",
            showlegend=False,
            hoverinfo="skip",
            **_xyz(np.array(middles), origin),
            **common,
        ),
    ]


def _named_pairs(pairs, resolve) -> list:
    """The pairs checked: (index, name a, name b, shape a, shape b) each."""
    if isinstance(pairs, (str, bytes)) or not isinstance(pairs, Sequence):
        raise TypeError(f"figure: pairs must be a sequence of (name, name) pairs, got {type(pairs).__name__}")
    out = []
    for i, pair in enumerate(pairs):
        if isinstance(pair, (str, bytes)) or not isinstance(pair, Sequence) or len(pair) != 2:
            raise TypeError(f"figure: pairs[{i}] must be a pair of shape names, got {pair!r}")
        shapes = []
        for name in pair:
            try:
                shapes.append(resolve(name))
            except (KeyError, TypeError):
                raise ValueError(f"figure: pairs[{i}]: no shape named {name!r}") from None
        out.append((i, pair[0], pair[1], *shapes))
    return out


def _closest(named: list) -> list:
    """Each checked pair's closest points: (name a, name b, distance, point a, point b)."""
    out = []
    for _, a, b, shape_a, shape_b in named:
        r = _core.closest_points(shape_a, shape_b)
        out.append((a, b, float(r.distance), np.asarray(r.point_a, np.float64), np.asarray(r.point_b, np.float64)))
    return out


def _scale(parts: list, closest: list) -> float:
    """The power of ten the figure's coordinates are given in: 1, or about the largest coordinate
    or length where that is outside the plain lengths (float32, which WebGL draws in, holds
    neither 1e300 nor 1e-300), as the command line's picture does."""
    largest = 0.0
    for part in parts:
        for value, role in zip(part.values, KINDS[part.kind][1].values()):
            if role in ("vector", "length", "control_points") and value.size:
                largest = max(largest, float(np.abs(value).max()))
        largest = max(largest, float(np.abs(part.sweep).max(initial=0.0)))
    for *_, p, q in closest:
        largest = max([largest] + [abs(float(x)) for x in np.concatenate([p, q]) if math.isfinite(x)])
    if largest == 0 or _PLAIN_LENGTHS[0] <= largest <= _PLAIN_LENGTHS[1]:
        return 1.0
    return 10.0 ** max(math.floor(math.log10(largest)), -300)  # a normal double, never 0


def _origin(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Where the drawn coordinates start: 0, or on an axis where the view lies far from 0 for its
    width (float32's 24 bits would step visibly across it: a scene 1e6 from the origin), its
    centre rounded to 3 significant digits."""
    mid, half = (lo + hi) / 2, float((hi - lo).max()) / 2
    origin = np.zeros(3)
    for i in range(3):
        if abs(mid[i]) > 1e3 * half:
            origin[i] = float(f"{mid[i]:.2e}")
    return origin


def rim_points(count: int) -> int:
    """The points on one closed rim of a figure of count shapes (the reduced-detail rule); 0: the
    shapes are drawn as one marker each."""
    rim = min(MAX_RIM, VERTEX_BUDGET // max(count, 1) - 2)
    return int(rim) if rim >= MIN_RIM else 0


def _rescaled(parts: list, closest: list, scale: float):
    """The parts and closest points in units of scale (the distances' labels stay as they are)."""
    if scale == 1:
        return parts, closest
    parts = [_Part(p.kind, p.names, _scaled(p.kind, p.values, scale), p.sweep / scale) for p in parts]
    return parts, [(a, b, d, p / scale, q / scale) for a, b, d, p, q in closest]


def _rim(detail, count: int) -> int:
    """Points on a closed rim: detail, checked, or the reduced-detail rule's for count shapes."""
    if detail is None:
        return rim_points(count)
    if isinstance(detail, (bool, float)) or not isinstance(detail, (int, np.integer)) or detail < 3:
        raise ValueError(f"figure: detail must be an integer >= 3 (points on a rim), got {detail!r}")
    return int(detail)


def _box(box, scale: float, parts: list, closest: list):
    """The view's corners (in units of scale): the box given, checked, or around the shapes."""
    if box is None:
        return _view_box(parts, closest)
    try:
        lo, hi = (np.asarray(c, np.float64).reshape(3) / scale for c in box)
    except (TypeError, ValueError):
        raise ValueError(f"figure: box must be two 3-vectors (lower and upper corners), got {box!r}") from None
    if not (np.isfinite(lo).all() and np.isfinite(hi).all() and (lo < hi).all()):
        raise ValueError(f"figure: box must be finite, its lower corner below its upper one, got {box!r}")
    return lo, hi


def _options(count: int, rim: int, origin: np.ndarray) -> dict:
    """What is drawn of count shapes (the reduced-detail rule) with rim points on a rim."""
    full = count <= FULL_LIMIT
    return {"hover": full, "sweeps": full, "faces": full, "outlines": rim > 0, "origin": origin}


def _draw(go, parts: list, rim: int, lo, hi, options: dict, per_shape: bool, k: int = 0, note: str = ""):
    """(traces, k): the parts' traces, a trace group (a colour, a legend entry) per shape or,
    merged, per kind; k counts the groups drawn so far (their colours), note ends a kind's label."""
    import plotly.colors

    colours = plotly.colors.qualitative.Plotly
    traces = []
    rim = max(rim, 2)  # the markers' places: a point on each shape
    for part in parts if per_shape else _merged(parts):
        geometry = _geometry(part, rim, lo, hi)
        if per_shape:
            groups = [(np.array([i]), part.names[i]) for i in range(len(part))]
        else:
            label = f"{part.kind} \u00d7 {len(part)}{note}"
            if not options["outlines"]:
                label += " (a marker each)"
            elif not options["sweeps"] and part.sweep.any():
                label += " (sweeps not drawn)"
            groups = [(np.arange(len(part)), label)]
        for rows, label in groups:
            traces += _traces(go, part, geometry, rows, label, colours[k % len(colours)], options)
            k += 1
    return traces, k


def _laid_out(go, traces: list, title, lo, hi, origin: np.ndarray, scale: float, bottom: int = 0):
    """The figure of the traces: the view's cube, the axes' titles saying the unit and origin."""
    unit = "" if scale == 1 else f" (\u00d7 {scale:.0e})"
    axes = {}
    for i, axis in enumerate("xyz"):
        shift = "" if origin[i] == 0 else f" \u2212 {origin[i]:.6g}"
        axes[f"{axis}axis"] = {
            "range": [float(lo[i] - origin[i]), float(hi[i] - origin[i])],
            "title": f"{axis}{shift}{unit}",
        }
    fig = go.Figure(data=traces)
    fig.update_layout(
        title=title,
        # The camera a little nearer than plotly's default: the cube's margin is empty space.
        scene={**axes, "aspectmode": "cube", "camera": {"eye": {"x": 1.15, "y": 1.15, "z": 0.85}}},
        legend={"itemsizing": "constant"},
        margin={"l": 0, "r": 0, "t": 40 if title else 10, "b": bottom},
    )
    return fig


def figure(
    shapes,
    *,
    pairs: Sequence[tuple[str, str]] | None = None,
    detail: int | None = None,
    box: tuple[ArrayLike, ArrayLike] | None = None,
    title: str | None = None,
    motions: Mapping[str, _core.Motion] | None = None,
    frames: int | None = None,
) -> plotly.graph_objects.Figure:
    """An interactive 3-D figure (plotly) of shapes, batches, a Scene or a scene file.

    Circles and arcs are drawn as their rims, disks and annuli as translucent faces with their
    rims, lines and rays clipped to the view's box, segments, points and Bezier curves as they
    are; a swept shape gets a translucent surface around it (a tube, torus, capsule, ball or
    rounded disk). Hovering over a shape shows its name (a batch's shapes are ``name[i]``).
    Closest points are drawn as a dashed segment labelled with the distance. Large figures are
    drawn at reduced detail (fewer points per rim; above ``circledist.view.FULL_LIMIT`` shapes
    outlines only, the names carried by one marker per shape; beyond the vertex budget one marker
    per shape): see the guide's page on figures. Shapes given motions are animated over t in
    [0, 1]: a time slider and a play button, the pairs' closest points at every time, and the
    time at which each pair with a moving shape first touches (`first_contact`) marked.

    Needs plotly (``pip install 'circledist[view]'``). In Jupyter the returned figure displays
    inline; ``fig.write_html(path)`` writes a page that opens in any browser.

    Parameters
    ----------
    shapes : Shape, mapping of str to Shape, Scene or scene file
        What to draw: a shape or batch (named by its kind), shapes by name (a batch's shapes are
        ``name[0]``, ``name[1]``, ...), a `Scene`, or a scene file as `read_scene` returns it.
    pairs : sequence of (str, str), optional
        Pairs of shape names whose closest points are drawn. Default: a scene file's queries
        that name two shapes; none for the other inputs.
    detail : int, optional
        Points on each closed rim (at least 3); default: from the number of shapes, fewer for
        more, and for the largest figures one marker per shape (``circledist.view.rim_points``).
    box : pair of 3-vectors, optional
        The lower and upper corners of the region shown, which lines and rays are clipped to.
        Default: a cube around every bounded shape (with its sweep), the lines' and rays'
        origins and the closest points.
    title : str, optional
        The figure's title; default: a scene file's description, else none.
    motions : mapping of str to Motion, optional
        Shapes that move, by name: a shape's name (``ring``, ``beads[1]``) or a batch's
        (``beads``: the batch moves by the motion, a batch of motions broadcasting to the batch's
        shape). The figure gets one frame per time step over [0, 1] and one at each pair's first
        contact; the view holds the shapes at every time; shapes without a motion are drawn once.
        The moving shapes count once per frame in the reduced-detail rule. Default: a scene
        file's motions (a shape its queries move, by the first query that moves it); none for
        the other inputs.
    frames : int, optional
        Time steps of the animation over [0, 1], both ends included (at least 2); default
        ``circledist.view.FRAMES``. Without motions there is no animation.

    Returns
    -------
    plotly.graph_objects.Figure
        Each trace's ``name`` is its shape's name (a figure of few shapes) or its kind (many);
        the vertices' ``text`` holds their shapes' names.

    Raises
    ------
    ImportError
        When plotly is not installed (the message says what to install).
    TypeError
        When `shapes` is none of the inputs above, `pairs` not pairs of names, `motions` not
        Motions by name, or `frames` not an integer.
    ValueError
        When a pair names no shape of `shapes`, a motion no shape, or `detail`, `box` or
        `frames` is invalid.

    Examples
    --------
    >>> import circledist as cd
    >>> fig = cd.figure({"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0),
    ...                  "rail": cd.Line([-3, 1, 0.5], [1, 0, 0])}, pairs=[("rail", "ring")])
    >>> [trace.name for trace in fig.data]
    ['ring', 'rail', 'closest points', 'closest points']
    >>> fig.data[2].text[0]
    'rail – ring: distance 0.5'

    A point moving towards the ring at speed 4 first touches it at t = 0.5:

    >>> fig = cd.figure({"ring": cd.Circle([0, 0, 0], [0, 0, 1], 1.0), "probe": cd.Point([3, 0, 0])},
    ...                 motions={"probe": cd.Motion(translation=[-4, 0, 0])}, pairs=[("probe", "ring")], frames=5)
    >>> len(fig.frames), [step.label for step in fig.layout.sliders[0].steps]
    (5, ['0', '0.25', '0.5 contact', '0.75', '1'])
    """
    go = _plotly()
    from . import _view_motion  # beside this module, which it draws with

    parts, resolve, file_pairs, file_motions = _parts_of(shapes)
    named = _named_pairs(file_pairs if pairs is None else pairs, resolve)
    if title is None and isinstance(shapes, SceneFile) and shapes.description:
        title = shapes.description.split("\n")[0]
    steps = _view_motion.frame_count(frames)
    movers = _view_motion.movers(parts, file_motions if motions is None else motions)
    if movers:
        return _view_motion.animated(go, parts, named, movers, steps, detail, box, title)
    closest = _closest(named)
    scale = _scale(parts, closest)
    parts, closest = _rescaled(parts, closest, scale)
    count = sum(len(p) for p in parts)
    rim = _rim(detail, count)
    lo, hi = _box(box, scale, parts, closest)
    origin = _origin(lo, hi)
    traces, _ = _draw(go, parts, rim, lo, hi, _options(count, rim, origin), count <= LEGEND_LIMIT)
    traces += _pair_traces(go, closest, origin)
    return _laid_out(go, traces, title, lo, hi, origin, scale)
