"""The API reference (docs/api) builds warning-free from the installed package, as
`bash tools/run.sh docs` builds it, and shows what the docstrings say."""

import html as html_module
import importlib.util
import os
import pathlib
import re
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
NEEDED = ("sphinx", "numpydoc", "myst_parser")

# One Sphinx build, seconds long, behind every test here.
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def html(tmp_path_factory):
    missing = [name for name in NEEDED if importlib.util.find_spec(name) is None]
    if missing:
        pytest.skip(f"{', '.join(missing)} not installed (the `docs` extra; tools/run.sh test installs it)")
    out = tmp_path_factory.mktemp("docs")
    # The subprocess imports the circledist this test imports (PYTHONPATH as here).
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    run = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
                          str(ROOT / "docs" / "api"), str(out)], capture_output=True, text=True, env=env)
    assert run.returncode == 0, f"the docs build failed or warned:\n{run.stdout}{run.stderr}"
    return out


def text_of(path):
    """The page's text, tags and entities removed, Sphinx's curly quotes straightened."""
    return html_module.unescape(re.sub(r"<[^>]+>", "", path.read_text())).replace("\u2019", "'")


def test_reference_documents_every_public_object(html):
    import circledist

    index = text_of(html / "index.html")
    for name in circledist.__all__:
        if name != "__version__":
            assert f"circledist.{name}" in index, name
    assert "precision: Literal['float32', 'float64', 'longdouble'] | None = None" in index
    assert "circledist.Circle(center: numpy.typing.ArrayLike, normal: numpy.typing.ArrayLike" in index
    for section in ("Parameters", "Returns", "Raises", "Examples"):
        assert section in index


def test_derivations_and_references_are_included(html):
    for page in ("line_circle", "line_disk", "circle_circle", "circle_disk", "disk_disk", "bezier", "bezier_linear",
                 "arc", "annulus",
                 "references"):
        source = (ROOT / "docs" / f"{page}.md").read_text()
        title = source.splitlines()[0].lstrip("# ").strip()
        assert title in text_of(html / "derivations" / f"{page}.html"), page
        assert f"derivations/{page}.html" in (html / "index.html").read_text(), page
    if (ROOT / "docs" / "line_disk.png").exists():  # not in the sdist
        assert (html / "_images" / "line_disk.png").is_file()
    assert "Distance Between Line and Circle or Disk in 3D" in text_of(html / "derivations" / "references.html")
