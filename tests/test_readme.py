"""The README's examples run as written: the Python block here, the C++ block through ctest's
consumer project (it builds examples/quick.cpp, which must be the README's block verbatim)."""

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()


def blocks(language):
    return re.findall(rf"```{language}\n(.*?)```", README, flags=re.S)


def test_python_examples_run():
    """Every Python block, in order, in one namespace (later blocks may use earlier names)."""
    codes = blocks("python")
    assert codes
    namespace = {}
    for code in codes:
        exec(compile(code, "README.md", "exec"), namespace)


def test_cpp_example_is_the_consumer_source():
    (code,) = blocks("cpp")
    assert code == (ROOT / "examples" / "quick.cpp").read_text()


def test_pair_table_offers_every_registered_pair():
    """The README's table of kind pairs ticks every pair the module registers (either order), and no
    other: its rows and columns are the families (lines, rays and segments are one)."""
    import circledist

    family = {"Point": "point", "Line": "line, ray, segment", "Ray": "line, ray, segment",
              "Segment": "line, ray, segment", "Circle": "circle", "Disk": "disk", "Arc": "arc",
              "Annulus": "annulus", "Bezier": "Bézier curve"}
    section = README.split("## What it answers", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("|")]
    columns = [cell.strip() for cell in rows[0].strip("|").split("|")][1:]
    ticked = set()
    for row in rows[2:]:
        cells = [cell.strip() for cell in row.strip("|").split("|")]
        name = cells[0].strip("*")
        ticked |= {frozenset((name, column)) for column, cell in zip(columns, cells[1:]) if cell == "✓"}
    registered = {frozenset((family[a], family[b])) for a, b in circledist._core._query_kinds()}
    assert ticked == registered


def test_ci_runs_the_readme_test_command():
    assert "bash tools/run.sh test" in README
    assert "tools/run.sh test" in (ROOT / ".ci" / "run").read_text()
