"""circledist's command line: answer the queries of a scene file.

    python -m circledist [scene.json | scene.npz] [--json [PATH]] [--plot PATH | --no-plot]
    circledist [scene] ...                            (the same, as a console script)

Without a scene file it runs the demo scene shipped in the package and draws it to
circledist_demo.png (or the --plot path). The scene format: FORMAT_HELP below (--help prints it).
"""

from __future__ import annotations

import argparse
import io
import json
import os
import sys
import tempfile
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

from . import _core
from .scenefile import SCHEMA_RESOURCE, SceneFile, SceneFileError, read_scene

FORMAT_HELP = """scene files, format version 1; JSON Schema: {schema}

  {{"format": "circledist-scene", "version": 1, "description": "optional text",
   "shapes": [
     {{"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
      "sweep": 0.05}},
     {{"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]}},
     {{"name": "beads", "kind": "point", "count": 3, "p": [[0, 0, 2], [1, 0, 2], [2, 0, 2]],
      "sweep": 0.1}}],
   "queries": [
     {{"a": "rail", "b": "ring", "effects": ["intersects", "within", "distance", "closest_points"],
      "d": 0.6}},
     {{"a": "beads[2]", "effects": ["nearest"], "k": 2}},
     {{"a": "ring", "effects": ["within"], "d": 0.5}},
     {{"effects": ["pairs_within"], "d": 0.25}}]}}

  "format" and "version" are required (a file without them is refused: add the two fields).
  Kinds and fields: point (p), line and ray (origin, direction), segment (p0, p1), circle and
  disk (center, normal, radius), bezier (control_points: 2 to 8 points); every kind takes an
  optional sweep >= 0 (a ball, capsule, cylinder, torus, rounded disk, tube).
  A batch: an entry with "count": n whose fields are columns of n rows, or one value for all
  (NumPy broadcasting); its shapes are named name[0] .. name[n-1] in queries and answers.
  Queries: with "b", the effects intersects, within (needs "d"), distance and closest_points of
  the pair a-b, each computed with only the work it needs. Without "b", against the rest of the
  scene: nearest ("k", default 1), within ("d"), intersects. {{"effects": ["pairs_within"],
  "d": ...}} lists every pair of shapes within d.

  .npz scenes (numpy.savez; circledist.write_scene writes both forms) hold the same content:
  format (0-d str), version (0-d int), description (0-d str, optional), shapes (1-d str: the
  entries' names in order), per entry <name>/kind (0-d str), <name>/count (0-d int, batches
  only) and <name>/<field> (float arrays: [count or 1 rows] + (3,) for vectors, () for numbers,
  (m, 3) for control points), queries (0-d str: the JSON text of the query list).

  A bad file: one line on stderr naming the file, the JSON path (or array and index) and what
  was expected; nothing is written; exit status 2. Newer format versions are refused.
"""

DEMO_PICTURE = "circledist_demo.png"

# Bad files raise this; the message names the file, the JSON path (or .npz array) and what was expected.
SceneError = SceneFileError
PICTURE_LIMIT = 2000  # shapes --plot draws at most


@dataclass
class Query:
    label: str
    a: str | None
    b: str | None
    effects: list[str]
    d: float | None = None
    k: int = 1
    answers: dict = field(default_factory=dict)


def _queries(scene: SceneFile) -> list[Query]:
    out = []
    for q in scene.queries:
        if q["effects"] == ["pairs_within"]:
            label = q["name"] or "pairs within"
        else:
            label = q["name"] or (f"{q['a']} ~ {q['b']}" if q["b"] is not None else f"{q['a']} ~ scene")
        out.append(Query(label=label, a=q["a"], b=q["b"], effects=q["effects"], d=q["d"], k=q["k"] or 1))
    return out


def load_scene(path: str, text: str | None = None) -> SceneFile:
    """Reads and validates a scene file, JSON or .npz (or JSON text); raises SceneError."""
    return read_scene(path, text)


# ------------------------------------------------------------------------------------------
# answering
# ------------------------------------------------------------------------------------------
def answer(scene: SceneFile) -> list[Query]:
    """Computes each query's effects, each with its own call (and only the work it needs)."""
    world = scene.scene()
    queries = _queries(scene)
    for q in queries:
        if q.effects == ["pairs_within"]:
            q.answers["pairs_within"] = [list(p) for p in world.pairs_within(q.d)]
            continue
        A = scene.shape(q.a)
        if q.b is not None:
            B = scene.shape(q.b)
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
    return queries


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


def _specs(scene: SceneFile) -> dict:
    """name -> {"kind", field: plain values} of every shape (batches element by element)."""
    out = {}
    for e in scene.entries:
        for i, name in enumerate(e.element_names()):
            values = {f: (a if e.count is None else a[i]) for f, a in e.fields.items()}
            out[name] = {"kind": e.kind, **{f: np.asarray(a).tolist() for f, a in values.items()}}
    return out


def picture(scene: SceneFile, queries: list[Query]) -> bytes:
    """The scene drawn in 3D (PNG bytes): shapes, and a segment between each pair of closest points."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    specs = _specs(scene)
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
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Answer the queries of a circledist scene file (JSON or .npz): intersects, within,\n"
                    "distance, closest_points, nearest, pairs_within. Without a file: the shipped demo\n"
                    f"scene, drawn to {DEMO_PICTURE}.",
        epilog=FORMAT_HELP.format(schema=resources.files("circledist").joinpath(SCHEMA_RESOURCE)))
    p.add_argument("scene", nargs="?", help="scene file (.json or .npz); default: the demo scene in the package")
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
        if plot is not None and scene.count > PICTURE_LIMIT:
            print(f"circledist: --plot draws at most {PICTURE_LIMIT} shapes, {scene.path} holds {scene.count}; "
                  "use --no-plot", file=sys.stderr)
            return 1
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
