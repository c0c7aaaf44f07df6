"""circledist motion demo: a ring-shaped tool (a torus: a circle with a sweep) slides past the
demo scene's shapes, turning as it goes, and the figure animates it: a time slider and a play
button, the closest points to the sensor and the probe at every time, and the time at which the
tool first touches the sensor marked (`first_contact`). Writes an interactive HTML page (plotly.js
inside, no network needed) to the path given, build/motion_demo.html by default; the guide's
picture, docs/guide/motion_demo.png, is this page drawn at the contact
(python -m bench.bench_view --motion-screenshot PATH).

    python examples/motion_demo.py [out.html]
"""

import os
import sys
from importlib import resources

import numpy as np

import circledist as cd

demo = cd.read_scene(resources.files("circledist") / "scenes" / "demo.json")  # the CLI's demo scene
start = [-2.6, -1.1, 0.3]
tool = cd.Circle(start, [1, 0, 0], 0.45, sweep=0.08)
# Over t in [0, 1] the tool moves 5.2 along x and turns a full turn about the z axis through its
# own center (its plane sweeps round as it slides): it meets the sensor on the way.
slide_and_turn = cd.Motion(translation=[5.2, 0, 0], rotation=[0, 0, 2 * np.pi], center=start)
shapes = {**demo.shapes, "tool": tool}


def main(path: str):
    fig = cd.figure(shapes, motions={"tool": slide_and_turn}, pairs=[("tool", "sensor"), ("tool", "probe")])
    fig.write_html(path, auto_play=False)  # press play, or drag the slider, to move the tool
    return fig


if __name__ == "__main__":
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    page = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "motion_demo.html")
    os.makedirs(os.path.dirname(os.path.abspath(page)), exist_ok=True)
    main(os.path.normpath(page))
    print(f"interactive view of the motion written to {os.path.normpath(page)}")
