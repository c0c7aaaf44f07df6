"""What ships: the sdist holds the sources that build, test and document the package and nothing
else (no build outputs, benchmarks, run reports or pictures); the installed package holds no
binding sources."""

import os
import tarfile
from importlib import resources

import pytest

cd = pytest.importorskip("circledist")

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


@pytest.fixture(scope="module")
def sdist_names(tmp_path_factory):
    build = pytest.importorskip("scikit_build_core.build")
    out = tmp_path_factory.mktemp("sdist")
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        name = build.build_sdist(str(out))
    finally:
        os.chdir(cwd)
    with tarfile.open(os.path.join(out, name)) as tar:
        return {member.split("/", 1)[1] for member in tar.getnames() if "/" in member}


def test_sdist_holds_the_sources(sdist_names):
    for needed in ("pyproject.toml", "CMakeLists.txt", "LICENSE", "README.md", "src/_core.cpp",
                   "src/pair_unit.cpp", "cpp/include/circledist/circledist.hpp",
                   "cpp/cmake/circledistConfig.cmake", "python/circledist/__init__.py",
                   "tests/conftest.py", "docs/circle_disk.md"):
        assert needed in sdist_names, needed


def test_sdist_holds_nothing_else(sdist_names):
    unwanted = [n for n in sdist_names
                if n.startswith((".ci/", "bench/", "build/", ".venv/", "dist/"))
                or n.endswith((".so", ".o", ".pyc", ".png", ".json")) and not n.startswith("python/")]
    assert not unwanted, unwanted[:10]


def test_installed_package_has_no_binding_sources():
    names = [p.name for p in resources.files("circledist").iterdir()]
    assert not [n for n in names if n.endswith((".cpp", ".hpp", ".h"))], names
