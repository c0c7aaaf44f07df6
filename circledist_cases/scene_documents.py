"""Scene files as documents: a valid scene of every kind and effect, and bad ones, each with the
JSON path and the words its one-line error must name (the command line's tests, the scene-file
and schema tests)."""

SCENE = {
    "format": "circledist-scene",
    "version": 3,  # it holds an annulus (and an arc)
    "description": "test scene",
    "shapes": [
        {"name": "ring", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1.0},
        {"name": "rail", "kind": "line", "origin": [-3, 1, 0.5], "direction": [1, 0, 0]},
        {"name": "coin", "kind": "disk", "center": [3, 0, 0], "normal": [1, 0, 1], "radius": 0.5, "sweep": 0.1},
        {"name": "probe", "kind": "segment", "p0": [3, 0, -1], "p1": [3, 0, 1]},
        {"name": "tip", "kind": "point", "p": [0, 0, 2]},
        {"name": "cable", "kind": "bezier", "control_points": [[-2, -2, 1], [0, 0, 3], [2, -2, 1]]},
        {
            "name": "hook",
            "kind": "arc",
            "center": [0, 3, 0],
            "normal": [0, 0, 1],
            "radius": 1.0,
            "start": [1, 0, 0],
            "angle": 4.0,
        },
        {
            "name": "washer",
            "kind": "annulus",
            "center": [0, -3, 0],
            "normal": [0, 1, 1],
            "inner_radius": 0.4,
            "outer_radius": 1.0,
        },
    ],
    "queries": [
        {"a": "rail", "b": "ring", "effects": ["intersects", "within", "distance", "closest_points"], "d": 0.6},
        {"name": "coin vs probe", "a": "coin", "b": "probe", "effects": ["intersects", "closest_points"]},
        {"a": "ring", "effects": ["nearest"], "k": 2},
        {"a": "coin", "effects": ["within"], "d": 3.0},
        {"a": "cable", "b": "ring", "effects": ["distance"]},
        {"a": "hook", "b": "ring", "effects": ["intersects", "distance", "closest_points"]},
        {"a": "washer", "b": "rail", "effects": ["intersects", "distance", "closest_points"]},
    ],
}


HEAD = {"format": "circledist-scene", "version": 3}  # the current version (annuli need it)
HEAD1 = {"format": "circledist-scene", "version": 1}
HEAD2 = {"format": "circledist-scene", "version": 2}
# (label, file content, the JSON path, what was expected): each must appear in the one-line message.
BAD = [
    ("not json", "{", "", "not valid JSON: Expecting property name"),
    ("NaN is not JSON", '{"format": "circledist-scene", "version": 1, "x": NaN}', "", "NaN is not a JSON number"),
    ("not an object", "[1, 2]", "$", "expected an object"),
    ("no format", {"shapes": SCENE["shapes"]}, "$", "missing field 'format'"),
    (
        "wrong format",
        {"format": "scene", "version": 1, "shapes": SCENE["shapes"]},
        "$.format",
        'expected "circledist-scene", got "scene"',
    ),
    (
        "no version",
        {"format": "circledist-scene", "shapes": SCENE["shapes"]},
        "$",
        "missing field 'version' (this circledist reads versions 1 to 3)",
    ),
    (
        "newer version",
        {**HEAD, "version": 4, "shapes": SCENE["shapes"]},
        "$.version",
        "version 4 is newer than this circledist reads (versions 1 to 3): upgrade circledist",
    ),
    (
        "bad version",
        {**HEAD, "version": "1", "shapes": SCENE["shapes"]},
        "$.version",
        'expected one of 1, 2, 3, got "1"',
    ),
    (
        "arc in a version 1 file",
        {**HEAD1, "shapes": SCENE["shapes"]},
        "$.shapes[6].kind (shape 'hook')",
        "kind 'arc' needs format version 2 or later, the file says version 1",
    ),
    (
        "annulus in a version 2 file",
        {**HEAD2, "shapes": SCENE["shapes"]},
        "$.shapes[7].kind (shape 'washer')",
        "kind 'annulus' needs format version 3 or later, the file says version 2",
    ),
    ("no shapes", {**HEAD, "queries": []}, "$", "missing field 'shapes'"),
    (
        "bad radius",
        {**HEAD, "shapes": [{"name": "r", "kind": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": -1}]},
        "$.shapes[0].radius (shape 'r')",
        "expected a number >= 0, got -1",
    ),
    (
        "missing field",
        {**HEAD, "shapes": [{"name": "r", "kind": "disk", "center": [0, 0, 0], "radius": 1}]},
        "$.shapes[0] (shape 'r')",
        "missing field 'normal'",
    ),
    (
        "zero normal",
        {**HEAD, "shapes": [{"name": "r", "kind": "disk", "center": [0, 0, 0], "normal": [0, 0, 0], "radius": 1}]},
        "$.shapes[0].normal",
        "expected a non-zero vector",
    ),
    (
        "unknown kind",
        {**HEAD, "shapes": [{"name": "x", "kind": "torus"}]},
        "$.shapes[0].kind (shape 'x')",
        'expected one of "point", "line", "ray", "segment", "circle", "disk", "bezier", "arc", "annulus", got "torus"',
    ),
    (
        "unknown field",
        {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0], "colour": "red"}]},
        "$.shapes[0].colour (shape 'p')",
        "unknown field (allowed: name, kind, count, p, sweep)",
    ),
    (
        "short vector",
        {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0]}]},
        "$.shapes[0].p (shape 'p')",
        "expected a vector of 3 numbers [x, y, z], got [0, 0]",
    ),
    (
        "string in vector",
        {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, "1", 0]}]},
        "$.shapes[0].p[1] (shape 'p')",
        'expected a number, got "1"',
    ),
    (
        "overflowing number",
        '{"format": "circledist-scene", "version": 1, "shapes": [{"name": "p", "kind": "point", '
        '"p": [0, 1e400, 0]}]}',
        "$.shapes[0].p[1]",
        "expected a finite number",
    ),
    (
        "negative sweep",
        {**HEAD, "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0], "sweep": -2}]},
        "$.shapes[0].sweep (shape 'p')",
        "expected a number >= 0, got -2",
    ),
    (
        "duplicate name",
        {
            **HEAD,
            "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0]}, {"name": "p", "kind": "point", "p": [1, 0, 0]}],
        },
        "$.shapes[1].name",
        'expected a name of its own, got "p"',
    ),
    (
        "bracket in name",
        {**HEAD, "shapes": [{"name": "p[0]", "kind": "point", "p": [0, 0, 0]}]},
        "$.shapes[0].name",
        "expected a name: a non-empty string without '[', ']' or '/'",
    ),
    (
        "bad bezier",
        {**HEAD, "shapes": [{"name": "c", "kind": "bezier", "control_points": [[0, 0, 0]]}]},
        "$.shapes[0].control_points (shape 'c')",
        "expected 2 to 8 control points",
    ),
    (
        "arc angle 0",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "h",
                    "kind": "arc",
                    "center": [0, 0, 0],
                    "normal": [0, 0, 1],
                    "radius": 1,
                    "start": [1, 0, 0],
                    "angle": 0,
                }
            ],
        },
        "$.shapes[0].angle",
        "expected an angle in (0, 2 pi], got 0.0",
    ),
    (
        "arc angles past 2 pi",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "h",
                    "kind": "arc",
                    "count": 2,
                    "center": [0, 0, 0],
                    "normal": [0, 0, 1],
                    "radius": 1,
                    "start": [1, 0, 0],
                    "angle": [1, 7],
                }
            ],
        },
        "$.shapes[0].angle[1]",
        "expected an angle in (0, 2 pi], got 7.0",
    ),
    (
        "arc start along its normal",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "h",
                    "kind": "arc",
                    "center": [0, 0, 0],
                    "normal": [0, 0, 1],
                    "radius": 1,
                    "start": [0, 0, 2],
                    "angle": 1,
                }
            ],
        },
        "$.shapes[0]",
        "Arc: start is parallel to normal",
    ),
    (
        "annulus inner past outer",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "w",
                    "kind": "annulus",
                    "count": 2,
                    "center": [0, 0, 0],
                    "normal": [0, 0, 1],
                    "inner_radius": [0.5, 2],
                    "outer_radius": 1,
                }
            ],
        },
        "$.shapes[0]",
        "Annulus: inner_radius[1] exceeds outer_radius[1] (2 > 1)",
    ),
    (
        "annulus negative inner radius",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "w",
                    "kind": "annulus",
                    "center": [0, 0, 0],
                    "normal": [0, 0, 1],
                    "inner_radius": -0.5,
                    "outer_radius": 1,
                }
            ],
        },
        "$.shapes[0].inner_radius (shape 'w')",
        "expected a number >= 0, got -0.5",
    ),
    (
        "batch column too short",
        {**HEAD, "shapes": [{"name": "beads", "kind": "point", "count": 3, "p": [[0, 0, 0], [1, 0, 0]]}]},
        "$.shapes[0].p",
        "expected 3 vectors (the batch's count) or 1, got 2",
    ),
    (
        "batch column not a column",
        {**HEAD, "shapes": [{"name": "beads", "kind": "point", "count": 2, "p": 5}]},
        "$.shapes[0].p (shape 'beads')",
        "expected a vector [x, y, z] (one for all) or an array of count vectors, got 5",
    ),
    (
        "batch radius",
        {
            **HEAD,
            "shapes": [
                {"name": "r", "kind": "disk", "count": 2, "center": [0, 0, 0], "normal": [0, 0, 1], "radius": -1}
            ],
        },
        "$.shapes[0].radius (shape 'r')",
        "expected a number >= 0 (one for all) or an array of count of them, got -1",
    ),
    (
        "batch zero normal",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "rings",
                    "kind": "circle",
                    "count": 2,
                    "center": [0, 0, 0],
                    "normal": [[0, 0, 1], [0, 0, 0]],
                    "radius": 1,
                }
            ],
        },
        "$.shapes[0].normal[1]",
        "expected a non-zero vector",
    ),
    (
        "batch curves of two degrees",
        {
            **HEAD,
            "shapes": [
                {
                    "name": "c",
                    "kind": "bezier",
                    "count": 2,
                    "control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [1, 0, 0], [2, 1, 0]]],
                }
            ],
        },
        "$.shapes[0].control_points[1]",
        "expected 2 control points as curve 0 has",
    ),
    (
        "bad count",
        {**HEAD, "shapes": [{"name": "b", "kind": "point", "count": 0, "p": [0, 0, 0]}]},
        "$.shapes[0].count (shape 'b')",
        "expected the number of shapes in the batch: an integer >= 1, got 0",
    ),
    (
        "unknown shape in query",
        {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "b": "nope", "effects": ["distance"]}]},
        "$.queries[0].b",
        'expected the name of a shape of the scene, got "nope"',
    ),
    (
        "whole batch in query",
        {
            **HEAD,
            "shapes": SCENE["shapes"] + [{"name": "beads", "kind": "point", "count": 2, "p": [[0, 0, 0], [1, 0, 0]]}],
            "queries": [{"a": "beads", "b": "ring", "effects": ["distance"]}],
        },
        "$.queries[0].a",
        "expected one shape: 'beads' is a batch of 2, name one as beads[i] with i from 0 to 1",
    ),
    (
        "batch index out of range",
        {
            **HEAD,
            "shapes": SCENE["shapes"] + [{"name": "beads", "kind": "point", "count": 2, "p": [[0, 0, 0], [1, 0, 0]]}],
            "queries": [{"a": "beads[2]", "b": "ring", "effects": ["distance"]}],
        },
        "$.queries[0].a",
        "expected an index from 0 to 1 (batch 'beads' has 2 shapes), got 2",
    ),
    (
        "unknown effect",
        {
            **HEAD,
            "shapes": SCENE["shapes"],
            "queries": [{"name": "q", "a": "ring", "b": "rail", "effects": ["volume"]}],
        },
        "$.queries[0].effects[0]",
        'expected one of "intersects"',
    ),
    (
        "scene effect on a pair",
        {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "b": "rail", "effects": ["nearest"]}]},
        "$.queries[0].effects",
        "expected effects against a pair (with 'b'): intersects, within, distance, " 'closest_points; got "nearest"',
    ),
    (
        "within without d",
        {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "b": "rail", "effects": ["within"]}]},
        "$.queries[0]",
        "missing field 'd'",
    ),
    # (No "no query for the pair" case: since Bezier against Bezier, every pair of the scene
    # file's kinds has a query; scenefile.py keeps the check for kinds to come.)
    (
        "bad k",
        {**HEAD, "shapes": SCENE["shapes"], "queries": [{"a": "ring", "effects": ["nearest"], "k": 0}]},
        "$.queries[0].k",
        "expected an integer >= 1, got 0",
    ),
]
