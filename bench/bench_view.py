"""What circledist.figure costs for large batches: for 10^3, 10^4 and 10^5 random disks (and as
many circles), the time figure() takes, the size of the self-contained HTML page (plotly.js
inline), the rim points of the reduced-detail rule, and, where Chromium and selenium are
installed (tools/browser.py), how long a headless browser takes to open and draw the page (the
first row: a page of one point, plotly.js's own share) and one WebGL frame of it (what each step
of rotating the view costs; headless Chromium draws WebGL in software, on the CPU, so a browser
with a GPU draws a frame in a fraction of that time). The last row is an animated figure, the
motion example's (examples/motion_demo.py: the demo scene and a moving tool, at the default
frame count), its figure() time with the writing of its page.
Prints a table; writes nothing unless --screenshot PATH is given, which saves the demo scene's
page as a PNG (the guide's picture, docs/guide/view_demo.png), or --motion-screenshot PATH, the
motion example's page at its first contact (docs/guide/motion_demo.png).

    python -m bench.bench_view [--sizes 1000 10000 100000] [--no-browser] [--screenshot PATH]
                               [--motion-screenshot PATH]
"""

import argparse
import os
import platform
import runpy
import sys
import tempfile
import time

if not __package__:  # run as a file: its sibling one_core would not import
    sys.exit("bench/bench_view.py: run it from the repository's root as python -m bench.bench_view")

from . import one_core  # noqa: F401  (before NumPy: one BLAS thread)

import numpy as np

import circledist as cd
from circledist import cli, view

from tools import browser as chromium


def shapes(kind: str, n: int, rng):
    """n shapes of radius 0.2..1 at a fixed density (about one per 8 unit^3), random normals."""
    side = 2.0 * n ** (1 / 3)
    cls = cd.Disk if kind == "disk" else cd.Circle
    return cls(rng.uniform(-side / 2, side / 2, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.2, 1.0, n))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    ap.add_argument("--kinds", nargs="+", default=["disk", "circle"], choices=["disk", "circle"])
    ap.add_argument("--no-browser", action="store_true", help="figure time and page size only")
    ap.add_argument("--screenshot", metavar="PATH", help="save the demo scene's page, drawn, as a PNG")
    ap.add_argument(
        "--motion-screenshot", metavar="PATH", help="save the motion example's page at its first contact as a PNG"
    )
    args = ap.parse_args()

    why = chromium.missing()
    browser = None if args.no_browser or why else chromium.Browser(1000, 800)
    if browser is None and not args.no_browser:
        print(f"(no browser times: {why})")
    print(f"{platform.machine()}, {os.cpu_count()} logical cores, Python {platform.python_version()}")
    print(
        f"rule: rim points = min({view.MAX_RIM}, {view.VERTEX_BUDGET} / n - 2), one marker per shape where that "
        f"is below {view.MIN_RIM} (rim 0 in the table); above {view.FULL_LIMIT} shapes outlines only, names on one "
        "marker per shape"
    )
    print(f"motion: the motion example, {view.FRAMES} time steps and its contact; figure() s includes write_html")
    print(
        f"{'shapes':>8} {'kind':>7} {'rim':>4} {'traces':>6} {'figure() s':>10} {'page MB':>8} {'open s':>7} "
        f"{'redraw s':>8}"
    )
    rng = np.random.default_rng(2026)
    example = runpy.run_path(os.path.join(os.path.dirname(__file__), "..", "examples", "motion_demo.py"))
    try:
        with tempfile.TemporaryDirectory() as folder:
            rows = [(1, "point", cd.Point([0, 0, 0]))]  # first, plotly.js's own load and first draw
            rows += [(n, kind, shapes(kind, n, rng)) for n in args.sizes for kind in args.kinds]
            motion_page = os.path.join(folder, "motion.html")
            rows.append((len(example["shapes"]), "motion", None))  # last: the animated figure
            for n, kind, batch in rows:
                start = time.perf_counter()
                if batch is None:  # the motion example: figure() and write_html, in its two lines
                    page, fig = motion_page, example["main"](motion_page)
                    made = time.perf_counter() - start
                else:
                    fig = cd.figure({kind: batch})
                    made = time.perf_counter() - start
                    page = os.path.join(folder, f"{kind}{n}.html")
                    fig.write_html(page, include_plotlyjs=True)
                size = os.path.getsize(page) / 1e6
                opened = redrawn = note = ""
                if browser is not None:
                    start = time.perf_counter()
                    browser.open(page, timeout=600)
                    opened = f"{time.perf_counter() - start:.2f}"
                    redrawn = f"{browser.redraw_seconds():.3f}"
                    errors = browser.console_errors()
                    if errors:
                        note = f"  ({len(errors)} console errors: {errors[0][:60]})"
                rim = view.rim_points(n if batch is not None else n - 1 + len(fig.frames))  # the tool: once a frame
                print(
                    f"{n:>8} {kind:>7} {rim:>4} {len(fig.data):>6} {made:>10.2f} {size:>8.1f} {opened:>7} "
                    f"{redrawn:>8}{note}"
                )
            if args.screenshot:
                if browser is None:
                    sys.exit(f"--screenshot needs a browser: {why or 'not with --no-browser'}")
                page = os.path.join(folder, "demo.html")
                cli.main(["--no-plot", "--html", page])
                browser.open(page)
                with open(args.screenshot, "wb") as f:
                    f.write(browser.png())
                print(f"the demo scene's page drawn: {args.screenshot}")
            if args.motion_screenshot:
                if browser is None:
                    sys.exit(f"--motion-screenshot needs a browser: {why or 'not with --no-browser'}")
                browser.open(motion_page)
                steps = browser.run("return document.querySelector('.js-plotly-plot').layout.sliders[0].steps;")
                contact = next(s["args"][0][0] for s in steps if s["label"].endswith("contact"))
                shown = browser.animate(contact)
                if shown != contact or browser.console_errors():
                    sys.exit(f"the motion example's page did not show its contact frame: {shown}")
                with open(args.motion_screenshot, "wb") as f:
                    f.write(browser.png())
                print(f"the motion example's page drawn at its first contact: {args.motion_screenshot}")
    finally:
        if browser is not None:
            browser.close()


if __name__ == "__main__":
    main()
