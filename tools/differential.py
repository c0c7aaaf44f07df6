#!/usr/bin/env python3
"""Long mode of the differential accuracy test.

    python -m tools.differential --answers 10000000 --seed 1 --report build/reports/differential_report.json

(from the repository's root: a module run, so that the shared cases, circledist_cases, import.)

Sizes are counted in library ANSWERS: every value the library
returns for one query, i.e. per case every solver x precision combination, both argument orders,
and every entry point -- distance, closest_points, within and distance_if_within (each probed at
two limits), intersects -- batched: 2 x 7 = 14 answers per combination, 168 per case with the 12
combinations (differential.answers_per_case), plus the scalar sample (scalar calls that must
give exactly the batch's answers).  --answers N runs ceil(N / answers per case) cases;
--cases N (alias --queries, its old name) sets the cases directly.  The report gives both, and
the answers per entry point.

The cases (one kind pair instance each, "family/seed/index") are spread evenly over the case
families of circledist_cases/differential/ and, within a family, over its kind pairs; every chunk holds a
share of every family (one library batch per kind pair and chunk: large batches, and a partial
run sees every family).  Answers are judged by the fast NumPy screen and by the returned closest
points.  Accuracy findings are confirmed against the 50-digit mpmath references (at most
--max-confirm per finding class, solver, precision and chunk; the rest are counted as
candidates).  Prints counts per family, kind pair, solver and precision and one reproducer per
finding class, writes the JSON report, and exits 1 when any finding is confirmed.

Every case is reproducible from its id "family/seed/index" (differential.case_from_id).
--families restricts a run to some families (comma-separated), "round" to the seventeen of the
pairs with a circle or disk, "no-round" to the ten of the pairs without one (points, lines, rays,
segments among themselves, Bezier curves against them), "arc" to the seventeen of the arc
against every kind with a query, "annulus" to the eighteen of an annulus against every kind
(the records go to build/reports/, the summary of past long runs to docs/reports/differential.md):

    python -m tools.differential --answers 200000 --seed 1 --families no-round \
        --report build/reports/differential_report_linear.json
    python -m tools.differential --answers 10000000 --seed 1 --families arc \
        --report build/reports/differential_report_arc.json
    python -m tools.differential --answers 1000000 --seed 1 --families annulus \
        --report build/reports/differential_report_annulus.json

closest_points().unique is checked where differential.expected_unique's rule decides it (the
module's docstring); the report counts those checks apart ("unique_checked": per expectation,
one per case, combination and order), since they are part of closest_points' answers.  Besides,
--unique-direct N (default 8) cases per chunk that expected_unique leaves open and
differential.reference_unique covers (a circle, arc or Bezier curve against a shape with a closed
point distance, a line, ray or segment against a disk or annulus: a 50-digit search over the
moving shape's parameter) have their unique answer
checked against that search ("unique_checked_direct": per pair and expectation; float64 scenes,
the float64 and long double combinations, both orders).
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load_differential():
    """The differential test's library module (circledist_cases/differential/)."""
    try:
        from circledist_cases import differential
    except ModuleNotFoundError as e:
        if e.name != "circledist_cases":
            raise
        sys.exit("tools/differential.py: run it from the repository's root as python -m tools.differential")
    return differential


def library_info(cd):
    """Which build was tested: module path, the compiled extension's mtime, the repository's HEAD
    and its uncommitted files (the package is rebuilt from the working tree)."""
    import glob
    import subprocess

    info = {"version": getattr(cd, "__version__", "?"), "module": cd.__file__}
    so = glob.glob(os.path.join(os.path.dirname(cd.__file__), "_core*.so"))
    if so:
        info["extension_mtime"] = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(os.path.getmtime(so[0])))
    try:
        info["git_head"] = subprocess.run(
            ["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True, text=True, timeout=10
        ).stdout.strip()
        info["git_dirty"] = subprocess.run(
            ["git", "-C", ROOT, "status", "--short"], capture_output=True, text=True, timeout=10
        ).stdout.split("\n")
    except Exception:  # noqa: BLE001 - informational only
        pass
    return info


def plan(D, families, cases, batch):
    """Chunks, each a list of parts (family, start, count): `cases` split evenly over the
    families, and every chunk of about `batch` cases holding an even share of each family."""
    per = [cases // len(families) + (1 if i < cases % len(families) else 0) for i in range(len(families))]
    n_chunks = max(1, -(-cases // batch))
    chunks = []
    for j in range(n_chunks):
        parts = []
        for fam, n in zip(families, per):
            lo, hi = n * j // n_chunks, n * (j + 1) // n_chunks
            if hi > lo:
                parts.append((fam, lo, hi - lo))
        if parts:
            chunks.append(parts)
    return chunks


def _size(f):
    return len(json.dumps([f["a_data"], f["b_data"]]))


def pick_examples(fs, keep):
    """Examples worth keeping: the simplest confirmed ones (shortest inputs: a minimal reproducer)
    and the worst ones (largest error), confirmed findings first."""
    by_size = sorted(fs, key=lambda f: (not f.get("confirmed"), _size(f), -(f.get("error") or 0)))
    by_error = sorted(fs, key=lambda f: (not f.get("confirmed"), -(f.get("error") or 0)))
    out, seen = [], set()
    for f in by_size[:keep] + by_error[:keep]:
        key = (f["case_id"], f["solver"], f["precision"], f["order"], f["entry"])
        if key not in seen:
            seen.add(key)
            out.append(f)
    return out


def run_chunk(job):
    """One chunk in a worker: check, confirm (bounded), and summarise."""
    parts, seed, combo_list, scalar_n, max_confirm, keep, unique_n = job
    D = load_differential()
    import circledist as cd

    cases = [c for fam, start, count in parts for c in D.generate(fam, count, seed, start=start)]
    step = max(1, len(cases) // max(scalar_n, 1)) if scalar_n else None
    scalar = set(range(0, len(cases), step)) if scalar_n else set()
    t0 = time.perf_counter()
    findings, stats = D.check_and_confirm(cd, cases, combo_list, scalar=scalar, max_confirm=max_confirm)
    # the direct unique check (differential.reference_unique, ~0.3 s of 50-digit search a case) on
    # unique_n cases of the chunk that its rule covers and expected_unique does not, evenly spread
    eligible = [c for c in cases if D._unique_roles(c) is not None and D.expected_unique(c)[0] is None]
    if unique_n and eligible:
        pick = [eligible[i * len(eligible) // unique_n] for i in range(min(unique_n, len(eligible)))]
        findings += D.unique_direct_check(cd, pick, combo_list, stats)
    seconds = time.perf_counter() - t0
    pairs = collections.Counter(f"{c['a']}-{c['b']}" for c in cases)
    # per class: counts by status / solver / precision, and a few examples (confirmed first,
    # largest error first)
    classes = {}
    for f in findings:
        key = "|".join(D.finding_class(f))
        c = classes.setdefault(
            key,
            {
                "candidates": 0,
                "confirmed": 0,
                "refuted": 0,
                "unchecked": 0,
                "by_solver": collections.Counter(),
                "by_precision": collections.Counter(),
                "cases": set(),
                "examples": [],
                "reference_missed": 0,
            },
        )
        c["candidates"] += 1
        status = f.get("confirmed")
        c["confirmed" if status else ("refuted" if status is False else "unchecked")] += 1
        if status:
            c["by_solver"][f["solver"]] += 1
            c["by_precision"][f["precision"]] += 1
        c["cases"].add(f["case_id"])
        c["reference_missed"] += bool(f.get("reference_missed"))
        c["examples"].append(f)
    for c in classes.values():
        c["examples"] = pick_examples(c["examples"], keep)
        c["n_cases"] = len(c["cases"])
        c["cases"] = sorted(c["cases"])[: keep * 4]
    return dict(
        count=len(cases),
        by_family=dict(collections.Counter(c["family"] for c in cases)),
        pairs=dict(pairs),
        answers=dict(stats["answers"]),
        unique_checked=dict(stats["unique_checked"]),
        unique_checked_direct=dict(stats.get("unique_checked_direct", {})),
        seconds=seconds,
        classes=classes,
    )


def merge(total, part):
    total["cases"] += part["count"]
    total["answers"].update(part["answers"])
    total["unique_checked"].update(part.get("unique_checked", {}))
    total["unique_checked_direct"].update(part.get("unique_checked_direct", {}))
    total["by_family"].update(part["by_family"])
    for p, n in part["pairs"].items():
        total["by_pair"][p] += n
    for key, c in part["classes"].items():
        t = total["classes"].setdefault(
            key,
            {
                "candidates": 0,
                "confirmed": 0,
                "refuted": 0,
                "unchecked": 0,
                "by_solver": collections.Counter(),
                "by_precision": collections.Counter(),
                "cases": [],
                "examples": [],
                "reference_missed": 0,
            },
        )
        for k in ("candidates", "confirmed", "refuted", "unchecked", "reference_missed", "n_cases"):
            t[k] = t.get(k, 0) + c[k]
        t["by_solver"].update(c["by_solver"])
        t["by_precision"].update(c["by_precision"])
        t["cases"] = (t["cases"] + c["cases"])[:40]
        t["examples"] = pick_examples(t["examples"] + c["examples"], 3)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    size = ap.add_mutually_exclusive_group()
    size.add_argument(
        "--answers",
        type=int,
        help="library answers to check (the standing run checks 1e7); " "runs ceil(answers / answers per case) cases",
    )
    size.add_argument("--cases", "--queries", dest="cases", type=int, help="number of cases (default 1e5)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--report", default=os.path.join(ROOT, "build", "reports", "differential_report.json"))
    ap.add_argument("--batch", type=int, default=2000, help="cases per chunk (one library batch per kind pair)")
    ap.add_argument(
        "--families",
        default="all",
        help='comma-separated subset of the families, or "round" '
        '(the pairs with a circle or disk), "no-round" (the pairs among points, lines, rays, '
        'segments and Bezier curves), "arc" (the arc families) or "annulus" (the annulus families)',
    )
    ap.add_argument("--solvers", default="all")
    ap.add_argument("--precisions", default="all")
    ap.add_argument("--scalar", type=int, default=16, help="scalar-vs-batch sample per chunk")
    ap.add_argument(
        "--max-confirm", type=int, default=3, help="50-digit confirmations per (class, solver, precision) and chunk"
    )
    ap.add_argument(
        "--unique-direct",
        type=int,
        default=8,
        help="cases per chunk whose closest_points().unique is checked against the 50-digit "
        "search of differential.reference_unique (~0.3 s a case); 0: none",
    )
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)

    D = load_differential()
    families = {
        "all": list(D.FAMILIES),
        "round": [f for f in D.FAMILIES if D.has_round(f)],
        "no-round": [f for f in D.FAMILIES if not D.has_round(f) and not D.is_arc(f) and not D.is_annulus(f)],
        "arc": [f for f in D.FAMILIES if D.is_arc(f)],
        "annulus": [f for f in D.FAMILIES if D.is_annulus(f)],
    }.get(args.families)
    families = families or args.families.split(",")
    for f in families:
        if f not in D.FAMILIES:
            ap.error(f"unknown family {f!r}; known: {', '.join(D.FAMILIES)}")
    solvers = D.SOLVERS if args.solvers == "all" else tuple(args.solvers.split(","))
    precisions = D.PRECISIONS if args.precisions == "all" else tuple(args.precisions.split(","))
    combo_list = D.combos(solvers, precisions)
    per_case = D.answers_per_case(len(combo_list))
    if args.answers is not None:
        n_cases = -(-args.answers // per_case)
    else:
        n_cases = args.cases if args.cases is not None else 100000
    chunks = plan(D, families, n_cases, args.batch)
    jobs = [(parts, args.seed, combo_list, args.scalar, args.max_confirm, 3, args.unique_direct) for parts in chunks]

    import circledist as cd

    lib = library_info(cd)
    if not args.quiet:
        print(
            f"library: {lib.get('module')} built {lib.get('extension_mtime')} (HEAD {lib.get('git_head', '?')[:10]})",
            flush=True,
        )
    if not args.quiet:
        print(
            f"{n_cases} cases x {per_case} batched answers each (+ the scalar sample)"
            + (f" for --answers {args.answers}" if args.answers is not None else ""),
            flush=True,
        )
    total = {
        "cases": 0,
        "answers": collections.Counter(),
        "unique_checked": collections.Counter(),
        "unique_checked_direct": collections.Counter(),
        "by_family": collections.Counter(),
        "by_pair": collections.Counter(),
        "classes": {},
    }
    t0 = time.perf_counter()
    if args.workers > 1:
        import multiprocessing as mp

        pool = mp.get_context("fork").Pool(args.workers)
        results = pool.imap_unordered(run_chunk, jobs)
    else:
        pool = None
        results = map(run_chunk, jobs)
    last = 0.0
    for i, part in enumerate(results, 1):
        merge(total, part)
        now = time.perf_counter() - t0
        if not args.quiet and (now - last > 20 or i == len(jobs)):
            last = now
            conf = sum(c["confirmed"] for c in total["classes"].values())
            cand = sum(c["candidates"] for c in total["classes"].values())
            print(
                f"[{now:7.0f} s] {total['cases']:>9}/{n_cases} cases, {sum(total['answers'].values())} answers, "
                f"{cand} candidate / {conf} confirmed findings",
                flush=True,
            )
    if pool is not None:
        pool.close()
        pool.join()
    seconds = time.perf_counter() - t0

    # ---- summary ----------------------------------------------------------------------------
    classes = total["classes"]
    confirmed = {k: c for k, c in classes.items() if c["confirmed"]}
    by_solver, by_precision = collections.Counter(), collections.Counter()
    by_family_f, by_pair_f = collections.Counter(), collections.Counter()
    for key, c in classes.items():
        check, fam, pair = key.split("|")
        by_solver.update(c["by_solver"])
        by_precision.update(c["by_precision"])
        by_family_f[fam] += c["confirmed"]
        by_pair_f[pair] += c["confirmed"]
    n_answers = sum(total["answers"].values())
    lines = [
        f"circledist differential run: {total['cases']} cases, {n_answers} library answers "
        f"({len(combo_list)} solver x precision combinations, both orders, every entry point), {seconds:.0f} s "
        f"({1e3 * seconds / max(total['cases'], 1):.2f} ms/case, {n_answers / max(seconds, 1e-9):.0f} answers/s), "
        f"seed {args.seed}",
        "answers per entry point: " + ", ".join(f"{k} {v}" for k, v in sorted(total["answers"].items())),
        "unique checked (expected value: count): "
        + ", ".join(f"{k} {v}" for k, v in sorted(total["unique_checked"].items())),
        "unique checked directly (differential.reference_unique; pair expected value: count): "
        + ", ".join(f"{k} {v}" for k, v in sorted(total["unique_checked_direct"].items())),
        "",
        "cases / confirmed findings per family:",
    ]
    lines += [f"  {fam:20s} {total['by_family'][fam]:>9} {by_family_f[fam]:>7}" for fam in families]
    lines += ["", "cases / confirmed findings per kind pair:"]
    lines += [f"  {p:20s} {n:>9} {by_pair_f[p]:>7}" for p, n in sorted(total["by_pair"].items())]
    lines += [
        "",
        "confirmed findings per solver: " + ", ".join(f"{s} {by_solver[s]}" for s in solvers),
        "confirmed findings per precision: " + ", ".join(f"{p} {by_precision[p]}" for p in precisions),
        "",
    ]
    lines.append(f"{len(classes)} finding classes ({len(confirmed)} with confirmed findings):")
    for key, c in sorted(classes.items(), key=lambda kv: -kv[1]["confirmed"]):
        lines.append(
            f"  {key:55s} candidates {c['candidates']:>6}  confirmed {c['confirmed']:>6}  "
            f"refuted {c['refuted']:>5}  unchecked {c['unchecked']:>6}  cases {c['n_cases']:>5}"
            + (f"  reference_missed {c['reference_missed']}" if c["reference_missed"] else "")
        )
    for key, c in sorted(confirmed.items()):
        ex = c["examples"][0]
        errs = [f.get("error") for f in c["examples"] if f.get("confirmed") and isinstance(f.get("error"), float)]
        lines += [
            "",
            f"--- reproducer for {key} (case {ex['case_id']}, {ex['solver']}/{ex['precision']}, "
            f"order {ex['order']}, {ex['entry']}; solvers {dict(c['by_solver'])}, "
            f"precisions {dict(c['by_precision'])}"
            + (f"; worst relative error seen {max(errs):.3g}" if errs else "")
            + "):",
            D.reproducer(ex),
        ]
    text = "\n".join(lines)
    print(text)

    report = {
        "command": " ".join(sys.argv),
        "cases": total["cases"],
        "answers": n_answers,
        "answers_by_entry": dict(total["answers"]),
        "unique_checked": dict(total["unique_checked"]),
        "unique_checked_direct": dict(total["unique_checked_direct"]),
        "answers_per_case_batched": per_case,
        "seconds": seconds,
        "ms_per_case": 1e3 * seconds / max(total["cases"], 1),
        "answers_per_second": n_answers / max(seconds, 1e-9),
        "seed": args.seed,
        "combos": [list(c) for c in combo_list],
        "families": families,
        "bars": D.BARS,
        "cases_by_family": dict(total["by_family"]),
        "cases_by_pair": dict(total["by_pair"]),
        "confirmed_by_solver": dict(by_solver),
        "confirmed_by_precision": dict(by_precision),
        "confirmed_by_family": dict(by_family_f),
        "confirmed_by_pair": dict(by_pair_f),
        "classes": {
            k: {
                **{
                    x: c[x]
                    for x in ("candidates", "confirmed", "refuted", "unchecked", "reference_missed", "n_cases", "cases")
                },
                "by_solver": dict(c["by_solver"]),
                "by_precision": dict(c["by_precision"]),
                "examples": c["examples"],
                "reproducer": D.reproducer(c["examples"][0]),
            }
            for k, c in classes.items()
        },
        "library": lib,
    }
    if args.report:
        os.makedirs(os.path.dirname(os.path.abspath(args.report)), exist_ok=True)
        with open(args.report, "w") as fh:
            json.dump(report, fh, indent=1, default=str)
        print(f"\nreport written to {args.report}")
    return 1 if confirmed else 0


if __name__ == "__main__":
    sys.exit(main())
