"""The fixed-seed slice of the crash-isolating fuzz (tools/fuzz_crash.py, issue 15): every kind
pair, entry point, precision and solver, magnitudes from 1e-300 to 1e300, degenerate shapes,
batch layouts; each chunk in a child process, so a crash fails this test with its input named
instead of taking pytest down. The long mode is `bash tools/run.sh fuzz`."""

import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_fuzz_slice_finds_nothing(tmp_path):
    report = tmp_path / "fuzz.json"
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "fuzz_crash.py"), "--cases", "6000", "--seed", "15",
                           "--chunk", "3000", "--report", str(report)], capture_output=True, text=True, timeout=600)
    summary = json.loads(report.read_text())
    assert summary["cases"] == 6000
    assert (summary["crashes"], summary["hangs"], summary["findings"]) == (0, 0, 0), json.dumps(
        summary["examples"][:3], indent=1)
    assert proc.returncode == 0


def test_hostile_files_slice_finds_nothing(tmp_path):
    """The command line on hostile files (tools/fuzz_crash.py --files): FIFOs and devices, zip
    bombs, lying .npy headers, JSON nested near the recursion limit, lone surrogates, counts beyond
    memory, unsupported compression, foreign members, truncated and flipped files; each in its own
    process held to 1 GiB and 60 s, answered with one clean error line and exit status 2. The slice
    runs each class twice."""
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        import fuzz_crash
    finally:
        sys.path.pop(0)
    report = tmp_path / "files.json"
    cases = 2 * len(fuzz_crash.FILE_CLASSES)
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "fuzz_crash.py"), "--files", str(cases), "--seed", "15",
                           "--report", str(report)], capture_output=True, text=True, timeout=600)
    summary = json.loads(report.read_text())
    assert summary["cases"] == cases and set(summary["classes"]) == set(fuzz_crash.FILE_CLASSES)
    assert (summary["crashes"], summary["hangs"], summary["findings"]) == (0, 0, 0), json.dumps(
        summary["examples"][:3], indent=1)
    assert proc.returncode == 0
