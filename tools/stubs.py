"""The type stubs of the compiled module, python/circledist/_core.pyi, generated from it.

    python tools/stubs.py          write the stubs of the importable circledist._core
    python tools/stubs.py --check  exit 1, with a diff, when the checked-in file differs

pybind11-stubgen (the `docs` extra) reads the module's signatures and docstrings (src/bindings/);
the one change made to its output: the version's value is left out (`__version__: str`), so
that a version bump does not make the stubs stale. tests/package/test_stubs.py runs the check.
"""

import argparse
import difflib
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CHECKED_IN = ROOT / "python" / "circledist" / "_core.pyi"
MODULE = "circledist._core"


def generate(python=sys.executable, env=None) -> str:
    """The stub text pybind11-stubgen writes for the circledist._core that `python` imports."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run(
            [python, "-m", "pybind11_stubgen", "--exit-code", "-o", out, MODULE],
            check=True,
            capture_output=True,
            text=True,
            env=env,
        )
        text = (pathlib.Path(out) / "circledist" / "_core.pyi").read_text()
    return re.sub(r"^__version__: str = .*$", "__version__: str", text, flags=re.M)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare with the checked-in stubs instead")
    args = parser.parse_args()
    try:
        text = generate()
    except subprocess.CalledProcessError as error:
        print(error.stdout + error.stderr, file=sys.stderr)
        return 1
    if not args.check:
        CHECKED_IN.write_text(text)
        print(f"wrote {CHECKED_IN.relative_to(ROOT)}")
        return 0
    old = CHECKED_IN.read_text()
    if old == text:
        return 0
    sys.stdout.writelines(
        difflib.unified_diff(old.splitlines(True), text.splitlines(True), "checked-in _core.pyi", "generated")
    )
    print("\nthe stubs are stale: regenerate them with `python tools/stubs.py`", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
