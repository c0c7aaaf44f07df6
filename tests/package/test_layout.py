"""The tests' own house: every test file in a room named for its purpose, none over 1,000 lines,
the markers tools/run.sh selects on registered in pyproject.toml, and the files cibuildwheel runs
on every wheel present."""

import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
TESTS = ROOT / "tests"
ROOMS = {"api", "pairs", "accuracy", "package"}

try:
    import tomllib
except ImportError:  # Python < 3.11: pip's own copy
    from pip._vendor import tomli as tomllib


def pyproject():
    with open(ROOT / "pyproject.toml", "rb") as f:
        return tomllib.load(f)


def test_every_test_file_is_in_a_room():
    files = sorted(TESTS.rglob("test_*.py"))
    assert files
    outside = [str(f.relative_to(TESTS)) for f in files if f.parent.parent != TESTS or f.parent.name not in ROOMS]
    assert not outside, outside


def test_no_test_file_is_over_1000_lines():
    long = {
        str(f.relative_to(ROOT)): n
        for f in TESTS.rglob("*.py")
        if (n := len(f.read_text(encoding="utf-8").splitlines())) > 1000
    }
    assert not long, long


def test_the_markers_run_sh_selects_on_are_registered():
    registered = {line.split(":")[0] for line in pyproject()["tool"]["pytest"]["ini_options"]["markers"]}
    script = (ROOT / "tools" / "run.sh").read_text()
    used = set(re.findall(r"-m \"(?:not )?(\w+)", script)) | set(
        re.findall(r"pytest_on_every_core \"not (\w+)\"", script)
    )
    assert used, "tools/run.sh selects tests by no marker"
    assert used <= registered, used - registered
    assert {"slow", "serial"} <= registered


def test_the_wheel_tests_exist():
    out = subprocess.run(
        [sys.executable, str(ROOT / "tools" / "pyproject.py"), "wheel-tests"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    assert out and all((ROOT / name).is_file() for name in out), out
