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
