"""The kinds, entry points, precisions and solvers the fuzz draws from, and the address-space
limit its children run under.
"""

from __future__ import annotations

KINDS = ("point", "line", "ray", "segment", "circle", "disk", "bezier", "arc", "annulus")
ROUNDS = ("circle", "disk", "arc", "annulus")  # the kinds with a center: concentric pairs
ENTRY_POINTS = ("distance", "closest_points", "within", "intersects", "distance_if_within")
PRECISIONS = (None, "float32", "float64", "longdouble")
SOLVERS = (None, "bracketing", "companion", "polished", "eigen")
FILE_MEMORY = 1 << 30


def _limit_memory(limit=FILE_MEMORY):
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
