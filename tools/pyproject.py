"""What tools/run.sh reads from pyproject.toml, the one place it is written.

python tools/pyproject.py missing EXTRA... [-- TOOL...]
    the build requirements, dependencies, the extras' requirements and the tools not installed
    yet (or installed in a version pyproject.toml does not accept), space-separated
python tools/pyproject.py wheel-tests
    the test files of cibuildwheel's test-command, space-separated
"""

from __future__ import annotations

import re
import sys
from importlib import metadata

try:
    import tomllib
except ImportError:  # Python < 3.11: pip's own copy
    from pip._vendor import tomli as tomllib
try:
    from packaging.requirements import Requirement
except ImportError:
    from pip._vendor.packaging.requirements import Requirement


def load() -> dict:
    with open("pyproject.toml", "rb") as f:
        return tomllib.load(f)


def missing(args: list[str]) -> list[str]:
    pyproject = load()
    cut = args.index("--") if "--" in args else len(args)
    wanted = pyproject["build-system"]["requires"] + pyproject["project"]["dependencies"]
    for extra in args[:cut]:
        wanted += pyproject["project"]["optional-dependencies"][extra]
    out = []
    for text in wanted + args[cut + 1 :]:
        req = Requirement(text)
        if req.marker is not None and not req.marker.evaluate({"extra": ""}):
            continue
        try:
            ok = req.specifier.contains(metadata.version(req.name), prereleases=True)
        except metadata.PackageNotFoundError:
            ok = False
        spec = req.name + ("[" + ",".join(sorted(req.extras)) + "]" if req.extras else "") + str(req.specifier)
        if not ok and spec not in out:
            out.append(spec)
    return out


def wheel_tests() -> list[str]:
    return re.findall(r"tests/[\w/]+\.py", load()["tool"]["cibuildwheel"]["test-command"])


if __name__ == "__main__":
    command, rest = sys.argv[1], sys.argv[2:]
    print(" ".join(missing(rest) if command == "missing" else wheel_tests()))
