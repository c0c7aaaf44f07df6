"""The parent: chunks of cases in child processes (``python tools/fuzz_crash.py --child``), a
crash or hang named by the case the child was running.
"""

from __future__ import annotations

import json
import os
import subprocess

from .common import _limit_memory

# the script whose --child mode runs a chunk
SCRIPT = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "fuzz_crash.py")


# ----------------------------------------------------------------------------------------------
# the parent: chunks in child processes
# ----------------------------------------------------------------------------------------------
def _run_child(todo, mode, python, timeout, tmp, memory=None):
    """Runs the cases in a child (mode: as child()'s; memory: a bound on its address space, in
    bytes); returns (result or None, last case started, crash/hang text)."""
    cases_file, current_file, results_file = (os.path.join(tmp, n) for n in ("cases", "current", "results"))
    json.dump(todo, open(cases_file, "w"))
    for f in (current_file, results_file):
        if os.path.exists(f):
            os.remove(f)
    try:
        proc = subprocess.run(
            [python, SCRIPT, "--child", cases_file, current_file, results_file, mode],
            timeout=timeout,
            capture_output=True,
            text=True,
            stdin=subprocess.DEVNULL,
            preexec_fn=None if memory is None else lambda: _limit_memory(memory),
        )
        if proc.returncode == 0 and os.path.exists(results_file):
            return json.load(open(results_file)), None, None
        what = f"crash (exit {proc.returncode})", proc.stderr[-2000:]
    except subprocess.TimeoutExpired:
        what = "hang", ""
    last = json.load(open(current_file)) if os.path.exists(current_file) else None
    return None, last, what


def _run_chunk(todo, mode, python, timeout, tmp, summary, memory=None):
    """Adds the chunk's counts to summary. A batched chunk that stops its child is run again case
    by case; a case that stops its child is recorded with its input, and the rest run on."""
    while todo:
        result, last, what = _run_child(todo, mode, python, timeout, tmp, memory)
        if result is not None:
            summary["cases"] += result["ran"]
            summary["findings"] += len(result["findings"])
            seen = {e["finding"] for e in summary["examples"]}
            for f in result["findings"]:
                if f["finding"] not in seen:
                    summary["examples"].append(f)
                    seen.add(f["finding"])
            return
        if mode == "1":
            mode = "0"
            continue
        summary["hangs" if what[0] == "hang" else "crashes"] += 1
        summary["examples"].append({"finding": what[0], "case": last, "stderr": what[1]})
        done = next((i + 1 for i, c in enumerate(todo) if last and c["index"] == last["index"]), len(todo))
        summary["cases"] += done
        todo = todo[done:]
