"""circledist demo: distances and closest points for a small set of shapes."""

import numpy as np

import circledist as cd

ring = cd.Circle(center=[0, 0, 0], normal=[0, 0, 1], radius=1.0)
coin = cd.Disk(center=[3, 0, 0], normal=[1, 0, 1], radius=0.5)
shapes = {
    "point above the ring's axis": cd.Point([0, 0, 2]),
    "line grazing the ring 1e-9 above": cd.Line(origin=[-5, 1, 1e-9], direction=[1, 0, 0]),
    "line along the ring's axis": cd.Line(origin=[0, 0, 5], direction=[0, 0, -1]),
    "ray pointing away": cd.Ray(origin=[0, 3, 1], direction=[0, 1, 0]),
    "segment through the coin": cd.Segment(p0=[3, 0, -1], p1=[3, 0, 1]),
}

np.set_printoptions(precision=6, suppress=True)
for target_name, target in (("ring", ring), ("coin", coin)):
    print(f"against the {target_name}:")
    for name, shape in shapes.items():
        r = cd.closest_points(shape, target)
        print(
            f"  {name:34s} distance {r.distance:.12g}  at {r.point_a} -> {r.point_b}"
            f"{'' if r.unique else '  (not unique)'}"
        )

# A batch: one line against 5 circles of growing radius, computed in one call.
radii = np.linspace(0.5, 2.5, 5)
circles = cd.Circle(np.zeros((5, 3)), [0, 0, 1], radii)
print("one line against 5 circles:", cd.distance(cd.Line([0, 1.5, 0.25], [1, 0, 0]), circles))

# A scene shipped inside the package (circledist/scenes/demo.json): each query names only the
# effects it wants (intersects, within, distance, closest_points, nearest), and nothing else is
# computed. The same as running `python -m circledist`; the picture goes to the path given
# (the README's is docs/guide/demo_scene.png), build/demo_scene.png by default.
import os  # noqa: E402 (after the first part of the demo, which needs none)
import sys  # noqa: E402 (after the first part of the demo, which needs none)

from circledist import cli  # noqa: E402 (after the first part of the demo, which needs none)

print()
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
picture = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "demo_scene.png")
os.makedirs(os.path.dirname(os.path.abspath(picture)), exist_ok=True)
sys.exit(cli.main(["--plot", os.path.normpath(picture)]))
