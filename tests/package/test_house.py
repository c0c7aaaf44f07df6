"""The house rules a test can check (the tests' own rooms: test_layout.py): no source file over
1,000 lines anywhere, no history (issue numbers, dates, machine paths, load averages) in code,
tests or docs, and the pair map of docs/design/pairs.md naming every pair the module answers, with
files that exist."""

import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def tracked(*patterns):
    try:
        out = subprocess.run(["git", "ls-files", "-z", *patterns], cwd=ROOT, capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("not a git checkout")
    return [ROOT / p for p in out.stdout.decode().split("\0") if p]


SOURCES = ("*.py", "*.hpp", "*.cpp", "*.h", "*.sh", "*.cmake", "CMakeLists.txt", "*.toml", "*.rst", "*.md")


def test_no_source_file_over_a_thousand_lines():
    long = {
        str(p.relative_to(ROOT)): n
        for p in tracked(*SOURCES)
        if p.name != "CHANGELOG.md" and (n := p.read_text(errors="replace").count("\n")) > 1000
    }
    assert not long, f"split these files (at most 1,000 lines each): {long}"


PROVENANCE = {
    "an issue number": re.compile(r"\bissues? #?\d+", re.I),
    "a date": re.compile(r"\b20\d\d-[01]\d-[0-3]\d\b"),
    "a machine path": re.compile(r"(?<![\w.])/(?:work|tmp|home|root)/"),
    "a load average": re.compile(r"\bload (?:average|about|~|\d)", re.I),
    "a before/after measurement": re.compile(r"\d[\d.,]* ?(?:->|\u2192) ?\d[\d.,]* ?(?:[KMG]B|[mnu\u00b5]?s)\b"),
    "a byte count": re.compile(r"\b\d{1,3}(?:,\d{3}){2,} bytes\b"),
    "a branch's history": re.compile(r"\(branch \w+\)|\bfrom branch \w+", re.I),
}


def test_no_history_in_code_tests_or_docs():
    this = Path(__file__).resolve()  # this file names the patterns it looks for
    found = {}
    for p in tracked(*SOURCES, ".ci/*"):
        if p.name == "CHANGELOG.md" or p.resolve() == this or not p.is_file():
            continue
        text = p.read_text(errors="replace")
        hits = [f"{what}: {m.group(0)!r}" for what, pattern in PROVENANCE.items() for m in pattern.finditer(text)]
        if hits:
            found[str(p.relative_to(ROOT))] = hits[:3]
    assert not found, f"history belongs in CHANGELOG.md and commit messages: {found}"


FAMILY = {"line": "linear", "ray": "linear", "segment": "linear"}


def test_pair_map_names_every_pair_and_its_files():
    cd = pytest.importorskip("circledist")
    text = (ROOT / "docs" / "design" / "pairs.md").read_text()
    rows = [line for line in text.splitlines() if line.startswith("| ") and not line.startswith("| Pair")]
    named = {}
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        pair = tuple(sorted(cells[0].split("-")))
        named[pair] = cells
        paths = re.findall(r"`((?:cpp|tests|circledist_cases)/[^`]+)`", row)
        assert len(paths) == 4, f"{cells[0]}: a header, a C++ test, a Python test and a reference, each by its path"
        for path in paths:
            assert (ROOT / path).is_file(), f"docs/design/pairs.md, {cells[0]}: no file {path}"
        header = Path(paths[0])
        assert (
            header.parent.as_posix() == "cpp/include/circledist" and tuple(sorted(header.stem.split("_"))) == pair
        ), f"{cells[0]}: the header is named for the pair ({paths[0]})"
    answered = {tuple(sorted(FAMILY.get(k.lower(), k.lower()) for k in p)) for p in cd._core._query_kinds()}
    missing = answered - set(named)
    assert not missing, f"pairs the module answers that docs/design/pairs.md does not map: {sorted(missing)}"
