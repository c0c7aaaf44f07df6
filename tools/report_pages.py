#!/usr/bin/env python3
"""Rewrite the long-run report pages, docs/reports/differential.md and docs/reports/fuzz.md, whole,
from the JSON records of a run (which stay in build/reports/, out of the tree):

    python -m tools.report_pages differential build/reports/differential_report.json
    python -m tools.report_pages fuzz build/reports/fuzz_report.json [fuzz_threads_report.json ...]

Each page holds what the run checks, the latest run of each kind in full, and a short table of the
past long runs. That table is read back from the page being replaced (between its two markers), and
the new runs' rows join it, newest first; a row already there is not repeated. `bash tools/run.sh
fuzz` calls this after its runs. The page says which command wrote it; edit this tool, not the page.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPORTS = os.path.join(ROOT, "docs", "reports")
BEGIN, END = "<!-- past runs: rows kept by tools/report_pages.py -->", "<!-- end of past runs -->"

DIFFERENTIAL_INTRO = """\
`python -m tools.differential` is the long mode of the differential accuracy test
(`tests/accuracy/test_differential.py` runs its CI slice). Cases are drawn from random and adversarial
families of every kind pair (`circledist_cases/differential.py`); every case is answered by every
solver x precision combination, in both argument orders and through every entry point (distance,
closest_points, within and distance_if_within at two limits, intersects), and each answer is
judged against the others, its own closest points and, for the suspects, 50-digit references.
`closest_points().unique` is checked where a rule decides it, and by a 50-digit search on a sample
of each chunk. A confirmed finding is a class (check, family, kind pair) with reproducible case
ids (`differential.case_from_id`). The JSON record of a run goes to `build/reports/`."""

FUZZ_INTRO = """\
`tools/fuzz_crash.py` runs each chunk of calls in a child process, so that a crash or a hang is
isolated and its case kept. `bash tools/run.sh fuzz [N]` runs its classes below; the JSON records
go to `build/reports/`."""

FUZZ_CLASSES = {
    "cases": (
        "Numeric pairs (`--cases N --batched`)",
        "Every kind pair in both orders, every entry point, precision and solver, magnitudes from "
        "1e-300 to 1e300 and at float32's edges, degenerate shapes, batch layouts and dtypes. A "
        "finding is a crash, a hang, a NaN for inputs the constructors accepted, a negative "
        "distance, non-finite closest points for a finite distance, or `distance()` != "
        "`closest_points().distance`.",
    ),
    "files": (
        "Hostile scene files (`--files N`)",
        "Malformed, truncated, oversized and lying JSON and `.npz` scene files through "
        "`read_scene` and the command line. A finding is a crash, a hang, or an error that is not "
        "one `circledist: error: ...` line (a `SceneFileError` from Python).",
    ),
    "threads": (
        "A Scene shared by threads (`--threads N`)",
        "A Scene of random shapes shared by 3-5 threads that add and query it (pairs_within, "
        "nearest, within, pickling and copying mid-run). Every answer must be that of a serial "
        "scene of the first m shapes for an m between the counts at the query's start and end.",
    ),
    "arguments": (
        "Hostile scalar arguments (`--arguments N`)",
        "Every entry point called with one hostile scalar in one argument (huge integers, bools, "
        "NaN, strings, None, arrays, complex, Fraction, ...), over small, empty and huge "
        "broadcast batches. A finding is a crash, a hang, an exception other than TypeError, "
        "ValueError, MemoryError and IndexError, pybind11's own words, or a MemoryError after "
        "memory was really taken.",
    ),
}


def commit_of(record):
    head = (record.get("library") or {}).get("git_head") or record.get("commit") or ""
    return head[:7] if head else "—"


def number(n):
    return f"{n:,}" if isinstance(n, int) else str(n)


def past_rows(path):
    """The rows of the page's past-runs table, as written (header and delimiter rows left out)."""
    if not os.path.exists(path):
        return []
    text = open(path).read()
    if BEGIN not in text or END not in text:
        return []
    block = text.split(BEGIN, 1)[1].split(END, 1)[0]
    rows = [line for line in block.splitlines() if line.startswith("|")]
    return [row for row in rows[2:]]


def merged(new_rows, old_rows, limit):
    rows = list(new_rows) + [row for row in old_rows if row not in new_rows]
    return rows[:limit]


def table(header, rows):
    return "\n".join(["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|", *rows])


# --- the differential test -------------------------------------------------------------------


def differential_families(record):
    command = record.get("command", "")
    match = re.search(r"--families (\S+)", command)
    return match.group(1) if match else "all"


def differential_row(record):
    confirmed = sum((record.get("confirmed_by_solver") or {}).values())
    return (
        f"| {differential_families(record)} ({len(record.get('families', []))}) | {record.get('seed', '—')} | "
        f"{number(record.get('cases'))} | {number(record.get('answers'))} | {len(record.get('classes', {}))} "
        f"({number(confirmed)} answers) | {commit_of(record)} |"
    )


def differential_latest(record):
    lines = [
        f"Families: {differential_families(record)} ({', '.join(record.get('families', []))}); "
        f"seed {record.get('seed')}; module {commit_of(record)}.",
        "",
        f"- **{number(record.get('answers'))} answers** over {number(record.get('cases'))} cases "
        f"({record.get('answers_per_case_batched', '—')} batched answers per case).",
    ]
    unique = record.get("unique_checked") or {}
    if unique:
        lines.append("- `unique` checked " + ", ".join(f"{number(v)} times {k}" for k, v in unique.items()) + ".")
    entries = record.get("answers_by_entry") or {}
    if entries:
        lines += ["", table(["entry point", "answers"], [f"| {k} | {number(v)} |" for k, v in entries.items()])]
    classes = record.get("classes") or {}
    if not classes:
        lines += ["", "**No confirmed finding.**"]
    else:
        body = []
        for name, c in classes.items():
            cases = ", ".join(f"`{case}`" for case in c.get("cases", [])[:3])
            body.append(
                f"| {name.replace('|', ' / ')} | {number(c.get('confirmed', 0))} | "
                f"{', '.join(f'{k} {v}' for k, v in (c.get('by_solver') or {}).items())} | "
                f"{', '.join(f'{k} {v}' for k, v in (c.get('by_precision') or {}).items())} | {cases} |"
            )
        lines += [
            "",
            f"**{len(classes)} confirmed finding classes** (reproduce a case with " "`differential.case_from_id`):",
            "",
            table(["class (check / family / pair)", "confirmed answers", "solvers", "precisions", "cases"], body),
        ]
    return "\n".join(lines)


def write_differential(records, page):
    latest = records[-1]  # the records in the order given: the last is the latest
    rows = merged([differential_row(r) for r in reversed(records)], past_rows(page), limit=24)
    text = "\n".join(
        [
            "# Differential test: long runs",
            "",
            "Written by `python -m tools.report_pages differential RECORD.json` from the record of the last run; "
            "edit that tool, not this page.",
            "",
            DIFFERENTIAL_INTRO,
            "",
            "## Latest run",
            "",
            differential_latest(latest),
            "",
            "## Past long runs",
            "",
            "Each row one run of the long mode on the module of that commit; a finding class is fixed with a "
            "regression test before the next run of its families.",
            "",
            BEGIN,
            table(["families", "seed", "cases", "answers", "confirmed classes", "commit"], rows),
            END,
            "",
        ]
    )
    with open(page, "w") as fh:
        fh.write(text)


# --- the crash-isolating fuzz ----------------------------------------------------------------


def fuzz_class(path, record):
    name = os.path.basename(path)
    for key in ("threads", "arguments", "files"):
        if f"_{key}" in name or record.get("mode") == key:
            return key
    return "cases"


def fuzz_row(record):
    return (
        f"| {number(record.get('cases'))} | {record.get('seed', '—')} | {record.get('crashes')} | "
        f"{record.get('hangs')} | {record.get('findings')} | {commit_of(record)} |"
    )


def fuzz_latest(record):
    lines = [
        f"- {number(record.get('cases'))} cases: {record.get('crashes')} crashes, {record.get('hangs')} hangs, "
        f"{record.get('findings')} findings (module {commit_of(record)})."
    ]
    if record.get("classes"):
        lines.append("- by class: " + ", ".join(f"{k} {number(v)}" for k, v in record["classes"].items()) + ".")
    for example in (record.get("examples") or [])[:5]:
        lines.append(f"- finding: {example.get('finding')} (case `{json.dumps(example.get('case'))[:200]}`)")
    return "\n".join(lines)


def write_fuzz(records, page):
    """records: {class: record}; the classes not run keep their latest section and past rows."""
    old = open(page).read() if os.path.exists(page) else ""
    sections = [
        "# Crash-isolating fuzz: long runs",
        "",
        "Written by `python -m tools.report_pages fuzz RECORD.json ...` from the records of the last "
        "runs; edit that tool, not this page.",
        "",
        FUZZ_INTRO,
        "",
    ]
    for key, (title, what) in FUZZ_CLASSES.items():
        begin, end = BEGIN.replace("past runs", f"past runs of {key}"), END.replace("past runs", f"past runs of {key}")
        old_rows = []
        old_latest = "Not run yet."
        if begin in old and end in old:
            old_rows = [r for r in old.split(begin, 1)[1].split(end, 1)[0].splitlines() if r.startswith("|")][2:]
            old_latest = (
                old.split(f"## {title}", 1)[1].split("### Latest run", 1)[1].split("### Past long runs", 1)[0].strip()
            )
        if key in records:
            latest, rows = fuzz_latest(records[key]), merged([fuzz_row(records[key])], old_rows, limit=12)
        else:
            latest, rows = old_latest, old_rows
        sections += [
            f"## {title}",
            "",
            what,
            "",
            "### Latest run",
            "",
            latest,
            "",
            "### Past long runs",
            "",
            begin,
            table(["cases, files, scenarios or calls", "seed", "crashes", "hangs", "findings", "commit"], rows),
            end,
            "",
        ]
    with open(page, "w") as fh:
        fh.write("\n".join(sections))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("page", choices=["differential", "fuzz"])
    ap.add_argument("records", nargs="+", help="JSON records written by the run (build/reports/)")
    ap.add_argument("--out", help="the page to write (default docs/reports/<page>.md)")
    args = ap.parse_args(argv)
    page = args.out or os.path.join(REPORTS, f"{args.page}.md")
    loaded = []
    for path in args.records:
        with open(path) as fh:
            record = json.load(fh)
        if "commit" not in record and "library" not in record:  # the fuzz's records: the tree's commit
            head = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True, text=True)
            record["commit"] = head.stdout.strip() if head.returncode == 0 else ""
        loaded.append((path, record))
    if args.page == "differential":
        write_differential([r for _, r in loaded], page)
    else:
        write_fuzz({fuzz_class(p, r): r for p, r in loaded}, page)
    print(f"wrote {os.path.relpath(page, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
