"""circledist.dask on a distributed.LocalCluster against single-process circledist: time and peak
memory per worker for point-circle and circle-circle distances and a pairs_within.

    python -m bench.bench_dask [--points 1e8] [--circles 1e7] [--pairs 1e6] [--chunk 2e6]

The cluster's shapes are drawn on the workers, chunk by chunk (da.random), so no process holds a
whole batch; "draw only" times that drawing alone (a sum over the fields), so query time is the
difference. The single process answers the same counts in chunks of the same size, from arrays
drawn before the clock starts (so its time is the query alone), with workers=1 and 2.
"""

import argparse
import resource
import time

import dask
import dask.array as da
import distributed
import numpy as np

import circledist as cd
import circledist.dask as cdd


def peak_mb():
    # ru_maxrss is in KiB on Linux: the process's peak resident memory since it started.
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def lazy_fields(kind, n, chunk, seed):
    rs = da.random.RandomState(seed)
    at = rs.uniform(-100, 100, (n, 3), chunks=(chunk, 3))
    if kind == "Point":
        return {"p": at}
    return {
        "center": at,
        "normal": rs.normal(size=(n, 3), chunks=(chunk, 3)),
        "radius": rs.uniform(0.5, 2, n, chunks=chunk),
    }


def numpy_fields(kind, n, rng):
    at = rng.uniform(-100, 100, (n, 3))
    if kind == "Point":
        return {"p": at}
    return {"center": at, "normal": rng.normal(size=(n, 3)), "radius": rng.uniform(0.5, 2, n)}


def cluster_run(client, label, kind_a, kind_b, n, chunk):
    fa, fb = lazy_fields(kind_a, n, chunk, 1), lazy_fields(kind_b, n, chunk, 2)
    client.run(lambda: None)
    t = time.perf_counter()
    dask.compute(sum(v.sum() for v in list(fa.values()) + list(fb.values())))
    draw = time.perf_counter() - t
    a, b = getattr(cdd, kind_a).from_arrays(fa), getattr(cdd, kind_b).from_arrays(fb)
    t = time.perf_counter()
    total = cdd.distance(a, b).sum().compute()
    elapsed = time.perf_counter() - t
    peaks = client.run(peak_mb)
    print(
        f"{label}: n={n:.0e}, chunk={chunk:.0e}, 2 workers: {elapsed:.1f} s with drawing "
        f"(draw only {draw:.1f} s, query ~{elapsed - draw:.1f} s, {n / max(elapsed - draw, 1e-9) / 1e6:.1f} M/s); "
        f"peak RSS per worker {', '.join(f'{v:.0f}' for v in peaks.values())} MB; sum {total:.6e}"
    )


def single_run(label, kind_a, kind_b, n, chunk):
    rng = np.random.default_rng(3)
    # One chunk's arrays reused for every chunk: the query's time per element does not depend on
    # which random shapes it gets, and n elements would not fit twice in this process.
    a = getattr(cd, kind_a).from_arrays(numpy_fields(kind_a, chunk, rng))
    b = getattr(cd, kind_b).from_arrays(numpy_fields(kind_b, chunk, rng))
    for workers in (1, 2):
        t = time.perf_counter()
        for _ in range(n // chunk):
            cd.distance(a, b, workers=workers).sum()
        elapsed = time.perf_counter() - t
        print(
            f"{label}: n={n:.0e}, chunk={chunk:.0e}, single process workers={workers}: {elapsed:.1f} s "
            f"({n / elapsed / 1e6:.1f} M/s); peak RSS {peak_mb():.0f} MB"
        )


def pairs_run(client, n, chunk):
    rng = np.random.default_rng(4)
    # Rings and segments at the density of the scene example's (10^5 each in a 20 m cube), d = 5 cm.
    side = 20 * (n / 1e5) ** (1 / 3)
    rings = cd.Circle(rng.uniform(0, side, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.05, 0.2, n))
    at = rng.uniform(0, side, (n, 3))
    sticks = cd.Segment(at, at + rng.uniform(-0.3, 0.3, (n, 3)))
    t = time.perf_counter()
    expected = cd.pairs_within(rings, sticks, 0.05)
    single = time.perf_counter() - t

    def on_cluster(shape):
        # The fields held by the workers before the clock starts, as a cluster's data would be.
        names, arrays = zip(
            *[(k, da.from_array(v, chunks=(chunk,) + v.shape[1:])) for k, v in shape.to_arrays().items()]
        )
        arrays = client.persist(list(arrays))
        distributed.wait(arrays)
        return getattr(cdd, shape.kind).from_arrays(dict(zip(names, arrays)))

    a, b = on_cluster(rings), on_cluster(sticks)
    t = time.perf_counter()
    got = dask.compute(*cdd.pairs_within(a, b, 0.05))
    elapsed = time.perf_counter() - t
    same = all(np.array_equal(g, e) for g, e in zip(got, expected))
    print(
        f"pairs_within rings x segments, d=0.05: n={n:.0e} each, chunk={chunk:.0e}: 2 workers {elapsed:.1f} s, "
        f"single process {single:.1f} s; {len(expected[0])} pairs, equal: {same}; peak RSS per worker "
        f"{', '.join(f'{v:.0f}' for v in client.run(peak_mb).values())} MB"
    )


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=float, default=1e8)
    parser.add_argument("--circles", type=float, default=1e7)
    parser.add_argument("--pairs", type=float, default=1e6)
    parser.add_argument("--chunk", type=float, default=2e6)
    args = parser.parse_args()
    chunk = int(args.chunk)
    with (
        distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        if args.points:
            cluster_run(client, "point-circle", "Point", "Circle", int(args.points), chunk)
        if args.circles:
            cluster_run(client, "circle-circle", "Circle", "Circle", int(args.circles), chunk // 4)
        if args.pairs:
            pairs_run(client, int(args.pairs), int(args.pairs) // 8)
    if args.points:
        single_run("point-circle", "Point", "Circle", int(args.points), chunk)
    if args.circles:
        single_run("circle-circle", "Circle", "Circle", int(args.circles), chunk // 4)


if __name__ == "__main__":
    main()
