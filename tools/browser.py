"""A headless Chromium (Debian's chromium and chromium-driver, driven by selenium) that opens the
pages circledist.figure writes and waits until plotly has drawn them: for the browser tests
(tests/api/test_view_browser.py) and the guide's screenshot (python -m bench.bench_view).

    browser = Browser(width, height)   # or None from Browser.missing(): why there is none
    browser.open(path)                 # waits for the plot
    browser.animate(name)              # an animated figure shown at its frame of that name
    browser.png(), browser.console_errors(), browser.run("return ...")
    browser.close()
"""

from __future__ import annotations

import importlib.util
import pathlib
import shutil
import time

# Debian's names for the browser and its driver (tools/run.sh installs them for the test task).
CHROMIUM = ("chromium", "chromium-browser")
DRIVER = ("chromedriver",)
INSTALL = "apt-get install chromium chromium-driver, pip install selenium; tools/run.sh test installs them"


def _which(names) -> str | None:
    return next((path for path in map(shutil.which, names) if path), None)


def missing() -> str | None:
    """Why no browser can be started here (what to install), or None."""
    lacking = [
        what
        for what, found in (
            ("selenium", importlib.util.find_spec("selenium") is not None),
            ("chromium", _which(CHROMIUM)),
            ("chromium-driver", _which(DRIVER)),
        )
        if not found
    ]
    return f"no {', '.join(lacking)} here ({INSTALL})" if lacking else None


class Browser:
    """One headless Chromium window of a fixed size, software WebGL (no GPU needed)."""

    def __init__(self, width: int = 800, height: int = 800):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service

        options = webdriver.ChromeOptions()
        options.binary_location = _which(CHROMIUM)
        for argument in (
            "--headless=new",
            "--no-sandbox",  # as root (CI): Chromium refuses its sandbox
            "--disable-dev-shm-usage",
            f"--window-size={width},{height}",
            "--hide-scrollbars",
            "--force-device-scale-factor=1",
            "--use-angle=swiftshader",  # WebGL in software: plotly's 3-D scenes need it
            "--enable-unsafe-swiftshader",
        ):
            options.add_argument(argument)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self.driver = webdriver.Chrome(options=options, service=Service(_which(DRIVER)))

    def open(self, path, timeout: float = 30.0) -> None:
        """Opens a page and waits until every plotly plot on it has drawn (its WebGL canvas made
        and a frame painted after plotly's last redraw)."""
        self.driver.get(pathlib.Path(path).resolve().as_uri())
        ready = (
            "const plots = document.querySelectorAll('.js-plotly-plot');"
            "return plots.length > 0 && [...plots].every(p => p._fullLayout && p.querySelector('canvas'));"
        )
        deadline = time.monotonic() + timeout
        while not self.driver.execute_script(ready):
            if time.monotonic() > deadline:
                raise TimeoutError(f"{path}: no plot drawn within {timeout} s")
            time.sleep(0.05)
        # Two animation frames: the scene's first WebGL frame is painted after plotly returns.
        self.driver.execute_async_script(
            "const done = arguments[0]; requestAnimationFrame(() => requestAnimationFrame(() => done()));"
        )

    def animate(self, frame: str) -> str:
        """Shows the first plot's frame of that name (Plotly.animate, at once) and waits until it
        is painted; returns the frame plotly then says is current (or why the animation was
        refused)."""
        return self.driver.execute_async_script(
            """
            const done = arguments[arguments.length - 1], gd = document.querySelector('.js-plotly-plot');
            const now = {mode: 'immediate', frame: {duration: 0, redraw: true}, transition: {duration: 0}};
            Plotly.animate(gd, [arguments[0]], now).then(
              () => requestAnimationFrame(() => requestAnimationFrame(() => done(gd._fullLayout._currentFrame))),
              error => done('refused: ' + error));
            """,
            frame,
        )

    def redraw_seconds(self, frames: int = 5) -> float:
        """Seconds per WebGL frame of the first plot's 3-D scene (what each step of rotating the
        view costs): frames redraws, each waited for by reading a pixel back. Reads plotly.js's
        scene object (not a public API): NaN where it is not there."""
        seconds = self.driver.execute_script(
            """
            const scene = document.querySelector('.js-plotly-plot')._fullLayout.scene._scene;
            const plot = scene && scene.glplot, pixel = new Uint8Array(4);
            if (!plot || typeof plot.redraw !== 'function') return null;
            const start = performance.now();
            for (let i = 0; i < arguments[0]; i++) {
              plot.redraw();
              plot.gl.readPixels(0, 0, 1, 1, plot.gl.RGBA, plot.gl.UNSIGNED_BYTE, pixel);
            }
            return (performance.now() - start) / arguments[0] / 1000;
            """,
            frames,
        )
        return float("nan") if seconds is None else seconds

    def run(self, script: str, *arguments):
        return self.driver.execute_script(script, *arguments)

    def png(self) -> bytes:
        return self.driver.get_screenshot_as_png()

    def console_errors(self) -> list:
        """The console's errors (and uncaught exceptions) since the last call."""
        return [e["message"] for e in self.driver.get_log("browser") if e["level"] == "SEVERE"]

    def close(self) -> None:
        self.driver.quit()
