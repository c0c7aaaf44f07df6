"""The previous release's C++ scalar loop, for the benchmark's "against the previous release"
column: bench/bench_queries.cpp and the headers as they were at that release, compiled with the
flags of the current build's bench_queries, then timed alternately with the current program on
the same input file.

    python -m bench.baseline [--build-dir build/cpp]    # builds it, prints the binary's path

Both programs time a kind by the same loop (bench_queries.cpp's protocol has not changed since the
release); the release's program reads the same queries under the names it knows (a kind of
inputs it did not have, such as a line in an arc's plane, under its shapes' kind: line-arc), and
skips a pair of shapes it did not have. The ratio of a kind is the
median, over rounds, of the current time over the release's time in the same round: a slow spell
of a shared machine lasts seconds and slows both sides of a round alike.
"""

from __future__ import annotations

import argparse
import io
import shlex
import subprocess
import sys
import tarfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
# The previous release and its last commit (the commit before CHANGELOG.md began the Unreleased
# section). When a release is made, these name it.
RELEASE = "0.1.0"
COMMIT = "1537550e8a1a6de0e8162f91cd8c31f4a4100bc2"
SOURCES = ("cpp/include", "bench/bench_queries.cpp", "bench/bench_kinds.hpp")


def _compile_command(build_dir: Path) -> list[str]:
    """The current bench_queries' compile command (ninja's), without its dependency-file,
    object and source arguments."""
    out = subprocess.run(
        ["ninja", "-C", str(build_dir), "-t", "commands", "bench/bench_queries"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    line = next(x for x in out.splitlines() if "bench_queries.cpp" in x and " -c " in x)
    args, keep = shlex.split(line), []
    skip = 0
    for arg in args:
        if skip:
            skip -= 1
        elif arg in ("-MT", "-MF", "-o"):
            skip = 1
        elif arg in ("-MD", "-c") or arg.endswith("bench_queries.cpp"):
            continue
        else:
            keep.append(arg)
    return keep


def build(build_dir: Path = ROOT / "build" / "cpp", commit: str = COMMIT) -> Path | None:
    """The release's bench_queries binary (built once per commit under build/bench-baseline/), or
    None with the reason printed where it cannot be built (no git history, no ninja build)."""
    home = ROOT / "build" / "bench-baseline" / commit
    binary = home / "bench_queries"
    if binary.is_file():
        return binary
    try:
        archive = subprocess.run(
            ["git", "-C", str(ROOT), "archive", "--format=tar", commit, *SOURCES], capture_output=True, check=True
        ).stdout
        command = _compile_command(build_dir)
    except (subprocess.CalledProcessError, FileNotFoundError, StopIteration) as e:
        print(f"!! release {RELEASE} ({commit[:10]}) not built: {e}")
        return None
    src = home / "src"
    src.mkdir(parents=True, exist_ok=True)
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        tar.extractall(src, filter="data")
    current_include = f"-I{ROOT / 'cpp' / 'include'}"
    command = [f"-I{src / 'cpp' / 'include'}" if a == current_include else a for a in command]
    if f"-I{src / 'cpp' / 'include'}" not in command:
        print(f"!! release {RELEASE}: the current compile command has no {current_include}")
        return None
    print(f"== building release {RELEASE}'s bench_queries ({commit[:10]})", flush=True)
    subprocess.run([*command, "-o", str(binary) + ".part", str(src / "bench" / "bench_queries.cpp")], check=True)
    Path(str(binary) + ".part").rename(binary)
    return binary


def _times(binary: Path, inp: Path, outp: Path, seconds: float) -> list:
    """Each kind's time in the order of the input file (None where the program skipped it)."""
    proc = subprocess.run(
        [str(binary), str(inp), str(outp), "--min-time", str(seconds)], capture_output=True, text=True, check=True
    )
    lines = [line.split() for line in proc.stdout.splitlines()]
    return [float(p[3]) if p[0] == "T" else None for p in lines if p and p[0] in ("T", "S")]


def alternate(current: Path, release: Path, inputs: tuple, names: list, workdir: Path, rounds: int, seconds: float):
    """{name: [current / release time of each round]} for the kinds both programs time. `inputs`:
    the input files of the two programs, holding the same queries in the same order (the
    release's under the names it knows); `names`: the kinds in that order."""
    ratios: dict = {}
    outp = Path(workdir) / "baseline-out.bin"
    for k in range(rounds):
        now = _times(current, inputs[0], outp, seconds)
        then = _times(release, inputs[1], outp, seconds)
        for name, a, b in zip(names, now, then):
            if a is not None and b is not None:
                ratios.setdefault(name, []).append(a / b)
        print(f"   round {k + 1}/{rounds}: {sum(x is not None for x in then)} kinds at {RELEASE}", flush=True)
    return ratios


def median_ratio(ratios: list[float]) -> float:
    return float(np.median(ratios))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", type=Path, default=ROOT / "build" / "cpp")
    args = parser.parse_args()
    binary = build(args.build_dir)
    if binary is None:
        sys.exit(1)
    print(binary)


if __name__ == "__main__":
    main()
