"""Scene files as documents: a valid scene of every kind and effect, and bad ones, each with the
JSON path and the words its one-line error must name (the command line's tests, the scene-file
and schema tests)."""

SCENE = {
    "format": "circledist-scene",
    "version": 4,  # it holds motions (and an annulus, and an arc)
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
        {"a": "tip", "b": "ring", "motion": {"translation": [0, 1, -2]}, "effects": ["first_contact"], "d": 0.1},
        {
            "name": "swinging probe",
            "a": "probe",
            "motion": {"translation": [-3, 0, 0], "rotation": [0, 0, 3.0], "center": [1.5, 0, 0]},
            "effects": ["first_contact"],
            "k": 2,
        },
    ],
}


HEAD = {"format": "circledist-scene", "version": 4}  # the current version (motions need it)
HEAD1 = {"format": "circledist-scene", "version": 1}
HEAD2 = {"format": "circledist-scene", "version": 2}
HEAD3 = {"format": "circledist-scene", "version": 3}
SHAPES = SCENE["shapes"]


def _motion_query(**query):
    """A version-4 document of the scene's shapes with one query."""
    return {**HEAD, "shapes": SHAPES, "queries": [query]}


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
        "missing field 'version' (this circledist reads versions 1 to 4)",
    ),
    (
        "newer version",
        {**HEAD, "version": 5, "shapes": SCENE["shapes"]},
        "$.version",
        "version 5 is newer than this circledist reads (versions 1 to 4): upgrade circledist",
    ),
    (
        "bad version",
        {**HEAD, "version": "1", "shapes": SCENE["shapes"]},
        "$.version",
        'expected one of 1, 2, 3, 4, got "1"',
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
        "expected effects against a pair (with 'b'): intersects, within, distance, "
        'closest_points, first_contact, closest_approach; got "nearest"',
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
    (
        "a motion in a version 3 file",
        {**HEAD3, "shapes": SHAPES[:1], "queries": [{"a": "ring", "motion": {}, "effects": ["first_contact"]}]},
        "$.queries[0].motion",
        "a query's motion needs format version 4 or later, the file says version 3",
    ),
    (
        "a motion effect in a version 3 file",
        {**HEAD3, "shapes": SHAPES[:1], "queries": [{"a": "ring", "effects": ["first_contact"]}]},
        "$.queries[0].effects",
        "effect 'first_contact' needs format version 4 or later, the file says version 3",
    ),
    (
        "first_contact without a motion",
        _motion_query(a="tip", b="ring", effects=["first_contact"]),
        "$.queries[0]",
        "missing field 'motion' (the motion of 'a') or 'motion_b' (of 'b'), which first_contact needs",
    ),
    (
        "first_contact against the scene without a motion",
        _motion_query(a="tip", effects=["first_contact"]),
        "$.queries[0]",
        "missing field 'motion' (the motion of 'a'), which first_contact needs",
    ),
    (
        "motion_b without b",
        _motion_query(a="tip", effects=["first_contact"], motion_b={}),
        "$.queries[0].motion_b",
        "not expected: motion_b moves 'b', and the query has no 'b'",
    ),
    (
        "a motion no effect uses",
        _motion_query(a="tip", b="ring", motion={"translation": [1, 0, 0]}, effects=["distance"]),
        "$.queries[0].motion",
        "not expected: only first_contact and closest_approach take a motion",
    ),
    (
        "a motion of b no effect uses",
        _motion_query(a="tip", b="ring", motion_b={"translation": [1, 0, 0]}, effects=["closest_points"]),
        "$.queries[0].motion_b",
        "not expected: only first_contact and closest_approach take a motion",
    ),
    (
        "motion effects beside static ones",
        _motion_query(a="tip", b="ring", motion={}, effects=["first_contact", "distance"]),
        "$.queries[0].effects",
        "expected first_contact without distance: the motion effects are a query of their own",
    ),
    (
        "a rotating line",
        _motion_query(a="rail", b="ring", motion={"rotation": [0, 0, 1]}, effects=["first_contact"]),
        "$.queries[0].motion.rotation",
        "expected no rotation: 'rail' is a line, which cannot rotate",
    ),
    (
        "a rotating line as b",
        _motion_query(a="ring", b="rail", motion_b={"rotation": [0, 1, 0]}, effects=["first_contact"]),
        "$.queries[0].motion_b.rotation",
        "expected no rotation: 'rail' is a line, which cannot rotate",
    ),
    (
        "an unknown motion field",
        _motion_query(a="tip", b="ring", motion={"speed": [1, 0, 0]}, effects=["first_contact"]),
        "$.queries[0].motion.speed",
        "unknown field (allowed: translation, rotation, center)",
    ),
    (
        "a motion's vector of 2",
        _motion_query(a="tip", b="ring", motion={"translation": [1, 0]}, effects=["first_contact"]),
        "$.queries[0].motion.translation",
        "expected a vector of 3 numbers [x, y, z], got [1, 0]",
    ),
    (
        "a motion that is no object",
        _motion_query(a="tip", b="ring", motion=[1, 0, 0], effects=["first_contact"]),
        "$.queries[0].motion",
        "expected a motion: an object with translation, rotation and center",
    ),
    (
        "an infinite motion",
        '{"format": "circledist-scene", "version": 4, "shapes": [{"name": "p", "kind": "point", "p": [0, 0, 0]}, '
        '{"name": "q", "kind": "point", "p": [1, 0, 0]}], "queries": [{"a": "p", "b": "q", '
        '"motion": {"center": [0, 1e999, 0]}, "effects": ["first_contact"]}]}',
        "$.queries[0].motion.center[1]",
        "expected a finite number (within a double's range), got",
    ),
    (
        "k on a pair's first_contact",
        _motion_query(a="tip", b="ring", motion={}, effects=["first_contact"], k=2),
        "$.queries[0].k",
        "not expected: only nearest and first_contact against the scene take k",
    ),
    (
        "closest_approach against the scene",
        _motion_query(a="tip", motion={}, effects=["closest_approach"]),
        "$.queries[0].effects",
        "expected effects against the rest of the scene (without 'b'): nearest, within, intersects, "
        'first_contact; got "closest_approach"',
    ),
]
