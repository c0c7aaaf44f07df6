"""The type stubs: python/circledist/_core.pyi is what pybind11-stubgen generates from the built
module (tools/stubs.py), and the installed package ships it with its py.typed marker."""

import difflib
import importlib.util
import os
import pathlib
import runpy
import subprocess
import sys

import pytest

import circledist

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUBS = runpy.run_path(str(ROOT / "tools" / "stubs.py"))


def test_installed_package_is_typed():
    """PEP 561: the marker and the stubs of the compiled module sit next to it."""
    package = pathlib.Path(circledist.__file__).parent
    assert (package / "py.typed").is_file()
    assert (package / "_core.pyi").read_text() == (ROOT / "python" / "circledist" / "_core.pyi").read_text()


@pytest.mark.skipif(
    importlib.util.find_spec("pybind11_stubgen") is None,
    reason="pybind11-stubgen is not installed (the `docs` extra; tools/run.sh test installs it)",
)
def test_checked_in_stubs_are_generated_from_the_module():
    # The subprocess imports the circledist this test imports (PYTHONPATH as here).
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    try:
        generated = STUBS["generate"](sys.executable, env)
    except subprocess.CalledProcessError as error:
        pytest.fail(f"pybind11-stubgen failed:\n{error.stdout}{error.stderr}")
    checked_in = STUBS["CHECKED_IN"].read_text()
    diff = "".join(
        difflib.unified_diff(
            checked_in.splitlines(True), generated.splitlines(True), "checked-in _core.pyi", "generated"
        )
    )
    assert not diff, f"the stubs are stale: regenerate them with `python tools/stubs.py`\n{diff}"


def test_stubs_describe_the_public_api():
    """Every compiled public name has a typed entry (what IDEs and type checkers read)."""
    text = (ROOT / "python" / "circledist" / "_core.pyi").read_text()
    for name in circledist.__all__:
        if name in (
            "Scene",
            "SceneFileError",
            "read_scene",
            "write_scene",
            "figure",
        ):  # pure Python, typed where defined
            continue
        assert f"class {name}" in text or f"def {name}(" in text or f"{name}: str" in text, name
    assert "precision: typing.Literal['float32', 'float64', 'longdouble'] | None = None" in text
    assert "-> object" not in text and ": object" not in text
