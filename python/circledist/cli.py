"""circledist's command line: answer the queries of a scene file.

    python -m circledist [scene.json] [--json [PATH]] [--plot PATH | --no-plot]
    circledist [scene.json] ...                       (the same, as a console script)

Without a scene file it runs the demo scene shipped in the package and draws it to
circledist_demo.png (or the --plot path).

Scene file (JSON):

    {
      "description": "optional text",
      "shapes": [
        {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
         "sweep": 0.05},
        {"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]},
        ...
      ],
      "queries": [
        {"a": "rail", "b": "ring", "effects": ["intersects", "within", "distance", "closest_points"],
         "d": 0.6},
        {"a": "ring", "effects": ["nearest"], "k": 2},
        {"a": "ring", "effects": ["within"], "d": 0.5},
        {"effects": ["pairs_within"], "d": 0.25}
      ]
    }

Shape kinds and fields: point (p), line and ray (origin, direction), segment (p0, p1), circle and
disk (center, normal, radius), bezier (control_points: 2 to 8 points); every kind takes an
optional sweep >= 0 (a ball, capsule, cylinder, torus, rounded disk, tube).
Queries: with "b", the effects intersects, within (needs "d"), distance and closest_points of
the pair a-b, each computed on its own with only the work it needs. Without "b", against the
rest of the scene: nearest ("k", default 1), within ("d"), intersects. {"effects":
["pairs_within"], "d": ...} lists every pair of shapes within d.

Errors in the file name the file, the shape or query and the field; nothing is written then,
and the exit status is 2.
"""

from __future__ import annotations

import argparse
import io
import json
import math
import os
import sys
import tempfile
from dataclasses import dataclass, field
from importlib import resources
from typing import Any

import numpy as np

from . import _core
from .scene import Scene

DEMO_PICTURE = "circledist_demo.png"

# kind -> (class name, required vector fields, required scalar fields)
KINDS = {
    "point": ("Point", ("p",), ()),
    "line": ("Line", ("origin", "direction"), ()),
    "ray": ("Ray", ("origin", "direction"), ()),
    "segment": ("Segment", ("p0", "p1"), ()),
    "circle": ("Circle", ("center", "normal"), ("radius",)),
    "disk": ("Disk", ("center", "normal"), ("radius",)),
    "bezier": ("Bezier", (), ()),
}
NONZERO = ("normal", "direction")
PAIR_EFFECTS = ("intersects", "within", "distance", "closest_points")
SCENE_EFFECTS = ("nearest", "within", "intersects")
QUERY_KEYS = ("name", "a", "b", "effects", "d", "k")


class SceneError(Exception):
    """A problem with a scene file; the message names the file, the shape or query and the field."""


@dataclass
class Query:
    label: str
    a: str | None
    b: str | None
    effects: list[str]
    d: float | None = None
    k: int = 1
    answers: dict = field(default_factory=dict)


@dataclass
class LoadedScene:
    path: str
    description: str
    shapes: dict          # name -> circledist shape
    specs: dict           # name -> validated JSON object of the shape
    queries: list


# ------------------------------------------------------------------------------------------
# loading and validation
# ------------------------------------------------------------------------------------------
def _number(value, where: str, *, minimum: float | None = None) -> float:
    try:  # an integer literal of 400 digits is a Python int that no float holds
        finite = not isinstance(value, bool) and isinstance(value, (int, float)) and math.isfinite(float(value))
    except OverflowError:
        finite = False
    if not finite:
        shown = json.dumps(value) if not isinstance(value, int) or abs(value) < 10**30 else f"an integer of {len(str(abs(value)))} digits"
        raise SceneError(f"{where}: must be a finite number, got {shown}")
    if minimum is not None and value < minimum:
        raise SceneError(f"{where}: must be >= {minimum:g}, got {json.dumps(value)}")
    return float(value)


def _vector(value, where: str, *, nonzero: bool = False) -> list[float]:
    if not isinstance(value, list) or len(value) != 3:
        raise SceneError(f"{where}: must be a list of 3 numbers, got {json.dumps(value)}")
    v = [_number(x, where) for x in value]
    if nonzero and not any(v):
        raise SceneError(f"{where}: must not be the zero vector")
    return v


def _shape(spec, index: int, path: str, names: set):
    where = f"{path}: shapes[{index}]"
    if not isinstance(spec, dict):
        raise SceneError(f"{where}: must be an object with a name, a kind and its fields")
    name = spec.get("name")
    if not isinstance(name, str) or not name:
        raise SceneError(f"{where}: field 'name': must be a non-empty string, got {json.dumps(name)}")
    where = f"{path}: shape {name!r}"
    if name in names:
        raise SceneError(f"{where}: field 'name': the name is used by another shape")
    kind = spec.get("kind")
    if not isinstance(kind, str) or kind.lower() not in KINDS:
        raise SceneError(f"{where}: field 'kind': must be one of {', '.join(KINDS)}, got {json.dumps(kind)}")
    kind = kind.lower()
    cls_name, vectors, scalars = KINDS[kind]
    expected = {"name", "kind", "sweep", *vectors, *scalars} | ({"control_points"} if kind == "bezier" else set())
    for key in spec:
        if key not in expected:
            raise SceneError(f"{where}: field {key!r}: unknown for a {kind} (its fields: "
                             f"{', '.join(sorted(expected - {'name', 'kind'}))})")
    args = []
    for key in vectors:
        if key not in spec:
            raise SceneError(f"{where}: field {key!r}: missing")
        args.append(_vector(spec[key], f"{where}: field {key!r}", nonzero=key in NONZERO))
    for key in scalars:
        if key not in spec:
            raise SceneError(f"{where}: field {key!r}: missing")
        args.append(_number(spec[key], f"{where}: field {key!r}", minimum=0))
    if kind == "bezier":
        cp = spec.get("control_points")
        if not isinstance(cp, list) or not 2 <= len(cp) <= 8:
            raise SceneError(f"{where}: field 'control_points': must be a list of 2 to 8 points, "
                             f"got {json.dumps(cp)}")
        args.append([_vector(p, f"{where}: field 'control_points'[{i}]") for i, p in enumerate(cp)])
    sweep = _number(spec.get("sweep", 0), f"{where}: field 'sweep'", minimum=0)
    try:
        return getattr(_core, cls_name)(*args, sweep=sweep)
    except ValueError as e:  # anything the library still refuses
        raise SceneError(f"{where}: {e}") from None


def _query(spec, index: int, path: str, shapes: dict, supported: set) -> Query:
    where = f"{path}: queries[{index}]"
    if not isinstance(spec, dict):
        raise SceneError(f"{where}: must be an object with effects")
    if "name" in spec:
        if not isinstance(spec["name"], str):
            raise SceneError(f"{where}: field 'name': must be a string, got {json.dumps(spec['name'])}")
        where = f"{path}: query {spec['name']!r}"
    for key in spec:
        if key not in QUERY_KEYS:
            raise SceneError(f"{where}: field {key!r}: unknown (query fields: {', '.join(QUERY_KEYS)})")
    effects = spec.get("effects")
    if not isinstance(effects, list) or not effects or not all(isinstance(e, str) for e in effects):
        raise SceneError(f"{where}: field 'effects': must be a non-empty list of effect names, "
                         f"got {json.dumps(effects)}")
    if len(set(effects)) != len(effects):
        raise SceneError(f"{where}: field 'effects': lists an effect twice")
    a, b = spec.get("a"), spec.get("b")
    for key, value in (("a", a), ("b", b)):
        if value is not None and (not isinstance(value, str) or value not in shapes):
            raise SceneError(f"{where}: field {key!r}: no shape named {json.dumps(value)} in the scene")
    if effects == ["pairs_within"]:
        if a is not None or b is not None:
            raise SceneError(f"{where}: field {'a' if a is not None else 'b'!r}: pairs_within takes no shapes")
        label = spec.get("name", "pairs within")
    else:
        if "pairs_within" in effects:
            raise SceneError(f"{where}: field 'effects': pairs_within must be a query's only effect")
        if a is None:
            raise SceneError(f"{where}: field 'a': missing")
        allowed = PAIR_EFFECTS if b is not None else SCENE_EFFECTS
        for e in effects:
            if e not in allowed:
                against = f"the pair {a} - {b}" if b is not None else "the rest of the scene (no 'b')"
                raise SceneError(f"{where}: field 'effects': {e!r} is not an effect against {against}; "
                                 f"use {', '.join(allowed)}")
        label = spec.get("name", f"{a} ~ {b}" if b is not None else f"{a} ~ scene")
        ka = shapes[a].kind
        others = [shapes[b].kind] if b is not None else [s.kind for n, s in shapes.items() if n != a]
        for kb in others:
            if (ka, kb) not in supported:
                raise SceneError(f"{where}: field {'b' if b is not None else 'a'!r}: circledist has no query "
                                 f"between a {ka} and a {kb}")
    needs_d = "within" in effects or "pairs_within" in effects
    d = None
    if needs_d:
        if "d" not in spec:
            raise SceneError(f"{where}: field 'd': missing (the distance of within / pairs_within)")
        d = _number(spec["d"], f"{where}: field 'd'", minimum=0)
    elif "d" in spec:
        raise SceneError(f"{where}: field 'd': only within and pairs_within take a distance")
    k = 1
    if "k" in spec:
        if "nearest" not in effects:
            raise SceneError(f"{where}: field 'k': only nearest takes k")
        k = spec["k"]
        if isinstance(k, bool) or not isinstance(k, int) or k < 1:
            raise SceneError(f"{where}: field 'k': must be an integer >= 1, got {json.dumps(k)}")
    return Query(label=label, a=a, b=b, effects=list(effects), d=d, k=k)


def load_scene(path: str, text: str | None = None) -> LoadedScene:
    """Reads and validates a scene file (or its text); raises SceneError."""
    if text is None:
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise SceneError(f"{path}: cannot read the scene file: {e.strerror}") from None
        except UnicodeDecodeError as e:
            raise SceneError(f"{path}: not a UTF-8 text file (byte {e.start}: {e.reason})") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as e:
        raise SceneError(f"{path}: not valid JSON: {e.msg} at line {e.lineno}, column {e.colno}") from None
    except RecursionError:
        raise SceneError(f"{path}: not a scene: JSON nested too deeply") from None
    except ValueError as e:  # e.g. an integer literal past Python's digit limit
        raise SceneError(f"{path}: not valid JSON: {e}") from None
    if not isinstance(data, dict):
        raise SceneError(f"{path}: the scene must be a JSON object with 'shapes' and 'queries'")
    for key in data:
        if key not in ("description", "shapes", "queries"):
            raise SceneError(f"{path}: field {key!r}: unknown (scene fields: description, shapes, queries)")
    description = data.get("description", "")
    if not isinstance(description, str):
        raise SceneError(f"{path}: field 'description': must be a string")
    specs = data.get("shapes")
    if not isinstance(specs, list) or not specs:
        raise SceneError(f"{path}: field 'shapes': must be a non-empty list of shapes")
    shapes, by_name = {}, {}
    for i, spec in enumerate(specs):
        shape = _shape(spec, i, path, set(shapes))
        shapes[spec["name"]] = shape
        by_name[spec["name"]] = spec
    qspecs = data.get("queries", [])
    if not isinstance(qspecs, list):
        raise SceneError(f"{path}: field 'queries': must be a list of queries")
    supported = {tuple(p) for p in _core._query_kinds()}
    queries = [_query(q, i, path, shapes, supported) for i, q in enumerate(qspecs)]
    return LoadedScene(path, description, shapes, by_name, queries)


# ------------------------------------------------------------------------------------------
# answering
# ------------------------------------------------------------------------------------------
def answer(scene: LoadedScene) -> list[Query]:
    """Computes each query's effects, each with its own call (and only the work it needs)."""
    world = Scene(scene.shapes)
    for q in scene.queries:
        if q.effects == ["pairs_within"]:
            q.answers["pairs_within"] = [list(p) for p in world.pairs_within(q.d)]
            continue
        A = scene.shapes[q.a]
        if q.b is not None:
            B = scene.shapes[q.b]
            for e in q.effects:
                if e == "intersects":
                    q.answers[e] = bool(_core.intersects(A, B))
                elif e == "within":
                    q.answers[e] = bool(_core.within(A, B, q.d))
                elif e == "distance":
                    q.answers[e] = float(_core.distance(A, B))
                elif e == "closest_points":
                    r = _core.closest_points(A, B)
                    q.answers[e] = {
                        "distance": float(r.distance),
                        "point_a": [float(x) for x in r.point_a],
                        "point_b": [float(x) for x in r.point_b],
                        "param_a": [float(x) for x in r.param_a],
                        "param_b": [float(x) for x in r.param_b],
                        "unique": bool(r.unique),
                    }
        else:
            for e in q.effects:
                if e == "nearest":
                    q.answers[e] = [{"name": n, "distance": d} for n, d in world.nearest(q.a, q.k)]
                elif e == "within":
                    q.answers[e] = world.within(q.a, q.d)
                elif e == "intersects":
                    q.answers[e] = world.within(q.a, 0.0)
    return scene.queries


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _point(p) -> str:
    return "(" + ", ".join(_fmt(v) for v in p) + ")"


def table(scene: LoadedScene, queries: list[Query]) -> str:
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
                text = (f"{_fmt(v['distance'])} between {_point(v['point_a'])} and {_point(v['point_b'])}"
                        + ("" if v["unique"] else " (not unique)"))
            elif e == "nearest":
                text = ", ".join(f"{x['name']} {_fmt(x['distance'])}" for x in v) or "-"
            elif e == "pairs_within":
                text = ", ".join(f"{a}-{b}" for a, b in v) or "none"
            else:  # within / intersects against the scene: names
                text = ", ".join(v) or "none"
            effect = {"within": f"within {_fmt(q.d) if q.d is not None else ''}",
                      "nearest": f"nearest k={q.k}",
                      "pairs_within": f"pairs within {_fmt(q.d) if q.d is not None else ''}"}.get(e, e)
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


def as_json(scene: LoadedScene, queries: list[Query]) -> str:
    out = {"scene": scene.path, "answers": []}
    for q in queries:
        item = {"query": q.label}
        if q.a is not None:
            item["a"] = q.a
        if q.b is not None:
            item["b"] = q.b
        if q.d is not None:
            item["d"] = q.d
        if "nearest" in q.effects:
            item["k"] = q.k
        item.update(q.answers)
        out["answers"].append(item)
    return json.dumps(out, indent=2) + "\n"


# ------------------------------------------------------------------------------------------
# the picture
# ------------------------------------------------------------------------------------------
def _frame(normal):
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    helper = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(n, helper)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def _ring(center, normal, radius, count=120):
    u, v = _frame(normal)
    t = np.linspace(0, 2 * np.pi, count)
    return np.asarray(center, float) + radius * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)


def _bezier(points, count=100):
    p = np.asarray(points, float)
    t = np.linspace(0, 1, count)[:, None, None]
    q = np.broadcast_to(p, (count,) + p.shape).copy()
    for k in range(len(p) - 1, 0, -1):
        q = (1 - t) * q[:, :k] + t * q[:, 1:k + 1]
    return q[:, 0]


def _clip(origin, direction, lo, hi, ray: bool):
    """The part of a line (or ray) inside the box [lo, hi], or None."""
    o, d = np.asarray(origin, float), np.asarray(direction, float)
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


def picture(scene: LoadedScene, queries: list[Query]) -> bytes:
    """The scene drawn in 3D (PNG bytes): shapes, and a segment between each pair of closest points."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    specs = scene.specs
    # The view: every bounded shape and every closest point, plus the lines' origins.
    pts = []
    for s in specs.values():
        k = s["kind"].lower()
        if k == "point":
            pts.append(s["p"])
        elif k in ("line", "ray"):
            pts.append(s["origin"])
        elif k == "segment":
            pts += [s["p0"], s["p1"]]
        elif k in ("circle", "disk"):
            pts += list(_ring(s["center"], s["normal"], s["radius"], 16))
        else:
            pts += s["control_points"]
    for q in queries:
        if "closest_points" in q.answers:
            pts += [q.answers["closest_points"]["point_a"], q.answers["closest_points"]["point_b"]]
    pts = np.asarray(pts, float)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    mid, half = (lo + hi) / 2, max(float((hi - lo).max()) / 2, 1e-9) * 1.15
    lo, hi = mid - half, mid + half

    fig = plt.figure(figsize=(8, 7), dpi=110)
    ax = fig.add_subplot(projection="3d")
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, (name, s) in enumerate(specs.items()):
        c = colors[i % len(colors)]
        k = s["kind"].lower()
        sweep = float(s.get("sweep", 0))
        width = 1.6 + (4.0 if sweep > 0 else 0.0)
        label = name + (f" (sweep {sweep:g})" if sweep > 0 else "")
        alpha = 0.55 if sweep > 0 else 1.0
        if k == "point":
            ax.scatter(*np.asarray(s["p"], float), color=c, s=30 + (120 if sweep else 0), label=label)
            anchor = np.asarray(s["p"], float)
        elif k in ("line", "ray"):
            seg = _clip(s["origin"], s["direction"], lo, hi, k == "ray")
            if seg is None:
                continue
            ax.plot(*seg.T, color=c, lw=width, alpha=alpha, label=label)
            anchor = seg.mean(axis=0)
        elif k == "segment":
            seg = np.array([s["p0"], s["p1"]], float)
            ax.plot(*seg.T, color=c, lw=width, alpha=alpha, solid_capstyle="round", label=label)
            anchor = seg.mean(axis=0)
        elif k in ("circle", "disk"):
            ring = _ring(s["center"], s["normal"], s["radius"])
            if k == "disk":
                ax.add_collection3d(Poly3DCollection([ring], facecolor=c, alpha=0.35, edgecolor="none"))
            ax.plot(*ring.T, color=c, lw=width, alpha=alpha, label=label)
            anchor = ring[0]
        else:
            curve = _bezier(s["control_points"])
            ax.plot(*curve.T, color=c, lw=width, alpha=alpha, label=label)
            anchor = curve[len(curve) // 2]
        ax.text(*anchor, f" {name}", color=c, fontsize=9)
    for q in queries:
        r = q.answers.get("closest_points")
        if r is None:
            continue
        seg = np.array([r["point_a"], r["point_b"]])
        ax.plot(*seg.T, color="crimson", lw=1.4, ls="--")
        ax.scatter(*seg.T, color="crimson", s=14)
        ax.text(*seg.mean(axis=0), f" {r['distance']:.3g}", color="crimson", fontsize=8)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    title = scene.description or os.path.basename(scene.path)
    ax.set_title(title + "\n(dashed: closest points)", fontsize=10)
    ax.legend(loc="upper left", fontsize=8)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


# ------------------------------------------------------------------------------------------
# main
# ------------------------------------------------------------------------------------------
def _write_atomically(path: str, data: bytes) -> None:
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".circledist-", dir=directory)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def demo_scene_text() -> str:
    return resources.files("circledist").joinpath("scenes", "demo.json").read_text(encoding="utf-8")


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="circledist",
        description="Answer the queries of a circledist scene file (JSON): intersects, within, distance, "
                    "closest_points, nearest, pairs_within. Without a file: the shipped demo scene, drawn "
                    f"to {DEMO_PICTURE}.")
    p.add_argument("scene", nargs="?", help="scene file (JSON); default: the demo scene in the package")
    p.add_argument("--json", nargs="?", const="-", metavar="PATH",
                   help="write the answers as JSON to PATH (to standard output, instead of the table, "
                        "when PATH is omitted or '-')")
    p.add_argument("--plot", metavar="PATH", help="draw the scene and its closest points to PATH (PNG, matplotlib)")
    p.add_argument("--no-plot", action="store_true", help="do not draw the demo scene")
    p.add_argument("--version", action="version", version=f"circledist {_version()}")
    return p


def _version() -> str:
    from . import __version__
    return __version__


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    plot = args.plot
    if args.scene is None and plot is None and not args.no_plot:
        plot = DEMO_PICTURE
    if args.no_plot:
        plot = None
    try:
        if args.scene is None:
            scene = load_scene("circledist/scenes/demo.json", demo_scene_text())
        else:
            scene = load_scene(args.scene)
        if plot is not None:
            try:
                import matplotlib  # noqa: F401
            except ImportError:
                print("circledist: --plot needs matplotlib (pip install matplotlib); use --no-plot to skip "
                      "the picture", file=sys.stderr)
                return 1
        queries = answer(scene)
        text = table(scene, queries)
        payload = as_json(scene, queries) if args.json is not None else None
        image = picture(scene, queries) if plot is not None else None
    except SceneError as e:
        print(f"circledist: error: {e}", file=sys.stderr)
        return 2
    # Everything is computed: only now is anything written.
    if payload is not None and args.json != "-":
        _write_atomically(args.json, payload.encode("utf-8"))
    if image is not None:
        _write_atomically(plot, image)
    if args.json == "-":
        sys.stdout.write(payload)
    else:
        sys.stdout.write(text)
        if payload is not None:
            print(f"answers written to {args.json}")
    if image is not None:
        print(f"picture written to {plot}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
