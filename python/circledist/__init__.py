"""circledist: exact distances and closest points between circles, disks, lines, rays, segments
and points in 3D, single or batched (NumPy broadcasting)."""

from ._core import (
    Bezier,
    Circle,
    ClosestPoints,
    Disk,
    Line,
    Point,
    Ray,
    Segment,
    Shape,
    __version__,
    closest_points,
    distance,
    distance_if_within,
    intersects,
    reset_stats,
    stats,
    within,
)
from .scene import Scene

__all__ = [
    "Bezier",
    "Circle",
    "ClosestPoints",
    "Disk",
    "Line",
    "Point",
    "Ray",
    "Scene",
    "Segment",
    "Shape",
    "__version__",
    "closest_points",
    "distance",
    "distance_if_within",
    "intersects",
    "reset_stats",
    "stats",
    "within",
]
