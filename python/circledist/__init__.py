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
    nearest,
    pairs_within,
    reset_stats,
    stats,
    within,
)
from .scene import Scene
from .scenefile import SceneFileError, read_scene, write_scene

__all__ = [
    "Bezier",
    "Circle",
    "ClosestPoints",
    "Disk",
    "Line",
    "Point",
    "Ray",
    "Scene",
    "SceneFileError",
    "Segment",
    "Shape",
    "__version__",
    "closest_points",
    "distance",
    "distance_if_within",
    "intersects",
    "nearest",
    "pairs_within",
    "read_scene",
    "reset_stats",
    "stats",
    "within",
    "write_scene",
]
