"""Crash-isolating fuzz of circledist's Python API.

Cases cover every kind pair in both orders, every entry point (distance, closest_points, within,
intersects, distance_if_within), precision and solver, magnitudes from 1e-300 to 1e300, degenerate
shapes (zero radius, zero-length segments, points on axes, coplanar and concentric rounds), sweeps,
batches in several memory layouts (C, Fortran, strided, read-only) and dtypes.

Each chunk of cases runs in a child process. The child writes the case it is about to run to a file
first, so when it dies (a signal: a crash) or stops answering (a hang), the parent names the input.
The child also checks every answer: no NaN for inputs the constructors accepted, distances >= 0,
closest points finite whenever the distance is finite, and distance() == closest_points().distance.

    python tools/fuzz_crash.py [--cases N] [--seed S] [--chunk K] [--timeout T] [--report FILE]
    python tools/fuzz_crash.py --files N [--seed S] [--report FILE]
    python tools/fuzz_crash.py --threads N [--seed S] [--timeout T] [--report FILE]
    python tools/fuzz_crash.py --arguments N [--seed S] [--chunk K] [--timeout T] [--report FILE]

--files: the command line on hostile files instead (FIFOs and devices, zip bombs, .npy headers
that lie about their shape, JSON nested near the recursion limit, lone surrogates, counts beyond
memory, unsupported compression, members that are no .npy, truncated and byte-flipped files),
each in its own process held to 1 GiB of address space and 60 s: a finding is anything but one
"circledist: error: FILE: ..." line and exit status 2 (a truncated or flipped file may still be
valid: exit 0).

--threads: N scenarios of one Scene shared by 3-5 threads (each scenario in its own child, held
to --timeout seconds, at most 120): random shapes (points, circles, disks, segments, arcs, annuli,
Bezier curves; some far or huge outliers, some float32, some swept), and in every thread a random
mix of adds (single and batched), pairs_within, nearest, within, queries by a shape's name,
distance_matrix, pickling or deep-copying the scene mid-run and adding a name already taken. A
finding: a crash, a hang, an exception other than the documented ones, or an answer that no
serial scene of the first m shapes gives for any m between the counts at the query's start and
end.

--arguments: N calls of every entry point (distance, closest_points, within, intersects,
distance_if_within, nearest, pairs_within, Scene.nearest/within/pairs_within, the shape
constructors, batch indexing, circledist.dask.pairs_within where dask is installed), each with one
hostile scalar argument (huge integers, bools, NumPy integers and bools, floats where integers are
expected, NaN, inf, strings, None) over small, empty, one-element, outer 10^5 x 10^5 and 10^15-row
broadcast batches, --chunk calls per child held to 2 GiB of address space. A finding: a crash, a
hang, an exception other than TypeError, ValueError, MemoryError and IndexError (KeyError for a
scene shape's name), pybind11's "Unable to cast" or "incompatible function arguments", or a
MemoryError raised after the process grew by 256 MiB (memory really allocated) or in C++'s words.

Exit status 0 when nothing was found, 1 otherwise; the summary (counts, and one reproducer per
finding) is printed and, with --report, written as JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

# The modes live in tools/fuzzing/: imported relative to this file's package when it is imported
# as tools.fuzz_crash, else from its folder (run as a script, or imported with tools/ on sys.path).
try:
    from .fuzzing import (
        ARGUMENT_GROWTH,
        ARGUMENTS,
        FILE_CLASSES,
        THREAD_TIMEOUT,
        _group_key,
        _write_npz,
        fuzz,
        fuzz_arguments,
        fuzz_files,
        fuzz_threads,
        generate_threads,
        run_argument_case,
        run_batch,
        run_case,
        run_thread_case,
    )
except ImportError:
    from fuzzing import (
        ARGUMENT_GROWTH,
        ARGUMENTS,
        FILE_CLASSES,
        THREAD_TIMEOUT,
        _group_key,
        _write_npz,
        fuzz,
        fuzz_arguments,
        fuzz_files,
        fuzz_threads,
        generate_threads,
        run_argument_case,
        run_batch,
        run_case,
        run_thread_case,
    )

# what the command line and the tests (tests/accuracy/test_fuzz_crash.py, tests/api/test_scene_file.py) use
__all__ = [
    "ARGUMENTS",
    "ARGUMENT_GROWTH",
    "FILE_CLASSES",
    "_write_npz",
    "child",
    "fuzz",
    "fuzz_arguments",
    "fuzz_files",
    "fuzz_threads",
    "generate_threads",
    "main",
    "run_argument_case",
    "run_thread_case",
]


def child(cases_file, current_file, results_file, mode="0"):
    """Runs the cases of cases_file: mode "0" one by one, "1" batched, "threads" the thread
    scenarios, "arguments" the hostile argument calls."""
    import faulthandler

    import circledist as cd

    faulthandler.enable()  # a crash's stderr names the threads' Python stacks
    cases = json.load(open(cases_file))
    findings = []
    run_one = {"threads": run_thread_case, "arguments": run_argument_case}.get(mode, run_case)

    def note(case):
        current.seek(0)
        current.write(json.dumps(case))
        current.truncate()
        current.flush()

    with open(current_file, "w") as current:
        if mode == "1":
            groups = {}
            for case in cases:
                groups.setdefault(_group_key(case), []).append(case)
            for group in groups.values():
                note({"batch_of": [c["index"] for c in group], **group[0]})
                result = run_batch(cd, group)
                if result is None:
                    continue
                # A clear error somewhere in the batch, or a bad element: each case alone.
                alone = 0
                for case in group:
                    note(case)
                    finding = run_case(cd, dict(case, batch=0))
                    if finding:
                        findings.append({"finding": finding, "case": case})
                        alone += 1
                if result != "error" and alone == 0:  # bad in the batch only
                    findings.append({"finding": result[1], "case": group[result[0]]})
        else:
            for case in cases:
                note(case)
                finding = run_one(cd, case)
                if isinstance(finding, dict):  # a finding with its detail
                    findings.append({**finding, "case": case})
                elif finding:
                    findings.append({"finding": finding, "case": case})
    json.dump({"ran": len(cases), "findings": findings}, open(results_file, "w"))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "--child":
        child(*argv[1:5])
        return 0
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=15)
    parser.add_argument("--chunk", type=int, default=2000)
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--report")
    parser.add_argument(
        "--batched",
        action="store_true",
        help="run each chunk's cases of one kind pair and query as one batched call (the long mode)",
    )
    parser.add_argument(
        "--files",
        type=int,
        metavar="N",
        help="instead: the command line on N hostile files (FIFOs, devices, zip bombs, lying .npy "
        "headers, deep nesting, surrogates, huge counts, odd compression, foreign members, "
        "truncated and flipped files), each in a process held to 1 GiB and 60 s",
    )
    parser.add_argument(
        "--threads",
        type=int,
        metavar="N",
        help="instead: N scenarios of a Scene shared by 3-5 threads that add and query it at "
        "once, each in its own child held to --timeout seconds (at most 120), every answer "
        "checked against serial scenes",
    )
    parser.add_argument(
        "--arguments",
        type=int,
        metavar="N",
        help="instead: N calls of the entry points with hostile scalar arguments (huge integers, "
        "bools, NumPy scalars, floats, NaN, strings, None; small, empty and 10^15-row "
        "broadcast batches), --chunk calls per child held to 2 GiB",
    )
    args = parser.parse_args(argv)
    t0 = time.time()
    if args.threads is not None:
        summary = fuzz_threads(args.threads, args.seed, progress=True, timeout=min(args.timeout, THREAD_TIMEOUT))
    elif args.arguments is not None:
        summary = fuzz_arguments(args.arguments, args.seed, args.chunk, args.timeout, progress=True)
    elif args.files is not None:
        summary = fuzz_files(args.files, args.seed, progress=True)
    else:
        summary = fuzz(args.cases, args.seed, args.chunk, args.timeout, progress=True, batched=args.batched)
    summary["seconds"] = round(time.time() - t0, 1)
    summary["seed"] = args.seed  # for the report page (tools/report_pages.py)
    text = json.dumps(summary, indent=1)
    print(text)
    if args.report:
        os.makedirs(os.path.dirname(os.path.abspath(args.report)), exist_ok=True)
        with open(args.report, "w") as fh:
            fh.write(text)
    return 0 if summary["crashes"] == summary["hangs"] == summary["findings"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
