"""The version is written once (CMakeLists.txt's project()); the package metadata, the module,
the command line and the CMake package (the ctest consumer checks that one) all report it."""

import importlib.metadata
import os
import re
import subprocess
import sys

import pytest

cd = pytest.importorskip("circledist")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def written_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(circledist VERSION ([0-9][0-9.]*)", f.read()).group(1)


def test_module_and_metadata_report_the_written_version():
    version = written_version()
    assert cd.__version__ == version
    assert cd._core.__version__ == version
    assert importlib.metadata.version("circledist") == version


def test_command_line_version():
    out = subprocess.run(
        [sys.executable, "-m", "circledist", "--version"], capture_output=True, text=True, timeout=120, check=True
    )
    assert out.stdout.strip() == f"circledist {written_version()}"
