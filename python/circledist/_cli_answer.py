"""The command line's second step: every query of a validated scene answered, each effect with a
call of its own (so each costs only the work it needs), as plain numbers, names and lists."""

from __future__ import annotations

from . import _core
from ._cli_load import Query, scene_queries
from .scenefile import SceneFile


def answer(scene: SceneFile) -> list[Query]:
    """Computes each query's effects, each with its own call (and only the work it needs)."""
    world = scene.scene()
    queries = scene_queries(scene)
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
                elif e == "first_contact":
                    within = 0.0 if q.d is None else q.d
                    q.answers[e] = _moving(_core.first_contact(A, B, q.motion, q.motion_b, within=within))
                elif e == "closest_approach":
                    import circledist

                    q.answers[e] = _moving(circledist.closest_approach(A, B, q.motion, q.motion_b))
        else:
            for e in q.effects:
                if e == "nearest":
                    q.answers[e] = [{"name": n, "distance": d} for n, d in world.nearest(q.a, q.k)]
                elif e == "within":
                    q.answers[e] = world.within(q.a, q.d)
                elif e == "intersects":
                    q.answers[e] = world.within(q.a, 0.0)
                elif e == "first_contact":
                    hits = world.first_contact(q.a, q.motion, within=0.0 if q.d is None else q.d, k=q.k)
                    q.answers[e] = [{"name": h.name, **_moving(h)} for h in hits]
    return queries


def _moving(r) -> dict:
    """A contact (or closest approach) of single shapes as plain numbers: time (inf where there
    is none), distance, the closest points and their parameters (NaN where there is none),
    unique."""
    return {
        "time": float(r.time),
        "distance": float(r.distance),
        "point_a": [float(x) for x in r.point_a],
        "point_b": [float(x) for x in r.point_b],
        "param_a": [float(x) for x in r.param_a],
        "param_b": [float(x) for x in r.param_b],
        "unique": bool(r.unique),
    }
