"""What ships: the sdist holds the sources that build, test and document the package (the tests'
shared cases included) and nothing else (no build outputs, benchmarks, run reports or pictures);
the installed package holds no binding sources and no test cases."""

import os
import tarfile
from importlib import resources

import pytest

cd = pytest.importorskip("circledist")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


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
    for needed in (
        "pyproject.toml",
        "CMakeLists.txt",
        "LICENSE",
        "README.md",
        "src/bindings/module.cpp",
        "src/kernels/pair_unit.cpp",
        "cpp/include/circledist/circledist.hpp",
        "cpp/cmake/circledistConfig.cmake",
        "python/circledist/__init__.py",
        "tests/conftest.py",
        "circledist_cases/__init__.py",
        "circledist_cases/scenes.py",
        "tests/references/reference_round.circle_circle.json",
        "docs/derivations/circle_disk.md",
    ):
        assert needed in sdist_names, needed


def test_sdist_holds_nothing_else(sdist_names):
    unwanted = [
        n
        for n in sdist_names
        if n.startswith((".ci/", "bench/", "build/", ".venv/", "dist/"))
        or n.endswith((".so", ".o", ".pyc", ".png", ".json"))
        and not n.startswith(("python/", "tests/references/"))  # the recorded 50-digit references
    ]
    assert not unwanted, unwanted[:10]


def test_installed_package_has_no_binding_sources():
    names = [p.name for p in resources.files("circledist").iterdir()]
    assert not [n for n in names if n.endswith((".cpp", ".hpp", ".h"))], names


def test_compiled_module_is_at_most_6_mb():
    module = [
        p
        for p in resources.files("circledist").iterdir()
        if p.name.startswith("_core.") and p.name.endswith((".so", ".pyd"))
    ]
    assert len(module) == 1, module
    size = os.path.getsize(str(module[0]))
    assert size <= 6 * 1024 * 1024, f"{module[0].name}: {size / 2**20:.1f} MB"


def _local_includes(path, seen):
    """The files of src/ and cpp/include/ that `path` includes, transitively."""
    import re

    if path in seen:
        return seen
    seen.add(path)
    with open(path) as f:
        for line in f:
            m = re.match(r'\s*#\s*include\s*[<"]([^>"]+)[>"]', line)
            if not m:
                continue
            name = m.group(1)
            for base in (os.path.dirname(path), os.path.join(ROOT, "cpp", "include")):
                candidate = os.path.normpath(os.path.join(base, name))
                if os.path.isfile(candidate):
                    _local_includes(candidate, seen)
                    break
            else:
                seen.add(name)  # a system or dependency header, kept by name
    return seen


def test_pair_units_do_not_include_pybind11():
    """The pair units (src/kernels/pair_unit.cpp, compiled once per precision and root policy)
    hold the queries only: pybind11's headers would add about 7 s to each of them (the build's
    time)."""
    unit = os.path.join(ROOT, "src", "kernels", "pair_unit.cpp")
    if not os.path.isfile(unit):
        pytest.skip("no sources here")
    included = _local_includes(unit, set())
    assert not [n for n in included if "pybind11" in n or n.endswith("Python.h")], sorted(included)
    assert os.path.join(ROOT, "src", "kernels", "pairs.hpp") in included


def test_kernels_do_not_include_pybind11():
    """src/ has two rooms: src/kernels/ (the batch loops, the pair tables, the threads), free of
    pybind11 and Python (no file there reaches them, nor src/bindings/), and src/bindings/, the
    module's translation units, which include the kernels."""
    kernels = os.path.join(ROOT, "src", "kernels")
    if not os.path.isdir(os.path.join(ROOT, "src")):
        pytest.skip("no sources here")
    files = sorted(os.path.join(kernels, n) for n in os.listdir(kernels)) if os.path.isdir(kernels) else []
    assert files, "no src/kernels/"
    for path in files:
        included = _local_includes(path, set())
        assert not [n for n in included if "pybind11" in n or n.endswith("Python.h")], (path, sorted(included))
        assert not [n for n in included if os.sep + "bindings" + os.sep in n], (path, sorted(included))


def test_binding_sources_include_before_code():
    """Every file of src/ names its includes at its top, before any code: no header is included
    half-way down a translation unit (each binding topic is a unit of its own)."""
    import re

    src = os.path.join(ROOT, "src")
    if not os.path.isdir(src):
        pytest.skip("no sources here")
    paths = [os.path.join(d, n) for d, _, names in os.walk(src) for n in names if n.endswith((".cpp", ".hpp"))]
    assert paths
    for path in paths:
        code_seen = False
        with open(path) as f:
            for number, line in enumerate(f, 1):
                text = line.strip()
                if re.match(r"#\s*include\b", text):
                    assert not code_seen, f"{os.path.relpath(path, ROOT)}:{number}: an include after code"
                elif text and not text.startswith(("//", "#")):
                    code_seen = True


def test_installed_distribution_holds_the_package_only():
    """What the wheel installed (its RECORD): the compiled module, the Python files, the stub, the
    demo scene; no sources, no build outputs."""
    import importlib.metadata

    files = [str(f) for f in importlib.metadata.files("circledist") or []]
    if not files:
        pytest.skip("circledist is not installed from a wheel here")
    package = [f for f in files if f.startswith("circledist/")]
    for needed in (
        "circledist/__init__.py",
        "circledist/scene.py",
        "circledist/cli.py",
        "circledist/py.typed",
        "circledist/_core.pyi",
        "circledist/scenes/demo.json",
    ):
        assert needed in package, needed
    assert [f for f in package if f.startswith("circledist/_core.") and f.endswith((".so", ".pyd"))]
    assert not [f for f in files if f.endswith((".cpp", ".hpp", ".h", ".o", ".cmake"))], files
    assert not [f for f in files if f.startswith("circledist_cases")], files  # the tests' cases stay home


@pytest.mark.skipif(not os.environ.get("CIRCLEDIST_WHEEL_ALONE"), reason="tools/run.sh's wheel_alone step only")
def test_wheel_alone_has_no_compiler_and_no_build_requirements():
    """The wheel_alone step of tools/run.sh runs these tests where a user without a compiler or
    Eigen would: this checks that it does (else its passing would prove nothing)."""
    import importlib.util
    import shutil

    assert not [c for c in ("c++", "g++", "gcc", "cc", "clang++", "cmake") if shutil.which(c)]
    for module in ("pybind11", "cmeel", "scikit_build_core"):
        assert importlib.util.find_spec(module) is None, module
