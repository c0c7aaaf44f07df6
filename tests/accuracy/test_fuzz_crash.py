"""The fixed-seed slice of the crash-isolating fuzz (tools/fuzz_crash.py): every kind
pair, entry point, precision and solver, magnitudes from 1e-300 to 1e300, degenerate shapes,
batch layouts; each chunk in a child process, so a crash fails this test with its input named
instead of taking pytest down. The long mode is `bash tools/run.sh fuzz`."""

import json
import pathlib
import subprocess
import sys

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _fuzz_module():
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        import fuzz_crash
    finally:
        sys.path.pop(0)
    return fuzz_crash


@pytest.mark.slow
@pytest.mark.serial
def test_fuzz_slice_finds_nothing(tmp_path):
    report = tmp_path / "fuzz.json"
    proc = subprocess.run(
        [
            sys.executable,
            str(ROOT / "tools" / "fuzz_crash.py"),
            "--cases",
            "6000",
            "--seed",
            "15",
            "--chunk",
            "3000",
            "--report",
            str(report),
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    summary = json.loads(report.read_text())
    assert summary["cases"] == 6000
    assert (summary["crashes"], summary["hangs"], summary["findings"]) == (0, 0, 0), json.dumps(
        summary["examples"][:3], indent=1
    )
    assert proc.returncode == 0


@pytest.mark.slow
@pytest.mark.serial
def test_hostile_files_slice_finds_nothing(tmp_path):
    """The command line on hostile files (tools/fuzz_crash.py --files): FIFOs and devices, zip
    bombs, lying .npy headers, JSON nested near the recursion limit, lone surrogates, counts beyond
    memory, unsupported compression, foreign members, truncated and flipped files; each in its own
    process held to 1 GiB and 60 s, answered with one clean error line and exit status 2. The slice
    runs each class twice."""
    fuzz_crash = _fuzz_module()
    report = tmp_path / "files.json"
    cases = 2 * len(fuzz_crash.FILE_CLASSES)
    proc = subprocess.run(
        [
            sys.executable,
            str(ROOT / "tools" / "fuzz_crash.py"),
            "--files",
            str(cases),
            "--seed",
            "15",
            "--report",
            str(report),
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    summary = json.loads(report.read_text())
    assert summary["cases"] == cases and set(summary["classes"]) == set(fuzz_crash.FILE_CLASSES)
    assert (summary["crashes"], summary["hangs"], summary["findings"]) == (0, 0, 0), json.dumps(
        summary["examples"][:3], indent=1
    )
    assert proc.returncode == 0


@pytest.mark.slow
@pytest.mark.serial
def test_threads_slice_finds_nothing(tmp_path):
    """A Scene shared by 3-5 threads (tools/fuzz_crash.py --threads): random kinds with far and
    huge outliers, each thread a random mix of single and batched adds, pairs_within, nearest,
    within, queries by name, distance_matrix, pickling mid-run and adding a name taken; each
    scenario in its own child, every answer that of a serial scene of a prefix of the adds."""
    report = tmp_path / "threads.json"
    proc = subprocess.run(
        [
            sys.executable,
            str(ROOT / "tools" / "fuzz_crash.py"),
            "--threads",
            "3",
            "--seed",
            "15",
            "--report",
            str(report),
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    summary = json.loads(report.read_text())
    assert summary["cases"] == 3
    assert (summary["crashes"], summary["hangs"], summary["findings"]) == (0, 0, 0), json.dumps(
        summary["examples"][:3], indent=1
    )
    assert proc.returncode == 0


@pytest.mark.slow
def test_thread_scenarios_catch_an_answer_no_serial_scene_gives():
    """The check can fail: a Scene whose nearest drops its last answer in threads only (the
    serial scenes run on the main thread) is caught, and so is a pickle that loses a shape."""
    import threading

    import circledist as cd

    fuzz_crash = _fuzz_module()
    cases = list(fuzz_crash.generate_threads(15, 2))
    real_nearest, real_state = cd.Scene.nearest, cd.Scene.__getstate__

    def in_thread():
        return threading.current_thread() is not threading.main_thread()

    def nearest(self, shape, k=1, **kw):
        answer = real_nearest(self, shape, k, **kw)
        return answer[:-1] if in_thread() and len(answer) > 1 else answer

    def state(self):
        kept = real_state(self)
        if in_thread() and kept["names"]:
            kept["names"] = kept["names"][:-1] + ["renamed"]
        return kept

    try:
        cd.Scene.nearest = nearest
        found = [fuzz_crash.run_thread_case(cd, case) for case in cases]
        assert all(f and "no serial scene gives" in f["finding"] for f in found), found
        cd.Scene.nearest, cd.Scene.__getstate__ = real_nearest, state
        found = [fuzz_crash.run_thread_case(cd, case) for case in cases]
        assert all(f and f["finding"].startswith("pickle") for f in found), found
    finally:
        cd.Scene.nearest, cd.Scene.__getstate__ = real_nearest, real_state
    assert [fuzz_crash.run_thread_case(cd, case) for case in cases] == [None, None]


# Families of the argument fuzz that are open library findings, each with its strict xfail in
# tests/accuracy/test_open_findings.py (none now). Remove a family here when its xfail passes.
OPEN_ARGUMENT_FAMILIES = set()


@pytest.mark.slow
@pytest.mark.serial
def test_arguments_slice_finds_nothing(tmp_path):
    """Every entry point with hostile scalar arguments (tools/fuzz_crash.py --arguments): huge
    and negative integers, bools, NumPy scalars, floats, NaN, strings, None, over small, empty,
    one-element, 10^5 x 10^5 outer and 10^15-row broadcast batches, in children held to 2 GiB:
    no crash or hang, only TypeError, ValueError, MemoryError (without memory really allocated)
    and IndexError, never pybind11's words; every entry point called."""
    fuzz_crash = _fuzz_module()
    report = tmp_path / "arguments.json"
    proc = subprocess.run(
        [
            sys.executable,
            str(ROOT / "tools" / "fuzz_crash.py"),
            "--arguments",
            "800",
            "--seed",
            "15",
            "--chunk",
            "400",
            "--report",
            str(report),
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    summary = json.loads(report.read_text())
    assert summary["cases"] == sum(summary["classes"].values()) > 700
    assert set(summary["classes"]) >= set(fuzz_crash.ARGUMENTS) - {"dask.pairs_within"}
    assert (summary["crashes"], summary["hangs"]) == (0, 0), json.dumps(summary["examples"][:3], indent=1)
    unexpected = [e for e in summary["examples"] if e["finding"] not in OPEN_ARGUMENT_FAMILIES]
    assert not unexpected, json.dumps(unexpected[:3], indent=1)
    assert proc.returncode == (1 if summary["findings"] else 0)


def test_argument_calls_catch_what_they_look_for():
    """The argument check can fail: pybind11's words, an exception of another type, a MemoryError
    from C++ and one raised after memory was really allocated are findings; the library's own
    errors are not."""
    import circledist as cd

    fuzz_crash = _fuzz_module()
    case = {"index": 0, "entry": "nearest", "argument": "k", "value": "2**64+1", "batch": "small", "kind": "point"}
    assert fuzz_crash.run_argument_case(cd, case) is None
    real = cd.nearest
    for error, words in (
        (TypeError("Unable to cast Python instance"), "pybind11's words"),
        (RuntimeError("boom"), "RuntimeError"),
        (MemoryError("std::bad_alloc"), "C++"),
        (MemoryError("nearest: too large"), "after growing"),
    ):

        def raising(*args, error=error, grow=words == "after growing", **kw):
            if grow:
                np.ones(fuzz_crash.ARGUMENT_GROWTH // 4)  # twice the growth that counts, touched
            raise error

        try:
            cd.nearest = raising
            found = fuzz_crash.run_argument_case(cd, case)
        finally:
            cd.nearest = real
        assert found and found["finding"].startswith("nearest(k): ") and words in found["finding"], found
