"""The documentation: the Sphinx site (docs/, with the API reference) builds warning-free from the
installed package, as `bash tools/run.sh docs` builds it, and shows what the docstrings say; the
Markdown pages (README, CONTRIBUTING, CHANGELOG, docs/) link only to what exists, every table
renders and the guide's examples run. That the docs, like the code, hold no history is
test_house.py's."""

import html as html_module
import importlib.util
import os
import pathlib
import re
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
NEEDED = ("sphinx", "numpydoc", "myst_parser")
PICTURES = (DOCS / "derivations" / "line_disk.png").exists()  # False in the sdist
DERIVATIONS = (
    "line_circle",
    "line_disk",
    "circle_circle",
    "circle_disk",
    "disk_disk",
    "bezier",
    "bezier_linear",
    "bezier_bezier",
    "arc",
    "annulus",
    "references",
)


def markdown_pages():
    return [ROOT / "README.md", ROOT / "CONTRIBUTING.md", ROOT / "CHANGELOG.md", *sorted(DOCS.rglob("*.md"))]


def without_code(text):
    """The text with fenced code blocks and inline code removed (links and tables are outside them)."""
    text = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    return re.sub(r"`[^`\n]*`", "", text)


def page_id(path):
    return str(path.relative_to(ROOT))


@pytest.fixture(scope="module")
def html(tmp_path_factory):
    missing = [name for name in NEEDED if importlib.util.find_spec(name) is None]
    if missing:
        pytest.skip(f"{', '.join(missing)} not installed (the `docs` extra; tools/run.sh test installs it)")
    out = tmp_path_factory.mktemp("docs")
    # The subprocess imports the circledist this test imports (PYTHONPATH as here).
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    run = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html", str(DOCS), str(out)],
        capture_output=True,
        text=True,
        env=env,
    )
    assert run.returncode == 0, f"the docs build failed or warned:\n{run.stdout}{run.stderr}"
    return out


def text_of(path):
    """The page's text, tags and entities removed, Sphinx's curly quotes straightened."""
    return html_module.unescape(re.sub(r"<[^>]+>", "", path.read_text())).replace("\u2019", "'")


@pytest.mark.slow  # the Sphinx build behind the html fixture: seconds
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


@pytest.mark.slow
def test_every_shelf_is_in_the_site(html):
    index = (html / "index.html").read_text()
    for page in DOCS.rglob("*.md"):
        target = page.relative_to(DOCS).with_suffix(".html").as_posix()
        assert (html / target).is_file(), target
        assert target in index, f"{target} is not in the index's tables of contents"
    for page in DERIVATIONS:
        source = (DOCS / "derivations" / f"{page}.md").read_text()
        title = source.splitlines()[0].lstrip("# ").strip()
        assert title in text_of(html / "derivations" / f"{page}.html"), page
    if (DOCS / "derivations" / "line_disk.png").exists():  # not in the sdist
        assert (html / "_images" / "line_disk.png").is_file()
    assert "Distance Between Line and Circle or Disk in 3D" in text_of(html / "derivations" / "references.html")


def test_the_shelves():
    """docs/ holds the Sphinx root and the four shelves; run records (JSON) live in build/, not here."""
    loose = [p.name for p in DOCS.iterdir() if p.is_file()]
    assert len(loose) <= 6, loose
    assert {"conf.py", "index.rst"} <= set(loose)
    assert {p.name for p in DOCS.iterdir() if p.is_dir()} == {"guide", "derivations", "design", "reports"}
    assert not list(DOCS.rglob("*.json")), "run records go to build/reports/"
    for page in DERIVATIONS:
        assert (DOCS / "derivations" / f"{page}.md").is_file(), page


@pytest.mark.parametrize("page", markdown_pages(), ids=page_id)
def test_relative_links_resolve(page):
    text = without_code(page.read_text())
    links = re.findall(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", text)
    broken = []
    for link in links:
        if re.match(r"[a-z]+:", link) or link.startswith("#"):
            continue
        target = (page.parent / link.split("#", 1)[0]).resolve()
        if target.suffix == ".png" and not PICTURES:
            continue  # the sdist leaves the pictures out (pyproject.toml's sdist.exclude)
        if not target.exists():
            broken.append(link)
    assert not broken, f"{page_id(page)}: links to nothing: {broken}"


@pytest.mark.parametrize("page", markdown_pages(), ids=page_id)
def test_every_table_renders(page):
    """A Markdown table is a header row, a delimiter row with as many cells, then its rows."""
    lines = without_code(page.read_text()).splitlines()
    delimiter = re.compile(r"^\|(\s*:?-{3,}:?\s*\|)+\s*$")
    cells = lambda line: len(re.split(r"(?<!\\)\|", line.strip().strip("|")))  # noqa: E731
    row = lambda line: line.startswith("|") and line.rstrip().endswith("|")  # noqa: E731 (not indented code)
    i = 0
    while i < len(lines):
        if row(lines[i]):
            start = i
            while i < len(lines) and row(lines[i]):
                i += 1
            table = lines[start:i]
            assert len(table) >= 2 and delimiter.match(
                table[1].strip()
            ), f"{page_id(page)} line {start + 1}: a table without a delimiter row: {table[0][:80]}"
            assert cells(table[1]) == cells(table[0]), f"{page_id(page)} line {start + 1}: delimiter cells"
        i += 1


@pytest.mark.parametrize("page", sorted((DOCS / "guide").glob("*.md")), ids=page_id)
def test_guide_examples_run(page):
    """Every Python block of a guide page, in order, in one namespace per page."""
    codes = re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S)
    if "cd.figure(" in "".join(codes):
        pytest.importorskip("plotly", reason="plotly is the view extra (pip install 'circledist[view]')")
    if "import circledist.dask" in "".join(codes):
        pytest.importorskip("dask")
        pytest.importorskip("distributed")
    namespace = {}
    for code in codes:
        exec(compile(code, str(page.relative_to(ROOT)), "exec"), namespace)
