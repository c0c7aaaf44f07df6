"""The command line's first step: the scene file read and validated, and its queries as the
command line answers them. Every bad file is a SceneError (circledist.SceneFileError) whose one
line names the file, the place in it and what was expected."""

from __future__ import annotations

import textwrap
from dataclasses import dataclass, field
from importlib import resources
from typing import Any

from .scene import MAX_CONTROL_POINTS
from .scenefile import KINDS, SCHEMA_RESOURCE, SceneFile, SceneFileError, read_scene

# Bad files raise this; the message names the file, the JSON path (or .npz array) and what was expected.
SceneError = SceneFileError

_FORMAT_TEMPLATE = """scene files, format version 4 (version 3: without motions; 2: without annuli; 1: without arcs); JSON Schema: {schema}

  {{"format": "circledist-scene", "version": 4, "description": "optional text",
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
     {{"effects": ["pairs_within"], "d": 0.25}},
     {{"a": "beads[0]", "b": "ring", "motion": {{"translation": [0, 0, -3]}},
      "effects": ["first_contact"], "d": 0.1}},
     {{"a": "ring", "motion": {{"rotation": [0, 3.1416, 0], "center": [1, 0, 0]}},
      "effects": ["first_contact"], "k": 2}}]}}

  "format" and "version" are required (a file without them is refused: add the two fields).
{kinds}
  A batch: an entry with "count": n whose fields are columns of n rows, or one value for all
  (NumPy broadcasting); its shapes are named name[0] .. name[n-1] in queries and answers.
  Queries: with "b", the effects intersects, within (needs "d"), distance and closest_points of
  the pair a-b, each computed with only the work it needs. Without "b", against the rest of the
  scene: nearest ("k", default 1), within ("d"), intersects. {{"effects": ["pairs_within"],
  "d": ...}} lists every pair of shapes within d.
  Motions (version 4): "motion": {{"translation": [x, y, z], "rotation": [x, y, z], "center":
  [x, y, z]}} (each default 0) moves a over t in [0, 1] (x -> center + R(t rotation)(x - center)
  + t translation), "motion_b" moves b. first_contact: the earliest t at which a comes within
  "d" (default 0) of b, or of the scene's shapes ("k" of them, earliest first); closest_approach
  (pairs, where circledist has it): the least distance over the motion. A query with motion asks
  only for these; a line or ray cannot rotate. --plot draws each moving shape at its start, its
  contact and its end.

  .npz scenes (numpy.savez; circledist.write_scene writes both forms) hold the same content:
  format (0-d str), version (0-d int), description (0-d str, optional), shapes (1-d str: the
  entries' names in order), per entry <name>/kind (0-d str), <name>/count (0-d int, batches
  only) and <name>/<field> (float arrays: [count or 1 rows] + (3,) for vectors, () for numbers,
  (m, 3) for control points), queries (0-d str: the JSON text of the query list).

  A bad file: one line on stderr naming the file, the JSON path (or array and index) and what
  was expected; nothing is written; exit status 2. Newer format versions are refused, and so are
  what is no regular file (a FIFO, a device) and counts whose shapes would need more memory than
  there is. In --json's answers a number beyond a double's range (an infinite distance) is null.
"""


def kinds_help() -> str:
    """FORMAT_HELP's paragraph of kinds and their fields, from the module's table of fields:
    kinds with the same fields are named together ("line and ray (origin, direction)")."""
    groups: list = []  # [[kind, ...], fields text]
    for kind, (_, roles) in KINDS.items():
        names = ", ".join(
            f + (f": 2 to {MAX_CONTROL_POINTS} points" if role == "control_points" else "") for f, role in roles.items()
        )
        if groups and groups[-1][1] == names:
            groups[-1][0].append(kind)
        else:
            groups.append([[kind], names])
    text = (
        "Kinds and fields: "
        + ", ".join(f"{' and '.join(kinds)} ({names})" for kinds, names in groups)
        + "; every kind takes an optional sweep >= 0 (a ball, capsule, cylinder, torus, rounded disk, tube)."
    )
    # The width of the rest of FORMAT_HELP (at most 99 columns).
    return textwrap.fill(text, width=96, initial_indent="  ", subsequent_indent="  ", break_on_hyphens=False)


# The format's help with the kinds filled in; "{schema}" is left for format_help (the path where
# the package is installed).
FORMAT_HELP = _FORMAT_TEMPLATE.replace("{kinds}", kinds_help())


def format_help() -> str:
    """The scene format, as --help prints it after the options."""
    return FORMAT_HELP.format(schema=resources.files("circledist").joinpath(SCHEMA_RESOURCE))


@dataclass
class Query:
    """A query as the command line answers it; motion and motion_b (circledist.Motion or None)
    move a and b for the effects first_contact and closest_approach."""

    label: str
    a: str | None
    b: str | None
    effects: list[str]
    d: float | None = None
    k: int = 1
    answers: dict = field(default_factory=dict)
    motion: Any = None
    motion_b: Any = None


def scene_queries(scene: SceneFile) -> list[Query]:
    """The scene's queries, each labelled as the answers name it, with no answer yet."""
    out = []
    for q in scene.queries:
        if q["effects"] == ["pairs_within"]:
            label = q["name"] or "pairs within"
        else:
            label = q["name"] or (f"{q['a']} ~ {q['b']}" if q["b"] is not None else f"{q['a']} ~ scene")
        out.append(
            Query(
                label=label,
                a=q["a"],
                b=q["b"],
                effects=q["effects"],
                d=q["d"],
                k=q["k"] or 1,
                motion=q.get("motion"),
                motion_b=q.get("motion_b"),
            )
        )
    return out


def load_scene(path: str, text: str | None = None) -> SceneFile:
    """Reads and validates a scene file, JSON or .npz (or JSON text); raises SceneError."""
    return read_scene(path, text)


def demo_scene_text() -> str:
    return resources.files("circledist").joinpath("scenes", "demo.json").read_text(encoding="utf-8")
