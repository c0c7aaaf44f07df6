"""The command line's last step: the answers as a text table or JSON, and the scene drawn in 3D
(matplotlib) with a segment between each pair of closest points, or as an interactive page
(plotly: circledist.view)."""

from __future__ import annotations

import io
import json
import math
import os

import numpy as np

from ._cli_load import Query
from .scenefile import _SWEEP, KINDS, SceneFile, SceneFileError, _write_atomically
from ._scene_format import _motion_as_written

PICTURE_LIMIT = 2000  # shapes --plot draws at most


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _point(p) -> str:
    return "(" + ", ".join(_fmt(v) for v in p) + ")"


def table(scene: SceneFile, queries: list[Query]) -> str:
    rows = [("query", "effect", "answer")]
    for q in queries:
        for e in q.effects:
            v = q.answers[e]
            if e == "intersects" and q.b is not None:
                text = "yes" if v else "no"
            elif e == "within" and q.b is not None:
                effect, text = f"within {_fmt(q.d)}", "yes" if v else "no"
            elif e == "distance":
                text = _fmt(v)
            elif e == "closest_points":
                text = f"{_fmt(v['distance'])} between {_point(v['point_a'])} and {_point(v['point_b'])}" + (
                    "" if v["unique"] else " (not unique)"
                )
            elif e in ("first_contact", "closest_approach") and q.b is not None:
                text = _moment(v) if math.isfinite(v["time"]) else "none"
            elif e == "first_contact":  # against the scene: the shapes reached, earliest first
                text = "; ".join(f"{x['name']} {_moment(x)}" for x in v) or "none"
            elif e == "nearest":
                text = ", ".join(f"{x['name']} {_fmt(x['distance'])}" for x in v) or "-"
            elif e == "pairs_within":
                text = ", ".join(f"{a}-{b}" for a, b in v) or "none"
            else:  # within / intersects against the scene: names
                text = ", ".join(v) or "none"
            effect = {
                "within": f"within {_fmt(q.d) if q.d is not None else ''}",
                "nearest": f"nearest k={q.k}",
                "pairs_within": f"pairs within {_fmt(q.d) if q.d is not None else ''}",
                "first_contact": "first_contact"
                + (f" within {_fmt(q.d)}" if q.d else "")
                + (f" k={q.k}" if q.b is None else ""),
            }.get(e, e)
            rows.append((q.label, effect, text))
    widths = [max(len(r[i]) for r in rows) for i in range(2)]
    lines = []
    if scene.description:
        lines.append(scene.description)
    for i, r in enumerate(rows):
        lines.append(f"{r[0]:<{widths[0]}}  {r[1]:<{widths[1]}}  {r[2]}")
        if i == 0:
            lines.append(f"{'-' * widths[0]}  {'-' * widths[1]}  {'-' * 6}")
    return "\n".join(lines) + "\n"


def _moment(v: dict) -> str:
    """A contact or closest approach: its time, its distance and the closest points then."""
    return (
        f"at t={_fmt(v['time'])}: {_fmt(v['distance'])} between {_point(v['point_a'])} and {_point(v['point_b'])}"
        + ("" if v["unique"] else " (not unique)")
    )


def as_json(scene: SceneFile, queries: list[Query]) -> str:
    out = {"scene": scene.path, "answers": []}
    for q in queries:
        item = {"query": q.label}
        if q.a is not None:
            item["a"] = q.a
        if q.b is not None:
            item["b"] = q.b
        if q.d is not None:
            item["d"] = q.d
        if "nearest" in q.effects or (q.b is None and "first_contact" in q.effects):
            item["k"] = q.k
        for key in ("motion", "motion_b"):
            if getattr(q, key) is not None:
                item[key] = _motion_as_written(getattr(q, key))
        item.update(q.answers)
        out["answers"].append(item)
    return json.dumps(_json_numbers(out), indent=2, allow_nan=False) + "\n"


def _json_numbers(value):
    """The answers with every number JSON can hold: a float that is not finite (a distance that
    overflowed a double) becomes None, written null; JSON has no Infinity or NaN."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _json_numbers(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_json_numbers(v) for v in value]
    return value


def check_output(path: str) -> None:
    """Refuses (SceneError) an output path that cannot be written, before any work: its folder
    missing or not writable, or the path a folder."""
    folder = os.path.dirname(os.path.abspath(path))
    problem = None
    if os.path.isdir(path):
        problem = "it is a directory"
    elif not os.path.isdir(folder):
        problem = f"no directory {folder}"
    elif not os.access(folder, os.W_OK | os.X_OK):
        problem = f"directory {folder} is not writable"
    elif os.path.exists(path) and not os.path.isfile(path):
        problem = "it is not a regular file"
    if problem is not None:
        raise SceneFileError(f"{path}: cannot write the output: {problem}")


def write_output(path: str, data: bytes) -> None:
    """Writes a whole output file or nothing (a temporary file renamed into place)."""
    _write_atomically(path, lambda f: f.write(data))


def page(scene: SceneFile) -> bytes:
    """The scene as one self-contained HTML page (plotly.js inside): circledist.figure of the scene
    file, its pair queries' closest points drawn and its queries' motions animated (opening at
    t = 0: the frames play when asked, not on opening)."""
    from .view import figure

    return figure(scene).to_html(include_plotlyjs=True, full_html=True, auto_play=False).encode("utf-8")


# ------------------------------------------------------------------------------------------
# the picture
# ------------------------------------------------------------------------------------------
def _unit(v):
    """v / |v| for any finite non-zero v: scaled by its largest component first, so that |v| of
    5e-324 or 1e308 neither underflows to 0 nor overflows to inf."""
    v = np.asarray(v, float)
    v = v / np.abs(v).max()
    return v / np.linalg.norm(v)


def _frame(normal):
    n = _unit(normal)
    helper = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(n, helper)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def _ring(center, normal, radius, count=120):
    u, v = _frame(normal)
    t = np.linspace(0, 2 * np.pi, count)
    return np.asarray(center, float) + radius * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)


def _arc(center, normal, radius, start, angle, count=120):
    """The arc's own definition: u the unit projection of start onto the plane, v = n x u."""
    n = _unit(normal)
    start = _unit(start)
    u = _unit(start - np.dot(start, n) * n)
    v = np.cross(n, u)
    t = np.linspace(0, float(angle), count)
    return np.asarray(center, float) + radius * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)


def _bezier(points, count=100):
    p = np.asarray(points, float)
    t = np.linspace(0, 1, count)[:, None, None]
    q = np.broadcast_to(p, (count,) + p.shape).copy()
    for k in range(len(p) - 1, 0, -1):
        q = (1 - t) * q[:, :k] + t * q[:, 1 : k + 1]
    return q[:, 0]


def _clip(origin, direction, lo, hi, ray: bool):
    """The part of a line (or ray) inside the box [lo, hi], or None."""
    o, d = np.asarray(origin, float), _unit(direction)
    t0, t1 = (0.0 if ray else -np.inf), np.inf
    for i in range(3):
        if d[i] == 0:
            if not lo[i] <= o[i] <= hi[i]:
                return None
            continue
        a, b = (lo[i] - o[i]) / d[i], (hi[i] - o[i]) / d[i]
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    if t0 > t1:
        return None
    return np.array([o + t0 * d, o + t1 * d])


def _specs(scene: SceneFile) -> dict:
    """name -> (kind, the kind's field values in the table's order, sweep) of every shape (batches
    element by element). Drawing knows each kind's geometry, not its field names."""
    out = {}
    for e in scene.entries:
        names = list(KINDS[e.kind][1])
        for i, name in enumerate(e.element_names()):
            values = [np.asarray(e.fields[f] if e.count is None else e.fields[f][i], float) for f in names + [_SWEEP]]
            out[name] = (e.kind, values[:-1], float(values[-1]))
    return out


# The kinds drawn as curves: kind -> the curves (each the points along it, count of them) from its
# field values in the table's order, an annulus its outer and inner rim; the filled ones are drawn
# with their face too (between the rims for an annulus). Drawing a new curve kind is a row here.
_CURVES = {
    "circle": lambda values, count: [_ring(*values, count)],
    "disk": lambda values, count: [_ring(*values, count)],
    "bezier": lambda values, count: [_bezier(values[0], count)],
    "arc": lambda values, count: [_arc(*values, count)],
    "annulus": lambda values, count: [_ring(*values[:2], values[3], count), _ring(*values[:3], count)],
}
_FILLED = {"disk", "annulus"}


def _face(curves):
    """The polygon of a filled kind's face: its rim, or for two rims the outer one and the inner one
    walked back (a ring with a hole: the two joined where both start, at angle 0)."""
    return curves[0] if len(curves) == 1 else np.concatenate([curves[0], curves[1][::-1]])


def _outline(kind: str, values) -> list:
    """Points the view must hold: every bounded shape's, the origins of lines and rays."""
    if kind in ("point", "line", "ray"):
        return [values[0]]
    if kind == "segment":
        return list(values)
    if kind == "bezier":
        return list(values[0])  # its control points
    return [p for curve in _CURVES[kind](values, 16) for p in curve]


def _short(text: str, limit: int) -> str:
    """A name or title cut to limit characters for the picture (a description may be a book)."""
    return text if len(text) <= limit else text[: limit - 3] + "..."


# Lengths drawn as they are between these; beyond, in units of a power of ten.
_PLAIN_LENGTHS = (1e-3, 1e6)


def _scale(specs: dict, closest: list) -> float:
    """The power of ten the picture's coordinates are given in: 1, or about the scene's largest
    coordinate or length where that is outside _PLAIN_LENGTHS."""
    largest = 0.0
    for kind, values, sweep in specs.values():
        for value, role in zip(values, KINDS[kind][1].values()):
            if role in ("vector", "length", "control_points"):
                largest = max(largest, float(np.abs(value).max()))
        largest = max(largest, abs(sweep))
    for r in closest:
        for p in (r["point_a"], r["point_b"]):
            finite = [abs(x) for x in p if math.isfinite(x)]
            largest = max([largest] + finite)
    if largest == 0 or _PLAIN_LENGTHS[0] <= largest <= _PLAIN_LENGTHS[1]:
        return 1.0
    return 10.0 ** max(math.floor(math.log10(largest)), -300)  # a normal double, never 0


def _scaled(kind: str, values: list, scale: float) -> list:
    """A shape's field values in units of scale (positions and lengths; directions and angles
    as they are)."""
    if scale == 1:
        return values
    return [
        np.asarray(v, float) / scale if role in ("vector", "length", "control_points") else v
        for v, role in zip(values, KINDS[kind][1].values())
    ]


def _library_spec(shape) -> tuple:
    """(kind, the kind's field values in the table's order, sweep) of a single library shape."""
    kind = shape.kind.lower()
    return kind, [np.asarray(getattr(shape, f), float) for f in KINDS[kind][1]], float(shape.sweep)


def _moment_times(q: Query) -> list:
    """(time, word) of the moments a query with motion is drawn at: its start, its contact or
    closest approach (the first shape reached, against the scene), its end."""
    times = [(0.0, "start")]
    for e, word in (("first_contact", "contact"), ("closest_approach", "closest approach")):
        v = q.answers.get(e)
        if isinstance(v, list):  # first_contact against the scene
            v = v[0] if v else None
        if v is not None and math.isfinite(v["time"]):
            times.append((v["time"], word))
    times.append((1.0, "end"))
    return times


def _poses(scene: SceneFile, queries: list[Query]) -> list:
    """(shape name, label, kind, values, sweep, word) of each moving shape at each moment of its
    query (_moment_times): the moved shape, to be drawn beside the scene's."""
    out = []
    for q in queries:
        for key, ref in (("motion", q.a), ("motion_b", q.b)):
            motion = getattr(q, key)
            if motion is None:
                continue
            shape = scene.shape(ref)
            for t, word in _moment_times(q):
                kind, values, sweep = _library_spec(shape.moved(motion, t))
                out.append((ref, f"{ref} t={_fmt(t)} ({word})", kind, values, sweep, word))
    return out


def _contact_points(queries: list[Query]) -> list:
    """The closest points of the motion effects' answers where there is a contact (or an
    approach): drawn as the closest points are."""
    out = []
    for q in queries:
        for e in ("first_contact", "closest_approach"):
            v = q.answers.get(e)
            for r in v if isinstance(v, list) else [v] if v is not None else []:
                if math.isfinite(r["time"]):
                    out.append(r)
    return out


def _draw(ax, kind, values, sweep, color, label, name, lo, hi, alpha_factor=1.0, style="-"):
    """One shape (a point, a clipped line or ray, a segment, a curve or a filled face)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    width = 1.6 + (4.0 if sweep > 0 else 0.0)
    alpha = (0.55 if sweep > 0 else 1.0) * alpha_factor
    if kind == "point":
        ax.scatter(*values[0], color=color, s=30 + (120 if sweep else 0), label=label, alpha=alpha_factor)
        anchor = values[0]
    elif kind in ("line", "ray"):
        seg = _clip(*values, lo, hi, kind == "ray")
        if seg is None:
            return
        ax.plot(*seg.T, color=color, lw=width, alpha=alpha, ls=style, label=label)
        anchor = seg.mean(axis=0)
    elif kind == "segment":
        seg = np.array(values, float)
        ax.plot(*seg.T, color=color, lw=width, alpha=alpha, ls=style, solid_capstyle="round", label=label)
        anchor = seg.mean(axis=0)
    else:
        curves = _CURVES[kind](values, 120)
        if kind in _FILLED:
            face = Poly3DCollection([_face(curves)], facecolor=color, alpha=0.35 * alpha_factor, edgecolor="none")
            ax.add_collection3d(face)
        for j, curve in enumerate(curves):
            ax.plot(*curve.T, color=color, lw=width, alpha=alpha, ls=style, label=label if j == 0 else None)
        anchor = curves[0][len(curves[0]) // 2]
    ax.text(*anchor, f" {name}", color=color, fontsize=9 if alpha_factor == 1 else 7, alpha=max(alpha_factor, 0.5))


def figure_of(scene: SceneFile, queries: list[Query]):
    """The scene drawn in 3D (a matplotlib figure): shapes, a segment between each pair of closest
    points, and each moving shape of a query with motion at its start, its contact (or closest
    approach) and its end, lighter than the scene's shapes and labelled with its time."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    specs = _specs(scene)
    closest = [q.answers["closest_points"] for q in queries if "closest_points" in q.answers]
    closest += _contact_points(queries)
    poses = _poses(scene, queries)
    # Drawn in units of `scale` (a power of ten) where the scene's lengths are far from 1: the
    # projection's arithmetic on coordinates near 1e308 overflows, and near 1e-300 underflows.
    scale = _scale({**specs, **{p[1]: p[2:5] for p in poses}}, closest)
    specs = {name: (kind, _scaled(kind, values, scale), sweep / scale) for name, (kind, values, sweep) in specs.items()}
    poses = [(ref, label, k, _scaled(k, v, scale), sweep / scale, word) for ref, label, k, v, sweep, word in poses]
    closest = [
        {
            "distance": r["distance"],
            "point_a": np.divide(r["point_a"], scale),
            "point_b": np.divide(r["point_b"], scale),
        }
        for r in closest
    ]
    # The view: every bounded shape (moved ones too) and every closest point, plus the lines' origins.
    pts = []
    for kind, values, _ in list(specs.values()) + [p[2:5] for p in poses]:
        pts += _outline(kind, values)
    for r in closest:
        pts += [r["point_a"], r["point_b"]]
    pts = np.asarray(pts, float)
    pts = pts[np.isfinite(pts).all(axis=1)]
    if not len(pts):
        pts = np.zeros((1, 3))
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    mid, half = (lo + hi) / 2, max(float((hi - lo).max()) / 2, 1e-9) * 1.15
    lo, hi = mid - half, mid + half

    fig = plt.figure(figsize=(8, 7), dpi=110)
    ax = fig.add_subplot(projection="3d")
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    color_of = {}
    for i, (name, (k, values, sweep)) in enumerate(specs.items()):
        c = color_of[name] = colors[i % len(colors)]
        name = _short(name, 40)
        label = name + (f" (sweep {sweep * scale:g})" if sweep > 0 else "")
        _draw(ax, k, values, sweep, c, label, name, lo, hi)
    for ref, label, k, values, sweep, word in poses:
        strength, style = (0.8, "-") if word in ("contact", "closest approach") else (0.3, ":")
        _draw(ax, k, values, sweep, color_of[ref], None, _short(label, 60), lo, hi, strength, style)
    for r in closest:
        seg = np.array([r["point_a"], r["point_b"]])
        ax.plot(*seg.T, color="crimson", lw=1.4, ls="--")
        ax.scatter(*seg.T, color="crimson", s=14)
        ax.text(*seg.mean(axis=0), f" {r['distance']:.3g}", color="crimson", fontsize=8)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect((1, 1, 1))
    unit = "" if scale == 1 else f" (\u00d7 {scale:.0e})"
    ax.set_xlabel("x" + unit)
    ax.set_ylabel("y" + unit)
    ax.set_zlabel("z" + unit)
    title = _short(scene.description.split("\n")[0] if scene.description else os.path.basename(scene.path), 100)
    moving = "; dotted: moving shapes at start and end" if poses else ""
    ax.set_title(title + f"\n(dashed: closest points{moving})", fontsize=10)
    ax.legend(loc="upper left", fontsize=8)
    return fig


def picture(scene: SceneFile, queries: list[Query]) -> bytes:
    """The scene drawn in 3D (PNG bytes): figure_of's figure."""
    import matplotlib.pyplot as plt

    fig = figure_of(scene, queries)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()
