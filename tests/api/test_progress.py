"""progress= on the batched calls: reports while a batch runs and once at the end, answers unchanged,
an exception from the callback stops the work, progress=True draws a bar only for long work."""

from __future__ import annotations

import io
import sys
import types

import numpy as np
import pytest

import circledist as cd
from circledist._progress import ProgressBar

CALLS = {
    "distance": lambda a, b, **kw: cd.distance(a, b, **kw),
    "closest_points": lambda a, b, **kw: cd.closest_points(a, b, **kw).distance,
    "within": lambda a, b, **kw: cd.within(a, b, 0.5, **kw),
    "distance_if_within": lambda a, b, **kw: cd.distance_if_within(a, b, 0.5, **kw),
    "intersects": lambda a, b, **kw: cd.intersects(a, b, **kw),
}


def _disks(n, seed):
    rng = np.random.default_rng(seed)
    return cd.Disk(rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.5, 2, n))


@pytest.fixture(scope="module")
def long_batch():
    # Disk-disk pairs cost about 2 microseconds each: 200,000 of them run for a few tenths of a
    # second, long enough for several reports on any machine.
    return _disks(200_000, 1), _disks(200_000, 2)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(CALLS))
@pytest.mark.parametrize("workers", [1, 2])
def test_reports_during_and_at_the_end(long_batch, name, workers):
    a, b = long_batch
    seen = []
    out = CALLS[name](a, b, workers=workers, progress=lambda done, total: seen.append((done, total)))
    assert seen[-1] == (200_000, 200_000)
    done = [d for d, _ in seen]
    assert done == sorted(done) and all(t == 200_000 for _, t in seen)
    assert all(0 < d <= 200_000 for d in done)
    np.testing.assert_array_equal(out, CALLS[name](a, b, workers=workers))


def test_several_reports_while_a_long_batch_runs(long_batch):
    a, b = long_batch
    seen = []
    cd.closest_points(a, b, progress=lambda done, total: seen.append(done))
    assert len(seen) >= 2 and seen[0] < 200_000


def test_single_shapes_report_once():
    seen = []
    assert cd.distance(cd.Point([0, 0, 0]), cd.Point([3, 4, 0]), progress=lambda d, t: seen.append((d, t))) == 5.0
    assert seen == [(1, 1)]
    seen.clear()
    assert cd.within(cd.Point([0, 0, 0]), cd.Point([3, 4, 0]), 6, progress=lambda d, t: seen.append((d, t)))
    assert seen == [(1, 1)]


def _stopper():
    """(seen, stop): a callback that records its first report and raises."""
    seen = []

    def stop(done, total):
        seen.append(done)
        raise RuntimeError("enough")

    return seen, stop


def test_an_exception_in_the_callback_stops_the_work(long_batch):
    a, b = long_batch
    seen, stop = _stopper()
    with pytest.raises(RuntimeError, match="enough"):
        cd.distance(a, b, progress=stop)
    assert len(seen) == 1 and seen[0] < 200_000  # stopped at the first report
    with pytest.raises(RuntimeError, match="enough"):
        cd.distance(cd.Point([0, 0, 0]), cd.Point([1, 0, 0]), progress=stop)


@pytest.mark.parametrize("bad", [3, "yes", [1]])
def test_bad_progress_is_a_type_error(bad):
    with pytest.raises(TypeError, match="progress must be None, True or a callable"):
        cd.distance(cd.Point([0, 0, 0]), cd.Point([1, 0, 0]), progress=bad)


def test_false_and_none_report_nothing(capsys):
    p, q = cd.Point(np.zeros((10, 3))), cd.Point([1, 0, 0])
    for value in (None, False):
        np.testing.assert_array_equal(cd.distance(p, q, progress=value), np.ones(10))
    assert capsys.readouterr().err == ""


def test_true_is_silent_for_short_work(capsys):
    p, q = cd.Point(np.zeros((1000, 3))), cd.Point([1, 0, 0])
    np.testing.assert_array_equal(cd.distance(p, q, progress=True), np.ones(1000))
    assert capsys.readouterr().err == ""


def test_bar_without_tqdm_writes_one_line(monkeypatch, long_batch):
    monkeypatch.setitem(sys.modules, "tqdm", None)  # import tqdm fails
    stream = io.StringIO()
    a, b = long_batch
    cd.distance(a, b, progress=ProgressBar(delay=0, stream=stream))
    text = stream.getvalue()
    assert text.endswith("circledist: 200,000 of 200,000 queries (100 %)\n")
    assert text.count("\n") == 1 and text.count("\r") >= 2


def test_bar_uses_tqdm_when_installed(monkeypatch, long_batch):
    updates = []

    class FakeTqdm:
        def __init__(self, total, **kwargs):
            self.total, self.n, self.closed = total, 0, False
            updates.append(("open", total))

        def update(self, k):
            self.n += k
            updates.append(("update", self.n))

        def close(self):
            updates.append(("close", self.n))

    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=FakeTqdm))
    a, b = long_batch
    cd.distance(a, b, progress=ProgressBar(delay=0))
    assert updates[0] == ("open", 200_000) and updates[-1] == ("close", 200_000)
    assert [n for kind, n in updates if kind == "update"][-1] == 200_000


# The all-pairs queries: stages (the candidates' search, their distances) each counted as len(a)
# steps, so total is 2 len(a) (pairs_within) or 4 len(a) (nearest), done rising to it once.
ALL_PAIRS = {
    "pairs_within": (lambda a, b, **kw: cd.pairs_within(a, b, 0.3, **kw), 2),
    "pairs_within_self": (lambda a, b, **kw: cd.pairs_within(a, None, 0.3, **kw), 2),
    "nearest": (lambda a, b, **kw: cd.nearest(a, b, k=3, **kw), 4),
}


@pytest.fixture(scope="module")
def crowded():
    # 40,000 disks in a box of side 60: a few neighbours each within 0.3, seconds of distances.
    rng = np.random.default_rng(5)
    n = 40_000
    return (
        cd.Disk(rng.uniform(0, 60, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.2, 0.6, n)),
        cd.Disk(rng.uniform(0, 60, (n, 3)), rng.normal(size=(n, 3)), rng.uniform(0.2, 0.6, n)),
    )


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(ALL_PAIRS))
@pytest.mark.parametrize("workers", [1, 2])
def test_all_pairs_report_in_stages(crowded, name, workers):
    call, stages = ALL_PAIRS[name]
    a, b = crowded
    seen = []
    out = call(a, b, workers=workers, progress=lambda done, total: seen.append((done, total)))
    total = stages * 40_000
    assert all(t == total for _, t in seen)
    done = [d for d, _ in seen]
    assert done == sorted(done) and len(set(done)) == len(done)  # rising, no value twice
    assert seen[-1] == (total, total) and done.count(total) == 1
    assert all(0 <= d <= total for d in done)
    for got, plain in zip(out, call(a, b, workers=workers)):
        np.testing.assert_array_equal(got, plain)


def test_all_pairs_report_while_they_run(crowded):
    a, b = crowded
    seen = []
    cd.nearest(a, b, k=3, progress=lambda done, total: seen.append(done))
    assert len(seen) >= 2 and seen[0] < 4 * 40_000


@pytest.mark.parametrize("name", sorted(ALL_PAIRS))
def test_all_pairs_stop_on_an_exception_in_the_callback(crowded, name):
    call, _ = ALL_PAIRS[name]
    a, b = crowded
    seen, stop = _stopper()
    with pytest.raises(RuntimeError, match="enough"):
        call(a, b, progress=stop)
    assert len(seen) == 1


def test_all_pairs_of_empty_batches_report_the_end_once():
    empty = cd.Point(np.zeros((0, 3)))
    seen = []
    i, j, dist = cd.pairs_within(empty, cd.Point([0, 0, 0]), 1.0, progress=lambda d, t: seen.append((d, t)))
    assert len(i) == 0 and seen == [(0, 0)]


@pytest.mark.parametrize("bad", [3, "yes"])
def test_all_pairs_bad_progress_is_a_type_error(bad):
    with pytest.raises(TypeError, match="progress must be None, True or a callable"):
        cd.pairs_within(cd.Point([0, 0, 0]), None, 1.0, progress=bad)
    with pytest.raises(TypeError, match="progress must be None, True or a callable"):
        cd.nearest(cd.Point([0, 0, 0]), cd.Point([1, 0, 0]), progress=bad)
