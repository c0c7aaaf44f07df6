"""The README's examples run as written: the Python block here, the C++ block through ctest's
consumer project (it builds examples/quick.cpp, which must be the README's block verbatim)."""

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
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


def test_ci_runs_the_readme_test_command():
    assert "bash tools/run.sh test" in README
    assert "tools/run.sh test" in (ROOT / ".ci" / "run").read_text()
