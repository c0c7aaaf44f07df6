"""Batches on several threads (workers=): the same answers to the bit for every worker count,
counters that add up, Ctrl-C that stops a long batch, and a clear error for a bad count."""

import os
import signal
import subprocess
import sys
import textwrap
import zlib

import numpy as np
import pytest

from circledist_cases.shapes import query_pairs, random_fields, same_bits

cd = pytest.importorskip("circledist")

# Chunks hold 256 elements at least (src/kernels/parallel.hpp): 6 chunks, two or more per thread
# at every worker count below; the Bezier pairs (the costliest) 3 chunks, more than one thread.
N = 6 * 256
N_BEZIER = 3 * 256
WORKERS = (2, 3)  # workers=-1 (every core): test_counters_add_up_across_threads


def _answers(a, b, d, **opts):
    r = cd.closest_points(a, b, **opts)
    return [
        cd.distance(a, b, **opts),
        cd.within(a, b, d, **opts),
        cd.distance_if_within(a, b, d, **opts),
        cd.intersects(a, b, **opts),
        r.distance,
        r.point_a,
        r.point_b,
        r.param_a,
        r.param_b,
        r.unique,
    ]


@pytest.mark.slow
@pytest.mark.parametrize("pair", query_pairs(cd), ids="-".join)
def test_every_worker_count_gives_the_same_bits(pair):
    rng = np.random.default_rng(zlib.crc32("-".join(pair).encode()))
    n = N if "Bezier" not in pair else N_BEZIER
    a = getattr(cd, pair[0])(**random_fields(cd, pair[0], rng, (n,)), sweep=rng.uniform(0, 0.2, n))
    b = getattr(cd, pair[1])(**random_fields(cd, pair[1], rng, (n,)))
    d = rng.uniform(0.0, 2.0, n)
    for solver in (None, "companion", "polished", "eigen"):
        for precision in ("float32", "float64", "longdouble") if solver is None else ("float64",):
            one = _answers(a, b, d, solver=solver, precision=precision)
            for workers in WORKERS:
                for got, want in zip(_answers(a, b, d, solver=solver, precision=precision, workers=workers), one):
                    same_bits(got, want)


def test_gathered_broadcast_on_several_threads():
    """An (n, 1) against (m,) broadcast walks an odometer that each thread starts mid-batch."""
    rng = np.random.default_rng(5)
    n, m = 37, 211  # chunks start at odd places of the odometer
    lines = cd.Line(rng.normal(size=(n, 1, 3)), rng.normal(size=(n, 1, 3)))
    rings = cd.Circle(rng.normal(size=(m, 3)), rng.normal(size=(m, 3)), rng.uniform(0.5, 2, m))
    full_lines = cd.Line(np.repeat(lines.origin, m, axis=1), np.repeat(lines.direction, m, axis=1))
    want = cd.distance(full_lines, rings)  # every field full size: the linear path, one thread
    for workers in (1, 2, 5):
        same_bits(cd.distance(lines, rings, workers=workers), want)
        got, ref = cd.closest_points(lines, rings, workers=workers), cd.closest_points(full_lines, rings)
        same_bits(got.point_a, ref.point_a)
        same_bits(got.param_b, ref.param_b)


def test_counters_add_up_across_threads():
    rng = np.random.default_rng(6)
    a = cd.Circle(rng.normal(size=(N, 3)), rng.normal(size=(N, 3)), rng.uniform(0.5, 2, N))
    b = cd.Disk(rng.normal(size=(N, 3)), rng.normal(size=(N, 3)), rng.uniform(0.5, 2, N))
    counts = []
    for workers in (1, 2, -1):
        cd.reset_stats()
        cd.distance(a, b, workers=workers)
        cd.closest_points(a, b, workers=workers)
        cd.within(a, b, 0.5, workers=workers)
        counts.append(cd.stats())
    assert counts[0]["distances"] > N and counts[0]["closest_points"] == N and counts[0]["within"] == N
    assert counts[0]["solves"] > 0
    assert counts[1] == counts[0] and counts[2] == counts[0]


@pytest.mark.parametrize("workers", [0, -2, -10])
def test_bad_worker_count_is_a_value_error(workers):
    p = cd.Point(np.zeros((10, 3)))
    ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
    for call in (
        lambda: cd.distance(p, ring, workers=workers),
        lambda: cd.closest_points(p, ring, workers=workers),
        lambda: cd.within(p, ring, 1.0, workers=workers),
        lambda: cd.intersects(p, ring, workers=workers),
        lambda: cd.distance_if_within(p, ring, 1.0, workers=workers),
    ):
        with pytest.raises(ValueError, match=f"workers must be a positive integer or -1.*got {workers}"):
            call()


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.skipif(not hasattr(signal, "SIGINT") or os.name != "posix", reason="POSIX signals")
@pytest.mark.parametrize("workers", [1, 2])
def test_ctrl_c_stops_a_long_batch(workers):
    """SIGINT 0.3 s into a batch of many seconds: KeyboardInterrupt within half a second."""
    script = textwrap.dedent(f"""
        import os, signal, threading, time
        import numpy as np
        import circledist as cd
        # Python's own Ctrl-C handler, as an interactive session has it: a process started in the
        # background by a non-interactive shell inherits SIGINT ignored, and Python then installs none
        signal.signal(signal.SIGINT, signal.default_int_handler)
        rng = np.random.default_rng(1)
        n = 400_000  # Bezier-disk: about 10 us each, seconds of work on any core count here
        curves = cd.Bezier(rng.normal(size=(n, 4, 3)))
        disks = cd.Disk(rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.5, 2, n))
        threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        start = time.perf_counter()
        try:
            cd.distance(curves, disks, workers={workers})
            print("finished", time.perf_counter() - start)
        except KeyboardInterrupt:
            print("interrupted", time.perf_counter() - start)
    """)
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    outcome, seconds = out.stdout.split()
    assert outcome == "interrupted", out.stdout
    assert float(seconds) < 0.3 + 0.5, out.stdout


# Long phases of the all-pairs queries and of a Scene (setup, then the call SIGINT interrupts):
# each is seconds of work here at these sizes, most of it a hierarchy's build or passes over the
# candidates, which hear Ctrl-C as the batches do.
LONG_PHASES = {
    "scene_first_query": (
        "scene = cd.Scene(); scene.extend('p', cd.Point(rng.uniform(0, 100, (N, 3))))",
        "scene.nearest([0.0, 0.0, 0.0])",
    ),
    "scene_pairs_within": (
        "scene = cd.Scene(); scene.extend('p', cd.Point(rng.uniform(0, 100, (N, 3))))\n"
        "scene.nearest([0.0, 0.0, 0.0]); scene.add('x', cd.Point([0.0, 0.0, 0.0]))",
        "scene.pairs_within(0.05)",
    ),
    "pairs_within": ("points = cd.Point(rng.uniform(0, 100, (N, 3)))", "cd.pairs_within(points, None, 0.05)"),
    "nearest": ("points = cd.Point(rng.uniform(0, 100, (N, 3)))", "cd.nearest(points, points, k=2)"),
}


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.skipif(not hasattr(signal, "SIGINT") or os.name != "posix", reason="POSIX signals")
@pytest.mark.parametrize("phase", list(LONG_PHASES))
def test_ctrl_c_stops_the_broadphase_phases(phase):
    """SIGINT 0.3 s into a Scene's first query (the hierarchy's build), the merge and pairs of
    Scene.pairs_within, and pairs_within / nearest over a large set: KeyboardInterrupt within
    half a second; the interrupted scene then answers as before."""
    setup, call = LONG_PHASES[phase]
    script = (
        textwrap.dedent("""
        import os, signal, threading, time
        import numpy as np
        import circledist as cd
        signal.signal(signal.SIGINT, signal.default_int_handler)  # as in the test above
        rng = np.random.default_rng(2)
        N = 1_500_000
    """)
        + setup
        + textwrap.dedent(f"""
        threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        start = time.perf_counter()
        try:
            {call}
            print("finished", time.perf_counter() - start)
        except KeyboardInterrupt:
            print("interrupted", time.perf_counter() - start)
        if "scene" in globals():
            scene.add("probe", cd.Point([50.0, 50.0, 50.0]))
            print(scene.nearest([50.0, 50.0, 50.0])[0][0] == "probe")
        else:
            print(True)
    """)
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    outcome, seconds, after = out.stdout.split()
    assert outcome == "interrupted", out.stdout
    assert float(seconds) < 0.3 + 0.5, out.stdout
    assert after == "True"
