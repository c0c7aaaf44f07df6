"""The pages circledist.figure and `python -m circledist --html` write, opened in a real browser
(headless Chromium driven by selenium: tools/browser.py): they draw without a JavaScript error, a
ring seen from above is a ring of coloured pixels around its centre (not a blank page), hovering
over a shape shows its name, and the page holds every shape's name. One browser for the module.

Without Chromium, its driver or selenium these tests skip, saying what to install; under CI
(tools/run.sh test installs them) they fail instead, so that a run never passes by skipping them."""

import io
import os

import numpy as np
import pytest

import circledist as cd
from circledist import cli
from tools import browser as chromium

pytest.importorskip("plotly", reason="plotly is the view extra (pip install 'circledist[view]')")
pytestmark = [pytest.mark.slow, pytest.mark.serial]  # a browser: seconds of CPU, WebGL in software

SIZE = 600  # the window and the plot, pixels (square)


@pytest.fixture(scope="module")
def browser():
    why = chromium.missing()
    if why is not None:
        if os.environ.get("CI"):
            pytest.fail(f"the browser tests cannot run under CI: {why}")
        pytest.skip(f"the browser tests need a browser: {why}")
    b = chromium.Browser(SIZE, SIZE)
    yield b
    b.close()


def pixels(png: bytes) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def coloured(image: np.ndarray) -> np.ndarray:
    """Pixels of some colour: neither white nor grey (plotly's axes, grid and text are grey)."""
    return image.max(axis=2) - image.min(axis=2) > 40


def top_view(fig) -> None:
    """The figure seen from straight above (orthographic), nothing else drawn: no axes, legend
    or title, the plot filling the window."""
    hidden = {"visible": False}
    fig.update_layout(
        width=SIZE,
        height=SIZE,
        showlegend=False,
        margin={"l": 0, "r": 0, "t": 0, "b": 0},
        scene={
            "xaxis": hidden,
            "yaxis": hidden,
            "zaxis": hidden,
            "camera": {
                "eye": {"x": 0, "y": 0, "z": 2},
                "up": {"x": 0, "y": 1, "z": 0},
                "projection": {"type": "orthographic"},
            },
        },
    )


def ring_page(path) -> None:
    """An annulus seen from straight above, nothing else drawn (no toolbar either)."""
    fig = cd.figure({"ring": cd.Annulus([0, 0, 0], [0, 0, 1], 0.6, 1.0)})
    top_view(fig)
    fig.write_html(path, include_plotlyjs=True, config={"displayModeBar": False})


def test_a_ring_seen_from_above_is_a_ring_of_coloured_pixels(browser, tmp_path):
    ring_page(tmp_path / "ring.html")
    browser.open(tmp_path / "ring.html")
    assert browser.console_errors() == []
    image = pixels(browser.png())
    mask = coloured(image)
    assert mask.sum() > 0.02 * mask.size, "a blank page"
    ys, xs = np.nonzero(mask)
    # The ring's centre and outer radius from its pixels' extent; seen from above it is round.
    cx, cy = (xs.min() + xs.max()) / 2, (ys.min() + ys.max()) / 2
    width, height = xs.max() - xs.min(), ys.max() - ys.min()
    assert abs(width - height) <= 0.03 * width, (width, height)
    radius = width / 2
    assert radius > 0.15 * SIZE, "drawn as a speck"
    yy, xx = np.mgrid[: mask.shape[0], : mask.shape[1]]
    r = np.hypot(xx - cx, yy - cy) / radius
    band = mask[(r > 0.66) & (r < 0.94)].mean()  # the annulus: inner radius 0.6 of the outer
    hole = mask[r < 0.54].mean()
    outside = mask[r > 1.06].mean()
    assert band > 0.95 and hole < 0.01 and outside < 0.01, (band, hole, outside)
    angle = np.arctan2(yy - cy, xx - cx)[mask & (r > 0.6)]
    assert len(np.unique(np.floor((angle + np.pi) / (np.pi / 6)))) == 12, "not all the way round"
    # Hovering over the ring (the mouse moved there: plotly picks in WebGL) gives its name.
    from selenium.webdriver.common.action_chains import ActionChains

    browser.run(
        "window.hovered = []; document.querySelector('.js-plotly-plot')"
        ".on('plotly_hover', d => window.hovered.push(...d.points.map(p => p.text)));"
    )
    canvas = browser.driver.find_element("css selector", ".js-plotly-plot canvas")
    box = browser.run("return arguments[0].getBoundingClientRect().toJSON()", canvas)
    dx, dy = cx + 0.8 * radius - box["left"] - box["width"] / 2, cy - box["top"] - box["height"] / 2
    ActionChains(browser.driver).move_to_element_with_offset(canvas, int(dx), int(dy)).pause(0.2).move_by_offset(
        1, 0
    ).pause(0.5).perform()
    hovered = browser.run("return window.hovered")
    assert hovered and set(hovered) == {"ring"}, hovered


def test_the_demo_page_draws_every_shape_without_errors(browser, tmp_path):
    page = tmp_path / "demo.html"
    assert cli.main(["--no-plot", "--html", str(page)]) == 0
    browser.open(page)
    assert browser.console_errors() == []
    names = browser.run(
        "const gd = document.querySelector('.js-plotly-plot');"
        "return gd.data.map(t => [t.name, [...new Set(t.text || [])]]);"
    )
    scene = cli.load_scene("demo.json", cli.demo_scene_text())
    for entry in scene.entries:
        hovered = [set(text) for name, text in names if name == entry.name]
        assert hovered and all(text == {entry.name} for text in hovered), (entry.name, hovered)
    pairs = [text for name, text in names if name == "closest points"]
    assert any(any(t.startswith("cable \u2013 ring: distance ") for t in text) for text in pairs)
    mask = coloured(pixels(browser.png()))
    assert mask.mean() > 0.02, "a blank page"


def test_an_animated_page_moves_its_moving_shape(browser, tmp_path):
    """A ring sliding from left to right below a disk at rest, seen from above: the page draws
    without errors and holds the figure's frames; stepping to the last frame (Plotly.animate)
    moves the ring's pixels from the left half to the right one and leaves the disk's alone."""
    shapes = {"disk": cd.Disk([0, 1.2, 0], [0, 0, 1], 0.5), "ring": cd.Annulus([-1.5, -0.9, 0], [0, 0, 1], 0.3, 0.5)}
    fig = cd.figure(shapes, motions={"ring": cd.Motion(translation=[3, 0, 0])}, frames=6)
    top_view(fig)
    page = tmp_path / "motion.html"
    fig.write_html(page, include_plotlyjs=True, auto_play=False, config={"displayModeBar": False})
    browser.open(page)
    assert browser.console_errors() == []
    frames = browser.run(
        "return document.querySelector('.js-plotly-plot')._transitionData._frames.map(f => [f.name, f.traces]);"
    )
    assert frames == [[f.name, list(f.traces)] for f in fig.frames]
    before = coloured(pixels(browser.png()))
    result = browser.animate(fig.frames[-1].name)
    assert result == fig.frames[-1].name
    assert browser.console_errors() == []
    after = coloured(pixels(browser.png()))
    # The scene's middle row: the disk (y = 1.2) is drawn above it, the ring (y = -0.9) below.
    rows = np.nonzero(before.any(axis=1))[0]
    middle = (rows.min() + rows.max()) // 2
    assert np.array_equal(before[:middle], after[:middle]), "the disk at rest moved"
    centre = SIZE // 2
    left_before, right_before = before[middle:, :centre].sum(), before[middle:, centre:].sum()
    left_after, right_after = after[middle:, :centre].sum(), after[middle:, centre:].sum()
    assert left_before > 1000 and right_before == 0, (left_before, right_before)
    assert right_after > 1000 and left_after == 0, (left_after, right_after)
    assert abs(right_after - left_before) < 0.1 * left_before  # the same ring, moved
