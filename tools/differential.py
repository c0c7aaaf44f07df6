#!/usr/bin/env python3
"""Long mode of the differential accuracy test (issue 14, "keep it closed").

    python tools/differential.py --queries 10000000 --seed 1 --report docs/differential_report.json

runs N queries (cases: one kind pair instance each, spread evenly over the case families of
tests/differential.py and, within a family, over its kind pairs) through every solver x precision
combination, both argument orders, distance / closest_points / within / distance_if_within /
intersects, batched (plus a scalar sample per batch that must give exactly the batch's answers),
judged by the fast NumPy screen and by the returned closest points.  Accuracy findings are
confirmed against the 50-digit mpmath references (at most --max-confirm per finding class,
solver and precision; the rest are counted as candidates).  Prints counts per family, kind pair,
solver and precision and one reproducer per finding class, writes the JSON report, and exits 1
when any finding is confirmed.

Every case is reproducible from its id "family/seed/index" (differential.case_from_id).
"""

from __future__ import annotations

import argparse
import collections
import importlib.util
import json
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load_differential():
    """tests/differential.py, imported by path (no sys.path edits)."""
    if "differential" in sys.modules:
        return sys.modules["differential"]
    spec = importlib.util.spec_from_file_location("differential", os.path.join(ROOT, "tests", "differential.py"))
    mod = importlib.util.module_from_spec(spec)
    sys.modules["differential"] = mod
    spec.loader.exec_module(mod)
    return mod


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
        info["git_head"] = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True,
                                          text=True, timeout=10).stdout.strip()
        info["git_dirty"] = subprocess.run(["git", "-C", ROOT, "status", "--short"], capture_output=True,
                                           text=True, timeout=10).stdout.split("\n")
    except Exception:  # noqa: BLE001 - informational only
        pass
    return info


def plan(D, families, queries, batch):
    """Chunks (family, start, count): N queries split evenly over the families."""
    per = [queries // len(families) + (1 if i < queries % len(families) else 0) for i in range(len(families))]
    chunks = []
    for fam, n in zip(families, per):
        for start in range(0, n, batch):
            chunks.append((fam, start, min(batch, n - start)))
    # interleave families so that partial runs see all of them
    by_fam = collections.defaultdict(list)
    for c in chunks:
        by_fam[c[0]].append(c)
    out = []
    while any(by_fam.values()):
        for fam in families:
            if by_fam[fam]:
                out.append(by_fam[fam].pop(0))
    return out


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
    fam, start, count, seed, combo_list, scalar_n, max_confirm, keep = job
    D = load_differential()
    import circledist as cd
    cases = D.generate(fam, count, seed, start=start)
    step = max(1, len(cases) // max(scalar_n, 1)) if scalar_n else None
    scalar = set(range(0, len(cases), step)) if scalar_n else set()
    t0 = time.perf_counter()
    findings, stats = D.check_and_confirm(cd, cases, combo_list, scalar=scalar, max_confirm=max_confirm)
    seconds = time.perf_counter() - t0
    pairs = collections.Counter(f"{c['a']}-{c['b']}" for c in cases)
    # per class: counts by status / solver / precision, and a few examples (confirmed first,
    # largest error first)
    classes = {}
    for f in findings:
        key = "|".join(D.finding_class(f))
        c = classes.setdefault(key, {"candidates": 0, "confirmed": 0, "refuted": 0, "unchecked": 0,
                                     "by_solver": collections.Counter(), "by_precision": collections.Counter(),
                                     "cases": set(), "examples": [], "reference_missed": 0})
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
        c["cases"] = sorted(c["cases"])[:keep * 4]
    return dict(family=fam, count=count, pairs=dict(pairs), calls=stats["calls"], seconds=seconds, classes=classes)


def merge(total, part):
    total["queries"] += part["count"]
    total["calls"] += part["calls"]
    total["by_family"][part["family"]] += part["count"]
    for p, n in part["pairs"].items():
        total["by_pair"][p] += n
    for key, c in part["classes"].items():
        t = total["classes"].setdefault(key, {"candidates": 0, "confirmed": 0, "refuted": 0, "unchecked": 0,
                                              "by_solver": collections.Counter(),
                                              "by_precision": collections.Counter(), "cases": [],
                                              "examples": [], "reference_missed": 0})
        for k in ("candidates", "confirmed", "refuted", "unchecked", "reference_missed", "n_cases"):
            t[k] = t.get(k, 0) + c[k]
        t["by_solver"].update(c["by_solver"])
        t["by_precision"].update(c["by_precision"])
        t["cases"] = (t["cases"] + c["cases"])[:40]
        t["examples"] = pick_examples(t["examples"] + c["examples"], 3)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--queries", type=int, default=100000, help="number of cases (default 1e5; 1e7 intended)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--report", default=os.path.join(ROOT, "docs", "differential_report.json"))
    ap.add_argument("--batch", type=int, default=2000, help="cases per chunk (one library batch per kind pair)")
    ap.add_argument("--families", default="all", help="comma-separated subset of the families")
    ap.add_argument("--solvers", default="all")
    ap.add_argument("--precisions", default="all")
    ap.add_argument("--scalar", type=int, default=16, help="scalar-vs-batch sample per chunk")
    ap.add_argument("--max-confirm", type=int, default=3,
                    help="50-digit confirmations per (class, solver, precision) and chunk")
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)

    D = load_differential()
    families = list(D.FAMILIES) if args.families == "all" else args.families.split(",")
    for f in families:
        if f not in D.FAMILIES:
            ap.error(f"unknown family {f!r}; known: {', '.join(D.FAMILIES)}")
    solvers = D.SOLVERS if args.solvers == "all" else tuple(args.solvers.split(","))
    precisions = D.PRECISIONS if args.precisions == "all" else tuple(args.precisions.split(","))
    combo_list = D.combos(solvers, precisions)
    chunks = plan(D, families, args.queries, args.batch)
    jobs = [(f, s, n, args.seed, combo_list, args.scalar, args.max_confirm, 3) for f, s, n in chunks]

    import circledist as cd
    lib = library_info(cd)
    if not args.quiet:
        print(f"library: {lib.get('module')} built {lib.get('extension_mtime')} (HEAD {lib.get('git_head', '?')[:10]})",
              flush=True)
    total = {"queries": 0, "calls": 0, "by_family": collections.Counter(), "by_pair": collections.Counter(),
             "classes": {}}
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
            print(f"[{now:7.0f} s] {total['queries']:>9}/{args.queries} queries, {total['calls']} calls, "
                  f"{cand} candidate / {conf} confirmed findings", flush=True)
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
    lines = [f"circledist differential run: {total['queries']} queries, {len(combo_list)} solver x precision "
             f"combinations, both orders, {total['calls']} library calls, {seconds:.0f} s "
             f"({1e3 * seconds / max(total['queries'], 1):.2f} ms/query), seed {args.seed}",
             "", "queries / confirmed findings per family:"]
    lines += [f"  {fam:20s} {total['by_family'][fam]:>9} {by_family_f[fam]:>7}" for fam in families]
    lines += ["", "queries / confirmed findings per kind pair:"]
    lines += [f"  {p:20s} {n:>9} {by_pair_f[p]:>7}" for p, n in sorted(total["by_pair"].items())]
    lines += ["", "confirmed findings per solver: " + ", ".join(f"{s} {by_solver[s]}" for s in solvers),
              "confirmed findings per precision: " + ", ".join(f"{p} {by_precision[p]}" for p in precisions), ""]
    lines.append(f"{len(classes)} finding classes ({len(confirmed)} with confirmed findings):")
    for key, c in sorted(classes.items(), key=lambda kv: -kv[1]["confirmed"]):
        lines.append(f"  {key:55s} candidates {c['candidates']:>6}  confirmed {c['confirmed']:>6}  "
                     f"refuted {c['refuted']:>5}  unchecked {c['unchecked']:>6}  cases {c['n_cases']:>5}"
                     + (f"  reference_missed {c['reference_missed']}" if c["reference_missed"] else ""))
    for key, c in sorted(confirmed.items()):
        ex = c["examples"][0]
        errs = [f.get("error") for f in c["examples"] if f.get("confirmed") and isinstance(f.get("error"), float)]
        lines += ["", f"--- reproducer for {key} (case {ex['case_id']}, {ex['solver']}/{ex['precision']}, "
                      f"order {ex['order']}, {ex['entry']}; solvers {dict(c['by_solver'])}, "
                      f"precisions {dict(c['by_precision'])}"
                      + (f"; worst relative error seen {max(errs):.3g}" if errs else "") + "):", D.reproducer(ex)]
    text = "\n".join(lines)
    print(text)

    report = {
        "command": " ".join(sys.argv),
        "queries": total["queries"], "seconds": seconds, "seed": args.seed, "calls": total["calls"],
        "combos": [list(c) for c in combo_list], "families": families,
        "bars": D.BARS, "queries_by_family": dict(total["by_family"]), "queries_by_pair": dict(total["by_pair"]),
        "confirmed_by_solver": dict(by_solver), "confirmed_by_precision": dict(by_precision),
        "confirmed_by_family": dict(by_family_f), "confirmed_by_pair": dict(by_pair_f),
        "classes": {k: {**{x: c[x] for x in ("candidates", "confirmed", "refuted", "unchecked", "reference_missed",
                                             "n_cases", "cases")},
                        "by_solver": dict(c["by_solver"]), "by_precision": dict(c["by_precision"]),
                        "examples": c["examples"], "reproducer": D.reproducer(c["examples"][0])}
                    for k, c in classes.items()},
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
