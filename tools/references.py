"""Records and checks the 50-digit references the tests read from tests/references/
(circledist_cases/reference_store.py says how they are keyed and stored).

    python -m tools.references record   # compute every reference the tests use, rewrite the files
    python -m tools.references verify   # compute every reference the tests use again; a recorded
                                        # one that differs fails its test

Both run the tests that are not marked serial on every core, with CIRCLEDIST_REFERENCES set to the
mode; extra arguments go to pytest (a test file, -k EXPR). record writes into build/ and moves
the files into place at the end; over every test it starts from nothing, so that a reference no
test uses any more is dropped, and a selection adds to the files. Record again after a change to
a reference module (tests/package/test_reference_store.py fails until then).
"""

from __future__ import annotations

import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from circledist_cases.reference_store import STORE  # noqa: E402


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] not in ("record", "verify"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, rest = argv[0], argv[1:]
    env = {**os.environ, "CIRCLEDIST_REFERENCES": mode}
    out = ROOT / "build" / "references-recorded"
    if mode == "record":
        # Recorded into a folder of its own, moved into place at the end: the run's own tests see
        # the files as they were. A run over every test starts from nothing, so that a reference
        # no test uses any more is dropped; a selection adds to the files.
        shutil.rmtree(out, ignore_errors=True)
        out.mkdir(parents=True)
        if rest:
            for f in STORE.glob("*.json"):
                shutil.copy(f, out / f.name)
        env["CIRCLEDIST_REFERENCES_OUT"] = str(out)
    cmd = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-n", str(os.cpu_count() or 1)]
    cmd += ["--dist", "loadfile", "-m", "not serial"] + (rest or ["tests"])
    print("==", " ".join(cmd), f"(CIRCLEDIST_REFERENCES={mode})", flush=True)
    rc = subprocess.call(cmd, cwd=ROOT, env=env)
    if mode == "record":
        for f in STORE.glob("*.json"):
            f.unlink()
        files = sorted(out.glob("*.json"))
        for f in files:
            shutil.move(str(f), STORE / f.name)
        print(f"== {len(files)} files in {STORE.relative_to(ROOT)}: " + ", ".join(f.stem for f in files))
    return rc


if __name__ == "__main__":
    sys.exit(main())
